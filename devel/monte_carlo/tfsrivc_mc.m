## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## Monte Carlo of tfsrivc (delay estimated): spread of the estimates
## against the reported standard deviations. Run from the repository
## root: devel/run-study tfsrivc_mc
## (R = 40 runs, about 20-30 s; set R before running for more).
## Measured (R = 40): ratios MC std / mean reported sd for b1 b0 f1 f2 td
## 1.33 1.18 1.09 1.04 1.33. This system has relative degree 1: with a
## ZOH input y(t_k) has kinks in td whenever td crosses a whole sample,
## and at an sd of 0.2 samples the linearisation behind sigma^2 (J'J)^-1
## under-reports td and b1. With the delay fixed the ratios are 0.97-1.08;
## for 4/(s^2+1.2s+4) (relative degree 2, the %!test in tfsrivc.m) they
## are 0.97-1.05 with td estimated.
if (! exist ("R", "var"))
  R = 40;
endif
Ts = 0.05;
u = prbs (10, 4);
u = [u; u](1:2000);
M0 = idtf ([0.5 4], [1 1.2 4], "IODelay", 0.37);      # 7.4 samples
y0 = simc (M0, iddata ([], u, Ts, "InterSample", "zoh"));
P = zeros (R, 5);
S = P;
randn ("state", 7);
t_run = tic ();
for r = 1:R
  data = iddata (y0 + 0.2 * randn (size (y0)), u, Ts, "InterSample", "zoh");
  M = tfsrivc (data, 2, 1, 0.3);
  [p, s] = getpvec (M);                 # [b1 b0 f1 f2 IODelay]
  P(r, :) = p';
  S(r, :) = s';
endfor
printf ("%d runs in %.1f s\n", R, toc (t_run));
printf ("%12s %10s %10s %10s %10s %10s\n", "", "b1", "b0", "f1", "f2", "td");
printf ("%12s %10.4f %10.4f %10.4f %10.4f %10.4f\n", "true", ...
        getpvec (M0));
printf ("%12s %10.4f %10.4f %10.4f %10.4f %10.4f\n", "mean", mean (P));
printf ("%12s %10.4f %10.4f %10.4f %10.4f %10.4f\n", "MC std", std (P));
printf ("%12s %10.4f %10.4f %10.4f %10.4f %10.4f\n", "mean sd", mean (S));
printf ("%12s %10.4f %10.4f %10.4f %10.4f %10.4f\n", "ratio", ...
        std (P) ./ mean (S));
