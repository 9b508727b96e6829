## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn  {} {[@var{sys}, @var{sysN}] =} tfrivc (@var{data}, @var{np}, @var{nz}, 'NN', [@var{nd} @var{nc}])
## @deftypefnx {} {[@var{sys}, @var{sysN}] =} tfrivc (@var{data}, @var{np}, @var{nz}, @var{IODelay}, @dots{})
## @deftypefnx {} {[@var{sys}, @var{sysN}] =} tfrivc (@dots{}, @var{name}, @var{value}, @dots{})
## Continuous-time transfer function with a time delay and a discrete
## ARMA noise model,
## @example
## y(t_k) = B(p)/F(p) u(t_k - td) + C(q^-1)/D(q^-1) e(t_k),
## deg F = np, deg B = nz, deg D = nd, deg C = nc,
## @end example
## by refined IV: @code{tfsrivc} gives the start (delay search and
## refinement, Focus), then the delay is estimated jointly with the plant
## and the noise model, as CONTSID does: RIVC
## (core/include/ctid/offline/refined_iv_bj.hpp, as @code{rivc}) at each
## delay, the delayed input filtered exactly for any fraction of a sample,
## and Gauss-Newton steps on td that minimise the innovation variance
## (the output error whitened by the noise model's D/C; the coefficients
## re-estimated by RIVC projected out); with 'FixTd' 'on' td is kept.
##
## @var{data}: @code{iddata} (regular sampling). Options: @code{'NN'},
## [nd nc] (default [0 0]: then the result is tfsrivc's plant re-iterated
## by the same engine); all others (@code{FixTd}, @code{TdMin},
## @code{TdMax}, @code{NumTd}, @code{Lambda}, @code{MaxIter},
## @code{TolPar}, @code{TolFun}, @code{StepMax}, ...) are tfsrivc's, for
## the start and for the joint refinement (MaxIter and TolPar also stop
## the RIVC iterations), except @code{InitMethod}, the start of the
## RIVC iterations: @qcode{"sriv"} (default: tfsrivc's SRIVC model),
## @qcode{"ivgpmf"} (= @qcode{"ivsvf"}: one IVSVF estimate, thesis eqs.
## 2.4-2.7, the state-variable filter (lambda/(p + lambda))^n that is
## CONTSID's Poisson-moment-functional filter), @qcode{"lssvf"} (one
## LSSVF estimate, eq. 1.32), an @code{idpoly}/@code{idtf} or [f b]; the
## one-step starts are computed by the core (as @code{lssvf},
## @code{ivsvf}) with tfsrivc's delay td, at @code{Lambda} when given,
## else at the one of 12 cut-offs log-spaced between 5/T and 0.5 pi/Ts
## whose estimate has the smallest simulation error; an unstable one
## has its right-half-plane poles reflected (p -> -conj (p)) with the
## warning @code{tfrivc:unstableStart}. @code{sys.Report.Parameters.InitMethod}
## says which start was used. @code{Focus} (CONTSID's cut-off fc, or a
## band; order @code{FocusOrder}, default 5) is tfsrivc's: the start is
## first fitted to the prefiltered data (for the convergence of the
## delay); RIVC and the joint refinement use the data as given.
## @code{Integration} 'on' (CONTSID's
## enforced integrator) is @code{tfrivc:notSupported}: the RIVC
## iterations cannot hold a coefficient fixed (@code{tfsrivc} and
## @code{tfcoe} can).
##
## @var{sys}: an @code{idtf} with IODelay = td, the covariance of [b; f;
## td] (sigma_e^2 (J' J)^-1, J the output's sensitivities whitened by
## D/C; with 'FixTd' 'on' that of [b; f], sigma_e^2 (sum zeta_f
## zeta_f')^-1, eq. 2.13), @code{Report.Fit},
## @code{Report.Parameters.IODelaySD} (0 when fixed) and @code{.NoiseModel},
## @code{Report.Termination} (RIVC's @code{Iterations}, the
## @code{DelayIterations} of the refinement).
## @var{sysN}: the noise model, a discrete @code{idpoly} C/D (B = C,
## F = D, CONTSID's @code{idpoly (1, C, 1, 1, D, 0, Ts)} form) with
## NoiseVariance sigma_e^2.
##
## @strong{Example}
## @example
## Ts = 0.05; u = kron (sign (randn (300, 1)), ones (10, 1));
## M0 = idtf (4, [1 1.2 4], "IODelay", 0.37);
## x = simc (M0, iddata ([], u, Ts, "InterSample", "zoh"));
## v = filter ([1 0.5], [1 -0.9], 0.05 * randn (3000, 1));
## [MP, MN] = tfrivc (iddata (x + v, u, Ts), 2, 0, "NN", [1 1])
## @end example
## @seealso{tfsrivc, rivc}
## @end deftypefn

