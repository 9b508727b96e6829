## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn  {} {@var{M} =} ssbcgpmf (@var{data}, @var{nni}, @var{param}, @var{root})
## @deftypefnx {} {@var{M} =} ssbcgpmf (@var{data}, @var{nni}, @var{param}, @var{root}, @var{n0})
## Bias-compensated least-squares estimate of a multivariable
## continuous-time state-space model in observable canonical form by
## generalised Poisson moment functionals (GPMF).
##
## @var{data}, @var{nni}, @var{param}, @var{n0} and the model structure are
## those of @code{sslsgpmf}.  @var{root} holds the roots (real, negative)
## of the artificial filter @math{1/F_i(p)}, @math{F_i(p) = \prod (p - r)},
## through which the inputs of output equation @var{i} are passed: one row
## per output, or one row for all of them.
##
## The input filter augments each output equation with the known factor
## @math{F_i}, so the numerators of the augmented equation vanish at the
## roots.  Under white output noise the least-squares GPMF estimate is
## biased by a term proportional to the noise variances, which the GPMF
## filter's impulse response gives up to those variances; the variances
## are chosen so that the compensated estimate meets the known zeros
## (Gauss-Newton, variances @math{\ge 0}), and the compensated estimate is
## returned.  The roots must differ from the system's poles (a common
## root makes the augmented equation non-unique).  The result depends
## strongly on the roots and needs long, not too noisy records: on the
## system of the example (20000 samples, Ts = 0.01, 10 dB) one root -1
## per output gave a parameter error of 0.1 to 0.2 (LS 0.8 to 1.0, IV
## 0.15), the three roots -1, -1.5, -2 an error above 6; on 1000 samples
## with Ts = 0.1 at 5 dB every choice tried was worse than LS.  Check the
## model against @code{ssivgpmf}.  Only uniformly sampled data are
## supported (error @code{ssbcgpmf:notSupported}).
##
## Reference: H. Garnier, P. Sibille and T. Bastogne, "A bias-free
## least-squares parameter estimator for continuous-time state-space
## models", CDC 1997; the bias-eliminated least-squares principle of
## Feng and Zheng (IEE Proc. D 138, 1991).
##
## @strong{Example}
## @example
## A0 = [0 1 0; -3 -2 -1; -1 -2 -1];  B0 = [1 1; 2 1; 1 2];
## C0 = [1 0 0; 0 0 1];
## Ts = 0.01;  u = kron (sign (randn (400, 2)), ones (50, 1));
## y = lsim (c2d (ss (A0, B0, C0, zeros (2)), Ts), u);
## y = y + 0.3 * std (y) .* randn (size (y));
## M = ssbcgpmf (iddata (y, u, Ts), [2 1], [3; 3], [-1; -1]);
## M.A
## @end example
## @seealso{sslsgpmf, ssivgpmf, idss}
## @end deftypefn

function varargout = ssbcgpmf (varargin)
  varargout = contsid_guard ("ssbcgpmf", @ssbcgpmf_body, nargout, varargin);
endfunction

function [M, varargout] = ssbcgpmf_body (varargin)
  contsid_nargchk ("ssbcgpmf", nargin, nargout, [4 5], 1);
  M = contsid_gpmf ("ssbcgpmf", varargin);
endfunction

%!function H = gpmf_freq (A, B, C, w)
%!  H = zeros (rows (C), columns (B), numel (w));
%!  for k = 1:numel (w)
%!    H(:,:,k) = C * ((1i * w(k) * eye (rows (A)) - A) \ B);
%!  endfor
%!endfunction

## The system of the sslsgpmf tests (observability indices [2 1], poles
## -1 +- i and -2); one artificial root -0.5 per output.
%!shared A0, B0, C0, u, Ts, w, y, theta0
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
%! T = [C0(1,:); C0(1,:) * A0; C0(2,:)];
%! theta0 = [T * A0 / T, T * B0];

