## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn {} {} test_residtrace_delay ()
## A transport delay that is not a whole number of samples:
## @itemize
## @item the fractional input channel (@file{octave/private/residtrace_channels.m},
## its inline tests: the identity (1 - f) u(k) + f u(k-1), and the
## simulation of a delay of 3.4 samples against an exact sub-stepped
## simulation of the delayed held input);
## @item a second-order plant behind a delay of 3.5 samples, simulated
## exactly for its held input (20 sub-steps per sample), and a model
## fitted by srivc without delay: residtrace names the delay, not an
## order change, sizes it to a fraction of a sample (3.5 +- 0.25) and
## brings the validation error down to the noise; the returned model,
## simulated again by @code{residtrace_sim}, gives the same figure.
## @end itemize
## @example
## octave --no-gui -q --eval \
##   "addpath tests/octave; test_residtrace_delay"
## @end example
## @end deftypefn

function test_residtrace_delay ()
  ctid_run_private_tests ("residtrace_channels.m");
  randn ("state", 41); rand ("state", 41);
  Ts = 0.05; S = 20;
  G = idctm (4, [1 2.4 4]);
  sim = @(u) delayed (G, u, Ts, S, 3.5);
  u = prbs (10, 4); uv = circshift (u, 300); N = numel (u);
  s = 0.02;
  y = sim (u) + s * randn (N, 1);
  yv = sim (uv) + s * randn (N, 1);
  ws = warning ("off", "all");
  M = srivc (iddata (y - mean (y), u - mean (u), Ts), [1 2 0]);
  warning (ws);
  M = idctm (M.B, M.F);
  R = residtrace (iddata (y, u, Ts), M, "validation", iddata (yv, uv, Ts),
                  "effects", {"delay", "order"}, "iterate", 1);
  printf ("delay of 3.5 samples: %s (%s), RMSE %.4g -> %.4g\n", R.effect,
          R.evidence.text, R.rmse_before, R.rmse_after);
  assert (R.effect, "delay");
  assert (R.evidence.value, 3.5, 0.25);
  assert (R.rmse_after < 1.3 * s);
  ## the returned model carries the fraction: simulated again on the
  ## validation record it gives the figure residtrace scored
  [~, ~, rm] = residtrace_sim (R, iddata (yv, uv, Ts));
  assert (rm, R.rmse_after, 1e-9 * R.rmse_after);
endfunction

## The output of G for the held input u delayed by d samples: the input
## held over S sub-steps per sample, shifted by round (d S) sub-steps,
## simulated on the fine grid and sampled.
function y = delayed (G, u, Ts, S, d)
  uf = kron (u(:), ones (S, 1));
  k = round (d * S);
  uf = [zeros(k, 1); uf(1:end-k)];
  yf = simc (G, uf, Ts / S);
  y = yf(1:S:end);
endfunction
