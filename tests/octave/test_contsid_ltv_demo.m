## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## The estimation steps of CONTSID's recursive LTI/LTV demos, written as
## its users write them (iddata with InterSample 'zoh', the 7.2/7.3 and the
## 7.0/7.1 syntax), run unchanged on data from our simc, and the IV methods
## track a drifting parameter better than RLSSVF does on noisy data.
function test_contsid_ltv_demo ()
  Ts = 0.05;
  u = prbs (13, 10);
  N = numel (u);
  t = (0:N-1)' * Ts;
  a1 = 2 + 1.5 * t / t(end);                       # drifting damping
  theta = [a1, 4 * ones(N, 1), 4 * ones(N, 1)];    # [a1 a2 b0]
  randn ("state", 11);
  y = simc (theta, [2 1 0], u, Ts) + 0.3 * randn (N, 1);
  data = iddata (y, u, Ts, "InterSample", "zoh");
  Qn = diag ([1e-6 1e-8 1e-8]);
  lam = 3;

  thm_ls = rlssvf (data, [2 1 0], "lambda_svf", lam, "adm", "kf", "adg", Qn);
  thm_ls_old = rlssvf (data, [2 1 0], lam, "adm", "rw", "adg", Qn);
  assert (thm_ls_old, thm_ls, 0);
  thm_iv = rivsvf (data, [2 1 0], "lambda_svf", lam, "adm", "kf", ...
                   "adg", Qn, "tsiv", 100);
  thm_iv_old = rivsvf (data, [2 1 0], lam, "adm", "rw", "adg", Qn, ...
                       "tsiv", 100);
  assert (thm_iv_old, thm_iv, 0);
  thm_sr = rsrivc (data, [1 2 0], "lambda_svf", lam, "adm", "kf", ...
                   "adg", Qn([3 1 2], [3 1 2]), "tsiv", 100);
  [thm_sr2, yh] = rsrivc (data, [1 2 0], "A", [1 4 4], "adm", "kf", ...
                          "adg", Qn([3 1 2], [3 1 2]), "tsiv", 100);
  assert (size (yh), [N 1]);

  after = t > 200;
  err = @(a) sqrt (mean ((a(after) - a1(after)) .^ 2));
  e_ls = err (thm_ls(:, 1));
  e_iv = err (thm_iv(:, 1));
  e_sr = err (thm_sr(:, 2));
  e_sr2 = err (thm_sr2(:, 2));
  printf ("RMS error of a1 after 200 s: RLSSVF %.3f, RIVSVF %.3f, ", e_ls, e_iv);
  printf ("RSRIVC %.3f (A start %.3f)\n", e_sr, e_sr2);
  assert (e_iv < 0.7 * e_ls);
  assert (e_sr < 0.7 * e_ls);
  assert (e_sr2 < 0.7 * e_ls);
  ## The frozen models of the estimates, and the model/data comparison.
  [mag, ph, w] = bode4frozensys (thm_iv, [2 1], "w", logspace (-1, 1, 10));
  assert (size (mag), [10 10]);
  ## (From 200 s on: the start-up estimates, theta0 = 0 and P0 = 1e4 I,
  ## include unstable frozen models whose simulation swamps any fit.)
  idx = find (after);
  [~, info] = comparec (data(idx), thm_iv(idx, :), [2 1 0]);
  fit = info.Fit;
  printf ("fit of the RIVSVF frozen models after 200 s: %.1f %%\n", fit);
  assert (fit > 50);
endfunction
