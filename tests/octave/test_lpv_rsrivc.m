## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## An LPV model and a recursive estimator on the same scheduling-dependent
## system. The first-order system x' + a(rho) x = b(rho) u with
## a = 2 + rho, b = 3 + rho and rho = sin (2 pi t / 20), Ts = 0.01 s,
## 60 s of a random binary input held 6 samples, white output noise at
## 20 dB. The data come from simc's time-varying simulator (the Magnus
## integration of x' = -a(t) x + b(t) u, independent of simulLPVCT's Euler
## recursion). lpvsrivc, told the structure (basis [1, rho] for both
## coefficients), gives a(rho) and b(rho) for every rho; rsrivc
## ([nb nf nk] = [1 1 0], Kalman-filter adaptation with Qn = 1e-2 I, the
## best of Qn = 1e-5 .. 1 for this record: RMS errors 0.17, 0.22 against
## 0.7 for 1e-5 and 3 for 1) tracks a(t), b(t) with a lag and noise.
## Required: the LPV coefficients within 0.1 of the true ones (RMS over the
## record; the Euler model has an O(Ts) bias here: backward differences,
## and the held input lags the u_k that the model pairs with y_k by up to
## one sample), and the LPV trajectories closer to the truth than RSRIVC's
## over the second half of the record (after RSRIVC's start-up).
function test_lpv_rsrivc ()
  Ts = 0.01;
  randn ("state", 21);
  rand ("state", 21);
  u = kron (sign (randn (1000, 1)), ones (6, 1));
  N = numel (u);
  t = (0:N-1)' * Ts;
  rho = sin (2 * pi * t / 20);
  a = 2 + rho;
  b = 3 + rho;
  x = simc ([a b], [1 1 0], u, Ts);
  y = x + 0.1 * std (x) * randn (N, 1);
  data = iddata (y, u, Ts, "InterSample", "zoh");

  dep = reshape ([ones(1, N); rho'], 2, 1, N);
  [~, infos] = lpvsrivc (data, [1 1], dep, dep);
  a_lpv = [ones(N, 1), rho] * infos.Arivc(2, :)';
  b_lpv = [ones(N, 1), rho] * infos.Brivc(1, :)';
  thm = rsrivc (data, [1 1 0], "lambda_svf", 5, "adm", "kf",
                "adg", 1e-2 * eye (2), "tsiv", 5);
  b_rec = thm(:, 1);
  a_rec = thm(:, 2);

  rms = @(e) sqrt (mean (e .^ 2));
  half = (floor (N / 2) + 1):N;
  e_lpv = [rms(a_lpv - a), rms(b_lpv - b)];
  e_lpv_half = [rms(a_lpv(half) - a(half)), rms(b_lpv(half) - b(half))];
  e_rec_half = [rms(a_rec(half) - a(half)), rms(b_rec(half) - b(half))];
  printf ("RMS error of a(t), b(t): lpvsrivc %.4f %.4f, second half %.4f %.4f; rsrivc second half %.4f %.4f\n",
          e_lpv, e_lpv_half, e_rec_half);
  assert (all (e_lpv < 0.1));
  assert (all (e_lpv_half < e_rec_half));
endfunction
