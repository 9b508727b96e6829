## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn {} {} ch2_md_error_table (@var{fid}, @var{names}, @var{E}, @var{E0}, @var{yard}, @var{winname}, @var{nruns}, @var{figs})
## Helper of the Chapter 2 demos: writes to @var{fid} the Markdown table of
## the mean relative errors (eq. 2.33) per method of @var{names} in the two
## windows @var{winname}: @var{E} (nruns-by-3-by-M-by-2) the per-run window
## means, @var{E0} (rows 1-2) those of noise-free RLSSVF, @var{yard}
## (M-by-3, NaN rows for none) the yardstick for the second window, and
## @var{figs} the thesis' figures named in the text, e.g. "2.13, 2.14".
## @end deftypefn

function ch2_md_error_table (fid, names, E, E0, yard, winname, nruns, figs)
  M = numel (names);
  Em = mean (E, 1);                               # 1 x 3 x M x 2
  fprintf (fid, "### Mean relative error (eq. 2.33, %%), averaged over the window and over %d runs\n\n", nruns);
  fprintf (fid, "The thesis gives these only as figures (%s); the yardstick is ",
           figs);
  fprintf (fid, "the independent implementation of the implementation notes (item 8, ");
  fprintf (fid, "10 runs, last 500 s).\n\n");
  fprintf (fid, "| method | %s: a1 | a2 | b0 | %s: a1 | a2 | b0 | yardstick, last 500 s: a1 / a2 / b0 |\n",
           winname{:});
  fprintf (fid, "|---|---|---|---|---|---|---|---|\n");
  fprintf (fid, "| RLSSVF noise-free | %.2f | %.2f | %.2f | %.2f | %.2f | %.2f | - |\n",
           E0(1, :), E0(2, :));
  for m = 1:M
    if (isnan (yard(m, 1)))
      ys = "-";
    else
      ys = sprintf ("%.1f / %.1f / %.1f", yard(m, :));
    endif
    fprintf (fid, "| %s | %.2f | %.2f | %.2f | %.2f | %.2f | %.2f | %s |\n",
             names{m}, Em(1, :, m, 1), Em(1, :, m, 2), ys);
  endfor
endfunction
