## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn  {} {[@var{M}, @var{C}, @var{D}] =} rivc (@var{data}, [@var{nb} @var{nc} @var{nd} @var{nf} @var{nk}])
## @deftypefnx {} {[@var{M}, @var{C}, @var{D}, @var{RT2}, @var{YIC}, @var{Cond_IPM}, @var{AIC}] =} rivc (@dots{})
## @deftypefnx {} {@dots{} =} rivc (@var{data}, @var{Mi})
## @deftypefnx {} {@dots{} =} rivc (@dots{}, @var{name}, @var{value}, @dots{})
## Refined instrumental-variable estimate (RIVC, Young and Garnier) of the
## hybrid Box-Jenkins model
## @example
## y(t_k) = B(p)/F(p) u(t_k - nk Ts) + C(q^-1)/D(q^-1) e(t_k)
## @end example
## a continuous-time plant with a discrete-time ARMA noise model.
##
## Each iteration (core/include/ctid/offline/refined_iv_bj.hpp) simulates the
## auxiliary model x_hat = B/F u, fits an ARMA model D xi = C e to the
## noise estimate xi = y - x_hat (Hannan-Rissanen, then Gauss-Newton
## prediction-error steps), and solves the IV equations of thesis
## eqs. 2.10-2.12 with the hybrid prefilter: 1/F(p) in continuous time
## (exact ZOH/FOH filters), then D/C on the samples (eq. 2.9 with the
## Box-Jenkins optimal prefilter). The start is SRIVC (eqs. 2.8-2.13).
## With nc = nd = 0 this is SRIVC.
##
## @var{data}: an @code{iddata} (one output, regular sampling,
## InterSample 'zoh' or 'foh'). Orders: B has nb parameters (1 <= nb <=
## nf + 1), F order nf, C order nc, D order nd, delay nk samples.
##
## Several inputs (CONTSID's MISO form): nn = [nb_1 .. nb_m nc nd nf_1
## .. nf_m nk_1 .. nk_m], one denominator per input (CONTSID's default
## 'Different'): y = sum_i B_i/F_i u_i(t - nk_i Ts) + C/D e. Each
## iteration updates the inputs in turn (backfitting: input i's target is
## y minus the other inputs' auxiliary model outputs; Young's MISO refined
## IV with different denominators), the start is the MISO SRIVC. @code{M.B},
## @code{M.F} are then cells, @code{M.theta} = [f_1 .. f_m b_1 .. b_m]
## and @code{M.covariance} sigma_e^2 (sum zeta_f zeta_f')^-1 with the
## instruments of all inputs stacked (cross-input blocks included).
## @var{Mi}: an @code{idpoly} whose B, C, D, F give the orders and whose
## B, F start the iterations.
##
## Options:
## @table @code
## @item lambda
## SVF cut-off of the start, rad/s.
## @item Tol, MaxIter
## stop when the relative parameter change falls below Tol (default
## 1e-6), or after MaxIter iterations (default 30).
## @item InitMethod
## the model the iterations start from:
## @qcode{"sriv"} or @qcode{"srivc"} (default: SRIVC, from IVSVF starts
## at @code{lambda} or at 12 cut-offs log-spaced between 5/T and
## 0.5 pi/Ts), @qcode{"ivgpmf"} (one IVSVF estimate, thesis eqs.
## 2.4-2.7: CONTSID's IV with Poisson-moment-functional filtering is this
## state-variable filter (lambda/(p + lambda))^n; @qcode{"ivsvf"} is the
## same), @qcode{"lssvf"} (one LSSVF estimate, eq. 1.32), an
## @code{idpoly} or [f b]. The one-step starts are computed by the core's
## LSSVF/IVSVF (as @code{lssvf}, @code{ivsvf}) at @code{lambda}, or
## without it at the one of the 12 cut-offs above whose estimate has the
## smallest simulation error; an unstable one-step start has its
## right-half-plane poles reflected (p -> -conj (p)) with the warning
## @code{rivc:unstableStart} (a given model must be stable:
## @code{rivc:badInput}). @code{M.Report.Parameters.InitMethod} says which
## start was used (@code{Method}, @code{Requested}, @code{Lambda},
## @code{Theta} = its [f b], @code{Stabilised}).
## @item ArmaMaxIter, ArmaMethod
## the largest number of iterations of the noise model's estimator
## (default 50), and that estimator: @qcode{"pem"} (default), prediction
## error by Gauss-Newton from Hannan-Rissanen, or @qcode{"ivarma"},
## Young's IVARMA: the ARMA model's pseudo-linear regression solved
## iteratively by IV with the instruments prefiltered by 1/C, whose fixed
## point solves the prediction-error score equation (see
## @code{ivarma_estimate} in refined_iv_bj.hpp).
## @end table
## Unknown names, and values out of range: @code{rivc:badOption}.
##
## @var{M}: the hybrid Box-Jenkins model as a continuous-time
## @code{idpoly}: B(s)/F(s) with the covariance of [f b] (@code{M.theta},
## @code{M.covariance}: sigma_e^2 (sum zeta_f zeta_f')^-1, eq. 2.13 with
## the innovation variance sigma_e^2 of the noise model), and the noise
## model in @code{M.C}, @code{M.D} (q^-1 at the data's Ts, as the
## outputs @var{C}, @var{D}) and @code{M.NoiseVariance} = sigma_e^2;
## @code{present (M)} shows it as "hybrid BJ" with C(z), D(z),
## @code{getpvec}/@code{getcov} hold [b c d f] with the ARMA covariance
## of [c d] (the plant/noise cross-covariance is not estimated: zero);
## @code{Report.Parameters.NoiseModel} (C, D, NoiseVariance, Ts, the mark
## of the hybrid model) and @code{Report.Fit}. @var{C}, @var{D}: the
## noise polynomials in q^-1 (rows [1 c1 ..], [1 d1 ..]). @var{RT2}:
## 1 - var(y - x_hat)/var(y); @var{YIC}; @var{Cond_IPM}: the condition
## number of the instrumental product matrix; @var{AIC}:
## log(sigma_e^2) + 2 (nb + nf + nc + nd)/N. A run that does not
## converge warns @code{rivc:notConverged} and returns the last iterate.
##
## @strong{Example}
## @example
## pkg load control
## Ts = 0.05; u = kron (sign (randn (400, 1)), ones (10, 1));
## x = lsim (c2d (tf ([1.5 4], [1 1.2 4]), Ts), u);
## v = filter ([1 0.5], [1 -0.9], 0.3 * randn (4000, 1));
## [M, C, D] = rivc (iddata (x + v, u, Ts), [2 1 1 2 0])
## @end example
## @seealso{srivc, tfrivc, clrivc, cl2srivc}
## @end deftypefn

