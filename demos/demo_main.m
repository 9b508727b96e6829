## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn {} {@var{R} =} demo_main (@var{outdir}, @var{nseeds})
## The main demo (@code{scripts/run-demo}), in three parts.
##
## @strong{1. RLSSVF-KF tracking a time-varying system} (thesis sec. 1.3.4):
## @code{demo_rlssvf_ltv} on the LTV system of eqs. (1.61)-(1.63), with
## @var{nseeds} noise runs (default 50): Fig. 1.9b and the MSE table.
##
## @strong{2. The recursive IV estimate removes RLSSVF's bias.} On the same
## record (its run 1: the input prbs (15, 10), the noise after
## randn ("state", 1)), RLSSVF-KF and RSRIVC-KF (the recursive simplified
## refined IV of thesis sec. 2.2.3, eqs. 2.19-2.25, taking over from
## RLSSVF at tsiv = 100 s) with the same Qn = 1e-4 I3 and lambda_svf =
## 3.2 rad/s. RLSSVF's equation error is the output noise filtered by A(p):
## coloured, so its least-squares estimates are biased (the ARX noise-model
## bias visible in Fig. 1.9b); the instruments of RSRIVC, built from the
## noise-free output of the auxiliary model, are uncorrelated with it. For
## each parameter, over t >= tsiv: the bias (mean of estimate - truth) and
## the RMSE. The variation of the parameters spans two whole periods of
## 4500 s there, so the tracking lag averages out of the bias.
##
## @strong{3. Closing the loop on a measured record.} @code{residtrace} on
## the EMPS positioning axis (@code{demo_emps} in its reduced form: the
## first 6 s of each record, one pass): the position error of the
## closed-loop simulation on the validation record before and after the
## effect it finds is added to the linear model. Needs the measured records
## (@code{ctid_data_dir}); without them this part says so and is skipped.
##
## Writes to @var{outdir} (default "results"): results.md (the tables of
## parts 2 and 3, and where the others are), fig_main_iv.png (the true
## parameters and both estimates), and the files of @code{demo_rlssvf_ltv}
## and @code{demo_emps}. Returns @var{R} with fields @code{t},
## @code{theta} (true [a1 a2 b0]), @code{thm_ls}, @code{thm_iv} (the
## estimates, [a1 a2 b0]), @code{tsiv}, @code{bias}, @code{rmse} (2-by-3:
## RLSSVF row 1, RSRIVC row 2) and @code{emps} (the struct returned by
## @code{demo_emps}, empty when the records are absent), @code{emps_why}
## (the reason then).
## @end deftypefn

function R = demo_main (outdir = "results", nseeds = 50)
  demo_prepare (outdir);
  t_all = tic;

  ## 1. Thesis sec. 1.3.4.
  demo_rlssvf_ltv (outdir, nseeds);

  ## 2. The same record: RLSSVF-KF and RSRIVC-KF.
  [Ts, t, theta, u] = ch2_example_235 ();     # [a1 a2 b0], eq. (1.62)
  N = numel (t);
  x = simc (theta, [2 1 0], u, Ts);
  randn ("state", 1);                         # run 1 of demo_rlssvf_ltv
  y = x + sqrt (0.05) * randn (N, 1);
  data = iddata (y, u, Ts, "InterSample", "zoh");
  tsiv = 100;
  common = {"lambda_svf", 3.2, "adm", "kf", "adg", 1e-4 * eye(3)};
  thm_ls = rlssvf (data, [2 1 0], common{:});
  thm_sr = rsrivc (data, [1 2 0], common{:}, "tsiv", tsiv);
  thm_iv = thm_sr(:, [2 3 1]);                # [b0 f1 f2] -> [a1 a2 b0]
  after = t >= tsiv;
  [bias, rmse] = deal (zeros (2, 3));
  for m = 1:2
    err = {thm_ls, thm_iv}{m}(after, :) - theta(after, :);
    bias(m, :) = mean (err);
    rmse(m, :) = sqrt (mean (err .^ 2));
  endfor
  plot_tracks (fullfile (outdir, "fig_main_iv.png"), t, theta, thm_ls,
               thm_iv, tsiv);

  ## 3. residtrace on the EMPS record, when the records are there.
  [emps_dir, emps_why] = ctid_data_dir ("emps");
  emps = [];
  if (isempty (emps_dir))
    printf ("EMPS part skipped: %s\n", emps_why);
  else
    emps = demo_emps (outdir, true);
  endif

  elapsed = toc (t_all);
  R = struct ("t", t, "theta", theta, "thm_ls", thm_ls, "thm_iv", thm_iv,
              "tsiv", tsiv, "bias", bias, "rmse", rmse, "emps", emps,
              "emps_why", emps_why);
  write_results (fullfile (outdir, "results.md"), R, nseeds, elapsed);
  names = {"a1", "a2", "b0"};
  for i = 1:3
    printf ("%s: bias RLSSVF %+.4f, RSRIVC %+.4f; RMSE %.4f, %.4f\n",
            names{i}, bias(1, i), bias(2, i), rmse(1, i), rmse(2, i));
  endfor
  if (! isempty (emps))
    printf ("EMPS: validation position RMSE %.3g m before, %.3g m after (%s)\n",
            emps.rmse_before, emps.rmse_after, emps.effect);
  endif
  printf ("demo_main: %.0f s; results in %s\n", elapsed, outdir);
