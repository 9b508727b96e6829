## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn {} {} test_lab_rigs ()
## The simulators of the simulated lab rigs (@code{devel/validation/lab_rigs.m},
## @code{devel/validation/lab_rig_rk4.m}) against identities and
## independent computations.  It checks only the simulators, never
## residtrace's verdicts (those are reported by
## @code{demos/residtrace_lab_rigs.m}).
##
## @itemize
## @item linear rigs (thermal3, beam_mode): RK4 with sub-steps against the
## control package's @code{lsim} (zero-order hold, matrix exponential);
## mixing_delay (delay of 12.4 samples) against @code{lsim} on a grid of
## Ts/5 with the input shifted by 62 fine samples;
## @item heated_block: the steady state against the root of the loss
## balance; small steps around 100 degC against @code{lsim} of the
## linearisation, with an error that falls as the square of the step;
## @item conveyor (exact piecewise solution): without friction, and with
## friction while the belt never stops, against @code{lsim}; the stop
## instant and sticking against the closed form;
## @item fan_driver: commands below 7.5 V against @code{lsim}, above it
## the response to 7.5 V; adc_clip: the unclipped tacho voltage against
## @code{lsim}, the ADC's clipping and quantisation;
## @item pendulum: energy conserved without damping and input; small
## swings against @code{lsim} of the linearisation;
## @item the records: reproducible, of the stated lengths, raw levels.
## @end itemize
## @end deftypefn

function test_lab_rigs ()
  root = ctid_test_root ();
  addpath (fullfile (root, "octave"));
  addpath (fullfile (root, "demos"));
  addpath (fullfile (root, "devel", "validation"));
  pkg load control;
  rand ("state", 7);
  randn ("state", 7);
  check_thermal3 ();
  check_beam_mode ();
  check_mixing_delay ();
  check_heated_block ();
  check_conveyor ();
  check_fan_driver ();
  check_adc_clip ();
  check_pendulum ();
  check_records ();
endfunction

## The control package's simulation of sys with the input held over each
## interval Ts: lsim of c2d (sys, Ts, "zoh") (the matrix exponential).
## (lsim of a continuous model interpolates the input linearly between
## samples, which is not how these rigs are driven.)
function y = zoh_lsim (sys, u, Ts, x0)
  if (nargin < 4)
    x0 = zeros (rows (sys.a), 1);
  endif
  y = lsim (c2d (sys, Ts, "zoh"), u, [], x0);
endfunction

## Relative error of a against b, scaled by b's largest magnitude.
function e = relerr (a, b)
  e = max (abs (a(:) - b(:))) / max (abs (b(:)));
endfunction

function check (name, e, tol)
  printf ("%-48s %.3g (tolerance %.3g)\n", name, e, tol);
  if (! (e <= tol))
    error ("test_lab_rigs: %s: %.3g above %.3g", name, e, tol);
  endif
endfunction

## A random staircase for the checks: levels on [lo, hi], holds of 5 to 40
## samples.
function u = steps (N, lo, hi)
  u = zeros (N, 1);
  k = 1;
  while (k <= N)
    n = 5 + floor (36 * rand ());
    u(k:min(N, k+n-1)) = lo + (hi - lo) * rand ();
    k += n;
  endwhile
endfunction

## RK4's global error is O((h |lambda|)^4): h |lambda| <= 0.03 on these
## rigs, so 1e-6 of the signal's range is ample and far below any
## modelling error a wrong sign or coefficient would cause.
function check_thermal3 ()
  rig = lab_rigs ("thermal3", 0);
  p = rig.p;
  N = 1500;
  u = steps (N, 0, 40);
  x0 = rig.x_rest (p, 0);
  X = rig.sim (p, u, x0);
  y = rig.out (p, X) - p.Ta;
  A = [-(p.G12 + p.Ga(1)), p.G12, 0;
       p.G12, -(p.G12 + p.G23 + p.Ga(2)), p.G23;
       0, p.G23, -(p.G23 + p.Ga(3))] ./ p.C(:);
  B = [1 / p.C(1); 0; 0];
  yl = zoh_lsim (ss (A, B, [0 0 1], 0), u, rig.Ts);
  check ("thermal3: RK4 vs lsim", relerr (y, yl), 1e-6);
  ## At rest under 40 W the balance holds: f(x_rest, 40) = 0.
  f = rig.f (p);
  xr = rig.x_rest (p, 40);
  check ("thermal3: rest state is an equilibrium",
         norm (f (xr, 40)) * max (p.C) / 40, 1e-12);
