## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn  {} {[@var{model}, @var{Infos}] =} hsrivc (@var{data}, [@var{nb} @var{nf} @var{nk}])
## @deftypefnx {} {[@dots{}] =} hsrivc (@var{data}, @var{nn}, @var{lambda0}, @var{t0}, @var{init_method}, @var{tol}, @var{maxiter}, @var{arma_method})
## @deftypefnx {} {[@dots{}] =} hsrivc (@var{data}, @var{nn}, @var{name}, @var{value}, @dots{})
## Continuous-time Hammerstein model by simplified refined IV (HSRIVC,
## Laurain, Gilson, Garnier and Young, CDC 2008):
## @example
## y(t) = B(p)/F(p) ubar(t - nk Ts) + e(t),  ubar = sum_i alpha_i f_i(u)
## @end example
## with white noise e. The inputs of @var{data} (an @code{iddata} or
## y, U, Ts) are the basis functions f_i(u), e.g. @code{[u u.^2 u.^3]}
## for a polynomial; alpha_1 = 1 (the nonlinearity is "monic", as
## CONTSID). @var{nn} = [nb nf nk] describes B/F (nb numerator, nf
## denominator parameters, nk delay in samples).
##
## Algorithm: the model is linear in the products alpha_i b, a MISO model
## whose inputs share F, estimated by SRIVC (thesis eqs. 2.8-2.13, the
## engine of @code{srivc}); each iteration then takes one refined-IV step
## from the structured model and separates alpha and b: the best rank-one
## approximation of the matrix of products (its leading singular pair)
## starts a minimum-distance fit of the structure to the products,
## weighted by the inverse of their covariance P (eq. 2.13), until the
## separated parameters stop changing (relative change < @var{tol},
## default 1e-6; at most @var{maxiter} = 30 iterations). Their covariance
## is (J' P^-1 J)^-1, J the Jacobian of the products in the separated
## parameters.
##
## Options (positional as CONTSID, [] for a default, or name-value):
## @var{lambda0} / @code{"lambda"} the SVF cut-off of the start
## (default: see below); @var{t0} must be 0;
## @var{init_method} / @code{"InitMethod"} the start of the first
## refined-IV pass, the MISO model [f B_1 .. B_l] of the basis channels:
## @qcode{"sriv"} or @qcode{"srivc"} (default: the engine's, IVSVF at
## @var{lambda0} or at 12 cut-offs log-spaced between 5/T and 0.5 pi/Ts,
## then SRIVC), @qcode{"ivgpmf"} (= @qcode{"ivsvf"}: one IVSVF estimate,
## thesis eqs. 2.4-2.7; CONTSID's IV with Poisson-moment-functional
## filtering is this state-variable filter (lambda/(p + lambda))^n),
## @qcode{"lssvf"} (one LSSVF estimate, eq. 1.32), or a model (a MISO
## @code{idpoly} such as @var{model}, or [f B_1 .. B_l]). The one-step
## starts are the core's (as @code{lssvf}, @code{ivsvf} on the basis
## data) at @var{lambda0}, or without it at the one of those cut-offs
## whose estimate has the smallest simulation error; an unstable one has
## its right-half-plane poles reflected (p -> -conj (p)) with the warning
## @code{hsrivc:unstableStart}. @code{Infos.InitMethod} (and
## @code{model.Report.Parameters.InitMethod}) says which start was used.
## @var{tol} / @code{"Tol"}, @var{maxiter} / @code{"MaxIter"};
## @var{arma_method} / @code{"ArmaMethod"}: only @qcode{"pem"} (the
## noise is white here, there is no noise model to fit: @qcode{"ivarma"}
## raises @code{hsrivc:notSupported}; see @code{hrivc}).
##
## Outputs: @var{model}, the MISO @code{idpoly} B_i = alpha_i B over the
## common F (for @code{present}, @code{simc}, @code{comparec} on the basis
## data), with covariance and @code{Report.Fit}; @var{Infos} with fields
## @code{modelLin} (the @code{idpoly} B/F, covariance of [f b]),
## @code{NLinCoeff} (row alpha, alpha(1) = 1), @code{NLinCoeff_sd},
## @code{Noisemodel} (white: an idpoly with the noise variance),
## @code{InfoCriterion} (@code{RT2}, @code{YIC}, @code{AIC}),
## @code{Cond_IPM}, @code{iternum}, @code{converged}, @code{reason},
## @code{theta} = [f b alpha(2:end)]', @code{covariance}, @code{sd},
## @code{present} (the text of @code{present (model)}).
## Without convergence a warning @code{hsrivc:notConverged} is issued and
## the last iterate returned.
## @seealso{hrivc, hwsrivc, srivc}
## @end deftypefn

