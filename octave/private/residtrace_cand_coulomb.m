## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn {} {@var{c} =} residtrace_cand_coulomb (@var{cur}, @var{ctx})
## Coulomb-friction candidate of @code{residtrace}: the extra regressor
## sign(v) in the filtered linear regression, as the thesis does for the
## throttle (sec. 4.2, eq. 4.17), v the velocity: the SVF derivative of
## the measured output (a first-order model reads the output itself as a
## velocity), filtered forward and backward so that its zero crossings
## are not delayed (@code{ctx.D.vhat}), or the output itself when it is
## a velocity (a variant for models of any order; no differentiation);
## whether the term is determined and the velocity reverses often enough
## is @code{residtrace_accept}'s general check (evidence @code{share},
## the share of samples moving forward, and @code{reversals}). A
## second variant adds a constant
## too (Coulomb levels that differ with the direction: sign(v) and an
## offset). When none of them gives a friction (a gain opposing the
## motion), each is fitted again with v the velocity of the
## model's own output (the current model's simulation on the estimation
## record, then the fitted candidate's, twice), filtered the same way: at
## rest the sign of the measured velocity is the measurement noise's,
## correlated with the equation error (a body that sticks between the
## steps of its input then gets a gain pushing along the motion), while
## the model's velocity is free of it and is the one its simulation
## uses. The BIC on the estimation data chooses among the variants whose
## fitted gain opposes the motion (a friction), among all when none does. A fitted b_s > 0 (F
## being monic, a force along the motion) is not friction: the candidate
## is then reported as not applicable, and so is a sign(v) that the
## input's levels and a constant explain to more than 90 % (R^2; with a
## two-level input through a velocity, sign(v) follows the input): "not
## identifiable from these data". Evidence: the
## correlation of the current residual with the filtered sign(v), the
## fitted gain b_s with its standard deviation, and the friction level
## -b_s / b_u in input units (a force when the input is a force).
## @end deftypefn

function c = residtrace_cand_coulomb (cur, ctx)
  c = residtrace_cand ("coulomb");
  if (any (strcmp ({cur.channels.type}, "signv")))
    c.reason = "the model has Coulomb friction already";
    return;
  endif
  n = numel (cur.F) - 1;
  ## which velocity: dy/dt (the output a position), or the output itself
  ## (a velocity; for a first-order model both columns are y)
  kinds = {"dy", "y"};
  vnames = {"sign(dy/dt)", "sign(y)"};
  if (n == 1)
    kinds = {"y"}; vnames = {"sign(y)"};
  endif
  [tmpls, names, starts, sigs] = variants_on (cur, ctx.D, kinds, vnames, "");
  if (isempty (tmpls))
    c.reason = "the velocity never changes sign";
    return;
  endif
  [fits, c.variants] = fit_each (tmpls, names, ctx.D, ctx, starts);
  ## when no variant on the measured velocity gives a friction, the
  ## same with the velocity of the model's own output (the current
  ## model's simulation, then the fitted candidate's): at rest the sign
  ## of the measured velocity is the measurement noise's, correlated with
  ## the equation error, and a body that sticks between the steps of its
  ## input gets a sign(v) gain pushing along the motion; the model's
  ## velocity is free of that noise, and is the one its simulation uses
  m = choose (fits);
  if ((isempty (m) || m.theta(end) >= 0)
      && isfield (ctx, "lam_v") && numel (cur.e_est) == numel (ctx.D.y))
    x = ctx.D.y - cur.e_est;
    for it = 1:2
      Dm = ctx.D;
      Dm.vhat = [residtrace_velocity(x, Dm.Ts, ctx.lam_v, ctx.vel_is_y), ...
                 residtrace_velocity(x, Dm.Ts, ctx.lam_v, true)];
      [t2, n2, st2, sg2] = variants_on (cur, Dm, kinds,
                                        strcat (vnames, sprintf (
                                          ", model's velocity (%d)", it)),
                                        "");
      if (isempty (t2))
        break;
      endif
      [f2, v2] = fit_each (t2, n2, Dm, ctx, st2);
      c.variants = [c.variants(:); v2(:)];
      fits = [fits, f2]; names = [names, n2]; sigs = [sigs, sg2];
      m2 = choose (f2);
      if (isempty (m2) || numel (m2.e_est) != numel (x))
        break;
      endif
      x = ctx.D.y - m2.e_est;
    endfor
  endif
  m = choose (fits);
  if (isempty (m))
    c.reason = "the estimation failed";
    c.failed = true;
    return;
  endif
  s = sigs{strcmp (names, m.variant_)};
  k = numel (m.theta);
  val = m.theta(k); sd = sqrt (m.cov(k, k));
  bu = m.channels(1).B(end);
  ## identifiable? sign(v) must not be (nearly) a function of the input:
  ## with a two-level input through a velocity, sign(v) follows sign(u)
  r2 = explained (s, ctx.D.u);
  if (r2 > 0.9)
    c.reason = sprintf (["not identifiable from these data: sign(v) is ", ...
                         "%.0f %% explained by the input and a constant ", ...
                         "(%s)"], 100 * r2,
                        ifelse_ (two_level (ctx.D.u), "a two-level input",
                                 "the input decides the direction"));
    return;
  endif
  if (val > 0)                  # F monic: friction needs b_s < 0
    c.reason = sprintf (["the fitted term %.3g sign(v) pushes along ", ...
                         "the motion: not a friction"], val);
    return;
  endif
  c.applicable = true;
  c.model = m;
  c.variant = m.variant_;
  c.nadd = m.np - cur.np;
  Fp = residtrace_prefilter (cur.F, ctx.wlo);
  sf = residtrace_filter (Fp, s, ctx.D.Ts, "zoh")(:, 1);
  r = corr_coef (cur.e_est, sf);
  c.evidence = struct ("term", "b_s (gain of sign(v))", "value", val,
                       "std", sd, "physical", -val / bu,
                       "physical_std", sd / abs (bu), "corr", r,
                       "r2_input", r2, "share", mean (s > 0),
                       "reversals", reversals (s),
                       "text", sprintf (["Coulomb level %.4g +- %.2g ", ...
                                         "(input units); corr(residual, ", ...
                                         "sign(v)/F) = %.2f"],
                                        -val / bu, sd / abs (bu), r));
