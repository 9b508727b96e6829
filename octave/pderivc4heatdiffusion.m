## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn  {} {[@var{theta}, @var{Cet}, @var{Det}, @var{Ces}, @var{Des}, @var{ni}] =} pderivc4heatdiffusion (@var{Data1}, @var{Data2}, @var{IC}, @var{nn})
## @deftypefnx {} {[@dots{}] =} pderivc4heatdiffusion (@var{Data1}, @var{Data2}, @var{IC}, @var{nn}, @var{tol}, @var{maxiter})
## Refined instrumental variable (RIVC) estimate of the heat equation with
## a coloured, separable noise field
##
## @example
## dX/dt (t,x) - a d2X/dx2 (t,x) = b u(t,x),  X = 0 at both ends of x,
## y = X + v,  v = Cet(q_t) Ces(q_x) / (Det(q_t) Des(q_x)) e
## @end example
##
## @var{nn} = [ndet ncet ndes nces]: the orders of the time AR, time MA,
## space AR and space MA polynomials.  @var{theta} = [a; b]; @var{Cet},
## @var{Det}, @var{Ces}, @var{Des} are monic rows (e.g. @var{Det} = [1 d1
## d2]); @var{ni} is the number of iterations.  The data, @var{IC},
## @var{tol} and @var{maxiter} are those of @code{pdesrivc4heatdiffusion}.
##
## Each iteration is the SRIVC one plus the noise model: the residual field
## of the auxiliary model is fitted, pooled over the nodes, by an ARMA model
## along time (least squares, or Hannan-Rissanen when ncet > 0), the
## time-whitened field by one along space, and the inverse
## @code{Det Des / (Cet Ces)} (the time MA part and the space MA part made
## minimum-phase) joins the prefilter.
##
## Example (the noise of CONTSID's heat demo):
## @example
## Data2.x = 0:0.02:1;  Data2.t = 0:1:900;
## Data1.Input = zeros (numel (Data2.t), numel (Data2.x));
## Data1.Input(mod (Data2.t, 300) < 150, 26) = 0.01;
## ydet = sim_heat ([8.4e-5 1], Data1, Data2, zeros (size (Data2.x)));
## e = local_filter3 (1, [1 -1.2 0.4]' * [1 -0.3], randn (size (ydet)));
## Data1.Output = ydet + std (ydet(:)) / sqrt (10) * e / std (e(:));
## [theta, Cet, Det, Ces, Des, ni] = ...
##   pderivc4heatdiffusion (Data1, Data2, zeros (size (Data2.x)), [2 0 1 0])
## @end example
## @seealso{pdesrivc4heatdiffusion, pdelssvf4heatdiffusion, local_filter3, sim_heat}
## @end deftypefn

function varargout = pderivc4heatdiffusion (varargin)
  varargout = contsid_guard ("pderivc4heatdiffusion", @pderivc4heatdiffusion_body, nargout, varargin);
endfunction

function [theta, Cet, Det, Ces, Des, ni, varargout] = pderivc4heatdiffusion_body (varargin)
  fname = "pderivc4heatdiffusion";
  contsid_nargchk (fname, nargin, nargout, [4 6], 6);
  nn = varargin{4};
  if (! (isnumeric (nn) && isreal (nn) && numel (nn) == 4
         && all (nn(:) >= 0) && all (nn(:) == fix (nn(:)))))
    error ([fname ":badInput"],
           "%s: nn must be [ndet ncet ndes nces], integers >= 0", fname);
  endif
  [theta, ni, noise] = pde_heat_iv (fname, varargin([1:3, 5:end]), nn);
  [Cet, Det, Ces, Des] = noise{:};
endfunction

%!shared D1, D2, th0, ydet
%! D2.x = 0:0.025:1;  D2.t = 0:2:1200;
%! D1.Input = zeros (numel (D2.t), numel (D2.x));
%! D1.Input(:, 21) = 0.01 * (mod (D2.t(:), 400) < 200);
%! D1.Input(:, 9) = 0.004 * sin (D2.t(:) / 60);
%! th0 = [5e-4; 0.7];
%! ydet = sim_heat (th0, D1, D2, zeros (size (D2.x)));
%! D1.Output = ydet;

%!test
%! [th, Cet, Det, Ces, Des, ni] = pderivc4heatdiffusion (D1, D2, zeros (size (D2.x)), [2 0 1 0]);
%! assert (th, th0, 1e-6 * abs (th0));
%! assert (numel (Det) == 3 && numel (Des) == 2 && Cet == 1 && Ces == 1);

%!test
%! ## The coloured noise of CONTSID's demo at 10 dB: the noise model is
%! ## recovered and theta is close to the truth.
%! randn ("state", 5);
%! e = local_filter3 (1, [1 -1.2 0.4]' * [1 -0.3], randn (size (ydet)));
%! D = D1;  D.Output = ydet + std (ydet(:)) / sqrt (10) * e / std (e(:));
%! [th, Cet, Det, Ces, Des] = pderivc4heatdiffusion (D, D2, zeros (size (D2.x)), [2 0 1 0]);
%! assert (th, th0, 0.05 * abs (th0));
%! assert (Det, [1 -1.2 0.4], 0.05);
%! assert (Des, [1 -0.3], 0.05);

%!test
%! ## A time MA part: estimated by Hannan-Rissanen.
%! randn ("state", 6);
%! e = local_filter3 ([1 0.5]', [1 -0.8]', randn (size (ydet)));
%! D = D1;  D.Output = ydet + 0.2 * std (ydet(:)) * e / std (e(:));
%! [th, Cet, Det] = pderivc4heatdiffusion (D, D2, zeros (size (D2.x)), [1 1 0 0]);
%! assert (th, th0, 0.05 * abs (th0));
%! assert ([Det Cet], [1 -0.8 1 0.5], 0.05);

%!error id=pderivc4heatdiffusion:badInput
%! pderivc4heatdiffusion (D1, D2, zeros (size (D2.x)), [2 0 1])
%!error id=pderivc4heatdiffusion:badInput
%! pderivc4heatdiffusion (D1, D2, zeros (size (D2.x)), [2 0 -1 0])
%!error id=pderivc4heatdiffusion:badOption
%! pderivc4heatdiffusion (D1, D2, zeros (size (D2.x)), [2 0 30 0])
%!error id=pderivc4heatdiffusion:dimensionMismatch
%! pderivc4heatdiffusion (D1, D2, [0 0], [1 0 0 0])
%!error id=pderivc4heatdiffusion:badInput
%! pderivc4heatdiffusion (D1, D2, zeros (size (D2.x)))

%!demo
%! Data2.x = 0:0.02:1;  Data2.t = 0:1:900;
%! Data1.Input = zeros (numel (Data2.t), numel (Data2.x));
%! Data1.Input(mod (Data2.t, 300) < 150, 26) = 0.01;
%! theta = [8.4e-5 1];  IC = zeros (size (Data2.x));
%! ydet = sim_heat (theta, Data1, Data2, IC);
%! e = local_filter3 (1, [1 -1.2 0.4]' * [1 -0.3], randn (size (ydet)));
%! Data1.Output = ydet + std (ydet(:)) / sqrt (10) * e / std (e(:));
%! [th, Cet, Det, Ces, Des, ni] = ...
%!   pderivc4heatdiffusion (Data1, Data2, IC, [2 0 1 0]);
%! printf ("true [%g %g], RIVC [%g %g] in %d iterations\n", theta, th, ni);
%! printf ("Det = [%s] (true [1 -1.2 0.4]), Des = [%s] (true [1 -0.3])\n",
%!         num2str (Det, 3), num2str (Des, 3));