function varargout = hsrivc (varargin)
  varargout = contsid_guard ("hsrivc", @hsrivc_body, nargout, varargin);
endfunction

function [model, Infos, varargout] = hsrivc_body (varargin)
  contsid_nargchk ("hsrivc", nargin, nargout, [2 Inf], 2);
  [model, Infos] = contsid_block ("hsrivc", varargin);
endfunction

%!shared u, udata, Ts, ydet, m
%! rand ("state", 3); randn ("state", 3);
%! N = 1000; u = 4 * rand (N, 1) - 2; Ts = 0.5;
%! udata = [u u.^2 u.^3];
%! m = idpoly (1, [10 30], 1, 1, [1 1 5], 0, 0);
%! ydet = simc (m, iddata ([], udata * [1; 0.5; 0.25], Ts));

%!test  # noise-free: the linear part and the nonlinearity exactly
%! [model, Infos] = hsrivc (iddata (ydet, udata, Ts), [2 2 0]);
%! assert (Infos.NLinCoeff, [1 0.5 0.25], 1e-6);
%! assert (Infos.modelLin.F, [1 1 5], 1e-6);
%! assert (Infos.modelLin.B, [10 30], 1e-5);
%! assert (Infos.converged);
%! ## the MISO model is B_i = alpha_i B over the common F
%! assert (model.B{3}, 0.25 * [10 30], 1e-5);
%! assert (model.Report.Fit.FitPercent > 99.99);

%!test  # the MISO model simulates the system (comparec on the basis data)
%! [model, Infos] = hsrivc (iddata (ydet, udata, Ts), [2 2 0], [], 0, [], 1e-8, 20);
%! [ys, est] = comparec (iddata (ydet, udata, Ts), model);
%! assert (est.Fit > 99.99);
%! assert (Infos.iternum <= 20);

%!test  # noisy: within 4 reported sd of the truth
%! randn ("state", 5);
%! y = ydet + 0.3 * std (ydet) * randn (size (ydet));
%! [~, I] = hsrivc (iddata (y, udata, Ts), [2 2 0]);
%! truth = [1 5 10 30 0.5 0.25]';
%! assert (all (abs (I.theta - truth) < 4 * I.sd(:)));
%! assert (all (I.sd > 0));