function varargout = tfrivc (varargin)
  varargout = contsid_guard ("tfrivc", @tfrivc_body, nargout, varargin);
endfunction

function [sys, sysN, varargout] = tfrivc_body (varargin)
  contsid_nargchk ("tfrivc", nargin, nargout, [3 Inf], 2);
  [sys, info, d] = contsid_rivc ("tfrivc", varargin);
  sysN = [];
  if (nargout > 1)
    sysN = idpoly (1, info.C, 1, 1, info.D, info.noise_variance, d.Ts);
  endif
endfunction

%!shared u, x, Ts, N, M0
%! Ts = 0.05; N = 3000; randn ("state", 3);
%! u = kron (sign (randn (N / 10, 1)), ones (10, 1));
%! M0 = idtf (4, [1 1.2 4], "IODelay", 0.37);
%! x = simc (M0, iddata ([], u, Ts, "InterSample", "zoh"));

%!test  # noise-free, delay a fraction of a sample, kept: exact
%! [MP, MN] = tfrivc (iddata (x, u, Ts), 2, 0, 0.37, "FixTd", "on", ...
%!                    "NN", [1 1]);
%! assert (MP.IODelay, 0.37);
%! assert ([MP.num{1}, MP.den{1}], [4 1 1.2 4], 1e-7);
%! assert (isa (MN, "idpoly") && MN.Ts == Ts);

%!test  # coloured noise: the noise model and the reported sd
%! randn ("state", 8);
%! v = filter ([1 0.5], [1 -0.9], 0.05 * randn (N, 1));
%! [MP, MN] = tfrivc (iddata (x + v, u, Ts), 2, 0, 0.37, "FixTd", "on", ...
%!                    "NN", [1 1]);
%! sd = sqrt (diag (getcov (MP)))(1:3).';   # [b f], then the IODelay
%! assert (all (abs ([MP.num{1}, MP.den{1}(2:3)] - [4 1.2 4]) < 4 * sd));
%! assert (MN.F(2), -0.9, 0.05);
%! assert (MN.B(2), 0.5, 0.1);

%!test  # Focus serves the start only: with the delay kept, RIVC on the
%! ## data as given (the same model as without Focus)
%! randn ("state", 8);
%! v = filter ([1 0.5], [1 -0.9], 0.05 * randn (N, 1));
%! MP1 = tfrivc (iddata (x + v, u, Ts), 2, 0, 0.37, "FixTd", "on",
%!               "NN", [1 1], "Focus", 8, "FocusOrder", 3);
%! MP2 = tfrivc (iddata (x + v, u, Ts), 2, 0, 0.37, "FixTd", "on",
%!               "NN", [1 1]);
%! assert (getpvec (MP1), getpvec (MP2), 1e-6 * norm (getpvec (MP2)));

%!test  # CONTSID's TFRIVC demo (4/(s^2 + 2.8 s + 4), delay 8 s, nearly
%! ## integrated ARMA noise at 15 dB): the delay estimated with the noise
%! ## model lowers the innovation variance below RIVC's at tfsrivc's
%! ## delay, both computed independently (simc, then the whitening filter
%! ## D/C of each noise model), and its reported sd covers the truth
%! M8 = idtf (4, [1 2.8 4], "IODelay", 8);
%! u8 = prbs (8, 5);
%! y8 = simc (M8, iddata ([], u8, 0.1, "InterSample", "zoh"));
%! randn ("state", 21);
%! e8 = filter ([1 0.2679], [1 -1.98 0.9802], randn (numel (u8), 1));
%! y8 += 10 ^ (-15 / 20) * std (y8) / std (e8) * e8;
%! d8 = iddata (y8, u8, 0.1, "InterSample", "zoh");
%! [MP, MN] = tfrivc (d8, 2, 0, "NN", [2 1]);
%! Ms = tfsrivc (d8, 2, 0);
%! [MF, MNF] = tfrivc (d8, 2, 0, Ms.IODelay, "FixTd", "on", "NN", [2 1]);
%! innov = @(M, N) var (filter (N.F, N.B, y8 - simc (M, d8)), 1);
%! assert (innov (MP, MN) < innov (MF, MNF));
%! sd = MP.Report.Parameters.IODelaySD;
%! assert (sd > 0 && sd < 1e-3);
%! assert (abs (MP.IODelay - 8) < 4 * sd);
%! assert (abs (MP.IODelay - Ms.IODelay) > 0);

