## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn {} {@var{t} =} residtrace_dmtest (@var{e0}, @var{e1})
## Does the error @var{e1} have a smaller mean square than @var{e0} on the
## same samples? The Diebold-Mariano test on d = e0.^2 - e1.^2: the
## statistic mean(d) / sqrt(S / N) with S the Newey-West (Bartlett)
## long-run variance of d, whose bandwidth follows Andrews' AR(1) plug-in
## rule (1991), so that errors correlated in time are not counted as
## independent samples. One-sided p-value from the normal distribution.
##
## @var{t}: @code{score} = 1 - mean(e1.^2) / mean(e0.^2) (the share of
## the mean square removed), @code{stat}, @code{p}, @code{bandwidth} of
## the DM test, and @code{z}, @code{p_corr} of the encompassing test
## (Harvey, Leybourne and Newbold, J. Bus. Econ. Stat. 16 (1998)
## 254-259): does the correction delta = e0 - e1 explain part of e0? In
## the regression e0 = beta delta + u (no intercept, no means removed: a
## constant correction, i.e. a pure offset, is a correction like any
## other), the t value of beta_hat = sum e0 delta / sum delta^2 with the
## Newey-West variance of the score u delta (same bandwidth rule). Both series' autocorrelations are accounted
## for, so slow residuals do not fake significance, and since the
## variance comes from what is left after the correction, a large effect
## does not hide itself (as it can in the DM variance when the residual
## is periodic). One-sided normal p-value of beta > 0.
## @end deftypefn

function t = residtrace_dmtest (e0, e1)
  d = e0(:) .^ 2 - e1(:) .^ 2;
  N = numel (d);
  t.score = 1 - mean (e1 .^ 2) / mean (e0 .^ 2);
  dc = e0(:) - e1(:);
  a = e0(:);
  sdd = sum (dc .^ 2);
  t.z = 0;
  if (sdd > 0)
    beta = sum (a .* dc) / sdd;
    g = (a - beta * dc) .* dc;          # the score of the regression
    v = newey_west (g);
    if (v > 0)
      t.z = beta * sdd / sqrt (v * N);
    endif
  endif
  t.p_corr = 0.5 * erfc (t.z / sqrt (2));
  [S, L] = newey_west (d);
  if (! (S > 0) || ! isfinite (S))
    t.stat = 0;
    t.p = 1;
    t.bandwidth = 0;
    if (mean (d) > 0 && isfinite (mean (d)))
      t.stat = Inf;
      t.p = 0;
    endif
    return;
  endif
  t.stat = mean (d) / sqrt (S / N);
  t.p = 0.5 * erfc (t.stat / sqrt (2));
  t.bandwidth = L;
endfunction

## Long-run variance of g (per sample): prewhitened by an AR(1) (Andrews
## and Monahan, Econometrica 60 (1992) 953-966, which removes most of the
## downward bias for persistent series), Bartlett weights with the
## bandwidth of Andrews' AR(1) plug-in rule on the whitened series (at
## most N/4), then recoloured by 1/(1 - rho)^2.
function [S, L] = newey_west (g)
  N = numel (g);
  gc = g - mean (g);
  g0 = sum (gc .^ 2) / N;
  S = g0;
  L = 0;
  if (! (g0 > 0) || ! isfinite (g0))
    return;
  endif
  rho = sum (gc(2:end) .* gc(1:end-1)) / sum (gc(1:end-1) .^ 2);
  rho = min (max (rho, -0.97), 0.97);
  w = gc(2:end) - rho * gc(1:end-1);
  n = numel (w);
  w0 = sum (w .^ 2) / n;
  r1 = sum (w(2:end) .* w(1:end-1)) / sum (w .^ 2);
  r1 = min (max (r1, -0.97), 0.97);
  a1 = 4 * r1 ^ 2 / ((1 - r1) ^ 2 * (1 + r1) ^ 2);
  L = min (floor (1.1447 * (a1 * n) ^ (1 / 3)), floor (n / 4));
  Sw = w0;
  for l = 1:L
    Sw += 2 * (1 - l / (L + 1)) * sum (w(1+l:end) .* w(1:end-l)) / n;
  endfor
  S = max (Sw / (1 - rho) ^ 2, g0 / N);
endfunction
