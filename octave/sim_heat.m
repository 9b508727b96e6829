## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn {} {@var{y} =} sim_heat (@var{theta}, @var{Data1}, @var{Data2}, @var{IC})
## Simulate the one-dimensional heat equation with a distributed source
##
## @example
## dX/dt (t,x) = a d2X/dx2 (t,x) + b u(t,x),   X(t,x0) = X(t,xN) = 0,
## X(t0,x) = IC(x)
## @end example
##
## (Dirichlet boundaries at both ends of the space grid), the model of
## @code{pdelssvf4heatdiffusion}, @code{pdesrivc4heatdiffusion} and
## @code{pderivc4heatdiffusion}.
##
## @var{theta} = [a b] (a >= 0, the diffusion coefficient; b, the input
## gain).  @var{Data2}.t is the time grid (Nt instants) and @var{Data2}.x
## the space grid (Nx nodes, boundaries included), both strictly increasing;
## the steps may vary.  @var{Data1}.Input is the source u, Nt-by-Nx (one row
## per instant, one column per node; the boundary columns do not enter, the
## boundary values being fixed).  @var{IC} holds the Nx values of the
## initial field.  @var{y} is Nt-by-Nx: its first row is @var{IC}, its
## boundary columns are zero afterwards.
##
## The space derivative is the three-point second difference on the grid;
## time advances by Crank-Nicolson steps (the trapezoidal rule, the source
## averaged over each step), so that the simulated field obeys exactly the
## bilinear difference equation the estimators use.
##
## Example (a source pulse in the middle of a 1 m bar):
## @example
## Data2.x = 0:0.02:1;  Data2.t = 0:1:600;
## Data1.Input = zeros (numel (Data2.t), numel (Data2.x));
## Data1.Input(Data2.t <= 300, 26) = 0.01;
## Data1.Output = sim_heat ([8.4e-5 1], Data1, Data2, zeros (size (Data2.x)));
## plot (Data2.t, Data1.Output(:, 26))
## @end example
## @seealso{pdelssvf4heatdiffusion, pdesrivc4heatdiffusion, pderivc4heatdiffusion, local_filter3}
## @end deftypefn

function varargout = sim_heat (varargin)
  varargout = contsid_guard ("sim_heat", @sim_heat_body, nargout, varargin);
endfunction

