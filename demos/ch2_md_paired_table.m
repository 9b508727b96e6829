## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn {} {@var{better} =} ch2_md_paired_table (@var{fid}, @var{E}, @var{n2}, @var{n3}, @var{nruns})
## Helper of the Chapter 2 demos: writes to @var{fid} the Markdown table of
## the paired difference, method 2 (@var{n2}) minus method 3 (@var{n3}), of
## the mean relative errors in the first window, @var{E}(:, :, [2 3], 1),
## per parameter and for the mean of the three, with twice its standard
## error over @var{nruns} runs. @var{better} (1-by-3) is true where method
## 3 is significantly better.
## @end deftypefn

function better = ch2_md_paired_table (fid, E, n2, n3, nruns)
  pn = {"a1", "a2", "b0"};
  fprintf (fid, "| parameter | %s (%%) | %s (%%) | %s - %s (+- 2 s.e.) | %s better in | verdict |\n",
           n2, n3, n2, n3, n3);
  fprintf (fid, "|---|---|---|---|---|---|\n");
  better = false (1, 3);
  for i = 1:3
    d = E(:, i, 2, 1) - E(:, i, 3, 1);
    se = std (d) / sqrt (nruns);
    better(i) = mean (d) > 2 * se;
    if (better(i))
      v = [n3 " better"];
    elseif (mean (d) < -2 * se)
      v = [n3 " worse"];
    else
      v = "no significant difference";
    endif
    fprintf (fid, "| %s | %.2f | %.2f | %+.2f +- %.2f | %d of %d runs | %s |\n",
             pn{i}, mean (E(:, i, 2, 1)), mean (E(:, i, 3, 1)), mean (d),
             2 * se, sum (d > 0), nruns, v);
  endfor
  dall = mean (E(:, :, 2, 1), 2) - mean (E(:, :, 3, 1), 2);
  fprintf (fid, "| mean of the three | %.2f | %.2f | %+.2f +- %.2f | %d of %d runs | %s |\n\n",
           mean (mean (E(:, :, 2, 1))), mean (mean (E(:, :, 3, 1))),
           mean (dall), 2 * std (dall) / sqrt (nruns), sum (dall > 0), nruns,
           ch2_ifelse_str (mean (dall) > 2 * std (dall) / sqrt (nruns),
                           [n3 " better"], "not shown"));
endfunction
