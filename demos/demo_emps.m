## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn {} {@var{R} =} demo_emps (@var{outdir}, @var{reduced})
## Closing the loop on measured data: the EMPS (electro-mechanical
## positioning system, nonlinearbenchmark.org; ../shared/data/emps).
##
## The input is the motor force u = gtau * vir (N), the output the motor
## position qm (m), sampled at 1 kHz; DATA_EMPS.mat estimates,
## DATA_EMPS_PULSES.mat validates. The start is a linear model of a mass
## with viscous friction, m q'' + c q' = u, i.e. the idctm 1/m / (p^2 +
## c/m p) with the integrator structural (the coefficient of p^0 fixed at
## zero), nominal m = 100 kg, c = 200 N s/m; @code{residtrace} re-estimates
## it and looks for what it lacks.
##
## @strong{Simulation.} The axis has an integrator and runs in closed loop,
## so an open-loop simulation of force to position drifts without bound
## for any model error. Every simulation here (estimation and validation,
## before and after) runs in the loop instead, with the model's own
## position fed back through the known controller of the files, vir =
## kv (kp (qg - qm) - dqm/dt) with dqm/dt the backward difference (it
## reproduces the recorded vir to 3 % RMS), and the reference qg as the
## external signal. In the validation record the force pulses enter the
## controller's output, vir = ... + pulses_N (a regression of the
## recorded vir gives the coefficient 1.06 for them and the same 4-6 %
## excess for kp kv and kv), so they are part of the external signal r1
## = gtau (kv kp qg + pulses_N). The RMSE is that of the position.
##
## @strong{Cross-check.} An inverse-dynamic least-squares fit, independent
## of residtrace: u = m a + c v + Fc sign(v) + f0 with v, a the zero-phase
## filtered derivatives of qm (fourth-order Butterworth-like smoothing at
## 20 Hz, central differences) on the estimation record.
##
## Writes to @var{outdir} (default "results"): emps.md (the before/after
## table of @code{residtrace_table} and the cross-check),
## fig_emps_sim.png (measured and simulated position on the validation
## record, and the errors), fig_emps_resid.png (residual autocorrelation
## and cross-correlation with the force, before and after, 99 % bounds),
## fig_emps_segments.png (mass and viscous coefficient estimated on
## segments of the estimation record, before and after the effects were
## added). @var{reduced} (default false): the first 6 s of each record and
## a single pass, for the test suite.
## @end deftypefn

function R = demo_emps (outdir = "results", reduced = false)
  demo_prepare (outdir);
  [root, why] = ctid_data_dir ("emps");
  if (isempty (root))
    error ("demo_emps:noData", "demo_emps: %s", why);
  endif
  s = load (fullfile (root, "DATA_EMPS.mat"));
  p = load (fullfile (root, "DATA_EMPS_PULSES.mat"));
  Ts = s.t(2) - s.t(1);
  u = s.gtau * s.vir; y = s.qm;
  uv = p.gtau * p.vir; yv = p.qm;
  r1 = s.gtau * s.kv * s.kp * s.qg;
  r1v = p.gtau * (p.kv * p.kp * p.qg + p.pulses_N);
  iterate = 3;
  if (reduced)
    n = round (6 / Ts);
    u = u(1:n); y = y(1:n); r1 = r1(1:n);
    uv = uv(1:n); yv = yv(1:n); r1v = r1v(1:n);
    iterate = 1;
  endif
  C = struct ("num", s.gtau * s.kv * [s.kp + 1 / Ts, -1 / Ts], "den", 1);
  M0 = idctm (1 / 100, [1 200 / 100 0]);
  t_run = tic ();
  R = residtrace (iddata (y, u, Ts), M0, "validation", iddata (yv, uv, Ts),
                  "controller", C, "r1", r1, "r1v", r1v, "lambda_v", 200,
                  "substeps", 2, "iterate", iterate);
  elapsed = toc (t_run);
  idim = inverse_dynamics (u, y, Ts);

  plot_sim (fullfile (outdir, "fig_emps_sim.png"), Ts, R.sim);
  plot_corr (fullfile (outdir, "fig_emps_resid.png"), R, "force");
  plot_segments (fullfile (outdir, "fig_emps_segments.png"), R, Ts);
  write_md (fullfile (outdir, "emps.md"), R, idim, elapsed, reduced);
  printf ("EMPS: %s; validation RMSE %.3g -> %.3g m (final %.3g m)\n",
          strjoin (R.effects, ", "), R.rmse_before, R.rmse_after,
          R.rmse_final);
endfunction

## u = m a + c v + Fc sign(v) + f0 by least squares, v and a from qm by
## zero-phase smoothing and central differences.
function th = inverse_dynamics (u, q, Ts)
  wc = 2 * pi * 20;                       # 20 Hz, applied forward and back
  F = [1 2.6131 3.4142 2.6131 1] .* wc .^ (0:4);
  qs = smooth_zero_phase (q, F, Ts);
  v = [0; (qs(3:end) - qs(1:end-2)) / (2 * Ts); 0];
  acc = [0; (qs(3:end) - 2 * qs(2:end-1) + qs(1:end-2)) / Ts ^ 2; 0];
  k = 50:numel (q) - 50;
  X = [acc(k), v(k), sign(v(k)), ones(numel (k), 1)];
  th = X \ u(k);
