## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn {} {@var{p} =} residtrace_physical (@var{model}, @var{Ts})
## Physical reading of a @code{residtrace} model, a struct array with
## fields @code{name}, @code{value}, @code{std} (NaN when not available;
## ratios by the first-order delta method from the SRIVC covariance):
## static gain (or, with integrators, the gain of the rest), poles as time
## constants (real) or natural frequency and damping (pairs), zeros, the
## delay, and for a numerator b0 alone with one integrator and order 2 the
## mass 1/b0 and viscous coefficient f1/b0; then each added effect in
## input units of the first input (offset b_c/b0, Coulomb level -b_s/b0,
## nonlinear coefficients b_k/b0), output terms, Qn, the noise model.
## @end deftypefn

function p = residtrace_physical (model, Ts)
  p = struct ("name", {}, "value", {}, "std", {});
  F = model.F;
  n = numel (F) - 1;
  C = model.cov;
  [idxF, idxB] = indices (model);
  ch1 = model.channels(1);
  b = ch1.B;
  r = 0;
  while (r < n && F(n+1-r) == 0)
    r++;
  endwhile
  F1 = F(1:end-r);
  if (F1(end) != 0)
    name = "static gain";
    if (r > 0)
      name = sprintf ("gain after %d integrator(s)", r);
    endif
    p(end+1) = struct ("name", name, "value", b(end) / F1(end), "std", NaN);
  endif
  pl = roots (F);
  done = false (size (pl));
  for k = 1:numel (pl)
    if (done(k))
      continue;
    endif
    if (abs (pl(k)) == 0)
      p(end+1) = struct ("name", "pole", "value", 0, "std", NaN);
    elseif (imag (pl(k)) == 0)
      p(end+1) = struct ("name", "time constant (s)", "value", -1 / pl(k),
                         "std", NaN);
    else
      j = find (! done & abs (pl - conj (pl(k))) < 1e-9 * abs (pl(k)));
      done(j) = true;
      wn = abs (pl(k));
      p(end+1) = struct ("name", "natural frequency (rad/s)", "value", wn,
                         "std", NaN);
      p(end+1) = struct ("name", "damping ratio", "value", -real (pl(k)) / wn,
                         "std", NaN);
    endif
    done(k) = true;
  endfor
  z = roots (b);
  for k = 1:numel (z)
    p(end+1) = struct ("name", "zero", "value", z(k), "std", NaN);
  endfor
  f = 0;
  if (strcmp (ch1.type, "input") && ! isempty (ch1.param))
    f = ch1.param;                # a fraction of a sample
  endif
  if (ch1.nk + f > 0)
    p(end+1) = struct ("name", "delay (s)", "value", (ch1.nk + f) * Ts,
                       "std", NaN);
  endif
  ib0 = idxB{1}(end);
  if (numel (b) == 1 && r == 1 && n == 2)
    p(end+1) = struct ("name", "mass 1/b0", "value", 1 / b,
                       "std", ratio_std (1, b, 0, var_of (C, ib0), 0));
    if (! model.fixed(1))
      p(end+1) = struct ("name", "viscous coefficient f1/b0",
                         "value", F(2) / b,
                         "std", ratio_std (F(2), b, var_of (C, idxF(1)),
                                           var_of (C, ib0),
                                           cov_of (C, idxF(1), ib0)));
    endif
  endif
  if (strcmp (ch1.type, "node"))
    P = ch1.param;
    for z = roots (P.Fa).'
      p(end+1) = struct ("name", "pole before the clipped node", "value", z,
                         "std", NaN);
    endfor
    p(end+1) = struct ("name", "node levels [lo hi] (input units)",
                       "value", [P.lo P.hi], "std", NaN);
  endif
  for j = 2:numel (model.channels)
    c = model.channels(j);
    k = idxB{j}(end);
    switch (c.type)
      case "const"
        nm = "input offset b_c/b0";
        s = 1;
      case "signv"
        nm = "Coulomb level -b_s/b0";
        s = -1;
      case "power"
        nm = sprintf ("coefficient of %s (b/b0)", c.name);
        s = 1;
      case "clip"
        nm = sprintf ("gain of %s (b/b0)", c.name);
        s = 1;
      case "ypower"
        nm = sprintf ("coefficient of %s in the dynamics (g/b0)", c.name);
        s = 1;
      otherwise
        nm = sprintf ("gain of %s (b/b0)", c.name);
        s = 1;
    endswitch
    p(end+1) = struct ("name", nm, "value", s * c.B(end) / b(end),
                       "std", ratio_std (c.B(end), b(end), var_of (C, k),
                                         var_of (C, ib0), cov_of (C, k, ib0)));
  endfor
  for k = 1:numel (model.out)
    o = model.out(k);
    switch (o.type)
      case "offset"
        p(end+1) = struct ("name", "output offset", "value", o.c,
                           "std", o.cstd);
      case "poly"
        p(end+1) = struct ("name", "output c2", "value", o.c(1),
                           "std", o.cstd(1));
        p(end+1) = struct ("name", "output c3", "value", o.c(2),
                           "std", o.cstd(2));
      case "sat"
        p(end+1) = struct ("name", "output saturation [lo hi]",
                           "value", o.c, "std", NaN);
      case "sinusoid"
        p(end+1) = struct ("name", "disturbance frequency (Hz)",
                           "value", o.omega / (2 * pi), "std", NaN);
        p(end+1) = struct ("name", "disturbance amplitude",
                           "value", hypot (o.c(1), o.c(2)),
                           "std", sqrt (mean (o.cstd .^ 2)));
    endswitch
  endfor
  if (! isempty (model.ltv))
    q = diag (model.ltv.Qn);
    for k = 1:numel (q)
      p(end+1) = struct ("name", sprintf ("Qn(%d,%d)", k, k), "value", q(k),
                         "std", NaN);
    endfor
  endif
  if (isfield (model, "phys") && ! isempty (model.phys))
    P = model.phys;
    sd = NaN (numel (P.theta), 1);
    if (isfield (P, "cov"))
      sd = sqrt (max (diag (P.cov), 0));
    endif
    if (strcmp (P.kind, "stop"))
      lv = [P.lo P.hi];
      k = numel (P.theta) - sum (isfinite (lv));
      for s = find (isfinite (lv))
        k++;
        p(end+1) = struct ("name", ifelse_ (s == 1, "lower end stop",
                                            "upper end stop"),
                           "value", lv(s), "std", sd(k));
      endfor
    else
      nc = numel (model.channels);
      p(end+1) = struct ("name", "inner outflow coefficient alpha",
                         "value", P.alpha, "std", P.alpha * sd(nc+2));
      p(end+1) = struct ("name", "outflow coefficient gamma",
                         "value", P.gamma, "std", P.gamma * sd(nc+3));
      p(end+1) = struct ("name", "constant inflow d", "value", P.d,
                         "std", sd(nc+1));
      if (isfinite (P.hi))
        p(end+1) = struct ("name", "inner state's upper level",
                           "value", P.hi, "std", sd(end));
      endif
      p(end+1) = struct ("name", "output level c", "value", P.c,
                         "std", ifelse_ (strcmp (P.g, "sqrt"), sd(nc+4),
                                         NaN));
    endif
  endif
  if (! isempty (model.noise))
    p(end+1) = struct ("name", "AR noise order", "value",
                       numel (model.noise) - 1, "std", NaN);
  endif
endfunction

function [idxF, idxB] = indices (model)
  free = find (! model.fixed);
  idxF = zeros (1, numel (model.fixed));
  idxF(free) = 1:numel (free);
  off = numel (free);
  idxB = cell (1, numel (model.channels));
  for j = 1:numel (model.channels)
    idxB{j} = off + (1:model.channels(j).nb);
    off += model.channels(j).nb;
  endfor
endfunction

function v = var_of (C, i)
  v = NaN;
  if (i > 0 && i <= rows (C))
    v = C(i, i);
  endif
endfunction

function v = cov_of (C, i, j)
  v = NaN;
  if (i > 0 && j > 0 && i <= rows (C) && j <= rows (C))
    v = C(i, j);
  endif
endfunction

## std of a / b by the delta method
function s = ratio_std (a, b, va, vb, cab)
  s = sqrt (max (va / b ^ 2 + a ^ 2 * vb / b ^ 4 - 2 * a * cab / b ^ 3, 0));
endfunction

function v = ifelse_ (c, a, b)
  if (c)
    v = a;
  else
    v = b;
  endif
endfunction
