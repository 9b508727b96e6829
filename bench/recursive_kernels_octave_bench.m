## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## Side by side, in one run, for model orders na = 1..4: RSRIVC-KF and
## RLSSVF-KF with the fixed-size filter kernels (companion_kernels.hpp, the
## default) against the dynamic-size reference, in the core (bench_rsrivc,
## bench_rlssvf) and end to end from Octave, and RSRIVC against the
## plain-Octave implementation bench/rsrivc_plain_octave.m.
##
## Usage, from the repository root, after building the gateways (target
## octave_mex) and the benchmarks:
##   octave-cli -q bench/recursive_kernels_octave_bench.m [Nplain]
## Nplain: samples given to the plain-Octave baseline (default 3000; its
## rate is per sample).
##
## End to end: thm = rsrivc (data, [1 na 0], "lambda_svf", 3.2, "adm",
## "kf", "adg", 1e-4*eye (na+1), "tsiv", 100) on 1e5 samples (prefilter and
## auxiliary model refreshed every sample), and thm = rlssvf (data,
## [na 1 0], "lambda_svf", 3.2, "adm", "kf", "adg", 1e-4*eye (na+1)) and
## [thm, yh] = rlssvf (...) on 1e6 samples; best of 3, CPU time (cputime),
## as the core benchmarks. The RLSSVF table prints the ratio of the time of
## [thm, yh] to that of thm alone in the core (run_rlssvf) and end to end
## (the two front-end calls timed in turn), and the largest difference of
## YH between the fixed-size path (the series of frozen_model.hpp) and the
## dynamic reference. Without riv_mex the RSRIVC table is skipped.
## The dynamic path is reached through the gateways' option
## kernels = "dynamic" (the front-ends do not expose it), called from
## octave/private with the options struct the front-end builds; "gateway
## fixed" is the same call with the default.
## Data: a random binary input (switching with probability 0.1), the exact
## ZOH response of b0/A(p) (unit static gain; A as in the core benchmarks),
## Ts = 0.1 s, output noise 0.05.

1;  # a script file, not a function file

function rates = run_core (bin, filter)
  rates = struct ();
  if (! exist (bin, "file"))
    printf ("core benchmark %s not found\n", bin);
    return;
  endif
  cmd = sprintf ("\"%s\" '--benchmark_filter=%s' --benchmark_format=json",
                 bin, filter);
  [status, out] = system (cmd);
  if (status != 0)
    error ("recursive_kernels_octave_bench:coreFailed",
           "recursive_kernels_octave_bench: %s exited with status %d", bin,
           status);
  endif
  runs = jsondecode (out).benchmarks;
  if (! iscell (runs))
    runs = num2cell (runs);
  endif
  for i = 1:numel (runs)
    if (isfield (runs{i}, "items_per_second"))
      key = regexprep (runs{i}.name, "[^A-Za-z0-9]", "_");
      rates.(key) = runs{i}.items_per_second;
    endif
  endfor
endfunction

function r = core_rate (rates, name, na, dynamic)
  key = regexprep (sprintf ("%s/na:%d/dynamic:%d", name, na, dynamic),
                   "[^A-Za-z0-9]", "_");
  if (isfield (rates, key))
    r = rates.(key);
  else
    r = NaN;
  endif
endfunction

## Best of `runs` CPU times of f(): on a shared, loaded machine wall-clock
## time counts the time the process waits for a core; the core benchmarks
## report CPU time too.
function best = best_time (f, runs)
  best = Inf;
  for r = 1:runs
    t0 = cputime ();
    f ();
    best = min (best, cputime () - t0);
  endfor
endfunction

function [y, u] = make_record (a, N, Ts)
  na = numel (a);
  u = 2 * mod (cumsum (rand (N, 1) < 0.1), 2) - 1;
  F = [zeros(na - 1, 1), eye(na - 1); -fliplr(a)];
  E = expm ([F, [zeros(na - 1, 1); 1]; zeros(1, na + 1)] * Ts);
  Phi = E(1:na, 1:na);
  Gam = E(1:na, na + 1);
  C = [a(end), zeros(1, na - 1)];
  den = poly (Phi);
  num = poly (Phi - Gam * C) - den;
  y = filter (num, den, u) + 0.05 * randn (N, 1);
