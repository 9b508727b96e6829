## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn {} {} demo_throttle (@var{outdir}, @var{nruns})
## Thesis section 4.2: recursive estimation of the electrical submodel of
## an electronic throttle body in closed loop, theta = [1/R, Kv Gr/R] (eq.
## 4.15), with the armature resistance R(t) rising linearly from 0.7 to 2.1
## Ohm (+-50 % of 1.4 Ohm, eq. 4.10).
##
## Plant and loop: @code{throttlesim} with its defaults (eqs. 4.6-4.13,
## Table 4.3, Ts = 1 ms, 100 s, angle noise of variance 1e-3 rad^2, the
## default set point of 1 s steps between 25 and 70 degrees). The thesis'
## set point, record length and noise realisation are not published; what
## the thesis leaves open is listed in @code{help throttlesim}.
##
## Methods (@code{throttleid}): RLSSVF with the SVF (4.22), lambda_svf = 5 *
## 12.4 rad/s, and CLRSRIVC with the mechanical prefilter (4.19) and the
## closed-loop auxiliary model (Fig. 4.12), tsiv = 5 s; both with Qn =
## diag (1e-6, 5e-5), theta0 = 0, P0 = 1e4 I. As a diagnostic not in the
## thesis, least squares with the prefilter (4.19) ("RLS prefilter"), to
## separate the prefilter's and the instruments' share.
##
## Over @var{nruns} runs (default 100; run s draws its noise after randn
## ("state", s), the set point and R(t) are the same in every run) it
## reports the relative tracking errors of theta, R and Kv averaged over
## t >= tsiv, their mean and spread over the runs, and the error of the
## run-averaged estimates, and checks the thesis' statement: "RLSSVF shows
## a significant tracking error, CLRSRIVC estimates are very close to the
## true values".
##
## Writes to @var{outdir} (default "results"): fig_4_13_data.png,
## fig_4_14_estimates.png, fig_4_15_physical.png, fig_4_16_mc_mean.png and
## throttle.md.
## @end deftypefn

