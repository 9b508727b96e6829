## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn {} {@var{theta} =} pdelssvf4heatdiffusion (@var{Data1}, @var{Data2}, @var{Filter})
## Least-squares state-variable-filter (LSSVF) estimate of the heat
## equation
##
## @example
## dX/dt (t,x) - a d2X/dx2 (t,x) = b u(t,x),  X = 0 at both ends of x,
## y = X + v
## @end example
##
## from a field sampled on a uniform time-space grid.  @var{theta} = [a; b].
##
## @var{Data1}.Output (y) and @var{Data1}.Input (u) are
## numel(@var{Data2}.t)-by-numel(@var{Data2}.x) (one row per instant, one
## column per node, boundaries included); @var{Data2}.t and @var{Data2}.x
## are the uniform time and space grids (at least 4 points each).
## @var{Filter}.BF = [lambda_t lambda_x] are the cut-offs of the
## state-variable filter, order 1 in time and 2 in space,
## @code{lambda_t/(s+lambda_t) * (lambda_x/(p+lambda_x))^2} (rad per time
## unit, rad per space unit; a scalar serves both); @var{Filter}.Str is
## @qcode{"Bili"} (the default: bilinear rule, the Crank-Nicolson scheme of
## @code{sim_heat}, so that noise-free data simulated by @code{sim_heat}
## give theta exactly) or @qcode{"Euler"} (backward Euler rule, first-order
## accurate in the time step).
##
## The filter is applied to the differenced field (the time difference, the
## second space difference with the known zero boundary values, the
## averaged source) node by node, so the unknown boundary slope and the
## initial field do not bias the estimate.  With noisy data the least
## squares estimate is biased; use @code{pdesrivc4heatdiffusion}.
##
## Example:
## @example
## Data2.x = 0:0.02:1;  Data2.t = 0:1:900;
## Data1.Input = zeros (numel (Data2.t), numel (Data2.x));
## Data1.Input(mod (Data2.t, 300) < 150, 26) = 0.01;
## Data1.Output = sim_heat ([8.4e-5 1], Data1, Data2, zeros (size (Data2.x)));
## Filter.Str = "Bili";  Filter.BF = [1 1];
## theta = pdelssvf4heatdiffusion (Data1, Data2, Filter)'
## @end example
## @seealso{pdesrivc4heatdiffusion, pderivc4heatdiffusion, sim_heat}
## @end deftypefn

function varargout = pdelssvf4heatdiffusion (varargin)
  varargout = contsid_guard ("pdelssvf4heatdiffusion", @pdelssvf4heatdiffusion_body, nargout, varargin);
endfunction

