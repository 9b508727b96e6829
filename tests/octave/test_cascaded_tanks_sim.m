## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn {} {} test_cascaded_tanks_sim ()
## The Cascaded Tanks simulator (@code{devel/validation/cascaded_tanks_sim.m})
## against independent computations. It checks only the simulator, never
## residtrace's verdicts (those are reported by
## @code{demos/residtrace_cascaded_tanks.m}).
##
## @itemize
## @item small steps around a rest point against @code{lsim} of the
## control package's ZOH discretisation of the linearisation, with an
## error that doubles with the step (the quadratic term);
## @item the rest state under a constant pump voltage against the
## closed-form root (x1 = (k4 u / k1)^2, x2 = (k2 / k3)^2 x1), and with
## the upper tank overflowing (x1 = x1max, x2 from the balance with the
## share frac of the spill);
## @item the water balance: without the lower outflow (k3 = 0) the
## volume k2/k1 x1 + x2 grows by k2/k1 k4 Ts sum(u) to rounding, and with
## both tanks overflowing by that less what was booked as spilled and
## lost; the booked rates at rest against the closed form;
## @item a pump does not suck (u < 0 acts as 0); sub-step convergence
## across overflow switches;
## @item the records: lengths, Ts, input range and reproducibility, the
## multisine's lines, the sensor's quantisation, range and noise level.
## @end itemize
## @end deftypefn

function test_cascaded_tanks_sim ()
  root = ctid_test_root ();
  addpath (fullfile (root, "octave"));
  addpath (fullfile (root, "demos"));
  addpath (fullfile (root, "devel", "validation"));
  pkg load control;
  rand ("state", 11);
  randn ("state", 11);
  check_linearisation ();
  check_rest_states ();
  check_water_balance ();
  check_pump_and_substeps ();
  check_records ();
  check_errors ();
endfunction

function check_errors ()
  ids = {};
  calls = {@() cascaded_tanks_sim ("records", 1, "bogus"), ...
           @() cascaded_tanks_sim ("bogus"), ...
           @() cascaded_tanks_sim ([1 2 3], -4, struct ()), ...
           @() cascaded_tanks_sim ("multisine", 16, 4)};
  want = {"cascaded_tanks_sim:badOption", "cascaded_tanks_sim:badOption", ...
          "cascaded_tanks_sim:badInput", "cascaded_tanks_sim:badInput"};
  for k = 1:numel (calls)
    try
      calls{k} ();
      error ("test_cascaded_tanks_sim: call %d did not fail", k);
    catch err
      assert (err.identifier, want{k});
    end_try_catch
  endfor
endfunction

function p = clean_params ()
  p = cascaded_tanks_sim ("params");
  p.sigma = 0; p.q = 0; p.yrange = [-Inf Inf];
endfunction

## Small steps around the rest point of u0 = 4 V against lsim of the ZOH
## discretisation (matrix exponential) of the linearisation
## A = [-k1/(2 sqrt x1) 0; k2/(2 sqrt x1) -k3/(2 sqrt x2)], B = [k4; 0].
function check_linearisation ()
  p = clean_params ();
  u0 = 4;
  x1 = (p.k4 * u0 / p.k1) ^ 2;
  x2 = (p.k2 / p.k3) ^ 2 * x1;
  p.x0 = [x1; x2];
  A = [-p.k1 / (2 * sqrt (x1)), 0; p.k2 / (2 * sqrt (x1)), ...
       -p.k3 / (2 * sqrt (x2))];
  sys = ss (A, [p.k4; 0], [0 1], 0);
  N = 300;
  v = sign (randn (N, 1));
  v = kron (v(1:N/10), ones (10, 1));       # steps held over 40 s
  yl = lsim (c2d (sys, p.Ts, "zoh"), v, [], [0; 0]);
  err = zeros (1, 2);
  for k = 1:2
    d = 0.01 * k;
    y = cascaded_tanks_sim (u0 + d * v, p.Ts, p);
    err(k) = max (abs ((y - x2) / d - yl)) / max (abs (yl));
  endfor
  printf ("linearisation: relative error %.3g (step 0.01 V), %.3g (0.02 V)\n",
          err);
  assert (err(1) < 5e-3);
  ## The error is the quadratic term: it doubles with the step.
  assert (err(2) / err(1) > 1.8 && err(2) / err(1) < 2.2);
