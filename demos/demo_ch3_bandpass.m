## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn {} {@var{res} =} demo_ch3_bandpass (@var{outdir}, @var{full})
## Thesis sections 4.1.2-4.1.3 and 3.5 on a simulated LTV band-pass filter
## standing in for the benchmark of sec. 4.1 (whose measured data are not
## available here), and the recursions in single precision (float), with
## and without scaling.
##
## System (eq. 4.1, see ch3_bandpass_record): (p^2 + a1 p + a2(t)) x =
## b0 p u with a1 = b0 = 1.5e4, a2 = 2.5e9 (1 + 0.3 sin (2 pi t / T)),
## T = 15640 samples = 0.1 s, fs = 156250 Hz, multisine 10 Hz - 16 kHz of
## 70 mV RMS (linear between samples), SNR 65 dB. Resonance w0 = 5e4 rad/s
## (8 kHz): at 1e5 rad/s (w0 Ts = 0.64) the trapezoidal rule with which
## the SVF filters y biases the estimates by several percent (measured
## below); at 5e4 the bias is about 2 %. The model has the numerator
## b0 p + b1 (nn = [2 2 0]; b1 = 0 in truth) since nn cannot fix b1 to
## zero: four parameters where the thesis has three.
##
## Records (3 periods each, as the benchmark's experiments): estimation
## (multisine and noise seed 1), validation (seed 3, same scheduling),
## training (seed 4, scheduling shifted by pi/2) for M_s (eq. 3.54).
##
## Settings as in the thesis: lambda_svf = 1e7 rad/s, Qn = diag (1e-15,
## 0.5, 1e-15, 1e-15) for [a1 a2 b0 b1] (thesis: diag([1e-15 0.5 1e-15]));
## t_s,iv = 20 ms; theta0 = 0, P0 = 1e4 I. The ML value of q for a2 (qnml,
## RSRIVC) is reported next to the thesis' 0.5.
##
## Methods: RLSSVF-KF, RSRIVC-KF and PotterSVF, each plain and with
## signal scaling (eqs. 3.66, 3.74, App. C), in double and in single
## precision. Reported: kappa_2(P) (Fig. 4.7), the tracking of a2
## (Fig. 4.4), RMSE_y and fit (eqs. 4.4-4.5) on the validation record
## (Table 4.1; the thesis' values are for the measured benchmark), and for
## single precision the samples where P is not positive definite at
## working precision (kappa_2 = Inf) and the largest deviation from the
## double-precision estimates.
##
## With @var{full} false (default true) the qnml search and the 1e5 rad/s
## check are skipped (for the script test).
##
## Writes to @var{outdir} (default "results"): fig_4_4_estimates.png,
## fig_4_7_kappa.png, fig_4_6_validation.png, fig_ch3_single.png and
## ch3_bandpass.md. Returns @var{res} with per-method fields (see the
## code) for the tests.
## @end deftypefn