%!test  # noise-free: every start method reaches the exact system
%! for init = {"sriv", "srivc", "ivgpmf", "ivsvf", "lssvf"}
%!   [~, Infos] = hsrivc (iddata (ydet, udata, Ts), [2 2 0], [], 0, init{1});
%!   assert (Infos.theta, [1 5 10 30 0.5 0.25]', 1e-6);
%!   assert (Infos.InitMethod.Requested, init{1});
%! endfor

%!test  # the start is lssvf's MISO estimate and is used: one iteration
%! # from it is one iteration from that model, not from the engine's start
%! randn ("state", 5);
%! z = iddata (ydet + 0.3 * std (ydet) * randn (size (ydet)), udata, Ts);
%! warning ("off", "hsrivc:notConverged", "local");
%! [~, I1] = hsrivc (z, [2 2 0], 1, 0, "lssvf", [], 1);
%! Ml = lssvf (z, [2 2 2 2 0 0 0], 1);
%! assert (I1.InitMethod.Theta, Ml.theta, 1e-12);
%! assert (I1.InitMethod.Lambda, 1);
%! [~, I1m] = hsrivc (z, [2 2 0], 1, 0, Ml.theta, [], 1);
%! assert (I1.theta, I1m.theta, 1e-12 * norm (I1.theta));
%! [~, I0] = hsrivc (z, [2 2 0], 1, 0, "sriv", [], 1);
%! assert (norm (I1.theta - I0.theta) > 1e-3 * norm (I0.theta));
%! [~, I2] = hsrivc (z, [2 2 0], "lambda", 1, "InitMethod", "ivgpmf",
%!                   "MaxIter", 1);
%! Mv = ivsvf (z, [2 2 2 2 0 0 0], 1);
%! assert (I2.InitMethod.Theta, Mv.theta, 1e-12);
%! ## the MISO model restarts the iterations
%! [M, I] = hsrivc (z, [2 2 0]);
%! [~, I3] = hsrivc (z, [2 2 0], "InitMethod", M);
%! assert (I3.theta, I.theta, 1e-6 * norm (I.theta));

%!error id=hsrivc:badOption hsrivc (iddata (ydet, udata, Ts), [2 2 0], [], 0, "nonsense")
%!error id=hsrivc:badOption hsrivc (iddata (ydet, udata, Ts), [2 2 0], "InitMethod", [1 2])
%!error id=hsrivc:badInput hsrivc (iddata (ydet, udata, Ts), [2 2 0], "InitMethod", [-1 5 10 30 5 15 2.5 7.5])
%!error id=hsrivc:notSupported hsrivc (iddata (ydet, udata, Ts), [2 2 0], [], 0, [], [], [], "ivarma")
%!error id=hsrivc:badOption hsrivc (iddata (ydet, udata, Ts), [2 2 0], "ArmaMethod", "ls")
%!error id=hsrivc:badOption hsrivc (iddata (ydet, udata, Ts), [2 2 0], "ArmaMethod", 1)
%!error id=hsrivc:badInput hsrivc (iddata (ydet, udata, Ts))
%!error id=hsrivc:badInput hsrivc (iddata (ydet, udata, Ts), [2 2])
%!error id=hsrivc:badInput hsrivc (iddata (ydet, udata, Ts), [2 -2 0])
%!error id=hsrivc:badInput hsrivc (iddata (ydet, udata, Ts), [4 2 0])
%!error id=hsrivc:badInput hsrivc (iddata (ydet, udata, Ts), [2 0 0])
%!error id=hsrivc:badOption hsrivc (iddata (ydet, udata, Ts), [2 2 0], "Tol", -1)
%!error id=hsrivc:badOption hsrivc (iddata (ydet, udata, Ts), [2 2 0], "MaxIter", 0)
%!error id=hsrivc:badOption hsrivc (iddata (ydet, udata, Ts), [2 2 0], "lambda", -1)
%!error id=hsrivc:badOption hsrivc (iddata (ydet, udata, Ts), [2 2 0], "bogus", 1)
%!error id=hsrivc:badOption hsrivc (iddata (ydet, udata, Ts), [2 2 0], "Tol")
%!error id=hsrivc:badOption hsrivc (iddata (ydet, udata, Ts), [2 2 0], [], 0, 3)
%!error id=hsrivc:notSupported hsrivc (iddata (ydet, udata, Ts), [2 2 0], [], 5)
%!error id=hsrivc:badInput hsrivc (iddata (ydet, udata, Ts), [2 2 0], [], 0, [], 1e-6, 10, "x", 1)
%!error id=hsrivc:badInput hsrivc (iddata (ydet, [zeros(1000, 1) udata(:, 2:3)], Ts), [2 2 0])
%!error id=hsrivc:badInput [a, b, c] = hsrivc (iddata (ydet, udata, Ts), [2 2 0])
%!warning id=hsrivc:notConverged hsrivc (iddata (ydet + 0.5 * randn (size (ydet)), udata, Ts), [2 2 0], "MaxIter", 1);

%!demo
%! ## CONTSID's Hammerstein demo: ubar = u + 0.5 u^2 + 0.25 u^3, G = (10 s + 30)/(s^2 + s + 5)
%! N = 2000; u = 4 * rand (N, 1) - 2; Ts = 0.5;
%! udata = [u u.^2 u.^3];
%! m = idpoly (1, [10 30], 1, 1, [1 1 5], 0, 0);
%! ydet = simc (m, iddata ([], udata * [1; 0.5; 0.25], Ts));
%! y = ydet + sqrt (var (ydet) * 10^(-5/10)) * randn (N, 1);   # SNR 5 dB
%! [model, Infos] = hsrivc (iddata (y, udata, Ts), [2 2 0]);
%! Infos.modelLin
%! Infos.NLinCoeff
%! plot (u, udata * [1 0.5 0.25]', ".", u, udata * Infos.NLinCoeff', "r.");
%! legend ("true", "estimated");
