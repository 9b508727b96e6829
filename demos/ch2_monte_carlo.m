## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn {} {[@var{R}, @var{S}, @var{stats}, @var{thm1}, @var{rej}, @var{data1}, @var{runinfo}, @var{tmain}, @var{textra}] =} ch2_monte_carlo (@var{theta}, @var{nruns}, @var{M}, @var{main}, @var{simrun}, @var{estfun}, @var{statfun})
## Helper of the Chapter 2 demos: the Monte Carlo loop over @var{nruns}
## noise runs and @var{M} methods.
##
## Run s sets randn ("state", s) and calls
## @code{[data, info] = @var{simrun} (s)} for its iddata and a row of
## per-run values (stored as row s of @var{runinfo}); then method m is
## @code{[thm, info] = @var{estfun} (m, data)}, N-by-3 estimates of the
## true parameters @var{theta}. Returned are the sums over runs of the
## relative errors in percent, eq. (2.33), @var{R}, and of the estimates,
## @var{S} (both N-by-3-by-M), the rows
## @code{@var{statfun} (thm, rel)} per run and method in
## @var{stats} (nruns-by-K-by-M), the estimates of run 1 @var{thm1}, the
## stability rejections @var{rej} (nruns-by-M), the data of run 1
## @var{data1}, and the time spent on the simulations and the methods
## @var{main} (@var{tmain}) and on the other methods (@var{textra}).
## @end deftypefn

function [R, S, stats, thm1, rej, data1, runinfo, tmain, textra] = ...
         ch2_monte_carlo (theta, nruns, M, main, simrun, estfun, statfun)
  N = rows (theta);
  R = zeros (N, 3, M);            # sum over runs of the relative errors (%)
  S = zeros (N, 3, M);            # sum over runs of the estimates
  thm1 = zeros (N, 3, M);         # run 1
  stats = [];
  runinfo = [];
  rej = zeros (nruns, M);
  tmain = 0;
  textra = 0;
  for s = 1:nruns
    tic_run = tic;
    randn ("state", s);
    [data, ri] = simrun (s);
    if (! isempty (ri))
      runinfo(s, :) = ri;
    endif
    if (s == 1)
      data1 = data;
    endif
    tmain += toc (tic_run);
    for m = 1:M
      tic_m = tic;
      [thm, info] = estfun (m, data);
      rel = abs ((theta - thm) ./ theta) * 100;   # eq. (2.33)
      R(:, :, m) += rel;
      S(:, :, m) += thm;
      st = statfun (thm, rel);
      stats(s, 1:numel (st), m) = st;
      rej(s, m) = info.stability_rejections;
      if (s == 1)
        thm1(:, :, m) = thm;
      endif
      if (any (m == main))
        tmain += toc (tic_m);
      else
        textra += toc (tic_m);
      endif
    endfor
  endfor
endfunction
