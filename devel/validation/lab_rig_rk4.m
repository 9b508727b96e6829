## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn {} {@var{X} =} lab_rig_rk4 (@var{f}, @var{x0}, @var{u}, @var{Ts}, @var{nsub})
## @deftypefnx {} {@var{X} =} lab_rig_rk4 (@dots{}, @var{delay})
## Integrator of the simulated lab rigs (@code{lab_rigs}): the state
## equation dx/dt = f(x, u) integrated by the classical fourth-order
## Runge-Kutta method with @var{nsub} equal sub-steps per sampling
## interval, the input held constant over each interval (zero-order hold)
## and, when @var{delay} (seconds, default 0) is given, delayed by it (the
## input before the first sample is u(1): the record starts at rest).
##
## @var{f}: handle @code{f (x, u)} returning a column; @var{x0}: initial
## state (column); @var{u}: N-vector of input samples; @var{Ts}: sampling
## interval.  @var{X}: N-by-n, row k the state at t_k = (k - 1) Ts.
##
## The input is constant over each sub-step (its value at the sub-step's
## midpoint), so a delay that is a multiple of Ts / @var{nsub} is exact and
## between input switches RK4 has its local error O(h^5).
## @end deftypefn

function X = lab_rig_rk4 (f, x0, u, Ts, nsub, delay)
  if (nargin < 5)
    error ("lab_rig_rk4:badInput",
           "lab_rig_rk4: f, x0, u, Ts, nsub are needed");
  endif
  if (nargin < 6)
    delay = 0;
  endif
  u = u(:);
  N = numel (u);
  x = x0(:);
  X = zeros (N, numel (x));
  X(1,:) = x.';
  h = Ts / nsub;
  for k = 1:N-1
    for j = 1:nsub
      tm = (k - 1) * Ts + (j - 0.5) * h - delay;
      idx = min (max (floor (tm / Ts) + 1, 1), N);
      uk = u(idx);
      k1 = f (x, uk);
      k2 = f (x + 0.5 * h * k1, uk);
      k3 = f (x + 0.5 * h * k2, uk);
      k4 = f (x + h * k3, uk);
      x = x + (h / 6) * (k1 + 2 * k2 + 2 * k3 + k4);
    endfor
    X(k+1,:) = x.';
  endfor
endfunction
