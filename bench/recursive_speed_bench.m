## Fixed-size kernels against the dynamic path and plain Octave, side by side
## in ONE run (issue 14), orders na = 1..4 (nb = 1):
##
##   RSRIVC-KF, prefilter and auxiliary model refreshed every sample:
##     core run_recursive_iv THM, fixed and dynamic (bench_rsrivc);
##     rsrivc (...) end to end from Octave, "kernels" "fixed" and "dynamic";
##     the plain-Octave implementation bench/rsrivc_plain_octave.m;
##   RLSSVF-KF:
##     core run_rlssvf THM and THM+YH, fixed and dynamic (bench_rlssvf);
##     thm = rlssvf (...) and [thm, yh] = rlssvf (...) end to end, fixed and
##     dynamic.
##
## Usage, from the repository root (the core binaries default to build/bench/):
##   nice octave-cli -q bench/recursive_speed_bench.m [bench_rsrivc [bench_rlssvf]]
##
## The machine is shared: the core benchmarks run before and after the
## Octave timings (the better of the two is used), the Octave timings are the
## best of `runs`, and the ratios printed are those of this run. The
## estimates of the fixed and dynamic paths are compared (largest
## difference relative to the largest estimate), and so are the plain-Octave
## and front-end estimates on the baseline's prefix. See bench/README.md.
1;  # a script file, not a function file

## items_per_second per benchmark (names with / and : made field-legal), or
## an empty struct without the binary.
function rates = core_rates (bin, filter)
  rates = struct ();
  if (isempty (bin))
    return;
  endif
  cmd = sprintf ("\"%s\" '--benchmark_filter=%s' --benchmark_format=json",
                 bin, filter);
  [status, out] = system (cmd);
  if (status != 0)
    error ("recursive_speed_bench:coreFailed",
           "recursive_speed_bench: %s exited with status %d", bin, status);
  endif
  report = jsondecode (out);
  runs = report.benchmarks;
  if (! iscell (runs))
    runs = num2cell (runs);
  endif
  for i = 1:numel (runs)
    if (isfield (runs{i}, "items_per_second"))
      rates.(key (runs{i}.name)) = runs{i}.items_per_second;
    endif
  endfor
endfunction

function k = key (name)
  k = strrep (strrep (name, "/", "_"), ":", "_");
endfunction

## The better of two core runs of benchmark `name`, in samples/s (NaN if
## absent).
function r = best_core (a, b, name)
  r = NaN;
  k = key (name);
  if (isfield (a, k))
    r = a.(k);
  endif
  if (isfield (b, k))
    r = max (r, b.(k));
  endif
endfunction

function bin = find_binary (root, args, i, name)
  if (numel (args) >= i && ! isempty (args{i}))
    bin = args{i};
  else
    bin = fullfile (root, "build", "bench", name);
  endif
  if (! exist (bin, "file"))
    printf ("%s not found at %s: no core figures for it\n", name, bin);
    bin = "";
  endif
endfunction

## Best of `runs` wall-clock times of f(), and f()'s last result.
function [best, out] = best_time (f, runs)
  best = Inf;
  for r = 1:runs
    t0 = tic ();
    out = f ();
    best = min (best, toc (t0));
  endfor
endfunction

function thm = call_thm (f, args)
  thm = f (args{:});
endfunction

function out = call_thm_yh (f, args)
  [thm, yh] = f (args{:});
  out = {thm, yh};
endfunction

function d = rel_diff (a, b)
  d = max (abs (a(:) - b(:))) / max (1, max (abs (b(:))));
endfunction

root = fileparts (fileparts (mfilename ("fullpath")));
addpath (fullfile (root, "octave"));
addpath (fullfile (root, "bench"));
args_in = argv ();
bin_iv = find_binary (root, args_in, 1, "bench_rsrivc");
bin_ls = find_binary (root, args_in, 2, "bench_rlssvf");
filter_iv = "^BM_RunRsrivc/order:[1-4]/fixed:[01]$";
filter_ls = "^BM_RunRlsSvf/order:[1-4]/fixed:[01]/yh:[01]$";

N = 1e5;           # samples per Octave run (the core uses its own records)
Nn = 2000;         # samples given to the plain-Octave baseline
Ts = 0.1;
lambda_svf = 3.2;
tsiv = 100;
runs = 3;
rand ("state", 1);
randn ("state", 2);
u = 2 * mod (cumsum (rand (N, 1) < 0.1), 2) - 1;

printf ("Fixed-size kernels vs dynamic path vs plain Octave, one run\n");
printf ("(records of %d samples, Ts = %g, binary input, noise 0.05; core: the\n",
        N, Ts);
printf (" better of the runs before and after; Octave: best of %d)\n", runs);
core_iv_before = core_rates (bin_iv, filter_iv);
core_ls_before = core_rates (bin_ls, filter_ls);

iv = zeros (4, 7);   # core fixed, core dyn, octave fixed, octave dyn, plain,
                     # fixed-vs-dyn difference, plain-vs-front-end difference
ls = zeros (4, 9);   # core thm f/d, core thm+yh f/d, octave thm f/d,
                     # octave [thm,yh] f/d, fixed-vs-dyn difference
