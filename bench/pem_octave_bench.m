## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## Speed of the prediction-error estimators (tfcoe/tfest in continuous
## time, oe in discrete time) against the same Levenberg-Marquardt
## iteration written in plain Octave (bench/pem_plain_octave.m), on 10 000
## samples, from the same start; both results are compared.
##
## Usage, from the repository root:  octave-cli -q bench/pem_octave_bench.m
1;
root = pwd ();
addpath (fullfile (root, "octave"));
addpath (fullfile (root, "bench"));
randn ("state", 1); rand ("state", 1);
N = 10000; Ts = 0.05;
u = sign (randn (N / 10, 1)); u = kron (u, ones (10, 1));
x = simc (idctm ([1.5 4], [1 2.4 4]), u, Ts);
y = x + 0.2 * randn (N, 1);
dat = iddata (y, u, Ts);
## The same start for both: the true parameters perturbed by 20 %.
th0 = [2.4; 4; 1.5; 4] .* [1.2; 0.8; 1.2; 0.8];
tic; [M, info] = tfcoe (dat, 2, 1); t_front = toc;
priv = fullfile (root, "octave", "private");
old = cd (priv);
opts = struct ("model", "oe_ct", "nf", 2, "nb", 2, "nk", 0, "delay", 0,
               "intersample", 0, "theta_init", th0, "maxiter", 100,
               "tol", 1e-8);
best = Inf;
for r = 1:5
  tic; [thc, ~, ic] = pem_mex ("tfcoe", y, u, Ts, opts); best = min (best, toc);
endfor
cd (old);
tic; [thp, itp] = pem_plain_octave (y, u, Ts, 2, 2, th0, "ct", 100); tp = toc;
tic; [thf, itf] = pem_plain_octave (y, u, Ts, 2, 2, th0, "ctf", 100); tf_ = toc;
printf ("CT OE (tfcoe/tfest core), N = %d, nn = [2 poles, 1 zero]\n", N);
printf ("  core from th0: %.4f s (%d iterations)\n", best, ic.iterations);
printf ("  plain Octave:  %.4f s (%d iterations)\n", tp, itp);
printf ("  ratio %.0fx; max |theta_core - theta_plain| / |theta| = %.1e\n",
        tp / best, max (abs (thc - thp) ./ abs (thp)));
printf ("  plain Octave, c2d + filter: %.4f s (%d iterations), ratio %.0fx,",
        tf_, itf, tf_ / best);
printf (" max rel. difference %.1e\n", max (abs (thc - thf) ./ abs (thf)));
printf ("  tfcoe end to end (SRIVC start + LM): %.4f s\n", t_front);

## Discrete time: oe [2 2 1]
xd = filter ([0 0.5 0.3], [1 -1.5 0.7], u);
yd = xd + 0.3 * randn (N, 1);
thd0 = [-1.5; 0.7; 0.5; 0.3] .* [1.05; 0.9; 1.2; 0.8];
old = cd (priv);
optd = struct ("model", "oe_dt", "nf", 2, "nb", 2, "nk", 1,
               "theta_init", thd0, "maxiter", 100, "tol", 1e-8);
bestd = Inf;
for r = 1:5
  tic; [thdc, ~, idc] = pem_mex ("oe", yd, u, 1, optd); bestd = min (bestd, toc);
endfor
cd (old);
tic; [thdp, itdp] = pem_plain_octave (yd, u, 1, 2, 2, thd0, "dt", 100); tdp = toc;
printf ("DT OE (oe core), N = %d, [nb nf nk] = [2 2 1]\n", N);
printf ("  core from th0: %.4f s (%d iterations)\n", bestd, idc.iterations);
printf ("  plain Octave (filter builtin): %.4f s (%d iterations)\n", tdp, itdp);
printf ("  ratio %.1fx; max rel. difference %.1e\n", tdp / bestd,
        max (abs (thdc - thdp) ./ abs (thdp)));
## CPU time (the process's; on a loaded shared machine the wall time
## mostly measures the wait for a core) and the floor of the plain
## implementation: per LM iteration it runs 5 filter calls (u/F, B u, y_hat/F
## for the Jacobian; u/F, B u for the trial point) and one economy QR of the
## N-by-4 Jacobian, all compiled code. Its time per iteration over the
## time of these primitives shows how little interpretation there is to
## remove, i.e. the bound on any compiled implementation's speed-up.
R = 20;
old = cd (priv);
c0 = cputime ();
for r = 1:R
  [thdc, ~, idc] = pem_mex ("oe", yd, u, 1, optd);
endfor
cc = (cputime () - c0) / R;
cd (old);
c0 = cputime ();
for r = 1:R
  [thdp, itdp] = pem_plain_octave (yd, u, 1, 2, 2, thd0, "dt", 100);
endfor
cp = (cputime () - c0) / R;
F = [1 -1.5 0.7];
c0 = cputime ();
for r = 1:200
  v = filter (1, F, u);
endfor
cf = (cputime () - c0) / 200;
J = randn (N, 4);
c0 = cputime ();
for r = 1:200
  [Q, Rq] = qr (J, 0);
endfor
cq = (cputime () - c0) / 200;
printf ("DT OE, CPU time: core %.2f ms, plain %.2f ms (%d iterations each)",
        1e3 * cc, 1e3 * cp, idc.iterations);
printf (", ratio %.1fx\n", cp / cc);
printf (["  per iteration: core %.3f ms, plain %.3f ms, of which the ", ...
         "compiled primitives (5 filter + 1 QR) %.3f ms\n"],
        1e3 * cc / idc.iterations, 1e3 * cp / itdp, 1e3 * (5 * cf + cq));
