## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn {} {@var{out} =} demo_greybox (@var{outdir}, @var{reduced})
## A physical grey-box demo beyond the thesis: @code{residtrace} on two
## simulated rigs whose physics a linear model lacks, in raw units with
## measurement noise.
##
## @strong{Two tanks in cascade} (@code{tanks_sim}): pump voltage (V,
## about 2.5 to 7.5 V) to the level of the lower tank (cm, measured from
## its outlet, noise 0.3 cm), square-root outflows, the upper tank
## overflowing at 40 cm; Ts = 2 s; the pump voltage holds random levels
## for random times (40 to 300 s). The start is the linear model a user
## would fit, @code{srivc} [1 2 0] on the estimation record with its
## means removed (the record is in raw units: @code{residtrace} estimates
## the levels itself and says so).
##
## @strong{Positioning axis with end stops} (@code{axis_sim}): the
## reference voltage of a position-controlled drive (0 to 10 V) to the
## carriage position (mm, noise 0.05 mm), wn = 6 rad/s, zeta = 0.6, 10
## mm/V, inelastic stops at 8 and 92 mm; Ts = 20 ms; the reference is a
## random staircase, smoothed, that sometimes asks for positions beyond a
## stop. The start is @code{srivc} [1 2 0].
##
## For both, the best linear model is the best of SRIVC [nb nf 0] for nf
## = 1..3, nb = 1..nf on the estimation record (means removed), judged by
## its validation simulation with the estimation record's levels, and of
## residtrace's own linear re-estimate (levels and initial state handled
## as residtrace handles them): the linear + traced model is compared
## with the better of them.
##
## Writes to @var{outdir} (default "results"): greybox.md (the results
## table and both residtrace tables), fig_greybox_tanks.png and
## fig_greybox_axis.png (measured, best linear and traced model on the
## validation record, and their errors). @var{reduced} (default false):
## shorter records, for the test suite. @var{out}: struct with fields
## @code{tanks} and @code{axis}, each with the residtrace result @code{R}
## and @code{rmse_linear} (best linear model) and its structure.
## @end deftypefn

function out = demo_greybox (outdir = "results", reduced = false)
  demo_prepare (outdir);
  randn ("state", 7); rand ("state", 7);
  if (reduced)
    Nt = 1500; Na = 2500;
  else
    Nt = 3000; Na = 5000;
  endif
  ## two tanks
  pt = struct ("k", 0.1, "c1", 0.09, "c2", 0.075, "h1max", 40);
  Tt = 2;
  [ut, yt, st] = greybox_record ("tanks", Nt, Tt, pt);
  [utv, ytv, stv] = greybox_record ("tanks", Nt, Tt, pt);
  out.tanks = trace ("two tanks", ut, yt, utv, ytv, Tt, 3);
  out.tanks.spill_share = [mean(st), mean(stv)];
  ## positioning axis
  pa = struct ("wn", 6, "zeta", 0.6, "K", 10, "ymin", 8, "ymax", 92);
  Ta = 0.02;
  [ua, ya] = greybox_record ("axis", Na, Ta, pa);
  [uav, yav] = greybox_record ("axis", Na, Ta, pa);
  out.axis = trace ("axis", ua, ya, uav, yav, Ta, 2);
  out.axis.stop_share = [mean(ya <= pa.ymin + 0.2 | ya >= pa.ymax - 0.2),
                         mean(yav <= pa.ymin + 0.2 | yav >= pa.ymax - 0.2)];

  plot_rig (fullfile (outdir, "fig_greybox_tanks.png"), Tt, out.tanks,
            "two tanks: level of the lower tank (cm)");
  plot_rig (fullfile (outdir, "fig_greybox_axis.png"), Ta, out.axis,
            "positioning axis: carriage position (mm)");
  write_md (fullfile (outdir, "greybox.md"), out, reduced);
  for f = {"tanks", "axis"}
    o = out.(f{1});
    printf (["%s: %s; validation simulation RMSE: best linear %.4g, ", ...
             "re-estimated %.4g, traced %.4g\n"], f{1},
            strjoin (o.R.effects, ", "), o.rmse_linear, o.R.rmse_before,
            o.R.rmse_final);
  endfor
