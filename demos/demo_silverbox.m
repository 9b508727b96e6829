## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn {} {@var{R} =} demo_silverbox (@var{outdir}, @var{reduced})
## Closing the loop on measured data: the Silverbox (an electronic circuit
## with a resonance, nonlinearbenchmark.org; ../shared/data/silverbox,
## SNLS80mV.mat, input V1, output V2, fs = 1e7/2^14 Hz).
##
## @strong{Tracking.} RSRIVC (Kalman-filter adaptation) tracks the
## resonance of a second-order model [nb nf nk] = [1 2 0] along the first
## 40 000 samples, where the filtered-noise input grows in amplitude. The
## data are rescaled in time by w0 = 450 rad/s (time unit 1/w0, so that
## the parameters are of order one and the recursion well conditioned, as
## the thesis' chapter 3 scaling; unscaled, f2 is about 2e5 and RSRIVC's
## estimates leave the stable region at every step). Started from the
## SRIVC estimate of the same samples, P0 = 1e-2 I (scaled units), IV
## from the first sample, Qn by maximum likelihood (@code{qnml}, thesis
## sec. 3.3, between 1e-10 and 1e-2). The figure shows the natural
## frequency w0 sqrt(f2(t)) and the damping against the input's RMS.
##
## @strong{Tracing.} The LTI model is SRIVC [1 2 0] on the same 40 000
## samples; @code{residtrace} validates on samples 40 001 - 60 000 (the
## first odd multisines, constant amplitude) and looks for what the model
## lacks, adding effects until nothing significant is left (at most 4).
##
## Writes to @var{outdir} (default "results"): silverbox.md (tracking
## summary and the before/after table), fig_silverbox_track.png,
## fig_silverbox_sim.png (measured vs simulated, an excerpt of the
## validation record, and the errors), fig_silverbox_resid.png (residual
## correlations before and after with 99 % bounds). @var{reduced} (default
## false): 8 000 estimation and 4 000 validation samples, a single pass,
## for the test suite.
## @end deftypefn

function R = demo_silverbox (outdir = "results", reduced = false)
  demo_prepare (outdir);
  [root, why] = ctid_data_dir ("silverbox");
  if (isempty (root))
    error ("demo_silverbox:noData", "demo_silverbox: %s", why);
  endif
  s = load (fullfile (root, "SNLS80mV.mat"));
  u = double (s.V1(:)); y = double (s.V2(:));
  Ts = 2 ^ 14 / 1e7;
  Ne = 40000; iv = 40001:60000; iterate = 4;
  if (reduced)
    Ne = 8000; iv = 40001:44000; iterate = 1;
  endif

  ## tracking the resonance along the growing input
  w0 = 450;
  ds = iddata (y(1:Ne), u(1:Ne), Ts * w0, "InterSample", "zoh");
  Ms = srivc (ds, [1 2 0]);
  th0 = [Ms.B, Ms.F(2:3)];
  ropts = {"A", Ms.F, "th0", th0, "P0", 1e-2 * eye(3), "tsiv", 0};
  [Qn, ~, qinfo] = qnml (ds, [1 2 0], "method", "rsrivc", ropts{:},
                         "q0", 1e-6, "lb", 1e-10, "ub", 1e-2);
  [thm, ~, ~, info] = rsrivc (ds, [1 2 0], ropts{:}, "adm", "kf",
                              "adg", Qn);
  wn = w0 * sqrt (max (thm(:, 3), 0));
  zeta = thm(:, 2) ./ (2 * sqrt (max (thm(:, 3), eps)));
  urms = sqrt (movmean_ (u(1:Ne) .^ 2, 2001));

  ## the LTI fit and what explains its residual
  d = iddata (y(1:Ne), u(1:Ne), Ts, "InterSample", "zoh");
  dv = iddata (y(iv), u(iv), Ts, "InterSample", "zoh");
  M = srivc (d, [1 2 0]);
  t_run = tic ();
  R = residtrace (d, M, "validation", dv, "iterate", iterate);
  elapsed = toc (t_run);

  plot_track (fullfile (outdir, "fig_silverbox_track.png"), Ts, wn, zeta,
              urms);
  plot_sim (fullfile (outdir, "fig_silverbox_sim.png"), Ts, R.sim);
  plot_corr (fullfile (outdir, "fig_silverbox_resid.png"), R);
  k = round ([0.05 0.25 0.5 0.75 0.95] * Ne);
  write_md (fullfile (outdir, "silverbox.md"), R, reduced, elapsed, Ne,
            wn(k), zeta(k), urms(k), info, diag (Qn), qinfo);
  printf ("Silverbox: resonance %.1f -> %.1f rad/s as the input RMS grows ",
          wn(k(1)), wn(k(end)));
  printf ("%.3g -> %.3g; residtrace: %s; RMSE %.3g -> %.3g (final %.3g)\n",
          urms(k(1)), urms(k(end)), strjoin (R.effects, ", "), R.rmse_before,
          R.rmse_after, R.rmse_final);
