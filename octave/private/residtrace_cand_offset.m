## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn {} {@var{c} =} residtrace_cand_offset (@var{cur}, @var{ctx})
## Offset candidate of @code{residtrace}: a constant entering with the
## input (an extra regressor 1 in the filtered regression, its own gain
## b_c/F(p)) or added to the output (y = x + c; not with an integrating
## model, where a constant output is an initial condition). The variant
## with the smaller BIC on the estimation data is kept. Evidence: the
## constant with its standard deviation, in input units (b_c over the
## input's static numerator) for the input offset.
## The candidate is built and fitted in the core
## (core/include/ctid/apps/residtrace/candidate.hpp, offset_candidate,
## through @code{effect_sim_mex}, method "candidate").
## @end deftypefn

function c = residtrace_cand_offset (cur, ctx)
  c = effect_sim_mex ("residtrace", "candidate", "offset", cur, ctx.D,
                     residtrace_fitopts (ctx));
endfunction
