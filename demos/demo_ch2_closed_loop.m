## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn {} {} demo_ch2_closed_loop (@var{outdir}, @var{nruns})
## Thesis section 2.4.6: closed-loop recursive IV methods on the LTV plant
## of section 2.3.6,
##
##   (p^2 + a1(t) p + a2(t)) x = b0 u,   a1 = 5 + 40 t / 1000 (linear),
##   a2 = 160 - 90 cos (2 pi t / 1000),  b0 = 200,   y = x + e,
##
## in the loop u = r1 + C(q^-1) (r2 - y) with r2 = 0 and the PID of eq.
## (2.55) read as the backward-Euler discretisation of the continuous PID,
## C = kp + ki Ts / (1 - q^-1) + (kd / Ts) (1 - q^-1), kp = 1.79,
## ki = 13.8, kd = 5.83e-2 (implementation notes, item 3: read literally,
## ki per sample destabilises the loop). Ts = 0.01 s over 1000 s, noise
## variance 0.1, lambda_svf = 16 rad/s, Qn = diag (1e-5, 1e-4, 1e-10) for
## (a1, a2, b0), theta0 = 0, P0 = 1e4 I, tsiv = 10 s and, for the IV
## methods, M_theta = (0.04762 + 0.04762 q^-1) / (1 - 0.9048 q^-1).
##
## Methods: RLSSVF on noise-free and on noisy data, CLRIVSVF, CLRSRIVC with
## the unit-static-gain adaptive prefilter (the toolbox default) and, as
## the measured justification of that choice, CLRSRIVC with the monic
## prefilter 1/A(p) of eq. (2.19).
##
## Input and noise: r1 is the maximum-length PRBS of a 15-bit register,
## levels +-1, each chip held 10 samples (prbs (15, 10)), truncated to the
## N = 100001 samples, the same in every run. The noise enters the loop,
## so every run is simulated anew with simc in closed loop: run s uses
## e = sqrt (0.1) * randn (N, 1) drawn after randn ("state", s), and the
## measured y = x + e is fed back. The noise-free case is the same loop
## with e = 0.
##
## Over @var{nruns} runs (default 100) it reports the relative errors
## (eq. 2.33), averaged over the last 200 s and the last 500 s and over
## the runs, and checks the thesis' claims: RLSSVF fails on noisy data,
## CLRIVSVF and CLRSRIVC track, CLRSRIVC is the best at the end.
##
## Writes to @var{outdir} (default "results"): fig_2_17_rlssvf.png,
## fig_2_18_cliv.png, fig_2_19_rlssvf_relerr.png, fig_2_20_cliv_relerr.png
## and ch2_closed_loop.md.
## @end deftypefn

