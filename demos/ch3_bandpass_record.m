## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn {} {@var{r} =} ch3_bandpass_record (@var{seed}, @var{phase}, @var{nper}, @var{w0})
## Helper of demo_ch3_bandpass and of the single-precision test: a
## simulated record standing in for the band-pass benchmark of thesis
## sec. 4.1 (eq. 4.1),
##
##   (p^2 + a1 p + a2(t)) x = (b0 p + b1) u,   y = x + e,
##   a1 = b0 = 0.3 w0,  b1 = 0,  a2(t) = w0^2 (1 + 0.3 sin (2 pi t/T + phase)),
##
## sampled at fs = 156250 Hz, T = 15640 samples (one period of the data and
## of the one-harmonic scheduling, as in the benchmark), @var{nper} periods
## (default 3) in periodic steady state (one more period is simulated first
## and dropped). @var{w0} is the resonance (default 5e4 rad/s). The input
## is a random-phase multisine over the harmonics 1 .. 1600 of fs/T
## (10 Hz - 16 kHz), 70 mV RMS, its phases drawn after
## rand ("state", @var{seed}); the input is linear between samples (FOH).
## The noise e is white, drawn after randn ("state", @var{seed}), for an
## SNR of 65 dB (10 log10 of mean x^2 over mean e^2). @var{phase} shifts
## the scheduling (0 for the estimation and validation records, pi/2 for
## the training record, as the benchmark's second scheduling signal).
##
## Returns a struct with @code{Ts}, @code{t}, @code{u}, @code{y}, @code{x},
## @code{theta} (N-by-4, [a1 a2 b0 b1]), @code{scale} (the size of each
## parameter: [a1 a2 b0 b0*w0]), @code{data} (iddata, InterSample foh),
## @code{Np} and @code{snr}.
## @end deftypefn

function r = ch3_bandpass_record (seed, phase = 0, nper = 3, w0 = 5e4)
  fs = 156250;
  Ts = 1 / fs;
  Np = 15640;
  kmax = 1600;
  rand ("state", seed);
  U = zeros (Np, 1);
  U(2:kmax+1) = exp (2i * pi * rand (kmax, 1));
  u1 = real (ifft (U));
  u1 = 0.070 * u1 / sqrt (mean (u1 .^ 2));
  N = (nper + 1) * Np;
  t = (0:N-1)' * Ts;
  u = repmat (u1, nper + 1, 1);
  a2 = w0 ^ 2 * (1 + 0.3 * sin (2 * pi * t / (Np * Ts) + phase));
  theta = [0.3 * w0 * ones(N, 1), a2, 0.3 * w0 * ones(N, 1), zeros(N, 1)];
  x = simc (theta, [2 2 0], u, Ts, "InterSample", "foh");
  keep = Np + 1:N;                                # periodic steady state
  r.Ts = Ts;
  r.Np = Np;
  r.t = t(1:nper * Np);
  r.u = u(keep);
  r.x = x(keep);
  r.theta = theta(keep, :);
  r.scale = [0.3 * w0, w0 ^ 2, 0.3 * w0, 0.3 * w0 ^ 2];
  r.snr = 65;
  randn ("state", seed);
  e = randn (numel (r.x), 1);
  r.y = r.x + e * sqrt (mean (r.x .^ 2) / 10 ^ (r.snr / 10));
  r.data = iddata (r.y, r.u, Ts, "InterSample", "foh");
endfunction
