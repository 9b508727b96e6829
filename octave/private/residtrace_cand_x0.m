## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn {} {@var{c} =} residtrace_cand_x0 (@var{cur}, @var{ctx})
## Unknown-initial-state candidate of @code{residtrace}: the record did
## not start at rest. The model's free response from an initial state x0
## (n basis functions: the output of the model in observable canonical
## form started from each unit state, no input) is fitted by least squares
## on each record's simulation error, as MATLAB's @code{compare} estimates
## x0: n parameters per record, declared in the result (every simulation
## of a model with this effect is "simulated from the input plus an
## estimated initial state"). Not with a split record (the validation part
## starts where the simulation of the estimation part left it) or a
## closed loop. Evidence: the share of the estimation residual's mean
## square the free response removes, and the estimated x0.
## The candidate is fitted in the core
## (core/include/ctid/apps/residtrace/candidate_x0.hpp, x0_candidate,
## through @code{effect_sim_mex}, method "candidate").
## @end deftypefn

function c = residtrace_cand_x0 (cur, ctx)
  o = residtrace_fitopts (ctx);
  o.validation_continues = ! isempty (ctx.V.pre);
  c = effect_sim_mex ("residtrace", "candidate", "initial_state", cur, ctx.D,
                     o);
endfunction