%!test  # a structure the data cannot determine well (two poles for a
%! ## first-order response with a noise model): a model, with the
%! ## covariance left out when J'J gives none that is positive semi-definite
%! randn ("state", 1);
%! u1 = sign (randn (200, 1));
%! y1 = filter ([0 0.3], [1 -0.7], u1) + 0.05 * randn (200, 1);
%! warning ("off", "tfrivc:notConverged", "local");
%! MP = tfrivc (iddata (y1, u1, 0.1), 2, 0, "NN", [1 1]);
%! assert (isa (MP, "idtf") && all (isfinite (getpvec (MP))));
%! C = getcov (MP);
%! assert (isempty (C) || min (eig ((C + C') / 2)) > -1e-10 * norm (C, 1));

%!error id=tfrivc:notSupported
%! tfrivc (iddata (x, u, Ts), 2, 0, "Integration", "on")
%!error id=tfrivc:badOption
%! tfrivc (iddata (x, u, Ts), 2, 0, "Integration", "maybe")
%!test  # noise-free: every start method reaches the exact system
%! for init = {"sriv", "ivgpmf", "lssvf"}
%!   MP = tfrivc (iddata (x, u, Ts), 2, 0, 0.37, "FixTd", "on", ...
%!                "NN", [1 1], "InitMethod", init{1});
%!   assert ([MP.num{1}, MP.den{1}], [4 1 1.2 4], 1e-7);
%!   assert (MP.Report.Parameters.InitMethod.Method, init{1});
%! endfor

%!test  # the start is lssvf's estimate at the delay (7 samples), used:
%! # one iteration from it is not one iteration from tfsrivc's model
%! xd = simc (idtf (4, [1 1.2 4], "IODelay", 7 * Ts),
%!            iddata ([], u, Ts, "InterSample", "zoh"));
%! randn ("state", 4);
%! z = iddata (xd + filter ([1 0.5], [1 -0.9], 0.1 * randn (N, 1)), u, Ts);
%! warning ("off", "tfrivc:notConverged", "local");
%! M1 = tfrivc (z, 2, 0, 7 * Ts, "FixTd", "on", "NN", [1 1],
%!              "InitMethod", "lssvf", "Lambda", 3, "MaxIter", 1);
%! Ml = lssvf (z, [2 1 7], 3);
%! s = M1.Report.Parameters.InitMethod;
%! assert (s.Theta, Ml.theta, 1e-12);
%! assert (s.Lambda, 3);
%! M0 = tfrivc (z, 2, 0, 7 * Ts, "FixTd", "on", "NN", [1 1],
%!              "Lambda", 3, "MaxIter", 1);
%! assert (M0.Report.Parameters.InitMethod.Method, "sriv");
%! p1 = [M1.num{1}, M1.den{1}];
%! p0 = [M0.num{1}, M0.den{1}];
%! assert (norm (p1 - p0) > 1e-4 * norm (p0));

%!error id=tfrivc:badOption tfrivc (iddata (x, u, Ts), 2, 0, 0.37, "FixTd", "on", "InitMethod", "bogus")
%!error id=tfrivc:badOption tfrivc (iddata (x, u, Ts), 2, 0, 0.37, "FixTd", "on", "InitMethod", [1 2])
%!error id=tfrivc:badInput tfrivc (iddata (x, u, Ts), 2)
%!error id=tfrivc:badInput tfrivc (iddata (x, u, Ts), 0, 0, "NN", [1 1])
%!error id=tfrivc:badInput tfrivc (iddata (x, u, Ts), 2, 3, "NN", [1 1])
%!error id=tfrivc:badInput tfrivc (iddata (x, u, Ts), 2, 0, -1, "NN", [1 1])
%!error id=tfrivc:badInput tfrivc (iddata (x, u, Ts), 2, 0, "NN", [1 1 1])
%!error id=tfrivc:badInput tfrivc (iddata (x, u, Ts), 2, 0, "NN")
%!error id=tfrivc:badInput tfrivc (iddata (x, u, Ts), 2, 0, 3, 4)
%!error id=tfrivc:badOption tfrivc (iddata (x, u, Ts), 2, 0, 0.37, "FixTd", "on", "Bogus", 1)
%!error id=tfrivc:badOption tfrivc (iddata (x, u, Ts), 2, 0, 0.37, "FixTd", "on", "MaxIter", 0)

%!demo
%! Ts = 0.05; u = kron (sign (randn (300, 1)), ones (10, 1));
%! M0 = idtf (4, [1 1.2 4], "IODelay", 0.37);
%! x = simc (M0, iddata ([], u, Ts, "InterSample", "zoh"));
%! v = filter ([1 0.5], [1 -0.9], 0.05 * randn (3000, 1));
%! [MP, MN] = tfrivc (iddata (x + v, u, Ts), 2, 0, "NN", [1 1])
