## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn {} {@var{out} =} plain_zoh_derivatives (@var{F}, @var{s}, @var{Ts})
## p^i s / F(p), i = 0..n (columns), exact for s held between samples:
## the ZOH-sampled state z(k+1) = Phi z(k) + g s(k) of 1/F, each state
## as a discrete transfer function run by the built-in filter (vectorised;
## numerators by the matrix determinant lemma, c (zI - Phi)^-1 g =
## (det (zI - Phi + g c) - det (zI - Phi)) / det (zI - Phi)).
## Shared by the plain-Octave baselines of the benchmarks.
## @end deftypefn

function out = plain_zoh_derivatives (F, s, Ts)
  n = numel (F) - 1;
  d = F(2:end) / F(1);
  A = [zeros(n - 1, 1), eye(n - 1); -fliplr(d)];
  E = expm ([A, [zeros(n - 1, 1); 1]; zeros(1, n + 1)] * Ts);
  Phi = E(1:n, 1:n);
  g = E(1:n, n+1);
  den = poly (Phi);
  out = zeros (numel (s), n + 1);
  for i = 1:n
    num = poly (Phi - g * ((1:n) == i)) - den;
    out(:, i) = filter ([0, num(2:end)], den, s);
  endfor
  out(:, n+1) = s - out(:, 1:n) * fliplr(d).';
endfunction
