## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn  {} {[@var{th}, @var{infos}, @var{ysim}] =} lpvsrivc (@var{data}, @var{nn}, @var{DepA}, @var{DepB})
## @deftypefnx {} {[@dots{}] =} lpvsrivc (@var{data}, @var{nn}, @var{DepA}, @var{DepB}, @var{tol}, @var{maxiter}, @var{Ainit}, @var{Binit})
## Simplified refined instrumental variable estimate of a continuous-time
## linear parameter-varying output-error model (LPV-SRIVC).
##
## The model (see @code{simulLPVCT} for its form and discretisation)
## @example
## y^(na) + a1(rho) y^(na-1) + .. + a_na(rho) y = b1(rho) u^(nb-1) + .. + b_nb(rho) u + e
## @end example
## with each coefficient a combination of known basis functions of the
## scheduling signal, a_i(rho_k) = sum_j a_ij DepA(j, i, k).
##
## @table @var
## @item data
## an @code{iddata} object (one input, uniformly sampled) or @var{y},
## @var{u}, @var{Ts}.
## @item nn
## [nb na]: the number of numerator coefficients and the denominator order;
## they must match @code{size (DepB, 2)} and @code{size (DepA, 2)}.
## @item DepA, DepB
## n_dep-by-na-by-N and n_dep-by-nb-by-N basis functions evaluated at the N
## samples (a row of zeros: a basis function not used for that
## coefficient).
## @item tol, maxiter
## stop when the relative change of the parameters is below @var{tol}
## (default 1e-4), or after @var{maxiter} iterations (default 50).
## @item Ainit, Binit
## an initial model in the format of @code{infos.Arivc}, @code{infos.Brivc}
## (default: least squares with the prefilter 1/(p + lambda)^na for
## lambda = 0.3/Ts, 0.1/Ts, .. (8 values, factors of 3), keeping the
## estimate whose simulated output fits the data best).  An iterate whose
## auxiliary model is unstable is pulled back towards the previous one.
## @end table
##
## Outputs: @var{th}, the used coefficients as a column (a_1j .. a_na,j row
## by row, then b_1j .. b_nb,j); @var{infos}, a struct with fields
## @code{J} (mean squared output error), @code{Iteration},
## @code{converged}, @code{Arivc} ((na+1)-by-n_dep, first row [1 0 .. 0])
## and @code{Brivc} (nb-by-n_dep), ready for @code{simulLPVCT},
## @code{extractPoles} and @code{extractZeros}; @var{ysim}, the simulated
## output of the estimate.
##
## @strong{Algorithm} (Laurain, Gilson, Toth, Garnier, Automatica 46, 2010;
## Laurain, Toth, Gilson, Garnier, IET Control Theory Appl. 5(7), 2011):
## the model is linear in the a_ij, b_ij with regressors that are products of
## the basis functions with derivatives of y and u; each iteration
## simulates the previous estimate (auxiliary model), takes the
## time-varying regressors and the instruments from its output, and
## prefilters every product by 1/A_0(p), A_0 the part of A with constant
## basis functions.  Derivatives are the Euler differences of
## @code{simulLPVCT}, so data simulated by it are fitted exactly; data from
## a continuous-time system give estimates biased by O(Ts).
##
## @strong{Example}
## @example
## Ts = 0.005; t = 0:Ts:15; p = sin (2*pi/3*t); u = rand (numel (t), 1)*2 - 1;
## DepA(:,1,:) = [ones(size(p)); p; p.^2];
## DepA(:,2,:) = [ones(size(p)); p; zeros(size(p))];
## DepB(:,1,:) = [ones(size(p)); cos(p)];
## DepB(:,2,:) = [ones(size(p)); sin(2*p)];
## y = simulLPVCT (u, [1 0 0; 2 -1.5 2; 5 3 0], DepA, [3 2; 5 -3], DepB, Ts);
## y = y + 0.1 * std (y) * randn (size (y));
## [modelOE, infosOE] = lpvsrivc (iddata (y, u, Ts), [2 2], DepA, DepB);
## infosOE.Arivc
## @end example
## @seealso{lpvrivc, simulLPVCT, extractPoles, extractZeros, srivc}
## @end deftypefn

function varargout = lpvsrivc (varargin)
  varargout = contsid_guard ("lpvsrivc", @lpvsrivc_body, nargout, varargin);
endfunction

function varargout = lpvsrivc_body (varargin)
  contsid_nargchk ("lpvsrivc", nargin, nargout, [4 10], 3);
  [th, infos, ysim] = lpv_estimate ("lpvsrivc", 2, varargin);
  varargout = {th, infos, ysim};
endfunction

%!shared Ts, u, A, B, DepA, DepB, ydet, N
%! Ts = 0.005; t = 0:Ts:15; N = numel (t); p = sin (2*pi/3*t);
%! rand ("seed", 1); u = rand (N, 1)*2 - 1;
%! DepA = zeros (3, 2, N); DepB = zeros (2, 2, N);
%! DepA(:,1,:) = [ones(size(p)); p; p.^2];
%! DepA(:,2,:) = [ones(size(p)); p; zeros(size(p))];
%! DepB(:,1,:) = [ones(size(p)); cos(p)];
%! DepB(:,2,:) = [ones(size(p)); sin(2*p)];
%! A = [1 0 0; 2 -1.5 2; 5 3 0]; B = [3 2; 5 -3];
%! ydet = simulLPVCT (u, A, DepA, B, DepB, Ts);

