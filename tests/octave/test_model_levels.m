## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn {} {} test_model_levels ()
## One meaning of a model's levels in every function
## (doc/manual/levels.md). A raw record y = 20 + G (u - 5),
## G = 2 / (s^2 + 1.2 s + 1), u = 5 +- 3 in random steps, 4000 samples at
## Ts = 0.05 s, output noise of standard deviation 0.5; srivc on the first
## half estimates and stores the levels (Report.DataUsed.InputOffset and
## OutputOffset). On the second half, the validation RMSE of the model by
## simc, sim, comparec, residc and residtrace (rmse_given) and the
## validation R_T^2 of srivcstruc all equal that of an independent
## simulation with the levels: the control package's lsim of the exact ZOH
## model on u - u0, plus y0. With "Levels", "ignore", simc, sim, comparec
## and residc give the level-free figure (lsim on u without levels), and
## with the offsets removed from the data by hand, the first figure again.
## @end deftypefn

function test_model_levels ()
  root = fileparts (fileparts (fileparts (mfilename ("fullpath"))));
  addpath (fullfile (root, "octave"));
  pkg load control
  randn ("state", 3);
  rand ("state", 3);
  Ts = 0.05;
  N = 4000;
  u = 5 + 3 * sign (randn (N / 40, 1));
  u = kron (u, ones (40, 1));
  t = (0:N-1)' * Ts;
  G = c2d (tf (2, [1 1.2 1]), Ts, "zoh");
  y = 20 + lsim (G, u - 5, t) + 0.5 * randn (N, 1);
  h = N / 2;
  ZE = iddata (y(1:h), u(1:h), Ts, "InterSample", "zoh");
  ZV = iddata (y(h+1:end), u(h+1:end), Ts, "InterSample", "zoh");
  uv = u(h+1:end);
  yv = y(h+1:end);
  tv = t(1:h);

  M = srivc (ZE, [1 2 0]);
  lev = M.Report.DataUsed;
  assert (lev.OutputOffset, 20, 0.5);
  assert (lev.InputOffset, 5, 0.25);
  ## the independent figures: with the levels, and without them
  Gd = c2d (tf (M.B, M.F), Ts, "zoh");
  ind = lsim (Gd, uv - lev.InputOffset, tv) + lev.OutputOffset;
  free = lsim (Gd, uv, tv);
  rmse = @(ys) sqrt (mean ((yv - ys(:)) .^ 2));
  r_ind = rmse (ind);
  r_free = rmse (free);
  tol = 1e-9 * r_ind;                   # two exact ZOH simulations
  names = {"simc", "sim", "comparec", "residc", "residtrace", ...
           "srivcstruc (R_T^2)"};
  got = zeros (1, 5);
  got(1) = rmse (simc (M, ZV));
  got(2) = rmse (sim (M, ZV).y);
  [~, est] = comparec (ZV, M);
  got(3) = est.RMSE;
  R = residc (ZV, M);
  got(4) = rmse (yv - R.e);
  Rt = residtrace (ZE, M, "validation", ZV, "effects", {"offset"});
  got(5) = Rt.rmse_given;
  V = srivcstruc (ZE, ZV, [1 2 0], "NN", "list");
  for k = 1:5
    printf ("%-12s validation RMSE %.6f (independent, with levels %.6f)\n",
            names{k}, got(k), r_ind);
    assert (got(k), r_ind, tol);
  endfor
  rt2 = 1 - var (yv - ind, 1) / var (yv, 1);
  printf ("%-12s validation R_T^2 %.6f (independent %.6f)\n", names{6},
          V(1, 1), rt2);
  assert (V(1, 1), rt2, 1e-9);
  assert (est.Fit, 100 * (1 - norm (yv - ind) / norm (yv - mean (yv))),
          1e-7);
  assert (r_ind < 1 && r_free > 5);     # the levels matter here

  ## 'Levels', 'ignore': the model alone (MATLAB's sim and compare)
  ign = zeros (1, 4);
  ign(1) = rmse (simc (M, ZV, "Levels", "ignore"));
  ign(2) = rmse (sim (M, ZV, "Levels", "ignore").y);
  [~, est0] = comparec (ZV, M, "Levels", "ignore");
  ign(3) = est0.RMSE;
  R0 = residc (ZV, M, "Levels", "ignore");
  ign(4) = rmse (yv - R0.e);
  for k = 1:4
    printf ("%-12s 'ignore' RMSE %.6f (independent, no levels %.6f)\n",
            names{k}, ign(k), r_free);
  endfor
  assert (ign, repmat (r_free, 1, 4), 1e-9 * r_free);
  ## ... and with the offsets removed by hand, the model as estimated
  ZVo = iddata (yv - lev.OutputOffset, uv - lev.InputOffset, Ts,
                "InterSample", "zoh");
  [~, esto] = comparec (ZVo, M, "Levels", "ignore");
  assert (esto.RMSE, r_ind, tol);
  yo = sim (M, uv - lev.InputOffset, Ts, "Levels", "ignore") ...
       + lev.OutputOffset;
  assert (rmse (yo), r_ind, tol);

  ## closed loop about the levels: u = r1 + C (r2 - y) with y = c + x is
  ## the loop of u - d, y - c driven by r1 - d, r2 - c
  C = struct ("kp", 0.3, "ki", 0.2, "kd", 0);
  r2 = 20 + 2 * sign (sin (0.05 * t(1:h)));
  [yc, ~, uc] = simc (M, zeros (h, 1), Ts, "controller", C, "r2", r2);
  [yd, ~, ud] = simc (M, zeros (h, 1) - lev.InputOffset, Ts, "controller",
                      C, "r2", r2 - lev.OutputOffset, "Levels", "ignore");
  assert (yc, yd + lev.OutputOffset, 1e-9 * max (abs (yc)));
  assert (uc, ud + lev.InputOffset, 1e-9 * max (abs (uc)));

  ## step and bode describe the dynamics: no levels
  [ys, ts] = step (M);
  assert (ys(end), polyval (M.B, 0) / polyval (M.F, 0), 0.02);
endfunction