endfunction

function o = trace (name, u, y, uv, yv, Ts, iterate)
  d = iddata (y, u, Ts, "InterSample", "zoh");
  dv = iddata (yv, uv, Ts, "InterSample", "zoh");
  M = srivc (iddata (y - mean (y), u - mean (u), Ts, "InterSample", "zoh"),
             [1 2 0]);
  [o.rmse_linear, o.linear_nn, o.sim_linear] = best_linear (u, y, uv, yv,
                                                            Ts);
  t_run = tic ();
  o.R = residtrace (d, M, "validation", dv, "iterate", iterate);
  o.elapsed = toc (t_run);
  o.name = name;
  ## residtrace's own re-estimate is linear too, with the levels and the
  ## initial state handled: the best linear model is the better of both
  if (o.R.rmse_before < o.rmse_linear)
    o.rmse_linear = o.R.rmse_before;
    o.linear_nn = [1 2 0];
    o.sim_linear = o.R.sim.before;
  endif
endfunction

## The best linear model: SRIVC on the estimation record with its means
## removed, simulated on the validation input with the same levels.
function [best, nn, ysim] = best_linear (u, y, uv, yv, Ts)
  best = Inf; nn = []; ysim = [];
  mu = mean (u); my = mean (y);
  d = iddata (y - my, u - mu, Ts, "InterSample", "zoh");
  for nf = 1:3
    for nb = 1:nf
      try
        M = srivc (d, [nb nf 0]);
        ys = simc (M, uv - mu, Ts) + my;
      catch
        continue;
      end_try_catch
      r = sqrt (mean ((yv - ys) .^ 2));
      if (isfinite (r) && r < best)
        best = r; nn = [nb nf 0]; ysim = ys;
      endif
    endfor
  endfor
endfunction

function plot_rig (file, Ts, o, label)
  warning ("off", "Octave:gnuplot-graphics");
  graphics_toolkit ("gnuplot");
  f = figure ("visible", "off", "position", [0 0 900 700]);
  S = o.R.sim;
  t = (0:numel (S.y) - 1)' * Ts;
  subplot (2, 1, 1);
  plot (t, S.y, "k", t, o.sim_linear, "b", t, S.final_simulation, "r");
  legend ("measured", sprintf ("best linear %s", mat2str (o.linear_nn)),
          "with the effects found", "location", "northeast");
  ylabel (label);
  title (sprintf ("%s, validation record, simulated from the input",
                  o.name));
  subplot (2, 1, 2);
  plot (t, S.y - o.sim_linear, "b", t, S.y - S.final_simulation, "r");
  legend ("best linear", "with the effects found");
  ylabel ("error"); xlabel ("time (s)");
  print (f, file, "-dpng");
  close (f);
endfunction

function write_md (file, out, reduced)
  fid = fopen (file, "w");
  fprintf (fid, "# Grey-box demo: two tanks and a positioning axis\n\n");
  if (reduced)
    fprintf (fid, "Reduced run (shorter records).\n\n");
  endif
  fprintf (fid, ["| rig | effects found (in order) | best linear model ", ...
                 "(validation simulation RMSE) | re-estimated start | ", ...
                 "with the effects | residtrace time (s) |\n"]);
  fprintf (fid, "|---|---|---|---|---|---|\n");
  for f = {"tanks", "axis"}
    o = out.(f{1});
    fprintf (fid, "| %s | %s | %.4g (%s) | %.4g | %.4g | %.0f |\n", o.name,
             strjoin (o.R.effects, ", "), o.rmse_linear,
             mat2str (o.linear_nn), o.R.rmse_before, o.R.rmse_final,
             o.elapsed);
  endfor
  for f = {"tanks", "axis"}
    o = out.(f{1});
    fprintf (fid, "\n## %s\n\n%s\n", o.name, o.R.table);
  endfor
  fclose (fid);
endfunction
