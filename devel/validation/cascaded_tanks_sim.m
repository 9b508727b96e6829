## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn  {} {[@var{y}, @var{X}, @var{info}] =} cascaded_tanks_sim (@var{u}, @var{Ts}, @var{p})
## @deftypefnx {} {@var{p} =} cascaded_tanks_sim ("params")
## @deftypefnx {} {[@var{de}, @var{dv}, @var{truth}] =} cascaded_tanks_sim ("records", @var{draw})
## @deftypefnx {} {[@var{de}, @var{dv}, @var{truth}] =} cascaded_tanks_sim ("records", @var{draw}, @var{variant})
## @deftypefnx {} {@var{u} =} cascaded_tanks_sim ("multisine", @var{N}, @var{Ts}, @var{p})
## A simulator of the Cascaded Tanks benchmark (Schoukens, Mattsson,
## Wigren, Noel; nonlinearbenchmark.org): two tanks in cascade, the
## pump voltage u (V) fills the upper tank, which drains through a small
## opening into the lower one, which drains into the reservoir; the
## levels are in volts of the level sensors (as the benchmark's model
## writes them):
## @example
## x1' = -k1 sqrt(x1) + k4 u                       (0 <= x1 <= x1max)
## x2' =  k2 sqrt(x1) - k3 sqrt(x2) + k2/k1 frac s (0 <= x2 <= x2max)
## y   =  x2 + e, quantised, within the sensor range
## @end example
## When the upper tank is at its rim and its net inflow s = k4 u - k1
## sqrt(x1max) is positive it overflows: a share @code{frac} of the
## spilled water falls into the lower tank (k2/k1 converts the upper
## level to the lower one), the rest into the reservoir. The lower tank
## overflows at x2max (the water above is lost). A pump does not suck
## (u < 0 acts as 0).
##
## Integration: classical Runge-Kutta with @code{p.substeps} sub-steps per
## sampling interval (default 40, h = 0.1 s at Ts = 4 s), the input held
## over each interval (zero-order hold), the overflow switches evaluated
## in each stage, and the levels projected onto [0, max] after each
## sub-step; the water moved by a projection is booked as spilled or lost,
## so the water balance closes to rounding (@var{info}).
##
## @var{u}: N-vector (V); @var{Ts}: s; @var{p}: struct with k1, k2, k3,
## k4, frac, x1max, x2max, x0 (initial levels [x1; x2]), and optionally
## substeps, sigma (sensor noise, V, default 0), q (quantisation step, V,
## default 0: none), yrange ([lo hi], default [-Inf Inf]). The noise is
## drawn from randn. @var{y}: N-by-1 measured output, sample k at t =
## (k - 1) Ts; @var{X}: N-by-2 levels at the samples (noise-free);
## @var{info}: struct with spilled1 (upper-tank level units that
## overflowed, cumulative at each sample, N-by-1), lost2 (lower-tank
## level units lost over the rim, cumulative), top1 and top2 (logical
## N-by-1: the tank at its rim at the sample), y0 (the noise-free output).
##
## @code{cascaded_tanks_sim ("params")}: the simulator's parameters (which
## are documented and which chosen: see the README section on the
## Cascaded Tanks benchmark).
## @code{cascaded_tanks_sim ("records", draw)}: an estimation and a
## validation record (@code{iddata}, 1024 samples, Ts = 4 s) made with two
## realisations (random phases) of the same multisine, both from the same
## initial state @code{p.x0}, with sensor noise; the random draw
## @var{draw} (an integer) selects the phases and the noise. @var{truth}:
## struct with p, the noise-free outputs ye0, yv0 and the states Xe, Xv,
## and the overflow masks. @var{variant}: "nominal" (default) or
## "strong": the same tanks driven harder (multisine 5 V +- 2.2 V rms,
## clipped to the pump's 0-10 V): the upper level spans 1.6-10 V and
## both tanks overflow on 1-4 % of the samples (on the nominal records a
## well-fitted linear model is far below the published 0.76 V; the strong
## excitation was chosen on the records' statistics alone).
## @code{cascaded_tanks_sim ("multisine", N, Ts, p)}: one random-phase
## multisine of period N Ts with all lines from 1/(N Ts) to p.fmax,
## scaled to the rms p.urms around p.umean and clipped to [0, p.umax]
## (draws from rand).
## @end deftypefn

