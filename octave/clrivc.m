## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn  {} {@var{M} =} clrivc (@var{data_yu}, @var{data_yr}, [@var{nb} @var{nc} @var{nd} @var{nf} @var{nk}], @var{Mc})
## @deftypefnx {} {@var{M} =} clrivc (@dots{}, @var{Mc}, @var{T0}, @var{tol}, @var{maxiter})
## @deftypefnx {} {@var{M} =} clrivc (@dots{}, "ReferenceAt", @var{at}, "InitMethod", @var{init})
## @deftypefnx {} {[@var{M}, @var{C}, @var{D}] =} clrivc (@dots{})
## Closed-loop refined IV (CLRIVC) of the hybrid Box-Jenkins model
## @example
## y(t_k) = B(p)/F(p) u(t_k) + C(q^-1)/D(q^-1) e(t_k),
## u(t) = r1(t) + Mc(p) (r2(t) - y(t)),
## @end example
## with a known continuous-time controller Mc = Nc/Dc. As @code{rivc}
## (core/include/ctid/offline/refined_iv_bj.hpp), but the instruments come
## from the closed loop driven by the external signals: x_hat = B (Nc r2 +
## Dc r1) / (F Dc + B Nc) and u_hat = F (Nc r2 + Dc r1) / (F Dc + B Nc)
## (thesis eqs. 2.48-2.49b with a continuous controller), prefiltered by
## 1/F(p) and then D/C; the regressors use the measured y and u, and the
## noise model is fitted to y - B/F u. The start is CLSRIVC with the same
## controller, or the one the trailing option @code{InitMethod} names:
## @qcode{"sriv"} (= @qcode{"srivc"}, default: CLSRIVC),
## @qcode{"ivgpmf"} (= @qcode{"ivsvf"}: one IVSVF estimate, thesis eqs.
## 2.4-2.7, whose state-variable filter (lambda/(p + lambda))^n is
## CONTSID's Poisson-moment-functional filter), @qcode{"lssvf"} (one LSSVF
## estimate, eq. 1.32), an @code{idpoly} or [f b]. The one-step starts
## are the open-loop estimates of y on the measured u (biased by the
## loop's noise, they only start the iterations), computed by the core
## (as @code{lssvf}, @code{ivsvf}) at the one of 12 cut-offs log-spaced
## between 5/T and 0.5 pi/Ts whose estimate has the smallest simulation
## error; an unstable one has its right-half-plane poles reflected
## (p -> -conj (p)) with the warning @code{clrivc:unstableStart}.
## @code{M.Report.Parameters.InitMethod} says which start was used.
##
## @var{data_yu}: @code{iddata (y, u, Ts)} (regular sampling; u is
## filtered by its InterSample rule, 'foh' suits a continuous controller
## output); @var{data_yr}: @code{iddata (y, r, Ts)} or r itself (N-by-1,
## held between samples), or N-by-2 [r1 r2]. One signal r enters where
## @var{at} says: @code{"input"} (default: r1 = r, u = r - Mc y, as
## CONTSID's closedloop demos build their data) or @code{"setpoint"} (r2
## = r, u = Mc (r - y)). nn = [nb nc nd nf nk] with nk = 0; @var{Mc}: a
## continuous-time control-package @code{tf}, an @code{idpoly}/@code{idtf}
## with Ts = 0, or a struct with @code{num} and @code{den} (descending
## powers of s). @var{T0}: CONTSID's first sample, only 1 (the whole
## record); @var{tol} (1e-6) and @var{maxiter} (30).
##
## @var{M}: a continuous-time @code{idpoly} with the covariance
## sigma_e^2 (Z'Phi)^-1 Z'Z (Phi'Z)^-1 (the IV sandwich of the prefiltered
## instruments Z and regressors Phi; it equals sigma_e^2 (sum zeta_f
## zeta_f')^-1 when the instruments are the noise-free regressors, and
## stays right when they come from another loop than the data's) and
## @code{Report.Parameters.NoiseModel};
## @var{C}, @var{D}: the noise polynomials (q^-1).
##
## @strong{Example}
## @example
## pkg load control
## Ts = 0.01; N = 6000; r = kron (sign (randn (N / 100, 1)), ones (100, 1));
## G = tf (3, [1 2 3]); Mc = tf ([0.5 1], [0.1 1 0]);
## y = lsim (c2d (feedback (G * Mc, 1), Ts), r);
## u = lsim (c2d (feedback (Mc, G), Ts), r);
## M = clrivc (iddata (y, u, Ts, "InterSample", "foh"), iddata (y, r, Ts),
##             [1 1 1 2 0], Mc, 1, "ReferenceAt", "setpoint")
## @end example
## @seealso{rivc, clsrivc, cl2srivc}
## @end deftypefn