function varargout = rivc (varargin)
  varargout = contsid_guard ("rivc", @rivc_body, nargout, varargin);
endfunction

function [M, C, varargout] = rivc_body (varargin)
  contsid_nargchk ("rivc", nargin, nargout, [2 Inf], 7);
  [M, info] = contsid_rivc ("rivc", varargin);
  C = info.C;
  out = {info.D, info.RT2, info.YIC, info.condition, info.AIC};
  varargout = out(1:max (nargout - 2, 0));
endfunction

%!shared u, x, Ts, N, G
%! pkg load control
%! Ts = 0.05; N = 3000; randn ("state", 11);
%! u = kron (sign (randn (N / 10, 1)), ones (10, 1));
%! G = c2d (tf ([1.5 4], [1 1.2 4]), Ts);
%! x = lsim (G, u);

%!test  # noise-free: exact, with any ARMA orders
%! [M, C, D, RT2] = rivc (iddata (x, u, Ts), [2 1 2 2 0], "Tol", 1e-10);
%! assert (M.theta, [1.2 4 1.5 4], 1e-8);
%! assert (size (C), [1 2]);
%! assert (size (D), [1 3]);
%! assert (RT2, 1, 1e-10);
%! assert (size (M.covariance), [4 4]);

%!test  # nc = nd = 0: RIVC's iteration is SRIVC's; same fixed point
%! randn ("state", 3);
%! y = x + 0.1 * randn (N, 1);
%! Ms = srivc (iddata (y, u, Ts), [2 2 0], "Tol", 1e-12, "MaxIter", 200);
%! M = rivc (iddata (y, u, Ts), [2 0 0 2 0], "InitMethod", Ms, "Tol", 1e-10);
%! assert (M.theta, Ms.theta, 1e-6 * norm (Ms.theta));
%! M2 = rivc (iddata (y, u, Ts), [2 0 0 2 0]);
%! assert (M2.theta, Ms.theta, 1e-4 * norm (Ms.theta));

