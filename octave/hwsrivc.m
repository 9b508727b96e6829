## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn  {} {[@var{model}, @var{Infos}, @var{yhat}] =} hwsrivc (@var{data}, [@var{nb} @var{nf}+1 @var{nk} @var{lenH} @var{lenW}])
## @deftypefnx {} {[@dots{}] =} hwsrivc (@var{data}, [@var{nb} @var{nf}+1 @var{nk}])
## @deftypefnx {} {[@dots{}] =} hwsrivc (@var{data}, @var{nn}, @var{model}, @var{tol}, @var{maxiter})
## @deftypefnx {} {[@dots{}] =} hwsrivc (@dots{}, @var{name}, @var{value})
## Continuous-time Hammerstein-Wiener model by simplified refined IV
## (HWSRIVC, Ni, Garnier and Gilson, IET CTA 7(9), 2013):
## @example
## ubar = f(u) = u + alpha_2 u^2 + .. + alpha_lenH u^lenH
## xbar = B(p)/F(p) ubar(t - nk Ts)
## xbar = g(x) = x + beta_2 x^2 + .. + beta_lenW x^lenW,  y = x + e
## @end example
## @var{data} has one input u. As in CONTSID's demo, @var{nn}(2) is the
## number of denominator coefficients nf + 1 (e.g. [1 2 0 3 3] for
## 1/(s + a) with cubic nonlinearities); the 3-element form takes lenH =
## lenW = 3.
##
## Algorithm: g(x) = B/F f(u) gives y = B/F f(u) - sum_j beta_j x^j + e,
## linear in the products alpha_i b and beta_j [1 f]: the refined-IV engine
## (thesis eqs. 2.8-2.13) estimates them with the channels u^i and x^j
## (x^j with numerator -beta_j F(p)); alpha, b (alpha_1 = 1) and beta
## from a fit of the structure to the products weighted by their inverse
## covariance (started from the rank-one fit and least squares of each
## -beta_j F against [1 f]), as @code{hsrivc}. The x^j are
## the model's noise-free x_hat = g^-1(B/F f(u)) (real root nearest the
## previous sample), y in the first pass; iterated until the separated
## parameters stop changing; the Wiener step is halved (the noise makes the
## plain fixed-point iteration overshoot). Options @code{"Tol"} (1e-6),
## @code{"MaxIter"} (100), @code{"lambda"}; @code{"InitMethod"} only
## @qcode{"sriv"} (the engine's start, default): the first pass regresses
## on powers of the measured y, which a one-step LSSVF/IVSVF estimate or
## a model of the linear part cannot start, so @qcode{"ivgpmf"},
## @qcode{"lssvf"} and models raise @code{hwsrivc:notSupported};
## @code{"ArmaMethod"} only @qcode{"pem"} (the noise is white, there is no
## noise model: @qcode{"ivarma"} raises @code{hwsrivc:notSupported}).
## CONTSID's positional form (@var{model}, @var{tol}, @var{maxiter}) is
## the same as @code{"InitMethod"}, @code{"Tol"}, @code{"MaxIter"}; an
## empty argument keeps the default (so @var{model} = [] is the
## engine's start, and a model raises @code{hwsrivc:notSupported}).
##
## Outputs: @var{model}, the linear part B/F (@code{idpoly}, covariance of
## [f b], @code{Report.Fit} of @var{yhat}); @var{Infos} with @code{NL_H}
## (column alpha, NL_H(1) = 1), @code{NL_W} (column beta of g, NL_W(1) =
## 1), @code{NL_H_sd}, @code{NL_W_sd}, @code{theta} = [f b alpha(2:end)
## beta(2:end)]', @code{covariance}, @code{sd}, @code{InfoCriterion},
## @code{Cond_IPM}, @code{iternum}, @code{converged}, @code{reason};
## @var{yhat} the simulated output x_hat. The covariance is the IV
## sandwich sigma^2 (Z' Psi)^-1 Z' Z (Psi' Z)^-1 of the fixed point: Psi
## the sensitivity of x_hat to the separated parameters (through
## g^-1), Z = g'(x_hat) Psi the instruments the MISO step actually uses
## (thesis eq. 2.13); in a Monte Carlo the spread of the
## estimates was 0.96-1.10 of the reported sd (80 runs).
## @seealso{hsrivc, hrivc}
## @end deftypefn

function varargout = hwsrivc (varargin)
  varargout = contsid_guard ("hwsrivc", @hwsrivc_body, nargout, varargin);
endfunction

function [model, Infos, varargout] = hwsrivc_body (varargin)
  contsid_nargchk ("hwsrivc", nargin, nargout, [2 Inf], 3);
  [model, Infos, yhat] = contsid_block ("hwsrivc", varargin);
  if (nargout > 2)
    varargout{1} = yhat;
  endif
endfunction

