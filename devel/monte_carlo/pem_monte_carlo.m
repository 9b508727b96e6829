## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## Monte Carlo check of the covariance reported by tfcoe (continuous-time
## output error, SRIVC start + Levenberg-Marquardt) and oe (discrete
## time): the spread of the estimates over R noise realisations against
## the mean of the reported standard deviations (the target: ratio
## 0.8-1.25 per parameter).
##
## Usage, from the repository root:
##   devel/run-study pem_monte_carlo      (R = 200 noise realisations)
1;
root = fileparts (fileparts (fileparts (mfilename ("fullpath"))));
addpath (fullfile (root, "octave"));
args = argv ();
R = 200;
if (! isempty (args) && ! isempty (str2double (args{end}))
    && isfinite (str2double (args{end})))
  R = str2double (args{end});
endif
rand ("state", 7); randn ("state", 7);
N = 1000; Ts = 0.05;
u = kron (sign (randn (N / 8, 1)), ones (8, 1));
x = simc (idctm ([1.5 4], [1 2.4 4]), u, Ts);
thc = zeros (R, 4); sdc = thc;
xd = filter ([0 0.5 0.3], [1 -1.5 0.7], u);
thd = zeros (R, 4); sdd = thd;
t0 = tic ();
for r = 1:R
  y = x + 0.3 * randn (N, 1);
  M = tfcoe (iddata (y, u, Ts), 2, 1);
  [p, sd] = getpvec (M);                # [b1 b0 f1 f2 IODelay]
  thc(r, :) = p(1:4); sdc(r, :) = sd(1:4);
  yd = xd + 0.3 * randn (N, 1);
  Md = oe (iddata (yd, u, 1), [2 2 1]);
  [p, sd] = getpvec (Md);               # [0 b1 b2 f1 f2]: B's nk zero
  thd(r, :) = p(2:end); sdd(r, :) = sd(2:end);
endfor
printf ("R = %d runs, N = %d, %.1f s\n", R, N, toc (t0));
names = {"b1", "b0", "f1", "f2"};
printf ("tfcoe, 1.5 p + 4 / (p^2 + 2.4 p + 4), ZOH, noise sd 0.3\n");
printf ("  %-4s %10s %10s %10s %8s\n", "par", "mean", "MC sd", "rep. sd",
        "ratio");
truec = [1.5 4 2.4 4];
for i = 1:4
  printf ("  %-4s %10.4f %10.4f %10.4f %8.3f   (true %g)\n", names{i},
          mean (thc(:, i)), std (thc(:, i)), mean (sdc(:, i)),
          std (thc(:, i)) / mean (sdc(:, i)), truec(i));
endfor
printf ("oe [2 2 1], (0.5 q^-1 + 0.3 q^-2) / (1 - 1.5 q^-1 + 0.7 q^-2)\n");
namesd = {"b1", "b2", "f1", "f2"};
trued = [0.5 0.3 -1.5 0.7];
for i = 1:4
  printf ("  %-4s %10.4f %10.4f %10.4f %8.3f   (true %g)\n", namesd{i},
          mean (thd(:, i)), std (thd(:, i)), mean (sdd(:, i)),
          std (thd(:, i)) / mean (sdd(:, i)), trued(i));
endfor