endfunction

function thm = call_gateway (name, p, kernels, nout)
  opts = p.opts;
  opts.kernels = kernels;
  outs = cell (1, nout);
  [outs{:}] = feval (name, p.fname, p.data{:}, opts);
  thm = outs{1};
endfunction

root = fileparts (fileparts (mfilename ("fullpath")));
addpath (fullfile (root, "octave"));
addpath (fullfile (root, "bench"));
args_in = argv ();
Nplain = 3000;
if (numel (args_in) >= 1)
  Nplain = round (str2double (args_in{1}));
endif
rand ("state", 1);
randn ("state", 2);
Ts = 0.1;
lambda_svf = 3.2;
tsiv = 100;
runs = 3;
A = {2, [2.4 4], [3 7 5], [3.2 8.4 10.4 8]};
bin_iv = fullfile (root, "build", "bench", "bench_rsrivc");
bin_ls = fullfile (root, "build", "bench", "bench_rlssvf");
[~, load_avg] = system ("uptime");
printf ("uptime: %s", load_avg);
core_iv = run_core (bin_iv,
                    "^BM_(RsrivcUpdate_KF|RunRecursiveIv_Rsrivc_Thm)/");
core_ls = run_core (bin_ls,
                    "^BM_(RlsSvfUpdate_KF|RunRlsSvf_Thm|RunRlsSvf_ThmYh)/");
private_dir = fullfile (root, "octave", "private");

if (! exist (fullfile (private_dir, "riv_mex.mex"), "file"))
  printf ("\nriv_mex not built: RSRIVC skipped\n");
  na_iv = [];
else
  na_iv = 1:4;
  printf ("\nRSRIVC-KF, 1e5 samples, per-sample refresh (M samples/s)\n");
  printf ("%3s %9s %9s %9s %9s %9s %9s %9s %9s\n", "na", "core fix",
          "core dyn", "run fix", "run dyn", "front", "gw fix", "gw dyn",
          "plain");
endif
for na = na_iv
  a = A{na};
  N = 1e5;
  [y, u] = make_record (a, N, Ts);
  data = iddata (y, u, Ts, "InterSample", "zoh");
  Qn = 1e-4 * eye (na + 1);
  options = {"lambda_svf", lambda_svf, "adm", "kf", "adg", Qn, "tsiv", tsiv};
  rsrivc (iddata (y(1:2000), u(1:2000), Ts, "InterSample", "zoh"), [1 na 0],
          options{:});
  t_front = best_time (@() rsrivc (data, [1 na 0], options{:}), runs);
  here = pwd ();
  cd (private_dir);
  unwind_protect
    p = contsid_riv_args ("rsrivc", "rsrivc", data, [1 na 0], options{:});
    p.fname = "rsrivc";
    t_fix = best_time (@() call_gateway ("riv_mex", p, "fixed", 1), runs);
    t_dyn = best_time (@() call_gateway ("riv_mex", p, "dynamic", 1), runs);
    d = max (max (abs (call_gateway ("riv_mex", p, "fixed", 1)
                       - call_gateway ("riv_mex", p, "dynamic", 1))));
  unwind_protect_cleanup
    cd (here);
  end_unwind_protect
  t0 = cputime ();
  rsrivc_plain_octave (y(1:Nplain), u(1:Nplain), Ts, lambda_svf, Qn, tsiv);
  r_plain = Nplain / (cputime () - t0);
  printf (["%3d %9.3f %9.3f %9.3f %9.3f %9.3f %9.3f %9.3f %9.4f", ...
           "   max|fix-dyn| %.1e\n"], na,
          core_rate (core_iv, "BM_RsrivcUpdate_KF", na, 0) / 1e6,
          core_rate (core_iv, "BM_RsrivcUpdate_KF", na, 1) / 1e6,
          core_rate (core_iv, "BM_RunRecursiveIv_Rsrivc_Thm", na, 0) / 1e6,
          core_rate (core_iv, "BM_RunRecursiveIv_Rsrivc_Thm", na, 1) / 1e6,
          N / t_front / 1e6, N / t_fix / 1e6, N / t_dyn / 1e6, r_plain / 1e6,
          d);
