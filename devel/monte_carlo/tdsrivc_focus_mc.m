## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## CONTSID's time-delay SRIVC demo (12/(s+2)^2, delay 8 s, PRBS(8, 20),
## Ts = 0.1 s, 15 dB): tfsrivc from the coarse start delay td0 = 1 with
## the Focus filter fc = 0.1 rad/s, against the estimate started at the
## true delay (the global minimum). Run from the repository root:
## devel/run-study tdsrivc_focus_mc
## (R = 5 runs, about 30 s each on a loaded machine; set R first for more).
if (! exist ("R", "var"))
  R = 5;
endif
M0 = idtf (12, [1 4 4], "IODelay", 8);
u = prbs (8, 20);
Ts = 0.1;
ydet = simc (M0, iddata ([], u, Ts, "InterSample", "zoh"));
randn ("state", 11);
printf ("%4s %9s %9s %9s %9s | %9s %9s %9s\n", "run", "td", "b0", "f1",
        "f2", "td(true0)", "|dp|/sd", "td(nofoc)");
for r = 1:R
  e = randn (size (ydet));
  e *= 10 ^ (-15 / 20) * std (ydet) / std (e);
  data = iddata (ydet + e, u, Ts, "InterSample", "zoh");
  M2 = tfsrivc (data, 2, 0, 1, "Lambda", 2, "Focus", 0.1);
  Mt = tfsrivc (data, 2, 0, 8, "Lambda", 2);
  M1 = tfsrivc (data, 2, 0, 1, "Lambda", 2);
  [p2, s2] = getpvec (M2);
  pt = getpvec (Mt);
  printf ("%4d %9.4f %9.4f %9.4f %9.4f | %9.4f %9.2g %9.4f\n", r,
          M2.IODelay, p2(1), p2(2), p2(3), Mt.IODelay,
          max (abs (p2 - pt) ./ s2), M1.IODelay);
endfor
