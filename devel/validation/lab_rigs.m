## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn {} {@var{names} =} lab_rigs ()
## @deftypefnx {} {@var{rig} =} lab_rigs (@var{name})
## @deftypefnx {} {@var{rig} =} lab_rigs (@var{name}, @var{scale})
## @deftypefnx {} {@var{rig} =} lab_rigs (@var{name}, @var{scale}, @var{draw})
## Simulated lab rigs on which @code{residtrace} is checked
## (@code{demos/residtrace_lab_rigs.m}): five nonlinear and three
## linear processes, each simulated from its physics (@code{lab_rig_rk4}:
## RK4, zero-order-hold input, sub-steps; the conveyor by its exact
## piecewise-exponential solution), recorded in raw units with sensor
## noise and quantisation, with an estimation and a validation record
## made with a realistic excitation and different random draws.
##
## Without arguments: the rig names.  @var{rig}: a struct with the name,
## a title, @code{kind} ("nonlinear" or "linear"), @code{effect} (the
## documented effect in @code{residtrace}'s vocabulary, "none" for a
## linear rig), @code{physics} (one line), the sampling interval
## @code{Ts}, the parameters @code{p}, handles @code{sim (p, u, x0)} (the
## states at the sampling instants, noise-free), @code{out (p, X)} (the
## noise-free output), @code{meas (p, y)} (the sensor: noise,
## quantisation, range; it draws from randn), @code{x_rest (p, u0)} (the
## state at rest under a constant input u0), @code{f (p)} (the state
## equation x' = f(x, u) where there is one), the structures @code{NN}
## a user would try, and the records @code{de}, @code{dv} (iddata) with
## their noise-free outputs @code{ye0}, @code{yv0}.  @var{scale} (default
## 1) shortens the records; 0 gives the rig without records (for the
## simulator checks of @code{tests/octave/test_lab_rigs.m}).  @var{draw}
## (default 0) selects another random draw of the excitations and the
## noise (another realisation of the same rigs).
##
## Rigs (documented effect):
## @table @code
## @item heated_block
## aluminium block, heater power (W) -> thermocouple (degC); convective
## and radiative loss, eps sigma A ((T+273.15)^4 - (Ta+273.15)^4), so the
## time constant and the gain fall by half from 22 to 250 degC
## (state_nonlinearity).
## @item conveyor
## belt conveyor, motor voltage (V) -> belt speed from the encoder (m/s),
## Coulomb friction of the belt on its bed (1.8 V equivalent) with the
## belt stuck while |u| <= 1.8 V (coulomb).
## @item fan_driver
## air-flow rig, fan command (V) -> air speed from a hot-wire anemometer
## (m/s); the PWM driver's output saturates at 7.5 V of the 0-10 V command
## (static_nonlinearity: the input clipped).
## @item adc_clip
## air-bearing rotary table, current command (V) -> tachogenerator
## voltage (V) through a +-10 V, 12-bit ADC that clips (saturation: the
## output limited).
## @item pendulum
## pendulum driven by a torque motor, current command (V) -> angle from a
## potentiometer (degrees, 180 when hanging); restoring torque m g l
## sin(theta), swings to +-70 degrees (state_nonlinearity).
## @item thermal3
## three-node thermal chain (heater, plate, sensor boss), heater power (W)
## -> plate temperature (degC), linear conduction and convection (linear).
## @item beam_mode
## cantilever beam, voice-coil command (V) -> tip position from a laser
## triangulation sensor (mm, 25 mm at rest), one mode at 4.2 Hz, damping
## ratio 0.015 (linear).
## @item mixing_delay
## salt dosing into a pipe, dosing-pump flow (L/h) -> conductivity
## downstream (mS/cm), first-order mixing (25 s) and a transport delay of
## 12.4 s (12.4 samples) (linear).
## @end table
## @end deftypefn

function rig = lab_rigs (name, scale, draw)
  names = {"heated_block", "conveyor", "fan_driver", "adc_clip", ...
           "pendulum", "thermal3", "beam_mode", "mixing_delay"};
  if (nargin == 0)
    rig = names;
    return;
  endif
  if (nargin < 2 || isempty (scale))
    scale = 1;
  endif
  if (nargin < 3)
    draw = 0;
  endif
  k = find (strcmp (name, names));
  if (isempty (k))
    error ("lab_rigs:badInput", "lab_rigs: unknown rig '%s'", name);
  endif
  rig = feval (["rig_" name]);
  rig.name = name;
  if (! isfield (rig, "sim"))
    Ts = rig.Ts;
    nsub = rig.nsub;
    fh = rig.f;
    rig.sim = @(p, u, x0) lab_rig_rk4 (fh (p), x0, u, Ts, nsub, p.delay);
  endif
  if (scale == 0)
    return;
  endif
  rig.est.N = round (scale * rig.est.N);
  rig.val.N = round (scale * rig.val.N);
  seed = 1000 * k + 10 * draw;
  [rig.de, rig.ye0, rig.ue] = make_record (rig, rig.est, seed + 1);
  [rig.dv, rig.yv0, rig.uv] = make_record (rig, rig.val, seed + 2);