function [a, b, c] = cascaded_tanks_sim (u, Ts, p, p4)
  if (ischar (u))
    switch (u)
      case "params"
        a = tank_params ();
      case "records"
        if (nargin < 2)
          Ts = 0;
        endif
        if (nargin < 3)
          p = "nominal";
        endif
        [a, b, c] = tank_records (Ts, p);
      case "multisine"
        if (nargin < 4)
          error ("cascaded_tanks_sim:badInput",
                 "cascaded_tanks_sim: multisine needs N, Ts, p");
        endif
        a = multisine (Ts, p, p4);
      otherwise
        error ("cascaded_tanks_sim:badOption",
               "cascaded_tanks_sim: unknown mode '%s'", u);
    endswitch
    return;
  endif
  if (nargin < 3 || ! isnumeric (u) || ! isvector (u) || ! isscalar (Ts)
      || Ts <= 0 || ! isstruct (p))
    error ("cascaded_tanks_sim:badInput",
           "cascaded_tanks_sim: u (vector), Ts > 0 and p (struct) needed");
  endif
  [a, b, c] = simulate (u(:), Ts, p);
endfunction

## The simulator's parameters. Documented (see the README section): the
## structure of the equations, Ts = 4 s, 1024 samples per record, the
## input a low-frequency random-phase multisine, the overflow of the
## upper tank with part of the water into the lower tank, the lower tank
## limited too, the output in volts. Chosen here (without looking at any
## identification result on these records): every number below.
function p = tank_params ()
  p.k1 = 0.055;      # upper outflow, V^0.5/s: tau1 = 2 sqrt(x1)/k1, 89 s at 6 V
  p.k2 = 0.060;      # inflow to the lower tank (k2/k1: area and sensor ratio)
  p.k3 = 0.058;      # lower outflow: tau2 = 91 s at 6.2 V
  p.k4 = 0.029;      # pump gain, V/s per V: x1 = 6.95 V at rest at u = 5 V
  p.frac = 0.5;      # share of the upper tank's overflow into the lower
  p.x1max = 10;      # upper rim, V (overflows at rest for u > 6.45 V)
  p.x2max = 10;      # lower rim, V
  p.x0 = [5.5; 5.0]; # initial levels, the same for both records, unknown
                     # to the user
  p.substeps = 40;
  p.sigma = 0.02;    # sensor noise, V rms
  p.q = 10 / 4096;   # 12-bit converter over 0-10 V
  p.yrange = [0 10];
  p.Ts = 4;
  p.N = 1024;
  p.fmax = 0.0191;   # multisine band, Hz (lines 1/(N Ts) .. fmax)
  p.umean = 5;       # V
  p.urms = 1.5;      # V, the multisine's AC part
  p.umax = 10;       # pump voltage range 0..10 V
endfunction

function [de, dv, truth] = tank_records (draw, variant)
  p = tank_params ();
  switch (variant)
    case "nominal"
    case "strong"
      p.urms = 2.2;
    otherwise
      error ("cascaded_tanks_sim:badOption",
             "cascaded_tanks_sim: unknown variant '%s'", variant);
  endswitch
  ## One stream per draw: phases of the two multisines, then the noise.
  rand ("state", 1000 + draw);
  randn ("state", 2000 + draw);
  ue = multisine (p.N, p.Ts, p);
  uv = multisine (p.N, p.Ts, p);
  [ye, Xe, ie] = simulate (ue, p.Ts, p);
  [yv, Xv, iv] = simulate (uv, p.Ts, p);
  de = iddata (ye, ue, p.Ts, "InterSample", "zoh");
  dv = iddata (yv, uv, p.Ts, "InterSample", "zoh");
  truth.p = p;
  truth.draw = draw;
  truth.variant = variant;
  truth.ye0 = ie.y0;
  truth.yv0 = iv.y0;
  truth.Xe = Xe;
  truth.Xv = Xv;
  truth.top1e = ie.top1; truth.top2e = ie.top2;
  truth.top1v = iv.top1; truth.top2v = iv.top2;
endfunction

