## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn  {} {@var{M} =} clsrivc (@var{data}, @var{datacl}, [@var{nb} @var{nf} @var{nk}], @var{Mc})
## @deftypefnx {} {[@var{M}, @var{RT2}, @var{YIC}, @var{info}] =} clsrivc (@dots{}, @var{name}, @var{value})
## Closed-loop simplified refined IV estimate (CLSRIVC, thesis eqs.
## 2.47-2.50) of a continuous-time plant in the loop
## u = r1 + C (r2 - y) (eq. 2.49b) with a known controller C.
##
## @var{data}: the measured plant input u and output y (iddata, ZOH);
## @var{datacl}: the external signals, N-by-2 [r1 r2], or one signal r
## (N-by-1, or an iddata with it as input, CONTSID's @code{iddata (y, r)})
## that enters the loop where option @code{"ReferenceAt"} says:
## @code{"input"} (default, r1 = r, r2 = 0: r added to the plant input, u
## = r - C y, as CONTSID's closedloop demos build their data) or
## @code{"setpoint"} (r2 = r, r1 = 0: u = C (r - y)). @var{Mc}: the
## controller, a struct with @code{num} and @code{den} (powers of
## q^-1), or @code{kp}, @code{ki}, @code{kd} (backward-Euler PID, thesis
## eq. 2.55), or a discrete control-package tf (ZOH data). Options and
## outputs as for @code{srivc}; the start is the closed-loop IVSVF (eq.
## 2.44), or the one @code{InitMethod} names (as @code{srivc}:
## @qcode{"sriv"} the default, @qcode{"ivgpmf"}/@qcode{"ivsvf"},
## @qcode{"lssvf"}, a model); the one-step starts are the open-loop
## IVSVF/LSSVF of y on the measured u, biased by the loop's noise but
## only the start of the closed-loop iterations.
##
## CONTSID's form: @var{Mc} a @strong{continuous-time} control-package
## @code{tf} C(p) = Nc/Dc (nk = 0). The auxiliary model is then the
## continuous closed loop x_hat = B (Nc r2 + Dc r1) / (F Dc + B Nc),
## u_hat = F (Nc r2 + Dc r1) / (F Dc + B Nc).
##
## The covariance is the IV sandwich sigma^2 (Z'Phi)^-1 Z'Z (Phi'Z)^-1 of
## the prefiltered instruments Z and regressors Phi (sigma^2 the
## simulation-error variance): it equals eq. 2.13's sigma^2 (Z'Z)^-1 when
## the instruments are the noise-free regressors (the loop given right)
## and remains the estimate's covariance (white noise) when they are built
## from another loop than the data's (e.g. r given at the wrong place).
##
## @strong{Example}
## @example
## Ts = 0.01; r1 = prbs (11, 20); N = numel (r1);
## C = struct ("kp", 0.5, "ki", 2, "kd", 0);
## [y, x, u] = simc (idctm (200, [1 10 160]), r1, Ts, "controller", C, ...
##                   "r2", zeros (N, 1), "noisevar", 0.05);
## M = clsrivc (iddata (y, u, Ts), r1, [1 2 0], C, "lambda", 16)
## @end example
## @seealso{srivc, clrsrivc}
## @end deftypefn

function varargout = clsrivc (varargin)
  varargout = contsid_guard ("clsrivc", @clsrivc_body, nargout, varargin);
endfunction

function [M, RT2, YIC, info, varargout] = clsrivc_body (varargin)
  contsid_nargchk ("clsrivc", nargin, nargout, [0 Inf], 4);
  [M, RT2, YIC, info] = contsid_offline ("clsrivc", varargin);
endfunction

%!shared Ts, r1, C, y, x, u, N
%! Ts = 0.01; r1 = prbs (11, 20); N = numel (r1);
%! C = struct ("kp", 0.5, "ki", 2, "kd", 0);
%! [y, x, u] = simc (idctm (200, [1 10 160]), r1, Ts, "controller", C, ...
%!                   "r2", zeros (N, 1));

