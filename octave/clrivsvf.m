## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn  {} {@var{thm} =} clrivsvf (@var{data}, @var{nn}, "lambda_svf", @var{lam}, "controller", @var{C}, "r1", @var{r1}, "r2", @var{r2}, @dots{})
## @deftypefnx {} {[@var{thm}, @var{yh}, @var{pset}, @var{info}] =} clrivsvf (@dots{})
## Closed-loop recursive IV state-variable filter estimation (CLRIVSVF) of a
## continuous-time plant with time-varying parameters, operating in the
## loop u = r1 + C(q^-1) (r2 - y) with a known discrete controller.
##
## @var{data} holds the measured plant input u and output y; @var{nn} =
## [na nb nk] and @var{thm} = [a1 .. a_na, b0 .. b_(nb-1)] as in
## @code{rivsvf}, whose options all apply (@code{tsiv} also "auto", see
## @code{rlsconverge}). Closed-loop options:
## @table @code
## @item controller
## the controller C(q^-1): a struct with fields @code{num} and @code{den}
## (coefficients of q^0, q^-1, ..), or with @code{kp}, @code{ki}, @code{kd}
## for the backward-Euler PID kp + ki Ts/(1 - q^-1) + (kd/Ts)(1 - q^-1)
## (the reading of thesis eq. 2.55 that keeps example 2.4.6 stable).
## @item r1, r2
## the external signals (N-by-1); at least one is required, a missing one
## is zero.
## @end table
##
## @strong{Algorithm.} As RIVSVF, but the instruments come from the
## closed-loop auxiliary model (thesis eqs. 2.51-2.53): the estimated plant
## A(p, theta) x_hat = B(p, theta) u_hat in a loop with the known controller,
## u_hat = r1 + C (r2 - x_hat), so they are free of the noise fed back
## through u. Reference: A. Padilla, PhD thesis, 2017, sec. 2.4.
##
## @strong{Example}
## @example
## Ts = 0.01; r1 = prbs (12, 20); N = numel (r1);
## C = struct ("kp", 0.5, "ki", 2, "kd", 0);
## [y, x, u] = simc (struct ("B", 200, "F", [1 10 160]), r1, Ts, ...
##                   "controller", C, "r2", zeros (N, 1), "noisevar", 0.01);
## data = iddata (y, u, Ts, "InterSample", "zoh");
## thm = clrivsvf (data, [2 1 0], "lambda_svf", 16, "controller", C, ...
##                 "r1", r1);
## @end example
## @seealso{clrsrivc, rivsvf, simc}
## @end deftypefn

function varargout = clrivsvf (varargin)
  varargout = contsid_guard ("clrivsvf", @clrivsvf_body, nargout, varargin);
endfunction

function varargout = clrivsvf_body (varargin)
  contsid_nargchk ("clrivsvf", nargin, nargout, [0 Inf], 4);
  [varargout{1:max(1, nargout)}] = contsid_riv ("clrivsvf", nargout,
                                                varargin{:});
endfunction

%!shared Ts, r1, C, y, x, u, N, truth
%! Ts = 0.005; r1 = prbs (12, 20); N = numel (r1);
%! C = struct ("kp", 0.5, "ki", 2, "kd", 0);
%! truth = [10 160 200];
%! [y, x, u] = simc (struct ("B", 200, "F", [1 10 160]), r1, Ts, ...
%!                   "controller", C, "r2", zeros (N, 1));

%!test  # noise-free closed loop: recovered
%! data = iddata (x, u, Ts, "InterSample", "zoh");
%! thm = clrivsvf (data, [2 1 0], "lambda_svf", 16, "controller", C, "r1", r1);
%! ## The error is that of the trapezoidal filtering of y, O(Ts^2):
%! ## measured 2.2e-3 (relative) at Ts = 0.01 s and 6e-4 at 0.005 s.
%! assert (norm (thm(end, :) - truth) / norm (truth) < 2e-3);

