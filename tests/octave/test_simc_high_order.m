## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn {} {} test_simc_high_order ()
## simc (the core's simulator) on stable high-order models whose companion
## form is badly scaled: lightly damped modes spread over two to three
## decades (orders 6, 8 and 10, damping 0.005-0.05) with zeros 1 % away
## from the poles (near cancellation), and the sixth-order flexible
## structure of test_srivc_flexible (modes at 3.5, 16 and 38 Hz,
## coefficients up to 2.8e11), on fast-sampled records of 20000 samples
## (random steps). Checked against the control package's lsim of the exact
## ZOH discretisation of a scaled state-space realisation (prescale), to
## 1e-9 of the output's norm. The unbalanced exponential of the companion
## form made every one of these simulations except the first overflow
## ("the simulated output is not finite").
## @end deftypefn

function test_simc_high_order ()
  root = fileparts (fileparts (fileparts (mfilename ("fullpath"))));
  addpath (fullfile (root, "octave"));
  pkg load control
  cases = {[1 7 50], [0.02 0.01 0.005];
           [1 10 100 400], [0.05 0.02 0.01 0.01];
           [0.5 3 20 90 300], 0.01 * ones(1, 5)};
  models = {};
  for c = 1:rows (cases)
    [w, z] = cases{c, :};
    F = 1;
    for i = 1:numel (w)
      F = conv (F, [1 2*z(i)*w(i) w(i)^2]);
    endfor
    zz = roots (F)(1:end-1) * 1.01;      # zeros next to the poles
    B = real (poly (zz)) * abs (F(end) / prod (zz));
    models(end+1, :) = {B, F};
  endfor
  [B, F] = flexible ();
  models(end+1, :) = {B, F};
  N = 20000;
  randn ("state", 1);
  u = kron (randn (N / 10, 1), ones (10, 1));
  for c = 1:rows (models)
    [B, F] = models{c, :};
    for Ts = [1e-3 1e-2]
      t = (0:N-1)' * Ts;
      yl = lsim (c2d (prescale (ss (tf (B, F))), Ts, "zoh"), u, t);
      ys = simc (idtf (B, F), u, Ts);
      err = norm (ys - yl) / norm (yl);
      printf ("order %2d, coefficients up to %.1e, Ts %g: relative error %.2e\n",
              numel (F) - 1, max (abs (F)), Ts, err);
      assert (err < 1e-9);
    endfor
  endfor
endfunction

## The flexible structure of test_srivc_flexible.
function [B, F] = flexible ()
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
endfunction
