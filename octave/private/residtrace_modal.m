## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn {} {@var{D} =} residtrace_modal (@var{F}, @var{x}, @var{Ts}, @var{rule})
## Filtered time-derivatives of a sampled signal: column i+1 of @var{D}
## (N-by-(n+1)) is p^i / F(p) x for i = 0 .. n, F = [1 f1 .. fn] monic with
## n >= 1 distinct nonzero roots, the filters at rest at the first sample.
##
## The signal is held between samples by @var{rule}: @qcode{"zoh"}
## (constant) or @qcode{"foh"} (linear); for either the result is exact.
## By partial fractions p^i / F(p) = [i == n] + sum_k r_k^i / F'(r_k) /
## (p - r_k), so one first-order (complex) recursion per root, discretised
## exactly for the hold, gives all n + 1 derivatives (O(N n) work in
## @code{filter}). Roots closer than 1e-2 relative to each other are moved
## apart first by the caller (@code{residtrace_separate}): the partial
## fractions lose accuracy as 1/min |r_k - r_j|.
## @end deftypefn

function D = residtrace_modal (F, x, Ts, rule)
  F = F(:).' / F(1);
  n = numel (F) - 1;
  r = roots (F);
  N = numel (x);
  x = x(:);
  dF = polyval (polyder (F), r);          # F'(r_k) = prod_{j != k} (r_k - r_j)
  up = find (imag (r) >= 0);              # one root of each conjugate pair
  Mr = zeros (N, numel (up));
  Mi = zeros (N, numel (up));
  Cr = zeros (numel (up), n + 1);
  Ci = zeros (numel (up), n + 1);
  for i = 1:numel (up)
    k = up(i);
    z = r(k) * Ts;
    a = exp (z);
    if (strcmp (rule, "zoh"))
      m = filter ([0, Ts * phi1(z)], [1, -a], x);
    else
      g1 = Ts * phi2 (z);                 # weight of x(t+1)
      g0 = Ts * phi1 (z) - g1;            # weight of x(t)
      m = filter ([g1, g0], [1, -a], x, -g1 * x(1));
    endif
    w = 1 + (imag (r(k)) > 0);            # a pair counts twice (real part)
    c = w * r(k) .^ (0:n) / dF(k);
    Mr(:, i) = real (m);
    Mi(:, i) = imag (m);
    Cr(i, :) = real (c);
    Ci(i, :) = imag (c);
  endfor
  D = [Mr, Mi] * [Cr; -Ci];
  D(:, n+1) += x;                         # the direct term of p^n / F(p)
endfunction

## (e^z - 1) / z and (e^z - 1 - z) / z^2, by series near 0.
function v = phi1 (z)
  if (abs (z) < 1e-2)
    v = 1 + z / 2 + z ^ 2 / 6 + z ^ 3 / 24 + z ^ 4 / 120;
  else
    v = expm1 (z) / z;
  endif
endfunction

function v = phi2 (z)
  if (abs (z) < 1e-2)
    v = 1 / 2 + z / 6 + z ^ 2 / 24 + z ^ 3 / 120 + z ^ 4 / 720;
  else
    v = (expm1 (z) - z) / z ^ 2;
  endif
endfunction
