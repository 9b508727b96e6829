## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn {} {} demo_ch1_indirect (@var{outdir}, @var{nseeds})
## Thesis section 1.3.4, indirect versus direct (Fig. 1.9): the LTV system
## of eqs. (1.61)-(1.63) tracked
##
## @itemize
## @item indirectly: a DT ARX model (eq. 1.66, nn = [2 2 1]) estimated by
## the Kalman filter with Qn = diag([1e-3 1e-3 1e-5 1e-5]) on data
## prefiltered by the SVF (lambda = 3.2 rad/s) discretised with the bilinear
## rule, converted to CT under ZOH at every step (@code{rarxc}; MATLAB
## users run @code{recursiveARX} + @code{d2c});
## @item directly: RLSSVF-KF with Qn = 1e-4 I3, lambda_svf = 3.2
## (@code{rlssvf}, as in @code{demo_rlssvf_ltv}).
## @end itemize
##
## Writes to @var{outdir} (default "results") fig_1_9_indirect_direct.png
## (true and estimated a1, a2, b0 of run 1 for both routes, cf. Fig. 1.9a
## and 1.9b) and indirect_direct.md: the tracking MSE (eq. 2.32) over
## @var{nseeds} noise realisations (default 20), whole record and after
## t = 100 s, the size of the spurious CT zero coefficient the indirect
## route estimates (the true b(p) has none), and the samples without a CT
## equivalent.  The thesis gives the two figures only (no numbers); its
## conclusion is that both routes track, the direct one with one parameter
## less and an easier Qn.
## @end deftypefn

function demo_ch1_indirect (outdir = "results", nseeds = 20)
  demo_prepare (outdir);
  [Ts, t, theta, u] = ch2_example_235 ();     # [a1 a2 b0], eq. (1.62)
  N = numel (t);
  x = simc (theta, [2 1 0], u, Ts);
  after = t >= 100;
  Qdt = diag ([1e-3 1e-3 1e-5 1e-5]);
  mse = zeros (nseeds, 2);
  mse_after = zeros (nseeds, 2);
  spurious = zeros (nseeds, 1);
  failures = zeros (nseeds, 1);
  t_run = tic ();
  for s = 1:nseeds
    randn ("state", s);
    y = x + sqrt (0.05) * randn (N, 1);
    data = iddata (y, u, Ts, "InterSample", "zoh");
    [thc, ~, info] = rarxc (data, [2 2 1], "adm", "kf", "adg", Qdt,
                            "lambda_svf", 3.2);
    ind = thc(:, [1 2 4]);                     # b(p) = b0' p + b1': b1' is b0
    dir = rlssvf (data, [2 1 0], "lambda_svf", 3.2, "adm", "kf",
                  "adg", 1e-4 * eye (3));
    for m = 1:2
      est = {ind, dir}{m};
      err2 = sum ((theta - est) .^ 2, 2);
      mse(s, m) = mean (err2);
      mse_after(s, m) = mean (err2(after));
    endfor
    spurious(s) = mean (abs (thc(after, 3)));
    failures(s) = info.failures;
    if (s == 1)
      ind1 = ind;
      dir1 = dir;
    endif
  endfor
  elapsed = toc (t_run);
  plot_routes (fullfile (outdir, "fig_1_9_indirect_direct.png"), t, theta,
               ind1, dir1);
  write_table (fullfile (outdir, "indirect_direct.md"), mse, mse_after,
               spurious, failures, nseeds, N, elapsed);
  printf ("MSE after 100 s (median of %d runs): indirect %.4f, direct %.4f\n",
          nseeds, median (mse_after(:, 1)), median (mse_after(:, 2)));
endfunction

function plot_routes (file, t, theta, ind, dir)
  warning ("off", "Octave:gnuplot-graphics");
  graphics_toolkit ("gnuplot");
  f = figure ("visible", "off", "position", [0 0 1000 700]);
  names = {"a_1", "a_2", "b_0"};
  titles = {"indirect: DT ARX-KF + ZOH (cf. Fig. 1.9a)",
            "direct: RLSSVF-KF (cf. Fig. 1.9b)"};
  est = {ind, dir};
  k = 1:10:numel (t);
  for m = 1:2
    for i = 1:3
      subplot (3, 2, 2 * (i - 1) + m);
      plot (t(k), theta(k, i), "k", "linewidth", 1.5, t(k), est{m}(k, i), "r");
      ylim ([0 1.5 * max(theta(:, i))]);
      xlim ([0 t(end)]);
      ylabel (names{i});
      grid on;
      if (i == 1)
        title (titles{m});
      endif
    endfor
    xlabel ("time (s)");
  endfor
  print (f, "-dpng", "-r90", file);
  close (f);
