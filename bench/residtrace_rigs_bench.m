## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## residtrace's time on the grey-box rigs of demo_greybox at a given length
## (target: never above 10 s on records of 20 000 samples): the
## two-tank cascade with overflow (iterate 3, as the demo) and the axis
## with end stops (iterate 2), seed 7, an estimation and a validation
## record of N samples each, the start srivc [1 2 0] on the estimation
## record with its means removed. Prints wall and CPU time, the effects
## named and the validation RMSE before/after. Run from the repository
## root, alone on a quiet machine (the wall time is the load's otherwise):
##   octave-cli -q bench/residtrace_rigs_bench.m [N]
args = argv ();
N = 20000;
if (! isempty (args))
  N = str2double (args{1});
endif
addpath (fullfile (pwd (), "octave"));
addpath (fullfile (pwd (), "demos"));
rigs = {"tanks", 2, struct("k", 0.1, "c1", 0.09, "c2", 0.075, "h1max", 40), 3;
        "axis", 0.02, struct("wn", 6, "zeta", 0.6, "K", 10, "ymin", 8,
                             "ymax", 92), 2};
for i = 1:rows (rigs)
  [rig, Ts, p, iterate] = rigs{i, :};
  randn ("state", 7); rand ("state", 7);
  [u, y] = greybox_record (rig, N, Ts, p);
  [uv, yv] = greybox_record (rig, N, Ts, p);
  d = iddata (y, u, Ts, "InterSample", "zoh");
  dv = iddata (yv, uv, Ts, "InterSample", "zoh");
  M = srivc (iddata (y - mean (y), u - mean (u), Ts, "InterSample", "zoh"),
             [1 2 0]);
  c0 = cputime ();
  tic;
  R = residtrace (d, M, "validation", dv, "iterate", iterate);
  printf ("%-5s N = %d: wall %.2f s, CPU %.2f s; %s; RMSE %.4g -> %.4g\n",
          rig, N, toc, cputime () - c0, strjoin (R.effects, ", "),
          R.rmse_before, R.rmse_final);
endfor