%!test  # noise-free closed loop: exact
%! M = clsrivc (iddata (x, u, Ts), r1, [1 2 0], C, "lambda", 16);
%! assert (M.theta, [10 160 200], 1e-7);

%!test  # noise-free: every start method gives the exact system; the
%! # LSSVF start is lssvf's open-loop estimate of y on u
%! for init = {"sriv", "ivgpmf", "lssvf"}
%!   M = clsrivc (iddata (x, u, Ts), r1, [1 2 0], C, "lambda", 16,
%!                "InitMethod", init{1});
%!   assert (M.theta, [10 160 200], 1e-7);
%! endfor
%! s = M.Report.Parameters.InitMethod;
%! Ml = lssvf (iddata (x, u, Ts), [2 1 0], 16);
%! assert (s.Theta, Ml.theta, 1e-12);

%!error id=clsrivc:badOption clsrivc (iddata (x, u, Ts), r1, [1 2 0], C, "InitMethod", "pem")

%!test  # controller given as num/den and as a discrete tf
%! Cd = struct ("num", [0.5 + 2 * Ts, -0.5], "den", [1 -1]);
%! a = clsrivc (iddata (x, u, Ts), [r1 zeros(N, 1)], [1 2 0], Cd, "lambda", 16);
%! assert (a.theta, [10 160 200], 1e-7);
%! pkg load control
%! b = clsrivc (iddata (x, u, Ts), r1, [1 2 0], tf ([0.5 + 2 * Ts, -0.5], [1 -1], Ts), "lambda", 16);
%! assert (b.theta, a.theta, 1e-9);

%!test  # CONTSID form: continuous-time controller, datacl = iddata (y, r),
%! # r the setpoint (u = Cc (r - y))
%! pkg load control
%! Tsc = 0.005; Nc = 4000; tc = (0:Nc-1)' * Tsc;
%! randn ("state", 2);
%! r = kron (sign (randn (Nc / 100, 1)), ones (100, 1));
%! G = tf (3, [1 2 3]); Cc = tf ([0.5 1], [1 0]);
%! [a, b, c, d] = ssdata (feedback (G * Cc, 1));
%! [a2, b2, c2, d2] = ssdata (feedback (Cc, G));
%! yc = zeros (Nc, 1); uc = zeros (Nc, 1);
%! E = expm ([a b; zeros(1, rows (a) + 1)] * Tsc);
%! E2 = expm ([a2 b2; zeros(1, rows (a2) + 1)] * Tsc);
%! s1 = zeros (rows (a), 1); s2 = zeros (rows (a2), 1);
%! for k = 1:Nc
%!   yc(k) = c * s1 + d * r(k); uc(k) = c2 * s2 + d2 * r(k);
%!   s1 = E(1:end-1, 1:end-1) * s1 + E(1:end-1, end) * r(k);
%!   s2 = E2(1:end-1, 1:end-1) * s2 + E2(1:end-1, end) * r(k);
%! endfor
%! yn = yc + 0.01 * randn (Nc, 1);
%! [M, ~, ~, info] = clsrivc (iddata (yn, uc, Tsc), iddata (yn, r, Tsc),
%!                            [1 2 0], Cc, "ReferenceAt", "setpoint");
%! assert (info.converged && info.stable);
%! assert (M.theta, [2 3 3], 0.05);
%! M2 = clsrivc (iddata (yn, uc, Tsc), [0 * r, r], [1 2 0], Cc);
%! assert (M2.theta, M.theta, 1e-10);

