## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn {} {} test_srivc_flexible ()
## srivc (data, [6 6 0]) on a sixth-order lightly damped flexible
## structure sampled at 500 Hz (a flexible-arm record of this kind, on
## which srivc must not report "no cut-off frequency gave an estimate").
## Three modes at 3.5, 16 and 38 Hz with damping ratios 0.05, 0.02 and 0.01,
## numerator of degree 5 (nb = 6); noise 10 % of the output's standard
## deviation; one ZOH record (held multisine) and one FOH record (multisine,
## linear between samples). The data are simulated here independently of the
## toolbox (exact ZOH/FOH discretisation of a balanced state-space model by
## the control package and expm). Checks: converged, stable, and on a fresh
## validation input R_T^2 > 0.95 against the noise-free output (the bar of
## CONTSID's robot-arm case study), the three natural frequencies within
## 1 %, and comparec's simulation of the model (the core's simulator) equal
## to the independent one.
## @end deftypefn

function test_srivc_flexible ()
  root = fileparts (fileparts (fileparts (mfilename ("fullpath"))));
  addpath (fullfile (root, "octave"));
  pkg load control
  w = 2 * pi * [3.5 16 38];
  z = [0.05 0.02 0.01];
  k = [1 -0.6 0.3];
  m = [0.02 0.01 -0.005];
  F = 1;
  for i = 1:3
    F = conv (F, [1 2*z(i)*w(i) w(i)^2]);
  endfor
  B = zeros (1, 6);
  for i = 1:3
    Di = 1;
    for j = [1:i-1, i+1:3]
      Di = conv (Di, [1 2*z(j)*w(j) w(j)^2]);
    endfor
    B += conv ([m(i)*w(i), k(i)*w(i)^2], Di);
  endfor
  Ts = 1 / 500;
  N = 4096;
  t = (0:N-1)' * Ts;
  for rule = {"zoh", "foh"}
    randn ("state", 7);
    rand ("state", 7);
    u = multisine (t);
    uv = multisine (t);
    x = simulate (B, F, u, Ts, rule{1});
    y = x + 0.1 * std (x) * randn (N, 1);
    data = iddata (y, u, Ts, "InterSample", rule{1});
    [M, RT2, ~, ~, ~, info] = srivc (data, [6 6 0]);
    assert (info.converged, true, rule{1});
    assert (info.stable, true);
    xv = simulate (B, F, uv, Ts, rule{1});
    ym = simulate (M.B, M.F, uv, Ts, rule{1});
    rt2v = 1 - var (xv - ym) / var (xv);
    printf ("%s: RT2 (estimation) %.4f, RT2 validation vs noise-free %.4f, ",
            rule{1}, RT2, rt2v);
    wn = sort (abs (roots (M.F)));
    printf ("natural frequencies %s Hz, %d iterations\n",
            mat2str (unique (round (wn' / 2 / pi * 100) / 100)),
            info.iterations);
    assert (rt2v > 0.95);
    ## comparec simulates the model by simc (the core's simulator): the
    ## same figure as the independent simulation above (its companion form,
    ## coefficients up to 3e11, used to overflow: "the simulated output is
    ## not finite")
    [ys, ci] = comparec (iddata (xv, uv, Ts, "InterSample", rule{1}), M);
    printf ("%s: comparec R_T^2 %.6f (independent %.6f)\n", rule{1},
            ci.RT2, rt2v);
    assert (ys, ym, 1e-8 * max (abs (ym)));
    assert (ci.RT2, rt2v, 1e-8);
    wn = unique (round (wn * 1e6) / 1e6);
    assert (numel (wn), 3);
    assert (wn', w, 0.01 * w);
  endfor
endfunction

function u = multisine (t)
  u = zeros (size (t));
  for f = linspace (0.5, 60, 60)
    u += sin (2 * pi * f * t + 2 * pi * rand ());
  endfor
  u /= std (u);
endfunction

## Exact simulation of B(p)/F(p): ZOH, or FOH (u linear between samples).
function y = simulate (B, F, u, Ts, rule)
  [a, b, c, d] = ssdata (prescale (ss (tf (B, F))));
  n = rows (a);
  E = expm ([a, b, zeros(n, 1); zeros(1, n + 1), 1 / Ts; zeros(1, n + 2)]
            * Ts);
  Ad = E(1:n, 1:n);
  G0 = E(1:n, n + 1);
  G1 = E(1:n, n + 2);
  if (strcmp (rule, "zoh"))
    G1(:) = 0;
  endif
  x = zeros (n, 1);
  y = zeros (numel (u), 1);
  u = [u(:); u(end)];
  for k = 1:numel (y)
    y(k) = c * x + d * u(k);
    x = Ad * x + G0 * u(k) + G1 * (u(k+1) - u(k));
  endfor
endfunction
