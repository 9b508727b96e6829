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
## separated plant parameters stop changing. Options as @code{hsrivc};
## @var{arma_method} is accepted and ignored. The covariance is that of
## the last refined-IV step on prefiltered data.
##
## Outputs as @code{hsrivc}; @code{Infos.Noisemodel} is the discrete-time
## @code{idpoly} C/D with the innovation variance.
## @seealso{hsrivc, hwsrivc, srivc}
## @end deftypefn

function [model, Infos, varargout] = hrivc (varargin)
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