endfunction

## One record: rest at u_rest, then the excitation; the state starts at
## rest; the random draws (excitation, then noise) follow the seed.
function [d, y0, u] = make_record (rig, r, seed)
  sr = rand ("state");
  sn = randn ("state");
  rand ("state", seed);
  randn ("state", seed);
  u = [rig.u_rest * ones(rig.nrest, 1); rig.excite(r.N - rig.nrest)];
  X = rig.sim (rig.p, u, rig.x_rest (rig.p, rig.u_rest));
  y0 = rig.out (rig.p, X);
  y = rig.meas (rig.p, y0);
  rand ("state", sr);
  randn ("state", sn);
  d = iddata (y, u, rig.Ts, "InterSample", "zoh");
endfunction

## ---------------------------------------------------------------- rigs

function rig = rig_heated_block ()
  rig.title = "heated aluminium block";
  rig.kind = "nonlinear";
  rig.effect = "state_nonlinearity";
  rig.physics = ["radiative + convective loss: time constant 980 s at ", ...
                 "22 degC, 450 s at 200 degC"];
  rig.units = {"W", "degC"};
  rig.Ts = 5;
  rig.nsub = 2;
  ## 0.45 kg of aluminium (C = 400 J/K), h A = 0.25 W/K, black anodised
  ## (emissivity 0.9) 0.03 m^2: eps sigma A = 1.53e-9 W/K^4.
  rig.p = struct ("C", 400, "hA", 0.25, "ka", 1.53e-9, "Ta", 22, ...
                  "T0K", 273.15, "tau_s", 15, "delay", 0, ...
                  "noise", 0.15, "q", 0.1);
  rig.f = @(p) @(x, u) [(u - p.hA * (x(1) - p.Ta) ...
                         - p.ka * ((x(1) + p.T0K)^4 - (p.Ta + p.T0K)^4)) / p.C;
                        (x(1) - x(2)) / p.tau_s];
  rig.x_rest = @(p, u0) heated_block_rest (p, u0) * [1; 1];
  rig.out = @(p, X) X(:,2);
  rig.meas = @(p, y) p.q * round ((y + p.noise * randn (size (y))) / p.q);
  rig.u_rest = 0;
  rig.nrest = 120;
  rig.excite = @(N) staircase (N, 5, 0, 120, 1200, 3000);
  rig.est.N = 5760;                  # 8 h
  rig.val.N = 4320;                  # 6 h
  rig.NN = [1 1 0; 1 2 0; 2 2 0];
endfunction

## The block's temperature at rest under the heater power P0: the root of
## the loss balance (monotone in T).
function T = heated_block_rest (p, P0)
  loss = @(T) p.hA * (T - p.Ta) ...
              + p.ka * ((T + p.T0K)^4 - (p.Ta + p.T0K)^4) - P0;
  if (P0 == 0)
    T = p.Ta;
  else
    T = fzero (loss, [p.Ta, p.Ta + 2000], optimset ("TolX", 1e-12));
  endif
endfunction

function rig = rig_conveyor ()
  rig.title = "belt conveyor";
  rig.kind = "nonlinear";
  rig.effect = "coulomb";
  rig.physics = ["Coulomb friction of the belt on its bed, 1.8 V of a ", ...
                 "+-10 V drive; stuck while |u| <= 1.8 V"];
  rig.units = {"V", "m/s"};
  rig.Ts = 0.01;
  rig.nsub = 10;
  rig.p = struct ("K", 0.06, "tau", 0.35, "Vc", 1.8, "delay", 0, ...
                  "noise", 0.004, "q", 0.002);
  ## Without sticking (no zero crossing): for the check against RK4.
  rig.f = @(p) @(x, u) (p.K * (u - p.Vc * sign (x)) - x) / p.tau;
  Ts = rig.Ts;
  rig.sim = @(p, u, x0) conveyor_exact (p, u, Ts, x0);
  rig.x_rest = @(p, u0) p.K * sign (u0) * max (abs (u0) - p.Vc, 0);
  rig.out = @(p, X) X(:,1);
  rig.meas = @(p, y) p.q * round ((y + p.noise * randn (size (y))) / p.q);
  rig.u_rest = 0;
  rig.nrest = 100;
  rig.excite = @(N) staircase (N, 0.01, -10, 10, 0.3, 1.5);
  rig.est.N = 6000;
  rig.val.N = 4000;
  rig.NN = [1 1 0; 1 2 0; 2 2 0];