%!shared u, Ts, y0, N
%! rand ("state", 4); randn ("state", 4);
%! Ts = 5e-3; N = 5000;
%! u = 0.5 * kron (2 * rand (13, 1) - 1, ones (400, 1)); u = u(1:N);
%! ubar = u - 2 * u.^2 + 0.8 * u.^3;
%! xbar = simc (idpoly (1, 1, 1, 1, [1 2], 0, 0), iddata ([], ubar, Ts));
%! x = xbar;
%! for k = 1:60
%!   x -= (x + 1.5 * x.^2 + x.^3 - xbar) ./ (1 + 3 * x + 3 * x.^2);
%! endfor
%! y0 = x;

%!test  # noise-free: linear part, NL_H and NL_W exactly
%! [model, Infos, yhat] = hwsrivc (iddata (y0, u, Ts), [1 2 0 3 3]);
%! assert (model.F, [1 2], 1e-4);
%! assert (model.B, 1, 1e-4);
%! assert (Infos.NL_H, [1; -2; 0.8], 1e-3);
%! assert (Infos.NL_W, [1; 1.5; 1], 1e-3);
%! assert (norm (yhat - y0) / norm (y0) < 1e-3);

%!test  # noisy: within 4 reported sd
%! randn ("state", 8);
%! y = y0 + 0.03 * randn (N, 1);
%! [~, I] = hwsrivc (iddata (y, u, Ts), [1 2 0 3 3]);
%! truth = [2 1 -2 0.8 1.5 1]';
%! assert (all (abs (I.theta - truth) < 4 * I.sd(:)));

%!test  # CONTSID's positional (model, tol, maxiter) = the named options
%! d = iddata (y0, u, Ts);
%! warning ("off", "hwsrivc:notConverged", "local");
%! [~, I0] = hwsrivc (d, [1 2 0 3 3]);
%! assert (I0.iternum > 1);
%! [m1, I1] = hwsrivc (d, [1 2 0 3 3], [], 1e-3, 1);
%! [m2, I2] = hwsrivc (d, [1 2 0 3 3], "Tol", 1e-3, "MaxIter", 1);
%! assert (I1.theta, I2.theta, 0);
%! assert (I1.iternum, 1);      # the positional maxiter was used

%!error id=hwsrivc:notSupported hwsrivc (iddata (y0, u, Ts), [1 2 0 3 3], [2 1 1 1], 1e-6, 10)
%!error id=hwsrivc:badInput hwsrivc (iddata (y0, u, Ts), [1 2 0 3 3], [], 1e-6, 10, 1)
%!error id=hwsrivc:notSupported hwsrivc (iddata (y0, u, Ts), [1 2 0 3 3], "InitMethod", "lssvf")
%!error id=hwsrivc:notSupported hwsrivc (iddata (y0, u, Ts), [1 2 0 3 3], "InitMethod", "ivgpmf")
%!error id=hwsrivc:notSupported hwsrivc (iddata (y0, u, Ts), [1 2 0 3 3], "InitMethod", [2 1 1 1])
%!error id=hwsrivc:badOption hwsrivc (iddata (y0, u, Ts), [1 2 0 3 3], "InitMethod", "nonsense")
%!error id=hwsrivc:notSupported hwsrivc (iddata (y0, u, Ts), [1 2 0 3 3], "ArmaMethod", "ivarma")
%!error id=hwsrivc:badOption hwsrivc (iddata (y0, u, Ts), [1 2 0 3 3], "ArmaMethod", "x")
%!error id=hwsrivc:badInput hwsrivc (iddata (y0, u, Ts), [1 2])
%!error id=hwsrivc:badInput hwsrivc (iddata (y0, u, Ts), [1 1 0 3 3])
%!error id=hwsrivc:badInput hwsrivc (iddata (y0, u, Ts), [1 2 0 0 3])
%!error id=hwsrivc:badInput hwsrivc (iddata (y0, [u u], Ts), [1 2 0 3 3])
%!error id=hwsrivc:badOption hwsrivc (iddata (y0, u, Ts), [1 2 0 3 3], "Tol", 0)
%!error id=hwsrivc:badInput [a, b, c, d] = hwsrivc (iddata (y0, u, Ts), [1 2 0])

%!demo
%! ## CONTSID's Hammerstein-Wiener demo: f(u) = u - 2u^2 + 0.8u^3,
%! ## G = 1/(s + 2), g(x) = x + 1.5x^2 + x^3
%! Ts = 5e-3; N = 5000;
%! u = 0.5 * kron (2 * rand (13, 1) - 1, ones (400, 1)); u = u(1:N);
%! xbar = simc (idpoly (1, 1, 1, 1, [1 2], 0, 0),
%!              iddata ([], u - 2 * u.^2 + 0.8 * u.^3, Ts));
%! x = xbar;
%! for k = 1:60, x -= (x + 1.5*x.^2 + x.^3 - xbar) ./ (1 + 3*x + 3*x.^2); end
%! y = x + 0.03 * randn (N, 1);
%! [model, Infos, yhat] = hwsrivc (iddata (y, u, Ts), [1 2 0 3 3]);
%! present (model)
%! [Infos.NL_H Infos.NL_W]
%! plot ((1:N) * Ts, [y yhat]); legend ("noisy output", "model output");
