## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## CONTSID's TFFSRIVC / TFFCOE demo: relay feedback test of
## (-0.4 s + 0.1)/(s^2 + 0.24 s + 0.1) with a delay of 1 s, Ts = 0.05 s,
## hysteresis [1 -1], 15 dB. Per run: tffsrivc's delay and its reported
## sd, tffcoe's, and the largest difference between the two models
## relative to the sd (the SRIVC fixed point is a stationary point of the
## output-error criterion, so the two agree), and the output-error loss of
## each. Run from the repository root:
## devel/run-study tffsrivc_relay_mc
## (R = 10 runs; set R, and seed for other draws, first).
if (! exist ("R", "var"))
  R = 10;
endif
num = [-0.4 0.1];
den = [1 0.24 0.1];
if (! exist ("seed", "var"))
  seed = 31;
endif
randn ("state", seed);
rand ("state", seed);
T = zeros (R, 4);
printf ("%4s %9s %9s %9s %9s %10s\n", "run", "td", "sd(td)", "td(coe)",
        "|dp|/sd", "dV/V");
for r = 1:R
  data = relay (num, den, 0.05, "IODelay", 1, "Amp", [1 -1], "Hyst", [1 -1],
                "SNR", 15);
  M = tffsrivc (data, 2, 1);
  Mc = tffcoe (data, 2, 1);
  [p, s] = getpvec (M);
  pc = getpvec (Mc);
  T(r, :) = [M.IODelay, M.Report.Parameters.IODelaySD, Mc.IODelay, ...
             max(abs (p - pc) ./ s)];
  dv = (M.Report.Fit.LossFcn - Mc.Report.Fit.LossFcn) / M.Report.Fit.LossFcn;
  printf ("%4d %9.5f %9.2g %9.5f %9.2g %10.2g\n", r, T(r, :), dv);
endfor
printf ("td: mean %.5f, spread %.2g, mean reported sd %.2g, max |td - 1| / sd %.2g\n",
        mean (T(:, 1)), std (T(:, 1)), mean (T(:, 2)),
        max (abs (T(:, 1) - 1) ./ T(:, 2)));