endfunction

## Each template fitted on its own (to convergence): a cell of the fitted
## models (the failed ones empty) and the table of their BIC.
function [fits, table] = fit_each (tmpls, names, D, ctx, starts)
  fits = cell (1, numel (tmpls));
  table = [];
  for i = 1:numel (tmpls)
    [m, t] = residtrace_select (tmpls(i), names(i), D, ctx, starts(i));
    fits{i} = m;
    table = [table; t(:)];
  endfor
endfunction

## The variant with the smallest BIC among those whose sign(v) gain
## opposes the motion (a friction: b_s < 0, F monic); when none does,
## the smallest BIC of all (which is then reported as no friction).
function best = choose (fits)
  best = [];
  ok = ! cellfun (@isempty, fits);
  if (! any (ok))
    return;
  endif
  f = fits(ok);
  bic = cellfun (@(m) m.bic, f);
  fric = cellfun (@(m) m.theta(end) < 0, f);
  if (any (fric))
    bic(! fric) = Inf;
  endif
  [~, i] = min (bic);
  best = f{i};
endfunction

## The Coulomb variants on the record D (its velocity D.vhat): sign(v),
## and sign(v) with a constant, for each kind of velocity that changes
## sign; their names end with SUFFIX.
function [tmpls, names, starts, sigs] = variants_on (cur, D, kinds, vnames,
                                                    suffix)
  tmpls = {}; names = {}; starts = {}; sigs = {};
  for i = 1:numel (kinds)
    col = ifelse_ (strcmp (kinds{i}, "y"), 2, 1);
    s = sign (D.vhat(:, col));
    if (numel (unique (s(s != 0))) < 2)
      continue;
    endif
    t = cur;
    t.channels(end+1) = residtrace_chan ("signv", 0, kinds{i}, 1, 0,
                                         "sign(v)");
    tmpls{end+1} = t; names{end+1} = [vnames{i} suffix];
    starts{end+1} = {cur.F};
    sigs{end+1} = s;
    if (! any (strcmp ({cur.channels.type}, "const")) && ! cur.levels)
      ## unequal levels for the two directions: sign(v) plus a constant
      t2 = cur;
      t2.channels(end+1) = residtrace_chan ("const", 0, [], 1, 0, "offset");
      t2.channels(end+1) = residtrace_chan ("signv", 0, kinds{i}, 1, 0,
                                            "sign(v)");
      tmpls{end+1} = t2; names{end+1} = [vnames{i} ", asymmetric" suffix];
      starts{end+1} = {cur.F};
      sigs{end+1} = s;
    endif
  endfor
endfunction

## R^2 of s regressed on the inputs' levels (each distinct level of a
## few-level input its own indicator) and a constant.
function r2 = explained (s, u)
  X = ones (rows (u), 1);
  for j = 1:columns (u)
    lv = unique (u(:, j));
    if (numel (lv) <= 4)
      for i = 2:numel (lv)
        X = [X, u(:, j) == lv(i)];
      endfor
    else
      X = [X, u(:, j)];
    endif
  endfor
  sc = s - mean (s);
  if (! any (sc))
    r2 = 1;
    return;
  endif
  r2 = 1 - sum ((s - X * (X \ s)) .^ 2) / sum (sc .^ 2);
endfunction

## Sign changes of s, its zeros skipped.
function n = reversals (s)
  s = s(s != 0);
  n = sum (s(2:end) != s(1:end-1));
endfunction

function t = two_level (u)
  t = false;
  for j = 1:columns (u)
    t = t || numel (unique (u(:, j))) == 2;
  endfor
endfunction

function v = ifelse_ (c, a, b)
  if (c)
    v = a;
  else
    v = b;
  endif
endfunction

function r = corr_coef (a, b)
  a = a - mean (a); b = b - mean (b);
  r = sum (a .* b) / sqrt (sum (a .^ 2) * sum (b .^ 2));
endfunction
