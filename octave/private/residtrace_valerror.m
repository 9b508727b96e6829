## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn {} {[@var{e}, @var{yh}] =} residtrace_valerror (@var{model}, @var{V}, @var{ctx})
## The error of a @code{residtrace} model on the record @var{V} (not used
## to fit it): @var{e} = y - @var{yh}.
##
## @itemize
## @item The model is simulated on V's input from rest; when V is the end
## of a split record (@code{V.pre} holds the part before it) the
## simulation starts at the beginning of the whole record, so that the
## model's state at V's first sample comes from the input.
## @item The model is simulated on V's input (in closed loop when V has a
## @code{loop}), see @code{residtrace_simulate}.
## @item A drifting model (@code{model.ltv}) is simulated with the
## parameters tracked on V by @code{rsrivc} or @code{residtrace_track}
## (see @code{residtrace_cand_drift}), one sample behind.
## @item With an unknown initial state (@code{model.x0}), the model's free
## response (@code{residtrace_free}) is fitted on V's error by least
## squares and added to the output, as MATLAB's @code{compare} does; a
## cascade realisation's initial levels (@code{phys.h0}, @code{phys.z0})
## are fitted on V instead. Without, a cascade starts at the levels
## fitted on the estimation record.
## @item Sinusoidal output terms keep their frequencies; their amplitudes
## and phases, unknown on another record, are fitted on each half of the
## residual and applied to the other half (two-fold cross-fitting).
## @item A noise model A(q) (@code{model.noise}) turns e into the
## one-step-ahead prediction error A(q) e.
## @item At V's missing samples (@code{V.missing}, bridged by
## @code{residtrace_bridge}) e is 0 and yh the bridged y: they are not
## scored.
## @end itemize
## The error is computed in the core
## (core/include/ctid/apps/residtrace/simulate.hpp, validation_error,
## gateway @code{effect_sim_mex}, method "valerror"); the parameter path
## of a drifting model and a cascade's initial levels are found here and
## passed to it.
## @end deftypefn

function [e, yh] = residtrace_valerror (model, V, ctx)
  o = struct ("substeps", ctx.opts.substeps, "thm", [], "yh", []);
  m = model;
  m.out(strcmp ({m.out.type}, "sinusoid")) = [];
  if (! isempty (m.ltv))
    ## With a prefix (the estimation part of a split record) the tracking
    ## starts at the beginning of the whole record.
    Vf = V;
    npre = 0;
    if (! isempty (V.pre))
      npre = numel (V.pre.y);
      Vf.y = [V.pre.y; V.y];
      Vf.u = [V.pre.u; V.u];
      Vf.vhat = [V.pre.vhat; V.vhat];
      Vf.ysm = [V.pre.ysm; V.ysm];
    endif
    if (strcmp (m.ltv.method, "rsrivc"))
      o.thm = track_rsrivc (m, Vf, npre);
    else
      o.thm = residtrace_track (m, Vf, ctx, m.ltv.Qn, m.ltv.th0, m.ltv.P0,
                                npre + 1);
    endif
  elseif (isfield (m, "x0") && m.x0 && has_levels (m) && isempty (V.pre))
    yh = residtrace_simulate (m, V.u, V.Ts, V.loop, ctx.opts.substeps);
    if (all (isfinite (V.y - yh)))
      yh = refit_levels (m, V, ctx);
    endif
    o.yh = yh;
  endif
  [e, yh] = effect_sim_mex ("residtrace", "valerror", model, V, o);
endfunction

function ok = has_levels (m)
  ok = ! isempty (m.phys) && strcmp (m.phys.kind, "cascade") ...
       && isfield (m.phys, "h0") && ! isempty (m.phys.h0);
endfunction

## A cascade's initial state is its two levels (h0, and z0 at rest with
## it unless given): with the initial state estimated both are fitted on
## the record's error by Nelder-Mead, from the best of three starts: the
## estimation record's levels, at rest at the record's first sample, and
## at rest for its first input (as a linear model's free response is
## fitted). Returns the simulated output with those levels.
function yh = refit_levels (m, V, ctx)
  y = V.y;
  P = m.phys;
  starts = zeros (2, 3);
  starts(:, 1) = [P.h0; residtrace_cascade_levels(P)];
  r = m; r.phys.z0 = [];
  r.phys.h0 = y(1) - P.c;
  starts(:, 2) = [r.phys.h0; residtrace_cascade_levels(r.phys)];
  r.phys.h0 = [];                        # at rest for the first input
  [yr, z] = residtrace_physsim (r, V.u, V.Ts);
  starts(:, 3) = [yr(1) - P.c; z(1)];
  f = @(x) sum ((y - sim_x0 (m, x, V, ctx)) .^ 2);
  fs = arrayfun (@(k) f (starts(:, k)), 1:3);
  [~, k] = min (fs);
  x = starts(:, k);
  [xb, fb] = fminsearch (f, x, optimset ("MaxFunEvals", 200,
                                         "TolX", 1e-8, "TolFun", 1e-10,
                                         "Display", "off"));
  if (! (fb < fs(k)))
    xb = x;
  endif
  yh = sim_x0 (m, xb, V, ctx);
endfunction

function yh = sim_x0 (m, x, V, ctx)
  m.phys.h0 = x(1);
  m.phys.z0 = max (x(2), 0);
  yh = residtrace_simulate (m, V.u, V.Ts, V.loop, ctx.opts.substeps);
endfunction

## RSRIVC-KF on the record (from the start of a split record, or from
## where it ended on the estimation record), one sample behind, in the
## [f b] order of the model.
function thm = track_rsrivc (m, Vf, npre)
  L = m.ltv;
  if (npre > 0)
    th0 = L.th_start; P0 = L.P_start;
  else
    th0 = L.th0; P0 = L.P0;
  endif
  nf = numel (m.F) - 1;
  Fs = residtrace_prefilter ([1, th0(end-nf+1:end)], 1e-6);
  data = iddata (Vf.y, Vf.u(:, m.channels.col), Vf.Ts,
                 "InterSample", Vf.intersample);
  t = rsrivc (data, L.nn, "A", Fs, "th0", th0, "P0", P0, "tsiv", 0,
              "adm", "kf", "adg", L.Qn);
  t = [th0(:).'; t(1:end-1, :)];
  thm = zeros (size (t));
  thm(:, L.perm) = t;                # back to [f b]
endfunction