endfunction

function write_table (file, mse, mse_after, spurious, failures, nseeds, N,
                      elapsed)
  fid = fopen (file, "w");
  fprintf (fid, "## Indirect vs direct recursive CT identification ");
  fprintf (fid, "(thesis sec. 1.3.4, Fig. 1.9)\n\n");
  fprintf (fid, "System of eqs. (1.61)-(1.63), Ts = 0.1 s, %d samples, ", N);
  fprintf (fid, "noise variance 0.05, input prbs (15, 10); run s uses ");
  fprintf (fid, "randn (\"state\", s). Indirect: `rarxc`, nn = [2 2 1], ");
  fprintf (fid, "KF with Qn = diag([1e-3 1e-3 1e-5 1e-5]), bilinear SVF ");
  fprintf (fid, "prefilter at 3.2 rad/s, ZOH conversion every sample. ");
  fprintf (fid, "Direct: `rlssvf`, KF with Qn = 1e-4 I3, lambda_svf = 3.2. ");
  fprintf (fid, "%d runs took %.1f s.\n\n", nseeds, elapsed);
  fprintf (fid, "| quantity (%d runs) | indirect (DT ARX + ZOH) | ", nseeds);
  fprintf (fid, "direct (RLSSVF) | thesis |\n|---|---|---|---|\n");
  fprintf (fid, "| MSE (eq. 2.32), median [min, max] | %.3f [%.3f, %.3f] | ",
           median (mse(:, 1)), min (mse(:, 1)), max (mse(:, 1)));
  fprintf (fid, "%.3f [%.3f, %.3f] | figures only |\n",
           median (mse(:, 2)), min (mse(:, 2)), max (mse(:, 2)));
  fprintf (fid, "| MSE for t >= 100 s, median [min, max] | %.4f [%.4f, %.4f] | ",
           median (mse_after(:, 1)), min (mse_after(:, 1)),
           max (mse_after(:, 1)));
  fprintf (fid, "%.4f [%.4f, %.4f] | figures only |\n",
           median (mse_after(:, 2)), min (mse_after(:, 2)),
           max (mse_after(:, 2)));
  fprintf (fid, "| runs where the direct route has the lower MSE after 100 s ");
  fprintf (fid, "| - | %d of %d | - |\n", sum (mse_after(:, 2) < mse_after(:, 1)),
           nseeds);
  fprintf (fid, "| mean abs. spurious CT zero coefficient (true 0), t >= 100 s ");
  fprintf (fid, "| %.3f | (not estimated) | - |\n", mean (spurious));
  fprintf (fid, "| samples without a CT equivalent (a DT pole at 0 or on the ");
  fprintf (fid, "negative real axis; the start-up from theta0 = 0), all runs ");
  fprintf (fid, "| %d | - | - |\n\n", sum (failures));
  fprintf (fid, "The indirect route estimates 4 DT parameters and, after ");
  fprintf (fid, "conversion, a CT numerator b0' p + b1' whose b0' is truly 0; ");
  fprintf (fid, "the direct route estimates the 3 CT parameters of the model ");
  fprintf (fid, "structure. The thesis shows both tracking (Fig. 1.9) without ");
  fprintf (fid, "a number to compare with. Measured here, the indirect ");
  fprintf (fid, "route with the thesis' trial-and-error Qn tracks closer after ");
  fprintf (fid, "the start-up than RLSSVF with Qn = 1e-4 I3: its Qn is larger ");
  fprintf (fid, "relative to its parameters (faster tracking of a slow ");
  fprintf (fid, "variation), at the price of a spurious zero coefficient. ");
  fprintf (fid, "Both Qn are the thesis' hand-tuned values, not optimised. ");
  fprintf (fid, "Over the whole record the indirect route is far worse and ");
  fprintf (fid, "erratic: in the first seconds the ZOH conversion maps a ");
  fprintf (fid, "poorly determined DT estimate (poles near z = 0) to CT ");
  fprintf (fid, "parameters of order 1e2-1e3.\n");
  fclose (fid);
endfunction