%!test  # CONTSID form, r at the plant input (u = r - Cc y, the default, as
%! # CONTSID's closedloop demos build their data): r a binary signal
%! # through 10 / (s + 10), so that u is continuous; noise-free exact to
%! # O((w Ts)^2), [r 0] the same
%! pkg load control
%! Tsc = 0.005; Nc = 4000; randn ("state", 3);
%! W = tf (10, [1 10]);
%! v = kron (sign (randn (Nc / 100, 1)), ones (100, 1));
%! G = tf (3, [1 2 3]); Cc = tf ([0.5 1], [0.1 1 0]);
%! r = lsim (c2d (W, Tsc), v);
%! yc = lsim (c2d (feedback (G, Cc) * W, Tsc), v);
%! uc = lsim (c2d (feedback (1, G * Cc) * W, Tsc), v);
%! dat = iddata (yc, uc, Tsc, "InterSample", "foh");
%! a = clsrivc (dat, iddata (yc, r, Tsc), [1 2 0], Cc);
%! b = clsrivc (dat, [r, 0 * r], [1 2 0], Cc, "ReferenceAt", "setpoint");
%! assert (a.theta, [2 3 3], 1e-3);
%! assert (b.theta, a.theta, 1e-10);

%!test  # reported sd against a small Monte Carlo on exact closed-loop data
%! # (discrete PI, ZOH plant exact at the samples, white noise fed back;
%! # 20 runs, the sample sd's relative sd ~16 %; the 100-run check,
%! # also with a continuous controller: devel/monte_carlo/closed_loop_mc.m, 0.94-1.12)
%! pkg load control
%! randn ("state", 17);
%! Tm = 0.01; Nm = 2000; kp = 0.5; ki = 2;
%! Cd = tf ([kp + ki * Tm, -kp], [1 -1], Tm);
%! Gd = c2d (tf (200, [1 10 160]), Tm, "zoh");
%! r = kron (sign (randn (Nm / 50, 1)), ones (50, 1));
%! yr = lsim (feedback (Gd, Cd), r); ur = lsim (feedback (1, Gd * Cd), r);
%! Sye = feedback (1, Gd * Cd); Sue = -feedback (Cd, Gd);
%! R = 20; T = S = zeros (R, 3);
%! for i = 1:R
%!   e = 0.1 * std (yr) * randn (Nm, 1);
%!   M = clsrivc (iddata (yr + lsim (Sye, e), ur + lsim (Sue, e), Tm), r,
%!                [1 2 0], struct ("kp", kp, "ki", ki, "kd", 0));
%!   T(i, :) = M.theta; S(i, :) = sqrt (diag (M.covariance)).';
%! endfor
%! ratio = std (T) ./ mean (S);
%! assert (all (ratio > 0.6 & ratio < 1.6), sprintf ("%g ", ratio));
%! assert (all (abs (mean (T) - [10 160 200]) < 3 * std (T) / sqrt (R) + 0.1 * mean (S)));

%!error <unstable> clsrivc (iddata (x, u, Ts), r1, [1 2 0], struct ("num", [-50 0], "den", [1 0]), "lambda", 16)
%!error id=clsrivc:badInput clsrivc (iddata (x, u, Ts), r1, [1 2 0])
%!error id=clsrivc:dimensionMismatch clsrivc (iddata (x, u, Ts), r1(1:10), [1 2 0], C, "lambda", 16)
%!error id=clsrivc:badInput clsrivc (iddata (x, u, Ts), {1}, [1 2 0], C, "lambda", 16)
%!error id=clsrivc:badOption clsrivc (iddata (x, u, Ts), r1, [1 2 0], C, "ReferenceAt", "output")
%!error id=clsrivc:badOption clsrivc (iddata (x, u, Ts), r1, [1 2 0], C, "ReferenceAt", 1)
%!error id=clsrivc:badInput clsrivc (iddata (x, u, Ts), r1, [1 2 0], 3, "lambda", 16)
%!error id=clsrivc:badInput clsrivc (iddata (x, u, Ts), r1, [1 2 0], struct ("num", 1, "den", 0), "lambda", 16)

%!demo
%! Ts = 0.01; r1 = prbs (11, 20); N = numel (r1);
%! C = struct ("kp", 0.5, "ki", 2, "kd", 0);
%! [y, x, u] = simc (idctm (200, [1 10 160]), r1, Ts, "controller", C, ...
%!                   "r2", zeros (N, 1), "noisevar", 0.05);
%! M = clsrivc (iddata (y, u, Ts), r1, [1 2 0], C, "lambda", 16)
