## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn {} {@var{r} =} mc_sd_ratio (@var{name}, @var{runs}, @var{fun})
## The Monte Carlo loop of the sd checks (@code{freq_mc},
## @code{oe_miso_mc}): @var{fun} () returns the estimate and its reported
## standard deviations; after one warm-up call (randn state 1) it runs
## @var{runs} times and prints and returns the ratio of the spread to the
## mean reported sd per parameter, then the ratio of the robust spread
## (1.4826 median absolute deviation: insensitive to the few runs whose
## loss has its global minimum elsewhere, e.g. a zero traded for delay).
## @end deftypefn

function r = mc_sd_ratio (name, runs, fun)
  randn ("state", 1);
  [th1, sd1] = fun ();
  th = zeros (numel (th1), runs);
  sd = th;
  t0 = cputime ();
  t_run = tic ();
  for k = 1:runs
    [th(:, k), sd(:, k)] = fun ();
  endfor
  r = (std (th, 0, 2) ./ mean (sd, 2)).';
  mad = 1.4826 * median (abs (th - median (th, 2)), 2);
  printf ("%s, %d runs (%.0f s, %.0f s CPU): spread / reported sd = %s\n",
          name, runs, toc (t_run), cputime () - t0, mat2str (r, 3));
  printf ("  robust spread (1.4826 MAD) / reported sd = %s\n",
          mat2str ((mad ./ mean (sd, 2)).', 3));
endfunction
