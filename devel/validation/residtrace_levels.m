## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn {} {@var{u} =} residtrace_levels (@var{N}, @var{Ts}, @var{tmin}, @var{tmax}, @var{lo}, @var{hi})
## A staircase input of @var{N} samples (sampling interval @var{Ts}):
## levels drawn uniformly in [@var{lo}, @var{hi}], each held for a
## duration drawn uniformly in [@var{tmin}, @var{tmax}] (at least one
## sample), from the generator @code{rand} (seed it first). The input of
## the simulated records (@code{residtrace_sim_records}) and of the tests of
## residtrace's physical realisations.
## @end deftypefn

function u = residtrace_levels (N, Ts, tmin, tmax, lo, hi)
  u = zeros (N, 1);
  k = 1;
  while (k <= N)
    L = max (1, round ((tmin + (tmax - tmin) * rand) / Ts));
    u(k:min (N, k + L - 1)) = lo + (hi - lo) * rand;
    k += L;
  endwhile
endfunction
