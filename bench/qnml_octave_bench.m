## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## Time of the Qn maximum-likelihood search (qnml) on thesis example 3.3.3,
## against a limit of 30 s, measured side by side with one
## estimator run on the same data (the search costs about `evaluations`
## such runs):
##
##   octave-cli -q bench/qnml_octave_bench.m
##
## Data as in demos/demo_ch3_qn_ml.m: b0 = 3, a1(t) = 2 + 0.8 t/250,
## Ts = 0.025 s, 250 s (10001 samples), noise variance 3e-3, input
## prbs (8, 40), lambda_svf = 3, q0 = 1e-5, bounds [1e-6, 1e-4], b0 fixed.
root = fileparts (fileparts (mfilename ("fullpath")));
addpath (fullfile (root, "octave"));
Ts = 0.025; t = (0:Ts:250)'; N = numel (t);
u = prbs (8, 40); u = u(1:N);
x = simc ([2 + 0.8 * t / 250, 3 * ones(N, 1)], [1 1 0], u, Ts);
runs = 7;
t_search = zeros (runs, 1); t_run = t_search; evals = t_search;
for s = 1:runs
  randn ("state", s);
  data = iddata (x + sqrt (3e-3) * randn (N, 1), u, Ts, "InterSample", "zoh");
  tic;
  thm = rsrivc (data, [1 1 0], "lambda_svf", 3, "adm", "kf", ...
                "adg", diag ([0 1e-5]));
  t_run(s) = toc;
  tic;
  [Qn, V, info] = qnml (data, [1 1 0], "lambda_svf", 3, "fixed", [0 NaN], ...
                        "q0", 1e-5, "lb", 1e-6, "ub", 1e-4);
  t_search(s) = toc;
  evals(s) = info.evaluations;
endfor
printf ("qnml on example 3.3.3, %d noise runs (interleaved with one rsrivc run each)\n",
        runs);
printf ("  search time: median %.3f s [%.3f, %.3f]; limit 30 s: %.0fx margin\n",
        median (t_search), min (t_search), max (t_search),
        30 / max (t_search));
printf ("  one rsrivc run: median %.4f s; search / run = %.1f (evaluations: median %d)\n",
        median (t_run), median (t_search ./ t_run), median (evals));
