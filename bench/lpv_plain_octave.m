## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn {} {[@var{A}, @var{B}, @var{ysim}] =} lpv_plain_octave (@var{y}, @var{u}, @var{Ts}, @var{DepA}, @var{DepB}, @var{K}, @var{Ainit}, @var{Binit})
## The LPV-SRIVC iteration of core/include/ctid/offline/lpv_refined_iv.hpp
## written in plain, vectorised Octave (products of whole columns,
## @code{filter} for the prefilters, one loop over the samples for the
## Euler simulation of the auxiliary model): @var{K} iterations from the
## model @var{Ainit}, @var{Binit}, no convergence test.  The baseline of
## @file{lpv_octave_bench.m}.
## @end deftypefn

function [A, B, ysim] = lpv_plain_octave (y, u, Ts, DepA, DepB, K, Ainit, Binit)
  y = y(:); u = u(:); N = numel (y);
  nfa = size (DepA, 1); na = size (DepA, 2);
  nfb = size (DepB, 1); nb = size (DepB, 2);
  FA = reshape (permute (DepA, [3 1 2]), N, nfa * na);  # column j + nfa*(i-1)
  FB = reshape (permute (DepB, [3 1 2]), N, nfb * nb);
  act_a = find (any (FA != 0, 1));
  act_b = find (any (FB != 0, 1));
  const_a = act_a(all (FA(:, act_a) == FA(1, act_a), 1));
  ia = floor ((act_a - 1) / nfa) + 1;     # coefficient of each a term
  ib = floor ((act_b - 1) / nfb) + 1;
  dy = zeros (N, na + 1); du = zeros (N, nb);
  for m = 0:na
    dy(:, m + 1) = filter (diffw (m, Ts), 1, y);
  endfor
  for m = 0:nb - 1
    du(:, m + 1) = filter (diffw (m, Ts), 1, u);
  endfor
  ## Raw products: a terms -f D^(na-i) s, b terms g D^(nb-i) u.
  Pb = FB(:, act_b) .* du(:, nb - ib + 1);
  Pay = -FA(:, act_a) .* dy(:, na - ia + 1);
  theta = [Ainit(sub2ind (size (Ainit), ia + 1, mod (act_a - 1, nfa) + 1)), ...
           Binit(sub2ind (size (Binit), ib, mod (act_b - 1, nfb) + 1))]' / Ainit(1, 1);
  for it = 1:K
    [A, B] = to_matrices (theta, act_a, act_b, nfa, na, nfb, nb);
    chi = simulate (u, Ts, A, FA, B, FB, na, nb, nfa, nfb);
    alti = zeros (1, na);
    for q = 1:numel (act_a)
      if (any (const_a == act_a(q)))
        alti(ia(q)) += theta(q) * FA(1, act_a(q));
      endif
    endfor
    if (any (real (roots ([1 alti])) >= 0))
      frozen = zeros (N, na);
      for i = 1:na
        frozen(:, i) = FA(:, (i-1)*nfa + (1:nfa)) * A(i + 1, :)';
      endfor
      alti = mean (frozen, 1);
      if (any (real (roots ([1 alti])) >= 0))
        r = roots ([1 alti]); r = -abs (real (r)) + 1i * imag (r);
        alti = real (poly (r))(2:end);
      endif
    endif
    den = zeros (1, na + 1);
    c = [1 alti];
    for i = 0:na
      w = diffw (na - i, Ts);
      den(1:numel (w)) += c(i + 1) * w;
    endfor
    den = den / den(1);
    dchi = zeros (N, na);
    for m = 0:na - 1
      dchi(:, m + 1) = filter (diffw (m, Ts), 1, chi);
    endfor
    Pachi = -FA(:, act_a) .* dchi(:, na - ia + 1);
    Z = filter (1, den, [Pachi, Pb]);
    Pphi = Pachi;
    isc = ismember (act_a, const_a);
    Pphi(:, isc) = Pay(:, isc);
    Phi = filter (1, den, [Pphi, Pb]);
    target = filter (1, den, dy(:, na + 1));
    sp = 1 ./ sqrt (sum (Phi.^2, 1)); sz = 1 ./ sqrt (sum (Z.^2, 1));
    M = (sz' .* (Z' * Phi)) .* sp;
    theta = sp' .* (M \ (sz' .* (Z' * target)));
  endfor
  [A, B] = to_matrices (theta, act_a, act_b, nfa, na, nfb, nb);
  ysim = simulate (u, Ts, A, FA, B, FB, na, nb, nfa, nfb);
endfunction

function w = diffw (m, Ts)
  w = ((-1) .^ (0:m)) .* arrayfun (@(l) nchoosek (m, l), 0:m) * Ts^-m;
endfunction

function [A, B] = to_matrices (theta, act_a, act_b, nfa, na, nfb, nb)
  A = zeros (na + 1, nfa); A(1, 1) = 1;
  B = zeros (nb, nfb);
  for q = 1:numel (act_a)
    i = floor ((act_a(q) - 1) / nfa) + 1; j = mod (act_a(q) - 1, nfa) + 1;
    A(i + 1, j) = theta(q);
  endfor
  for q = 1:numel (act_b)
    i = floor ((act_b(q) - 1) / nfb) + 1; j = mod (act_b(q) - 1, nfb) + 1;
    B(i, j) = theta(numel (act_a) + q);
  endfor
endfunction

## Euler simulation: sum_i alpha_i(k) D^(na-i) y_k = sum_i beta_i(k) D^(nb-i) u_k.
function y = simulate (u, Ts, A, FA, B, FB, na, nb, nfa, nfb)
  N = numel (u);
  alpha = zeros (N, na + 1); alpha(:, 1) = A(1, 1);
  for i = 1:na
    alpha(:, i + 1) = FA(:, (i-1)*nfa + (1:nfa)) * A(i + 1, :)';
  endfor
  r = zeros (N, 1);
  for i = 1:nb
    r += (FB(:, (i-1)*nfb + (1:nfb)) * B(i, :)') .* filter (diffw (nb - i, Ts), 1, u);
  endfor
  ## Row k of W: weights of y_k, y_(k-1), .., y_(k-na).
  W = zeros (N, na + 1);
  for i = 0:na
    w = diffw (na - i, Ts);
    W(:, 1:numel (w)) += alpha(:, i + 1) .* w;
  endfor
  y = zeros (N, 1);
  past = zeros (na, 1);                  # y_(k-1) .. y_(k-na)
  for k = 1:N
    y(k) = (r(k) - W(k, 2:end) * past) / W(k, 1);
    past = [y(k); past(1:end-1)];
  endfor
endfunction