endfunction

## tau v' = K (u - Vc sign(v)) - v with the belt held at v = 0 while
## |u| <= Vc: between a start and a stop v is an exponential toward
## K (u - Vc s), s the direction of motion; the instant it reaches zero is
## computed exactly, so the solution is exact at every sample.
function V = conveyor_exact (p, u, Ts, v0)
  N = numel (u);
  V = zeros (N, 1);
  v = v0;
  V(1) = v;
  for k = 1:N-1
    left = Ts;
    uk = u(k);
    while (left > 0)
      if (v == 0)
        if (abs (uk) <= p.Vc)
          break;
        endif
        s = sign (uk);
      else
        s = sign (v);
      endif
      vinf = p.K * (uk - p.Vc * s);
      if (s * vinf >= 0)
        v = vinf + (v - vinf) * exp (-left / p.tau);
        left = 0;
      else
        tc = p.tau * log ((v - vinf) / (-vinf));
        if (tc >= left)
          v = vinf + (v - vinf) * exp (-left / p.tau);
          left = 0;
        else
          v = 0;
          left -= tc;
        endif
      endif
    endwhile
    V(k+1) = v;
  endfor
endfunction

function rig = rig_fan_driver ()
  rig.title = "air-flow rig with a saturating fan driver";
  rig.kind = "nonlinear";
  rig.effect = "static_nonlinearity";
  rig.physics = ["PWM driver output saturates at 7.5 V of the 0-10 V ", ...
                 "command (the input clipped)"];
  rig.units = {"V", "m/s"};
  rig.Ts = 0.05;
  rig.nsub = 4;
  rig.p = struct ("Usat", 7.5, "Kf", 0.9, "tau_f", 1.2, "tau_a", 0.15, ...
                  "delay", 0, "noise", 0.03, "q", 0.01);
  rig.f = @(p) @(x, u) [(p.Kf * min (max (u, 0), p.Usat) - x(1)) / p.tau_f;
                        (x(1) - x(2)) / p.tau_a];
  rig.x_rest = @(p, u0) p.Kf * min (max (u0, 0), p.Usat) * [1; 1];
  rig.out = @(p, X) X(:,2);
  rig.meas = @(p, y) p.q * round ((y + p.noise * randn (size (y))) / p.q);
  rig.u_rest = 2;
  rig.nrest = 200;
  rig.excite = @(N) staircase (N, 0.05, 1, 10, 2, 6);
  rig.est.N = 9600;                  # 8 min
  rig.val.N = 6000;                  # 5 min
  rig.NN = [1 1 0; 1 2 0; 2 2 0];
endfunction

function rig = rig_adc_clip ()
  rig.title = "air-bearing table, tachometer through a clipping ADC";
  rig.kind = "nonlinear";
  rig.effect = "saturation";
  rig.physics = ["tacho voltage (0.1 V per rad/s) read by a +-10 V ADC ", ...
                 "that clips above 100 rad/s (|u| > 5.6 V)"];
  rig.units = {"V", "V"};
  rig.Ts = 0.05;
  rig.nsub = 4;
  rig.p = struct ("tau_m", 2, "Kw", 18, "kg", 0.1, "tau_t", 0.15, ...
                  "Vmax", 10, "bits", 12, "delay", 0, "noise", 0.02);
  rig.f = @(p) @(x, u) [(p.Kw * u - x(1)) / p.tau_m;
                        (p.kg * x(1) - x(2)) / p.tau_t];
  rig.x_rest = @(p, u0) [p.Kw * u0; p.kg * p.Kw * u0];
  rig.out = @(p, X) X(:,2);
  rig.meas = @(p, y) adc (y + p.noise * randn (size (y)), p.Vmax, p.bits);
  rig.u_rest = 0;
  rig.nrest = 100;
  rig.excite = @(N) staircase (N, 0.05, -8, 8, 1.5, 6);
  rig.est.N = 7200;                  # 6 min
  rig.val.N = 4800;                  # 4 min
  rig.NN = [1 1 0; 1 2 0; 2 2 0];