function res = demo_ch3_bandpass (outdir = "results", full = true)
  here = demo_prepare (outdir);
  t_all = tic;

  est = ch3_bandpass_record (1, 0);
  val = ch3_bandpass_record (3, 0);
  train = ch3_bandpass_record (4, pi / 2);
  Ts = est.Ts;
  Np = est.Np;
  t = est.t;
  N = numel (t);
  lam = 1e7;
  tsiv = 0.02;
  q = 0.5;
  nn = [2 2 0];
  ms = svfscaling (train.data, nn, "lambda_svf", lam);   # eq. (3.54)
  after = t >= tsiv;
  tail = t >= Np * Ts;                            # periods 2 and 3

  ## name, method, options (RSRIVC's in its order [b0 b1 f1 f2]). The
  ## input, piecewise linear, is filtered by the trapezoidal rule as in the
  ## thesis (sec. 3.1.3): with the exact first-order hold the frozen model
  ## of RLSSVF's first estimates (theta0 = 0, P0 = 1e4 I, w0 Ts = 0.32)
  ## overflows from sample 7 on.
  ls = {"lambda_svf", lam, "adm", "kf", "adg", diag([1e-15 q 1e-15 1e-15]), ...
        "InterSample", "trapezoid"};
  iv = {"lambda_svf", lam, "adm", "kf", "adg", ...
        diag([1e-15 1e-15 1e-15 q]), "tsiv", tsiv, "InterSample", "trapezoid"};
  cfg = {"RLSSVF",        "rlssvf", ls;
         "RLSSVF scaled", "rlssvf", [ls, {"scaling", train.data}];
         "RSRIVC",        "rsrivc", iv;
         "RSRIVC scaled", "rsrivc", [iv, {"scaling", train.data}];
         "PotterSVF",     "rlssvf", [ls, {"potter", true}];
         "PotterSVF scaled", "rlssvf", ...
         [ls, {"potter", true, "scaling", train.data}]};
  M = rows (cfg);
  ## P0 = 1e4 I (the thesis' default) and P0 = 1e4 M_s^2, i.e. the scaled
  ## recursions start from P_s = 1e4 I (RSRIVC's P0 in its order).
  P0s = {1e4, 1e4 * diag(ms .^ 2)};
  P0s_iv = {1e4, 1e4 * diag(ms([3 4 1 2]) .^ 2)};
  for v = 1:2
    for m = 1:M
      P0 = ch2_ifelse_str (strcmp (cfg{m, 2}, "rsrivc"), P0s_iv{v}, P0s{v});
      for p = 1:2
        prec = ch2_ifelse_str (p == 1, "double", "single");
        tic_m = tic;
        [thm, info] = run_method (cfg{m, 2}, est.data, nn,
                                  [cfg{m, 3}, {"P0", P0}], prec);
        rr(m, p).time = toc (tic_m);
        rr(m, p).thm = thm;
        rr(m, p).kappa = info.kappa;
        rr(m, p).nonpd = sum (! isfinite (info.kappa(after)));
        rr(m, p).innov0 = max (info.innovation(1:10));
        err = (thm(tail, :) - est.theta(tail, :)) ./ est.scale;
        rr(m, p).a2_rms = sqrt (mean (err(:, 2) .^ 2));
        rr(m, p).bias = mean (err);
      endfor
      d = abs (rr(m, 2).thm - rr(m, 1).thm) ./ est.scale;
      rr(m, 2).dev = max (d(tail, :));            # single vs double
      rr(m, 2).dev_after = max (d(after, :));
      rr(m, 2).dev_p3 = max (d(t >= 2 * Np * Ts, :));
    endfor
    if (v == 1)
      r = rr;
    else
      r2 = rr;
    endif
  endfor

  ## Table 4.1 on the validation record: the estimates of the estimation
  ## record (same scheduling) simulated with the validation input; RMSE
  ## and fit over the second period without its first 500 samples.
  Ntr = 500;
  k2 = Np + Ntr:2 * Np - 1;
  vnames = {"true parameters", "RLSSVF", "RSRIVC"};
  vthm = {val.theta, r(1, 1).thm, r(3, 1).thm};
  yv = zeros (N, numel (vthm));
  for i = 1:numel (vthm)
    yv(:, i) = simc (vthm{i}, nn, val.u, Ts, "InterSample", "foh");
    e = val.y(k2) - yv(k2, i);
    vrmse(i) = 1e3 * sqrt (mean (e .^ 2));        # mV
    vfit(i) = 100 * (1 - norm (e) / norm (val.y(k2) - mean (val.y(k2))));
  endfor

  ## Qn by ML for a2, and the 1e5 rad/s resonance.
  qml = NaN;
  qml_time = NaN;
  ml_a2 = NaN;
  w5 = struct ("a2_rms", NaN, "bias", NaN (1, 4));
  if (full)
    tic_q = tic;
    Qml = qnml (est.data, nn, "lambda_svf", lam, "tsiv", tsiv,
                "fixed", [1e-15 1e-15 1e-15 NaN], "q0", 1e-1, "lb", 1e-6,
                "ub", 1e4);
    qml_time = toc (tic_q);
    qml = Qml(4, 4);
    thm = run_method ("rsrivc", est.data, nn,
                      [iv(1:4), {"adg", Qml, "tsiv", tsiv, "InterSample", "trapezoid"}], "double");
    ml_a2 = sqrt (mean (((thm(tail, 2) - est.theta(tail, 2))
                         / est.scale(2)) .^ 2));
    e5 = ch3_bandpass_record (1, 0, 3, 1e5);
    thm = run_method ("rsrivc", e5.data, nn, iv, "double");
    err = (thm(tail, :) - e5.theta(tail, :)) ./ e5.scale;
    w5.a2_rms = sqrt (mean (err(:, 2) .^ 2));
    w5.bias = mean (err);
  endif

  ## Figures.
  ch3_plot_panels (fullfile (outdir, "fig_4_4_estimates.png"),
                   {struct("t", t, "series", {{est.theta(:, 2), r(1, 1).thm(:, 2), r(3, 1).thm(:, 2)}},
                           "labels", {{"true", "RLSSVF", "RSRIVC"}},
                           "ylabel", "a_2", "step", 4,
                           "ylim", [0.5 1.5] * est.scale(2),
                           "title", "Simulated band-pass filter: true a_2 and its estimates (cf. Fig. 4.4)"),
                    struct("t", t, "series", {{est.theta(:, 1), r(1, 1).thm(:, 1), r(3, 1).thm(:, 1)}},
                           "labels", {{"true", "RLSSVF", "RSRIVC"}},
                           "ylabel", "a_1", "step", 4,
                           "ylim", [0.8 1.2] * est.scale(1)),
                    struct("t", t, "series", {{est.theta(:, 3), r(1, 1).thm(:, 3), r(3, 1).thm(:, 3)}},
                           "labels", {{"true", "RLSSVF", "RSRIVC"}},
                           "ylabel", "b_0", "step", 4,
                           "ylim", [0.8 1.2] * est.scale(3))});
  letters = "abcdef";
  for m = 1:M
    pan{m} = struct ("t", t, "series", {{r(m, 1).kappa}},
                     "labels", {{cfg{m, 1}}}, "logy", true, "step", 4,
                     "ylabel", "kappa_2(P)",
                     "title", sprintf ("(%s) %s", letters(m), cfg{m, 1}));
  endfor
  ch3_plot_panels (fullfile (outdir, "fig_4_7_kappa.png"), pan([1 2 3 4 5 6]),
                   2);
  kv = t >= Np * Ts & t < (Np + 2000) * Ts;
  ch3_plot_panels (fullfile (outdir, "fig_4_6_validation.png"),
                   {struct("t", t(kv) * 1e3, "series", {{1e3 * val.y(kv), 1e3 * yv(kv, 3)}},
                           "labels", {{"measured (simulated) y", "RSRIVC model output"}},
                           "xlabel", "time (ms)", "ylabel", "y (mV)",
                           "title", "Validation record, part of period 2 (cf. Fig. 4.6)")});
  dev = @(rr, m, i) (rr(m, 2).thm(:, i) - rr(m, 1).thm(:, i)) / est.scale(i);
  ch3_plot_panels (fullfile (outdir, "fig_ch3_single.png"),
                   {struct("t", t, "series", {{r(1, 2).kappa, r(2, 2).kappa, r(6, 2).kappa}},
                           "labels", {{"RLSSVF", "RLSSVF scaled", "PotterSVF scaled"}},
                           "styles", {{"-", "-", ":"}}, "logy", true, "step", 4, "ylabel", "kappa_2(P)",
                           "title", "Single precision, P0 = 1e4 I: kappa_2(P) (gaps: P not positive definite at working precision)"),
                    struct("t", t, "series", {{dev(r, 2, 1), dev(r2, 2, 1), dev(r, 6, 1)}},
                           "labels", {{"RLSSVF scaled, P0 = 1e4 I", "RLSSVF scaled, P0 = 1e4 M_s^2", "PotterSVF scaled, P0 = 1e4 I"}},
                           "step", 4, "ylabel", "(a_1 single - a_1 double) / a_1",
                           "ylim", [-0.03 0.03],
                           "title", "Single minus double precision estimate of a_1")});

  res.cfg = cfg(:, 1);
  res.r = r;
  res.r2 = r2;
  res.scale = est.scale;
  res.ms = ms;
  res.vrmse = vrmse;
  res.vfit = vfit;
  res.qml = qml;
  elapsed = toc (t_all);
  write_table (fullfile (outdir, "ch3_bandpass.md"), cfg(:, 1), r, r2, ms,
               vnames, vrmse, vfit, qml, qml_time, ml_a2, q, w5, est,
               elapsed);

  printf ("ch3 band-pass (secs. 4.1.3, 3.5, single precision), %.1f s in all\n",
          elapsed);
  printf ("  %-17s %10s %10s %8s %8s | single: %7s %9s %9s\n", "method",
          "kappa med", "kappa max", "a2 rms%", "time s", "non-PD", "dev a1%",
          "dev a2%");
  for m = 1:M
    printf ("  %-17s %10.3g %10.3g %8.2f %8.2f | %7d %9.3f %9.3f\n",
            cfg{m, 1}, median (r(m, 1).kappa(tail)), max (r(m, 1).kappa),
            100 * r(m, 1).a2_rms, r(m, 1).time, r(m, 2).nonpd,
            100 * r(m, 2).dev(1), 100 * r(m, 2).dev(2));
  endfor
  printf ("  single, P0 = 1e4 M_s^2: non-PD / dev a1 %%: %s\n",
          sprintf ("%d / %.3f  ", [[r2(:, 2).nonpd];
                                   100 * arrayfun(@(z) z.dev(1), r2(:, 2))']));
  printf ("  validation RMSE (mV) / fit (%%): true %.4f / %.2f, RLSSVF %.4f / %.2f, RSRIVC %.4f / %.2f\n",
          [vrmse; vfit]);
endfunction

function s = list_or_none (c)
  if (isempty (c))
    s = "none";
  else
    s = strjoin (c, ", ");
  endif
endfunction

## Single precision reproduces the thesis' recursions (sec. 3.5), without
## the covariance protection (on by default; it leaves every double run
## here untouched, but would repair the float P where it loses
## definiteness, which is what this demo shows).
function [thm, info] = run_method (method, data, nn, opts, prec)
  if (strcmp (prec, "single"))
    opts = [opts, {"covariance_guard", false}];
  endif
  if (strcmp (method, "rlssvf"))
    [thm, ~, ~, info] = rlssvf (data, nn, opts{:}, "precision", prec);
  else
    [thm, ~, ~, info] = rsrivc (data, nn, opts{:}, "precision", prec);
    thm = thm(:, [3 4 1 2]);                      # [b0 b1 f1 f2] -> [a b]
  endif
endfunction

function write_table (file, names, r, r2, ms, vnames, vrmse, vfit, qml,
                      qml_time, ml_a2, q, w5, est, elapsed)
  M = numel (names);
  fid = fopen (file, "w");
  fprintf (fid, "## Band-pass filter: conditioning, scaling, square-root ");
  fprintf (fid, "filtering, single precision (thesis secs. 4.1.2-4.1.3, ");
  fprintf (fid, "3.5)\n\n");
  fprintf (fid, "Simulated stand-in for the benchmark of sec. 4.1 (measured ");
  fprintf (fid, "data not available): (p^2 + a1 p + a2(t)) x = (b0 p + b1) ");
  fprintf (fid, "u, a1 = b0 = 1.5e4, b1 = 0, a2 = 2.5e9 (1 + 0.3 sin(2 pi ");
  fprintf (fid, "t/0.1 s)), fs = 156250 Hz, 3 periods of 15640 samples, ");
  fprintf (fid, "multisine 10 Hz-16 kHz of 70 mV RMS, ");
  fprintf (fid, "SNR 65 dB. lambda_svf = 1e7 rad/s, Qn = diag(1e-15, %g, 1e-15, 1e-15), ",
           q);
  fprintf (fid, "t_s,iv = 20 ms, theta0 = 0, P0 = 1e4 I. M_s (eq. 3.54) from ");
  fprintf (fid, "the ");
  fprintf (fid, "training record: [%s] for [a1 a2 b0 b1]. %.1f s in all.\n\n",
           strtrim (sprintf ("%.3g ", ms)), elapsed);

  fprintf (fid, "### Fig. 4.7: kappa_2(P) (double precision) and tracking\n\n");
  fprintf (fid, "Medians over periods 2-3; a2 error relative to w0^2, bias ");
  fprintf (fid, "of a1, b0 relative to their values, of b1 relative to b0 ");
  fprintf (fid, "w0. The thesis shows kappa_2 only as figures, for the ");
  fprintf (fid, "measured data.\n\n");
  fprintf (fid, "| method | median kappa_2(P) | max kappa_2(P) | RMS error ");
  fprintf (fid, "of a2 | bias a1 / b0 / b1 | time (s) |\n");
  fprintf (fid, "|---|---|---|---|---|---|\n");
  for m = 1:M
    rr = r(m, 1);
    tail = numel (rr.kappa) / 3 + 1:numel (rr.kappa);
    fprintf (fid, "| %s | %.3g | %.3g | %.2f %% | %+.2f / %+.2f / %+.2f %% | %.2f |\n",
             names{m}, median (rr.kappa(tail)), max (rr.kappa),
             100 * rr.a2_rms, 100 * rr.bias([1 3 4]), rr.time);
  endfor
  fprintf (fid, "\nScaling lowers the median kappa_2 of RLSSVF by a factor %.2g and ",
           median (r(1, 1).kappa(tail)) / median (r(2, 1).kappa(tail)));
  fprintf (fid, "that of RSRIVC by %.2g, with the same estimates (largest ",
           median (r(3, 1).kappa(tail)) / median (r(4, 1).kappa(tail)));
  fprintf (fid, "difference plain vs scaled, relative: RLSSVF %.1e, RSRIVC %.1e). ",
           max (max (abs (r(2, 1).thm - r(1, 1).thm) ./ est.scale)),
           max (max (abs (r(4, 1).thm - r(3, 1).thm) ./ est.scale)));
  fprintf (fid, "PotterSVF propagates S with kappa_2(S) = sqrt(kappa_2(P)) ");
  fprintf (fid, "(median %.3g unscaled, %.3g scaled); the values shown are ",
           sqrt (median (r(5, 1).kappa(tail))),
           sqrt (median (r(6, 1).kappa(tail))));
  fprintf (fid, "kappa_2(S S^T). As in the thesis, scaling gives smaller ");
  fprintf (fid, "numbers than the square root alone. The peak at the start ");
  fprintf (fid, "is P0 = 1e4 I seen in scaled coordinates (M_s^-1 P0 ");
  fprintf (fid, "M_s^-1).\n\n");
  if (! isnan (w5.a2_rms))
    fprintf (fid, "Discretisation: the same record with the resonance at 1e5 ");
    fprintf (fid, "rad/s ");
    fprintf (fid, "(w0 Ts = 0.64) gives RSRIVC an RMS a2 error of %.1f %% and biases ",
             100 * w5.a2_rms);
    fprintf (fid, "a1 / b0 of %+.1f / %+.1f %% (5e4 rad/s: %.1f %%, %+.1f / %+.1f %%): ",
             100 * w5.bias([1 3]), 100 * r(3, 1).a2_rms,
             100 * r(3, 1).bias([1 3]));
    fprintf (fid, "the trapezoidal rule for y warps frequencies by tan(w ");
    fprintf (fid, "Ts/2)/(w Ts/2) - 1 (3.5 %% at 0.64, 0.9 %% at 0.32).\n\n");
  endif
  if (! isnan (qml))
    fprintf (fid, "Qn by ML (qnml, RSRIVC, a2 free, the others fixed at ");
    fprintf (fid, "1e-15): ");
    fprintf (fid, "q = %.3g (%.1f s); RMS a2 error of RSRIVC with it %.2f %% ",
             qml, qml_time, 100 * ml_a2);
    fprintf (fid, "against %.2f %% with the thesis' 0.5.\n\n", 100 * r(3, 1).a2_rms);
  endif

  fprintf (fid, "### Table 4.1: validation (RMSE_y eq. 4.4 over period 2 ");
  fprintf (fid, "minus 500 samples, fit eq. 4.5)\n\n");
  fprintf (fid, "| model | RMSE_y (mV) | fit (%%) | thesis, measured data: ");
  fprintf (fid, "RMSE_y (mV) / fit (%%) |\n");
  fprintf (fid, "|---|---|---|---|\n");
  th = {"-", "0.6909 / 95.7", "0.3781 / 97.6"};
  for i = 1:numel (vnames)
    fprintf (fid, "| %s | %.4f | %.2f | %s |\n", vnames{i}, vrmse(i), vfit(i),
             th{i});
  endfor
  fprintf (fid, "| [Lataire et al., 2015] | - | - | 0.1156 / not reported |\n");
  fprintf (fid, "\nThe thesis' numbers are for the measured benchmark (with ");
  fprintf (fid, "its nonlinear effects and a model structure that is only an ");
  fprintf (fid, "approximation); ours are for a simulation in the model ");
  fprintf (fid, "class, so they are not comparable in value: the 'true ");
  fprintf (fid, "parameters' row is the noise floor, and the distance of the ");
  fprintf (fid, "estimated models to it is the estimation (mostly ");
  fprintf (fid, "discretisation) error. ");
  fprintf (fid, "RSRIVC %s RLSSVF here, as in the thesis.\n\n",
           ch2_ifelse_str (vrmse(3) < vrmse(2), "does better than",
                           "does not do better than"));

  fprintf (fid, "### Single precision\n\n");
  fprintf (fid, "Each method run again with 'precision', 'single' (the whole ");
  fprintf (fid, "recursion in float), from P0 = 1e4 I (the thesis' default) ");
  fprintf (fid, "and from P0 = 1e4 M_s^2, i.e. P_s(t_0) = 1e4 I in scaled ");
  fprintf (fid, "coordinates. ");
  fprintf (fid, "Non-PD: samples after t_s,iv (of %d) where P (S S^T for Potter; ",
           sum (est.t >= 0.02));
  fprintf (fid, "for RSRIVC, whose P is not symmetric, singular) is not ");
  fprintf (fid, "positive definite at working precision (kappa_2 reported as ");
  fprintf (fid, "Inf). Deviation: max |theta_single - theta_double| relative ");
  fprintf (fid, "to each parameter's size (b1: to b0 w0), over periods 2-3; ");
  fprintf (fid, "in brackets over t >= t_s,iv and over period 3.\n\n");
  fprintf (fid, "| method | P0 | non-PD | median kappa_2 in float (double) | ");
  fprintf (fid, "dev. a1 | dev. a2 | dev. b0 | dev. b1 |\n");
  fprintf (fid, "|---|---|---|---|---|---|---|---|\n");
  tail = numel (r(1, 1).kappa) / 3 + 1:numel (r(1, 1).kappa);
  P0name = {"1e4 I", "1e4 M_s^2"};
  for v = 1:2
    rv = ch2_ifelse_str (v == 1, r, r2);
    for m = 1:M
      s = rv(m, 2);
      fprintf (fid, "| %s | %s | %d | %.3g (%.3g) |", names{m}, P0name{v},
               s.nonpd, median (s.kappa(tail)), median (rv(m, 1).kappa(tail)));
      fprintf (fid, " %.3f %% (%.2f, %.3f) |", 100 * [s.dev; s.dev_after; s.dev_p3]);
      fprintf (fid, "\n");
    endfor
  endfor
  tol = 0.01;
  fprintf (fid, "\nStated tolerance: after t_s,iv P stays positive definite ");
  fprintf (fid, "and ");
  fprintf (fid, "a1, a2, b0 stay within %g %% of the double-precision estimates ",
           100 * tol);
  fprintf (fid, "(a float error well below the double-precision estimator's ");
  fprintf (fid, "own ");
  fprintf (fid, "error here, %.1f %% RMS in a2 and %+.1f %% bias in a1). ",
           100 * r(1, 1).a2_rms, 100 * r(1, 1).bias(1));
  for v = 1:2
    rv = ch2_ifelse_str (v == 1, r, r2);
    ok_all = arrayfun (@(m) rv(m, 2).nonpd == 0 ...
                            && all (rv(m, 2).dev_after(1:3) < tol), 1:M);
    ok_tail = arrayfun (@(m) rv(m, 2).nonpd == 0 ...
                             && all (rv(m, 2).dev(1:3) < tol), 1:M);
    fprintf (fid, "With P0 = %s it is met from t_s,iv on by: %s; over periods ",
             P0name{v}, list_or_none (names(ok_all)));
    fprintf (fid, "2-3 only by: %s; never by: %s. ",
             list_or_none (names(ok_tail & ! ok_all)),
             list_or_none (names(! ok_tail)));
  endfor
  fprintf (fid, "\n\nWhat single precision does here. (1) Without scaling ");
  fprintf (fid, "kappa_2(P) (about %.1g) exceeds 1/eps_single = 1.7e7: P cannot ",
           median (r(1, 1).kappa(tail)));
  fprintf (fid, "be resolved in float and is not positive definite at ");
  fprintf (fid, "working ");
  fprintf (fid, "precision in %.0f %% of the samples (a Cholesky or PD check on ",
           100 * r(1, 2).nonpd / sum (est.t >= 0.02));
  fprintf (fid, "a microcontroller fails). The ill-conditioning is that of ");
  fprintf (fid, "the parameter sizes (1e4 to 1e9), which the diagonal M_s ");
  fprintf (fid, "removes ");
  fprintf (fid, "(kappa_2 about %.3g) and the square root halves in the exponent. ",
           median (r(2, 1).kappa(tail)));
  fprintf (fid, "(2) From P0 = 1e4 I the standard (non-square-root) update, ");
  fprintf (fid, "scaled or not, loses accuracy at the start: 1 + phi^T P phi ");
  fprintf (fid, "reaches %.1g in the first samples, the update P - P phi phi^T ",
           r(1, 1).innov0);
  fprintf (fid, "P / (1 + phi^T P phi) cancels in float, and the error left ");
  fprintf (fid, "in the nearly constant a1, ");
  fprintf (fid, "b0 (Qn = 1e-15) decays only as information accumulates (%.1f %% ",
           100 * r(2, 2).dev_after(1));
  fprintf (fid, "at 20 ms, %.2f %% over periods 2-3, %.2f %% over period 3 for ",
           100 * r(2, 2).dev(1), 100 * r(2, 2).dev_p3(1));
  fprintf (fid, "scaled RLSSVF). Scaling does not change this, Potter's ");
  fprintf (fid, "square ");
  fprintf (fid, "root does (%.2f %% from 20 ms on, scaled). Starting the scaled ",
           100 * r(6, 2).dev_after(1));
  fprintf (fid, "recursion from P_s(t_0) = 1e4 I (P0 = 1e4 M_s^2) removes ");
  fprintf (fid, "the ");
  fprintf (fid, "cancellation (%.3f %% for scaled RLSSVF) with the same double-",
           100 * r2(2, 2).dev_after(1));
  fprintf (fid, "precision tracking (RMS a2 error %.2f %% vs %.2f %%). ",
           100 * r2(2, 1).a2_rms, 100 * r(2, 1).a2_rms);
  fprintf (fid, "(3) The a2 deviation of about 0.2 %% that remains in every ");
  fprintf (fid, "RLSSVF form, standard or square root, comes from the float ");
  fprintf (fid, "regression (the SVF at lambda_svf Ts = 64), not from the ");
  fprintf (fid, "update: RSRIVC, whose IV stage filters with the adaptive ");
  fprintf (fid, "prefilter, stays within %.3f %%. No form ",
           100 * r2(4, 2).dev(2));
  fprintf (fid, "diverged. In single precision, therefore: ");
  fprintf (fid, "float RLSSVF without scaling loses positive definiteness of ");
  fprintf (fid, "P (and, from P0 = 1e4 I, accuracy at start-up); scaled ");
  fprintf (fid, "Potter keeps tracking within 1 %% of double precision ");
  fprintf (fid, "throughout, and scaled RLSSVF does so when started from ");
  fprintf (fid, "P_s(t_0) = p I.\n");
  fclose (fid);
endfunction
