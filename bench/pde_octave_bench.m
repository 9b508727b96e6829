## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn {} {@var{T} =} pde_octave_bench ()
## Side-by-side timing of the heat-equation SRIVC iteration: the core
## (core/include/ctid/offline/pde_heat.hpp through the gateway pde_mex, as
## pdesrivc4heatdiffusion calls it) against @file{pde_plain_octave.m}, the
## same iteration in vectorised plain Octave, both run for K = 5
## iterations from their LSSVF start, on fields shaped like CONTSID's heat
## demo (a = 8.418e-5, b = 1, a 1 m bar, source pulses in the middle,
## white noise at 10 dB): 1801 instants by 51 nodes and 3601 by 101 (the
## demo's grid).  Median of 3 runs; the last column is the largest
## relative difference between the two estimates (the plain code is an
## independent check of the core).  Run from the repository root:
## @example
## octave-cli -q --eval "addpath octave bench; pde_octave_bench"
## @end example
## @end deftypefn

function T = pde_octave_bench ()
  here = fileparts (fileparts (mfilename ("fullpath")));
  tmp = tempname ();
  mkdir (tmp);
  copyfile (fullfile (here, "octave", "private", "pde_mex.mex"), tmp);
  addpath (tmp);
  cleanup = onCleanup (@() rmpath (tmp));
  K = 5;
  grids = {0:1:1800, 0:0.02:1; 0:0.5:1800, 0:0.01:1};
  T = zeros (rows (grids), 5);
  printf ("%6s %5s %12s %12s %8s %14s\n", "Nt", "Nx", "core [ms]",
          "plain [ms]", "ratio", "max rel diff");
  for r = 1:rows (grids)
    [t, x] = grids{r, :};
    D2 = struct ("t", t, "x", x);
    D1.Input = zeros (numel (t), numel (x));
    mid = (numel (x) + 1) / 2;
    D1.Input(:, mid) = 0.01 * (mod (t(:), 600) < 300 & t(:) < 1500);
    ic = zeros (size (x));
    ydet = sim_heat ([8.418e-5 1], D1, D2, ic);
    randn ("seed", 2);
    y = ydet + std (ydet(:)) / sqrt (10) * randn (size (ydet));
    opts = struct ("t", t, "x", x, "ic", ic, "tol", 1e-300, "maxiter", K);
    core = @() pde_mex ("pdesrivc4heatdiffusion", y, D1.Input, opts);
    plain = @() pde_plain_octave (t, x, y, D1.Input, ic, K);
    tc = zeros (1, 3);  tp = zeros (1, 3);
    for rep = 1:3
      t0 = tic;  thc = core ();  tc(rep) = toc (t0);
      t0 = tic;  thp = plain ();  tp(rep) = toc (t0);
    endfor
    d = max (abs (thc(:) - thp(:)) ./ abs (thp(:)));
    T(r, :) = [numel(t), numel(x), 1e3 * median(tc), 1e3 * median(tp), d];
    printf ("%6d %5d %12.1f %12.1f %8.1f %14.2e\n", T(r, 1:4),
            T(r, 4) / T(r, 3), d);
  endfor
endfunction
