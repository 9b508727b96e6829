## -*- texinfo -*-
## @deftypefn  {} {@var{M} =} clsrivc (@var{data}, @var{datacl}, [@var{nb} @var{nf} @var{nk}], @var{Mc})
## @deftypefnx {} {[@var{M}, @var{RT2}, @var{YIC}, @var{info}] =} clsrivc (@dots{}, @var{name}, @var{value})
## Closed-loop simplified refined IV estimate (CLSRIVC, thesis eqs.
## 2.47-2.50) of a continuous-time plant in the loop
## u = r1 + C(q^-1) (r2 - y) with a known discrete controller.
##
## @var{data}: the measured plant input u and output y (iddata, ZOH);
## @var{datacl}: the external signals, N-by-1 r1 (then r2 = 0) or N-by-2
## [r1 r2], or an iddata with those as inputs; @var{Mc}: the controller, a
## struct with @code{num} and @code{den} (powers of q^-1), or @code{kp},
## @code{ki}, @code{kd} (backward-Euler PID, thesis eq. 2.55), or a
## discrete control-package tf. Options and outputs as for @code{srivc};
## the start is the closed-loop IVSVF (eq. 2.44).
##
## CONTSID's form: @var{Mc} a @strong{continuous-time} control-package
## @code{tf} C(p) in the loop u = C(p) (r - y), and @var{datacl} =
## @code{iddata (y, r)} (its input is the reference r, or r itself as an
## N-by-1 vector). The auxiliary model is then the continuous closed loop
## x_hat = B Nc / (F Dc + B Nc) r, u_hat = F Nc / (F Dc + B Nc) r (nk = 0).
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

function [M, RT2, YIC, info, varargout] = clsrivc (varargin)
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

%!test  # controller given as num/den and as a discrete tf
%! Cd = struct ("num", [0.5 + 2 * Ts, -0.5], "den", [1 -1]);
%! a = clsrivc (iddata (x, u, Ts), [r1 zeros(N, 1)], [1 2 0], Cd, "lambda", 16);
%! assert (a.theta, [10 160 200], 1e-7);
%! pkg load control
%! b = clsrivc (iddata (x, u, Ts), r1, [1 2 0], tf ([0.5 + 2 * Ts, -0.5], [1 -1], Ts), "lambda", 16);
%! assert (b.theta, a.theta, 1e-9);

%!test  # CONTSID form: continuous-time controller, datacl = iddata (y, r)
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
%! [M, ~, ~, info] = clsrivc (iddata (yn, uc, Tsc), iddata (yn, r, Tsc), [1 2 0], Cc);
%! assert (info.converged && info.stable);
%! assert (M.theta, [2 3 3], 0.05);

%!test  # reported sd against a small Monte Carlo on exact closed-loop data
%! # (discrete PI, ZOH plant exact at the samples, white noise fed back;
%! # 20 runs, the sample sd's relative sd ~16 %; the 100-run check,
%! # also with a continuous controller: bench/closed_loop_mc.m, 0.94-1.12)
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
%!error id=clsrivc:badInput clsrivc (iddata (x, u, Ts), r1, [1 2 0], 3, "lambda", 16)
%!error id=clsrivc:badInput clsrivc (iddata (x, u, Ts), r1, [1 2 0], struct ("num", 1, "den", 0), "lambda", 16)

%!demo
%! Ts = 0.01; r1 = prbs (11, 20); N = numel (r1);
%! C = struct ("kp", 0.5, "ki", 2, "kd", 0);
%! [y, x, u] = simc (idctm (200, [1 10 160]), r1, Ts, "controller", C, ...
%!                   "r2", zeros (N, 1), "noisevar", 0.05);
%! M = clsrivc (iddata (y, u, Ts), r1, [1 2 0], C, "lambda", 16)