%!test  # the noise model of coloured noise, and the model-in form
%! randn ("state", 5);
%! v = filter ([1 0.5], [1 -0.9], 0.05 * randn (N, 1));
%! [M, C, D] = rivc (iddata (x + v, u, Ts), [2 1 1 2 0]);
%! assert (D(2), -0.9, 0.05);
%! assert (C(2), 0.5, 0.1);
%! sd = sqrt (diag (M.covariance)).';
%! assert (all (abs (M.theta - [1.2 4 1.5 4]) < 4 * sd));
%! Mi = idpoly (1, [1.5 4], [1 0], [1 0], [1 1.2 4], 1, 0);
%! M2 = rivc (iddata (x + v, u, Ts), Mi);
%! assert (M2.theta, M.theta, 1e-4 * norm (M.theta));

%!test  # the hybrid model: B/F in s, the noise model C/D (q^-1) in M
%! randn ("state", 6);
%! v = filter ([1 0.5], [1 -0.9], 0.05 * randn (N, 1));
%! [M, C, D] = rivc (iddata (x + v, u, Ts), [2 1 1 2 0]);
%! assert ({M.C, M.D}, {C, D});
%! assert (M.NoiseVariance, M.Report.Parameters.NoiseModel.NoiseVariance);
%! p = getpvec (M);  # [b0 b1 c1 d1 f1 f2]
%! P = getcov (M);
%! assert (p.', [M.B, C(2), D(2), M.F(2:3)]);
%! assert (M.theta, [M.F(2:3), M.B]);
%! assert (P([5 6 1 2], [5 6 1 2]), M.covariance, 1e-15);
%! assert (P([1 2 5 6], [3 4]), zeros (4, 2));
%! assert (sqrt (P(4, 4)) > 0 && sqrt (P(4, 4)) < 0.05);
%! txt = evalc ("present (M)");
%! assert (! isempty (strfind (txt, "hybrid BJ")), txt);
%! assert (! isempty (strfind (txt, "C(z) = 1")), txt);
%! assert (! isempty (strfind (txt, "D(z) = 1")), txt);
%! ## The returned model restarts rivc (model-in form: orders and start).
%! M2 = rivc (iddata (x + v, u, Ts), M);
%! assert (M2.theta, M.theta, 1e-5 * norm (M.theta));
%! assert (M2.D, M.D, 1e-4);

%!test  # delay in samples
%! xd = lsim (G, [zeros(3, 1); u(1:end-3)]);
%! M = rivc (iddata (xd, u, Ts), [2 1 1 2 3], "Tol", 1e-10);
%! assert (M.theta, [1.2 4 1.5 4], 1e-8);

%!test  # a small Monte Carlo: spread vs reported sd (20 runs; the full
%! # check is devel/monte_carlo/rivc_mc.m)
%! randn ("state", 9);
%! R = 20; T = zeros (R, 4); S = T;
%! for i = 1:R
%!   v = filter ([1 0.5], [1 -0.9], 0.05 * randn (N, 1));
%!   M = rivc (iddata (x + v, u, Ts), [2 1 1 2 0]);
%!   T(i, :) = M.theta; S(i, :) = sqrt (diag (M.covariance)).';
%! endfor
%! ratio = std (T) ./ mean (S);
%! ## 20 runs: the sample sd has a relative sd of ~16 %.
%! assert (all (ratio > 0.6 & ratio < 1.6), sprintf ("%g ", ratio));

%!warning <no convergence>
%! rivc (iddata (x + 0.1 * randn (N, 1), u, Ts), [2 1 1 2 0], "MaxIter", 1,
%!       "Tol", 1e-15);

%!error id=rivc:badInput rivc (iddata (x, u, Ts))
%!error id=rivc:badInput rivc ()
%!error id=rivc:badInput rivc (iddata (x, u, Ts), [2 1 1 2])
%!error id=rivc:badInput rivc (iddata (x, u, Ts), [2 1 1 2 -1])
%!error id=rivc:badInput rivc (iddata (x, u, Ts), [4 1 1 2 0])
%!error id=rivc:badInput rivc (iddata (x, u, Ts), [2 1 1 2 N])
%!error id=rivc:badOption rivc (iddata (x, u, Ts), [2 1 1 2 0], "Bogus", 1)
%!error id=rivc:badInput rivc (iddata (x, u, Ts), [2 1 1 2 0], "Tol")
%!error id=rivc:badInput rivc (iddata (x, u, Ts), [2 1 1 2 0], 3, 1)
%!error id=rivc:badOption rivc (iddata (x, u, Ts), [2 1 1 2 0], "Tol", -1)
%!error id=rivc:badOption rivc (iddata (x, u, Ts), [2 1 1 2 0], "MaxIter", 0.5)
%!error id=rivc:badOption rivc (iddata (x, u, Ts), [2 1 1 2 0], "lambda", -1)
%!error id=rivc:badOption rivc (iddata (x, u, Ts), [2 1 1 2 0], "ArmaMaxIter", -1)
%!error id=rivc:badOption rivc (iddata (x, u, Ts), [2 1 1 2 0], "ArmaMethod", "xx")
%!error id=rivc:badOption rivc (iddata (x, u, Ts), [2 1 1 2 0], "ArmaMethod", 3)
%!error id=rivc:badOption rivc (iddata (x, u, Ts), [2 1 1 2 0], "ArmaMethod", {"pem"})

%!test  # ArmaMethod 'ivarma': the same plant and noise model as 'pem' (both
%! # solve the prediction-error score equation at their fixed point)
%! randn ("state", 13);
%! v = filter ([1 0.5], [1 -0.9], 0.05 * randn (N, 1));
%! [Mp, Cp, Dp] = rivc (iddata (x + v, u, Ts), [2 1 1 2 0], "Tol", 1e-10);
%! [Mi, Ci, Di] = rivc (iddata (x + v, u, Ts), [2 1 1 2 0], "Tol", 1e-10,
%!                      "ArmaMethod", "ivarma", "ArmaMaxIter", 200);
%! assert ([Ci Di], [Cp Dp], 1e-5);
%! assert (Mi.theta, Mp.theta, 1e-6 * norm (Mp.theta));
%! assert (getcov (Mi), getcov (Mp), 1e-3 * norm (getcov (Mp)));
%!error id=rivc:badOption rivc (iddata (x, u, Ts), [2 1 1 2 0], "InitMethod", "nonsense")
%!error id=rivc:badOption rivc (iddata (x, u, Ts), [2 1 1 2 0], "InitMethod", {"lssvf"})

%!test  # noise-free: every start method reaches the exact system
%! for init = {"sriv", "srivc", "ivgpmf", "ivsvf", "lssvf"}
%!   M = rivc (iddata (x, u, Ts), [2 1 2 2 0], "Tol", 1e-10,
%!             "InitMethod", init{1});
%!   assert (M.theta, [1.2 4 1.5 4], 1e-8);
%!   assert (M.Report.Parameters.InitMethod.Requested, init{1});
%! endfor

%!test  # the start is used: it is lssvf's (ivsvf's) own estimate, one
%! # iteration from it is one iteration from that model given as start,
%! # and differs from one iteration from the SRIVC start
%! randn ("state", 21);
%! y = x + filter ([1 0.5], [1 -0.9], 0.1 * randn (N, 1));
%! z = iddata (y, u, Ts);
%! warning ("off", "rivc:notConverged", "local");
%! Ml = lssvf (z, [2 2 0], 3);
%! Mv = ivsvf (z, [2 2 0], 3);
%! M1 = rivc (z, [2 1 1 2 0], "InitMethod", "lssvf", "lambda", 3,
%!            "MaxIter", 1);
%! s = M1.Report.Parameters.InitMethod;
%! assert ({s.Method, s.Lambda, s.Stabilised}, {"lssvf", 3, false});
%! assert (s.Theta, Ml.theta, 1e-12);
%! M1m = rivc (z, [2 1 1 2 0], "InitMethod", Ml.theta, "MaxIter", 1);
%! assert (M1.theta, M1m.theta, 1e-12 * norm (M1.theta));
%! M2 = rivc (z, [2 1 1 2 0], "InitMethod", "ivgpmf", "lambda", 3,
%!            "MaxIter", 1);
%! assert (M2.Report.Parameters.InitMethod.Theta, Mv.theta, 1e-12);
%! M0 = rivc (z, [2 1 1 2 0], "InitMethod", "sriv", "lambda", 3,
%!            "MaxIter", 1);
%! assert (M0.Report.Parameters.InitMethod.Method, "sriv");
%! assert (norm (M1.theta - M0.theta) > 1e-4 * norm (M0.theta));
%! assert (norm (M2.theta - M0.theta) > 1e-6 * norm (M0.theta));
%! ## without lambda: the engine's automatic cut-off, reported
%! M3 = rivc (z, [2 1 1 2 0], "InitMethod", "lssvf", "MaxIter", 1);
%! lam = M3.Report.Parameters.InitMethod.Lambda;
%! Ml3 = lssvf (z, [2 2 0], lam);
%! assert (M3.Report.Parameters.InitMethod.Theta, Ml3.theta, 1e-12);
%!error id=rivc:badOption rivc (iddata (x, u, Ts), [2 1 1 2 0], "InitMethod", [1 2])
%!error id=rivc:badInput rivc (iddata (x, u, Ts), [2 1 1 2 0], "InitMethod", [-1 4 1 1])
%!test  # two inputs, one denominator each (CONTSID's MISO nn): exact
%! u2 = kron (sign (randn (N / 15, 1)), ones (15, 1));
%! x2 = lsim (c2d (tf (2, [1 0.5]), Ts), [0; 0; u2(1:end-2)]);
%! [M, C, D, RT2] = rivc (iddata (x + x2, [u u2], Ts),
%!                        [2 1 1 1 2 1 0 2], "Tol", 1e-10);
%! assert (M.theta, [1.2 4 0.5 1.5 4 2], 1e-8);
%! assert (M.F, {[1 1.2 4], [1 0.5]}, 1e-8);
%! assert (M.B, {[1.5 4], 2}, 1e-8);
%! assert (RT2, 1, 1e-10);
%! assert (size (M.covariance), [6 6]);
%! ## a given start [f_1 f_2 b_1 b_2], and IVARMA for the noise model
%! M2 = rivc (iddata (x + x2, [u u2], Ts), [2 1 1 1 2 1 0 2], "Tol", 1e-10,
%!            "InitMethod", [1 3 1 1 3 1], "ArmaMethod", "ivarma");
%! assert (M2.theta, [1.2 4 0.5 1.5 4 2], 1e-8);

%!test  # two inputs, ARMA noise: the fit equals the sum of each channel
%! # simulated by the control package (c2d + lsim), within 4 sd of the truth
%! randn ("state", 12);
%! u2 = kron (sign (randn (N / 15, 1)), ones (15, 1));
%! x2 = lsim (c2d (tf (2, [1 0.5]), Ts), u2);
%! v = filter ([1 0.5], [1 -0.9], 0.05 * randn (N, 1));
%! y = x + x2 + v;
%! [M, C, D, RT2] = rivc (iddata (y, [u u2], Ts), [2 1 1 1 2 1 0 0]);
%! ys = lsim (c2d (tf (M.B{1}, M.F{1}), Ts), u) ...
%!      + lsim (c2d (tf (M.B{2}, M.F{2}), Ts), u2);
%! assert (RT2, 1 - mean ((y - ys) .^ 2) / var (y, 1), 1e-9);
%! sd = sqrt (diag (M.covariance)).';
%! assert (all (abs (M.theta - [1.2 4 0.5 1.5 4 2]) < 4 * sd));
%! assert ([C(2) D(2)], [0.5 -0.9], 0.1);
%! p = getpvec (M);  # [b_1 b_2 c d f_1 f_2]
%! B = M.B; F = M.F;
%! assert (p.', [B{:}, C(2), D(2), F{1}(2:3), F{2}(2)], 1e-14);
%! P = getcov (M);
%! assert (P([6 7 8 1 2 3], [6 7 8 1 2 3]), M.covariance, 1e-15);
%! ## the cross-input blocks of the stacked instruments' covariance
%! assert (any (any (M.covariance(1:2, 3) != 0)));

%!error id=rivc:badInput rivc (iddata (x, [u u], Ts), [2 1 1 2 0])
%!error id=rivc:badInput rivc (iddata (x, [u u], Ts), [2 1 1 1 2 0 0 0])
%!error id=rivc:badInput rivc (iddata (x, [u u], Ts), [2 3 1 1 2 1 0 0])
%!error id=rivc:notSupported rivc (iddata (x, [u u], Ts), idpoly (1, {1, 1}, 1, 1, {[1 1], [1 1]}, 0, 0))
%!error id=rivc:badOption rivc (iddata (x, [u u], Ts), [1 1 0 0 1 1 0 0], "InitMethod", [1 1])
%!error id=rivc:notSupported rivc (iddata (x(1:50), u(1:50), "SamplingInstants", cumsum (0.01 + rand (50, 1) / 100)), [2 1 1 2 0])
%!error id=rivc:badInput rivc (iddata (x(1:40), u(1:40), Ts), [2 1 1 2 0])
%!error id=rivc:numericalFailure rivc (iddata (x, zeros (N, 1), Ts), [2 1 1 2 0])

%!demo
%! ## RIVC against SRIVC on coloured noise (Monte Carlo: devel/monte_carlo/rivc_mc.m)
%! pkg load control
%! Ts = 0.05; N = 3000; u = kron (sign (randn (N / 10, 1)), ones (10, 1));
%! x = lsim (c2d (tf ([1.5 4], [1 1.2 4]), Ts), u);
%! v = filter ([1 0.5], [1 -0.9], 0.05 * randn (N, 1));
%! [M, C, D] = rivc (iddata (x + v, u, Ts), [2 1 1 2 0])
%! Ms = srivc (iddata (x + v, u, Ts), [2 2 0])

%!demo
%! ## The start methods (InitMethod): one RIVC iteration from each start,
%! ## then the converged estimates (the same fixed point)
%! pkg load control
%! Ts = 0.05; N = 3000; u = kron (sign (randn (N / 10, 1)), ones (10, 1));
%! x = lsim (c2d (tf ([1.5 4], [1 1.2 4]), Ts), u);
%! z = iddata (x + filter ([1 0.5], [1 -0.9], 0.1 * randn (N, 1)), u, Ts);
%! warning ("off", "rivc:notConverged", "local");
%! for init = {"sriv", "ivgpmf", "lssvf"}
%!   M1 = rivc (z, [2 1 1 2 0], "InitMethod", init{1}, "MaxIter", 1);
%!   M = rivc (z, [2 1 1 2 0], "InitMethod", init{1});
%!   s = M1.Report.Parameters.InitMethod;
%!   printf ("%-7s lambda %-6.3g start %-32s 1 iteration %-32s converged %s\n",
%!           init{1}, s.Lambda, mat2str (s.Theta, 4), mat2str (M1.theta, 4),
%!           mat2str (M.theta, 5));
%! endfor
