## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn {} {@var{cases} =} residtrace_cases (@var{set})
## Undeclared-effect datasets for @code{residtrace}: one
## per effect of its library, that single effect present and not declared
## to the tool, plus a clean control. Each case has an estimation record
## @code{data}, a separate validation record @code{datav} (new input
## realisation and new noise; for the drift, the continuation of the same
## experiment), the model @code{M} a user would start from (SRIVC of the
## plain linear structure, or for the viscous case a mass-spring model
## without damping written down by hand), the true @code{effect} and a
## @code{description}.
##
## @var{set} 1 is the test set of @code{test_residtrace}; set 2 uses other
## seeds and other systems, orders, time constants, noise levels and
## inputs, to check by hand that the tool was not tuned to set 1. White
## Gaussian measurement noise (coloured in the 'colored_noise' case), SNR
## between about 14 and 30 dB. Systems with Coulomb friction are
## integrated here with 25 sub-steps per sample (2.5 times finer than the
## tool's default), by code of their own.
## @end deftypefn

function cases = residtrace_cases (set)
  if (nargin < 1)
    set = 1;
  endif
  cases = struct ("effect", {}, "data", {}, "datav", {}, "M", {},
                  "description", {}, "truth", {});
  if (set == 1)
    base = 100;
  else
    base = 500;
  endif
  names = {"none", "offset", "coulomb", "viscous", "delay", "order", ...
           "static_nonlinearity", "sinusoid", "drift", "colored_noise"};
  for k = 1:numel (names)
    randn ("state", base + k);
    rand ("state", base + k);
    c = feval (["case_" names{k}], set);
    c.effect = names{k};
    cases(end+1) = c;
  endfor
endfunction

## ---- inputs ----------------------------------------------------------

function u = input_signal (type, N, Ts, bw)
  switch (type)
    case "prbs"
      p = max (1, round (1 / (bw * Ts)));
      u = prbs (11, p, [-1 1], N + 1000);
      u = u(1 + randi (1000):end)(1:N);
    case "multisine"
      ## random-phase multisine, flat up to bw rad/s
      T = N * Ts;
      k = 1:max (2, floor (bw * T / (2 * pi)));
      t = (0:N-1)' * Ts;
      u = sum (cos (2 * pi * t * k / T + 2 * pi * rand (1, numel (k))), 2);
      u /= std (u);
    case "noise"
      ## white noise through a second-order low-pass at bw rad/s
      w = randn (N + 500, 1);
      u = simc (struct ("B", bw ^ 2, "F", [1 1.4 * bw bw ^ 2]), w, Ts);
      u = u(501:end);
      u /= std (u);
  endswitch
endfunction

function y = add_noise (x, snr_db)
  e = randn (size (x));
  y = x + e * sqrt (mean ((x - mean (x)) .^ 2) / 10 ^ (snr_db / 10));
endfunction

function d = rec (y, u, Ts)
  d = iddata (y, u, Ts, "InterSample", "zoh");
endfunction

function c = pack (y, u, yv, uv, Ts, M, text, truth)
  if (nargin < 8)
    truth = struct ();
  endif
  c = struct ("effect", "", "data", rec (y, u, Ts), "datav", rec (yv, uv, Ts),
              "M", M, "description", text, "truth", truth);
endfunction

## ---- one case per effect ---------------------------------------------

function c = case_none (set)
  if (set == 1)
    G = idctm (3, [1 1.6 4]); Ts = 0.05; N = 2500; typ = "prbs"; bw = 4;
    snr = 18;
  else
    G = idctm ([1.5 2], conv ([1 1], [1 3])); Ts = 0.02; N = 4000;
    typ = "noise"; bw = 6; snr = 25;
  endif
  u = input_signal (typ, N, Ts, bw); uv = input_signal (typ, N, Ts, bw);
  y = add_noise (simc (G, u, Ts), snr); yv = add_noise (simc (G, uv, Ts), snr);
  M = srivc (rec (y, u, Ts), [numel(G.B) numel(G.F)-1 0]);
  c = pack (y, u, yv, uv, Ts, M, "clean linear system (control)");
endfunction

function c = case_offset (set)
  if (set == 1)
    G = idctm (2, [1 1.2 1]); Ts = 0.05; N = 2500; typ = "noise"; bw = 2;
    off_in = 0.25; off_out = 0; snr = 20;
  else
    G = idctm (5, [1 2.5]); Ts = 0.02; N = 3000; typ = "prbs"; bw = 5;
    off_in = 0; off_out = -0.4; snr = 15;
  endif
  u = input_signal (typ, N, Ts, bw); uv = input_signal (typ, N, Ts, bw);
  x = simc (G, u + off_in, Ts) + off_out;
  xv = simc (G, uv + off_in, Ts) + off_out;
  y = add_noise (x, snr); yv = add_noise (xv, snr);
  nb = numel (G.B); nf = numel (G.F) - 1;
  M = srivc (rec (y, u, Ts), [nb nf 0]);
  c = pack (y, u, yv, uv, Ts, M, sprintf ("input offset %g, output offset %g",
                                          off_in, off_out),
            struct ("input_offset", off_in, "output_offset", off_out));
