## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn  {} {@var{M} =} sslsgpmf (@var{data}, @var{nni}, @var{param})
## @deftypefnx {} {@var{M} =} sslsgpmf (@var{data}, @var{nni}, @var{param}, @var{n0})
## Least-squares estimate of a multivariable continuous-time state-space
## model in observable canonical form by generalised Poisson moment
## functionals (GPMF).
##
## @var{data} is an @code{iddata} object with @var{p} outputs and @var{m}
## inputs (regular or irregular sampling, InterSample @qcode{"zoh"} or
## @qcode{"foh"}, the same for all inputs).  @var{nni} holds the @var{p}
## observability indices @var{n_i} of the outputs (their sum is the model
## order @var{n}); @var{param} the @var{p} Poisson filter parameters
## @var{lambda_i} (rad/s); the regression uses the samples from @var{n0}
## on (default 1: the data and the filters start at rest).
##
## The model is Guidorzi's observable canonical form of the indices
## @var{nni}: @code{y_i} is the first state of block @var{i}, each block a
## chain of integrators whose last row of @var{A} is free (the coupling to
## output @var{j} through @code{min (n_i + 1, n_j)} states for @var{j} <
## @var{i} and @code{min (n_i, n_j)} for @var{j} > @var{i}), @var{B}
## full and @var{D} = 0.  Each output gives one input-output differential
## equation, linear in its parameters; the GPMF of order @var{n_i} (the
## Poisson filter @code{(lambda_i/(p + lambda_i))^(n_i+1)}) turns it into a
## linear regression solved by least squares (Garnier, Sibille and Richard,
## CDC 1995).  With noisy outputs the estimate is biased: see
## @code{ssivgpmf}.
##
## @var{M} is a continuous-time @code{idss} (@var{Ts} = 0) with the
## estimated @var{A}, @var{B}, @var{C}, @var{D}.
##
## @strong{Example}
## @example
## A0 = [0 1 0; -3 -2 -1; -1 -2 -1];  B0 = [1 1; 2 1; 1 2];
## C0 = [1 0 0; 0 0 1];
## Ts = 0.01;  u = kron (sign (randn (200, 2)), ones (50, 1));
## y = lsim (c2d (ss (A0, B0, C0, zeros (2)), Ts), u);
## M = sslsgpmf (iddata (y, u, Ts), [2 1], [3; 3]);
## M.A
## @end example
## @seealso{ssivgpmf, idss, comparec}
## @end deftypefn

function varargout = sslsgpmf (varargin)
  varargout = contsid_guard ("sslsgpmf", @sslsgpmf_body, nargout, varargin);
endfunction

function [M, varargout] = sslsgpmf_body (varargin)
  contsid_nargchk ("sslsgpmf", nargin, nargout, [3 4], 1);
  M = contsid_gpmf ("sslsgpmf", varargin);
endfunction

## Frequency response C (jw I - A)^-1 B of a state-space model.
%!function H = gpmf_freq (A, B, C, w)
%!  H = zeros (rows (C), columns (B), numel (w));
%!  for k = 1:numel (w)
%!    H(:,:,k) = C * ((1i * w(k) * eye (rows (A)) - A) \ B);
%!  endfor
%!endfunction

## A stable 2-output 2-input system of order 3 in modal form (not in the
## canonical form); its observability indices are [2 1] (the rows C0(1,:),
## C0(2,:), C0(1,:) A0 are independent).
%!shared A0, B0, C0, u, t, Ts, w
%! A0 = [-1 1 0; -1 -1 0; 0 0 -2];
%! B0 = [1 0; 0 1; 1 1];
%! C0 = [1 0 1; 0 1 0];
%! Ts = 0.01;
%! t = (0:5999)' * Ts;
%! state = rand ("state");
%! rand ("state", 7);
%! u = kron (sign (rand (120, 2) - 0.5), ones (50, 1));
%! rand ("state", state);
%! w = logspace (-1, 1, 20);

## Noise-free ZOH data (control package's c2d and lsim): the model's
## frequency response equals the true one up to the trapezoidal filtering
## of y, O((lambda Ts)^2) = 1e-3 relative.  The canonical model is the
## true one in the coordinates x = [y1; y1' - B(1,:) u; y2], i.e.
## T = [C0(1,:); C0(1,:) A0; C0(2,:)]: A = T A0 / T, B = T B0 (parameters
## more sensitive than the response: 1e-2).
%!test
%! pkg load control;
%! y = lsim (c2d (ss (A0, B0, C0, zeros (2)), Ts, "zoh"), u);
%! M = sslsgpmf (iddata (y, u, Ts), [2 1], [3; 3]);
%! assert (isa (M, "idss"));
%! assert (M.Ts, 0);
%! assert (M.C, [1 0 0; 0 0 1]);
%! assert (M.D, zeros (2));
%! H0 = gpmf_freq (A0, B0, C0, w);
%! H = gpmf_freq (M.A, M.B, M.C, w);
%! assert (max (abs (H(:) - H0(:))) / max (abs (H0(:))) < 1e-3);
%! T = [C0(1,:); C0(1,:) * A0; C0(2,:)];
%! assert (M.A, T * A0 / T, 1e-2);
%! assert (M.B, T * B0, 1e-2);

