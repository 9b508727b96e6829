## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn  {} {[@var{model}, @var{Infos}] =} hrivc (@var{data}, [@var{nb} @var{nc} @var{nd} @var{nf} @var{nk}])
## @deftypefnx {} {[@dots{}] =} hrivc (@var{data}, @var{nn}, @var{lambda0}, @var{t0}, @var{initMethod}, @var{tol}, @var{maxiter}, @var{arma_method})
## @deftypefnx {} {[@dots{}] =} hrivc (@var{data}, @var{nn}, @var{name}, @var{value}, @dots{})
## Continuous-time Hammerstein Box-Jenkins model by refined IV (HRIVC,
## Laurain, Gilson, Garnier and Young, CDC 2008):
## @example
## y(tk) = B(p)/F(p) ubar(tk - nk Ts) + C(q^-1)/D(q^-1) e(tk),
## ubar = sum_i alpha_i f_i(u),  alpha_1 = 1
## @end example
## The inputs of @var{data} are the basis functions f_i(u) (as
## @code{hsrivc}); @var{nn} = [nb nc nd nf nk], nc and nd the orders of
## the discrete-time ARMA noise model (C, D monic in q^-1).
##
## Algorithm: HSRIVC (see @code{hsrivc}) alternated with the noise model:
## C and D are fitted to the simulation residual y - B/F ubar by
## Hannan-Rissanen (a long AR for the innovations, then least squares)
## polished by Gauss-Newton prediction-error steps, roots kept in the
## unit disc (the ARMA estimator of @code{rivc}), and the next refined-IV
## steps run on the data prefiltered by D/C (exact at the samples for ZOH
## inputs: the discrete filter commutes with the sampled B/F), until the
## separated plant parameters stop changing. Options as @code{hsrivc}
## (@var{initMethod} / @code{"InitMethod"}: @qcode{"sriv"} default,
## @qcode{"ivgpmf"} = @qcode{"ivsvf"}, the IVSVF start whose filter
## (lambda/(p + lambda))^n is CONTSID's Poisson-moment functionals,
## @qcode{"lssvf"}, or a MISO model; the start used in
## @code{Infos.InitMethod}); @var{arma_method} / @code{"ArmaMethod"}
## chooses the ARMA estimator as in @code{rivc}: @qcode{"pem"} (default,
## Hannan-Rissanen then Gauss-Newton prediction-error steps) or
## @qcode{"ivarma"} (Young's IVARMA), said in @code{Infos.ArmaMethod};
## other names raise @code{hrivc:badOption}. The covariance is that of
## the last refined-IV step on prefiltered data.
##
## Outputs as @code{hsrivc}; @code{Infos.Noisemodel} is the discrete-time
## @code{idpoly} C/D with the innovation variance.
## @seealso{hsrivc, hwsrivc, srivc}
## @end deftypefn

function varargout = hrivc (varargin)
  varargout = contsid_guard ("hrivc", @hrivc_body, nargout, varargin);
endfunction

function [model, Infos, varargout] = hrivc_body (varargin)
  contsid_nargchk ("hrivc", nargin, nargout, [2 Inf], 2);
  [model, Infos] = contsid_block ("hrivc", varargin);
endfunction

%!shared u, udata, Ts, ydet, N
%! rand ("state", 3); randn ("state", 3);
%! N = 1500; u = 4 * rand (N, 1) - 2; Ts = 0.5;
%! udata = [u u.^2 u.^3];
%! m = idpoly (1, [10 30], 1, 1, [1 1 5], 0, 0);
%! ydet = simc (m, iddata ([], udata * [1; 0.5; 0.25], Ts));

%!test  # noise-free: the linear part and the nonlinearity exactly
%! [model, Infos] = hrivc (iddata (ydet, udata, Ts), [2 1 1 2 0]);
%! assert (Infos.NLinCoeff, [1 0.5 0.25], 1e-6);
%! assert (Infos.modelLin.F, [1 1 5], 1e-6);
%! assert (Infos.modelLin.B, [10 30], 1e-5);

%!test  # coloured noise: plant within 4 sd, noise model near the truth
%! randn ("state", 7);
%! e = 0.6 * randn (N, 1);
%! v = filter ([1 0.5], [1 -0.85], e);
%! [~, I] = hrivc (iddata (ydet + v, udata, Ts), [2 1 1 2 0]);
%! truth = [1 5 10 30 0.5 0.25]';
%! assert (all (abs (I.theta - truth) < 4 * I.sd(:)));
%! assert (I.Noisemodel.D, [1 -0.85], 0.05);
%! assert (I.Noisemodel.C, [1 0.5], 0.1);