endfunction

function check_beam_mode ()
  rig = lab_rigs ("beam_mode", 0);
  p = rig.p;
  N = 2000;
  u = steps (N, -0.3, 0.3);
  X = rig.sim (p, u, [0; 0]);
  y = rig.out (p, X) - p.zero;
  w = 2 * pi * p.fn;
  sys = ss ([0 1; -w^2, -2 * p.zeta * w], [0; p.ka / p.m], [1000 0], 0);
  yl = zoh_lsim (sys, u, rig.Ts);
  check ("beam_mode: RK4 vs lsim", relerr (y, yl), 1e-6);
endfunction

## The delay (12.4 s = 62 sub-steps of 0.2 s) through lsim on the fine
## grid: an independent path for the delayed input.
function check_mixing_delay ()
  rig = lab_rigs ("mixing_delay", 0);
  p = rig.p;
  N = 600;
  u = steps (N, 2, 8);
  X = rig.sim (p, u, rig.x_rest (p, u(1)));
  y = rig.out (p, X) - p.base;
  nsub = rig.nsub;
  h = rig.Ts / nsub;
  nd = round (p.delay / h);
  assert (abs (nd * h - p.delay) < 1e-12);
  uf = kron (u, ones (nsub, 1));
  uf = [u(1) * ones(nd, 1); uf(1:end-nd)];
  yf = zoh_lsim (ss (-1 / p.tau, p.K / p.tau, 1, 0), uf, h, p.K * u(1));
  yl = yf(1:nsub:end);
  check ("mixing_delay: RK4 with delay vs lsim (Ts/5)", relerr (y, yl), 1e-6);
  ## The delay is seen: the same run without it differs by much more.
  q = p;
  q.delay = 0;
  y0 = rig.out (q, rig.sim (q, u, rig.x_rest (q, u(1)))) - p.base;
  if (relerr (y0, yl) < 0.05)
    error ("test_lab_rigs: mixing_delay: the delay has no effect");
  endif
endfunction

function check_heated_block ()
  rig = lab_rigs ("heated_block", 0);
  p = rig.p;
  f = rig.f (p);
  ## Steady state under 60 W from ambient, 24 000 s (more than 50 time
  ## constants at that temperature), against the root of the balance.
  N = 4800;
  X = rig.sim (p, 60 * ones (N, 1), rig.x_rest (p, 0));
  Tss = rig.x_rest (p, 60)(1);
  loss = p.hA * (Tss - p.Ta) + p.ka * ((Tss + p.T0K)^4 - (p.Ta + p.T0K)^4);
  check ("heated_block: rest state balances 60 W", abs (loss - 60) / 60,
         1e-12);
  check ("heated_block: 24000 s of 60 W reach the rest state",
         abs (X(end,2) - Tss) / (Tss - p.Ta), 1e-9);
  ## Linearisation at the rest state under P0 = 40 W: dT' = -g/C dT + dP/C,
  ## g = hA + 4 ka (T + 273.15)^3; the error of the linear model is
  ## quadratic in the step size, so relative to the response it doubles
  ## when the steps double.
  P0 = 40;
  x0 = rig.x_rest (p, P0);
  g = p.hA + 4 * p.ka * (x0(1) + p.T0K)^3;
  sys = ss ([-g / p.C, 0; 1 / p.tau_s, -1 / p.tau_s], [1 / p.C; 0], [0 1], 0);
  N = 600;
  du = steps (N, -1, 1);
  yl = zoh_lsim (sys, du, rig.Ts);
  for a = [2 1]
    X = rig.sim (p, P0 + a * du, x0);
    e(a) = relerr (X(:,2) - x0(2), a * yl);
  endfor
  printf ("heated_block: linearisation error %.3g (1 W), %.3g (2 W)\n",
          e(1), e(2));
  check ("heated_block: small steps vs lsim of the linearisation", e(1),
         1e-2);
  check ("heated_block: relative error doubles with the step",
         abs (e(2) / e(1) - 2), 0.1);
