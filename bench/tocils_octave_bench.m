## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn {} {@var{T} =} tocils_octave_bench ()
## Side-by-side timing of the errors-in-variables estimators tocls and
## tocils (core/include/ctid/offline/cumulant_eiv.hpp through offline_mex)
## against @file{tocils_plain_octave.m}, the same iteration in vectorised
## plain Octave (built-in @code{filter}), on CONTSID's errors-in-variables
## demo system (p - 1)/(p^2 + 2p + 1), 10 000 and 100 000 samples, L = 50
## lags, the same number of least-squares solutions; median of 3 runs.
## Prints the ratio plain / core of each.  Run from the repository root:
## @example
## octave-cli -q --eval "addpath octave bench; tocils_octave_bench;"
## @end example
## @end deftypefn

function T = tocils_octave_bench ()
  warning ("off", "all");
  here = fileparts (fileparts (mfilename ("fullpath")));
  tmp = tempname ();
  mkdir (tmp);
  copyfile (fullfile (here, "octave", "private", "offline_mex.mex"), tmp);
  addpath (tmp);
  T = struct ("name", {}, "samples", {}, "core", {}, "plain", {},
              "ratio", {});
  for N = [10000 100000]
    randg ("state", 1); randn ("state", 2);
    Ts = 0.1;
    u0 = chisqr (N, 1, 2);
    u0 = (u0 - mean (u0)) / std (u0);
    y0 = simc (idpoly (1, [1 -1], 1, 1, [1 2 1], "Ts", 0),
               iddata ([], u0, Ts, "InterSample", "zoh"));
    u = u0 + 0.3 * randn (N, 1);
    y = y0 + 0.1 * std (y0) * randn (N, 1);
    o = struct ("na", 2, "nb", 2, "nk", 0, "intersample", "zoh",
                "lambda_svf", 3, "lags", 50, "maxiter", 10, "tol", 1e-300);
    for name = {"tocls", "tocils"}
      iterative = strcmp (name{1}, "tocils");
      if (! iterative)
        o2 = rmfield (o, {"maxiter", "tol"});
      else
        o2 = o;
      endif
      o2.method = name{1};
      [~, ~, ~, iters] = offline_mex (name{1}, y, u, Ts, o2);
      t_core = median_time (@() offline_mex (name{1}, y, u, Ts, o2));
      t_plain = median_time (@() tocils_plain_octave (y, u, Ts, 2, 2, 50,
                                                      3, iters - 1));
      T(end+1) = struct ("name", name{1}, "samples", N, "core", t_core,
                         "plain", t_plain, "ratio", t_plain / t_core);
      printf ("%-7s N = %6d: core %8.4f s, plain Octave %8.4f s, ratio %5.1f\n",
              name{1}, N, t_core, t_plain, t_plain / t_core);
    endfor
  endfor
  rmpath (tmp);
  confirm_recursive_rmdir (false, "local");
  rmdir (tmp, "s");
endfunction

function t = median_time (f)
  times = zeros (1, 3);
  for i = 1:3
    tic;
    f ();
    times(i) = toc;
  endfor
  t = median (times);
endfunction
