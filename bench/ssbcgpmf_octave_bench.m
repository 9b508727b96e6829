## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## Side by side: the bias-compensated GPMF state-space estimate of the core
## (ssbcgpmf, through gpmf_mex) against the same iteration written in
## vectorised plain Octave: the GPMF channels discretised by the control
## package's c2d (ZOH for the inputs, which also pass through the
## artificial filter 1/F(p), and Tustin for the outputs) and run by
## filter(); the noise Gram of the output filter from its impulse response
## (W = sum_t (N - 1 - t) g(t) g(t)^T); the noise variances by the same
## Gauss-Newton with step halving on the constraints H^T beta_bar = 0; beta
## from beta_bar = F beta by least squares. A 2-output 2-input system of
## order 3 (indices [2 1]) with white output noise of 10 dB, one root -0.5
## per output.
##
## Usage, from the repository root, after building gpmf_mex:
##   octave-cli -q bench/ssbcgpmf_octave_bench.m
## Rows: N samples; columns: best-of-3 wall time of each path, their
## ratio, and the largest difference between the two estimates of [A B]
## (the output filters' discretisations differ: exact FOH in the core,
## Tustin here).

1;  # a script file, not a function file

function [A, B] = plain_gpmf_bc (y, u, Ts, nni, lambda, roots_)
  [N, p] = size (y);
  m = columns (u);
  eq = struct ("P", {}, "c", {}, "D", {}, "d", {}, "H", {}, "T", {},
               "alpha", {}, "width", {});
  for i = 1:p
    ord = nni(i) + 1;
    r = numel (roots_);
    den = poly (-lambda(i) * ones (1, ord));
    den_u = conv (den, poly (roots_));
    phi = [];
    for j = 1:p
      for k = 0:plain_gpmf_coupling (nni, i, j)-1
        phi(:, end+1) = -channel (k, den, lambda(i)^ord, Ts, "tustin",
                                  y(:, j));
      endfor
    endfor
    alpha = columns (phi);
    for l = 1:m
      for k = 0:nni(i)+r-1
        phi(:, end+1) = channel (k, den_u, lambda(i)^ord, Ts, "zoh", u(:, l));
      endfor
    endfor
    zeta = channel (nni(i), den, lambda(i)^ord, Ts, "tustin", y(:, i));
    ## noise Gram of the output filter from its impulse response
    impulse = [1; zeros(N - 2, 1)];
    g = zeros (N - 1, ord);
    for k = 0:nni(i)
      g(:, k+1) = channel (k, den, lambda(i)^ord, Ts, "tustin", impulse);
    endfor
    W = g.' * (g .* (N - 1 - (0:N-2).'));
    D = cell (1, p);
    d = zeros (columns (phi), 1);
    off = 0;
    for j = 1:p
      nu = plain_gpmf_coupling (nni, i, j);
      D{j} = zeros (columns (phi));
      D{j}(off+1:off+nu, off+1:off+nu) = W(1:nu, 1:nu);
      if (j == i)
        d(off+1:off+nu) = -W(1:nu, nni(i)+1);
      endif
      off += nu;
    endfor
    f = fliplr (poly (roots_)).';          # F(p), ascending powers
    T = zeros (nni(i) + r, nni(i));
    for k = 1:nni(i)
      T(k:k+r, k) = f;
    endfor
    [U, ~, ~] = svd (T);
    eq(i) = struct ("P", phi.' * phi, "c", phi.' * zeta, "D", {D}, "d", d,
                    "H", U(:, end-r+1:end), "T", T, "alpha", alpha,
                    "width", nni(i) + r);
  endfor
  sigma2 = zeros (p, 1);
  [g, J, thetas] = constraints (eq, sigma2, m, true);
  for iteration = 1:100
    step = J \ -g;
    cost = sumsq (g);
    improved = false;
    scale = 1;
    for halving = 1:40
      trial = max (sigma2 + scale * step, 0);
      [gt, ~, ~, ok] = constraints (eq, trial, m, false);
      if (ok && sumsq (gt) < cost)
        improved = true;
        break;
      endif
      scale /= 2;
    endfor
    moved = 0;
    if (improved)
      moved = norm (trial - sigma2);
      sigma2 = trial;
    endif
    [g, J, thetas] = constraints (eq, sigma2, m, true);
    if (! improved || moved <= 1e-10 * max (norm (sigma2), eps * max (y(:) .^ 2)))
      break;
    endif
  endfor
  parts = cell (1, p);
  for i = 1:p
    e = eq(i);
    th = thetas{i};
    beta = zeros (nni(i), m);
    for l = 1:m
      beta(:, l) = e.T \ th(e.alpha + (l-1)*e.width + (1:e.width));
    endfor
    parts{i} = [th(1:e.alpha); beta(:)];
  endfor
  [A, B] = plain_gpmf_canonical (parts, nni, m);
