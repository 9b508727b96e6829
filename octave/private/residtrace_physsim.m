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
## A cell of "cascade" models of one structure (channels, nonlinearity)
## gives their outputs side by side, in one pass over the samples (the
## columns of @var{y}; for a Jacobian).
##
## The simulators are in the core
## (@file{core/include/ctid/simulation/physical_realisations.hpp}, gateway
## @code{physsim_mex}); this function builds the channel signals and the
## options.
## @end deftypefn

function [y, z] = residtrace_physsim (model, u, Ts)
  batch = iscell (model);
  if (batch)
    models = model;
    model = models{1};
  else
    models = {model};
  endif
  P = model.phys;
  chans = model.channels;
  N = rows (u);
  W = residtrace_channels (chans, u, zeros (N, 1));
  for j = 1:numel (chans)
    k = chans(j).nk;
    if (k > 0)
      W(:, j) = [zeros(k, 1); W(1:end-k, j)];
    endif
  endfor
  switch (P.kind)
    case "stop"
      [y, z] = sim_stop (model, W, Ts);
    case "cascade"
      [y, z] = sim_cascade (models, W, Ts);
    otherwise
      error ("residtrace:notSupported", "residtrace: realisation '%s'",
             P.kind);
  endswitch
endfunction

function c = out_offset (model)
  c = 0;
  for k = 1:numel (model.out)
    if (strcmp (model.out(k).type, "offset"))
      c += model.out(k).c(1);
    endif
  endfor
endfunction

function [y, pos] = sim_stop (model, W, Ts)
  P = model.phys;
  F = model.F(:).' / model.F(1);
  n = numel (F) - 1;
  m = columns (W);
  Bm = zeros (n, m);
  for j = 1:m
    b = model.channels(j).B(:) / model.F(1);
    Bm(n-numel(b)+1:n, j) = b;
  endfor
  c = out_offset (model);
  o = struct ("kind", "stop", "ts", Ts, "f", F(2:end), "b", Bm,
              "substeps", P.substeps);
  if (isfinite (P.lo))
    o.lo = P.lo - c;                     # the levels of x
  endif
  if (isfinite (P.hi))
    o.hi = P.hi - c;
  endif
  pos = physsim_mex ("residtrace", W, o) + c;
  y = pos;
endfunction

function [y, z] = sim_cascade (models, W, Ts)
  ## models: a cell of models of one structure, their outputs side by side
  ## (the columns of y), in one pass over the samples
  K = numel (models);
  m = columns (W);
  b = zeros (m, K);
  d = al = ga = top = c = z0 = h0 = ho = sp = zeros (1, K);
  S = 1;
  for i = 1:K
    Mi = models{i};
    for j = 1:m
      b(j, i) = Mi.channels(j).B(end);
    endfor
    P = Mi.phys;
    d(i) = P.d; al(i) = P.alpha; ga(i) = P.gamma; top(i) = P.hi;
    c(i) = P.c;
    ho(i) = Inf;
    if (isfield (P, "yhi"))
      ho(i) = P.yhi - P.c;               # the output's level, of h
    endif
    sp(i) = NaN;
    if (isfield (P, "spill"))
      sp(i) = P.spill;
    endif
    [z0(i), h0(i)] = residtrace_cascade_levels (P);
    S = max (S, P.substeps);
  endfor
  ## the simulator takes a level (an initial state) for all sets or none:
  ## sets that differ in that are simulated in separate passes
  key = [isfinite(z0); isfinite(top); isfinite(ho); isfinite(sp)];
  [~, ~, grp] = unique (key.', "rows");
  if (any (grp != grp(1)))
    y = z = zeros (rows (W), K);
    for g = unique (grp).'
      i = grp == g;
      [y(:, i), z(:, i)] = sim_cascade (models(i), W, Ts);
    endfor
    return;
  endif
  o = struct ("kind", "cascade", "ts", Ts, "g", models{1}.phys.g, "b", b,
              "d", d, "alpha", al, "gamma", ga, "c", c, "substeps", S);
  if (key(1, 1))
    o.z0 = z0; o.h0 = h0;
  endif
  if (key(2, 1))
    o.hi = top;
  endif
  if (key(3, 1))
    o.ho = ho;
  endif
  if (key(4, 1))
    o.spill = sp;
  endif
  [y, z] = physsim_mex ("residtrace", W, o);
endfunction