%!test  # noise-free: every start method reaches the exact system
%! for init = {"sriv", "srivc", "ivgpmf", "ivsvf", "lssvf"}
%!   [~, Infos] = hrivc (iddata (ydet, udata, Ts), [2 1 1 2 0], [], 0,
%!                       init{1});
%!   assert (Infos.theta, [1 5 10 30 0.5 0.25]', 1e-6);
%!   assert (Infos.InitMethod.Requested, init{1});
%! endfor

%!test  # the start is lssvf's MISO estimate and is used
%! randn ("state", 7);
%! v = filter ([1 0.5], [1 -0.85], 0.6 * randn (N, 1));
%! z = iddata (ydet + v, udata, Ts);
%! warning ("off", "hrivc:notConverged", "local");
%! [~, I1] = hrivc (z, [2 1 1 2 0], 1, 0, "lssvf", [], 1);
%! Ml = lssvf (z, [2 2 2 2 0 0 0], 1);
%! assert (I1.InitMethod.Theta, Ml.theta, 1e-12);
%! [~, I1m] = hrivc (z, [2 1 1 2 0], 1, 0, Ml.theta, [], 1);
%! assert (I1.theta, I1m.theta, 1e-12 * norm (I1.theta));
%! [~, I0] = hrivc (z, [2 1 1 2 0], 1, 0, "sriv", [], 1);
%! assert (norm (I1.theta - I0.theta) > 1e-3 * norm (I0.theta));

%!test  # ArmaMethod 'ivarma' as rivc's: on a linear record (one basis
%! # column u, the Hammerstein of a degree-1 polynomial) hrivc is rivc;
%! # an ARMA(2,2) for ARMA(1,1) noise (near pole-zero cancellation) makes
%! # the two ARMA estimators' fixed points differ, so the choice shows
%! pkg load control
%! Tl = 0.05; Nl = 3000; randn ("state", 11);
%! ul = kron (sign (randn (Nl / 10, 1)), ones (10, 1));
%! xl = lsim (c2d (tf ([1.5 4], [1 1.2 4]), Tl), ul);
%! randn ("state", 13);
%! zl = iddata (xl + filter ([1 0.5], [1 -0.9], 0.05 * randn (Nl, 1)), ul, Tl);
%! [Mr, C, D] = rivc (zl, [2 2 2 2 0], "Tol", 1e-10, "ArmaMethod", "ivarma");
%! [~, I] = hrivc (zl, [2 2 2 2 0], "Tol", 1e-10, "ArmaMethod", "ivarma");
%! assert (I.ArmaMethod, "ivarma");
%! assert (I.theta.', Mr.theta, 1e-8 * norm (Mr.theta));
%! assert ([I.Noisemodel.C, I.Noisemodel.D], [C, D], 1e-8);
%! [~, Ip] = hrivc (zl, [2 2 2 2 0], "Tol", 1e-10, "ArmaMethod", "pem");
%! assert (norm ([Ip.Noisemodel.C, Ip.Noisemodel.D] - [C, D]) > 0.1);

%!error id=hrivc:badOption hrivc (iddata (ydet, udata, Ts), [2 1 1 2 0], [], 0, [], [], [], "ls")
%!error id=hrivc:badOption hrivc (iddata (ydet, udata, Ts), [2 1 1 2 0], "ArmaMethod", {"pem"})
%!error id=hrivc:badOption hrivc (iddata (ydet, udata, Ts), [2 1 1 2 0], "InitMethod", "nonsense")
%!error id=hrivc:badOption hrivc (iddata (ydet, udata, Ts), [2 1 1 2 0], [], 0, {"lssvf"})
%!error id=hrivc:badInput hrivc (iddata (ydet, udata, Ts), [2 2 0])
%!error id=hrivc:badInput hrivc (iddata (ydet, udata, Ts), [2 1 1 0 0])
%!error id=hrivc:badInput hrivc (iddata (ydet, udata, Ts), [2 1 1 2 0.5])
%!error id=hrivc:badOption hrivc (iddata (ydet, udata, Ts), [2 1 1 2 0], "MaxIter", -1)
%!error id=hrivc:badInput hrivc (iddata (ydet(1:40), udata(1:40, :), Ts), [2 5 5 2 0])

%!demo
%! ## Hammerstein plant with ARMA noise (1 + 0.5 q^-1)/(1 - 0.85 q^-1)
%! N = 2000; u = 4 * rand (N, 1) - 2; Ts = 0.5; udata = [u u.^2 u.^3];
%! m = idpoly (1, [10 30], 1, 1, [1 1 5], 0, 0);
%! ydet = simc (m, iddata ([], udata * [1; 0.5; 0.25], Ts));
%! y = ydet + filter ([1 0.5], [1 -0.85], 0.6 * randn (N, 1));
%! [model, Infos] = hrivc (iddata (y, udata, Ts), [2 1 1 2 0]);
%! Infos.modelLin
%! Infos.NLinCoeff
%! Infos.Noisemodel
