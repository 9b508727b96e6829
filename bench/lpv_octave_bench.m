## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn {} {@var{T} =} lpv_octave_bench ()
## Side-by-side timing of the LPV-SRIVC iteration: the core
## (core/include/ctid/offline/lpv_refined_iv.hpp through the gateway
## lpv_mex, as lpvsrivc calls it) against @file{lpv_plain_octave.m}, the
## same iteration in vectorised plain Octave, both run for K = 10
## iterations from the same start (the true model perturbed by 10 %), on
## CONTSID's LPV example (na = 2, nb = 2, 9 parameters, white noise at
## 20 dB) for N = 3001 and 30001 samples.  Median of 3 runs; the last
## column is the largest difference between the two estimates (the plain
## code is an independent check of the core).  Run from the repository
## root:
## @example
## octave-cli -q --eval "addpath octave bench; lpv_octave_bench"
## @end example
## @end deftypefn

function T = lpv_octave_bench ()
  here = fileparts (fileparts (mfilename ("fullpath")));
  tmp = tempname ();
  mkdir (tmp);
  copyfile (fullfile (here, "octave", "private", "lpv_mex.mex"), tmp);
  addpath (tmp);
  cleanup = onCleanup (@() rmpath (tmp));
  K = 10;
  Ntab = [3001 30001];
  T = zeros (numel (Ntab), 4);
  printf ("%8s %12s %12s %8s %14s\n", "N", "core [ms]", "plain [ms]",
          "ratio", "max|core-plain|");
  for r = 1:numel (Ntab)
    N = Ntab(r);
    Ts = 0.005; t = (0:N-1) * Ts; p = sin (2*pi/3*t);
    rand ("seed", 1); u = rand (N, 1) * 2 - 1;
    DepA = zeros (3, 2, N); DepB = zeros (2, 2, N);
    DepA(:,1,:) = [ones(size(p)); p; p.^2];
    DepA(:,2,:) = [ones(size(p)); p; zeros(size(p))];
    DepB(:,1,:) = [ones(size(p)); cos(p)];
    DepB(:,2,:) = [ones(size(p)); sin(2*p)];
    A = [1 0 0; 2 -1.5 2; 5 3 0]; B = [3 2; 5 -3];
    ydet = simulLPVCT (u, A, DepA, B, DepB, Ts);
    randn ("seed", 2); y = ydet + 0.1 * std (ydet) * randn (N, 1);
    A0 = A .* [1 1 1; 1.1 0.9 1.1; 0.9 1.1 1]; B0 = B * 1.1;
    fa = reshape (DepA, 3, []); fb = reshape (DepB, 2, []);
    opts = struct ("Ts", Ts, "dims_a", [3 2 N], "dims_b", [2 2 N],
                   "tol", 1e-300, "maxiter", K, "Ainit", A0, "Binit", B0);
    core = @() lpv_mex ("lpvsrivc", y, u, fa, fb, opts);
    plain = @() lpv_plain_octave (y, u, Ts, DepA, DepB, K, A0, B0);
    tc = zeros (1, 3); tp = zeros (1, 3);
    for rep = 1:3
      t0 = tic; [~, Ac, Bc] = core (); tc(rep) = toc (t0);
      t0 = tic; [Ap, Bp] = plain (); tp(rep) = toc (t0);
    endfor
    d = max ([abs(Ac(:) - Ap(:)); abs(Bc(:) - Bp(:))]);
    T(r, :) = [N, 1e3 * median(tc), 1e3 * median(tp), d];
    printf ("%8d %12.2f %12.2f %8.1f %14.2e\n", N, T(r, 2), T(r, 3),
            T(r, 3) / T(r, 2), d);
  endfor
endfunction
