## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn {} {@var{c} =} residtrace_cand_sinusoid (@var{cur}, @var{ctx})
## Sinusoidal-disturbance candidate of @code{residtrace}: the strongest
## line of the periodogram of the current estimation residual, tested by
## Fisher's g = max I_k / sum I_k (p-value m (1 - g)^(m - 1), m bins).
## Bins where an input has a line of its own (periodogram above 20 times
## its median over the 21 neighbouring bins) are left out: a line there
## is driven by the input, i.e. missing dynamics, not a disturbance. The
## frequency is refined to the maximum of |sum e(t) exp(-i w t)| between
## the neighbouring bins; then y = x + a sin(w t) + b cos(w t) is fitted
## with the model by alternation. Evidence: frequency, amplitude with its
## standard deviation, g and its p-value.
##
## Only periods the records resolve are candidates: at least two cycles in
## the estimation record (of duration T_e) and one in each half of the
## validation record (T_v), w >= 4 pi / min (T_e, T_v), for the search and
## for the refined frequency alike. Over a cycle or less a sinusoid cannot
## be told from a level or a drift (a "sinusoid" at 0.00014 Hz, under one
## cycle of a simulated heated block's record, would be named).
##
## The phase of the disturbance on another record is unknown:
## @code{residtrace} keeps w, and fits a and b on each half of the
## validation residual to predict the other half (two-fold cross-fitting,
## so no sample is predicted by a fit that used it).
## @end deftypefn

function c = residtrace_cand_sinusoid (cur, ctx)
  c = residtrace_cand ("sinusoid");
  e = cur.e_est - mean (cur.e_est);
  N = numel (e);
  Ts = ctx.D.Ts;
  m = floor ((N - 1) / 2);
  if (m < 8)
    c.reason = "too few samples for a periodogram";
    return;
  endif
  E = fft (e);
  I = abs (E(2:m+1)) .^ 2 / N;
  keep = true (m, 1);
  for j = 1:columns (ctx.D.u)
    U = fft (ctx.D.u(:, j) - mean (ctx.D.u(:, j)));
    Iu = abs (U(2:m+1)) .^ 2;
    loc = movmedian_ (Iu, 21);
    keep &= ! (Iu > 20 * loc);
  endfor
  ## periods the records resolve (see above)
  Tv = numel (ctx.V.y) * Ts;
  wmin = 4 * pi / min (N * Ts, Tv);
  wk = 2 * pi * (1:m)' / (N * Ts);
  resolved = wk >= wmin;
  if (! any (resolved))
    c.reason = sprintf (["the records are too short for a sinusoid (at ", ...
                         "least two cycles: a period of at most %.4g s)"],
                        2 * pi / wmin);
    return;
  endif
  keep &= resolved;
  if (! any (keep))
    c.reason = "every frequency carries input power";
    return;
  endif
  Ik = I;
  Ik(! keep) = 0;
  [Imax, k] = max (Ik);
  g = Imax / sum (I(keep));
  mk = sum (keep);
  pg = min (1, mk * (1 - g) ^ (mk - 1));
  ## refine the frequency between the neighbouring bins
  t = (0:N-1)' * Ts;
  w0 = 2 * pi * k / (N * Ts);
  dw = 2 * pi / (N * Ts);
  grid = linspace (max (w0 - dw, wmin), w0 + dw, 41);
  amp = arrayfun (@(w) abs (sum (e .* exp (-1i * w * t))), grid);
  [~, i] = max (amp);
  w = grid(i);
  tm = cur;
  tm.out(end+1) = struct ("type", "sinusoid", "c", [0 0], "cstd", [0 0],
                          "omega", w);
  mdl = residtrace_fit (tm, ctx.D, ctx, {cur.F});
  if (! mdl.ok)
    c.reason = "the estimation failed";
    c.failed = true;
    return;
  endif
  c.applicable = true;
  c.model = mdl;
  c.variant = sprintf ("%.4g Hz", w / (2 * pi));
  c.nadd = 2;
  o = mdl.out(end);
  A = hypot (o.c(1), o.c(2));
  sA = sqrt (mean (o.cstd .^ 2));
  c.evidence = struct ("term", "amplitude", "value", A, "std", sA,
                       "omega", w, "freq_hz", w / (2 * pi), "g", g,
                       "g_p", pg,
                       "text", sprintf (["line at %.4g Hz (%.4g rad/s), ", ...
                                         "amplitude %.4g +- %.2g; Fisher ", ...
                                         "g = %.3f, p = %.2g"],
                                        w / (2 * pi), w, A, sA, g, pg));
endfunction

## Running median over windows of L samples, shortened at the ends: the
## interior from one L-by-n matrix of windows, the 2 h end points one by one.
function m = movmedian_ (x, L)
  x = x(:);
  n = numel (x);
  m = zeros (n, 1);
  h = floor (L / 2);
  inner = (h + 1):(n - h);
  if (! isempty (inner))
    m(inner) = median (x(inner + (-h:h)'), 1)';
  endif
  for i = [1:min(h, n), max(n - h + 1, h + 1):n]
    m(i) = median (x(max (1, i - h):min (n, i + h)));
  endfor
endfunction