%!test  # controller as num/den equals the PID gains
%! data = iddata (x, u, Ts, "InterSample", "zoh");
%! a = clrivsvf (data, [2 1 0], "lambda_svf", 16, "controller", C, "r1", r1);
%! Cd = struct ("num", [0.5 + 2 * Ts, -0.5], "den", [1 -1]);
%! b = clrivsvf (data, [2 1 0], "lambda_svf", 16, "controller", Cd, "r1", r1);
%! assert (a, b, 1e-9 * max (abs (a(:))));

%!test  # noise fed back: CLRIVSVF less biased than RLSSVF
%! randn ("state", 5);
%! [yn, xn, un] = simc (struct ("B", 200, "F", [1 10 160]), r1, Ts, ...
%!                      "controller", C, "r2", zeros (N, 1), "noisevar", 0.5);
%! data = iddata (yn, un, Ts, "InterSample", "zoh");
%! ls = rlssvf (data, [2 1 0], "lambda_svf", 16);
%! iv = clrivsvf (data, [2 1 0], "lambda_svf", 16, "controller", C, "r1", r1);
%! last = round (0.8 * N):N;
%! bias = @(thm) norm ((mean (thm(last, :)) - truth) ./ truth);
%! assert (bias (iv) < bias (ls) / 3);   # measured 0.01-0.03 vs 0.11-0.13

%!error id=clrivsvf:badOption clrivsvf (iddata (x, u, Ts), [2 1 0], "lambda_svf", 16, "r1", r1)
%!error id=clrivsvf:badOption clrivsvf (iddata (x, u, Ts), [2 1 0], "lambda_svf", 16, "controller", C)
%!error id=clrivsvf:dimensionMismatch clrivsvf (iddata (x, u, Ts), [2 1 0], "lambda_svf", 16, "controller", C, "r1", r1(1:10))
%!error id=clrivsvf:badInput clrivsvf (iddata (x, u, Ts), [2 1 0], "lambda_svf", 16, "controller", 3, "r1", r1)
%!error id=clrivsvf:badInput clrivsvf (iddata (x, u, Ts), [2 1 0], "lambda_svf", 16, "controller", struct ("num", 1, "den", 0), "r1", r1)
%!error id=clrivsvf:badInput clrivsvf (iddata (x, u, Ts), [2 1 0], "lambda_svf", 16, "controller", struct ("kp", "a", "ki", 1, "kd", 0), "r1", r1)
%!error id=clrivsvf:badInput clrivsvf (iddata (x, u, Ts), [2 1 0], "lambda_svf", 16, "controller", C, "r1", r1 + NaN)
%!error id=clrivsvf:badInput clrivsvf (iddata (x, u, Ts, "InterSample", "foh"), [2 1 0], "lambda_svf", 16, "controller", C, "r1", r1)

%!demo
%! Ts = 0.01; r1 = prbs (13, 20); N = numel (r1); t = (0:N-1)' * Ts;
%! C = struct ("kp", 0.5, "ki", 2, "kd", 0);
%! theta = [10 + 20 * t / t(end), 160 * ones(N, 1), 200 * ones(N, 1)];
%! [y, x, u] = simc (theta, [2 1 0], r1, Ts, "controller", C, ...
%!                   "r2", zeros (N, 1), "noisevar", 0.5);
%! data = iddata (y, u, Ts, "InterSample", "zoh");
%! opts = {"lambda_svf", 16, "adm", "kf", "adg", diag([1e-5 1e-8 1e-8])};
%! ls = rlssvf (data, [2 1 0], opts{:});
%! iv = clrivsvf (data, [2 1 0], opts{:}, "controller", C, "r1", r1);
%! plot (t, theta(:, 1), "k", t, ls(:, 1), "b", t, iv(:, 1), "r");
%! legend ("true a_1", "RLSSVF", "CLRIVSVF"); xlabel ("t (s)");