endfunction

## A bipolar ADC of range +-vmax and the given bits: clips, then rounds.
function y = adc (v, vmax, bits)
  q = 2 * vmax / 2^bits;
  y = q * round (min (max (v, -vmax), vmax) / q);
endfunction

function rig = rig_pendulum ()
  rig.title = "motor-driven pendulum";
  rig.kind = "nonlinear";
  rig.effect = "state_nonlinearity";
  rig.physics = ["restoring torque m g l sin(theta), swings to about ", ...
                 "+-70 deg (natural frequency 0.88 Hz for small angles)"];
  rig.units = {"V", "deg"};
  rig.Ts = 0.01;
  rig.nsub = 4;
  ## 0.5 kg at 0.25 m, J = 0.04 kg m^2 with the rotor, damping ratio 0.08,
  ## current amplifier and motor 0.1 N m per volt.
  rig.p = struct ("J", 0.04, "b", 0.035, "m", 0.5, "g", 9.81, "l", 0.25, ...
                  "kt", 0.1, "zero", 180, "delay", 0, "noise", 0.05, ...
                  "q", 360 / 4096);
  rig.f = @(p) @(x, u) [x(2);
                        (p.kt * u - p.b * x(2) ...
                         - p.m * p.g * p.l * sin (x(1))) / p.J];
  rig.x_rest = @(p, u0) [asin(p.kt * u0 / (p.m * p.g * p.l)); 0];
  rig.out = @(p, X) p.zero + X(:,1) * 180 / pi;
  rig.meas = @(p, y) p.q * round ((y + p.noise * randn (size (y))) / p.q);
  rig.u_rest = 0;
  rig.nrest = 200;
  rig.excite = @(N) 2.4 * multisine (N, 0.01, 0.1, 2, 2048);
  rig.est.N = 200 + 4 * 2048;
  rig.val.N = 200 + 2 * 2048;
  rig.NN = [1 2 0; 2 2 0; 1 3 0];
endfunction

function rig = rig_thermal3 ()
  rig.title = "three-node thermal chain";
  rig.kind = "linear";
  rig.effect = "none";
  rig.physics = ["heater 150 J/K -> plate 600 J/K -> sensor boss ", ...
                 "200 J/K, linear conduction and convection"];
  rig.units = {"W", "degC"};
  rig.Ts = 2;
  rig.nsub = 2;
  rig.p = struct ("C", [150 600 200], "G12", 1.5, "G23", 1.0, ...
                  "Ga", [0.05 0.2 0.1], "Ta", 21, "delay", 0, ...
                  "noise", 0.05, "q", 0.01);
  rig.f = @(p) @(x, u) [(u - p.G12 * (x(1) - x(2)) ...
                         - p.Ga(1) * (x(1) - p.Ta)) / p.C(1);
                        (p.G12 * (x(1) - x(2)) - p.G23 * (x(2) - x(3)) ...
                         - p.Ga(2) * (x(2) - p.Ta)) / p.C(2);
                        (p.G23 * (x(2) - x(3)) ...
                         - p.Ga(3) * (x(3) - p.Ta)) / p.C(3)];
  rig.x_rest = @(p, u0) thermal3_rest (p, u0);
  rig.out = @(p, X) X(:,3);
  rig.meas = @(p, y) p.q * round ((y + p.noise * randn (size (y))) / p.q);
  rig.u_rest = 0;
  rig.nrest = 150;
  rig.excite = @(N) 40 * prbs_lfsr (N, 7, 30);
  rig.est.N = 7200;                  # 4 h
  rig.val.N = 5400;                  # 3 h
  rig.NN = [1 1 0; 1 2 0; 1 3 0; 2 3 0];
endfunction

## The three temperatures at rest under the heater power P0 (the linear
## balance G x = b).
function x = thermal3_rest (p, P0)
  G = [p.G12 + p.Ga(1), -p.G12, 0;
       -p.G12, p.G12 + p.G23 + p.Ga(2), -p.G23;
       0, -p.G23, p.G23 + p.Ga(3)];
  x = G \ ([P0; 0; 0] + p.Ta * p.Ga(:));
endfunction