function varargout = clrivc (varargin)
  varargout = contsid_guard ("clrivc", @clrivc_body, nargout, varargin);
endfunction

function [M, C, varargout] = clrivc_body (varargin)
  contsid_nargchk ("clrivc", nargin, nargout, [4 11], 3);
  [M, info] = contsid_rivc ("clrivc", varargin);
  C = info.C;
  varargout = {info.D}(1:max (nargout - 2, 0));
endfunction

%!shared y, u, r, Ts, N, Mc, G
%! pkg load control
%! Ts = 0.01; N = 6000; randn ("state", 3);
%! r = kron (sign (randn (N / 100, 1)), ones (100, 1));
%! G = tf (3, [1 2 3]); Mc = tf ([0.5 1], [0.1 1 0]);
%! y = lsim (c2d (feedback (G * Mc, 1), Ts), r);
%! u = lsim (c2d (feedback (Mc, G), Ts), r);

%!test  # noise-free closed loop, r the setpoint: exact up to the FOH rule
%! # on the measured (continuous, not piecewise linear) u: O((w Ts)^2)
%! [M, C, D] = clrivc (iddata (y, u, Ts, "InterSample", "foh"), ...
%!                     iddata (y, r, Ts), [1 1 1 2 0], Mc, 1, ...
%!                     "ReferenceAt", "setpoint");
%! assert (M.theta, [2 3 3], 1e-3);
%! assert (size (C), [1 2]);
%! assert (size (D), [1 2]);

%!test  # controller as a struct and as an idpoly, the setpoint as
%! # [r1 r2] = [0 r]: the same estimate
%! a = clrivc (iddata (y, u, Ts, "InterSample", "foh"), r, [1 1 1 2 0], ...
%!             struct ("num", [0.5 1], "den", [0.1 1 0]), ...
%!             "ReferenceAt", "setpoint");
%! b = clrivc (iddata (y, u, Ts, "InterSample", "foh"), [0 * r, r], ...
%!             [1 1 1 2 0], ...
%!             idpoly ([0.1 1 0] / 0.1, [0.5 1] / 0.1, 1, 1, 1, 0, "Ts", 0));
%! assert (a.theta, b.theta, 1e-8);
%! assert (a.theta, [2 3 3], 1e-3);

%!test  # r at the plant input (u = r - Mc y, CONTSID's closedloop demos,
%! # the default): a binary signal through 10 / (s + 10), so that u is
%! # continuous; noise-free exact to O((w Ts)^2), [r 0] the same
%! W = tf (10, [1 10]);
%! r1 = lsim (c2d (W, Ts), r);
%! y1 = lsim (c2d (feedback (G, Mc) * W, Ts), r);
%! u1 = lsim (c2d (feedback (1, G * Mc) * W, Ts), r);
%! a = clrivc (iddata (y1, u1, Ts, "InterSample", "foh"), ...
%!             iddata (y1, r1, Ts), [1 0 0 2 0], Mc);
%! b = clrivc (iddata (y1, u1, Ts, "InterSample", "foh"), [r1, 0 * r1], ...
%!             [1 0 0 2 0], Mc);
%! assert (a.theta, [2 3 3], 1e-3);
%! assert (a.theta, b.theta, 1e-10);

%!test  # coloured output noise: within the reported sd
%! randn ("state", 4);
%! v = filter ([1 0.3], [1 -0.95], 0.005 * randn (N, 1));
%! ## the loop feeds the noise back: simulate it through the sensitivity
%! yn = y + lsim (c2d (feedback (1, G * Mc), Ts), v);
%! un = u - lsim (c2d (feedback (Mc, G), Ts), v);
%! [M, C, D] = clrivc (iddata (yn, un, Ts, "InterSample", "foh"), r, ...
%!                     [1 1 1 2 0], Mc, "ReferenceAt", "setpoint");
%! sd = sqrt (diag (M.covariance)).';
%! assert (all (abs (M.theta - [2 3 3]) < 4 * sd + 2e-3));
%! assert (D(2), -0.95, 0.05);

%!test  # every start method: the same noise-free estimate (exact up to
%! # the FOH rule on u, see above; the starts' fixed points agree to 1e-6)
%! z = iddata (y, u, Ts, "InterSample", "foh");
%! M0 = clrivc (z, r, [1 1 1 2 0], Mc, 1, 1e-10, 30, "ReferenceAt", "setpoint");
%! for init = {"sriv", "ivgpmf", "lssvf", [2 3 3]}
%!   M = clrivc (z, r, [1 1 1 2 0], Mc, 1, 1e-10, 30,
%!               "ReferenceAt", "setpoint", "InitMethod", init{1});
%!   assert (M.theta, M0.theta, 1e-6);
%!   assert (M.theta, [2 3 3], 1e-3);
%! endfor

