## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn  {} {@var{T} =} residtrace_suite (@var{set})
## @deftypefnx {} {@var{T} =} residtrace_suite (@var{set}, @var{outdir})
## Runs @code{residtrace} (one pass, as @code{test_residtrace} does) on the
## undeclared-effect suite @code{residtrace_cases (@var{set})}
## (tests/octave) and prints, per case, the true effect, the one named
## first, the validation RMSE before (the re-estimated model) and after
## (a simulation; for drift the tracked and for coloured noise the
## predicted figure too), the score and the time. Set 1 is what
## @code{test_residtrace} checks; set 2 (other seeds, systems, orders,
## inputs and noise levels) is run by hand with this script. Writes
## @var{outdir}/residtrace_suite_@var{set}.md (default "results").
## @end deftypefn

function T = residtrace_suite (set = 2, outdir = "results")
  here = fileparts (mfilename ("fullpath"));
  addpath (fullfile (here, "..", "..", "tests", "octave"));
  demo_prepare (outdir);
  cases = residtrace_cases (set);
  T = struct ("effect", {}, "found", {}, "rmse_before", {},
              "rmse_after", {}, "tracked", {}, "prediction", {},
              "score", {}, "variant", {}, "seconds", {});
  for k = 1:numel (cases)
    c = cases(k);
    t0 = tic ();
    R = residtrace (c.data, c.M, "validation", c.datav, "iterate", 1);
    sc = NaN; var = "";
    if (! isempty (R.ranking) && ! strcmp (R.effect, "none"))
      i = find (strcmp ({R.ranking.effect}, R.effect), 1);
      if (! isempty (i))
        sc = R.ranking(i).score; var = R.ranking(i).variant;
      endif
    endif
    T(end+1) = struct ("effect", c.effect, "found", R.effect,
                       "rmse_before", R.rmse_before,
                       "rmse_after", R.rmse_after,
                       "tracked", R.rmse_after_tracked,
                       "prediction", R.rmse_after_prediction,
                       "score", sc, "variant", var, "seconds", toc (t0));
    t = T(end);
    printf (["%-20s -> %-20s %.4g -> %.4g (tracked %.4g, prediction ", ...
             "%.4g) score %.3g  %s  (%.0f s)\n"],
            t.effect, t.found, t.rmse_before, t.rmse_after, t.tracked,
            t.prediction, t.score, t.variant, t.seconds);
    fflush (stdout);
  endfor
  fid = fopen (fullfile (outdir, sprintf ("residtrace_suite_%d.md", set)),
               "w");
  fprintf (fid, ["| true effect | named first | RMSE before -> after ", ...
                 "(simulation) | tracked / prediction | score | variant | ", ...
                 "time (s) |\n|---|---|---|---|---|---|---|\n"]);
  for k = 1:numel (T)
    t = T(k);
    fprintf (fid, ["| %s | %s | %.4g -> %.4g | %.4g / %.4g | %.3g | ", ...
                   "%s | %.0f |\n"],
             t.effect, t.found, t.rmse_before, t.rmse_after, t.tracked,
             t.prediction, t.score, t.variant, t.seconds);
  endfor
  fclose (fid);
endfunction