endfunction

function check_rest_states ()
  p = clean_params ();
  p.substeps = 4;       # a rest state is a fixed point of RK4 at any step
  ## Below the rim: x1 = (k4 u / k1)^2, x2 = (k2 / k3)^2 x1.
  u0 = 3.5;
  p.x0 = [1; 8];
  y = []; X = [];
  [y, X] = cascaded_tanks_sim (u0 * ones (600, 1), p.Ts, p);
  x1 = (p.k4 * u0 / p.k1) ^ 2;
  x2 = (p.k2 / p.k3) ^ 2 * x1;
  e = abs (X(end,:) - [x1, x2]) ./ [x1, x2];
  printf ("rest state at %.1f V: relative errors %.2g %.2g\n", u0, e);
  assert (e < 1e-8);
  ## Upper tank at its rim: the spill s = k4 u - k1 sqrt(x1max) sends
  ## k2/k1 frac s into the lower tank (rim raised so it does not spill).
  u0 = 7;
  p.x2max = 50;
  p.x0 = [2; 2];
  [y, X, info] = cascaded_tanks_sim (u0 * ones (600, 1), p.Ts, p);
  s = p.k4 * u0 - p.k1 * sqrt (p.x1max);
  x2 = ((p.k2 * sqrt (p.x1max) + p.k2 / p.k1 * p.frac * s) / p.k3) ^ 2;
  assert (s > 0);
  assert (X(end,1), p.x1max, 1e-12);
  assert (abs (X(end,2) - x2) / x2 < 1e-8);
  assert (info.top1(end) && ! info.top2(end));
  rate = diff (info.spilled1(end-1:end)) / p.Ts;
  assert (abs (rate - s) / s < 1e-8);
  printf ("overflowing upper tank: x2 %.6f (closed form %.6f), spill %.3g/s\n",
          X(end,2), x2, rate);
  ## Both at their rims: the lower tank loses what exceeds its outflow.
  p.x2max = 10;
  [y, X, info] = cascaded_tanks_sim (u0 * ones (600, 1), p.Ts, p);
  assert (X(end,:), [p.x1max, p.x2max], 1e-12);
  loss = p.k2 * sqrt (p.x1max) + p.k2 / p.k1 * p.frac * s ...
         - p.k3 * sqrt (p.x2max);
  rate = diff (info.lost2(end-1:end)) / p.Ts;
  assert (loss > 0);
  assert (abs (rate - loss) / loss < 1e-8);
  assert (y(end), p.x2max);
endfunction

## Water balance: V = k2/k1 x1 + x2 (the upper tank's water in lower-tank
## level units plus the lower tank's).
function check_water_balance ()
  p = clean_params ();
  p.substeps = 10;      # the balance holds at any step
  a = p.k2 / p.k1;
  ## No lower outflow, no rim reached: dV/dt = a k4 u exactly (RK4 keeps
  ## linear invariants).
  p.k3 = 0;
  p.x2max = 1e3;
  p.x0 = [1; 1];
  u = 3 * rand (150, 1);
  [y, X, info] = cascaded_tanks_sim (u, p.Ts, p);
  V = a * X(:,1) + X(:,2);
  Vin = a * p.k4 * p.Ts * [0; cumsum(u(1:end-1))];
  assert (max (X(:,1)) < p.x1max);
  e = max (abs (V - V(1) - Vin)) / max (abs (Vin));
  printf ("water balance without outflow: relative error %.2g\n", e);
  assert (e < 1e-12);
  ## Both tanks overflowing (high pump voltage): the water that left over
  ## the rims is what was booked.
  p.x2max = 10;
  u = 6 + 4 * rand (400, 1);
  [y, X, info] = cascaded_tanks_sim (u, p.Ts, p);
  assert (any (info.top1) && any (info.top2));
  V = a * X(:,1) + X(:,2);
  Vin = a * p.k4 * p.Ts * [0; cumsum(u(1:end-1))];
  out = a * (1 - p.frac) * info.spilled1 + info.lost2;
  e = max (abs (V - V(1) - Vin + out)) / max (abs (Vin));
  printf ("water balance with both overflows: relative error %.2g\n", e);
  assert (e < 1e-12);
endfunction