function demo_throttle (outdir = "results", nruns = 100)
  here = demo_prepare (outdir);
  t_all = tic;
  deg = 180 / pi;
  tsiv = 5;
  names = {"RLSSVF", "CLRSRIVC", "RLS prefilter"};
  methods = {"rlssvf", "clrsrivc", "rlsprefilter"};
  M = numel (methods);

  ## Monte Carlo: per run and method the mean relative error (%) over
  ## t >= tsiv of theta1, theta2, R, Kv; and the running sums of the
  ## estimates for the averaged estimates (Fig. 4.16).
  E = zeros (nruns, 4, M);
  tsim = 0;
  test = zeros (1, M);
  for s = 1:nruns
    randn ("state", s);
    t0 = tic;
    sim = throttlesim ();
    tsim += toc (t0);
    if (s == 1)
      sim1 = sim;
      S = zeros (numel (sim.t), 2, M);
      thm1 = S;
      info1 = cell (1, M);
      sat = zeros (nruns, 1);
      outside = zeros (nruns, 1);
      range = zeros (nruns, 2);
      late = sim.t >= tsiv;
      Kv = sim.params.Kv;
    endif
    sat(s) = sim.info.saturated;
    outside(s) = sim.info.outside_linear;
    range(s, :) = sim.info.phi_range * deg;
    for m = 1:M
      t0 = tic;
      [thm, R, Kvh, info] = throttleid (sim, methods{m});
      test(m) += toc (t0);
      rel = abs ([thm, R, Kvh] ./ [sim.theta, sim.R, Kv + 0 * R] - 1) * 100;
      E(s, :, m) = mean (rel(late, :));
      S(:, :, m) += thm;
      if (s == 1)
        thm1(:, :, m) = thm;
        info1{m} = info;
      endif
    endfor
  endfor
  avg = S / nruns;
  ## The same experiment without noise: what remains is the lag of the
  ## random-walk Kalman filter with this Qn (and the discretisation).
  clean = throttlesim ("noisevar", 0);
  E0 = zeros (M, 2);
  for m = 1:M
    thm = throttleid (clean, methods{m});
    E0(m, :) = mean (abs (thm(late, :) ./ clean.theta(late, :) - 1)) * 100;
  endfor
  Eavg = zeros (M, 2);
  for m = 1:M
    Eavg(m, :) = mean (abs (avg(late, :, m) ./ sim1.theta(late, :) - 1)) * 100;
  endfor

  ## Figures.
  t = sim1.t;
  step = 20;
  throttle_plot_panels (fullfile (outdir, "fig_4_13_data.png"), t, step,
    {struct("series", {{sim1.phi_m * deg, sim1.phi_d * deg}},
            "labels", {{"phi_m", "phi_d"}}, "ylabel", "angle (deg)",
            "title", "Estimation data, run 1 (cf. Fig. 4.13)"),
     struct("series", {{sim1.u}}, "labels", {{"u"}}, "ylabel", "u (V)"),
     struct("series", {{sim1.i}}, "labels", {{"i"}}, "ylabel", "i (A)")});
  th = sim1.theta;
  ylim1 = [0 1.1 * max(th(:, 1))];
  ylim2 = [0 1.1 * max(th(:, 2))];
  throttle_plot_panels (fullfile (outdir, "fig_4_14_estimates.png"), t, step,
    {struct("series", {{th(:, 1), thm1(:, 1, 1)}}, "labels",
            {{"true", "RLSSVF"}}, "ylabel", "theta_1 = 1/R", "ylim", ylim1,
            "title", "(a) RLSSVF, run 1 (cf. Fig. 4.14a)"),
     struct("series", {{th(:, 1), thm1(:, 1, 2)}}, "labels",
            {{"true", "CLRSRIVC"}}, "ylabel", "theta_1 = 1/R", "ylim", ylim1,
            "vlines", tsiv, "title", "(b) CLRSRIVC, run 1 (cf. Fig. 4.14b)"),
     struct("series", {{th(:, 2), thm1(:, 2, 1)}}, "labels",
            {{"true", "RLSSVF"}}, "ylabel", "theta_2 = Kv Gr/R",
            "ylim", ylim2),
     struct("series", {{th(:, 2), thm1(:, 2, 2)}}, "labels",
            {{"true", "CLRSRIVC"}}, "ylabel", "theta_2 = Kv Gr/R",
            "ylim", ylim2, "vlines", tsiv)}, 2);
  Rh = 1 ./ thm1(:, 1, 2);
  Kvh = thm1(:, 2, 2) ./ (sim1.params.Gr * thm1(:, 1, 2));
  throttle_plot_panels (fullfile (outdir, "fig_4_15_physical.png"), t, step,
    {struct("series", {{sim1.R, Rh}}, "labels", {{"true", "CLRSRIVC"}},
            "ylabel", "R (Ohm)", "ylim", [0 3], "vlines", tsiv,
            "title", "Physical parameters, CLRSRIVC, run 1 (cf. Fig. 4.15)"),
     struct("series", {{Kv + 0 * t, Kvh}}, "labels", {{"true", "CLRSRIVC"}},
            "ylabel", "Kv (V s/rad)", "ylim", [0 0.04], "vlines", tsiv)});
  throttle_plot_panels (fullfile (outdir, "fig_4_16_mc_mean.png"), t, step,
    {struct("series", {{th(:, 1), avg(:, 1, 1), avg(:, 1, 2)}}, "labels",
            {{"true", "RLSSVF", "CLRSRIVC"}}, "ylabel", "theta_1",
            "ylim", ylim1, "vlines", tsiv,
            "title", sprintf ("Average estimates over %d runs (cf. Fig. 4.16)",
                              nruns)),
     struct("series", {{th(:, 2), avg(:, 2, 1), avg(:, 2, 2)}}, "labels",
            {{"true", "RLSSVF", "CLRSRIVC"}}, "ylabel", "theta_2",
            "ylim", ylim2, "vlines", tsiv)});

  elapsed = toc (t_all);
  claim = write_table (fullfile (outdir, "throttle.md"), names, E, Eavg, E0,
                       nruns, sim1, sat, outside, range, info1, thm1, tsim,
                       test, elapsed, tsiv);
  printf ("throttle (sec. 4.2): %d runs, %.1f s in all (simulation %.1f s, ",
          nruns, elapsed, tsim);
  printf ("RLSSVF %.1f s, CLRSRIVC %.1f s, RLS prefilter %.1f s)\n", test);
  printf ("  mean relative error (%%) over t >= %g s, mean over runs: ", tsiv);
  printf ("theta1 / theta2 / R / Kv\n");
  for m = 1:M
    printf ("  %-13s %6.2f / %6.2f / %6.2f / %6.2f\n", names{m},
            mean (E(:, :, m)));
  endfor
  printf ("  the thesis' statement: %s\n", claim);
