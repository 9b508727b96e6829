## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn {} {@var{c} =} residtrace_cand_saturation (@var{cur}, @var{ctx})
## Saturation candidate of @code{residtrace}: a level that a signal of the
## system cannot pass, with the level(s) estimated.
## @itemize
## @item Output saturation (a sensor range, a position at its end stop):
## y = min (max (x, lo), hi), x the model output; upper, lower or both
## levels. Fitted as censored data (@code{residtrace_fit}): where the
## model output lies beyond a level the sample tells nothing about the
## linear part.
## @item Saturation of an inner state (a tank that overflows, a valve at
## its end stop): the model's denominator is split into its first-order
## sections (real poles, complex pairs), F = F_a F_b; the node z =
## F_a(0)/F_a(p) u (static gain 1, so its level is in input units) is
## clipped, and y = B(p)/F_b(p) clip(z) is re-estimated by SRIVC. Every
## split of the sections into upstream F_a and downstream F_b is tried
## (models of at most four sections, no integrators, open loop). The
## input itself (F_a = 1) is the static nonlinearity's clipped input.
## @end itemize
## Levels: for each variant, the level minimising the squared error of the
## current model with the clip (its gain refitted by least squares) on a
## grid of 25 quantiles of the clipped signal (between its median and its
## maximum, resp. minimum), refined by a golden-section search between the
## grid neighbours; the side (upper, lower, both) by the BIC of
## this screening. Each node's variant and the output's are then fitted
## and the one with the smallest BIC on the estimation data is kept; its
## level is searched again with the fitted model (the gain refitted with
## each level), and the model fitted again, while the BIC falls (at most
## three rounds). Evidence: the
## level(s), the share of samples at a level, the node's poles.
## @itemize
## @item An end stop: the output is a position, a state of the
## model's realisation (observable canonical form, x1 = y, the velocity
## a state when every channel's relative degree is at least two), held
## at a level with its velocity reset to zero while the model pushes it
## into the stop (@code{residtrace_physsim}, kind "stop").
## @item An inner state of a two-section cascade that overflows (a tank
## cascade): z' = b u + d - alpha g(z), z <= h, y = c + x with x' = g(z)
## - gamma g(x), g a square root (Torricelli) or linear, a share of the
## overflow falling into the outer section; and the same with the outer
## state limited too (y <= yhi: both tanks overflow)
## (@code{residtrace_physcascade}).
## @end itemize
## These two are fitted on their simulation error, all their parameters
## and levels together (@code{residtrace_physfit}), and compared with the
## other variants by the same BIC. A cascade whose inner state sits at its
## level on more than half of the estimation samples is dropped: that is
## not an overflow but another structure (the inner section held full
## and its spill feeding the outer one: a single tank).
## @end deftypefn