endfunction

## m x'' + cv x' + k x = u - Fc sign(x'), output x (position): 25
## sub-steps per sample, each exact for the force held over it, the
## friction's sign taken at the start of the sub-step.
function x = mass_coulomb (u, Ts, m, cv, k, Fc)
  N = numel (u);
  S = 25;
  h = Ts / S;
  A = [0 1; -k / m, -cv / m];
  E = expm ([A, [0; 1 / m]; 0 0 0] * h);
  Ad = E(1:2, 1:2); Bd = E(1:2, 3);
  z = [0; 0];
  x = zeros (N, 1);
  for i = 1:N
    x(i) = z(1);
    for s = 1:S
      z = Ad * z + Bd * (u(i) - Fc * sign (z(2)));
    endfor
  endfor
endfunction

function c = case_coulomb (set)
  if (set == 1)
    m = 1; cv = 0.8; k = 4; Fc = 0.35; Ts = 0.02; N = 2500;
    typ = "multisine"; bw = 6; snr = 25;
  else
    m = 2; cv = 3; k = 10; Fc = 0.5; Ts = 0.01; N = 3000;
    typ = "noise"; bw = 8; snr = 20;
  endif
  u = input_signal (typ, N, Ts, bw); uv = input_signal (typ, N, Ts, bw);
  y = add_noise (mass_coulomb (u, Ts, m, cv, k, Fc), snr);
  yv = add_noise (mass_coulomb (uv, Ts, m, cv, k, Fc), snr);
  M = srivc (rec (y, u, Ts), [1 2 0]);
  c = pack (y, u, yv, uv, Ts, M,
            sprintf ("mass-spring-damper with Coulomb friction %g", Fc),
            struct ("coulomb", Fc));
endfunction

function c = case_viscous (set)
  if (set == 1)
    m = 1; cv = 0.6; k = 9; Ts = 0.02; N = 2500; typ = "prbs"; bw = 5;
    snr = 20;
  else
    m = 0.5; cv = 2; k = 8; Ts = 0.01; N = 3000; typ = "multisine"; bw = 10;
    snr = 25;
  endif
  G = idctm (1 / m, [1 cv / m k / m]);
  u = input_signal (typ, N, Ts, bw); uv = input_signal (typ, N, Ts, bw);
  y = add_noise (simc (G, u, Ts), snr); yv = add_noise (simc (G, uv, Ts), snr);
  ## the user's model: a mass on a spring, nominal values, no damping
  M = idctm (1.1 / m, [1 0 0.9 * k / m]);
  c = pack (y, u, yv, uv, Ts, M, "mass-spring with damping; model undamped",
            struct ("viscous", cv));
endfunction

function c = case_delay (set)
  if (set == 1)
    G = idctm (4, [1 2.4 4]); Ts = 0.05; N = 2500; typ = "prbs"; bw = 4;
    nk = 4; snr = 20;
  else
    G = idctm (2, [1 0.8]); Ts = 0.05; N = 2000; typ = "noise"; bw = 3;
    nk = 7; snr = 18;
  endif
  Gd = idctm (G.B, G.F, "nk", nk);
  u = input_signal (typ, N, Ts, bw); uv = input_signal (typ, N, Ts, bw);
  y = add_noise (simc (Gd, u, Ts), snr);
  yv = add_noise (simc (Gd, uv, Ts), snr);
  M = srivc (rec (y, u, Ts), [numel(G.B) numel(G.F)-1 0]);
  c = pack (y, u, yv, uv, Ts, M, sprintf ("input delay of %d samples", nk),
            struct ("nk", nk));
endfunction

function c = case_order (set)
  if (set == 1)
    ## a resonance with a real pole of similar speed: third order
    G = idctm (12, conv ([1 1.2 4], [1 3])); Ts = 0.05; N = 2500;
    typ = "prbs"; bw = 4; snr = 20; nn = [1 2 0];
  else
    ## a missing zero: (1 + p/0.8) / second order
    G = idctm ([2.5 2], [1 2 4]); Ts = 0.02; N = 3000; typ = "noise";
    bw = 5; snr = 25; nn = [1 2 0];
  endif
  u = input_signal (typ, N, Ts, bw); uv = input_signal (typ, N, Ts, bw);
  y = add_noise (simc (G, u, Ts), snr); yv = add_noise (simc (G, uv, Ts), snr);
  M = srivc (rec (y, u, Ts), nn);
  c = pack (y, u, yv, uv, Ts, M, "true order above the model's",
            struct ("F", G.F, "B", G.B));
