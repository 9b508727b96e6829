## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## CONTSID's TFRIVC demo: the hybrid Box-Jenkins plant 4/(s^2 + 2.8 s + 4)
## with a delay of 8 s and the noise (1 + 0.2679 q^-1)/(1 - 1.98 q^-1 +
## 0.9802 q^-2) e at 15 dB, PRBS(8, 5), Ts = 0.1 s; tfrivc (data, 2, 0,
## 'NN', [2 1]) estimates the delay jointly with the plant and the noise
## model. Prints per run the delay, its reported sd, the plant and c1, and
## at the end the spread of td against the mean reported sd. Run from the
## repository root: devel/run-study tfrivc_delay_mc
## (R = 5 runs, about a minute each on a loaded machine; set R first).
if (! exist ("R", "var"))
  R = 5;
endif
MP0 = idtf (4, [1 2.8 4], "IODelay", 8);
u = prbs (8, 5);
Ts = 0.1;
ydet = simc (MP0, iddata ([], u, Ts, "InterSample", "zoh"));
C = [1 0.2679];
D = [1 -1.98 0.9802];
randn ("state", 21);
P = zeros (R, 7);
printf ("%4s %9s %9s %8s %8s %8s %8s %8s\n", "run", "td", "sd(td)", "b0",
        "f1", "f2", "c1", "d1");
for r = 1:R
  e = filter (C, D, randn (numel (u), 1));
  e *= 10 ^ (-15 / 20) * std (ydet) / std (e);
  data = iddata (ydet + e, u, Ts, "InterSample", "zoh");
  [MP, MN] = tfrivc (data, 2, 0, "NN", [2 1]);
  P(r, :) = [MP.IODelay, MP.Report.Parameters.IODelaySD, MP.num{1}(end), ...
             MP.den{1}(2:3), MN.B(2), MN.F(2)];
  printf ("%4d %9.5f %9.2g %8.4f %8.4f %8.4f %8.4f %8.4f\n", r, P(r, :));
endfor
printf ("td: mean %.5f, spread %.2g, mean reported sd %.2g\n",
        mean (P(:, 1)), std (P(:, 1)), mean (P(:, 2)));