endfunction

function check_conveyor ()
  rig = lab_rigs ("conveyor", 0);
  p = rig.p;
  Ts = rig.Ts;
  N = 3000;
  t = (0:N-1).' * Ts;
  G = ss (-1 / p.tau, p.K / p.tau, 1, 0);
  ## No friction: a linear first-order plant.
  q = p;
  q.Vc = 0;
  u = steps (N, -10, 10);
  v = rig.sim (q, u, 0);
  check ("conveyor: Vc = 0 vs lsim", relerr (v, zoh_lsim (G, u, Ts)), 1e-10);
  ## Friction, belt always moving forward (u > Vc, v0 > 0): the input
  ## reduced by Vc.
  u = steps (N, 3, 10);
  v0 = p.K * (u(1) - p.Vc);
  v = rig.sim (p, u, v0);
  check ("conveyor: moving belt vs lsim of u - Vc",
         relerr (v, zoh_lsim (G, u - p.Vc, Ts, v0)), 1e-10);
  ## RK4 of the state equation on the same moving belt.
  X = lab_rig_rk4 (rig.f (p), v0, u, Ts, rig.nsub);
  check ("conveyor: exact vs RK4 (no stop)", relerr (X, v), 1e-8);
  ## A stop: from v0 with u = 0 the belt slows toward -K Vc, stops at
  ## tc = tau log (1 + v0 / (K Vc)) and stays stuck.
  v0 = 0.3;
  v = rig.sim (p, zeros (N, 1), v0);
  tc = p.tau * log (1 + v0 / (p.K * p.Vc));
  before = t < tc;
  vex = (v0 + p.K * p.Vc) * exp (-t(before) / p.tau) - p.K * p.Vc;
  check ("conveyor: deceleration before the stop", relerr (v(before), vex),
         1e-12);
  check ("conveyor: stuck after the stop", max (abs (v(! before))), 0);
  ## Under |u| <= Vc a belt at rest does not move; steady speed K (u - Vc).
  v = rig.sim (p, p.Vc * ones (N, 1), 0);
  check ("conveyor: |u| = Vc from rest stays at rest", max (abs (v)), 0);
  v = rig.sim (p, -6 * ones (N, 1), 0);
  check ("conveyor: steady speed K (u + Vc) at u = -6",
         abs (v(end) - p.K * (-6 + p.Vc)) / (p.K * 6), 1e-12);
endfunction

function check_fan_driver ()
  rig = lab_rigs ("fan_driver", 0);
  p = rig.p;
  N = 2000;
  sys = ss ([-1 / p.tau_f, 0; 1 / p.tau_a, -1 / p.tau_a], ...
            [p.Kf / p.tau_f; 0], [0 1], 0);
  u = steps (N, 1, 7.4);
  x0 = rig.x_rest (p, 2);
  y = rig.out (p, rig.sim (p, u, x0));
  yl = zoh_lsim (sys, u, rig.Ts, x0);
  check ("fan_driver: below saturation vs lsim", relerr (y, yl), 1e-6);
  u = steps (N, 7.5, 10);
  x0 = rig.x_rest (p, 7.5);
  y = rig.out (p, rig.sim (p, u, x0));
  check ("fan_driver: above 7.5 V the output stays at rest",
         relerr (y, x0(2) * ones (N, 1)), 1e-12);
endfunction

