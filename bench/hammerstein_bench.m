## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn {} {@var{T} =} hammerstein_bench ()
## Side-by-side timing (target: at least 50 times faster) of
## @code{hsrivc} (core @file{hammerstein.hpp} through the gateway, options
## and checks included) against @file{hsrivc_plain_octave.m}, the same
## iteration in plain Octave (built-in @code{filter}), on 10 000 samples
## of CONTSID's Hammerstein demo system (ubar = u + 0.5 u^2 + 0.25 u^3,
## G = (10 s + 30)/(s^2 + s + 5), Ts = 0.05, white noise, SNR 20 dB).
## Both are started from the same SVF cut-off and run 3 times; the
## median is kept. Prints the wall and CPU times (the CPU time of the
## process: on a shared, loaded machine the wall time mostly measures the
## wait for a core), their ratios and both estimates.
## @example
## octave-cli -q --eval "addpath octave bench; hammerstein_bench"
## @end example
## @end deftypefn

function T = hammerstein_bench ()
  rand ("state", 2); randn ("state", 2);
  N = 10000; Ts = 0.05;
  u = kron (4 * rand (N / 10, 1) - 2, ones (10, 1));
  W = [u u.^2 u.^3];
  ydet = simc (idpoly (1, [10 30], 1, 1, [1 1 5], 0, 0),
               iddata ([], W * [1; 0.5; 0.25], Ts));
  y = ydet + 0.1 * std (ydet) * randn (N, 1);
  data = iddata (y, W, Ts);
  lambda = 3;
  warning ("off", "all");
  tc = zeros (1, 3); tp = tc; cc = tc; cp = tc;
  for k = 1:3
    tic; c0 = cputime ();
    [~, I] = hsrivc (data, [2 2 0], "lambda", lambda, "Tol", 1e-6);
    tc(k) = toc; cc(k) = cputime () - c0;
    tic; c0 = cputime ();
    [f, b, alpha, it] = hsrivc_plain_octave (y, W, Ts, 2, 2, lambda, 30,
                                             1e-6);
    tp(k) = toc; cp(k) = cputime () - c0;
  endfor
  T = struct ("core", median (tc), "plain", median (tp),
              "ratio", median (tp) / median (tc), "core_cpu", median (cc),
              "plain_cpu", median (cp), "ratio_cpu", median (cp) / median (cc),
              "core_theta", I.theta.',
              "plain_theta", [f b alpha(2:end)], "core_iter", I.iternum,
              "plain_iter", it);
  printf (["hsrivc on %d samples: core %.3f s (%d iterations), plain ", ...
           "Octave %.3f s (%d iterations), ratio %.1f\n"],
          N, T.core, I.iternum, T.plain, it, T.ratio);
  printf ("  CPU time: core %.3f s, plain Octave %.3f s, ratio %.2f\n",
          T.core_cpu, T.plain_cpu, T.ratio_cpu);
  printf (["  truth        [1 5 10 30 0.5 0.25]\n  core  theta  %s\n", ...
           "  plain theta  %s\n"],
          mat2str (T.core_theta, 4), mat2str (T.plain_theta, 4));
endfunction