endfunction

function m = movmean_ (x, L)
  c = cumsum ([0; x(:)]);
  n = numel (x);
  h = floor (L / 2);
  i0 = max ((1:n)' - h, 1);
  i1 = min ((1:n)' + h, n);
  m = (c(i1 + 1) - c(i0)) ./ (i1 - i0 + 1);
endfunction

function setup_figure ()
  warning ("off", "Octave:gnuplot-graphics");
  graphics_toolkit ("gnuplot");
endfunction

function plot_track (file, Ts, wn, zeta, urms)
  setup_figure ();
  f = figure ("visible", "off", "position", [0 0 900 800]);
  t = (0:numel (wn) - 1)' * Ts;
  k = 1:10:numel (t);
  subplot (3, 1, 1);
  plot (t(k), wn(k), "r");
  ylabel ("w_n (rad/s)");
  title (["Silverbox: RSRIVC-KF tracking of the resonance ", ...
          "(first 40 000 samples)"]);
  subplot (3, 1, 2);
  plot (t(k), zeta(k), "r");
  ylabel ("damping ratio");
  subplot (3, 1, 3);
  plot (t(k), urms(k), "k");
  ylabel ("input RMS (V)"); xlabel ("time (s)");
  print (f, file, "-dpng");
  close (f);
endfunction

function plot_sim (file, Ts, S)
  setup_figure ();
  f = figure ("visible", "off", "position", [0 0 900 700]);
  n = min (numel (S.y), 1500);
  t = (0:n-1)' * Ts;
  subplot (2, 1, 1);
  plot (t, S.y(1:n), "k", t, S.refit(1:n), "b", t, S.final(1:n), "r");
  legend ("measured V2", "LTI model", "with the effects found");
  ylabel ("output (V)");
  title ("Silverbox validation record (excerpt), simulated output");
  subplot (2, 1, 2);
  t = (0:numel (S.y) - 1)' * Ts;
  plot (t, S.y - S.refit, "b", t, S.y - S.final, "r");
  legend ("LTI model", "with the effects found");
  ylabel ("error (V)"); xlabel ("time (s)");
  print (f, file, "-dpng");
  close (f);
endfunction

function plot_corr (file, R)
  setup_figure ();
  f = figure ("visible", "off", "position", [0 0 900 700]);
  T = {R.tests_before, R.tests_after};
  names = {"before (LTI)", "after"};
  for i = 1:2
    w = T{i};
    if (! w.testable)
      continue;
    endif
    m = w.maxlag;
    subplot (2, 2, i);
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
    title ("cross-correlation with the input (prewhitened)");
    xlabel ("lag (samples)");
  endfor
  print (f, file, "-dpng");
  close (f);
endfunction

function write_md (file, R, reduced, elapsed, Ne, wn, zeta, urms, info, q,
                   qinfo)
  fid = fopen (file, "w");
  fprintf (fid, ["# Silverbox: tracking the resonance, tracing the ", ...
                 "residual\n\n"]);
  if (reduced)
    fprintf (fid, "Reduced run (8 000 + 4 000 samples, one pass).\n\n");
  endif
  fprintf (fid, ["RSRIVC-KF, [1 2 0], time scaled by 450 rad/s, over ", ...
                 "the first %d samples; Qn = diag(%s) by qnml (%d cost ", ...
                 "evaluations); %d estimates refused by the stability ", ...
                 "test. Input RMS over 2001 samples around each ", ...
                 "instant:\n\n"], Ne, sprintf ("%.3g ", q)(1:end-1),
           qinfo.evaluations, info.stability_rejections);
  fprintf (fid, "| at | input RMS (V) | w_n (rad/s) | damping |\n");
  fprintf (fid, "|---|---|---|---|\n");
  at = {"5 %", "25 %", "50 %", "75 %", "95 %"};
  for i = 1:numel (at)
    fprintf (fid, "| %s of the record | %.4f | %.1f | %.4f |\n", at{i},
             urms(i), wn(i), zeta(i));
  endfor
  fprintf (fid, ["\nresidtrace (estimation: the %d samples above; ", ...
                 "validation: the odd multisines that follow), %.0f s:\n\n"],
           Ne, elapsed);
  fprintf (fid, "%s\n", R.table);
  fclose (fid);
endfunction