## Random-phase multisine, all lines k/(N Ts), k = 1 .. fmax N Ts, equal
## amplitudes, scaled to p.urms around p.umean, clipped to [0, p.umax].
function u = multisine (N, Ts, p)
  if (! isstruct (p))
    error ("cascaded_tanks_sim:badInput",
           "cascaded_tanks_sim: multisine needs N, Ts, p");
  endif
  K = floor (p.fmax * N * Ts);
  t = (0:N-1).' * Ts;
  ph = 2 * pi * rand (1, K);
  f = (1:K) / (N * Ts);
  s = sum (cos (2 * pi * t * f + ph), 2);
  u = p.umean + p.urms * s / sqrt (mean (s .^ 2));
  u = min (max (u, 0), p.umax);
endfunction

function [y, X, info] = simulate (u, Ts, p)
  S = 40;
  if (isfield (p, "substeps"))
    S = p.substeps;
  endif
  sigma = 0; q = 0; yr = [-Inf Inf];
  if (isfield (p, "sigma")) sigma = p.sigma; endif
  if (isfield (p, "q")) q = p.q; endif
  if (isfield (p, "yrange")) yr = p.yrange; endif
  h = Ts / S;
  k1 = p.k1; k2 = p.k2; k3 = p.k3; k4 = p.k4;
  g = k2 / k1 * p.frac;                 # lower level per upper level spilled
  t1 = p.x1max; t2 = p.x2max;
  a = p.x0(1); b = p.x0(2);
  N = numel (u);
  X = zeros (N, 2);
  sp = zeros (N, 1); lo = zeros (N, 1);
  top1 = false (N, 1); top2 = false (N, 1);
  S1 = 0; L2 = 0;                       # cumulative spilled, lost
  for i = 1:N
    X(i,:) = [a, b];
    sp(i) = S1; lo(i) = L2;
    top1(i) = a >= t1; top2(i) = b >= t2;
    qin = k4 * max (u(i), 0);
    for s = 1:S
      ## Stages: [dx1, dx2, spill rate, loss rate] at (a, b).
      [da1, db1, ds1, dl1] = rhs (a, b, qin, k1, k2, k3, g, t1, t2);
      [da2, db2, ds2, dl2] = rhs (a + h/2*da1, b + h/2*db1, qin, k1, k2, ...
                                  k3, g, t1, t2);
      [da3, db3, ds3, dl3] = rhs (a + h/2*da2, b + h/2*db2, qin, k1, k2, ...
                                  k3, g, t1, t2);
      [da4, db4, ds4, dl4] = rhs (a + h*da3, b + h*db3, qin, k1, k2, k3, ...
                                  g, t1, t2);
      a += h / 6 * (da1 + 2 * da2 + 2 * da3 + da4);
      b += h / 6 * (db1 + 2 * db2 + 2 * db3 + db4);
      S1 += h / 6 * (ds1 + 2 * ds2 + 2 * ds3 + ds4);
      L2 += h / 6 * (dl1 + 2 * dl2 + 2 * dl3 + dl4);
      ## Projections: water above a rim overflows (booked), a level below
      ## zero (an RK4 overshoot of an emptying tank) is set to zero.
      if (a > t1)
        S1 += a - t1;
        b += g * (a - t1);
        a = t1;
      elseif (a < 0)
        a = 0;
      endif
      if (b > t2)
        L2 += b - t2;
        b = t2;
      elseif (b < 0)
        b = 0;
      endif
    endfor
  endfor
  info.y0 = X(:,2);
  info.spilled1 = sp;
  info.lost2 = lo;
  info.top1 = top1;
  info.top2 = top2;
  y = X(:,2);
  if (sigma > 0)
    y = y + sigma * randn (N, 1);
  endif
  if (q > 0)
    y = q * round (y / q);
  endif
  y = min (max (y, yr(1)), yr(2));
endfunction

## Right-hand side with the overflow switches: at its rim a tank whose
## net inflow is positive stays there and the excess overflows.
function [da, db, ds, dl] = rhs (a, b, qin, k1, k2, k3, g, t1, t2)
  o1 = k1 * sqrt (max (a, 0));
  da = qin - o1;
  ds = 0;
  if (a >= t1 && da > 0)
    ds = da;
    da = 0;
  endif
  db = k2 / k1 * o1 + g * ds - k3 * sqrt (max (b, 0));
  dl = 0;
  if (b >= t2 && db > 0)
    dl = db;
    db = 0;
  endif
endfunction
