## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn  {} {[@var{th}, @var{Ce}, @var{De}, @var{infos}, @var{ysim}] =} lpvrivc (@var{data}, @var{nn}, @var{DepA}, @var{DepB})
## @deftypefnx {} {[@dots{}] =} lpvrivc (@var{data}, @var{nn}, @var{DepA}, @var{DepB}, @var{tol}, @var{maxiter}, @var{Ainit}, @var{Binit})
## Refined instrumental variable estimate of a continuous-time linear
## parameter-varying Box-Jenkins model (LPV-RIVC).
##
## The model
## @example
## y^(na) + a1(rho) y^(na-1) + .. + a_na(rho) y = b1(rho) u^(nb-1) + .. + b_nb(rho) u
## y(t_k) = chi(t_k) + C(q^-1)/D(q^-1) e(t_k)
## @end example
## is that of @code{lpvsrivc} with a discrete-time ARMA noise model.
##
## @table @var
## @item nn
## [nb na nc nd]: numerator coefficients, denominator order (matching
## @code{size (DepB, 2)} and @code{size (DepA, 2)}) and the noise orders.
## @item data, DepA, DepB, tol, maxiter, Ainit, Binit
## as for @code{lpvsrivc}.
## @end table
##
## Outputs: @var{th}, @var{infos} and @var{ysim} as for @code{lpvsrivc},
## with @code{infos.J} the innovation variance of the noise model;
## @var{Ce} = [1 c1 .. c_nc] and @var{De} = [1 d1 .. d_nd], the noise
## model in powers of q^-1 (estimated by prediction error on
## y - ysim).
##
## @strong{Algorithm}: the iteration of @code{lpvsrivc} with, at each step,
## an ARMA model of the output error of the auxiliary model, whose inverse
## D/C joins the prefilter 1/A_0(p) (Laurain, Toth, Gilson, Garnier, IET
## Control Theory Appl. 5(7), 2011).  With nc = nd = 0 it is
## @code{lpvsrivc}.
##
## @strong{Example}
## @example
## Ts = 0.005; t = 0:Ts:15; p = sin (2*pi/3*t); u = rand (numel (t), 1)*2 - 1;
## DepA(:,1,:) = [ones(size(p)); p; p.^2];
## DepA(:,2,:) = [ones(size(p)); p; zeros(size(p))];
## DepB(:,1,:) = [ones(size(p)); cos(p)];
## DepB(:,2,:) = [ones(size(p)); sin(2*p)];
## ydet = simulLPVCT (u, [1 0 0; 2 -1.5 2; 5 3 0], DepA, [3 2; 5 -3], DepB, Ts);
## v = filter (1, [1 -1 0.2], randn (size (ydet)));
## y = ydet + v / std (v) * 0.1 * std (ydet);
## [model, Ces, Des, infos] = lpvrivc (iddata (y, u, Ts), [2 2 0 2], DepA, DepB);
## @end example
## @seealso{lpvsrivc, simulLPVCT, extractPoles, extractZeros, rivc}
## @end deftypefn

function varargout = lpvrivc (varargin)
  varargout = contsid_guard ("lpvrivc", @lpvrivc_body, nargout, varargin);
endfunction

function varargout = lpvrivc_body (varargin)
  contsid_nargchk ("lpvrivc", nargin, nargout, [4 10], 5);
  [th, infos, ysim, c, d] = lpv_estimate ("lpvrivc", 4, varargin);
  varargout = {th, c, d, infos, ysim};
endfunction

%!shared Ts, u, A, B, DepA, DepB, ydet, N
%! Ts = 0.005; t = 0:Ts:15; N = numel (t); p = sin (2*pi/3*t);
%! rand ("seed", 2); u = rand (N, 1)*2 - 1;
%! DepA = zeros (3, 2, N); DepB = zeros (2, 2, N);
%! DepA(:,1,:) = [ones(size(p)); p; p.^2];
%! DepA(:,2,:) = [ones(size(p)); p; zeros(size(p))];
%! DepB(:,1,:) = [ones(size(p)); cos(p)];
%! DepB(:,2,:) = [ones(size(p)); sin(2*p)];
%! A = [1 0 0; 2 -1.5 2; 5 3 0]; B = [3 2; 5 -3];
%! ydet = simulLPVCT (u, A, DepA, B, DepB, Ts);

## Noise-free data: exact recovery.
%!test
%! [th, Ce, De, infos] = lpvrivc (iddata (ydet, u, Ts), [2 2 0 0], DepA, DepB);
%! assert (th, [2 -1.5 2 5 3 3 2 5 -3]', 1e-7);
%! assert ([Ce De], [1 1]);
%! assert (infos.converged);

## Coloured noise v = e / (1 - q^-1 + 0.2 q^-2) at 20 dB: the noise model
## and its innovation variance are found, the system stays close.
%!test
%! randn ("seed", 5); e = randn (N, 1);
%! v = filter (1, [1 -1 0.2], e);
%! s = 0.1 * std (ydet) / std (v);
%! [th, Ce, De, infos, ysim] = lpvrivc (ydet + s*v, u, Ts, [2 2 0 2], DepA, DepB);
%! assert (Ce, 1);
%! assert (De, [1 -1 0.2], 0.05);
%! assert (infos.J, var (s*e), 0.1 * var (s*e));
%! assert (norm (infos.Arivc - A) < 0.1 * norm (A));
%! assert (norm (infos.Brivc - B) < 0.1 * norm (B));
%! assert (ysim, simulLPVCT (u, infos.Arivc, DepA, infos.Brivc, DepB, Ts), 1e-10);

%!error <Invalid call|called with> lpvrivc (1, 2)
%!error id=lpvrivc:badInput lpvrivc (ydet, u, Ts, [2 2], DepA, DepB)
%!error id=lpvrivc:badInput lpvrivc (ydet, u, Ts, [2 2 -1 0], DepA, DepB)
%!error id=lpvrivc:dimensionMismatch lpvrivc (ydet, u, Ts, [2 2 0 2], DepA, DepB(:,:,1:100))
%!error id=lpvrivc:numericalFailure lpvrivc (ydet, 0*u, Ts, [2 2 0 2], DepA, DepB)

%!demo
%! ## LPV Box-Jenkins estimate of CONTSID's example: AR(2) noise at 20 dB
%! Ts = 0.005; t = 0:Ts:15; N = numel (t); p = sin (2*pi/3*t);
%! u = rand (N, 1)*2 - 1;
%! DepA = zeros (3, 2, N); DepB = zeros (2, 2, N);
%! DepA(:,1,:) = [ones(size(p)); p; p.^2];
%! DepA(:,2,:) = [ones(size(p)); p; zeros(size(p))];
%! DepB(:,1,:) = [ones(size(p)); cos(p)];
%! DepB(:,2,:) = [ones(size(p)); sin(2*p)];
%! ydet = simulLPVCT (u, [1 0 0; 2 -1.5 2; 5 3 0], DepA, [3 2; 5 -3], DepB, Ts);
%! v = filter (1, [1 -1 0.2], randn (N, 1));
%! y = ydet + v / std (v) * 0.1 * std (ydet);
%! [model, Ces, Des, infos, ysim] = lpvrivc (iddata (y, u, Ts), [2 2 0 2], DepA, DepB)
%! plot (t(1:1000), y(1:1000), t(1:1000), ysim(1:1000));
%! legend ("noisy output", "simulated LPV model");
