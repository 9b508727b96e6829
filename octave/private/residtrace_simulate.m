## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn  {} {[@var{y}, @var{x}, @var{uc}] =} residtrace_simulate (@var{model}, @var{u}, @var{Ts}, @var{loop}, @var{substeps})
## @deftypefnx {} {[@dots{}] =} residtrace_simulate (@dots{}, @var{thm})
## Simulated output of a @code{residtrace} model on the input @var{u}
## (N-by-nu), from rest. In closed loop the first input is replaced by
## r1 + C (r2 - y) (@var{loop}.r1 the external signal).
##
## The dynamic part is F(p) x = sum_j B_j(p) w_j(t - nk_j Ts) with the
## channel signals w_j of @code{residtrace_channels}; then y = x plus the
## output terms (offset, polynomial c2 x^2 + c3 x^3, sinusoid a sin(w t) +
## b cos(w t), t from the first sample).
##
## @itemize
## @item Open loop and no channel fed by the model's own velocity: the
## channels are computed from @var{u} and the linear part is integrated
## exactly (ZOH or FOH as the data's InterSample), as @code{simc} does.
## @item Coulomb friction (a @qcode{"signv"} channel), a nonlinearity of
## the output inside the dynamics (@qcode{"ypower"}: y^p of the model's
## own output, re-evaluated at each sub-step) or a closed loop
## (@var{loop} with fields @code{num}, @code{den} (controller C(q^-1)),
## @code{r1}, @code{r2}: u = r1 + C (r2 - y), y the simulated output):
## the model in observable canonical form is stepped through each
## sampling interval in @var{substeps} equal sub-steps, each exact (matrix
## exponential) for inputs held over the sub-step; sign(v) is re-evaluated
## at each sub-step from the simulated velocity v = dy/dt (or v = y for a
## first-order model: the output is then read as a velocity). The other
## inputs are held over the sampling interval (ZOH). In closed loop the
## channels of the controlled first input may be the input, a power or a
## clipped value of it (another kind is @code{residtrace:notSupported}).
## @end itemize
## With @var{thm} (N-by-np, the dynamic parameters at each sample as
## @code{residtrace_unpack} reads them) the model is time-varying: the
## sub-step of each sampling interval uses the parameters of its first
## sample (a single-input model in open loop is integrated with the
## parameters linear between the samples, as @code{simc} does).
## An output saturation (@code{out} term @qcode{"sat"}, levels c = [lo
## hi]) clips the output last: y = min (max (x + terms, lo), hi).
## @var{x} is the dynamic part alone, @var{uc} the input applied (equal to
## @var{u} in open loop). A model with a physical realisation
## (@code{model.phys}: an end stop, a tank cascade) is simulated as
## @code{residtrace_physsim} does (open loop only).
##
## The simulation runs in the core
## (core/include/ctid/apps/residtrace/simulate.hpp, simulate_model, gateway
## @code{effect_sim_mex}, method "simulate"); this function converts the
## arguments.
## @end deftypefn

function [y, x, uc] = residtrace_simulate (model, u, Ts, loop, substeps, thm)
  if (nargin < 6)
    thm = [];
  endif
  o = struct ("ts", Ts, "substeps", substeps, "loop", loop, "thm", thm);
  [y, x, uc] = effect_sim_mex ("residtrace", "simulate", model, u, o);
endfunction
