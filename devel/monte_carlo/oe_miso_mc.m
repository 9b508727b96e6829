## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn {} {@var{R} =} oe_miso_mc (@var{runs})
## Monte Carlo check of the standard deviations reported by the
## multi-input output-error estimators (target: spread / mean
## reported sd in 0.8-1.25), two inputs, each with its own denominator:
## @itemize
## @item @code{oe} (discrete time), y = (0.5 q^-2 + 0.3 q^-3)/(1 - 1.5
## q^-1 + 0.7 q^-2) u1 + (1.2 q^-2 - 0.4 q^-3)/(1 - 0.6 q^-1) u2 + e,
## N = 1000, white e of sd 0.3;
## @item @code{tfest} (continuous time, ZOH), y = (1.5 s + 4)/(s^2 + 2.4 s
## + 4) u1 + 2/(s + 0.8) u2(t - 0.25) + e, Ts = 0.05, N = 1000, sd 0.2;
## @item @code{tfest} on two-input frequency-domain iddata (the DFT of a
## two-channel multisine through the same system, noise on Y) and on an
## idfrd with one output and two inputs (50 frequencies, circular complex
## noise of sd 0.05 on each response).
## @end itemize
## Prints and returns the ratio per parameter (getpvec's order), and the
## ratio of the robust spread (1.4826 median absolute deviation).
## @example
## devel/run-study oe_miso_mc 200
## @end example
## @end deftypefn

function R = oe_miso_mc (runs)
  if (nargin < 1)
    runs = 200;
  endif
  warning ("off", "all");
  mc = @mc_sd_ratio;                    # devel/monte_carlo/mc_sd_ratio.m
  ## discrete time
  N = 1000;
  rand ("state", 1);
  u1 = sign (rand (N, 1) - 0.5);
  u2 = filter (1, [1 -0.5], sign (rand (N, 1) - 0.5));
  x = filter ([0 0 0.5 0.3], [1 -1.5 0.7], u1) ...
      + filter ([0 0 1.2 -0.4], [1 -0.6], u2);
  dt = @() iddata (x + 0.3 * randn (N, 1), [u1 u2], 1);
  R.oe = mc ("oe, 2 inputs (DT)", runs,
             @() free_pvec (oe (dt (), [2 2 2 1 2 2])));
  ## continuous time, ZOH
  Ts = 0.05;
  v1 = sign (rand (N, 1) - 0.5);
  v2 = v1(randperm (N));
  xc = zoh_sim ([1.5 4], [1 2.4 4], v1, Ts) ...
       + zoh_sim (2, [1 0.8], [zeros(5, 1); v2(1:end-5)], Ts);
  ct = @() iddata (xc + 0.2 * randn (N, 1), [v1 v2], Ts);
  R.tfest = mc ("tfest, 2 inputs (CT, ZOH)", runs,
                @() free_pvec (tfest (ct (), [2 1], [1 0], [0 0.25])));
  ## frequency-domain iddata
  rand ("state", 5); ui = sign (rand (400, 2) - 0.5);  # independent inputs
  U = fft (iddata ([], ui, 0.05, "InterSample", "bl"));
  U.Ts = 0;
  wu = get (U, "Frequency"); Ud = get (U, "InputData");
  Y0 = polyval ([1.5 4], 1i * wu) ./ polyval ([1 2.4 4], 1i * wu) ...
       .* Ud(:, 1) + 2 ./ (1i * wu + 0.8) .* Ud(:, 2);
  K = numel (Y0);
  Ys = sim (idpoly (1, {[1.5 4], 2}, 1, 1, {[1 2.4 4], [1 0.8]}, "Ts", 0), U);
  fd = @() noisy_fd (Ys, Y0, U);
  R.tfest_iddata = mc ("tfest, 2 inputs (frequency iddata)", runs,
                       @() free_pvec (tfest (fd (), [2 1], [1 0])));
  ## idfrd, one output, two inputs
  w = logspace (-1, 1.5, 50).';
  s = 1i * w;
  G1 = (1.5 * s + 4) ./ (s .^ 2 + 2.4 * s + 4);
  G2 = 2 ./ (s + 0.8);
  frd = @() noisy_frd (G1, G2, w);
  R.tfest_idfrd = mc ("tfest, 1 output 2 inputs (idfrd)", runs,
                      @() free_pvec (tfest (frd (), [2 1], [1 0])));
endfunction

## [Y U] with circular complex noise of sd 0.1 sqrt (2) on Y = Y0.
function d = noisy_fd (Ys, Y0, U)
  K = numel (Y0);
  Ys.y = Y0 + 0.1 * (randn (K, 1) + 1i * randn (K, 1));
  d = [Ys U];
endfunction

## The idfrd of [G1 G2] with circular complex noise of sd 0.05 on each.
function F = noisy_frd (G1, G2, w)
  K = numel (w);
  noise = @() 0.05 * (randn (K, 1) + 1i * randn (K, 1)) / sqrt (2);
  R = zeros (1, 2, K);
  R(1, 1, :) = G1 + noise ();
  R(1, 2, :) = G2 + noise ();
  F = idfrd (R, w, "Ts", 0);
endfunction

function y = zoh_sim (n, d, u, Ts)
  [b, a] = tfdata (c2d (tf (n, d), Ts, "zoh"), "vector");
  b = [zeros(1, numel (a) - numel (b)), b];
  y = filter (b, a, u);
endfunction

## The free parameters of getpvec (sd > 0: not the fixed zeros or delays).
function [th, sd] = free_pvec (M)
  [th, sd] = getpvec (M);
  keep = sd > 0;
  [th, sd] = deal (th(keep), sd(keep));
endfunction
