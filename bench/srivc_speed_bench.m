## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## srivc speed, side by side in one run: srivc with its automatic start
## on 100 000 samples in this tree against a reference tree given by the
## caller. Run from the repository root:
##   octave-cli -q bench/srivc_speed_bench.m REF_OCTAVE_DIR [ROUNDS]
## REF_OCTAVE_DIR is the octave/ folder of the reference tree WITH its own
## gateways built (its calling conventions may differ from this tree's),
## e.g.
##   git worktree add --detach /tmp/ref COMMIT
##   cd /tmp/ref && cmake -S . -B build -DCMAKE_BUILD_TYPE=Release
##   cmake --build build --target octave_mex -j1
##   octave-cli -q bench/srivc_speed_bench.m /tmp/ref/octave
## The records (100 000 samples, Ts = 0.01, ZOH PRBS input, 10 % output
## noise): a second-order system, structure [1 2 0], and a third-order one,
## [2 3 0]. Each tree runs in its own octave-cli process (two trees'
## functions and classes must not meet in one session); the processes
## alternate (this tree, reference, this tree, ...) ROUNDS times (default
## 3), each timing srivc (data, nn) twice after a warm-up call and keeping
## the faster; the medians over the rounds and their ratio are printed,
## with the estimates (both trees must find the same model).
args = argv ();
if (isempty (args))
  error ("srivc_speed_bench: give the reference tree's octave/ folder");
endif
ref = args{1};
rounds = 3;
if (numel (args) > 1)
  rounds = str2double (args{2});
endif
root = pwd ();
trees = {fullfile(root, "octave"), ref};
names = {"this tree", "reference"};
addpath (trees{1});
N = 100000;
Ts = 0.01;
randn ("state", 11);
rand ("state", 11);
u = kron (sign (randn (N / 10, 1)), ones (10, 1));
cases = {[1 2 0], idctm(4, [1 2.4 4]); ...
         [2 3 0], idctm([1 3], [1 3 5 3])};
record = [tempname() ".mat"];
job = [tempname() ".m"];
[~, load_text] = system ("uptime");
printf ("machine load at start: %s", load_text);
for c = 1:rows (cases)
  [nn, M0] = cases{c, :};
  x = simc (M0, u, Ts);
  y = x + 0.1 * std (x) * randn (N, 1);
  save ("-binary", record, "y", "u", "Ts", "nn");
  T = NaN (2, rounds);
  F = cell (1, 2);
  for r = 1:rounds
    for i = 1:2
      fid = fopen (job, "w");
      fprintf (fid, "addpath ('%s');\n", trees{i});
      fprintf (fid, "warning ('off', 'all');\n");
      fprintf (fid, "load ('%s');\n", record);
      fprintf (fid, "d = iddata (y, u, Ts, 'InterSample', 'zoh');\n");
      fprintf (fid, "M = srivc (d, nn);\n");   # warm-up (loads the MEX)
      fprintf (fid, "t = Inf;\n");
      fprintf (fid, "for k = 1:2, tic; M = srivc (d, nn); t = min (t, toc); end\n");
      fprintf (fid, "printf ('RESULT %%.4f %%s\\n', t, mat2str (M.F, 8));\n");
      fclose (fid);
      [~, out] = system (sprintf ("octave-cli -q %s 2>&1", job));
      tok = regexp (out, 'RESULT (\S+) (.*?)\n', "tokens", "once");
      if (isempty (tok))
        error ("srivc_speed_bench: the run of %s failed:\n%s", names{i}, out);
      endif
      T(i, r) = str2double (tok{1});
      F{i} = tok{2};
    endfor
  endfor
  t = median (T, 2);
  printf ("srivc %s, N = %d: this tree %.3f s, reference %.3f s, ", ...
          mat2str (nn), N, t(1), t(2));
  printf ("ratio %.1f (rounds: this %s, reference %s)\n", t(2) / t(1), ...
          mat2str (T(1, :), 3), mat2str (T(2, :), 3));
  printf ("  true F      %s\n  this tree F %s\n  reference F %s\n", ...
          mat2str (M0.F, 8), F{1}, F{2});
  fflush (stdout);
endfor
[~, load_text] = system ("uptime");
printf ("machine load at end: %s", load_text);
delete (record);
delete (job);
