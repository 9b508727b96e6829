## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn  {} {@var{M} =} ssivgpmf (@var{data}, @var{nni}, @var{param})
## @deftypefnx {} {@var{M} =} ssivgpmf (@var{data}, @var{nni}, @var{param}, @var{n0})
## Instrumental-variable estimate of a multivariable continuous-time
## state-space model in observable canonical form by generalised Poisson
## moment functionals (GPMF).
##
## Arguments, model structure and output as for @code{sslsgpmf}:
## @var{data} an @code{iddata} object with @var{p} outputs, @var{nni} the
## @var{p} observability indices, @var{param} the @var{p} Poisson filter
## parameters (rad/s), @var{n0} the first sample used (default 1).
##
## The least-squares GPMF model (@code{sslsgpmf}) is simulated from the
## input alone (exactly for the data's InterSample rule, from rest); its
## noise-free outputs replace the measured ones in the GPMF regressors to
## form the instruments, and each output equation is solved by the basic
## IV estimator.  The instruments are uncorrelated with output noise, so
## the estimate is consistent where the LS one is biased.  The LS model
## must be stable (error @code{ssivgpmf:numericalFailure} otherwise).
##
## @strong{Example}
## @example
## A0 = [0 1 0; -3 -2 -1; -1 -2 -1];  B0 = [1 1; 2 1; 1 2];
## C0 = [1 0 0; 0 0 1];
## Ts = 0.01;  u = kron (sign (randn (200, 2)), ones (50, 1));
## y = lsim (c2d (ss (A0, B0, C0, zeros (2)), Ts), u);
## y = y + 0.1 * std (y) .* randn (size (y));
## M = ssivgpmf (iddata (y, u, Ts), [2 1], [3; 3]);
## M.A
## @end example
## @seealso{sslsgpmf, idss, comparec}
## @end deftypefn

function varargout = ssivgpmf (varargin)
  varargout = contsid_guard ("ssivgpmf", @ssivgpmf_body, nargout, varargin);
endfunction

function [M, varargout] = ssivgpmf_body (varargin)
  contsid_nargchk ("ssivgpmf", nargin, nargout, [3 4], 1);
  M = contsid_gpmf ("ssivgpmf", varargin);
endfunction

%!function H = gpmf_freq (A, B, C, w)
%!  H = zeros (rows (C), columns (B), numel (w));
%!  for k = 1:numel (w)
%!    H(:,:,k) = C * ((1i * w(k) * eye (rows (A)) - A) \ B);
%!  endfor
%!endfunction

## The system of the sslsgpmf tests (observability indices [2 1]).
%!shared A0, B0, C0, u, Ts, w, y
%! pkg load control;
%! A0 = [-1 1 0; -1 -1 0; 0 0 -2];
%! B0 = [1 0; 0 1; 1 1];
%! C0 = [1 0 1; 0 1 0];
%! Ts = 0.01;
%! state = rand ("state");
%! rand ("state", 7);
%! u = kron (sign (rand (400, 2) - 0.5), ones (50, 1));
%! rand ("state", state);
%! w = logspace (-1, 1, 20);
%! y = lsim (c2d (ss (A0, B0, C0, zeros (2)), Ts, "zoh"), u);

## Noise-free data: the IV model is the true one (up to the O((lambda
## Ts)^2) filtering error of y, as for sslsgpmf).
%!test
%! M = ssivgpmf (iddata (y, u, Ts), [2 1], [3; 3]);
%! assert (isa (M, "idss"));
%! assert (M.Ts, 0);
%! H0 = gpmf_freq (A0, B0, C0, w);
%! H = gpmf_freq (M.A, M.B, M.C, w);
%! assert (max (abs (H(:) - H0(:))) / max (abs (H0(:))) < 1e-3);

## White output noise (10 dB): the LS estimate is biased, the IV estimate
## is not: its parameter error is several times smaller, and its frequency
## response stays within the 5 % its standard error (N = 20000) allows.
%!test
%! state = randn ("state");
%! randn ("state", 11);
%! yn = y + 10^(-10/20) * std (y) .* randn (size (y));
%! randn ("state", state);
%! data = iddata (yn, u, Ts);
%! Mls = sslsgpmf (data, [2 1], [3; 3]);
%! Miv = ssivgpmf (data, [2 1], [3; 3]);
%! T = [C0(1,:); C0(1,:) * A0; C0(2,:)];
%! theta0 = [T * A0 / T, T * B0];
%! err_ls = norm ([Mls.A, Mls.B] - theta0);
%! err_iv = norm ([Miv.A, Miv.B] - theta0);
%! assert (err_iv < err_ls / 3);
%! H0 = gpmf_freq (A0, B0, C0, w);
%! H = gpmf_freq (Miv.A, Miv.B, Miv.C, w);
%! assert (max (abs (H(:) - H0(:))) / max (abs (H0(:))) < 5e-2);

%!error <at least 3> ssivgpmf (iddata ((1:10)', (1:10)', 1), 1)
%!error id=ssivgpmf:badInput ssivgpmf ((1:10)', [1 1], [3; 3])
%!error id=ssivgpmf:dimensionMismatch ...
%! ssivgpmf (iddata (rand (50, 2), rand (50, 1), 1), [1 1 1], [3; 3])
%!error id=ssivgpmf:dimensionMismatch ...
%! ssivgpmf (iddata (rand (50, 2), rand (50, 1), 1), [1 1], [3; 3; 3])
%!error id=ssivgpmf:badInput ...
%! ssivgpmf (iddata (rand (50, 2), rand (50, 1), 1), [2 -1], [3; 3])
%!error id=ssivgpmf:badInput ...
%! ssivgpmf (iddata (rand (50, 2), rand (50, 1), 1), [1 1], [0; 3])
%!error id=ssivgpmf:badInput ...
%! ssivgpmf (iddata (rand (50, 2), rand (50, 1), 1), [1 1], [3; 3], 2.5)
%!error id=ssivgpmf:numericalFailure ...
%! ssivgpmf (iddata (rand (50, 2), zeros (50, 1), 1), [1 1], [3; 3])

## An unstable least-squares model gives no instruments: y2 grows as e^t.
%!error id=ssivgpmf:numericalFailure
%! t = (0:199)' * 0.05;
%! ssivgpmf (iddata ([sin(t), exp(t)], [cos(t), sin(2 * t)], 0.05), [1 1],
%!           [3; 3])

%!demo
%! pkg load control;
%! A0 = [0 1 0; -3 -2 -1; -1 -2 -1];  B0 = [1 1; 2 1; 1 2];
%! C0 = [1 0 0; 0 0 1];  Ts = 0.01;
%! u = kron (sign (randn (200, 2)), ones (50, 1));
%! y = lsim (c2d (ss (A0, B0, C0, zeros (2)), Ts), u);
%! y = y + 0.3 * std (y) .* randn (size (y));
%! Mls = sslsgpmf (iddata (y, u, Ts), [2 1], [3; 3]);
%! Miv = ssivgpmf (iddata (y, u, Ts), [2 1], [3; 3]);
%! disp ([Mls.A, Mls.B]); disp ([Miv.A, Miv.B]); disp ([A0, B0]);