endfunction

## The stacked constraints H^T beta_bar(sigma^2) of every output equation
## and input, their Jacobian in sigma^2 and the compensated estimates.
function [g, J, thetas, ok] = constraints (eq, sigma2, m, jacobian)
  p = numel (eq);
  g = [];
  J = [];
  thetas = cell (1, p);
  ok = true;
  for i = 1:p
    e = eq(i);
    R = e.P;
    for j = 1:p
      R -= sigma2(j) * e.D{j};
    endfor
    [L, fail] = chol (R, "lower");
    if (fail)
      ok = false;
      return;
    endif
    solve = @(v) L.' \ (L \ v);
    th = solve (e.c - sigma2(i) * e.d);
    thetas{i} = th;
    response = zeros (numel (th), p);
    if (jacobian)
      for j = 1:p
        v = e.D{j} * th;
        if (j == i)
          v -= e.d;
        endif
        response(:, j) = solve (v);
      endfor
    endif
    for l = 1:m
      seg = e.alpha + (l-1)*e.width + (1:e.width);
      g = [g; e.H.' * th(seg)];
      if (jacobian)
        J = [J; e.H.' * response(seg, :)];
      endif
    endfor
  endfor
endfunction

## p^k lambda^ord / den(p) discretised by c2d and run by filter().
function x = channel (k, den, gain, Ts, rule, s)
  ord = numel (den) - 1;
  num = [zeros(1, ord - k), gain, zeros(1, k)];
  G = c2d (tf (num, den), Ts, rule);
  [b, a] = tfdata (G, "vector");
  b = [zeros(1, numel (a) - numel (b)), b];  # tfdata drops leading zeros
  x = filter (b, a, s);
endfunction

pkg load control;
addpath (fullfile (pwd, "octave"));
addpath (fullfile (pwd, "bench"));
A0 = [-1 1 0; -1 -1 0; 0 0 -2];
B0 = [1 0; 0 1; 1 1];
C0 = [1 0 1; 0 1 0];
Ts = 0.01;
T0 = [C0(1,:); C0(1,:) * A0; C0(2,:)];
theta0 = [T0 * A0 / T0, T0 * B0];
printf ("%8s %12s %12s %8s %12s %10s %10s\n", "N", "core [s]", "plain [s]",
        "ratio", "max|d[A B]|", "err core", "err plain");
for N = [2000 20000 100000]
  rand ("state", 1);
  randn ("state", 1);
  u = kron (sign (rand (ceil (N / 50), 2) - 0.5), ones (50, 1))(1:N, :);
  y = lsim (c2d (ss (A0, B0, C0, zeros (2)), Ts, "zoh"), u);
  y += 10^(-10/20) * std (y) .* randn (size (y));
  data = iddata (y, u, Ts);
  tc = tp = Inf;
  for r = 1:3
    t0 = tic;
    M = ssbcgpmf (data, [2 1], [3; 3], -0.5);
    tc = min (tc, toc (t0));
    t0 = tic;
    [Ap, Bp] = plain_gpmf_bc (y, u, Ts, [2 1], [3 3], -0.5);
    tp = min (tp, toc (t0));
  endfor
  d = max (abs ([M.A, M.B](:) - [Ap, Bp](:)));
  printf ("%8d %12.4g %12.4g %8.1f %12.3g %10.3g %10.3g\n", N, tc, tp,
          tp / tc, d, norm ([M.A, M.B] - theta0), norm ([Ap, Bp] - theta0));
endfor
