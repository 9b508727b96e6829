## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn {} {@var{model} =} residtrace_physfit (@var{tmpl}, @var{D}, @var{ctx})
## Fits a @code{residtrace} model with a physical realisation
## (@code{tmpl.phys}, see @code{residtrace_physsim}) on the record @var{D}
## by minimising its simulation error (output error, Levenberg-Marquardt
## with a forward-difference Jacobian), started from @var{tmpl}'s values.
## The refined-IV engine cannot fit these models: their nonlinearity acts
## on a state that is not measured (an end stop that resets a velocity,
## an inner tank that overflows), so there is no regression form; the
## simulation error is the criterion every candidate is scored by.
##
## Parameters: for "stop", the free coefficients of F, every channel's
## numerator, the output offset (when the model has one) and the finite
## levels; for "cascade", every channel's gain, the constant inflow d,
## log alpha, log gamma, the output level c (square-root nodes), the
## inner level (when finite), the outer level @code{yhi} and the share
## @code{spill} of the inner overflow (when present) and the initial
## level @code{h0} (when present; with @code{D.initial_state} the inner
## one @code{z0} too, else at rest with h0: the cascade's initial state,
## so no free response is added). A share is kept in [0, 1] by
## projecting each step onto it (a step rejected at the bound would stall
## the others). With @code{D.initial_state} the free
## response of the model's (linearised) F is fitted on the error by least
## squares, as for every other model. At most @code{ctx.maxiter}
## iterations (three while residtrace screens) and at most max(8, 48 000 /
## n) on the n <= 6000 samples fitted (the first ones; a budget for speed
## that grows as n falls: eight whatever n would leave the cascades' fits
## short of their minimum on records of a few thousand samples); the residual
## variance, BIC and @code{e_est} are those of the whole record.
## @code{phys.theta}, @code{phys.cov}: the parameters above and their
## Gauss-Newton covariance; @code{theta}, @code{cov}: those of
## the linear part (for a cascade, its linearisation, without covariance).
## @end deftypefn

