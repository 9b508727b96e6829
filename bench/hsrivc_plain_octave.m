## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn {} {[@var{f}, @var{b}, @var{alpha}, @var{iter}] =} hsrivc_plain_octave (@var{y}, @var{W}, @var{Ts}, @var{nb}, @var{nf}, @var{lambda}, @var{maxiter}, @var{tol})
## The HSRIVC iteration of @code{hsrivc} written in plain Octave: the
## baseline of @file{hammerstein_bench.m}. Start: least squares on the
## data filtered by the SVF 1/(p + lambda)^nf; then each iteration filters
## y, the basis columns W and the auxiliary-model output x = B/A (W alpha)
## by p^k/A(p), k = 0..nf (ZOH discretisation of the companion state
## space, each transfer function run by the built-in @code{filter}),
## solves the IV normal equations of the MISO model with common
## denominator and separates alpha (alpha_1 = 1) and b by the leading
## singular pair of the matrix of products. Same structure and stop rule
## as the core; no start grid, no time scaling, no stability safeguards.
## @end deftypefn

function [f, b, alpha, it] = hsrivc_plain_octave (y, W, Ts, nb, nf, lambda,
                                                  maxiter, tol)
  l = columns (W);
  A0 = poly (-lambda * ones (1, nf));
  [Yf, Wf] = deal (svf (A0, y, Ts), cellfun (@(c) svf (A0, c, Ts),
                                            num2cell (W, 1), "UniformOutput",
                                            false));
  th = ls_step (Yf, Wf, Yf, nb, nf, l);
  [f, b, alpha] = separate (th, nb, nf, l);
  for it = 1:maxiter
    A = [1 f];
    ubar = W * alpha(:);
    x = simulate (b, A, ubar, Ts);
    Yf = svf (A, y, Ts);
    Xf = svf (A, x, Ts);
    Wf = cellfun (@(c) svf (A, c, Ts), num2cell (W, 1), "UniformOutput",
                  false);
    th = ls_step (Yf, Wf, Xf, nb, nf, l);
    fo = [f b alpha(2:end)];
    [f, b, alpha] = separate (th, nb, nf, l);
    fn = [f b alpha(2:end)];
    if (norm (fn - fo) / norm (fn) < tol)
      break;
    endif
  endfor
endfunction

## Columns p^k/A(p) s, k = 0..nf (ZOH), as an N-by-(nf+1) matrix.
function F = svf (A, s, Ts)
  n = numel (A) - 1;
  Ac = [zeros(n - 1, 1) eye(n - 1); -fliplr(A(2:end))];
  Bc = [zeros(n - 1, 1); 1];
  E = expm ([Ac Bc; zeros(1, n + 1)] * Ts);
  Ad = E(1:n, 1:n);
  Bd = E(1:n, end);
  den = real (poly (Ad));
  F = zeros (numel (s), n + 1);
  for k = 1:n
    C = zeros (1, n);
    C(k) = 1;
    num = real (poly (Ad - Bd * C)) - den;
    F(:, k) = filter (num, den, s);
  endfor
  F(:, n + 1) = s - F(:, 1:n) * fliplr (A(2:end)).';
endfunction

function x = simulate (b, A, u, Ts)
  F = svf (A, u, Ts);
  m = numel (b);
  x = F(:, m:-1:1) * b(:);
endfunction

## IV step: p^nf y_f = -sum a_i p^(nf-i) y_f + sum_i sum_k beta_ik p^k w_i,f.
function th = ls_step (Yf, Wf, Xf, nb, nf, l)
  Phi = -Yf(:, nf:-1:1);
  Z = -Xf(:, nf:-1:1);
  for i = 1:l
    Phi = [Phi Wf{i}(:, nb:-1:1)];
    Z = [Z Wf{i}(:, nb:-1:1)];
  endfor
  th = (Z' * Phi) \ (Z' * Yf(:, nf + 1));
endfunction

function [f, b, alpha] = separate (th, nb, nf, l)
  f = th(1:nf).';
  M = reshape (th(nf+1:end), nb, l).';
  [U, S, V] = svd (M, "econ");
  alpha = (U(:, 1) / U(1, 1)).';
  b = (S(1, 1) * U(1, 1) * V(:, 1)).';
endfunction