## Indices [1 2]: a system given in that canonical form (y1' depends on
## y1 and y2 only) is recovered parameter by parameter.
%!test
%! pkg load control;
%! A1 = [-2 1 0; 0 0 1; 0.5 -2 -2];
%! C1 = [1 0 0; 0 1 0];
%! y = lsim (c2d (ss (A1, B0, C1, zeros (2)), Ts, "zoh"), u);
%! M = sslsgpmf (iddata (y, u, Ts), [1 2], [3; 3]);
%! assert (M.C, C1);
%! assert (M.A, A1, 1e-2);
%! assert (M.B, B0, 1e-2);

## FOH data: control's lsim of the continuous-time system interpolates the
## input linearly between samples.
%!test
%! pkg load control;
%! uf = sin ([0.7 * t, 1.9 * t]) + cos ([0.31 * t, 1.3 * t]);
%! y = lsim (ss (A0, B0, C0, zeros (2)), uf, t);
%! M = sslsgpmf (iddata (y, uf, Ts, "InterSample", "foh"), [2 1], [3; 3]);
%! H0 = gpmf_freq (A0, B0, C0, w);
%! H = gpmf_freq (M.A, M.B, M.C, w);
%! assert (max (abs (H(:) - H0(:))) / max (abs (H0(:))) < 1e-3);

## Irregular sampling: the same record with about 30 % of its samples
## dropped at random, never one where u steps (so that u stays piecewise
## constant between the instants kept).
%!test
%! pkg load control;
%! y = lsim (c2d (ss (A0, B0, C0, zeros (2)), Ts, "zoh"), u);
%! state = rand ("state");
%! rand ("state", 3);
%! keep = find (rand (6000, 1) > 0.3 | mod ((0:5999)', 50) == 0);
%! rand ("state", state);
%! M = sslsgpmf (iddata (y(keep,:), u(keep,:), "SamplingInstants", t(keep)),
%!               [2 1], [3; 3]);
%! H0 = gpmf_freq (A0, B0, C0, w);
%! H = gpmf_freq (M.A, M.B, M.C, w);
%! assert (max (abs (H(:) - H0(:))) / max (abs (H0(:))) < 1e-3);

## n0 skips the first samples: with data that do not start at rest the
## filter transient of the initial condition dies out.
%!test
%! pkg load control;
%! y = lsim (c2d (ss (A0, B0, C0, zeros (2)), Ts, "zoh"), u);
%! M = sslsgpmf (iddata (y(1001:end,:), u(1001:end,:), Ts), [2 1], [3; 3],
%!               1001);
%! H0 = gpmf_freq (A0, B0, C0, w);
%! H = gpmf_freq (M.A, M.B, M.C, w);
%! assert (max (abs (H(:) - H0(:))) / max (abs (H0(:))) < 1e-3);

%!error <at least 3> sslsgpmf (iddata ((1:10)', (1:10)', 1), 1)
%!error id=sslsgpmf:badInput sslsgpmf ((1:10)', [1 1], [3; 3])
%!error id=sslsgpmf:dimensionMismatch ...
%! sslsgpmf (iddata (rand (50, 2), rand (50, 1), 1), [1 1 1], [3; 3])
%!error id=sslsgpmf:dimensionMismatch ...
%! sslsgpmf (iddata (rand (50, 2), rand (50, 1), 1), [1 1], 3)
%!error id=sslsgpmf:badInput ...
%! sslsgpmf (iddata (rand (50, 2), rand (50, 1), 1), [1 0], [3; 3])
%!error id=sslsgpmf:badInput ...
%! sslsgpmf (iddata (rand (50, 2), rand (50, 1), 1), [1 1.5], [3; 3])
%!error id=sslsgpmf:badInput ...
%! sslsgpmf (iddata (rand (50, 2), rand (50, 1), 1), [1 1], [3; -1])
%!error id=sslsgpmf:badInput ...
%! sslsgpmf (iddata (rand (50, 2), rand (50, 1), 1), [1 1], [3; 3], 0)
%!error id=sslsgpmf:badInput ...
%! sslsgpmf (iddata (rand (50, 2), rand (50, 1), 1), [1 1], [3; 3], 49)
%!error id=sslsgpmf:badInput ...
%! sslsgpmf (iddata (rand (50, 2), rand (50, 1), 1), [1 1], [3; NaN])
%!error id=sslsgpmf:numericalFailure ...
%! sslsgpmf (iddata (rand (50, 2), zeros (50, 1), 1), [1 1], [3; 3])

%!demo
%! pkg load control;
%! A0 = [0 1 0; -3 -2 -1; -1 -2 -1];  B0 = [1 1; 2 1; 1 2];
%! C0 = [1 0 0; 0 0 1];  Ts = 0.01;
%! u = kron (sign (randn (200, 2)), ones (50, 1));
%! y = lsim (c2d (ss (A0, B0, C0, zeros (2)), Ts), u);
%! M = sslsgpmf (iddata (y, u, Ts), [2 1], [3; 3]);
%! disp ([M.A, M.B]); disp ([A0, B0]);
