## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## residtrace on records with physical candidates (an end stop, two tanks
## with an overflowing upper tank, a simulated Cascaded Tanks record),
## side by side in one run: this tree against a reference tree's octave/
## folder with its own compiled gateways. Prints, per record and tree, the
## time of the residtrace call, the effects named and the RMSEs, and the
## largest relative difference of the RMSEs. Run from the repository root:
##   octave-cli -q bench/residtrace_physfit_bench.m /tmp/ref/octave
args = argv ();
if (isempty (args))
  error ("residtrace_physfit_bench: give a reference octave/ folder");
endif
root = pwd ();
trees = {fullfile(root, "octave"), args{1}};
names = {"this tree", "reference"};
demos = fullfile (root, "demos");
valid = fullfile (root, "devel", "validation");
setup = {
  ["randn ('state', 424242); rand ('state', 424242);\n", ...
   "p = struct ('wn', 7, 'zeta', 0.5, 'K', 12, 'ymin', 20, 'ymax', 100);\n", ...
   "Ts = 0.02; N = 2500;\n", ...
   "f = @() filter (0.1, [1 -0.9], residtrace_levels (N, Ts, 0.6, 3, 0, 10));\n", ...
   "u = f (); uv = f ();\n", ...
   "y = axis_sim (u, Ts, p) + 0.1 * randn (N, 1);\n", ...
   "yv = axis_sim (uv, Ts, p) + 0.1 * randn (N, 1);\n", ...
   "tic; R = residtrace_record (y, u, yv, uv, Ts, [1 2 0], 'iterate', 1); t = toc;\n"],
  ["randn ('state', 515151); rand ('state', 515151);\n", ...
   "q = struct ('k', 0.12, 'c1', 0.1, 'c2', 0.085, 'h1max', 40);\n", ...
   "Ts = 2; N = 2000;\n", ...
   "u = residtrace_levels (N, Ts, 50, 250, 2, 7);\n", ...
   "uv = residtrace_levels (N, Ts, 50, 250, 2, 7);\n", ...
   "y = tanks_sim (u, Ts, q) + 0.25 * randn (N, 1);\n", ...
   "yv = tanks_sim (uv, Ts, q) + 0.25 * randn (N, 1);\n", ...
   "tic; R = residtrace_record (y, u, yv, uv, Ts, [1 2 0], 'iterate', 1); t = toc;\n"],
  ["[de, dv] = cascaded_tanks_sim ('records', 1);\n", ...
   "M = srivc (de, [1 2 0]);\n", ...
   "tic; R = residtrace (de, M, 'validation', dv); t = toc;\n"]};
cases = {"end stop (axis)", "two tanks", "Cascaded Tanks draw 1"};
job = [tempname() ".m"];
rm = NaN (numel (cases), 2, 4);
T = NaN (numel (cases), 2);
for c = 1:numel (cases)
  for i = 1:2
    fid = fopen (job, "w");
    fprintf (fid, "addpath ('%s'); addpath ('%s'); addpath ('%s');\n",
             trees{i}, demos, valid);
    fprintf (fid, "pkg load control;\n");
    fprintf (fid, "%s", setup{c});
    fprintf (fid, ["printf ('RESULT %%.4f %%.12g %%.12g %%.12g %%.12g ", ...
                   "%%s {%%s}\\n', t, R.rmse_given, R.rmse_before, ", ...
                   "R.rmse_after, R.rmse_final, R.effect, ", ...
                   "strjoin (effect_names (R.effects), ', '));\n"]);
    fclose (fid);
    [~, out] = system (sprintf ("octave-cli --no-history -q %s 2>/dev/null",
                                job));
    tok = regexp (out, 'RESULT (\S+) (\S+) (\S+) (\S+) (\S+) (.*)', "tokens",
                  "once");
    if (isempty (tok))
      printf ("%-22s %-10s: failed\n%s\n", cases{c}, names{i}, out);
      continue;
    endif
    T(c, i) = str2double (tok{1});
    rm(c, i, :) = str2double (tok(2:5));
    printf ("%-22s %-10s %6.1f s  RMSE given/before/after/final %s %s %s %s  %s\n",
            cases{c}, names{i}, T(c, i), tok{2:5}, strtrim (tok{6}));
    fflush (stdout);
  endfor
endfor
delete (job);
printf ("\n| record | this tree (s) | reference (s) | speed-up | max rel. RMSE difference |\n");
printf ("|---|---|---|---|---|\n");
for c = 1:numel (cases)
  a = squeeze (rm(c, 1, :)); b = squeeze (rm(c, 2, :));
  d = max (abs (a - b) ./ abs (b));
  printf ("| %s | %.1f | %.1f | %.2f | %.2g |\n", cases{c}, T(c, 1), T(c, 2),
          T(c, 2) / T(c, 1), d);
endfor