function model = residtrace_physfit (tmpl, D, ctx)
  warning ("off", "Octave:singular-matrix", "local");
  warning ("off", "Octave:nearly-singular-matrix", "local");
  model = tmpl;
  model.ok = false;
  y = D.y;
  N = numel (y);
  x0 = isfield (D, "initial_state") && D.initial_state;
  if (x0 && isfield (tmpl.phys, "h0") && ! isempty (tmpl.phys.h0))
    ## the cascade's initial state, both levels, are parameters: no free
    ## response on top; the inner one starts at rest with h0
    x0 = false;
    tmpl.phys.z0 = residtrace_cascade_levels (tmpl.phys);
  endif
  nfit = min (N, 6000);
  Df = D;
  Df.y = D.y(1:nfit); Df.u = D.u(1:nfit, :);
  [th, scale] = pack (tmpl);
  res = @(t) resid (unpack (tmpl, t), Df, x0);
  r = res (th);
  sse = r' * r;
  sse0 = sse;
  if (! isfinite (sse))
    return;
  endif
  ## a budget of samples times iterations (8 on 6000 samples, 30 on 1600)
  maxit = min (max (ctx.maxiter, 1), max (8, floor (48000 / nfit)));
  mu = [];
  np = numel (th);
  for it = 1:maxit
    J = jacobian (tmpl, th, scale, r, Df, x0, res);
    if (any (! isfinite (J(:))))
      break;
    endif
    H = J' * J; g = J' * r;
    ## a parameter without effect (a level never reached) gets the floor,
    ## and so a zero step
    dH = max (diag (H), 1e-6 * max ([diag(H); eps]));
    if (isempty (mu))
      mu = 1e-3;
    endif
    improved = false;
    for tries = 1:6
      step = -(H + mu * diag (dH)) \ g;
      t = project (tmpl, th + step);
      if (! valid (tmpl, t))
        mu *= 10;
        continue;
      endif
      rt = res (t);
      st = rt' * rt;
      if (isfinite (st) && st < sse)
        improved = true;
        rel = (sse - st) / sse;
        th = t; r = rt; sse = st;
        mu = max (mu / 10, 1e-9);
        break;
      endif
      mu *= 10;
    endfor
    if (! improved || rel < 1e-7)
      break;
    endif
  endfor
  model = unpack (tmpl, th);
  e = resid (model, D, x0);
  if (! all (isfinite (e)))
    return;
  endif
  model.np = np;
  model.s2 = (e' * e) / max (N - np, 1);
  model.bic = N * log (model.s2) + np * log (N);
  model.e_est = e;
  s2f = sse / max (nfit - np, 1);
  C = s2f * pinv (J' * J);
  model.phys.theta = th(:);
  model.phys.cov = C;
  ## the linear part's parameters as every model carries them (free f's,
  ## then the numerators): for an end stop the first ones of th; for a
  ## cascade its linearisation (no covariance)
  nl = sum (! model.fixed) + sum ([model.channels.nb]);
  if (strcmp (model.phys.kind, "stop"))
    model.theta = th(1:nl);
    model.cov = C(1:nl, 1:nl);
  else
    F = model.F / model.F(1);
    model.theta = [F(1 + find (! model.fixed)), ...
                   [model.channels.B] / model.F(1)](:);
    model.cov = NaN (nl);
  endif
  model.ok = true;
endfunction

## Forward differences; the perturbed cascades are simulated side by side
## in one pass over the samples.
function J = jacobian (tmpl, th, scale, r, D, x0, res)
  np = numel (th);
  J = zeros (numel (r), np);
  h = 1e-5 * max (abs (th), scale);
  for i = 1:np                          # a bounded parameter at its bound
    t = th; t(i) += h(i);               # (a share of 1): backward
    if (! valid (tmpl, t))
      t(i) = th(i) - h(i);
      if (valid (tmpl, t))
        h(i) = -h(i);
      endif
    endif
    t = th; t(i) += h(i);               # never past a bound
    h(i) = project (tmpl, t)(i) - th(i);   # 0: no step, a zero column
  endfor
  if (strcmp (tmpl.phys.kind, "cascade"))
    ms = cell (1, np);
    for i = 1:np
      t = th; t(i) += h(i);
      ms{i} = unpack (tmpl, t);
    endfor
    Y = residtrace_physsim (ms, D.u, D.Ts);
    for i = 1:np
      e = D.y - Y(:, i);
      if (x0 && all (isfinite (e)))
        X = residtrace_free (ms{i}.F, numel (e), D.Ts);
        e -= X * (X \ e);
      endif
      if (h(i) != 0)
        J(:, i) = (e - r) / h(i);
      endif
    endfor
    return;
  endif
  for i = 1:np
    t = th; t(i) += h(i);
    if (h(i) != 0)
      J(:, i) = (res (t) - r) / h(i);
    endif
  endfor
endfunction

function e = resid (model, D, x0)
  try
    yh = residtrace_physsim (model, D.u, D.Ts);
  catch
    e = Inf (size (D.y));
    return;
  end_try_catch
  e = D.y - yh;
  if (x0 && all (isfinite (e)))
    X = residtrace_free (model.F, numel (e), D.Ts);
    e -= X * (X \ e);
  endif
  e(! isfinite (e)) = Inf;
endfunction

## The parameter vector of the realisation and a scale per parameter (the
## smallest step of its finite difference).
function [th, scale] = pack (m)
  P = m.phys;
  ys = max (P.yscale, eps);
  switch (P.kind)
    case "stop"
      F = m.F / m.F(1);
      th = F(1 + find (! m.fixed)).';
      scale = abs (th) + 1e-3;
      for j = 1:numel (m.channels)
        b = m.channels(j).B(:) / m.F(1);
        th = [th; b];
        scale = [scale; abs(b) + 1e-3];
      endfor
      k = find (strcmp ({m.out.type}, "offset"), 1);
      if (! isempty (k))
        th(end+1) = m.out(k).c(1); scale(end+1) = ys;
      endif
      lv = [P.lo P.hi];
      lv = lv(isfinite (lv));
      th = [th; lv(:)];
      scale = [scale; ys * ones(numel (lv), 1)];
    case "cascade"
      th = arrayfun (@(c) c.B(end), m.channels)(:);
      scale = abs (th) + 1e-6;
      th = [th; P.d; log(P.alpha); log(P.gamma)];
      scale = [scale; abs(P.d) + 1e-6; 1; 1];
      if (strcmp (P.g, "sqrt"))
        th(end+1) = P.c; scale(end+1) = ys;
      endif
      if (isfinite (P.hi))
        th(end+1) = P.hi; scale(end+1) = max (abs (P.hi), 1e-6);
      endif
      if (isfield (P, "yhi"))
        th(end+1) = P.yhi; scale(end+1) = ys;
      endif
      if (isfield (P, "spill"))
        th(end+1) = P.spill; scale(end+1) = 1;
      endif
      if (isfield (P, "h0") && ! isempty (P.h0))
        th(end+1) = P.h0; scale(end+1) = ys;
      endif
      if (isfield (P, "z0") && ! isempty (P.z0))
        th(end+1) = P.z0; scale(end+1) = max (abs (P.z0), 1e-6);
      endif
  endswitch
endfunction

function m = unpack (m, th)
  P = m.phys;
  switch (P.kind)
    case "stop"
      F = m.F / m.F(1);
      free = find (! m.fixed);
      F(1 + free) = th(1:numel (free));
      m.F = F;
      off = numel (free);
      for j = 1:numel (m.channels)
        nb = numel (m.channels(j).B);
        m.channels(j).B = th(off+1:off+nb).';
        off += nb;
      endfor
      k = find (strcmp ({m.out.type}, "offset"), 1);
      if (! isempty (k))
        off++;
        m.out(k).c = th(off);
      endif
      if (isfinite (P.lo))
        off++; m.phys.lo = th(off);
      endif
      if (isfinite (P.hi))
        off++; m.phys.hi = th(off);
      endif
    case "cascade"
      nc = numel (m.channels);
      for j = 1:nc
        m.channels(j).B = th(j);
      endfor
      m.phys.d = th(nc+1);
      m.phys.alpha = exp (th(nc+2));
      m.phys.gamma = exp (th(nc+3));
      off = nc + 3;
      if (strcmp (P.g, "sqrt"))
        off++; m.phys.c = th(off);
      endif
      if (isfinite (P.hi))
        off++; m.phys.hi = th(off);
      endif
      if (isfield (P, "yhi"))
        off++; m.phys.yhi = th(off);
      endif
      if (isfield (P, "spill"))
        off++; m.phys.spill = th(off);
      endif
      if (isfield (P, "h0") && ! isempty (P.h0))
        off++; m.phys.h0 = th(off);
      endif
      if (isfield (P, "z0") && ! isempty (P.z0))
        off++; m.phys.z0 = th(off);
      endif
      m.F = residtrace_physlin (m);
  endswitch
endfunction

## A step onto the bounds of a bounded parameter (a share in [0, 1]), so
## that the others still move when it sits at a bound (projected
## Levenberg-Marquardt; a rejected step would stall there).
function th = project (m, th)
  if (strcmp (m.phys.kind, "cascade") && isfield (m.phys, "spill"))
    m = unpack (m, th);
    m.phys.spill = min (max (m.phys.spill, 0), 1);
    th = pack (m);
  endif
endfunction

function ok = valid (m, th)
  ok = all (isfinite (th));
  if (! ok)
    return;
  endif
  m = unpack (m, th);
  if (strcmp (m.phys.kind, "stop"))
    z = roots (m.F);
    ok = all (real (z) <= 1e-9 * max (abs (z))) && m.phys.lo < m.phys.hi;
  else
    ok = m.phys.alpha < 1e8 && m.phys.gamma < 1e8;
    if (isfield (m.phys, "spill"))
      ok = ok && m.phys.spill >= 0 && m.phys.spill <= 1;
    endif
  endif
endfunction
