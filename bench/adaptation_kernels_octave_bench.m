## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## Side by side, in one run, for model orders na = 1..4: the adaptation
## steps at compile-time size (the IV step of adaptation.hpp, PotterSVF of
## potter.hpp, LMR-RLSSVF of lmr.hpp, with the fixed-size filter kernels)
## against the same steps at runtime size with the dynamic-size filter
## code (one source for both sizes, step_size.hpp), in the core
## (bench_rsrivc) and end to end through the gateways (riv_mex,
## rlssvf_mex, option kernels = "fixed" or "dynamic"), and against
## plain-Octave implementations
## (bench/rsrivc_plain_octave.m, bench/rlssvf_forms_plain_octave.m).
##
## Usage, from the repository root, after building riv_mex and rlssvf_mex
## (target octave_mex) and bench_rsrivc:
##   octave-cli -q bench/adaptation_kernels_octave_bench.m [Nplain]
## Nplain: samples given to the plain-Octave baselines (default 3000; their
## rate is per sample).
##
## Rows (1e5 samples, best of 3, CPU time as the core benchmarks):
##   RSRIVC-KF  rsrivc (data, [1 na 0], "lambda_svf", 3.2, "adm", "kf",
##              "adg", 1e-4 I, "tsiv", 100): prefilter and auxiliary model
##              refreshed every sample;
##   RIVSVF-KF  rivsvf (data, [na 1 0], same options);
##   RIVSVF-FF  rivsvf (..., "adm", "ff", "adg", 0.999, "tsiv", 100);
##   Potter-KF  rlssvf (data, [na 1 0], "lambda_svf", 3.2, "adm", "kf",
##              "adg", 1e-4 I, "potter", true);
##   LMR        rlssvf (..., "adm", "lmr", "adg", 0.999, "Gamma", 1e-3 I).
## "gw" columns call the gateway from octave/private with the options
## struct the front-end builds (kernels "fixed" or "dynamic"), "front" the
## public function. max|f-d| is the largest difference of THM between the
## two gateway paths, max|front-plain| that between the public function's
## and the plain-Octave estimates on the first Nplain samples. Data as in
## recursive_kernels_octave_bench.m.

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
    error ("adaptation_kernels_octave_bench:coreFailed",
           "adaptation_kernels_octave_bench: %s exited with status %d", bin,
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

function thm = call_gateway (gateway, p, kernels)
  opts = p.opts;
  opts.kernels = kernels;
  thm = feval (gateway, p.fname, p.data{:}, opts);
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
N = 1e5;
A = {2, [2.4 4], [3 7 5], [3.2 8.4 10.4 8]};
bin = fullfile (root, "build", "bench", "bench_rsrivc");
private_dir = fullfile (root, "octave", "private");
[~, load_avg] = system ("uptime");
printf ("uptime: %s", load_avg);
core = run_core (bin, ["^BM_(RsrivcUpdate_KF|RivsvfUpdate_KF|", ...
                       "RivsvfUpdate_FF|RlsSvfUpdate_Potter|", ...
                       "RlsSvfUpdate_Lmr)/"]);

cases = {"RSRIVC-KF", "BM_RsrivcUpdate_KF"; "RIVSVF-KF", "BM_RivsvfUpdate_KF";
         "RIVSVF-FF", "BM_RivsvfUpdate_FF"; "Potter-KF", "BM_RlsSvfUpdate_Potter";
         "LMR", "BM_RlsSvfUpdate_Lmr"};
printf ("\nmillion samples/s, %d samples (plain: %d)\n", N, Nplain);
printf ("%-10s %3s %9s %9s %9s %9s %9s %9s %9s %12s\n", "case", "na",
        "core fix", "core dyn", "ratio", "gw fix", "gw dyn", "front",
        "plain", "max|f-d|");
for c = 1:rows (cases)
  for na = 1:4
    a = A{na};
    [y, u] = make_record (a, N, Ts);
    data = iddata (y, u, Ts, "InterSample", "zoh");
    Q = 1e-4 * eye (na + 1);
    G = 1e-3 * eye (na + 1);
    if (c >= 4 && ! exist (fullfile (private_dir, "rlssvf_mex.mex"), "file"))
      printf ("%-10s %3d rlssvf_mex not built: skipped\n", cases{c, 1}, na);
      continue;
    endif
    switch (cases{c, 1})
      case "RSRIVC-KF"
        fname = "rsrivc"; gateway = "riv_mex"; nn = [1 na 0];
        options = {"lambda_svf", lambda_svf, "adm", "kf", "adg", Q, ...
                   "tsiv", tsiv};
        plain = @() rsrivc_plain_octave (y(1:Nplain), u(1:Nplain), Ts,
                                         lambda_svf, Q, tsiv);
      case "RIVSVF-KF"
        fname = "rivsvf"; gateway = "riv_mex"; nn = [na 1 0];
        options = {"lambda_svf", lambda_svf, "adm", "kf", "adg", Q, ...
                   "tsiv", tsiv};
        plain = [];
      case "RIVSVF-FF"
        fname = "rivsvf"; gateway = "riv_mex"; nn = [na 1 0];
        options = {"lambda_svf", lambda_svf, "adm", "ff", "adg", 0.999, ...
                   "tsiv", tsiv};
        plain = [];
      case "Potter-KF"
        fname = "rlssvf"; gateway = "rlssvf_mex"; nn = [na 1 0];
        options = {"lambda_svf", lambda_svf, "adm", "kf", "adg", Q, ...
                   "potter", true};
        plain = @() rlssvf_forms_plain_octave (y(1:Nplain), u(1:Nplain), Ts,
                                               lambda_svf, na, "potter", Q);
      case "LMR"
        fname = "rlssvf"; gateway = "rlssvf_mex"; nn = [na 1 0];
        options = {"lambda_svf", lambda_svf, "adm", "lmr", "adg", 0.999, ...
                   "Gamma", G};
        plain = @() rlssvf_forms_plain_octave (y(1:Nplain), u(1:Nplain), Ts,
                                               lambda_svf, na, "lmr",
                                               [0.999, 1e-3]);
    endswitch
    front = str2func (fname);
    t_front = best_time (@() front (data, nn, options{:}), runs);
    here = pwd ();
    cd (private_dir);
    unwind_protect
      if (strcmp (gateway, "riv_mex"))
        p = contsid_riv_args (fname, fname, data, nn, options{:});
      else
        p = contsid_rlssvf_args (fname, data, nn, options{:});
      endif
      p.fname = fname;
      t_fix = best_time (@() call_gateway (gateway, p, "fixed"), runs);
      t_dyn = best_time (@() call_gateway (gateway, p, "dynamic"), runs);
      thm_fix = call_gateway (gateway, p, "fixed");
      d = max (max (abs (thm_fix - call_gateway (gateway, p, "dynamic"))));
    unwind_protect_cleanup
      cd (here);
    end_unwind_protect
    r_plain = NaN;
    d_plain = NaN;
    if (! isempty (plain))
      t0 = cputime ();
      thm_plain = plain ();
      r_plain = Nplain / (cputime () - t0);
      thm_front = front (data, nn, options{:});  # the public column order
      d_plain = max (max (abs (thm_plain - thm_front(1:Nplain, :))));
    endif
    fix = core_rate (core, cases{c, 2}, na, 0);
    dyn = core_rate (core, cases{c, 2}, na, 1);
    printf (["%-10s %3d %9.3f %9.3f %9.2f %9.3f %9.3f %9.3f %9.4f %12.1e", ...
             "   max|front-plain| %.1e\n"], cases{c, 1}, na, fix / 1e6,
            dyn / 1e6, fix / dyn, N / t_fix / 1e6, N / t_dyn / 1e6,
            N / t_front / 1e6, r_plain / 1e6, d, d_plain);
  endfor
endfor
[~, load_avg] = system ("uptime");
printf ("uptime: %s", load_avg);