endfunction

function c = case_static_nonlinearity (set)
  if (set == 1)
    G = idctm (2, [1 1.5 2]); Ts = 0.05; N = 2500; typ = "noise"; bw = 2;
    g = @(u) max (min (u, 0.8), -0.8); snr = 25;
    text = "input saturation at +-0.8 (input std 1)";
    truth = struct ("clip", 0.8);
  else
    G = idctm (3, [1 3]); Ts = 0.02; N = 3000; typ = "multisine"; bw = 6;
    g = @(u) u + 0.3 * u .^ 3; snr = 20;
    text = "cubic input nonlinearity u + 0.3 u^3";
    truth = struct ("cubic", 0.3);
  endif
  u = input_signal (typ, N, Ts, bw); uv = input_signal (typ, N, Ts, bw);
  y = add_noise (simc (G, g (u), Ts), snr);
  yv = add_noise (simc (G, g (uv), Ts), snr);
  M = srivc (rec (y, u, Ts), [numel(G.B) numel(G.F)-1 0]);
  c = pack (y, u, yv, uv, Ts, M, text, truth);
endfunction

function c = case_sinusoid (set)
  if (set == 1)
    G = idctm (4, [1 2 4]); Ts = 0.05; N = 2500; typ = "prbs"; bw = 4;
    f = 0.7; A = 0.25; snr = 20;
  else
    G = idctm ([1 3], [1 2.2 3]); Ts = 0.01; N = 4000; typ = "noise";
    bw = 6; f = 3.3; A = 0.15; snr = 22;
  endif
  u = input_signal (typ, N, Ts, bw); uv = input_signal (typ, N, Ts, bw);
  t = (0:N-1)' * Ts;
  x = simc (G, u, Ts); xv = simc (G, uv, Ts);
  s = A * sin (2 * pi * f * t + 2 * pi * rand);
  sv = A * sin (2 * pi * f * t + 2 * pi * rand);
  y = add_noise (x, snr) + s; yv = add_noise (xv, snr) + sv;
  M = srivc (rec (y, u, Ts), [numel(G.B) numel(G.F)-1 0]);
  c = pack (y, u, yv, uv, Ts, M,
            sprintf ("additive sinusoid %g Hz, amplitude %g", f, A),
            struct ("freq_hz", f, "amplitude", A));
endfunction

function c = case_drift (set)
  ## one experiment; its first half estimates, its second half validates
  if (set == 1)
    Ts = 0.05; N = 5000; typ = "prbs"; bw = 4; snr = 20;
    t = (0:N-1)' * Ts;
    wn = 2 * (1 + 0.35 * t / t(end));           # resonance drifts +35 %
    th = [1.2 * wn, wn .^ 2, 2 * wn .^ 2];     # [a1 a2 b0]
    nn = [2 1 0];
  else
    Ts = 0.02; N = 6000; typ = "noise"; bw = 5; snr = 25;
    t = (0:N-1)' * Ts;
    a = 2 * (1 - 0.4 * t / t(end));            # a pole slows down by 40 %
    th = [a, 3 * ones(N, 1)];                   # [a1 b0]: gain grows
    nn = [1 1 0];
  endif
  u = input_signal (typ, N, Ts, bw);
  y = add_noise (simc (th, nn, u, Ts), snr);
  h = N / 2;
  M = srivc (rec (y(1:h), u(1:h), Ts), [nn(2) nn(1) 0]);
  c = pack (y(1:h), u(1:h), y(h+1:end), u(h+1:end), Ts, M,
            "parameters drifting along the experiment");
endfunction

function c = case_colored_noise (set)
  if (set == 1)
    G = idctm (3, [1 1.6 4]); Ts = 0.05; N = 2500; typ = "prbs"; bw = 4;
    a = 0.9; s = 0.25;
  else
    G = idctm (2, [1 1.5]); Ts = 0.02; N = 3000; typ = "noise"; bw = 5;
    a = [1.5 -0.7]; s = 0.1;
  endif
  u = input_signal (typ, N, Ts, bw); uv = input_signal (typ, N, Ts, bw);
  v = filter (1, [1 -a], s * randn (N, 1));
  vv = filter (1, [1 -a], s * randn (N, 1));
  y = simc (G, u, Ts) + v; yv = simc (G, uv, Ts) + vv;
  M = srivc (rec (y, u, Ts), [numel(G.B) numel(G.F)-1 0]);
  c = pack (y, u, yv, uv, Ts, M, "AR noise, no missing dynamics",
            struct ("ar", a));
endfunction
