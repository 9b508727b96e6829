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
## (the one with the smallest simulation error); the cascade of those
## poles, gains and level is the core's (@code{effect_sim_mex}, method
## "physstart"). The record's initial
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
## @end deftypefn

function [t, why] = residtrace_physcascade (cur, ctx, g, clip)
  t = [];
  why = "";
  D = ctx.D;
  if (! isempty (D.loop))
    why = "a cascade realisation in open loop only";
    return;
  endif
  types = {cur.channels.type};
  keep = ismember (types, {"input", "power", "clip"});
  if (any (! keep & ! strcmp (types, "const")) || ! any (keep))
    why = "channels other than inputs";
    return;
  endif
  if (! isempty (cur.out) && any (! strcmp ({cur.out.type}, "offset")))
    why = "output terms other than a level";
    return;
  endif
  r = roots (cur.F);
  ## an integrator: a pole at zero on the time scale of the samples (not
  ## of the fastest pole, which may be far beyond them)
  if (isempty (r) || any (abs (r) * D.Ts < 1e-9) || any (real (r) >= 0))
    why = "integrators or unstable poles";
    return;
  endif
  [~, i] = sort (abs (r));
  r = r(i);
  if (numel (r) == 1)
    p1 = 4 * abs (r(1)); p2 = abs (r(1));
  elseif (imag (r(1)) != 0)
    p1 = p2 = abs (r(1));        # a pair: the critically damped cascade
  else
    p1 = abs (r(2)); p2 = abs (r(1));
  endif
  chans = cur.channels(keep);
  W = residtrace_channels (chans, D.u, zeros (numel (D.y), 1));
  wbar = mean (W, 1);
  K = arrayfun (@(c) c.B(end), chans) / cur.F(end) * cur.F(1);
  y = D.y;
  sq = strcmp (g, "sqrt");
  if (sq)
    c0 = min (0, min (y) - 0.1 * (max (y) - min (y)));
  else
    c0 = 0;
  endif
  hbar = mean (y) - c0;
  if (hbar <= 0)
    why = "no positive level";
    return;
  endif
  ## the cascade whose linearisation has these poles and gains (the core's)
  c = effect_sim_mex ("residtrace", "physstart",
                      struct ("g", g, "p1", p1, "p2", p2, "K", K(:).',
                              "wbar", wbar, "hbar", hbar));
  al = c.alpha; ga = c.gamma; b = c.b; d = c.d;
  t = cur;
  for j = 1:numel (chans)
    chans(j).nb = 1;
    chans(j).B = b(j);
  endfor
  t.channels = chans;
  t.out = t.out([]);
  t.fixed = false (1, 2);
  S = min (20, max (1, ceil (D.Ts * max (p1, p2) / 0.1)));
  t.phys = struct ("kind", "cascade", "g", g, "d", d, "alpha", al,
                   "gamma", ga, "c", c0, "hi", Inf, "substeps", S,
                   "wbar", wbar, "yscale", std (y), "h0", y(1) - c0);
  t.F = c.F;
  if (clip)
    t.phys.spill = 0;                    # share of the overflow kept
    [~, z] = residtrace_physsim (t, D.u, D.Ts);
    best = Inf;
    for q = [0.7 0.8 0.9 0.95 0.99]
      tq = t;
      tq.phys.hi = quantile (z, q);
      e = y - residtrace_physsim (tq, D.u, D.Ts);
      if (e' * e < best)
        best = e' * e;
        hi = tq.phys.hi;
      endif
    endfor
    if (! isfinite (best))
      t = [];
      why = "no inner level to try";
      return;
    endif
    t.phys.hi = hi;
  endif
endfunction
