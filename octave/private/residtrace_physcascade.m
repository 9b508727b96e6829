## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn {} {[@var{t}, @var{why}] =} residtrace_physcascade (@var{cur}, @var{ctx}, @var{g}, @var{clip})
## A "cascade" realisation (@code{residtrace_physsim}) of the current
## @code{residtrace} model @var{cur}, fitted on the estimation record
## (@code{residtrace_physfit}): two first-order sections, the nonlinearity
## @var{g} ("sqrt": square-root outflows, two tanks by Torricelli's law;
## "lin": linear) at both nodes. With @var{clip}, the inner state limited
## above (an upper tank that overflows, its level estimated) and the share
## of its overflow that falls into the outer section estimated
## (@code{phys.spill} in [0, 1], started at 0: all of it lost). (The
## outer state's level, @code{phys.yhi}, is added by
## @code{residtrace_cand_saturation} to a fitted cascade.)
##
## Started at the model's linearisation: the current model's two slowest
## poles (the faster one upstream; a first-order model: its pole
## downstream and four times it upstream; a complex pair: two real poles
## at its natural frequency), its static gains, the output
## level c at min(0, min(y) - 0.1 range(y)) for square-root nodes (a
## level measured from the outlet starts at c = 0) and 0 for linear ones;
## the inner level on the quantiles 0.7-0.99 of the unclipped inner state
## (the one with the smallest simulation error). The record's initial
## state is a parameter: the cascade starts at rest at the outer level
## @code{phys.h0} (the inner one in balance with it), started at the
## first sample, fitted with the others and kept for any other record (as
## a linear model's output level is). A cascade started at rest for the
## first sample's input instead stalls at several times the linear
## model's error on a record that does not start there (a simulated
## cascaded-tanks record starts 4 V below it). It competes with the
## other variants of its candidate by BIC on the estimation record
## (@code{residtrace_select}) whatever the estimation residual looks like
## (the fit costs little; a gate on a quadratic dependence of the residual
## on the model output would keep it out of most simulated records of the
## Cascaded Tanks benchmark). Applicable in open loop,
## to a model of stable poles without integrators (a pole at zero on the
## time scale of the samples, |p| Ts < 1e-9) whose channels are
## inputs or static functions of them (an input constant is dropped: the
## inflow's constant d replaces it). @var{t} is
## [] with the reason @var{why} otherwise.
## The template is built in the core
## (core/include/ctid/apps/residtrace/physical_model.hpp,
## cascade_template, through @code{effect_sim_mex}, method
## "physcascade").
## @end deftypefn

function [t, why] = residtrace_physcascade (cur, ctx, g, clip)
  [t, why] = effect_sim_mex ("residtrace", "physcascade", cur, ctx.D,
                             struct ("g", g, "clip", logical (clip)));
endfunction