## Noise-free data: exact recovery; the parameter vector leaves out the
## unused basis function of a2.
%!test
%! [th, infos, ysim] = lpvsrivc (iddata (ydet, u, Ts), [2 2], DepA, DepB);
%! assert (th, [2 -1.5 2 5 3 3 2 5 -3]', 1e-7);
%! assert (infos.Arivc, A, 1e-7);
%! assert (infos.Brivc, B, 1e-7);
%! assert (infos.converged);
%! assert (ysim, ydet, 1e-8 * max (abs (ydet)));

## White output noise (20 dB): the estimate stays close and J is the noise
## variance.
%!test
%! randn ("seed", 3); e = 0.1 * std (ydet) * randn (N, 1);
%! [th, infos] = lpvsrivc (ydet + e, u, Ts, [2 2], DepA, DepB);
%! assert (norm (infos.Arivc - A) < 0.1 * norm (A));
%! assert (norm (infos.Brivc - B) < 0.1 * norm (B));
%! assert (infos.J, var (e), 0.1 * var (e));

## Data from the continuous-time system (ode45 with a smooth input): the
## Euler model is recovered up to its O(Ts) discretisation bias.
%!test
%! w = [0.3 0.9 1.7 2.9 4.3 6.1 8.3];
%! uu = @(tt) sum (sin (w' * tt), 1);
%! du = @(tt) sum (w' .* cos (w' * tt), 1);
%! rho = @(tt) sin (2*pi/3*tt);
%! f = @(tt, x) [x(2); -(2 - 1.5*rho(tt) + 2*rho(tt)^2)*x(2) ...
%!               - (5 + 3*rho(tt))*x(1) + (3 + 2*cos (rho(tt)))*du(tt) ...
%!               + (5 - 3*sin (2*rho(tt)))*uu(tt)];
%! t = (0:N-1)' * Ts;
%! [~, x] = ode45 (f, t, [0; 0], odeset ("RelTol", 1e-9, "AbsTol", 1e-11));
%! uc = uu (t')';
%! [~, infos] = lpvsrivc (x(:,1), uc, Ts, [2 2], DepA, DepB);
%! assert (infos.Arivc, A, 0.05 * max (abs (A(:))));
%! assert (infos.Brivc, B, 0.05 * max (abs (B(:))));

%!error <Invalid call|called with> lpvsrivc (1, 2)
%!error id=lpvsrivc:dimensionMismatch lpvsrivc (ydet, u, Ts, [2 3], DepA, DepB)
%!error id=lpvsrivc:dimensionMismatch lpvsrivc (ydet, u, Ts, [2 2], DepA(:,:,1:end-1), DepB)
%!error id=lpvsrivc:badInput lpvsrivc (ydet, u, Ts, [2 2 1], DepA, DepB)
%!error id=lpvsrivc:numericalFailure lpvsrivc (ydet, zeros (N, 1), Ts, [2 2], DepA, DepB)
%!error id=lpvsrivc:numericalFailure lpvsrivc (ydet, u, Ts, [2 2], repmat (DepA(:,:,1), [1 1 N]), repmat (DepB(:,:,1), [1 1 N]))
%!error id=lpvsrivc:badOption lpvsrivc (ydet, u, Ts, [2 2], DepA, DepB, -1)
%!error id=lpvsrivc:badInput lpvsrivc (ydet, u, Ts, [2 2], DepA, DepB, [], [], A)

%!demo
%! ## LPV output-error estimate of CONTSID's example at 20 dB, frozen poles
%! Ts = 0.005; t = 0:Ts:15; N = numel (t); p = sin (2*pi/3*t);
%! u = rand (N, 1)*2 - 1;
%! DepA = zeros (3, 2, N); DepB = zeros (2, 2, N);
%! DepA(:,1,:) = [ones(size(p)); p; p.^2];
%! DepA(:,2,:) = [ones(size(p)); p; zeros(size(p))];
%! DepB(:,1,:) = [ones(size(p)); cos(p)];
%! DepB(:,2,:) = [ones(size(p)); sin(2*p)];
%! A = [1 0 0; 2 -1.5 2; 5 3 0]; B = [3 2; 5 -3];
%! y = simulLPVCT (u, A, DepA, B, DepB, Ts);
%! y = y + 0.1 * std (y) * randn (N, 1);
%! [th, infos] = lpvsrivc (iddata (y, u, Ts), [2 2], DepA, DepB)
%! r = -1:0.02:1; DepAN = zeros (3, 2, numel (r));
%! DepAN(:,1,:) = [ones(size(r)); r; r.^2];
%! DepAN(:,2,:) = [ones(size(r)); r; zeros(size(r))];
%! P0 = extractPoles (A, DepAN); P = extractPoles (infos.Arivc, DepAN);
%! plot (real (P0(:)), imag (P0(:)), ".k", real (P(:)), imag (P(:)), "xg");
%! legend ("true frozen poles", "LPV-SRIVC");
