## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## Side by side: the GPMF least-squares state-space estimate of the core
## (sslsgpmf, through gpmf_mex) against the same regression written in
## vectorised plain Octave (each GPMF channel p^k (lambda/(p+lambda))^(n+1)
## discretised by the control package's c2d, ZOH for the inputs and
## Tustin for the outputs, run by filter(), then the LS solve by
## backslash), on a 2-output 2-input system of order 3 (indices [2 1]).
##
## Usage, from the repository root, after building gpmf_mex:
##   octave-cli -q bench/gpmf_octave_bench.m
## Rows: N samples; columns: best-of-3 wall time of each path, their
## ratio, and the largest difference between the two estimates of [A B].

1;  # a script file, not a function file

function [A, B] = plain_gpmf_ls (y, u, Ts, nni, lambda)
  p = columns (y);
  m = columns (u);
  thetas = cell (1, p);
  for i = 1:p
    ord = nni(i) + 1;
    den = poly (-lambda(i) * ones (1, ord));
    filt = @(k, rule, s) filter_channel (k, ord, den, lambda(i), Ts, rule, s);
    phi = [];
    for j = 1:p
      for k = 0:plain_gpmf_coupling (nni, i, j)-1
        phi(:, end+1) = -filt (k, "tustin", y(:, j));
      endfor
    endfor
    for l = 1:m
      for k = 0:nni(i)-1
        phi(:, end+1) = filt (k, "zoh", u(:, l));
      endfor
    endfor
    zeta = filt (nni(i), "tustin", y(:, i));
    thetas{i} = phi \ zeta;
  endfor
  [A, B] = plain_gpmf_canonical (thetas, nni, m);
endfunction

function x = filter_channel (k, ord, den, lambda, Ts, rule, s)
  num = [zeros(1, ord - k), lambda^ord, zeros(1, k)];
  num = num(end-ord:end);
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
printf ("%8s %12s %12s %8s %12s\n", "N", "core [s]", "plain [s]",
        "ratio", "max|d[A B]|");
for N = [2000 20000 100000]
  rand ("state", 1);
  u = kron (sign (rand (ceil (N / 50), 2) - 0.5), ones (50, 1))(1:N, :);
  y = lsim (c2d (ss (A0, B0, C0, zeros (2)), Ts, "zoh"), u);
  data = iddata (y, u, Ts);
  tc = tp = Inf;
  for r = 1:3
    t0 = tic;
    M = sslsgpmf (data, [2 1], [3; 3]);
    tc = min (tc, toc (t0));
    t0 = tic;
    [Ap, Bp] = plain_gpmf_ls (y, u, Ts, [2 1], [3 3]);
    tp = min (tp, toc (t0));
  endfor
  d = max (abs ([M.A, M.B](:) - [Ap, Bp](:)));
  printf ("%8d %12.4g %12.4g %8.1f %12.3g\n", N, tc, tp, tp / tc, d);
endfor