function check_adc_clip ()
  rig = lab_rigs ("adc_clip", 0);
  p = rig.p;
  N = 2000;
  sys = ss ([-1 / p.tau_m, 0; p.kg / p.tau_t, -1 / p.tau_t], ...
            [p.Kw / p.tau_m; 0], [0 1], 0);
  u = steps (N, -8, 8);
  y = rig.out (p, rig.sim (p, u, [0; 0]));
  check ("adc_clip: tacho voltage vs lsim",
         relerr (y, zoh_lsim (sys, u, rig.Ts)),
         1e-6);
  ## The ADC: clipped at +-Vmax, on the 2 Vmax / 2^bits grid.
  q = p;
  q.noise = 0;
  v = linspace (-14, 14, 5001).';
  m = rig.meas (q, v);
  lsb = 2 * p.Vmax / 2^p.bits;
  check ("adc_clip: ADC clips at +-10 V", max (abs (m)) - p.Vmax, 0);
  check ("adc_clip: ADC on its grid", max (abs (m / lsb - round (m / lsb))),
         1e-9);
  inside = abs (v) < p.Vmax - lsb;
  check ("adc_clip: ADC error inside the range (LSB)",
         max (abs (m(inside) - v(inside))) / lsb, 0.5 + 1e-9);
endfunction

function check_pendulum ()
  rig = lab_rigs ("pendulum", 0);
  p = rig.p;
  ## Energy without damping and input, from 60 degrees, 10 s.
  q = p;
  q.b = 0;
  N = 1000;
  X = rig.sim (q, zeros (N, 1), [pi / 3; 0]);
  E = 0.5 * p.J * X(:,2).^2 + p.m * p.g * p.l * (1 - cos (X(:,1)));
  check ("pendulum: energy conserved (undamped, 10 s)",
         max (abs (E - E(1))) / E(1), 1e-8);
  ## The angle swings through the bottom (the check is not vacuous).
  if (min (X(:,1)) > -pi / 4)
    error ("test_lab_rigs: pendulum: the undamped swing is too small");
  endif
  ## Small swings (0.01 rad): the linearisation J s^2 + b s + m g l; the
  ## neglected theta^3 / 6 is 2e-5 of theta.
  w2 = p.m * p.g * p.l / p.J;
  sys = ss ([0 1; -w2, -p.b / p.J], [0; p.kt / p.J], [1 0], 0);
  u = 0.02 * steps (N, -1, 1);
  X = rig.sim (p, u, [0; 0]);
  yl = zoh_lsim (sys, u, rig.Ts);
  check ("pendulum: small swings vs lsim of the linearisation",
         relerr (X(:,1), yl), 1e-4);
  if (max (abs (yl)) > 0.02)
    error ("test_lab_rigs: pendulum: the small swing is not small");
  endif
endfunction

function check_records ()
  a = lab_rigs ("conveyor", 0.1);
  b = lab_rigs ("conveyor", 0.1);
  check ("records: reproducible", max (abs (a.de.y - b.de.y)), 0);
  if (numel (a.de.y) != 600 || numel (a.dv.y) != 400)
    error ("test_lab_rigs: records: lengths %d, %d", numel (a.de.y),
           numel (a.dv.y));
  endif
  c = lab_rigs ("conveyor", 0.1, 1);
  if (isequal (c.de.u, a.de.u))
    error ("test_lab_rigs: records: draw 1 repeats draw 0");
  endif
  if (isequal (a.de.u(1:400), a.dv.u))
    error ("test_lab_rigs: records: validation input = estimation input");
  endif
  ## Noise of the stated size on the noise-free output (quantisation
  ## adds q^2 / 12).
  s = std (a.de.y - a.ye0);
  want = sqrt (a.p.noise^2 + a.p.q^2 / 12);
  check ("records: conveyor noise std (relative)", abs (s / want - 1), 0.15);
  ## Raw levels: the conductivity starts at its rest level.
  c = lab_rigs ("mixing_delay", 0.05);
  check ("records: mixing_delay starts at its rest level",
         abs (c.ye0(1) - (c.p.base + c.p.K * c.u_rest)), 1e-12);
endfunction
