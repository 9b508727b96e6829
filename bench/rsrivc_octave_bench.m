## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## Throughput of RSRIVC-KF in Octave: the compiled front-end rsrivc end to
## end (options, checks, gateway, core) and the plain-Octave baseline
## bench/rsrivc_plain_octave.m (the same algorithm written as a user would
## without the toolbox), next to the compiled core benchmark measured in the
## same run, so that the ratios are not spoilt by the load of a shared
## machine. Also checks that the baseline and rsrivc give the same
## estimates.
##
## Usage, from the repository root:
##   octave-cli -q bench/rsrivc_octave_bench.m [path/to/bench_rsrivc [Nb]]
## The core benchmark defaults to build/bench/bench_rsrivc; without it only
## the Octave timings are printed. Nb is the number of samples given to the
## baseline (default: the whole record if that is projected to take at most
## about 60 s, else fewer; rates are then compared per sample). See
## bench/README.md.
##
## Timed (1e5 samples, Ts = 0.1 s, nn = [1 2 0], RSRIVC-KF, prefilter and
## auxiliary model refreshed every sample):
##   thm = rsrivc (data, [1 2 0], "lambda_svf", 3.2, "adm", "kf",
##                 "adg", 1e-4*eye (3), "tsiv", 100)        best of 5 runs
##   thm = rsrivc_plain_octave (y, u, 0.1, 3.2, 1e-4*eye (3), 100)  1 run
## The core benchmark runs before and after the Octave timings; the better
## of its two runs is used for the ratios.

1;  # a script file, not a function file

function bin = find_core_benchmark (root, args)
  if (! isempty (args) && ! isempty (args{1}))
    bin = args{1};
  else
    bin = fullfile (root, "build", "bench", "bench_rsrivc");
  endif
  if (! exist (bin, "file"))
    printf ("core benchmark not found at %s: Octave timings only\n", bin);
    bin = "";
  endif
endfunction

## items_per_second of each benchmark selected by `filter`, as a struct
## whose field names are the benchmark names.
function rates = run_core_benchmark (bin, filter)
  cmd = sprintf ("\"%s\" '--benchmark_filter=%s' --benchmark_format=json",
                 bin, filter);
  [status, out] = system (cmd);
  if (status != 0)
    error ("rsrivc_octave_bench:coreFailed",
           "rsrivc_octave_bench: %s exited with status %d", bin, status);
  endif
  report = jsondecode (out);
  runs = report.benchmarks;
  if (! iscell (runs))
    runs = num2cell (runs);
  endif
  rates = struct ();
  for i = 1:numel (runs)
    if (isfield (runs{i}, "items_per_second"))
      ## The second-order case on the fixed-size kernels, by its bare name.
      rates.(regexprep (runs{i}.name, "/na:2/dynamic:0$", "")) = ...
          runs{i}.items_per_second;
    endif
  endfor
endfunction

function print_core (rates, when)
  names = fieldnames (rates);
  for i = 1:numel (names)
    printf ("  core %-6s %-28s %8.3f M samples/s\n", when, names{i},
            rates.(names{i}) / 1e6);
  endfor
endfunction

## Best of `runs` wall-clock times of f().
function best = best_time (f, runs)
  best = Inf;
  for r = 1:runs
    t0 = tic ();
    f ();
    best = min (best, toc (t0));
  endfor
endfunction

function s = ifelse_str (c, a, b)
  if (c)
    s = a;
  else
    s = b;
  endif
endfunction

function rsrivc_thm (args)
  thm = rsrivc (args{:});
endfunction

root = fileparts (fileparts (mfilename ("fullpath")));
addpath (fullfile (root, "octave"));
addpath (fullfile (root, "bench"));
args_in = argv ();
bin = find_core_benchmark (root, args_in);
core_filter = ["^BM_(RsrivcUpdate_KF|RivsvfUpdate_KF|", ...
               "RunRecursiveIv_Rsrivc_Thm)/na:2/dynamic:0$"];

## Data: a random binary input switching with probability 0.1 per sample,
## the exact ZOH response of 4/(p^2 + 2.4 p + 4) (the same system as the
## core benchmark) and output noise of standard deviation 0.05.
N = 1e5;
Ts = 0.1;
rand ("state", 1);
randn ("state", 2);
u = 2 * mod (cumsum (rand (N, 1) < 0.1), 2) - 1;
E = expm ([0 1 0; -4 -2.4 1; 0 0 0] * Ts);
Phi = E(1:2, 1:2);
Gam = E(1:2, 3);
C = [4 0];
den = poly (Phi);
num = poly (Phi - Gam * C) - den;  # C adj(zI - Phi) Gam, as D = 0
y = filter (num, den, u) + 0.05 * randn (N, 1);
theta_true = [4 2.4 4];            # [b0 f1 f2]