for n = 1:4
  ## True system 4 / (p^2 + 2.4 p + 4) for n = 2, 2^n / (p + 2)^n otherwise
  ## (the core benchmarks' systems), exact ZOH response plus noise.
  if (n == 2)
    a = [1 2.4 4];
    b0 = 4;
  else
    a = poly (-2 * ones (1, n));
    b0 = 2 ^ n;
  endif
  F = [zeros(n - 1, 1), eye(n - 1); -a(end:-1:2)];
  E = expm ([F, [zeros(n - 1, 1); 1]; zeros(1, n + 1)] * Ts);
  Phi = E(1:n, 1:n);
  Gam = E(1:n, n + 1);
  C = [b0, zeros(1, n - 1)];
  den = poly (Phi);
  num = poly (Phi - Gam * C) - den;
  y = filter (num, den, u) + 0.05 * randn (N, 1);
  data = iddata (y, u, Ts, "InterSample", "zoh");

  Qn = 1e-4 * eye (n + 1);
  opt_iv = {"lambda_svf", lambda_svf, "adm", "kf", "adg", Qn, "tsiv", tsiv};
  rsrivc (data, [1 n 0], opt_iv{:});                        # warm-up
  [t_f, thm_f] = best_time (@() call_thm (@rsrivc, {data, [1 n 0], ...
                            opt_iv{:}, "kernels", "fixed"}), runs);
  [t_d, thm_d] = best_time (@() call_thm (@rsrivc, {data, [1 n 0], ...
                            opt_iv{:}, "kernels", "dynamic"}), runs);
  t0 = tic ();
  thm_p = rsrivc_plain_octave (y(1:Nn), u(1:Nn), Ts, lambda_svf, Qn, tsiv);
  t_p = toc (t0);
  iv(n, 3:7) = [N / t_f, N / t_d, Nn / t_p, rel_diff(thm_f, thm_d), ...
                rel_diff(thm_f(1:Nn, :), thm_p)];

  opt_ls = {"lambda_svf", lambda_svf, "adm", "kf", "adg", Qn};
  rlssvf (data, [n 1 0], opt_ls{:});                        # warm-up
  [t_tf, thm_f] = best_time (@() call_thm (@rlssvf, {data, [n 1 0], ...
                             opt_ls{:}, "kernels", "fixed"}), runs);
  [t_td, thm_d] = best_time (@() call_thm (@rlssvf, {data, [n 1 0], ...
                             opt_ls{:}, "kernels", "dynamic"}), runs);
  [t_yf, out_f] = best_time (@() call_thm_yh (@rlssvf, {data, [n 1 0], ...
                             opt_ls{:}, "kernels", "fixed"}), runs);
  [t_yd, out_d] = best_time (@() call_thm_yh (@rlssvf, {data, [n 1 0], ...
                             opt_ls{:}, "kernels", "dynamic"}), runs);
  ls(n, 5:9) = [N / t_tf, N / t_td, N / t_yf, N / t_yd, ...
                max([rel_diff(thm_f, thm_d), rel_diff(out_f{1}, out_d{1}), ...
                     rel_diff(out_f{2}, out_d{2})])];
endfor

core_iv_after = core_rates (bin_iv, filter_iv);
core_ls_after = core_rates (bin_ls, filter_ls);
for n = 1:4
  for f = [1 0]
    iv(n, 2 - f) = best_core (core_iv_before, core_iv_after,
                              sprintf ("BM_RunRsrivc/order:%d/fixed:%d", n, f));
    for yh = [0 1]
      ls(n, 1 + 2 * yh + (1 - f)) = best_core (core_ls_before, core_ls_after,
        sprintf ("BM_RunRlsSvf/order:%d/fixed:%d/yh:%d", n, f, yh));
    endfor
  endfor
endfor

M = 1e6;
printf ("\nRSRIVC-KF, per-sample refresh, nn = [1 n 0] (M samples/s; plain Octave on %d samples)\n", Nn);
printf ("  n | core fixed  dynamic  f/d | rsrivc fixed  dynamic  f/d | plain   fixed/plain | |f-d|     |f-plain|\n");
for n = 1:4
  printf ("  %d | %10.3f %8.3f %4.1f | %12.3f %8.3f %4.1f | %7.4f %11.0f | %8.1e %8.1e\n",
          n, iv(n, 1) / M, iv(n, 2) / M, iv(n, 1) / iv(n, 2), iv(n, 3) / M,
          iv(n, 4) / M, iv(n, 3) / iv(n, 4), iv(n, 5) / M, iv(n, 3) / iv(n, 5),
          iv(n, 6), iv(n, 7));
endfor
printf ("  bars, n = 2: core fixed >= 3 (%.2f), rsrivc fixed >= 2.5 (%.2f), rsrivc fixed/dynamic >= 3 (%.2f)\n",
        iv(2, 1) / M, iv(2, 3) / M, iv(2, 3) / iv(2, 4));

printf ("\nRLSSVF-KF, nn = [n 1 0] (M samples/s)\n");
printf ("  n | core thm fixed  dyn  f/d | core thm+yh fixed  dyn | rlssvf thm fixed  dyn | [thm,yh] fixed  dyn | thm/[thm,yh] fixed | |f-d|\n");
for n = 1:4
  printf ("  %d | %14.3f %6.3f %4.1f | %17.3f %6.3f | %16.3f %6.3f | %14.3f %6.3f | %18.2f | %8.1e\n",
          n, ls(n, 1) / M, ls(n, 2) / M, ls(n, 1) / ls(n, 2), ls(n, 3) / M,
          ls(n, 4) / M, ls(n, 5) / M, ls(n, 6) / M, ls(n, 7) / M,
          ls(n, 8) / M, ls(n, 5) / ls(n, 7), ls(n, 9));
endfor
printf ("  bars, n = 2: core thm fixed >= 20 (%.2f); thm / [thm, yh] <= 2 (%.2f)\n",
        ls(2, 1) / M, ls(2, 5) / ls(2, 7));
