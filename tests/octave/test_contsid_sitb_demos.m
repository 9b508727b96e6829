## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## The call sequences of CONTSID 7.3's demos that need the SITB model
## objects (contsid-surface.md), replayed on simulated data: the SRIVC
## tutorials, the recursive LTI demo, the canning (three inputs) and
## aero-thermal channel case studies, the MISO demo with input delays and
## the closed-loop demos' model building (checked against the control
## package's feedback).  Each must run to its end with
## figures invisible; the numbers that can be checked are.
function test_contsid_sitb_demos ()
  set (0, "defaultfigurevisible", "off");
  randn ("state", 3);
  tutorial_srivc ();
  recursive_lti ();
  canning ();
  aero_thermal ();
  miso_delays ();
  closed_loop_models ();
  close all;
endfunction

## iddata ([], u, Ts, ...) as the demos write it; input-only data built
## with an empty N-by-0 output where that form is not accepted yet.
function d = input_data (u, Ts, varargin)
  try
    d = iddata ([], u, Ts, varargin{:});
  catch
    d = iddata (zeros (rows (u), 0), u, Ts, varargin{:});
  end_try_catch
endfunction

function tutorial_srivc ()
  Ts = 0.05;
  B = [1 4]; A = [1 2.4 4];
  M0 = idpoly (1, B, 1, 1, A, "Ts", 0);
  present (M0);
  u = prbs (10, 4);
  N = numel (u);
  datau = input_data (u, Ts, "InterSample", "zoh");
  ydet = simc (M0, datau);
  y = simc (M0, datau, 15);                  # SNR 15 dB
  assert (10 * log10 (mean (ydet .^ 2) / mean ((y - ydet) .^ 2)), 15, 1e-8);
  data = iddata (y, u, Ts, "InterSample", "zoh");
  data_est = data(1:2000);
  data_val = data(2001:N);
  Msrivc = srivc (data_est, [length(B) length(A)-1 0]);
  present (Msrivc);
  param_est = getpvec (Msrivc);
  param_true = getpvec (M0);
  [~, sd] = getpvec (Msrivc);
  printf ("tutorial: |theta - theta0| / sd = %s\n",
          mat2str ((abs (param_est - param_true) ./ sd).', 3));
  assert (all (abs (param_est - param_true) < 5 * sd));
  figure; bode (M0, "b-", Msrivc, "r--", "sd", 3, "fill");
  figure; bode (Msrivc, "sd", 3, "fill");
  figure; step (M0, "b", Msrivc, "r");
  figure; comparec (data_val, Msrivc, 1:1000);
  [ys, esti] = comparec (data_val, Msrivc);
  title (num2str (esti.RT2, 3));
  assert (esti.RT2(1, 1) > 0.9);
  [ys, estInfo] = comparec (data_est, Msrivc, 1001:2000);
  assert (rows (ys), 1000);
  figure; residc (data_est, Msrivc);
  figure; zpplot (Msrivc);
  figure; pzmap (Msrivc);
  Mtf = idtf (Msrivc);
  assert (getpvec (Mtf), [getpvec(Msrivc); 0], 1e-12);   # idtf: + IODelay
  ## Report.Fit of the estimator = comparec's figures on the estimation data
  ## with the levels the model was estimated with removed (srivc's
  ## Report.DataUsed, MATLAB's convention y - OutputOffset = M (u -
  ## InputOffset); here srivc's 'auto' rule estimates a small output
  ## offset because the noisy record's first samples are not at 0)
  lev = Msrivc.Report.DataUsed;
  [~, est] = comparec (iddata (data_est.y - lev.OutputOffset,
                               data_est.u - lev.InputOffset, Ts,
                               "InterSample", "zoh"), Msrivc,
                      "Levels", "ignore");
  printf ("tutorial: Report.Fit.FitPercent %.4f, comparec %.4f\n",
          Msrivc.Report.Fit.FitPercent, est.Fit);
  assert (Msrivc.Report.Fit.FitPercent, est.Fit, 1e-6);
  assert (Msrivc.Report.Fit.MSE, est.MSE, 1e-9 * est.MSE);
  damp (Msrivc);
endfunction

function recursive_lti ()
  Ts = 0.01;
  B = 2; A = [1 1.2 2];
  M0 = idpoly (1, B, 1, 1, A, 0, 0);
  u = prbs (12, 50);
  datau = input_data (u, Ts, "InterSample", "zoh");
  y = simc (M0, datau, 20);
  data = iddata (y, u, Ts, "InterSample", "zoh");
  thm = rlssvf (data, [2 1 0], "lambda_svf", 2);
  thm2 = rivsvf (data, [2 1 0], "lambda_svf", 2, "tsiv", 10);
  thm3 = rsrivc (data, [1 2 0], "lambda_svf", 2, "tsiv", 10);
  figure; bode4frozensys (thm2, [2 1], "w", logspace (-2, 3));
  figure; bode (M0);
  present (M0);
  rel = norm (thm2(end, :) - [1.2 2 2]) / norm ([1.2 2 2]);
  printf ("recursive LTI: RIVSVF final relative error %.3f\n", rel);
  assert (rel < 0.1);
endfunction

function canning ()
  ## three inputs, one output (the canning line), simulated
  Ts = 0.1;
  N = 3000;
  U = [prbs(10, 3)(1:N), prbs(11, 2)(1:N), prbs(9, 6)(1:N)];
  M0 = idpoly (1, {0.8, 0.5, [0.3 0.4]}, 1, 1, [1 1.5 0.8], 0, 0);
  present (M0);
  ydet = simc (M0, input_data (U, Ts, "InterSample", {"zoh"; "zoh"; "zoh"}));
  y = ydet + 0.05 * std (ydet) * randn (N, 1);
  data_est = iddata (y(1:2000), U(1:2000, :), Ts,
                     "InterSample", {"zoh"; "zoh"; "zoh"});
  data_val = iddata (y(2001:end), U(2001:end, :), Ts, "InterSample", "zoh");
  Msrivc = srivc (data_est, [1 1 2 2 0 0 0]);
  present (Msrivc);
  figure; comparec (data_val, Msrivc);
  [ys, estInfo] = comparec (data_val, Msrivc, 1:500);
  printf ("canning: RT2 on validation = %.4f\n", estInfo.RT2(1, 1));
  assert (estInfo.RT2(1, 1) > 0.95);
  figure; residc (data_est, Msrivc);
  figure; step (Msrivc);
endfunction

function aero_thermal ()
  ## second-order with a delay of 4 samples (the aero-thermal channel)
  Ts = 0.1;
  M0 = idtf (1.2, [1 1.1 0.3], "IODelay", 4 * Ts);
  u = prbs (10, 5);
  N = numel (u);
  ydet = simc (M0, input_data (u, Ts));
  data = iddata (ydet + 0.02 * randn (N, 1), u, Ts, "InterSample", "zoh");
  Msrivc = srivc (data, [1 2 4]);
  present (Msrivc);
  assert (totaldelay (Msrivc), 4 * Ts, 1e-12);
  figure; comparec (data, Msrivc, 1:1000);
  [~, esti] = comparec (data, Msrivc);
  assert (esti.Fit > 90);
  figure; bode (M0, "b", Msrivc, "r--", "sd", 3);
  figure; nyquist (Msrivc);
endfunction

function miso_delays ()
  Ts = 0.05; nk1 = 3; nk2 = 5;
  A = [1 3 2];
  B = [1 2; 0 3];
  F = [1 2.2 1.2; 1 4 4];
  M0 = idpoly (1, B, 1, 1, F, 0, 0, "InputDelay", [nk1 nk2] * Ts);
  present (M0);
  U = [prbs(9, 4), prbs(9, 4)(end:-1:1)];
  datau = input_data (U, Ts, "InterSample", {"zoh"; "zoh"});
  ydet = simc (M0, datau);
  data = iddata (ydet, U, Ts);
  [~, info] = comparec (data, M0);
  assert (info.RT2, 1, 1e-12);
  figure; step (M0);
  figure; bode (M0);
endfunction

function closed_loop_models ()
  Ts = 0.01;
  Nc = [1.2 2]; Dc = [1 0];                 # PI controller
  Mc = idpoly (Dc / Dc(1), Nc / Dc(1), 1, 1, 1, 0, "Ts", 0);
  assert (Mc.A, [1 0]);
  B = 2; A = [1 1.5 1];
  Acl = conv (A, Dc) + [0, 0, conv(B, Nc)];
  Bcl = conv (B, Nc);
  Ccl = conv (A, Nc);
  M0yr = idpoly (1, Bcl, 1, 1, Acl, "Ts", 0);
  M0ur = idpoly (1, Ccl, 1, 1, Acl, 0, 0);
  r = prbs (8, 20);
  datar = input_data (r, Ts, "InterSample", "zoh");
  ydet = simc (M0yr, datar);
  udet = simc (M0ur, datar);
  ## the control package's closed loop, discretised exactly (ZOH on r)
  pkg load control
  t = (0:numel (r) - 1)' * Ts;
  Gcl = feedback (tf (Nc, Dc) * tf (B, A), 1);
  ycl = lsim (c2d (Gcl, Ts), r, t);
  printf ("closed loop: max |y - y_control| = %.2e\n", max (abs (ydet - ycl)));
  assert (ydet, ycl, 1e-8);
  ucl = lsim (c2d (feedback (tf (Nc, Dc), tf (B, A)), Ts), r, t);
  assert (udet, ucl, 1e-8);
  present (M0yr);
endfunction