endfunction

function claim = write_table (file, names, E, Eavg, E0, nruns, sim, sat,
                              outside, range, info1, thm1, tsim, test,
                              elapsed, tsiv)
  M = numel (names);
  fid = fopen (file, "w");
  fprintf (fid, ["## Electronic throttle, recursive estimation of R(t) ", ...
                 "(thesis sec. 4.2)\n\n"]);
  fprintf (fid, ["Closed loop of eqs. 4.6-4.13 (Table 4.3; current ", ...
                 "dynamics neglected, eq. 4.11a), simulated by ", ...
                 "`throttlesim`: Ts = 1 ms, %d s, R(t) rising linearly ", ...
                 "from 0.7 to 2.1 Ohm, angle noise of variance 1e-3 rad^2 ", ...
                 "fed back through the PID (4.13) and the set-point ", ...
                 "filter (4.12), set point 1 s steps between 25 and 70 ", ...
                 "deg (the same in every run; run s draws its noise ", ...
                 "after `randn (\"state\", s)`). Over the %d runs the ", ...
                 "true angle stayed in [%.1f, %.1f] deg, inside (4.16) = ", ...
                 "]13.14, 85[ (%d samples outside), and the voltage ", ...
                 "reached its 12 V limit in %d samples.\n\n"],
           round (sim.t(end)), nruns, min (range(:, 1)), max (range(:, 2)),
           sum (outside), sum (sat));
  fprintf (fid, ["Methods (`throttleid`): RLSSVF with the SVF (4.22), ", ...
                 "lambda_svf = 62 rad/s; CLRSRIVC with the mechanical ", ...
                 "prefilter (4.19) and the closed-loop auxiliary model of ", ...
                 "Fig. 4.12, tsiv = %g s; Qn = diag (1e-6, 5e-5), ", ...
                 "theta0 = 0, P0 = 1e4 I. \"RLS prefilter\" (not in the ", ...
                 "thesis) is least squares with the prefilter (4.19), ", ...
                 "i.e. CLRSRIVC without its instruments. %d runs took ", ...
                 "%.1f s: simulation %.1f s, RLSSVF %.1f s, CLRSRIVC ", ...
                 "%.1f s, RLS prefilter %.1f s.\n\n"],
           tsiv, nruns, elapsed, tsim, test);

  fprintf (fid, "### Mean relative tracking error (%%) over t >= %g s\n\n",
           tsiv);
  fprintf (fid, ["The thesis shows these only as figures (4.14-4.16). Per ", ...
                 "run, the mean of |estimate/true - 1| over t >= %g s; ", ...
                 "then mean +- standard deviation [min, max] over the %d ", ...
                 "runs. \"Averaged\": the same error of the run-averaged ", ...
                 "estimates (Fig. 4.16), i.e. bias and lag without the ", ...
                 "noise. \"Noise-free\": the same experiment without ", ...
                 "noise, i.e. the lag of the Kalman filter with this Qn ", ...
                 "alone.\n\n"], tsiv, nruns);
  fprintf (fid, ["| method | theta1 = 1/R | theta2 = Kv Gr/R | R | Kv | ", ...
                 "averaged: theta1 / theta2 | noise-free: theta1 / ", ...
                 "theta2 |\n|---|---|---|---|---|---|---|\n"]);
  for m = 1:M
    fprintf (fid, "| %s |", names{m});
    for c = 1:4
      v = E(:, c, m);
      fprintf (fid, " %.2f +- %.2f [%.2f, %.2f] |", mean (v), std (v),
               min (v), max (v));
    endfor
    fprintf (fid, " %.2f / %.2f | %.2f / %.2f |\n", Eavg(m, :), E0(m, :));
  endfor

  Em = squeeze (mean (E, 1));     # 4 x M
  rls = Em(1:2, 1);
  iv = Em(1:2, 2);
  pre = Em(1:2, 3);
  better = sum (E(:, 2, 2) < E(:, 2, 1));
  reproduced = rls(2) > 3 * iv(2) && all (iv < 5);
  claim = ch2_ifelse_str (reproduced, "reproduced", "not reproduced");
  fprintf (fid, ["\n### The thesis' statement\n\n", ...
                 "*\"While for RLSSVF there is a significant tracking ", ...
                 "error, for CLRSRIVC the estimates are very close to the ", ...
                 "true values\"* (Figs. 4.14, 4.16). Criterion: CLRSRIVC ", ...
                 "within 5 %% on both parameters and RLSSVF's theta2 ", ...
                 "error more than three times CLRSRIVC's. Measured: ", ...
                 "CLRSRIVC %.2f / %.2f %%, RLSSVF %.2f / %.2f %%; ", ...
                 "CLRSRIVC has the smaller theta2 error in %d of %d runs: ", ...
                 "**%s**. "], iv, rls, better, nruns, claim);
  fprintf (fid, ["RLSSVF's error is a bias, not noise: its averaged ", ...
                 "estimate of theta2 is %.1f %% off (CLRSRIVC %.1f %%): ", ...
                 "with lambda_svf = 62 rad/s the SVF passes the angle ", ...
                 "noise into the regressor (p phi)_f, and the noise fed ", ...
                 "back by the PID correlates it with u_f. CLRSRIVC's ", ...
                 "error is almost all lag: %.2f / %.2f %% without noise ", ...
                 "(RLSSVF %.2f / %.2f %%), the price of the thesis' small ", ...
                 "Qn on our 100 s ramp (R from 0.7 to 2.1 Ohm; the ", ...
                 "thesis' record length is not published, and the lag ", ...
                 "scales with the rate of change).\n\n"],
           Eavg(1, 2), Eavg(2, 2), E0(2, :), E0(1, :));
  fprintf (fid, ["*Prefilter versus instruments.* Least squares with the ", ...
                 "mechanical prefilter (4.19) tracks %s CLRSRIVC (%.2f / ", ...
                 "%.2f %% against %.2f / %.2f %%): the narrow prefilter ", ...
                 "(bandwidth 12.4 rad/s) keeps most of the noise out of ", ...
                 "the regression, and the bias the instruments remove ", ...
                 "(core test, Qn = 0: -0.07 / -0.19 %%, significant but ", ...
                 "small) is far below the tracking error. In this set-up ", ...
                 "CLRSRIVC's advantage over RLSSVF comes from the ", ...
                 "prefilter the thesis chose rather than from the ", ...
                 "instruments.\n\n"],
           ch2_ifelse_str (all (pre <= iv), "as well as or slightly better than",
                       "about as well as"), pre, iv);
  bad = find (thm1(:, 1, 2) <= 0 | thm1(:, 2, 2) < 0);
  fprintf (fid, ["Run 1: the auxiliary model refused %d estimates as ", ...
                 "unphysical (R <= 0 or Kv < 0)"], info1{2}.rejections);
  if (! isempty (bad))
    fprintf (fid, ", the last at t = %.3f s", sim.t(bad(end)));
  endif
  fprintf (fid, ".\n");
  fclose (fid);
endfunction
