## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn {} {@var{R} =} srivc_records ()
## @deftypefnx {} {@var{R} =} srivc_records (@var{only})
## SRIVC with its automatic start over a grid of structures on the measured
## records (@code{ctid_data_dir}), raw and mean-removed (target: a stable,
## converged model on >= 95 % of such fits). Not a test (it takes minutes):
## run it from the repository root,
## @example
## devel/run-study srivc_records
## @end example
## Records: EMPS (force gtau*vir -> motor position qm, and -> velocity
## d qm/dt), estimation and pulses records; Silverbox V1 -> V2, its
## Gaussian-noise part (samples 1..40000) and its multisine part
## (40001..131072). Structures [nb nf nk] per record below. Prints one
## line per fit and the share stable and converged per record; returns
## the table as a struct array. @var{only} (indices into the six records
## in the order above, default all) runs a subset while iterating; the
## bar is judged on the whole grid. Columns: @code{clip} the returned
## iterate was pulled back into the stable region, @code{int} a pole at
## p = 0 was detected and declared (srivc:integratorDetected), @code{det}
## the data determine the parameters (false: srivc:overParameterised).
## @end deftypefn

function R = srivc_records (only)
  [data, why] = ctid_data_dir ();
  if (isempty (data))
    error ("srivc_records:noData", "srivc_records: %s", why);
  endif
  recs = {};
  for name = {"DATA_EMPS.mat", "DATA_EMPS_PULSES.mat"}
    s = load (fullfile (data, "emps", name{1}));
    Ts = s.t(2) - s.t(1);
    f = s.gtau * s.vir(:);
    q = s.qm(:);
    v = [0; diff(q)] / Ts;
    recs(end+1, :) = {[name{1} " force->position"], q, f, Ts, ...
                      [1 2 0; 1 3 0; 2 3 0; 1 1 0; 2 2 0; 3 3 0]};
    recs(end+1, :) = {[name{1} " force->velocity"], v, f, Ts, ...
                      [1 1 0; 1 2 0; 2 2 0; 1 3 0; 2 3 0; 3 3 0]};
  endfor
  s = load (fullfile (data, "silverbox", "SNLS80mV.mat"));
  Ts = 2 ^ 14 / 1e7;
  parts = {1:40000, 40001:numel(s.V1)};
  names = {"Silverbox noise part", "Silverbox multisine part"};
  for k = 1:2
    recs(end+1, :) = {names{k}, s.V2(parts{k})(:), s.V1(parts{k})(:), Ts, ...
                      [1 2 0; 2 2 0; 3 2 0; 2 3 0; 3 3 0; 3 4 0]};
  endfor

  if (nargin >= 1)
    recs = recs(only, :);
  endif
  R = struct ("record", {}, "nn", {}, "mean_removed", {}, "stable", {},
              "converged", {}, "RT2", {}, "iterations", {}, "seconds", {},
              "clipped", {}, "integrators", {}, "determined", {},
              "reason", {});
  state = warning ("off", "all");
  cleanup = onCleanup (@() warning (state));
  printf ("%-44s %-10s %-4s %6s %5s %5s %8s %6s %4s %3s %3s\n", "record",
          "nn", "mean", "stable", "conv", "iter", "RT2", "s", "clip", "int",
          "det");
  for r = 1:rows (recs)
    [name, y, u, Ts, NN] = recs{r, :};
    for centre = [false true]
      yy = y; uu = u;
      if (centre)
        yy -= mean (yy); uu -= mean (uu);
      endif
      d = iddata (yy, uu, Ts, "InterSample", "zoh");
      for k = 1:rows (NN)
        t_run = tic ();
        try
          [M, RT2, ~, ~, ~, info] = srivc (d, NN(k, :));
          ok = [info.stable, info.converged];
          it = info.iterations;
          extra = [info.clipped, sum(info.integrators), info.determined];
          why = info.reason;
        catch err
          RT2 = NaN; ok = [false false]; it = 0; extra = [0 0 0];
          why = err.message;
          printf ("  (%s)\n", err.message);
        end_try_catch
        sec = toc (t_run);
        R(end+1) = struct ("record", name, "nn", NN(k, :),
                           "mean_removed", centre, "stable", ok(1),
                           "converged", ok(2), "RT2", RT2, "iterations", it,
                           "seconds", sec, "clipped", extra(1),
                           "integrators", extra(2), "determined", extra(3),
                           "reason", why);
        printf ("%-44s %-10s %-4d %6d %5d %5d %8.4f %6.2f %4d %3d %3d\n",
                name, mat2str (NN(k, :)), centre, ok(1), ok(2), it, RT2, sec,
                extra);
        fflush (stdout);
      endfor
    endfor
  endfor
  printf ("\nshare stable and converged per record:\n");
  names = unique ({R.record});
  for k = 1:numel (names)
    sel = strcmp ({R.record}, names{k});
    good = [R(sel).stable] & [R(sel).converged];
    printf ("  %-44s %3d / %3d\n", names{k}, sum (good), sum (sel));
  endfor
  good = [R.stable] & [R.converged];
  printf ("  %-44s %3d / %3d = %.1f %%\n", "all", sum (good), numel (R),
          100 * mean (good));
  integ = good & [R.integrators] > 0;
  printf (["  of which %d with a detected pole at p = 0 (without them: ", ...
           "%d / %d = %.1f %%)\n"], sum (integ), sum (good & ! integ),
          numel (R), 100 * mean (good & ! integ));
  nofit = good & [R.RT2] < 0.01;
  printf (["  of which %d converged at a useless model (R_T^2 < 0.01, ", ...
           "srivc:noFit; without them: %d / %d)\n"], sum (nofit),
          sum (good & ! nofit), numel (R));
endfunction
