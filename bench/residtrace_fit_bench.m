## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## residtrace's structure fit (residtrace_fit, every candidate's fit) timed
## through whole residtrace runs, side by side in one run: this tree
## against a reference tree's octave/ folder with its own compiled
## gateways. Records: the undeclared-effect suite, set 2 (ten records, one
## per effect), and the eight simulated rigs of residtrace_sim_records
## (devel/validation: five nonlinear, three linear).
## Prints, per record set and tree, the time, the effects named and the
## validation RMSEs, and the largest relative difference of the RMSEs.
## Each tree runs twice, alternately, and the shorter time is kept (the
## machine may be shared).
## Run from the repository root:
##   octave-cli -q bench/residtrace_fit_bench.m /tmp/ref/octave
args = argv ();
if (isempty (args))
  error ("residtrace_fit_bench: give a reference octave/ folder");
endif
root = pwd ();
trees = {fullfile(root, "octave"), args{1}};
names = {"this tree", "reference"};
paths = {fullfile(root, "demos"), fullfile(root, "devel", "validation"), ...
         fullfile(root, "tests", "octave")};
setup = {
  ["C = residtrace_cases (2); r = []; e = {}; t0 = tic ();\n", ...
   "for k = 1:numel (C)\n", ...
   "  R = residtrace (C(k).data, C(k).M, 'validation', C(k).datav, ", ...
   "'iterate', 1);\n", ...
   "  r(end+1) = R.rmse_after; e{end+1} = R.effect;\n", ...
   "endfor\n", ...
   "t = toc (t0);\n"],
  ["r = []; e = {}; t0 = tic ();\n", ...
   "T = residtrace_sim_records (tempname ());\n", ...
   "t = toc (t0); r = [T.rmse_after]; e = {T.found};\n"]};
cases = {"effect suite, set 2", "eight simulated rigs"};
job = [tempname() ".m"];
rm = cell (numel (cases), 2);
T = Inf (numel (cases), 2);
for c = 1:numel (cases)
  for run = 1:4
    i = 2 - mod (run, 2);
    fid = fopen (job, "w");
    fprintf (fid, "addpath ('%s');\n", trees{i}, paths{:});
    fprintf (fid, "pkg load control;\n");
    fprintf (fid, "%s", setup{c});
    fprintf (fid, ["printf ('RESULT %%.4f [%%s] {%%s}\\n', t, ", ...
                   "sprintf ('%%.12g ', r), strjoin (e, ', '));\n"]);
    fclose (fid);
    [~, out] = system (sprintf ("octave-cli --no-history -q %s 2>/dev/null",
                                job));
    tok = regexp (out, 'RESULT (\S+) \[([^\]]*)\] \{(.*)\}', "tokens", "once");
    if (isempty (tok))
      printf ("%-24s %-10s: failed\n%s\n", cases{c}, names{i}, out);
      continue;
    endif
    t = str2double (tok{1});
    T(c, i) = min (T(c, i), t);
    rm{c, i} = str2num (tok{2});
    printf ("%-24s %-10s %6.1f s  RMSE %s {%s}\n", cases{c}, names{i}, t,
            strtrim (tok{2}), tok{3});
    fflush (stdout);
  endfor
endfor
delete (job);
printf ("\n| records | this tree (s) | reference (s) | speed-up | max rel. RMSE difference |\n");
printf ("|---|---|---|---|---|\n");
for c = 1:numel (cases)
  a = rm{c, 1}; b = rm{c, 2};
  d = NaN;
  if (numel (a) == numel (b) && ! isempty (a))
    d = max (abs (a - b) ./ abs (b));
  endif
  printf ("| %s | %.1f | %.1f | %.2f | %.2g |\n", cases{c}, T(c, 1), T(c, 2),
          T(c, 2) / T(c, 1), d);
endfor