function check_pump_and_substeps ()
  p = clean_params ();
  p.x0 = [8; 6];
  [y0, X0] = cascaded_tanks_sim (zeros (60, 1), p.Ts, p);
  y1 = cascaded_tanks_sim (-3 * ones (60, 1), p.Ts, p);
  assert (y1, y0);
  ## Without inflow the upper tank empties in finite time (Torricelli):
  ## sqrt(x1(t)) = sqrt(x1(0)) - k1 t / 2.
  t = (0:59).' * p.Ts;
  x1 = max (sqrt (p.x0(1)) - p.k1 * t / 2, 0) .^ 2;
  full = x1 > 0.5;
  e = max (abs (X0(full,1) - x1(full)) ./ x1(full));
  printf ("draining upper tank: relative error %.2g, empty after %.0f s\n",
          e, 2 * sqrt (p.x0(1)) / p.k1);
  assert (e < 1e-9);
  assert (all (X0(x1 == 0 & [false; x1(1:end-1) == 0],1) < 1e-6));
  assert (y0(end) < 0.5 * y0(1));         # and then the lower one
  ## Sub-step convergence across the overflow switches: 40 sub-steps
  ## against 160 (the switches are resolved to the sub-step).
  rec = cascaded_tanks_sim ("params");
  rand ("state", 5);
  u = cascaded_tanks_sim ("multisine", 160, p.Ts, rec);
  u = u + 2;                                 # overflows often
  p.x0 = [6; 6];
  [ya, ~, ia] = cascaded_tanks_sim (u, p.Ts, p);
  q = p; q.substeps = 160;
  yb = cascaded_tanks_sim (u, p.Ts, q);
  d = max (abs (ya - yb));
  printf ("40 vs 160 sub-steps with %d overflow samples: max diff %.2g V\n",
          sum (ia.top1 | ia.top2), d);
  assert (any (ia.top1));
  assert (d < 2e-3);
endfunction

function check_records ()
  p = cascaded_tanks_sim ("params");
  [de, dv, truth] = cascaded_tanks_sim ("records", 3);
  ue = get (de, "u"); ye = get (de, "y");
  uv = get (dv, "u"); yv = get (dv, "y");
  assert (numel (ue), 1024); assert (numel (yv), 1024);
  assert (get (de, "Ts"), 4); assert (get (dv, "Ts"), 4);
  assert (all (ue >= 0 & ue <= 10) && all (uv >= 0 & uv <= 10));
  assert (max (abs (ue - uv)) > 1);          # two realisations
  ## Reproducible: the record's inputs are the multisines of the draw's
  ## random state, and its noise-free output is the simulator's.
  rand ("state", 1003);
  u1 = cascaded_tanks_sim ("multisine", p.N, p.Ts, p);
  u2 = cascaded_tanks_sim ("multisine", p.N, p.Ts, p);
  assert (ue, u1); assert (uv, u2);
  ## The multisine's lines: 1/(N Ts) .. fmax only (apart from clipping).
  rand ("state", 99);
  q = p; q.umax = Inf; q.umean = 100;       # no clipping
  w = cascaded_tanks_sim ("multisine", p.N, p.Ts, q) - 100;
  W = abs (fft (w));
  K = floor (p.fmax * p.N * p.Ts);
  assert (max (W([1, K+2:p.N/2])) < 1e-9 * max (W));
  assert (min (W(2:K+1)) > 0.99 * max (W(2:K+1)));
  assert (sqrt (mean (w .^ 2)), p.urms, 1e-12);
  ## The sensor: quantised to q, within 0..10 V, noise of sigma rms.
  assert (max (abs (ye / p.q - round (ye / p.q))) < 1e-6);
  assert (all (ye >= 0 & ye <= 10));
  e = [ye - truth.ye0; yv - truth.yv0];
  ok = [ye; yv] > 0.01 & [ye; yv] < 9.99;
  r = sqrt (mean (e(ok) .^ 2));
  printf ("records: noise %.4f V rms (sigma %.3f, q %.2g)\n", r, p.sigma, p.q);
  assert (abs (r - sqrt (p.sigma ^ 2 + p.q ^ 2 / 12)) < 0.1 * p.sigma);
  assert (truth.Xe(1,:), p.x0.');
  assert (truth.Xv(1,:), p.x0.');          # the same initial state
endfunction
