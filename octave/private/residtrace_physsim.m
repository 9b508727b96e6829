## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn {} {[@var{y}, @var{z}] =} residtrace_physsim (@var{model}, @var{u}, @var{Ts})
## Output of a @code{residtrace} model with a physical realisation
## (@code{model.phys}) on the input @var{u} (N-by-nu, held over
## each sampling interval), open loop. Two kinds:
## @table @asis
## @item "stop" (a state saturated with its velocity reset)
## F(p) x = sum_j B_j(p) w_j in observable canonical form, x1 = x (the
## output's dynamic part, y = x + c with c the model's output offset),
## x1' = -f1 x1 + x2 (every channel's relative degree at least 2, so the
## velocity x1' is a function of the state). The output is a position
## limited to [phys.lo, phys.hi] (output units): a sub-step that crosses a
## level ends at it with the velocity zero (x1 = L - c, x2 = f1 x1: an
## inelastic end stop); while held there, x1 and x2 stay and the other
## states evolve; the stop is left when the acceleration x2' = -f2 x1 + x3
## + (B w)_2 points away from it. Each sub-step is exact (matrix
## exponential) for the held channels; @code{phys.substeps} sub-steps per
## sampling interval are taken only in the intervals where a level is
## crossed. Starts at rest at x = 0 (the record's level), clipped.
## @item "cascade" (two first-order sections with the nonlinearity at the
## inner node)
## z' = sum_j b_j w_j + d - alpha g(z), 0 <= z <= phys.hi (an inner state
## that overflows), and h' = g(z) - gamma g(h), y = c + h <= phys.yhi
## (when present: an outer state that overflows; the share phys.spill of
## the water over phys.hi falls into h), g = sqrt (two
## tanks with Torricelli outflows; phys.g = "sqrt") or g(s) = s (a linear
## cascade, phys.g = "lin"). Classical Runge-Kutta in
## @code{phys.substeps} sub-steps per sample, the states projected onto
## their bounds after each; starts at the level @code{phys.h0} when
## given, the inner state at @code{phys.z0} or else at rest with it, and
## without h0 at rest for the first sample's channels.
## @end table
## @var{z}: the inner state ("cascade") or the position x + c ("stop").
## A cell of models gives their outputs side by side (the columns of
## @var{y} and @var{z}).
##
## The simulators are in the core
## (@file{core/include/ctid/apps/residtrace/physical_fit.hpp}, gateway
## @code{effect_sim_mex}, method "physsim"); this function converts the
## arguments (@code{residtrace_physopts}).
## @end deftypefn

function [y, z] = residtrace_physsim (model, u, Ts)
  if (iscell (model))
    N = rows (u);
    y = z = zeros (N, numel (model));
    for i = 1:numel (model)
      [y(:, i), z(:, i)] = residtrace_physsim (model{i}, u, Ts);
    endfor
    return;
  endif
  [W, o] = residtrace_physopts (model, u, Ts);
  [y, z] = effect_sim_mex ("residtrace", "physsim", W, o);
endfunction
