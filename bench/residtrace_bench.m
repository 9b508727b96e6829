## residtrace speed, side by side in one run (issue 9): the residtrace of
## this tree against the one of a reference commit (default e5c0877, before
## issue 9), on a plain LTI system (SRIVC [1 2 0] of a second-order
## system, PRBS input, 5 % noise) of 20 000 and 100 000 samples, the last
## third validating. Run from the repository root:
##   octave-cli -q bench/residtrace_bench.m [commit]
## The reference tree is exported with git archive into a temporary folder
## and given this tree's compiled gateways.
args = argv ();
ref = "e5c0877";
if (! isempty (args))
  ref = args{1};
endif
root = pwd ();
tmp = tempname ();
mkdir (tmp);
system (sprintf ("git archive %s octave | tar -x -C %s", ref, tmp));
system (sprintf ("cp %s/octave/private/*.mex %s/octave/private/", root, tmp));
trees = {fullfile(root, "octave"), fullfile(tmp, "octave")};
names = {"this tree", ["reference " ref]};
Ns = [20000 100000];
T = NaN (2, numel (Ns));
E = cell (2, numel (Ns));
for j = 1:numel (Ns)
  for i = 1:2
    addpath (trees{i});
    randn ("state", 1); rand ("state", 1);
    N = Ns(j); Ts = 0.01;
    u = prbs (17, 20, [-1 1], N);
    y = simc (idctm (4, [1 1.2 4]), u, Ts) + 0.05 * randn (N, 1);
    d = iddata (y, u, Ts);
    M = srivc (d, [1 2 0]);
    tic;
    R = residtrace (d, M);
    T(i, j) = toc;
    E{i, j} = R.effect;
    printf ("%-22s N = %6d: %6.1f s, effect %s\n", names{i}, N, T(i, j),
            R.effect);
    fflush (stdout);
    rmpath (trees{i});
  endfor
endfor
printf ("\n| N | this tree (s) | %s (s) | speed-up |\n|---|---|---|---|\n",
        names{2});
for j = 1:numel (Ns)
  printf ("| %d | %.1f | %.1f | %.2f |\n", Ns(j), T(1, j), T(2, j),
          T(2, j) / T(1, j));
endfor
confirm_recursive_rmdir (false);
rmdir (tmp, "s");
