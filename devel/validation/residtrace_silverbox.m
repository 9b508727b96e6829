## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn {} {@var{R} =} residtrace_silverbox ()
## @deftypefnx {} {@var{R} =} residtrace_silverbox (@dots{})
## The residtrace part of @code{demo_silverbox} alone (without the RSRIVC
## tracking, which takes most of that demo's time): SRIVC [1 2 0] on the
## first 40 000 samples of the Silverbox record, @code{residtrace} with
## the next 20 000 as validation and @code{iterate} 4, verbose (each
## pass's ranking: effect, score, p), then the table's rows (validation
## simulation RMSE and fit of each step) and the wall and CPU time.
## Further arguments are residtrace's options. About 6 min at load 8 on
## a 2-core machine.
## @end deftypefn

function R = residtrace_silverbox (varargin)
  here = fileparts (mfilename ("fullpath"));
  addpath (fullfile (here, "..", "..", "octave"));
  [root, why] = ctid_data_dir ("silverbox");
  if (isempty (root))
    error ("residtrace_silverbox:noData", "residtrace_silverbox: %s", why);
  endif
  s = load (fullfile (root, "SNLS80mV.mat"));
  u = double (s.V1(:)); y = double (s.V2(:));
  Ts = 2 ^ 14 / 1e7;
  Ne = 40000; iv = 40001:60000;
  d = iddata (y(1:Ne), u(1:Ne), Ts, "InterSample", "zoh");
  dv = iddata (y(iv), u(iv), Ts, "InterSample", "zoh");
  M = srivc (d, [1 2 0]);
  t0 = tic (); c0 = cputime ();
  R = residtrace (d, M, "validation", dv, "iterate", 4, "verbose", true,
                  varargin{:});
  printf ("residtrace: %.1f s wall, %.1f s CPU\n", toc (t0),
          cputime () - c0);
  for k = 1:numel (R.steps)
    printf ("  %-62s RMSE %.5g V, fit %.2f %%\n", R.steps(k).label,
            R.steps(k).rmse, R.steps(k).fit);
  endfor
endfunction
