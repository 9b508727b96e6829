## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn {} {@var{c} =} residtrace_cand_order (@var{cur}, @var{ctx})
## Order candidate of @code{residtrace}: a missing pole or zero. The
## variants raise the denominator order by 1 or 2 and the numerator
## order of every input channel by 0, 1 or 2 (strictly proper models
## only); the model's integrators stay, other structural zeros of F are
## freed. Each variant is started from the current F times a factor at
## 1/3 and 3 times (order + 1) or 1/2 and 2 times (order + 2) the
## geometric mean of the current poles' moduli, and from the SVF start;
## the variant with the smallest BIC on the estimation data is kept; a
## variant whose fit sends an added pole beyond the samples (residualised
## by @code{residtrace_fit}) is not that variant and is dropped.
## Evidence: the poles and zeros of the chosen model and the drop in BIC.
## The candidate is built and fitted in the core
## (core/include/ctid/apps/residtrace/candidate_order.hpp,
## order_candidate, through @code{effect_sim_mex}, method "candidate").
## @end deftypefn

function c = residtrace_cand_order (cur, ctx)
  c = effect_sim_mex ("residtrace", "candidate", "order", cur, ctx.D,
                     residtrace_fitopts (ctx));
endfunction
