## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn {} {@var{c} =} residtrace_cand_sinusoid (@var{cur}, @var{ctx})
## Sinusoidal-disturbance candidate of @code{residtrace}: the strongest
## line of the periodogram of the current estimation residual, tested by
## Fisher's g = max I_k / sum I_k (p-value m (1 - g)^(m - 1), m bins).
## Bins where an input has a line of its own (periodogram above 20 times
## its median over the 21 neighbouring bins) are left out: a line there
## is driven by the input, i.e. missing dynamics, not a disturbance. The
## frequency is refined to the maximum of |sum e(t) exp(-i w t)| between
## the neighbouring bins; then y = x + a sin(w t) + b cos(w t) is fitted
## with the model by alternation. Evidence: frequency, amplitude with its
## standard deviation, g and its p-value.
##
## Only periods the records resolve are candidates: at least two cycles in
## the estimation record (of duration T_e) and one in each half of the
## validation record (T_v), w >= 4 pi / min (T_e, T_v), for the search and
## for the refined frequency alike. Over a cycle or less a sinusoid cannot
## be told from a level or a drift (a "sinusoid" at 0.00014 Hz, under one
## cycle of a simulated heated block's record, would be named).
##
## The phase of the disturbance on another record is unknown:
## @code{residtrace} keeps w, and fits a and b on each half of the
## validation residual to predict the other half (two-fold cross-fitting,
## so no sample is predicted by a fit that used it).
## The candidate is found and fitted in the core
## (core/include/ctid/apps/residtrace/candidate_sinusoid.hpp,
## sinusoid_candidate, through @code{effect_sim_mex}, method "candidate").
## @end deftypefn

function c = residtrace_cand_sinusoid (cur, ctx)
  o = residtrace_fitopts (ctx);
  o.validation_samples = numel (ctx.V.y);
  c = effect_sim_mex ("residtrace", "candidate", "sinusoid", cur, ctx.D, o);
endfunction