function [y, varargout] = sim_heat_body (varargin)
  contsid_nargchk ("sim_heat", nargin, nargout, [4 4], 1);
  [theta, Data1, Data2, IC] = varargin{:};
  if (! (isnumeric (theta) && isreal (theta) && numel (theta) == 2
         && all (isfinite (theta(:)))))
    error ("sim_heat:badInput", "sim_heat: theta must be [a b], finite");
  endif
  [t, x, ~, u] = pde_heat_data ("sim_heat", Data1, Data2, false);
  if (numel (x) < 3)
    error ("sim_heat:badInput", "sim_heat: Data2.x needs at least 3 nodes");
  endif
  if (! (isnumeric (IC) && isreal (IC) && isvector (IC)))
    error ("sim_heat:badInput", "sim_heat: IC must be a real vector");
  endif
  if (numel (IC) != numel (x))
    error ("sim_heat:dimensionMismatch",
           "sim_heat: IC must have numel(Data2.x) = %d values", numel (x));
  endif
  y = pde_mex ("sim_heat", u, struct ("theta", double (theta(:).'), "t", t,
                                     "x", x, "ic", double (IC(:).')));
endfunction

%!test
%! ## The separable solution exp(-a pi^2 t) sin(pi x) of the source-free
%! ## equation: second-order convergence in the steps dx and dt.
%! a = 0.1;
%! err = zeros (1, 2);
%! for k = 1:2
%!   D2.x = linspace (0, 1, 20 * k + 1);  D2.t = 0:0.02 / k:0.5;
%!   D1.Input = zeros (numel (D2.t), numel (D2.x));
%!   y = sim_heat ([a 3], D1, D2, sin (pi * D2.x));
%!   yex = exp (-a * pi^2 * D2.t(:)) * sin (pi * D2.x);
%!   err(k) = max (abs (y(:) - yex(:)));
%! endfor
%! assert (err(1) < 2e-3);
%! assert (err(1) / err(2) > 3.5 && err(1) / err(2) < 4.5);

%!test
%! ## Against the method of lines integrated by ode45 on the same space grid
%! ## (a non-uniform grid, a source varying in time and space, and a
%! ## non-uniform time grid).
%! x = [0 0.1 0.25 0.3 0.45 0.6 0.7 0.85 1];
%! t = [0 sort(rand (1, 200)) * 0.8, 0.8];  t = unique (t);
%! a = 0.05;  b = -2;
%! uf = @(tt, xx) sin (3 * tt) .* exp (-20 * (xx - 0.4).^2) + tt .* xx;
%! D2.x = x;  D2.t = t;
%! D1.Input = uf (t(:), x);
%! ic = x .* (1 - x);
%! y = sim_heat ([a b], D1, D2, ic);
%! n = numel (x) - 2;  xi = x(2:end-1);
%! hl = x(2:end-1) - x(1:end-2);  hr = x(3:end) - x(2:end-1);
%! L = diag (-2 ./ (hl .* hr)) + diag (2 ./ (hl(2:end) .* (hl(2:end) + hr(2:end))), -1) ...
%!     + diag (2 ./ (hr(1:end-1) .* (hl(1:end-1) + hr(1:end-1))), 1);
%! f = @(tt, z) a * L * z + b * uf (tt, xi(:));
%! opts = odeset ("RelTol", 1e-10, "AbsTol", 1e-12);
%! [~, z] = ode45 (f, t, ic(2:end-1)', opts);
%! assert (y(:, 2:end-1), z, 2e-4 * max (abs (z(:))));
%! assert (y(2:end, [1 end]), zeros (numel (t) - 1, 2));
%! assert (y(1, :), ic);

%!test
%! ## No diffusion: each node integrates its own source (trapezoidal rule).
%! D2.x = 0:0.25:1;  D2.t = 0:0.1:1;
%! D1.Input = repmat (D2.t(:), 1, 5);
%! y = sim_heat ([0 2], D1, D2, zeros (1, 5));
%! assert (y(:, 3), D2.t(:).^2, 1e-12);

%!shared g, z
%! g = struct ("t", [0 1], "x", [0 1 2]);
%! z = struct ("Input", zeros (2, 3));
%!error id=sim_heat:badInput sim_heat ([1 2 3], z, g, [0 0 0])
%!error id=sim_heat:badInput sim_heat ([-1 1], z, g, [0 0 0])
%!error id=sim_heat:badInput
%! sim_heat ([1 1], z, struct ("t", [1 0], "x", [0 1 2]), [0 0 0])
%!error id=sim_heat:badInput sim_heat ([1 1], z, struct ("t", [0 1]), [0 0 0])
%!error id=sim_heat:badInput
%! sim_heat ([1 1], struct ("Input", [0 NaN 0; 0 0 0]), g, [0 0 0])
%!error id=sim_heat:dimensionMismatch
%! sim_heat ([1 1], struct ("Input", zeros (3, 3)), g, [0 0 0])
%!error id=sim_heat:dimensionMismatch sim_heat ([1 1], z, g, [0 0])
%!error id=sim_heat:badInput sim_heat ([1 1], z)

%!demo
%! Data2.x = 0:0.02:1;  Data2.t = 0:1:600;
%! Data1.Input = zeros (numel (Data2.t), numel (Data2.x));
%! Data1.Input(Data2.t <= 300, 26) = 0.01;
%! y = sim_heat ([8.4e-5 1], Data1, Data2, zeros (size (Data2.x)));
%! imagesc (Data2.t, Data2.x, y'); xlabel ("t (s)"); ylabel ("x (m)");