endfunction

function y = smooth_zero_phase (x, F, Ts)
  G = idctm (F(end), F);
  y = simc (G, x, Ts, "InterSample", "foh");
  y = flipud (simc (G, flipud (y), Ts, "InterSample", "foh"));
endfunction

function setup_figure ()
  warning ("off", "Octave:gnuplot-graphics");
  graphics_toolkit ("gnuplot");
endfunction

function plot_sim (file, Ts, S)
  setup_figure ();
  f = figure ("visible", "off", "position", [0 0 900 700]);
  yv = S.y; yb = S.refit; ya = S.final;
  t = (0:numel (yv) - 1)' * Ts;
  subplot (2, 1, 1);
  plot (t, yv, "k", t, yb, "b", t, ya, "r");
  legend ("measured q_m", "linear model", "with the effects found",
          "location", "northeast");
  ylabel ("position (m)");
  title ("EMPS validation record (with force pulses), closed-loop simulation");
  subplot (2, 1, 2);
  plot (t, yv - yb, "b", t, yv - ya, "r");
  legend ("linear model", "with the effects found");
  ylabel ("error (m)"); xlabel ("time (s)");
  print (f, file, "-dpng");
  close (f);
endfunction

function plot_corr (file, R, uname)
  setup_figure ();
  f = figure ("visible", "off", "position", [0 0 900 700]);
  T = {R.tests_before, R.tests_after};
  names = {"before (re-estimated linear model)", "after"};
  for i = 1:2
    w = T{i};
    if (! w.testable)
      continue;
    endif
    subplot (2, 2, i);
    m = w.maxlag;
    stem (0:m, w.autocorr);
    hold on;
    plot ([0 m], w.bound * [1 1], "r--", [0 m], -w.bound * [1 1], "r--");
    hold off;
    title (["autocorrelation, " names{i}]);
    subplot (2, 2, i + 2);
    plot (-m:m, w.xcorr(:, 1), "o-");
    hold on;
    plot ([-m m], w.bound * [1 1], "r--", [-m m], -w.bound * [1 1], "r--");
    hold off;
    title (["cross-correlation with the " uname " (prewhitened)"]);
    xlabel ("lag (samples)");
  endfor
  print (f, file, "-dpng");
  close (f);
endfunction

## Mass 1/b0 and viscous coefficient f1/b0 of the segment fits behind the
## drift test, in the first pass and in the last one.
function plot_segments (file, R, Ts)
  setup_figure ();
  f = figure ("visible", "off", "position", [0 0 900 600]);
  passes = [1, numel(R.history)];
  labels = {"linear model", "with the effects found"};
  style = {"bo-", "rs-"};
  shown = {};
  for i = 1:2
    h = R.history(passes(i));
    k = find (strcmp ({h.ranking.effect}, "drift"), 1);
    if (isempty (k) || ! isfield (h.ranking(k).evidence, "theta_segments"))
      continue;
    endif
    th = h.ranking(k).evidence.theta_segments;
    b0 = th(:, 2); f1 = th(:, 1);
    subplot (2, 1, 1); hold on;
    plot (1:rows (th), 1 ./ b0, style{i});
    subplot (2, 1, 2); hold on;
    plot (1:rows (th), f1 ./ b0, style{i});
    shown{end+1} = labels{i};
  endfor
  subplot (2, 1, 1); ylabel ("mass 1/b_0 (kg)");
  if (! isempty (shown))
    legend (shown);
  endif
  title ("SRIVC on segments of the estimation record");
  subplot (2, 1, 2); ylabel ("viscous f_1/b_0 (N s/m)"); xlabel ("segment");
  print (f, file, "-dpng");
  close (f);
endfunction

function write_md (file, R, idim, elapsed, reduced)
  fid = fopen (file, "w");
  fprintf (fid, "# EMPS: tracing the residual of a linear mass model\n\n");
  if (reduced)
    fprintf (fid, "Reduced run (first 6 s of each record, one pass).\n\n");
  endif
  fprintf (fid, ["Force gtau*vir to position qm, 1 kHz; estimation on ", ...
                 "DATA_EMPS.mat, validation on DATA_EMPS_PULSES.mat; all ", ...
                 "simulations in closed loop with the files' controller ", ...
                 "(see demos/demo_emps.m). %.0f s.\n\n"], elapsed);
  fprintf (fid, "%s\n", R.table);
  fprintf (fid, ["Independent cross-check, inverse-dynamic least squares ", ...
                 "on the estimation record (u = m a + c v + Fc sign(v) + ", ...
                 "f0, derivatives of qm smoothed at 20 Hz):\n\n"]);
  fprintf (fid, "| m (kg) | c (N s/m) | Fc (N) | f0 (N) |\n");
  fprintf (fid, "|---|---|---|---|\n");
  fprintf (fid, "| %.4g | %.4g | %.4g | %.4g |\n", idim);
  fclose (fid);
endfunction
