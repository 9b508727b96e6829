## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn {} {[@var{mean_rivc}, @var{sd_rivc}, @var{mean_srivc}, @var{sd_srivc}] =} lpv_mc (@var{R})
## Monte Carlo of @code{lpvrivc} ([2 2 0 2]) and @code{lpvsrivc} ([2 2]) on
## CONTSID's LPV example: Ts = 0.005 s, 15 s, uniform input in [-1, 1],
## scheduling p = sin (2 pi t / 3), noise e / (1 - q^-1 + 0.2 q^-2) scaled
## to 20 dB; @var{R} records (default 150).  Prints the true parameters,
## the mean and standard deviation of each estimator and the largest
## |mean - true| in standard errors (sd / sqrt (R)).  Run from the
## repository root:
## @example
## devel/run-study lpv_mc 150
## @end example
## @end deftypefn

function [mr, sr, ms, ss] = lpv_mc (R = 150)
  Ts = 0.005; t = 0:Ts:15; N = numel (t);
  p = sin (2*pi/3*t);
  A = [1 0 0; 2 -1.5 2; 5 3 0]; B = [3 2; 5 -3];
  DepA = zeros (3, 2, N); DepB = zeros (2, 2, N);
  DepA(:,1,:) = [ones(size(p)); p; p.^2];
  DepA(:,2,:) = [ones(size(p)); p; zeros(size(p))];
  DepB(:,1,:) = [ones(size(p)); cos(p)];
  DepB(:,2,:) = [ones(size(p)); sin(2*p)];
  truth = [2 -1.5 2 5 3 3 2 5 -3]';
  TR = zeros (9, R); TS = TR;
  for r = 1:R
    rand ("seed", 100 + r); randn ("seed", 200 + r);
    u = rand (N, 1) * 2 - 1;
    ydet = simulLPVCT (u, A, DepA, B, DepB, Ts);
    v = filter (1, [1 -1 0.2], randn (N, 1));
    y = ydet + v / std (v) * 0.1 * std (ydet);
    data = iddata (y, u, Ts);
    TR(:, r) = lpvrivc (data, [2 2 0 2], DepA, DepB);
    TS(:, r) = lpvsrivc (data, [2 2], DepA, DepB);
  endfor
  mr = mean (TR, 2); sr = std (TR, 0, 2);
  ms = mean (TS, 2); ss = std (TS, 0, 2);
  row = @(name, x) printf ("%-10s%s\n", name, sprintf ("%8.3f", x));
  row ("true", truth);
  row ("rivc mean", mr); row ("rivc sd", sr);
  row ("srivc mean", ms); row ("srivc sd", ss);
  printf ("largest |mean - true| / (sd/sqrt(R)): rivc %.2f, srivc %.2f\n",
          max (abs (mr - truth) ./ (sr / sqrt (R))),
          max (abs (ms - truth) ./ (ss / sqrt (R))));
endfunction