function c = residtrace_cand_saturation (cur, ctx)
  c = residtrace_cand ("saturation");
  if (any (strcmp ({cur.out.type}, "sat"))
      || any (strcmp ({cur.channels.type}, "node"))
      || ! isempty (cur.phys))
    c.reason = "the model has a saturation already";
    return;
  endif
  D = ctx.D;
  y = D.y;
  x = y - cur.e_est;                     # the current model's output
  tmpls = {}; names = {}; starts = {};
  ## output saturation: the side(s) by the screening's BIC
  [best, lv, side] = best_side (y, x);
  if (isfinite (best))
    tout = cur;
    tout.out(end+1) = struct ("type", "sat", "c", lv, "cstd", [NaN NaN],
                              "omega", 0);
    nout = sprintf ("output, %s level", side);
    tmpls{end+1} = tout; starts{end+1} = {cur.F}; names{end+1} = nout;
  endif
  ## inner-node saturation
  [nt, nn] = node_templates (cur, ctx, y, x);
  tmpls = [tmpls, nt]; names = [names, nn];
  for k = 1:numel (nt)
    starts{end+1} = {nt{k}.F};
  endfor
  ## physical realisations: a state saturated with its velocity
  ## reset (an end stop), and a two-section cascade whose inner state
  ## overflows (square-root or linear nodes); fitted here on their
  ## simulation error and only compared by residtrace_select
  ph = {}; pn = {};
  [t, nm] = stop_template (cur, ctx, y, x);
  if (! isempty (t))
    ph{end+1} = t; pn{end+1} = nm;
  endif
  for g = {"sqrt", "lin"}
    t = residtrace_physcascade (cur, ctx, g{1}, true);
    if (! isempty (t))
      ph{end+1} = t;
      pn{end+1} = sprintf ("inner state of a %s cascade, upper level", g{1});
    endif
  endfor
  for k = 1:numel (ph)
    m = residtrace_physfit (ph{k}, D, ctx);
    if (m.ok && strcmp (m.phys.kind, "cascade"))
      ## a cascade's fit from the linearisation often ends on its
      ## iteration budget: restarted once from where it ended
      m2 = residtrace_physfit (m, D, ctx);
      if (m2.ok && m2.bic < m.bic)
        m = m2;
      endif
    endif
    m = overflowing (m, D);
    if (m.ok && strcmp (m.phys.kind, "cascade"))
      ## the lower tank's rim too, started from this fit with the rim at
      ## the highest sample (a fit of its own from the linearisation
      ## stalls where the clipped output hides the other parameters); a
      ## rim the fitted output never reaches is not estimated: dropped
      t = m;
      t.phys.yhi = max (y);
      mo = overflowing (residtrace_physfit (t, D, ctx), D);
      if (mo.ok)
        yo = y - mo.e_est;
        mo.ok = any (yo >= mo.phys.yhi - 1e-9 * abs (mo.phys.yhi));
      endif
      if (mo.ok)
        mo.fitted = true;
        tmpls{end+1} = mo; starts{end+1} = {};
        names{end+1} = sprintf (["inner and outer states of a %s ", ...
                                 "cascade, upper levels"], m.phys.g);
      endif
    endif
    if (m.ok)
      m.fitted = true;
      tmpls{end+1} = m; names{end+1} = pn{k}; starts{end+1} = {};
    endif
  endfor
  if (isempty (tmpls))
    c.reason = "no level to try";
    return;
  endif
  [m, c.variants] = residtrace_select (tmpls, names, D, ctx, starts);
  if (isempty (m))
    c.reason = "the estimation failed";
    c.failed = true;
    return;
  endif
  for it = 1:3 * isempty (m.phys)   # the levels and the model, alternately
    [m, better] = refine (m, cur, ctx);
    if (! better)
      break;
    endif
  endfor
  c.applicable = true;
  c.model = m;
  c.variant = m.variant_;
  c.nadd = m.np - cur.np;
  if (! isempty (m.phys))
    P = m.phys;
    if (strcmp (P.kind, "stop"))
      lv = [P.lo P.hi];
      z = y - m.e_est;
      what = "output (a position) held at";
    else
      lv = [-Inf P.hi];
      [~, z] = residtrace_physsim (m, D.u, D.Ts);
      what = sprintf ("inner state of the %s cascade limited to", P.g);
    endif
    share = mean (z >= lv(2) - 1e-9 * abs (lv(2)) | z <= lv(1));
    txt = sprintf ("%s [%.4g, %.4g] (%.1f %% of the estimation samples)",
                   what, lv(1), lv(2), 100 * share);
    if (isfield (P, "yhi"))              # the outer state (the output)
      yo = y - m.e_est;
      so = mean (yo >= P.yhi - 1e-9 * abs (P.yhi));
      txt = sprintf ("%s; output limited to %.4g (%.1f %%)", txt, P.yhi,
                     100 * so);
    endif
    c.evidence = struct ("term", "levels [lo hi]", "value", lv,
                         "std", NaN, "share", share, "text", txt);
  elseif (any (strcmp ({m.out.type}, "sat")))
    lv = m.out(strcmp ({m.out.type}, "sat")).c;
    xo = y - m.e_est;
    share = mean (xo >= lv(2) | xo <= lv(1));
    c.evidence = struct ("term", "output levels [lo hi]", "value", lv,
                         "std", NaN, "share", share,
                         "text", sprintf (["output saturated at [%.4g, ", ...
                                           "%.4g] (%.1f %% of the ", ...
                                           "estimation samples)"],
                                          lv(1), lv(2), 100 * share));
  else
    j = find (strcmp ({m.channels.type}, "node"), 1);
    P = m.channels(j).param;
    z = residtrace_channels (m.channels(j), D.u, 0, 0);
    share = mean (z >= P.hi | z <= P.lo);
    c.evidence = struct ("term", "node levels [lo hi] (input units)",
                         "value", [P.lo P.hi], "std", NaN, "share", share,
                         "poles_upstream", roots (P.Fa),
                         "text", sprintf (["inner node after the pole(s) ", ...
                                           "%s clipped at [%.4g, %.4g] ", ...
                                           "(input units; %.1f %% of the ", ...
                                           "samples)"],
                                          num2str (roots (P.Fa).', 4),
                                          P.lo, P.hi, 100 * share));
  endif
endfunction

## The level(s) of an output saturation of the model output x that best
## explain y (grid of 25 quantiles of x beyond its median).
function lv = out_levels (y, x, side)
  lv = [];
  r = y;
  hi = Inf; lo = -Inf;
  if (any (strcmp (side, {"upper", "both"})))
    hi = best_level (@(L) sum ((r - min (x, L)) .^ 2), x, "upper");
  endif
  if (any (strcmp (side, {"lower", "both"})))
    lo = best_level (@(L) sum ((r - max (min (x, hi), L)) .^ 2), x, "lower");
  endif
  if (isempty (hi) || isempty (lo))
    return;
  endif
  lv = [lo hi];
endfunction

## The level on the quantile grid minimising f; [] when the signal is flat.
function L = best_level (f, z, side)
  q = linspace (0.5, 0.995, 25);
  zs = sort (z);
  n = numel (zs);
  if (strcmp (side, "lower"))
    q = 1 - q;
  endif
  grid = unique (zs(max (1, min (n, round (q * n)))));
  if (numel (grid) < 2)
    L = [];
    return;
  endif
  v = arrayfun (f, grid);
  [~, i] = min (v);
  ## golden-section search between the grid neighbours
  lo = grid(max (i - 1, 1)); hi = grid(min (i + 1, numel (grid)));
  g = (sqrt (5) - 1) / 2;
  a = hi - g * (hi - lo); b = lo + g * (hi - lo);
  fa = f (a); fb = f (b);
  for it = 1:12
    if (fa < fb)
      hi = b; b = a; fb = fa; a = hi - g * (hi - lo); fa = f (a);
    else
      lo = a; a = b; fa = fb; b = lo + g * (hi - lo); fb = f (b);
    endif
  endfor
  L = grid(i);
  if (min (fa, fb) < v(i))
    L = ifelse_ (fa < fb, a, b);
  endif
endfunction

function v = ifelse_ (c, a, b)
  if (c)
    v = a;
  else
    v = b;
  endif
endfunction

## Inner-node variants: each split of F's sections into upstream F_a and
## downstream F_b, the level(s) of clip(z) chosen on the grid with the
## current model's gain refitted by least squares.
function [tmpls, names] = node_templates (cur, ctx, y, x)
  tmpls = {}; names = {};
  ins = find (strcmp ({cur.channels.type}, "input"));
  if (! isempty (ctx.D.loop) || numel (ins) != 1 || any (cur.fixed)
      || numel (cur.F) < 3)
    return;
  endif
  r = roots (cur.F);
  sec = {};
  used = false (size (r));
  for k = 1:numel (r)
    if (used(k))
      continue;
    endif
    if (imag (r(k)) == 0)
      sec{end+1} = r(k); used(k) = true;
    else
      j = find (! used & abs (r - conj (r(k))) < 1e-9 * abs (r(k)));
      j = j(j != k);
      if (isempty (j))
        return;
      endif
      sec{end+1} = [r(k); r(j(1))]; used([k j(1)]) = true;
    endif
  endfor
  K = numel (sec);
  if (K < 2 || K > 4 || any (abs (r) < 1e-9 * max (abs (r))))
    return;
  endif
  D = ctx.D;
  ch = cur.channels(ins);
  u = D.u(:, ch.col);
  uk = [zeros(ch.nk, 1); u(1:end-ch.nk)];
  ## the rest of the model's output (other channels, output terms)
  t0 = cur;
  t0.channels(ins).B(:) = 0;
  xo = residtrace_simulate (t0, D.u, D.Ts, D.loop, ctx.opts.substeps);
  tgt = y - xo;
  for mask = 1:2^K-2
    pick = logical (bitget (mask, 1:K));
    Fa = real (poly (vertcat (sec{pick})));
    Fb = real (poly (vertcat (sec{! pick})));
    z = simc (struct ("B", Fa(end), "F", Fa), uk, D.Ts,
              "InterSample", D.intersample);
    H = struct ("B", Fb(end), "F", Fb);
    sse = @(w) lsq_sse (tgt, simc (H, w, D.Ts, "InterSample",
                                   D.intersample));
    hi = best_level (@(L) sse (min (z, L)), z, "upper");
    lo = best_level (@(L) sse (max (z, L)), z, "lower");
    if (isempty (hi) || isempty (lo))
      continue;
    endif
    lv = {[-Inf hi], [lo Inf], [lo hi]};
    sides = {"upper", "lower", "both"};
    v = cellfun (@(L) bic_of (sse (max (min (z, L(2)), L(1))), y, L), lv);
    [~, s] = min (v);
    t = cur;
    t.F = Fb;
    t.fixed = false (1, numel (Fb) - 1);
    nb = min (ch.nb, numel (Fb) - 1);
    P = struct ("Fa", Fa, "lo", lv{s}(1), "hi", lv{s}(2), "Ts", D.Ts,
                "rule", D.intersample);
    nc = residtrace_chan ("node", ch.col, [], nb, ch.nk, "clip(z)");
    nc.param = P;
    ## started from the current model, B/F = (B/F_a(0)) / F_b times the
    ## node's unit-gain F_a(0)/F_a: a zero numerator would leave the
    ## engine's first auxiliary model, hence its instruments, at zero
    ## (rank deficient: on a simulated flow-loop valve record the node
    ## variants all failed so)
    b0 = ch.B(:).' / cur.F(1) / Fa(end);
    nc.B = [zeros(1, max (nb - numel (b0), 0)), b0(max (end-nb+1, 1):end)];
    t.channels(ins) = nc;
    tmpls{end+1} = t;
    names{end+1} = sprintf ("inner node after pole(s) %s, %s level",
                            num2str (roots (Fa).', 3), sides{s});
  endfor
endfunction

## BIC of a screening fit: N log(sse/N) + (finite levels) log N.
## The output clipped at the levels of each side ("upper", "lower",
## "both") chosen from the model output x: the side whose clip has the
## smallest BIC, its levels and that BIC (Inf, [], "" when no side has a
## level to try).
function [best, lvb, sb] = best_side (y, x)
  best = Inf; lvb = []; sb = "";
  for side = {"upper", "lower", "both"}
    lv = out_levels (y, x, side{1});
    if (isempty (lv))
      continue;
    endif
    v = bic_of (sum ((y - min (max (x, lv(1)), lv(2))) .^ 2), y, lv);
    if (v < best)
      best = v; lvb = lv; sb = side{1};
    endif
  endfor
endfunction

function v = bic_of (sse, y, lv)
  N = numel (y);
  v = N * log (max (sse, realmin) / N) + sum (isfinite (lv)) * log (N);
endfunction

function v = gain_sse (t, yb)
  k = (yb' * t) / max (yb' * yb, realmin);
  v = sum ((t - k * yb) .^ 2);
endfunction

function v = lsq_sse (t, yb)
  X = [yb, ones(numel (yb), 1)];
  v = sum ((t - X * (X \ t)) .^ 2);
endfunction

## One refinement of the level(s) with the fitted model.
function [m, better] = refine (m, cur, ctx)
  D = ctx.D;
  y = D.y;
  k = find (strcmp ({m.out.type}, "sat"), 1);
  if (! isempty (k))
    t = m;
    t.out(k).c = [-Inf Inf];
    xs = residtrace_simulate (t, D.u, D.Ts, D.loop, ctx.opts.substeps);
    lv = m.out(k).c;
    if (isfinite (lv(2)))
      lv(2) = best_level (@(L) sum ((y - max (min (xs, L), lv(1))) .^ 2),
                          xs, "upper");
    endif
    if (isfinite (lv(1)))
      lv(1) = best_level (@(L) sum ((y - max (min (xs, lv(2)), L)) .^ 2),
                          xs, "lower");
    endif
    t = m;
    t.out(k).c = lv;
  else
    j = find (strcmp ({m.channels.type}, "node"), 1);
    P = m.channels(j).param;
    t = m;
    t.channels(j).param.lo = -Inf; t.channels(j).param.hi = Inf;
    z = residtrace_channels (t.channels(j), D.u, 0, 0);
    z = [zeros(m.channels(j).nk, 1); z(1:end-m.channels(j).nk)];
    H = struct ("B", {m.channels(j).B}, "F", m.F);
    t0 = m;
    t0.channels(j).B(:) = 0;
    xo = residtrace_simulate (t0, D.u, D.Ts, D.loop, ctx.opts.substeps);
    ## the gain refitted with each level (as in the screening): with the
    ## fitted numerator held, a level found too wide is kept so by the
    ## gain the fit lowered to match it (on a simulated valve record:
    ## levels 109 % wide, gain 0.47 for 0.5)
    sse = @(w) gain_sse (y - xo, simc (H, w, D.Ts, "InterSample",
                                       D.intersample));
    if (isfinite (P.hi))
      P.hi = best_level (@(L) sse (max (min (z, L), P.lo)), z, "upper");
    endif
    if (isfinite (P.lo))
      P.lo = best_level (@(L) sse (max (min (z, P.hi), L)), z, "lower");
    endif
    t = m;
    t.channels(j).param = P;
  endif
  m2 = residtrace_fit (t, D, ctx, {m.F});
  better = m2.ok && m2.bic < m.bic;
  if (better)
    v = m.variant_;
    m = m2;
    m.variant_ = v;
  endif
endfunction

## A state saturation with the velocity reset: the output is a position
## (the first state of the observable canonical form) limited to levels
## that are estimated, the velocity zeroed at the level (an inelastic end
## stop). Needs two or more poles and a relative degree of at least two
## for every channel (the velocity is a state), channels that are inputs
## or functions of them, open loop. The side(s) and the start of the
## levels: the output saturation's screening on the current model output,
## which must lower the BIC by at least 10 (else no fit: for speed).
function [t, name] = stop_template (cur, ctx, y, x)
  t = []; name = "";
  n = numel (cur.F) - 1;
  if (! isempty (ctx.D.loop) || n < 2
      || any (! ismember ({cur.channels.type},
                          {"input", "const", "power", "clip"}))
      || any ([cur.channels.nb] > n - 1)
      || (! isempty (cur.out) && any (! strcmp ({cur.out.type}, "offset"))))
    return;
  endif
  [best, lvb, sb] = best_side (y, x);
  ## the costly fit only where the screening's clip shows evidence of a
  ## level (BIC at least 10 below the unclipped model's)
  if (! (best < bic_of (sum ((y - x) .^ 2), y, []) - 10))
    return;
  endif
  t = cur;
  t.phys = struct ("kind", "stop", "lo", lvb(1), "hi", lvb(2),
                   "substeps", 20, "yscale", std (y));
  name = sprintf (["output (a position) at an end stop, velocity ", ...
                   "reset, %s level"], sb);
endfunction

## A cascade whose inner state sits at its level on most samples does not
## overflow: the level and the spilled share then stand for another
## structure (a single tank fed through the spill, on the simulated
## record "tank" of residtrace_sim_records), which is not a saturation.
function m = overflowing (m, D)
  if (m.ok && strcmp (m.phys.kind, "cascade"))
    [~, z] = residtrace_physsim (m, D.u, D.Ts);
    m.ok = mean (z >= m.phys.hi - 1e-9 * abs (m.phys.hi)) <= 0.5;
  endif
endfunction
