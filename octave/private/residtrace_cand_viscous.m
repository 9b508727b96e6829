## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn {} {@var{c} =} residtrace_cand_viscous (@var{cur}, @var{ctx})
## Missing-viscous-friction candidate of @code{residtrace}: applicable
## when the model's coefficient of the velocity term is fixed at zero
## (a structural zero of F: the coefficient of p^1 for a model of order
## >= 2, whose output is read as a position; of p^0 for a first-order
## model, read as a velocity). The coefficient is freed, i.e. the
## regressor -p y_f (resp. -y_f) joins the filtered regression. Evidence:
## the fitted coefficient with its standard deviation and, for a
## numerator b0 alone, the viscous coefficient f / b0 in input units per
## unit velocity.
## The candidate is built and fitted in the core
## (core/include/ctid/apps/residtrace/candidate.hpp, viscous_candidate,
## through @code{effect_sim_mex}, method "candidate").
## @end deftypefn

function c = residtrace_cand_viscous (cur, ctx)
  c = effect_sim_mex ("residtrace", "candidate", "viscous", cur, ctx.D,
                     residtrace_fitopts (ctx));
endfunction