%!test  # the start is lssvf's open-loop estimate (y on u) and is used
%! randn ("state", 4);
%! v = filter ([1 0.3], [1 -0.95], 0.005 * randn (N, 1));
%! yn = y + lsim (c2d (feedback (1, G * Mc), Ts), v);
%! un = u - lsim (c2d (feedback (Mc, G), Ts), v);
%! z = iddata (yn, un, Ts, "InterSample", "foh");
%! warning ("off", "clrivc:notConverged", "local");
%! M1 = clrivc (z, r, [1 1 1 2 0], Mc, 1, 1e-6, 1, "ReferenceAt",
%!              "setpoint", "InitMethod", "lssvf");
%! M1m = clrivc (z, r, [1 1 1 2 0], Mc, 1, 1e-6, 1, "ReferenceAt",
%!               "setpoint", "InitMethod",
%!               M1.Report.Parameters.InitMethod.Theta);
%! assert (M1.theta, M1m.theta, 1e-12 * norm (M1.theta));
%! s = M1.Report.Parameters.InitMethod;
%! Ml = lssvf (z, [2 1 0], s.Lambda);
%! assert (s.Theta, Ml.theta, 1e-12);
%! M0 = clrivc (z, r, [1 1 1 2 0], Mc, 1, 1e-6, 1, "ReferenceAt",
%!              "setpoint");
%! assert (norm (M1.theta - M0.theta) > 1e-6 * norm (M0.theta));

%!error id=clrivc:badOption clrivc (iddata (y, u, Ts), r, [1 1 1 2 0], Mc, "InitMethod", "magic")
%!error id=clrivc:badOption clrivc (iddata (y, u, Ts), r, [1 1 1 2 0], Mc, "InitMethod", [1 2])
%!error id=clrivc:badInput clrivc (iddata (y, u, Ts), r, [1 1 1 2 0])
%!error id=clrivc:badInput clrivc (iddata (y, u, Ts), r, [1 1 1 2 0], Mc, 1, 1e-6, 30, 4)
%!error id=clrivc:badInput clrivc (iddata (y, u, Ts), r, [1 1 1 2], Mc)
%!error id=clrivc:dimensionMismatch clrivc (iddata (y, u, Ts), r(1:10), [1 1 1 2 0], Mc)
%!error id=clrivc:badInput clrivc (iddata (y, u, Ts), [r r r], [1 1 1 2 0], Mc)
%!error id=clrivc:badOption clrivc (iddata (y, u, Ts), r, [1 1 1 2 0], Mc, "ReferenceAt", "output")
%!error id=clrivc:badOption clrivc (iddata (y, u, Ts), r, [1 1 1 2 0], Mc, "Reference", "input")
%!error id=clrivc:badInput clrivc (iddata (y, u, Ts), r, [1 1 1 2 0], Mc, "ReferenceAt")
%!error id=clrivc:badInput clrivc (iddata (y, u, Ts), {r}, [1 1 1 2 0], Mc)
%!error id=clrivc:badInput clrivc (iddata (y, u, Ts), r, [1 1 1 2 0], 3)
%!error id=clrivc:badInput clrivc (iddata (y, u, Ts), r, [1 1 1 2 0], tf (1, [1 1], 0.1))
%!error id=clrivc:badInput clrivc (iddata (y, u, Ts), r, [1 1 1 2 0], struct ("num", [1 2 3], "den", [1 1]))
%!error id=clrivc:badInput clrivc (iddata (y, u, Ts), r, [1 1 1 2 0], struct ("num", 1, "den", 0))
%!error id=clrivc:notSupported clrivc (iddata (y, u, Ts), r, [1 1 1 2 0], Mc, 2)
%!error id=clrivc:notSupported clrivc (iddata (y, u, Ts), r, [1 1 1 2 1], Mc)
%!error id=clrivc:badOption clrivc (iddata (y, u, Ts), r, [1 1 1 2 0], Mc, 1, -1)
%!error id=clrivc:badOption clrivc (iddata (y, u, Ts), r, [1 1 1 2 0], Mc, 1, 1e-6, 0)
%!error id=clrivc:numericalFailure clrivc (iddata (y, u, Ts), r, [1 1 1 2 0], struct ("num", -50, "den", 1))

%!demo
%! pkg load control
%! Ts = 0.01; N = 6000; r = kron (sign (randn (N / 100, 1)), ones (100, 1));
%! G = tf (3, [1 2 3]); Mc = tf ([0.5 1], [0.1 1 0]);
%! y = lsim (c2d (feedback (G * Mc, 1), Ts), r);
%! u = lsim (c2d (feedback (Mc, G), Ts), r);
%! M = clrivc (iddata (y, u, Ts, "InterSample", "foh"), iddata (y, r, Ts),
%!             [1 1 1 2 0], Mc, 1, "ReferenceAt", "setpoint")
