## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## Throughput of rlssvf end to end in Octave (front-end, argument checks,
## gateway, core), next to the compiled core benchmark measured in the same
## run, so that the ratio core/Octave is not spoilt by the load of a shared
## machine.
##
## Usage, from the repository root:
##   octave-cli -q bench/rlssvf_octave_bench.m [path/to/bench_rlssvf]
## The core benchmark defaults to build/bench/bench_rlssvf; without it only
## the Octave timings are printed. See bench/README.md.
##
## Timed (best of 3 runs, 1e6 samples, RLSSVF-KF, nn = [2 1 0]):
##   thm = rlssvf (data, [2 1 0], "lambda_svf", 3.2, "adm", "kf",
##                 "adg", 1e-4*eye (3))
##   [thm, yh] = rlssvf (...)
## The core benchmark runs before and after the Octave timings; the better
## of its two runs is used for the ratios.

1;  # a script file, not a function file

function bin = find_core_benchmark (root, args)
  if (! isempty (args))
    bin = args{1};
  else
    bin = fullfile (root, "build", "bench", "bench_rlssvf");
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
    error ("rlssvf_octave_bench:coreFailed",
           "rlssvf_octave_bench: %s exited with status %d", bin, status);
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
    printf ("  core %-6s %-20s %8.3f M samples/s\n", when, names{i},
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

function rlssvf_thm (args)
  thm = rlssvf (args{:});
endfunction

function rlssvf_thm_yh (args)
  [thm, yh] = rlssvf (args{:});
endfunction

root = fileparts (fileparts (mfilename ("fullpath")));
addpath (fullfile (root, "octave"));
bin = find_core_benchmark (root, argv ());
core_filter = ["^BM_(RlsSvfUpdate_KF|RunRlsSvf_Thm|RunRlsSvf_ThmYh)", ...
               "/na:2/dynamic:0$"];

## Data: a random binary input switching with probability 0.1 per sample,
## the exact ZOH response of 4/(p^2 + 2.4 p + 4) (the same system as the
## core benchmark) and output noise of standard deviation 0.05.
N = 1e6;
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

Qn = 1e-4 * eye (3);
options = {"lambda_svf", 3.2, "adm", "kf", "adg", Qn};
nn = [2 1 0];
runs = 3;
form = "iddata";
try
  data = iddata (y, u, Ts, "InterSample", "zoh");
  args = [{data, nn}, options];
  ## Warm-up on a short record: loads the functions, checks the form works.
  rlssvf (iddata (y(1:100), u(1:100), Ts, "InterSample", "zoh"), nn,
          options{:});
catch err
  printf ("iddata form unavailable (%s): numeric form used\n", err.message);
  form = "numeric";
  args = [{y, u, Ts, nn}, options];
  rlssvf (y(1:100), u(1:100), Ts, nn, options{:});
end_try_catch

printf ("rlssvf, N = %d samples, RLSSVF-KF, nn = [2 1 0], %s data\n",
        N, form);
printf ("(Octave: best of %d runs; ratios: the better core run)\n", runs);
if (! isempty (bin))
  core_before = run_core_benchmark (bin, core_filter);
  print_core (core_before, "before");
endif

t_thm = best_time (@() rlssvf_thm (args), runs);
t_thm_yh = best_time (@() rlssvf_thm_yh (args), runs);
thm = rlssvf (args{:});
printf ("  octave thm = rlssvf (...)       %8.3f M samples/s (best %.3f s)\n",
        N / t_thm / 1e6, t_thm);
printf ("  octave [thm, yh] = rlssvf (...) %8.3f M samples/s (best %.3f s)\n",
        N / t_thm_yh / 1e6, t_thm_yh);
printf ("  final estimate [a1 a2 b0] = [%.3f %.3f %.3f] (true [2.4 4 4])\n",
        thm(end, :));
if (t_thm > 0.5 * t_thm_yh)
  printf (["  note: thm alone costs more than half of [thm, yh]: the\n" ...
           "  front-end may be computing outputs that were not requested\n"]);
endif

if (! isempty (bin))
  core_after = run_core_benchmark (bin, core_filter);
  print_core (core_after, "after");
  best = @(name) max (core_before.(name), core_after.(name));
  printf ("ratio core/Octave:\n");
  printf ("  core update loop (KF)  / octave thm       %7.2f\n",
          best ("BM_RlsSvfUpdate_KF") * t_thm / N);
  printf ("  core run_rlssvf THM    / octave thm       %7.2f\n",
          best ("BM_RunRlsSvf_Thm") * t_thm / N);
  printf ("  core run_rlssvf THM+YH / octave [thm, yh] %7.2f\n",
          best ("BM_RunRlsSvf_ThmYh") * t_thm_yh / N);
endif
