## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn {} {@var{T} =} rivc_octave_bench ()
## Side-by-side timing on 10 000 samples (target: at least 50 times
## faster than plain Octave): the core estimators rivc, clrivc and
## cl2srivc (core/include/ctid/offline/refined_iv_bj.hpp through rivc_mex) against
## @file{rivc_plain_octave.m}, the same iteration in plain Octave, run for
## the same number of iterations K (10) from the same start; the core is
## timed at its gateway (median of 3 runs). For cl2srivc both are given
## the starts of the two stages; the automatic start's time is printed
## apart. tfrivc's RIVC stage is rivc's iteration
## with a delay (its time is dominated by tfsrivc's delay search, timed in
## tfsrivc's own benchmark). Run from the repository root:
## @example
## octave-cli -q --eval "addpath octave bench; rivc_octave_bench"
## @end example
## @end deftypefn

function T = rivc_octave_bench ()
  pkg load control
  warning ("off", "all");
  ## The gateway itself (a copy of octave/private/rivc_mex.mex on the path,
  ## as tests/octave/test_gateway_fuzz.m does): the estimator without the
  ## front-end's parsing and model objects.
  here = fileparts (fileparts (mfilename ("fullpath")));
  tmp = tempname ();
  mkdir (tmp);
  copyfile (fullfile (here, "octave", "private", "rivc_mex.mex"), tmp);
  addpath (tmp);
  N = 10000;
  K = 10;
  randn ("state", 21);
  T = struct ("name", {}, "core", {}, "plain", {}, "ratio", {},
              "core_theta", {}, "plain_theta", {});

  ## Open loop, coloured noise.
  Ts = 0.05;
  u = kron (sign (randn (N / 10, 1)), ones (10, 1));
  x = lsim (c2d (tf ([1.5 4], [1 1.2 4]), Ts), u);
  y = x + filter ([1 0.5], [1 -0.9], 0.05 * randn (N, 1));
  th0 = [1.25 4.1 1.45 3.9];
  o = struct ("nb", 2, "nc", 1, "nd", 1, "nf", 2, "theta_init", th0,
              "tol", 1e-300, "maxiter", K);
  t_core = timeit (@() rivc_mex ("rivc", y, u, Ts, [], o));
  th_core = rivc_mex ("rivc", y, u, Ts, [], o);
  tic;
  th = rivc_plain_octave (y, u, Ts, [2 1 1 2], th0, K + 1);
  t_plain = toc;
  T(end+1) = row ("rivc [2 1 1 2 0]", t_core, t_plain, th_core, th);

  ## Closed loop, continuous controller.
  Ts = 0.01;
  r = kron (sign (randn (N / 100, 1)), ones (100, 1));
  G = tf (3, [1 2 3]); Mc = tf ([0.5 1], [0.1 1 0]);
  v = filter ([1 0.3], [1 -0.95], 0.005 * randn (N, 1));
  yc = lsim (c2d (feedback (G * Mc, 1), Ts), r) ...
       + lsim (c2d (feedback (1, G * Mc), Ts), v);
  uc = lsim (c2d (feedback (Mc, G), Ts), r) ...
       - lsim (c2d (feedback (Mc, G), Ts), v);
  th0 = [2.1 2.9 2.9];
  o = struct ("nb", 1, "nc", 1, "nd", 1, "nf", 2, "theta_init", th0,
              "tol", 1e-300, "maxiter", K, "intersample", 0,
              "controller_num", [0.5 1], "controller_den", [0.1 1 0]);
  t_core = timeit (@() rivc_mex ("clrivc", yc, uc, Ts, r, o));
  th_core = rivc_mex ("clrivc", yc, uc, Ts, r, o);
  tic;
  th = rivc_plain_octave (yc, uc, Ts, [1 1 1 2], th0, K + 1, r, [0.5 1],
                          [0.1 1 0]);
  t_plain = toc;
  T(end+1) = row ("clrivc [1 1 1 2 0]", t_core, t_plain, th_core, th);

  ## Two-stage: SRIVC of u on r, then of y on u_hat. Both sides run K
  ## iterations per stage from the same starts (the automatic start's
  ## stage results perturbed by 5 %: the core through theta_init and
  ## cl_theta_init), as the rows above; the automatic start (the SRIVC
  ## engine's IVSVF grid, refined_iv.hpp) is timed on its own line.
  o = struct ("method", "cl2srivc", "nb", 1, "nf", 2, "cl_nb", 4,
              "cl_nf", 4, "intersample", 1);
  tic;
  [th_auto, ~, info] = rivc_mex ("cl2srivc", yc, uc, Ts, r, o);
  t_auto = toc;
  o.tol = 1e-300;
  o.maxiter = K;
  o.theta_init = 1.05 * th_auto;
  o.cl_theta_init = 1.05 * info.cl_theta;
  o.max_starts = 1;
  t_core = timeit (@() rivc_mex ("cl2srivc", yc, uc, Ts, r, o));
  th_core = rivc_mex ("cl2srivc", yc, uc, Ts, r, o);
  tic;
  th1 = rivc_plain_octave (uc, r, Ts, [4 0 0 4], o.cl_theta_init, K);
  [nu_d, du_d] = tfdata (c2d (tf (th1(5:end).', [1, th1(1:4).']), Ts),
                         "vector");
  uhp = filter (nu_d, du_d, r);
  th = rivc_plain_octave (yc, uhp, Ts, [1 0 0 2], o.theta_init, K);
  t_plain = toc;
  T(end+1) = row ("cl2srivc [1 2 0] [4 4 0]", t_core, t_plain, th_core, th);
  printf ("cl2srivc with its automatic start (to convergence): %.2f s\n",
          t_auto);

  rmpath (tmp);
  confirm_recursive_rmdir (false, "local");
  rmdir (tmp, "s");
  printf ("%-26s %10s %10s %8s\n", "estimator (N = 10000)", "core (s)",
          "plain (s)", "ratio");
  for i = 1:numel (T)
    printf ("%-26s %10.4f %10.3f %8.0f\n", T(i).name, T(i).core,
            T(i).plain, T(i).ratio);
    printf ("  core  theta: %s\n  plain theta: %s\n",
            mat2str (T(i).core_theta(:).', 5),
            mat2str (T(i).plain_theta(:).', 5));
  endfor
endfunction

function s = row (name, t_core, t_plain, a, b)
  s = struct ("name", name, "core", t_core, "plain", t_plain,
              "ratio", t_plain / t_core, "core_theta", a(:).',
              "plain_theta", b(:).');
endfunction

## Median of 3 runs.
function t = timeit (f)
  ts = zeros (1, 3);
  for i = 1:3
    tic;
    f ();
    ts(i) = toc;
  endfor
  t = median (ts);
endfunction