function [theta, varargout] = pdelssvf4heatdiffusion_body (varargin)
  fname = "pdelssvf4heatdiffusion";
  contsid_nargchk (fname, nargin, nargout, [3 3], 1);
  [Data1, Data2, Filter] = varargin{:};
  [t, x, y, u] = pde_heat_data (fname, Data1, Data2, true);
  if (! isstruct (Filter) || ! isscalar (Filter) || ! isfield (Filter, "BF"))
    error ([fname ":badOption"],
           "%s: Filter must be a struct with the field BF (and Str)", fname);
  endif
  rule = "bili";
  if (isfield (Filter, "Str"))
    if (! ischar (Filter.Str))
      error ([fname ":badOption"], "%s: Filter.Str must be 'Bili' or 'Euler'",
             fname);
    endif
    switch (lower (Filter.Str))
      case "bili"
        rule = "bili";
      case "euler"
        rule = "euler";
      otherwise
        error ([fname ":badOption"],
               "%s: Filter.Str must be 'Bili' or 'Euler', got '%s'", fname,
               Filter.Str);
    endswitch
  endif
  bf = Filter.BF;
  if (! (isnumeric (bf) && isreal (bf) && any (numel (bf) == [1 2])
         && all (isfinite (bf(:))) && all (bf(:) > 0)))
    error ([fname ":badOption"],
           "%s: Filter.BF must be [lambda_t lambda_x] (or one value), > 0",
           fname);
  endif
  bf = double (bf(:).');
  if (isscalar (bf))
    bf = [bf bf];
  endif
  theta = pde_mex (fname, y, u, struct ("t", t, "x", x, "rule", rule,
                                       "lambda", bf));
endfunction

%!shared D1, D2, th0
%! D2.x = 0:0.05:1;  D2.t = 0:2:1200;
%! D1.Input = zeros (numel (D2.t), numel (D2.x));
%! D1.Input(:, 11) = 0.01 * (mod (D2.t(:), 400) < 200);
%! D1.Input(:, 5) = 0.004 * sin (D2.t(:) / 60);
%! th0 = [5e-4; 0.7];
%! D1.Output = sim_heat (th0, D1, D2, zeros (size (D2.x)));

%!test
%! ## Noise-free data of the Crank-Nicolson model: exact with the bilinear
%! ## rule, whatever the cut-offs.
%! th = pdelssvf4heatdiffusion (D1, D2, struct ("Str", "Bili", "BF", [1 1]));
%! assert (th, th0, 1e-8 * abs (th0));
%! th = pdelssvf4heatdiffusion (D1, D2, struct ("Str", "Bili", "BF", [0.05 20]));
%! assert (th, th0, 1e-8 * abs (th0));

%!test
%! ## Nonzero initial field: the initial transient does not enter.
%! D = D1;
%! D.Output = sim_heat (th0, D1, D2, sin (pi * D2.x));
%! th = pdelssvf4heatdiffusion (D, D2, struct ("BF", 0.5));
%! assert (th, th0, 1e-8 * abs (th0));

%!test
%! ## Euler's rule: first-order error in the time step (halved with it).
%! th = pdelssvf4heatdiffusion (D1, D2, struct ("Str", "Euler", "BF", [0.05 5]));
%! e1 = abs (th(1) / th0(1) - 1);
%! D2b = D2;  D2b.t = 0:1:1200;
%! D1b.Input = interp1 (D2.t, D1.Input, D2b.t);
%! D1b.Output = sim_heat (th0, D1b, D2b, zeros (size (D2.x)));
%! thb = pdelssvf4heatdiffusion (D1b, D2b, struct ("Str", "Euler", "BF", [0.05 5]));
%! e2 = abs (thb(1) / th0(1) - 1);
%! assert (e1 < 0.05);
%! assert (e1 / e2 > 1.6 && e1 / e2 < 2.4);

%!error id=pdelssvf4heatdiffusion:badOption
%! pdelssvf4heatdiffusion (D1, D2, struct ("Str", "Tustin", "BF", 1))
%!error id=pdelssvf4heatdiffusion:badOption
%! pdelssvf4heatdiffusion (D1, D2, struct ("BF", [1 -1]))
%!error id=pdelssvf4heatdiffusion:badOption
%! pdelssvf4heatdiffusion (D1, D2, struct ("Str", "Bili"))
%!error id=pdelssvf4heatdiffusion:dimensionMismatch
%! D = D1;  D.Output(end, :) = [];
%! pdelssvf4heatdiffusion (D, D2, struct ("BF", 1))
%!error id=pdelssvf4heatdiffusion:badInput
%! pdelssvf4heatdiffusion (struct ("Input", D1.Input), D2, struct ("BF", 1))
%!error id=pdelssvf4heatdiffusion:badInput
%! D = D2;  D.x(3) += 0.01;              # a non-uniform space grid
%! pdelssvf4heatdiffusion (D1, D, struct ("BF", 1))
%!error id=pdelssvf4heatdiffusion:numericalFailure
%! D = D1;  D.Input(:) = 0;
%! pdelssvf4heatdiffusion (D, D2, struct ("BF", 1))
%!error id=pdelssvf4heatdiffusion:badInput pdelssvf4heatdiffusion (D1, D2)

%!demo
%! Data2.x = 0:0.02:1;  Data2.t = 0:1:900;
%! Data1.Input = zeros (numel (Data2.t), numel (Data2.x));
%! Data1.Input(mod (Data2.t, 300) < 150, 26) = 0.01;
%! theta = [8.4e-5 1];
%! Data1.Output = sim_heat (theta, Data1, Data2, zeros (size (Data2.x)));
%! Filter.Str = "Bili";  Filter.BF = [1 1];
%! printf ("true [%g %g], LSSVF [%g %g]\n", theta,
%!         pdelssvf4heatdiffusion (Data1, Data2, Filter));
