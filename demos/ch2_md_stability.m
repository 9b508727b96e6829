## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn {} {} ch2_md_stability (@var{fid}, @var{names}, @var{rej}, @var{rej0}, @var{tsiv})
## Helper of the Chapter 2 demos: writes to @var{fid} the paragraph on the
## stability test (eq. 3.10) for the IV methods 2..M of @var{names}: the
## rejections per run @var{rej} (nruns-by-M), those of run 1 with the IV
## stage never started @var{rej0} (1-by-M), and @var{tsiv} in s.
## @end deftypefn

function ch2_md_stability (fid, names, rej, rej0, tsiv)
  M = numel (names);
  fprintf (fid, "Stability test (eq. 3.10): estimates refused on their way to the ");
  fprintf (fid, "auxiliary model, mean [max] per run: ");
  for m = 2:M
    fprintf (fid, "%s %.1f [%d]%s", names{m}, mean (rej(:, m)), max (rej(:, m)),
             ch2_ifelse_str (m < M, ", ", ". "));
  endfor
  fprintf (fid, "In run 1 the counts with the IV stage never started (RLSSVF ");
  fprintf (fid, "phase only) are %d / %d / %d against %d / %d / %d with ",
           rej0(2:M), rej(1, 2:M));
  fprintf (fid, "tsiv = %g s, ", tsiv);
  fprintf (fid, "i.e. %d / %d / %d refusals during the IV stage. ",
           rej(1, 2:M) - rej0(2:M));
  same = all (all (rej(:, 2:M) == rej(:, 2)));
  fprintf (fid, "The counts of the three IV variants are %s in every run%s.\n",
           ch2_ifelse_str (same, "the same", "not the same"),
           ch2_ifelse_str (same, [", as they are when all refusals fall in ", ...
                                  "the shared RLSSVF phase"], ""));
endfunction