lambda_svf = 3.2;
Qn = 1e-4 * eye (3);
tsiv = 100;
nn = [1 2 0];
options = {"lambda_svf", lambda_svf, "adm", "kf", "adg", Qn, "tsiv", tsiv};
runs = 5;
budget = 60;                       # s, for the baseline
data = iddata (y, u, Ts, "InterSample", "zoh");
args = {data, nn, options{:}};
## Warm-up: loads the functions; probes the baseline's cost per sample.
n_probe = 3000;
rsrivc (iddata (y(1:n_probe), u(1:n_probe), Ts, "InterSample", "zoh"), nn,
        options{:});
t0 = tic ();
rsrivc_plain_octave (y(1:n_probe), u(1:n_probe), Ts, lambda_svf, Qn, tsiv);
t_probe = toc (t0);
if (numel (args_in) >= 2)
  Nb = min (N, round (str2double (args_in{2})));
elseif (t_probe / n_probe * N <= budget)
  Nb = N;
else
  ## About half the budget, rounded to 1000 samples: the probe is short.
  Nb = max (n_probe, min (N, 1e3 * floor (budget / 2 / t_probe * n_probe / 1e3)));
endif

printf ("RSRIVC-KF, N = %d samples, nn = [1 2 0], lambda_svf = %g, tsiv = %g s,\n",
        N, lambda_svf, tsiv);
printf ("Qn = 1e-4 I, prefilter and auxiliary model refreshed every sample\n");
printf ("(front-end: best of %d runs; baseline: 1 run on %d samples%s;\n",
        runs, Nb, ifelse_str (Nb < N, ", rates per sample", ""));
printf (" ratios: the better core run)\n");
if (! isempty (bin))
  core_before = run_core_benchmark (bin, core_filter);
  print_core (core_before, "before");
endif

t_front = best_time (@() rsrivc_thm (args), runs);
[thm, ~, ~, info] = rsrivc (args{:});
r_front = N / t_front;
printf ("  front-end thm = rsrivc (...)          %10.4f M samples/s (best %.3f s)\n",
        r_front / 1e6, t_front);

t0 = tic ();
thm_plain = rsrivc_plain_octave (y(1:Nb), u(1:Nb), Ts, lambda_svf, Qn, tsiv);
t_plain = toc (t0);
r_plain = Nb / t_plain;
printf ("  baseline rsrivc_plain_octave (...)    %10.4f M samples/s (%.1f s for %d samples)\n",
        r_plain / 1e6, t_plain, Nb);

if (! isempty (bin))
  core_after = run_core_benchmark (bin, core_filter);
  print_core (core_after, "after");
endif

printf ("ratios (samples/s over samples/s):\n");
printf ("  front-end / baseline                           %9.1f\n",
        r_front / r_plain);
if (! isempty (bin))
  best = @(name) max (core_before.(name), core_after.(name));
  printf ("  core update loop RSRIVC-KF / front-end         %9.2f\n",
          best ("BM_RsrivcUpdate_KF") / r_front);
  printf ("  core run_recursive_iv THM  / front-end         %9.2f\n",
          best ("BM_RunRecursiveIv_Rsrivc_Thm") / r_front);
  printf ("  core update loop RSRIVC-KF / baseline          %9.1f\n",
          best ("BM_RsrivcUpdate_KF") / r_plain);
endif

## Agreement: both are causal, so the baseline on the first Nb samples must
## reproduce the front-end's first Nb estimates.
d = abs (thm(1:Nb, :) - thm_plain);
iv = (0:Nb-1)' * Ts >= tsiv * (1 - 1e-12);
printf ("agreement baseline vs rsrivc on samples 1..%d:\n", Nb);
printf ("  final estimate [b0 f1 f2]: rsrivc   [%.6f %.6f %.6f]\n", thm(Nb, :));
printf ("                             baseline [%.6f %.6f %.6f]\n", thm_plain(end, :));
printf ("  max |difference|: final %.3g, over all samples %.3g, over the IV phase %.3g\n",
        max (d(end, :)), max (d(:)), max (max (d(iv, :))));
if (max (d(end, :)) > 1e-6 * max (abs (thm(Nb, :))))
  printf ("  WARNING: the baseline and rsrivc disagree: a bug in one of them\n");
endif
printf ("rsrivc over the whole record: final [b0 f1 f2] = [%.3f %.3f %.3f] ",
        thm(end, :));
printf ("(true [4 2.4 4]), %d stability rejections\n", info.stability_rejections);
