## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn  {} {[@var{theta}, @var{ni}] =} pdesrivc4heatdiffusion (@var{Data1}, @var{Data2}, @var{IC})
## @deftypefnx {} {[@var{theta}, @var{ni}] =} pdesrivc4heatdiffusion (@var{Data1}, @var{Data2}, @var{IC}, @var{tol}, @var{maxiter})
## Simplified refined instrumental variable (SRIVC) estimate of the heat
## equation
##
## @example
## dX/dt (t,x) - a d2X/dx2 (t,x) = b u(t,x),  X = 0 at both ends of x,
## X(t0,x) = IC(x),  y = X + e  (e white)
## @end example
##
## @var{theta} = [a; b]; @var{ni} is the number of iterations.  The data
## are those of @code{pdelssvf4heatdiffusion} (uniform grids
## @var{Data2}.t, @var{Data2}.x; @var{Data1}.Output and @var{Data1}.Input
## one row per instant, one column per node); @var{IC} (numel(x) values)
## is the initial field, used by the auxiliary model.
##
## The iterations start from an LSSVF estimate.  Each one filters the
## differenced data by the current model itself (one Crank-Nicolson
## simulation with the array as source, zero initial field and
## boundaries), takes as instruments the noise-free field of the current
## model (@code{sim_heat} with @var{IC}) and solves the instrumental
## variable equations, until the relative change of theta is below
## @var{tol} (default 1e-6) or @var{maxiter} (default 50) iterations; the
## latter raises the warning @code{pdesrivc4heatdiffusion:notConverged}.
## A non-positive estimate of a on the way is the error
## @code{pdesrivc4heatdiffusion:numericalFailure}.
##
## Example (10 dB of white noise):
## @example
## Data2.x = 0:0.02:1;  Data2.t = 0:1:900;
## Data1.Input = zeros (numel (Data2.t), numel (Data2.x));
## Data1.Input(mod (Data2.t, 300) < 150, 26) = 0.01;
## ydet = sim_heat ([8.4e-5 1], Data1, Data2, zeros (size (Data2.x)));
## Data1.Output = ydet + std (ydet(:)) / sqrt (10) * randn (size (ydet));
## [theta, ni] = pdesrivc4heatdiffusion (Data1, Data2, zeros (size (Data2.x)))
## @end example
## @seealso{pdelssvf4heatdiffusion, pderivc4heatdiffusion, sim_heat}
## @end deftypefn

function varargout = pdesrivc4heatdiffusion (varargin)
  varargout = contsid_guard ("pdesrivc4heatdiffusion", @pdesrivc4heatdiffusion_body, nargout, varargin);
endfunction

function [theta, ni, varargout] = pdesrivc4heatdiffusion_body (varargin)
  fname = "pdesrivc4heatdiffusion";
  contsid_nargchk (fname, nargin, nargout, [3 5], 2);
  [theta, ni] = pde_heat_iv (fname, varargin, []);
endfunction

%!shared D1, D2, th0, ydet
%! D2.x = 0:0.05:1;  D2.t = 0:2:1200;
%! D1.Input = zeros (numel (D2.t), numel (D2.x));
%! D1.Input(:, 11) = 0.01 * (mod (D2.t(:), 400) < 200);
%! D1.Input(:, 5) = 0.004 * sin (D2.t(:) / 60);
%! th0 = [5e-4; 0.7];
%! ydet = sim_heat (th0, D1, D2, zeros (size (D2.x)));
%! D1.Output = ydet;

%!test
%! [th, ni] = pdesrivc4heatdiffusion (D1, D2, zeros (size (D2.x)));
%! assert (th, th0, 1e-7 * abs (th0));
%! assert (ni >= 1 && ni <= 50);

%!test
%! ## White noise at 10 dB: SRIVC close to the truth, LSSVF biased.
%! randn ("state", 3);
%! D = D1;
%! D.Output = ydet + std (ydet(:)) / sqrt (10) * randn (size (ydet));
%! th = pdesrivc4heatdiffusion (D, D2, zeros (size (D2.x)));
%! assert (th, th0, 0.05 * abs (th0));
%! thls = pdelssvf4heatdiffusion (D, D2, struct ("BF", [1 1]));
%! assert (abs (thls(1) / th0(1) - 1) > 0.2);

%!test
%! ## Nonzero initial field, given to the auxiliary model.
%! ic = 0.05 * sin (pi * D2.x);
%! D = D1;  D.Output = sim_heat (th0, D1, D2, ic);
%! th = pdesrivc4heatdiffusion (D, D2, ic);
%! assert (th, th0, 1e-7 * abs (th0));

%!warning id=pdesrivc4heatdiffusion:notConverged
%! randn ("state", 4);
%! D = D1;  D.Output = ydet + 0.01 * std (ydet(:)) * randn (size (ydet));
%! pdesrivc4heatdiffusion (D, D2, zeros (size (D2.x)), 1e-15, 1);

%!error id=pdesrivc4heatdiffusion:dimensionMismatch
%! pdesrivc4heatdiffusion (D1, D2, [0 0])
%!error id=pdesrivc4heatdiffusion:badOption
%! pdesrivc4heatdiffusion (D1, D2, zeros (size (D2.x)), -1)
%!error id=pdesrivc4heatdiffusion:badOption
%! pdesrivc4heatdiffusion (D1, D2, zeros (size (D2.x)), 1e-6, 0)
%!error id=pdesrivc4heatdiffusion:badInput
%! pdesrivc4heatdiffusion (D1, struct ("t", D2.t), zeros (size (D2.x)))
%!error id=pdesrivc4heatdiffusion:badInput pdesrivc4heatdiffusion (D1, D2)

%!demo
%! Data2.x = 0:0.02:1;  Data2.t = 0:1:900;
%! Data1.Input = zeros (numel (Data2.t), numel (Data2.x));
%! Data1.Input(mod (Data2.t, 300) < 150, 26) = 0.01;
%! theta = [8.4e-5 1];  IC = zeros (size (Data2.x));
%! ydet = sim_heat (theta, Data1, Data2, IC);
%! Data1.Output = ydet + std (ydet(:)) / sqrt (10) * randn (size (ydet));
%! [th, ni] = pdesrivc4heatdiffusion (Data1, Data2, IC);
%! printf ("true [%g %g], SRIVC [%g %g] in %d iterations\n", theta, th, ni);
%! y = sim_heat (th, Data1, Data2, IC);
%! plot (Data2.t, Data1.Output(:, 26), ".", Data2.t, y(:, 26), "r");
%! legend ("noisy temperature at x = 0.5", "SRIVC model output");