endfunction

function plot_tracks (file, t, theta, thm_ls, thm_iv, tsiv)
  warning ("off", "Octave:gnuplot-graphics");
  graphics_toolkit ("gnuplot");
  f = figure ("visible", "off", "position", [0 0 900 700]);
  names = {"a_1", "a_2", "b_0"};
  k = 1:10:numel (t);                         # every 10th sample
  for i = 1:3
    subplot (3, 1, i);
    h = plot (t(k), thm_ls(k, i), "r", t(k), thm_iv(k, i), "b");
    hold on;
    h(3) = plot (t(k), theta(k, i), "k", "linewidth", 2);
    hold off;
    ylabel (names{i});
    ylim ([0.5 * min(theta(:, i)), 1.25 * max(theta(:, i))]);
    xlim ([0 t(end)]);
    grid on;
    if (i == 1)
      title (sprintf (["Same record: RLSSVF-KF (biased) and RSRIVC-KF ", ...
                       "(recursive IV from t = %g s)"], tsiv));
      legend (h, {"RLSSVF", "RSRIVC", "true"}, "location", "southeast");
    endif
  endfor
  xlabel ("time (s)");
  print (f, "-dpng", "-r90", file);
  close (f);
endfunction

function write_results (file, R, nseeds, elapsed)
  fid = fopen (file, "w");
  fprintf (fid, "# ctid main demo\n\n");
  fprintf (fid, "## 1. RLSSVF-KF tracking a time-varying system\n\n");
  fprintf (fid, ["Thesis sec. 1.3.4, %d noise runs: rlssvf_ltv.md and ", ...
                 "fig_1_9b_rlssvf.png.\n\n"], nseeds);
  fprintf (fid, "## 2. Recursive IV removes RLSSVF's bias\n\n");
  fprintf (fid, ["The record of run 1 (Ts = 0.1 s, 9000 s, noise variance ", ...
                 "0.05), Qn = 1e-4 I3, lambda_svf = 3.2 rad/s; RSRIVC-KF ", ...
                 "from tsiv = %g s. Errors over t >= %g s ", ...
                 "(fig_main_iv.png):\n\n"], R.tsiv, R.tsiv);
  fprintf (fid, "| parameter | bias RLSSVF | bias RSRIVC | RMSE RLSSVF | RMSE RSRIVC |\n");
  fprintf (fid, "|---|---|---|---|---|\n");
  names = {"a1", "a2", "b0"};
  for i = 1:3
    fprintf (fid, "| %s | %+.4f | %+.4f | %.4f | %.4f |\n", names{i},
             R.bias(1, i), R.bias(2, i), R.rmse(1, i), R.rmse(2, i));
  endfor
  fprintf (fid, "\n## 3. Closing the loop on the EMPS record (residtrace)\n\n");
  if (isempty (R.emps))
    fprintf (fid, "Skipped: %s.\n", R.emps_why);
  else
    e = R.emps;
    fprintf (fid, ["residtrace on the first 6 s of DATA_EMPS.mat (one pass; ", ...
                   "demos/demo_emps.m without 'reduced' for the full ", ...
                   "records), validated on DATA_EMPS_PULSES.mat in closed ", ...
                   "loop (emps.md, fig_emps_*.png):\n\n"]);
    fprintf (fid, "| position RMSE on the validation record | value |\n");
    fprintf (fid, "|---|---|\n");
    fprintf (fid, "| linear model (before) | %.4g m |\n", e.rmse_before);
    fprintf (fid, "| with the effect found (%s) | %.4g m |\n", e.effect,
             e.rmse_after);
  endif
  fprintf (fid, "\nThe demo took %.0f s.\n", elapsed);
  fclose (fid);
endfunction
