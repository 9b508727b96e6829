## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## The RLSSVF step of CONTSID's LTI demo, as its users write it, runs
## unchanged on data from our simc: an iddata object with InterSample 'zoh'
## and rlssvf (data, [2 1 0], 'lambda_svf', 2). On noise-free data of a
## second-order system the final estimate is within 1e-3 (relative) of the
## truth (the only error is the trapezoidal filtering of y, O((w Ts)^2)).
function test_contsid_lti_demo ()
  Ts = 0.01;
  u = prbs (12, 50);
  N = numel (u);
  B = 2; F = [1 1.2 2];                     # 2 / (p^2 + 1.2 p + 2)
  y = simc (struct ("B", B, "F", F), u, Ts);
  data = iddata (y, u, Ts, "InterSample", "zoh");
  [thm, yh] = rlssvf (data, [2 1 0], "lambda_svf", 2);
  truth = [1.2 2 2];
  err = norm (thm(end, :) - truth) / norm (truth);
  printf ("relative error of the final estimate: %.2e\n", err);
  assert (err < 1e-3);
  fit = 100 * (1 - norm (y - yh) / norm (y - mean (y)));
  printf ("fit of the frozen-model output: %.2f %%\n", fit);
  assert (fit > 99);
  ## The same call with the control package's iddata loaded.
  pkg load control
  data = iddata (y, u, Ts, "InterSample", "zoh");
  thm2 = rlssvf (data, [2 1 0], "lambda_svf", 2);
  assert (thm2, thm, 0);
endfunction