function demo_ch2_closed_loop (outdir = "results", nruns = 100)
  here = demo_prepare (outdir);
  t_all = tic;

  Ts = 0.01;
  t = (0:Ts:1000)';
  N = numel (t);
  theta = [5 + 40 * t / 1000, 160 - 90 * cos(2 * pi * t / 1000), ...
           200 * ones(N, 1)];                     # [a1 a2 b0]
  r1 = prbs (15, 10);
  r1 = r1(1:N);
  r2 = zeros (N, 1);
  C = struct ("kp", 1.79, "ki", 13.8, "kd", 0.0583);
  sigma2 = 0.1;
  loop = {"controller", C, "r2", r2};

  tsiv = 10;
  Qn = diag ([1e-5 1e-4 1e-10]);                  # (a1, a2, b0)
  mtheta = struct ("num", [0.04762 0.04762], "den", [1 -0.9048]);
  cl = {"controller", C, "r1", r1, "r2", r2};
  cfg.svf = {"lambda_svf", 16, "adm", "kf", "adg", Qn};
  cfg.riv = [cfg.svf, cl, {"tsiv", tsiv, "mtheta", mtheta}];
  cfg.sriv = [{"lambda_svf", 16, "adm", "kf", "adg", Qn([3 1 2], [3 1 2])}, ...
              cl, {"tsiv", tsiv, "mtheta", mtheta}];  # order [b0 f1 f2]
  names = {"RLSSVF", "CLRIVSVF", "CLRSRIVC", "CLRSRIVC monic"};
  M = numel (names);
  main = 1:3;
  win = {t >= t(end) - 200, t >= t(end) - 500};
  winname = {"last 200 s", "last 500 s"};
  yard = [30.2 7.3 11.1; 5.8 8.0 1.4; 4.8 6.1 1.5; NaN NaN NaN];

  ## Noise-free loop and RLSSVF on it (Fig. 2.17a).
  [~, x0, u0] = simc (theta, [2 1 0], r1, Ts, loop{:});
  thm0 = estimate (1, iddata (x0, u0, Ts, "InterSample", "zoh"), cfg);
  rel0 = abs ((theta - thm0) ./ theta) * 100;
  E0 = [mean(rel0(win{1}, :)); mean(rel0(win{2}, :))];
  ## Is the noise-free error lag? The same with Qn(a2) ten times larger.
  cfgq = cfg;
  cfgq.svf{end} = diag ([1e-5 1e-3 1e-10]);
  thq = estimate (1, iddata (x0, u0, Ts, "InterSample", "zoh"), cfgq);
  relq = abs ((theta - thq) ./ theta) * 100;
  E0(3, :) = mean (relq(win{2}, :));

  simrun = @(s) closed_loop_run (theta, r1, Ts, loop, sigma2, N);
  winmeans = @(thm, rel) [mean(rel(win{1}, :)), mean(rel(win{2}, :))];
  [R, ~, stats, thm1, rej, data1, runinfo, tmain, textra] = ...
    ch2_monte_carlo (theta, nruns, M, main, simrun,
                     @(m, data) estimate (m, data, cfg), winmeans);
  E = permute (reshape (stats, nruns, 3, 2, M), [1 2 4 3]);  # run x 3 x M x w
  snr = runinfo(:, 1);
  umax = runinfo(:, 2);
  relerr = R / nruns;

  ## Rejections of the RLSSVF phase alone (IV stage never started), run 1.
  cfg0 = cfg;
  cfg0.riv{end - 2} = t(end);
  cfg0.sriv{end - 2} = t(end);
  rej0 = ch2_iv_phase_rejections (@(m, data) estimate (m, data, cfg0), data1,
                                  M);

  tb = t(end) - 200;
  ch2_plot_panels (fullfile (outdir, "fig_2_17_rlssvf.png"), t, 20,
                   {struct("series", {{theta, thm0}},
                           "ylims", 1.5 * max (theta), "labels", {{"true", "RLSSVF"}},
                           "title", "(a) RLSSVF, closed loop, noise-free (cf. Fig. 2.17a)"),
                    struct("series", {{theta, thm1(:, :, 1)}},
                           "ylims", 1.5 * max (theta), "labels", {{"true", "RLSSVF"}},
                           "title", "(b) RLSSVF, closed loop, noisy, run 1 (cf. Fig. 2.17b)")});
  ch2_plot_panels (fullfile (outdir, "fig_2_18_cliv.png"), t, 20,
                   {struct("series", {{theta, thm1(:, :, 2), thm1(:, :, 3)}},
                           "ylims", 1.5 * max (theta), "labels", {{"true", "CLRIVSVF", "CLRSRIVC"}},
                           "title", "True parameters, CLRIVSVF and CLRSRIVC estimates, run 1 (cf. Fig. 2.18)")});
  ch2_plot_panels (fullfile (outdir, "fig_2_19_rlssvf_relerr.png"), t, 20,
                   {struct("series", {{relerr(:, :, 1)}},
                           "labels", {{"RLSSVF"}}, "unit", " (%)",
                           "logy", true, "vlines", tsiv,
                           "title", sprintf ("RLSSVF, closed loop, mean relative error over %d runs (cf. Fig. 2.19)", nruns))});
  ch2_plot_panels (fullfile (outdir, "fig_2_20_cliv_relerr.png"), t, 20,
                   {struct("series", {{relerr(:, :, 2), relerr(:, :, 3)}},
                           "labels", {{"CLRIVSVF", "CLRSRIVC"}}, "unit", " (%)",
                           "logy", true, "vlines", [tsiv, tb],
                           "title", sprintf ("Mean relative error over %d runs (cf. Fig. 2.20)", nruns)),
                    struct("series", {{relerr(:, :, 2), relerr(:, :, 3), relerr(:, :, 4)}},
                           "labels", {{"CLRIVSVF", "CLRSRIVC", "CLRSRIVC monic"}},
                           "unit", " (%)", "logy", true, "vlines", [tsiv, tb],
                           "title", "the same with the monic prefilter 1/A(p)")});

  elapsed = toc (t_all);
  write_table (fullfile (outdir, "ch2_closed_loop.md"), names, E, E0, rej,
               rej0, yard, winname, snr, umax, nruns, N, tmain, textra,
               elapsed);

  Em = squeeze (mean (E, 1));                     # 3 x M x 2
  printf ("ch2 closed loop (sec. 2.4.6): SNR %.1f dB (mean over runs), %d runs, ",
          mean (snr), nruns);
  printf ("%.1f s for simulation+RLSSVF+CLRIVSVF+CLRSRIVC (+%.1f s monic ",
          tmain, textra);
  printf ("variant, %.1f s in all)\n", elapsed);
  printf ("  mean relative error (%%) a1/a2/b0   %-20s %-20s\n", winname{:});
  printf ("  %-17s %18s %6.1f/%5.1f/%5.1f   %6.1f/%5.1f/%5.1f\n",
          "RLSSVF noise-free", "", E0(1, :), E0(2, :));
  for m = 1:M
    printf ("  %-17s %18s %6.1f/%5.1f/%5.1f   %6.1f/%5.1f/%5.1f\n", names{m},
            "", Em(:, m, 1), Em(:, m, 2));
  endfor
  printf ("  yardstick (10 runs, last 500 s): RLSSVF 30.2/7.3/11.1, ");
  printf ("CLRIVSVF 5.8/8.0/1.4, CLRSRIVC 4.8/6.1/1.5\n");
