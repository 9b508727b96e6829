## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## residtrace speed, side by side in one run: the residtrace of this tree
## against the one of a reference tree given by the caller, on a plain LTI
## system (SRIVC [1 2 0] of a second-order system, PRBS input, 5 % noise)
## of 20 000 and 100 000 samples, the last third validating. Run from the
## repository root:
##   octave-cli -q bench/residtrace_bench.m COMMIT
## The reference commit is exported with git archive into a temporary
## folder and given this tree's compiled gateways (which works only while
## the gateways' calling conventions are those of the reference), or the
## reference is given as the octave/ folder of a tree with its own
## compiled gateways:
##   octave-cli -q bench/residtrace_bench.m /tmp/ref/octave
## For a reference whose gateways differ: git archive COMMIT octave into
## /tmp/ref, copy this tree's gateways there, then compile that commit's
## own gateways (its mex/ and core/, mkoctfile --mex -o
## /tmp/ref/octave/private/NAME.mex) over them, and pass /tmp/ref/octave.
args = argv ();
if (isempty (args))
  error ("residtrace_bench: give a reference commit or octave/ folder");
endif
ref = args{1};
root = pwd ();
tmp = tempname ();
mkdir (tmp);
if (exist (ref, "dir"))
  ## a tree with its own compiled gateways (its octave/ folder)
  trees = {fullfile(root, "octave"), ref};
else
  system (sprintf ("git archive %s octave | tar -x -C %s", ref, tmp));
  system (sprintf ("cp %s/octave/private/*.mex %s/octave/private/", root,
                   tmp));
  trees = {fullfile(root, "octave"), fullfile(tmp, "octave")};
endif
names = {"this tree", ["reference " ref]};
Ns = [20000 100000];
T = NaN (2, numel (Ns));
E = cell (2, numel (Ns));
## each run in its own octave-cli process (two trees' classes and private
## functions must not meet in one session)
job = [tempname() ".m"];
for j = 1:numel (Ns)
  for i = 1:2
    fid = fopen (job, "w");
    fprintf (fid, "addpath ('%s');\n", trees{i});
    fprintf (fid, "randn ('state', 1); rand ('state', 1);\n");
    fprintf (fid, "N = %d; Ts = 0.01;\n", Ns(j));
    fprintf (fid, "u = prbs (17, 20, [-1 1], N);\n");
    fprintf (fid, ["y = simc (idctm (4, [1 1.2 4]), u, Ts) ", ...
                   "+ 0.05 * randn (N, 1);\n"]);
    fprintf (fid, "d = iddata (y, u, Ts);\n");
    fprintf (fid, "M = srivc (d, [1 2 0]);\n");
    fprintf (fid, "tic; R = residtrace (d, M); t = toc;\n");
    fprintf (fid, "printf ('RESULT %%.3f %%s\\n', t, R.effect);\n");
    fclose (fid);
    [~, out] = system (sprintf ("octave-cli -q %s 2>/dev/null", job));
    tok = regexp (out, 'RESULT (\S+) (\S+)', "tokens", "once");
    if (! isempty (tok))
      T(i, j) = str2double (tok{1});
      E{i, j} = tok{2};
    endif
    printf ("%-22s N = %6d: %6.1f s, effect %s\n", names{i}, Ns(j), T(i, j),
            E{i, j});
    fflush (stdout);
  endfor
endfor
delete (job);
printf ("\n| N | this tree (s) | %s (s) | speed-up |\n|---|---|---|---|\n",
        names{2});
for j = 1:numel (Ns)
  printf ("| %d | %.1f | %.1f | %.2f |\n", Ns(j), T(1, j), T(2, j),
          T(2, j) / T(1, j));
endfor
confirm_recursive_rmdir (false);
rmdir (tmp, "s");