endfor

if (! exist (fullfile (private_dir, "rlssvf_mex.mex"), "file"))
  printf ("\nrlssvf_mex not built: RLSSVF skipped\n");
  return;
endif
printf ("\nRLSSVF-KF, 1e6 samples (M samples/s); +yh: [thm, yh] = rlssvf\n");
printf (["ratio: time of [thm, yh] over time of thm alone ", ...
         "(core: run_rlssvf;", ...
         " front: the Octave\nfront-end, the two timed in turn, best of %d", ...
         " each); |dyn|: max |yh fixed - yh dynamic|\nover max |yh|", ...
         " (gateway option kernels)\n"], runs);
printf ("%3s %8s %8s %8s %8s %8s %8s %8s %8s %8s %8s %8s %8s\n", "na",
        "core fix", "core dyn", "thm fix", "+yh fix", "ratio", "+yh dyn",
        "front", "front+yh", "ratio", "gw+yh fx", "gw+yh dy", "|dyn|");
for na = 1:4
  a = A{na};
  N = 1e6;
  [y, u] = make_record (a, N, Ts);
  data = iddata (y, u, Ts, "InterSample", "zoh");
  options = {"lambda_svf", lambda_svf, "adm", "kf", "adg", ...
             1e-4 * eye(na + 1)};
  rlssvf (iddata (y(1:2000), u(1:2000), Ts, "InterSample", "zoh"), [na 1 0],
          options{:});
  ## thm alone and [thm, yh] in turn, so that both see the same load
  t_front = Inf;
  t_front_yh = Inf;
  for r = 1:runs
    t_front = min (t_front,
                   best_time (@() rlssvf (data, [na 1 0], options{:}), 1));
    t_front_yh = min (t_front_yh,
                      best_time (@() nthargout (1:2, @rlssvf, data,
                                                [na 1 0], options{:}), 1));
  endfor
  here = pwd ();
  cd (private_dir);
  unwind_protect
    p = contsid_rlssvf_args ("rlssvf", data, [na 1 0], options{:});
    p.fname = "rlssvf";
    t_yh_fix = best_time (@() call_gateway ("rlssvf_mex", p, "fixed", 2),
                          runs);
    t_yh_dyn = best_time (@() call_gateway ("rlssvf_mex", p, "dynamic", 2),
                          runs);
    opts = p.opts;
    opts.kernels = "fixed";
    [~, yh_fix] = rlssvf_mex ("rlssvf", p.data{:}, opts);
    opts.kernels = "dynamic";
    [~, yh_dyn] = rlssvf_mex ("rlssvf", p.data{:}, opts);
    d_yh = max (abs (yh_fix - yh_dyn)) / max (abs (yh_dyn));
  unwind_protect_cleanup
    cd (here);
  end_unwind_protect
  c_thm = core_rate (core_ls, "BM_RunRlsSvf_Thm", na, 0);
  c_yh = core_rate (core_ls, "BM_RunRlsSvf_ThmYh", na, 0);
  printf (["%3d %8.3f %8.3f %8.3f %8.3f %8.2f %8.3f %8.3f %8.3f %8.2f", ...
           " %8.3f %8.3f %8.1e\n"], na,
          core_rate (core_ls, "BM_RlsSvfUpdate_KF", na, 0) / 1e6,
          core_rate (core_ls, "BM_RlsSvfUpdate_KF", na, 1) / 1e6,
          c_thm / 1e6, c_yh / 1e6, c_thm / c_yh,
          core_rate (core_ls, "BM_RunRlsSvf_ThmYh", na, 1) / 1e6,
          N / t_front / 1e6, N / t_front_yh / 1e6, t_front_yh / t_front,
          N / t_yh_fix / 1e6, N / t_yh_dyn / 1e6, d_yh);
endfor
[~, load_avg] = system ("uptime");
printf ("uptime: %s", load_avg);