endfunction

function [thm, info] = estimate (m, data, cfg)
  info = struct ("stability_rejections", 0);
  switch (m)
    case 1
      thm = rlssvf (data, [2 1 0], cfg.svf{:});
    case 2
      [thm, ~, ~, info] = clrivsvf (data, [2 1 0], cfg.riv{:});
    case 3
      [thm, ~, ~, info] = clrsrivc (data, [1 2 0], cfg.sriv{:});
      thm = thm(:, [2 3 1]);                      # [b0 f1 f2] -> [a1 a2 b0]
    case 4
      [thm, ~, ~, info] = clrsrivc (data, [1 2 0], cfg.sriv{:},
                                    "prefilter", "monic");
      thm = thm(:, [2 3 1]);
  endswitch
endfunction

function write_table (file, names, E, E0, rej, rej0, yard, winname, snr,
                      umax, nruns, N, tmain, textra, elapsed)
  M = numel (names);
  Em = mean (E, 1);                               # 1 x 3 x M x 2
  pn = {"a1", "a2", "b0"};
  fid = fopen (file, "w");
  fprintf (fid, "## Closed-loop recursive IV methods (thesis sec. 2.4.6)\n\n");
  fprintf (fid, "Plant of sec. 2.3.6 (a1 = 5 + 40 t/1000, a2 = 160 - 90 cos (2 pi t/1000), ");
  fprintf (fid, "b0 = 200) in the loop u = r1 + C (r2 - y), r2 = 0, C the backward-Euler ");
  fprintf (fid, "PID kp + ki Ts/(1 - q^-1) + (kd/Ts)(1 - q^-1), kp = 1.79, ki = 13.8, ");
  fprintf (fid, "kd = 5.83e-2. Ts = 0.01 s, %d samples (1000 s), noise variance 0.1 ", N);
  fprintf (fid, "(SNR %.1f dB, mean over runs; range %.1f-%.1f dB), ",
           mean (snr), min (snr), max (snr));
  fprintf (fid, "lambda_svf = 16 rad/s, Qn = diag (1e-5, 1e-4, 1e-10), tsiv = 10 s, ");
  fprintf (fid, "M_theta = (0.04762 + 0.04762 q^-1)/(1 - 0.9048 q^-1) for the IV ");
  fprintf (fid, "methods, theta0 = 0, P0 = 1e4 I. r1 = prbs (15, 10) (15-bit ");
  fprintf (fid, "maximum-length PRBS, levels +-1, chip 0.1 s), the same in every run; ");
  fprintf (fid, "each run is simulated in closed loop with its own noise, ");
  fprintf (fid, "sqrt (0.1) * randn after randn (\"state\", s); the loop stays ");
  fprintf (fid, "bounded (max |u| over runs %.2f). CLRSRIVC uses the ", max (umax));
  fprintf (fid, "unit-static-gain prefilter; \"CLRSRIVC monic\" is eq. 2.19 taken ");
  fprintf (fid, "literally, 1/A(p). %d runs took %.1f s for the simulations, ",
           nruns, tmain);
  fprintf (fid, "RLSSVF, CLRIVSVF and CLRSRIVC, %.1f s more for the monic ", textra);
  fprintf (fid, "variant, %.1f s in all.\n\n", elapsed);

  ch2_md_error_table (fid, names, E, E0, yard, winname, nruns, "2.19, 2.20");

  fprintf (fid, "\n### The thesis' claims\n\n");
  ## 1. RLSSVF fails on noisy data.
  rls = Em(1, :, 1, 2);
  ivbest = min (Em(1, :, 2, 2), Em(1, :, 3, 2));
  fails = all (E0(2, :) < 2) && any (rls > 10) && mean (rls) > 2 * mean (ivbest);
  fprintf (fid, "1. *RLSSVF tracks only on noise-free data.* Last 500 s: noise-free ");
  fprintf (fid, "%.1f / %.1f / %.1f %%, noisy %.1f / %.1f / %.1f %%, i.e. %.0f-%.0f times ",
           E0(2, :), rls, min (rls ./ E0(2, :)), max (rls ./ E0(2, :)));
  fprintf (fid, "larger, and %.1f-%.1f times the better closed-loop IV method's. ",
           min (rls ./ ivbest), max (rls ./ ivbest));
  fprintf (fid, "Criterion: noise-free below 2 %% on every parameter, noisy above ");
  fprintf (fid, "10 %% on some parameter, and its mean over the three parameters ");
  fprintf (fid, "more than twice that of the better IV method (%.1f vs %.1f %%): **%s**. ",
           mean (rls), mean (ivbest),
           ch2_ifelse_str (fails, "reproduced", "not reproduced"));
  bad = rls > 2 * ivbest;
  if (any (bad))
    fprintf (fid, "The failure is in %s (more than twice the IV error)",
             strjoin (pn(bad), " and "));
  endif
  if (! all (bad))
    fprintf (fid, "; on %s noisy RLSSVF is within a factor two of the IV ",
             strjoin (pn(! bad), " and "));
    fprintf (fid, "methods (the yardstick has the same: a2 7.3 vs 8.0 / 6.1 %%)");
  endif
  fprintf (fid, ". ");
  fprintf (fid, "The noise-free a2 error of %.1f %% is lag error of the small ", E0(2, 2));
  fprintf (fid, "Qn(a2) = 1e-4 (a2 changes by up to 0.57 per second): with ");
  fprintf (fid, "Qn(a2) = 1e-3 it drops to %.2f %%.\n\n", E0(3, 2));
  ## 2. Both closed-loop IV methods track.
  track = all (Em(1, :, 2, 2) < 10) && all (Em(1, :, 3, 2) < 10);
  fprintf (fid, "2. *CLRIVSVF and CLRSRIVC track the parameters.* Last 500 s: ");
  fprintf (fid, "CLRIVSVF %.1f / %.1f / %.1f %%, CLRSRIVC %.1f / %.1f / %.1f %% ",
           Em(1, :, 2, 2), Em(1, :, 3, 2));
  fprintf (fid, "(yardstick 5.8 / 8.0 / 1.4 and 4.8 / 6.1 / 1.5). Criterion: all ");
  fprintf (fid, "below 10 %%: **%s**.\n\n",
           ch2_ifelse_str (track, "reproduced", "not reproduced"));
  ## 3. CLRSRIVC best at the end.
  fprintf (fid, "3. *CLRSRIVC gives the best results towards the end.* Last 200 s, ");
  fprintf (fid, "paired difference CLRIVSVF - CLRSRIVC over %d runs with twice ", nruns);
  fprintf (fid, "its standard error:\n\n");
  better = ch2_md_paired_table (fid, E, names{2}, names{3}, nruns);
  if (all (better))
    fprintf (fid, "Reproduced for all three parameters.\n\n");
  else
    if (any (better))
      fprintf (fid, "Reproduced for %s; ", strjoin (pn(better), " and "));
    else
      fprintf (fid, "Reproduced for none of the parameters; ");
    endif
    fprintf (fid, "not for %s.", strjoin (pn(! better), " and "));
    if (! better(3))
      fprintf (fid, " b0 is constant (Qn(b0) = 1e-10) and held within a ");
      fprintf (fid, "few per cent by both methods; the yardstick has CLRSRIVC ");
      fprintf (fid, "slightly worse on b0 too (1.5 vs 1.4 %%).");
    endif
    fprintf (fid, "\n\n");
  endif

  fprintf (fid, "### Gain of the adaptive prefilter, and stability\n\n");
  fprintf (fid, "With the monic prefilter 1/A(p) CLRSRIVC's mean relative errors over ");
  fprintf (fid, "the last 500 s are %.1f / %.1f / %.1f %% against %.1f / %.1f / %.1f %% ",
           Em(1, :, 4, 2), Em(1, :, 3, 2));
  fprintf (fid, "with the unit-gain prefilter: the static gain 1/a2 (1/250-1/70) ");
  fprintf (fid, "shrinks the effective Qn by 1/a2^2 and the estimates cannot follow a2.\n\n");
  ch2_md_stability (fid, names, rej, rej0, 10);
  fclose (fid);
endfunction

function [data, info] = closed_loop_run (theta, r1, Ts, loop, sigma2, N)
  ## One noisy run in closed loop; info = [SNR (dB), max |u|].
  e = sqrt (sigma2) * randn (N, 1);
  [y, x, u] = simc (theta, [2 1 0], r1, Ts, loop{:}, "noise", e);
  info = [10 * log10(mean (x .^ 2) / sigma2), max(abs (u))];
  data = iddata (y, u, Ts, "InterSample", "zoh");
endfunction