function rig = rig_beam_mode ()
  rig.title = "cantilever beam, first bending mode";
  rig.kind = "linear";
  rig.effect = "none";
  rig.physics = ["one mode at 4.2 Hz, damping ratio 0.015, laser ", ...
                 "sensor reading 25 mm at rest"];
  rig.units = {"V", "mm"};
  rig.Ts = 0.004;
  rig.nsub = 4;
  rig.p = struct ("m", 0.8, "fn", 4.2, "zeta", 0.015, "ka", 2, ...
                  "zero", 25, "delay", 0, "noise", 0.005, "q", 0.001);
  rig.f = @(p) @(x, u) [x(2);
                        (p.ka * u ...
                         - 2 * p.zeta * (2 * pi * p.fn) * p.m * x(2) ...
                         - p.m * (2 * pi * p.fn)^2 * x(1)) / p.m];
  rig.x_rest = @(p, u0) [p.ka * u0 / (p.m * (2 * pi * p.fn)^2); 0];
  rig.out = @(p, X) p.zero + 1000 * X(:,1);
  rig.meas = @(p, y) p.q * round ((y + p.noise * randn (size (y))) / p.q);
  rig.u_rest = 0;
  rig.nrest = 100;
  rig.excite = @(N) 0.15 * multisine (N, 0.004, 0.5, 15, 1024);
  rig.est.N = 100 + 10 * 1024;
  rig.val.N = 100 + 6 * 1024;
  rig.NN = [1 2 0; 2 2 0; 1 3 0; 1 4 0];
endfunction

function rig = rig_mixing_delay ()
  rig.title = "salt dosing, conductivity downstream";
  rig.kind = "linear";
  rig.effect = "none";
  rig.physics = ["first-order mixing, 25 s, transport delay 12.4 s ", ...
                 "(12.4 samples), tap water at 0.45 mS/cm"];
  rig.units = {"L/h", "mS/cm"};
  rig.Ts = 1;
  rig.nsub = 5;
  rig.p = struct ("tau", 25, "K", 0.08, "delay", 12.4, "base", 0.45, ...
                  "noise", 0.003, "q", 0.001);
  rig.f = @(p) @(x, u) (p.K * u - x) / p.tau;
  rig.x_rest = @(p, u0) p.K * u0;
  rig.out = @(p, X) p.base + X(:,1);
  rig.meas = @(p, y) p.q * round ((y + p.noise * randn (size (y))) / p.q);
  rig.u_rest = 2;
  rig.nrest = 60;
  rig.excite = @(N) 2 + 6 * prbs_lfsr (N, 8, 20);
  rig.est.N = 7200;                  # 2 h
  rig.val.N = 5400;                  # 1.5 h
  rig.NN = [1 1 10; 1 1 11; 1 1 12; 1 1 13; 1 1 14;
            1 2 10; 1 2 11; 1 2 12; 1 2 13; 1 2 14];
endfunction

## ----------------------------------------------------------- excitations

## Random staircase: levels uniform on [lo, hi], each held a random time
## uniform on [hmin, hmax] seconds.
function u = staircase (N, Ts, lo, hi, hmin, hmax)
  u = zeros (N, 1);
  k = 1;
  while (k <= N)
    n = max (1, round ((hmin + (hmax - hmin) * rand ()) / Ts));
    u(k:min(N, k+n-1)) = lo + (hi - lo) * rand ();
    k += n;
  endwhile
endfunction

## Maximum-length binary sequence (0/1) of a Fibonacci shift register of
## order n (7 or 8), each bit held for 'clock' samples, from a random
## point of its period.
function u = prbs_lfsr (N, n, clock)
  switch (n)
    case 7
      taps = [7 6];
    case 8
      taps = [8 6 5 4];
    otherwise
      error ("lab_rigs:badInput", "lab_rigs: PRBS order %d", n);
  endswitch
  L = 2^n - 1;
  reg = ones (1, n);
  bits = zeros (L, 1);
  for i = 1:L
    bits(i) = reg(n);
    fb = mod (sum (reg(taps)), 2);
    reg = [fb, reg(1:n-1)];
  endfor
  bits = circshift (bits, -floor (L * rand ()));
  nb = ceil (N / clock);
  b = bits(mod ((0:nb-1).', L) + 1);
  u = kron (b, ones (clock, 1));
  u = u(1:N);
endfunction

## Random-phase multisine of period P samples, all lines of the period
## between fmin and fmax (Hz), unit RMS.
function u = multisine (N, Ts, fmin, fmax, P)
  f = (1:P/2-1).' / (P * Ts);
  f = f(f >= fmin & f <= fmax);
  phi = 2 * pi * rand (numel (f), 1);
  t = (0:N-1) * Ts;
  u = sum (cos (2 * pi * f * t + phi), 1).';
  u = u / sqrt (numel (f) / 2);
endfunction