## Noise-free data: the compensated model is the true one, as the LS one,
## up to the O((lambda Ts)^2) filtering error.
%!test
%! M = ssbcgpmf (iddata (y, u, Ts), [2 1], [3; 3], [-0.5; -0.5]);
%! Mls = sslsgpmf (iddata (y, u, Ts), [2 1], [3; 3]);
%! assert (isa (M, "idss"));
%! assert (M.Ts, 0);
%! H0 = gpmf_freq (A0, B0, C0, w);
%! H = gpmf_freq (M.A, M.B, M.C, w);
%! assert (max (abs (H(:) - H0(:))) / max (abs (H0(:))) < 1e-3);
%! assert (norm ([M.A, M.B] - [Mls.A, Mls.B]) < 1e-2);

## White output noise (10 dB): the LS estimate is biased, the compensated
## one is over ten times closer to the truth (one root row for both
## outputs gives the same model as one row per output).
%!test
%! state = randn ("state");
%! randn ("state", 11);
%! yn = y + 10^(-10/20) * std (y) .* randn (size (y));
%! randn ("state", state);
%! data = iddata (yn, u, Ts);
%! Mls = sslsgpmf (data, [2 1], [3; 3]);
%! Mbc = ssbcgpmf (data, [2 1], [3; 3], -0.5);
%! err_ls = norm ([Mls.A, Mls.B] - theta0);
%! err_bc = norm ([Mbc.A, Mbc.B] - theta0);
%! assert (err_bc < err_ls / 10);
%! M2 = ssbcgpmf (data, [2 1], [3; 3], [-0.5; -0.5]);
%! assert (M2.A, Mbc.A);

%!error <at least 4> ssbcgpmf (iddata ((1:10)', (1:10)', 1), 1, 3)
%!error id=ssbcgpmf:badInput ssbcgpmf ((1:10)', [1 1], [3; 3], -1)
%!error id=ssbcgpmf:badInput ...
%! ssbcgpmf (iddata (rand (50, 2), rand (50, 1), 1), [1 1], [3; 3], 0.5)
%!error id=ssbcgpmf:badInput ...
%! ssbcgpmf (iddata (rand (50, 2), rand (50, 1), 1), [1 1], [3; 3], [])
%!error id=ssbcgpmf:dimensionMismatch ...
%! ssbcgpmf (iddata (rand (50, 2), rand (50, 1), 1), [1 1], [3; 3],
%!           [-1; -1; -1])
%!error id=ssbcgpmf:dimensionMismatch ...
%! ssbcgpmf (iddata (rand (50, 2), rand (50, 1), 1), [1 1 1], [3; 3], -1)
%!error id=ssbcgpmf:badInput ...
%! ssbcgpmf (iddata (rand (50, 2), rand (50, 1), 1), [1 1], [3; 3], -1, 2.5)
%!error id=ssbcgpmf:numericalFailure ...
%! ssbcgpmf (iddata (rand (50, 2), zeros (50, 1), 1), [1 1], [3; 3], -1)
%!error id=ssbcgpmf:notSupported ...
%! ssbcgpmf (iddata (rand (50, 2), rand (50, 1), [], "SamplingInstants",
%!           cumsum (0.5 + rand (50, 1))), [1 1], [3; 3], -1)

%!demo
%! pkg load control;
%! A0 = [0 1 0; -3 -2 -1; -1 -2 -1];  B0 = [1 1; 2 1; 1 2];
%! C0 = [1 0 0; 0 0 1];  Ts = 0.01;
%! u = kron (sign (randn (400, 2)), ones (50, 1));
%! y = lsim (c2d (ss (A0, B0, C0, zeros (2)), Ts), u);
%! y = y + 0.3 * std (y) .* randn (size (y));
%! Mls = sslsgpmf (iddata (y, u, Ts), [2 1], [3; 3]);
%! Mbc = ssbcgpmf (iddata (y, u, Ts), [2 1], [3; 3], [-1; -1]);
%! disp ([Mls.A, Mls.B]); disp ([Mbc.A, Mbc.B]); disp ([A0, B0]);
