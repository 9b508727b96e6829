## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn  {} {@var{T} =} residtrace_sim_records (@var{outdir})
## @deftypefnx {} {@var{T} =} residtrace_sim_records (@var{outdir}, @var{which})
## A check of @code{residtrace} on records not used to tune it: five
## nonlinear and three linear simulated rigs of realistic physics, in raw
## units (offsets, engineering units) with measurement noise, each with
## its own estimation and validation experiment. The seeds (2026112301 +
## k) are fixed, and the rules of residtrace are not adjusted on these
## records. The model given to residtrace is what a user would fit: SRIVC
## of the plain linear structure on the estimation record with its means
## removed.
##
## @table @asis
## @item tanks
## two tanks in cascade (@code{tanks_sim}), square-root outflows, the
## upper tank overflowing; documented: saturation, state_nonlinearity.
## @item axis
## a positioning axis with inelastic end stops (@code{axis_sim});
## documented: saturation.
## @item motor
## a DC motor's speed (rpm, a velocity) from the current command (V),
## Coulomb friction, a first-order speed sensor filter; documented:
## coulomb.
## @item tank
## one tank, square-root outflow, level in cm from the inflow in l/min;
## documented: state_nonlinearity.
## @item valve
## a flow loop's valve (first-order actuator) at its end stops (0 and
## 100 %), then a first-order process (temperature in degC); documented:
## saturation.
## @item lin2, lin3, linv
## linear records: a linearised two-tank (level in cm), a third-order
## thermal process (degC around 40 degC), a motor speed with viscous
## friction only (rpm); documented: no nonlinear effect.
## @end table
##
## Writes @var{outdir}/residtrace_sim_records.md (default "results": the
## table, then residtrace's verdict on each record) and
## returns the table as a struct array (record, documented, found,
## rmse_before, rmse_after, elapsed, the ranking of each pass, verdict).
## @var{which}: a cell of record names to run (default all eight; each
## record keeps its own seed).
## @end deftypefn

function T = residtrace_sim_records (outdir = "results", which = {})
  demo_prepare (outdir);
  recs = {"tanks", "axis", "motor", "tank", "valve", "lin2", "lin3", "linv"};
  doc = {{"saturation", "state_nonlinearity"}, {"saturation"}, {"coulomb"}, ...
         {"state_nonlinearity"}, {"saturation"}, {}, {}, {}};
  T = struct ("record", {}, "documented", {}, "found", {}, "all", {},
              "rmse_before", {}, "rmse_after", {}, "elapsed", {},
              "levels", {}, "passes", {}, "verdict", {});
  for k = 1:numel (recs)
    if (! isempty (which) && ! any (strcmp (which, recs{k})))
      continue;
    endif
    randn ("state", 2026112301 + k); rand ("state", 2026112301 + k);
    [u, y, uv, yv, Ts, nn] = feval (["rec_" recs{k}]);
    t0 = tic ();
    R = residtrace_record (y, u, yv, uv, Ts, nn, "iterate", 2,
                           "verbose", true);
    el = toc (t0);
    T(end+1) = struct ("record", recs{k}, "documented", strjoin (doc{k}, "/"),
                       "found", R.effect, "all", strjoin (R.effects, ", "),
                       "rmse_before", R.rmse_before,
                       "rmse_after", R.rmse_final, "elapsed", el,
                       "levels", R.levels.estimated,
                       "passes", {passes(R)}, "verdict", R.verdict);
    printf (["%-6s documented %-30s found %-20s (%s) RMSE %.4g -> %.4g, ", ...
             "%.0f s\n"],
            recs{k}, T(end).documented, R.effect, T(end).all,
            R.rmse_before, R.rmse_final, el);
    printf ("       verdict: %s\n", R.verdict);
    fflush (stdout);
  endfor
  fid = fopen (fullfile (outdir, "residtrace_sim_records.md"), "w");
  fprintf (fid, ["| record | documented effect | named first | all ", ...
                 "effects (2 passes) | levels estimated | validation ", ...
                 "simulation RMSE before -> after | time (s) |\n"]);
  fprintf (fid, "|---|---|---|---|---|---|---|\n");
  for k = 1:numel (T)
    t = T(k);
    fprintf (fid, "| %s | %s | %s | %s | %s | %.4g -> %.4g | %.0f |\n",
             t.record, ifelse (isempty (t.documented), "none (linear)",
                               t.documented), t.found, t.all,
             ifelse (t.levels, "yes", "no"), t.rmse_before, t.rmse_after,
             t.elapsed);
  endfor
  fprintf (fid, "\nVerdicts:\n\n");
  for k = 1:numel (T)
    fprintf (fid, "- %s: %s\n", T(k).record, T(k).verdict);
  endfor
  fclose (fid);
endfunction

## Each pass's ranking: effect, score, p, significant, variant.
function P = passes (R)
  P = {};
  for h = 1:numel (R.history)
    r = R.history(h).ranking;
    P{end+1} = struct ("effect", {r.effect}, "score", {r.score},
                       "p", {r.p}, "significant", {r.significant},
                       "variant", {r.variant});
  endfor
endfunction

function s = ifelse (c, a, b)
  if (c)
    s = a;
  else
    s = b;
  endif
endfunction

## the staircase inputs (residtrace_levels, shared with the tests)
function u = levels (varargin)
  u = residtrace_levels (varargin{:});
endfunction

function [u, y, uv, yv, Ts, nn] = rec_tanks ()
  p = struct ("k", 0.12, "c1", 0.1, "c2", 0.085, "h1max", 45);
  Ts = 2; N = 2500; nn = [1 2 0];
  u = levels (N, Ts, 50, 250, 2, 7); uv = levels (N, Ts, 50, 250, 2, 7);
  y = tanks_sim (u, Ts, p) + 0.25 * randn (N, 1);
  yv = tanks_sim (uv, Ts, p) + 0.25 * randn (N, 1);
endfunction

function [u, y, uv, yv, Ts, nn] = rec_axis ()
  p = struct ("wn", 9, "zeta", 0.7, "K", 25, "ymin", 15, "ymax", 230);
  Ts = 0.01; N = 6000; nn = [1 2 0];
  f = @() filter (0.05, [1 -0.95], levels (N, Ts, 0.5, 2.5, 0, 10));
  u = f (); uv = f ();
  y = axis_sim (u, Ts, p) + 0.1 * randn (N, 1);
  yv = axis_sim (uv, Ts, p) + 0.1 * randn (N, 1);
endfunction

## J w' = Kt i - b w - Fc sign(w), i the command (A); speed in rpm through
## a first-order sensor filter of 20 ms.
function y = motor (i, Ts, Fc)
  J = 2e-3; b = 4e-3; Kt = 0.08; tf = 0.02; S = 20; h = Ts / S;
  w = 0; m = 0;
  N = numel (i);
  y = zeros (N, 1);
  for k = 1:N
    y(k) = m * 60 / (2 * pi);
    for s = 1:S
      tq = Kt * i(k) - Fc * sign (w);
      if (w == 0 && abs (Kt * i(k)) <= Fc)
        tq = 0;                         # stuck
      endif
      wn = w + h * (tq - b * w) / J;
      if (w != 0 && sign (wn) != sign (w) && abs (Kt * i(k)) <= Fc)
        wn = 0;
      endif
      w = wn;
      m += h * (w - m) / tf;
    endfor
  endfor
endfunction

function [u, y, uv, yv, Ts, nn] = rec_motor ()
  Ts = 0.005; N = 5000; nn = [1 2 0];
  u = levels (N, Ts, 0.1, 0.6, -1.5, 1.5); uv = levels (N, Ts, 0.1, 0.6,
                                                         -1.5, 1.5);
  y = motor (u, Ts, 0.02) + 3 * randn (N, 1);
  yv = motor (uv, Ts, 0.02) + 3 * randn (N, 1);
endfunction

## A h' = q - c sqrt(h): inflow q in l/min, level in cm.
function h = tank (q, Ts, h0)
  A = 1.5; c = 0.9; S = 10; dt = Ts / S;
  h = zeros (numel (q), 1); x = h0;
  for k = 1:numel (q)
    h(k) = x;
    for s = 1:S
      f1 = (q(k) - c * sqrt (max (x, 0))) / A;
      f2 = (q(k) - c * sqrt (max (x + dt * f1, 0))) / A;
      x = max (x + dt / 2 * (f1 + f2), 0);
    endfor
  endfor
endfunction

function [u, y, uv, yv, Ts, nn] = rec_tank ()
  Ts = 1; N = 3000; nn = [1 1 0];
  u = levels (N, Ts, 20, 150, 1, 6); uv = levels (N, Ts, 20, 150, 1, 6);
  y = tank (u, Ts, (u(1) / 0.9) ^ 2) + 0.2 * randn (N, 1);
  yv = tank (uv, Ts, (uv(1) / 0.9) ^ 2) + 0.2 * randn (N, 1);
endfunction

## valve position z (%) = 1/(2 p + 1) command, limited to 0 .. 100 %;
## temperature = 20 + 0.5 z / (30 p + 1) degC.
function y = valve (u, Ts)
  S = 10; h = Ts / S; z = min (max (u(1), 0), 100); T = 0.5 * z;
  y = zeros (numel (u), 1);
  for k = 1:numel (u)
    y(k) = 20 + T;
    for s = 1:S
      z = min (max (z + h * (u(k) - z) / 2, 0), 100);
      T += h * (0.5 * z - T) / 30;
    endfor
  endfor
endfunction

function [u, y, uv, yv, Ts, nn] = rec_valve ()
  Ts = 0.5; N = 3000; nn = [1 2 0];
  u = levels (N, Ts, 5, 60, -30, 130); uv = levels (N, Ts, 5, 60, -30, 130);
  y = valve (u, Ts) + 0.15 * randn (N, 1);
  yv = valve (uv, Ts) + 0.15 * randn (N, 1);
endfunction

function [u, y, uv, yv, Ts, nn] = rec_lin2 ()
  Ts = 2; N = 2500; nn = [1 2 0];
  G = idctm (0.8 * 0.01 * 0.006, conv ([1 0.01], [1 0.006]));
  u = levels (N, Ts, 50, 250, 2, 7); uv = levels (N, Ts, 50, 250, 2, 7);
  f = @(u) simc (G, u - 4.5, Ts) + 36 + 0.25 * randn (N, 1);
  y = f (u); yv = f (uv);
endfunction

function [u, y, uv, yv, Ts, nn] = rec_lin3 ()
  Ts = 1; N = 3000; nn = [1 3 0];
  G = idctm (0.4 * 0.05 * 0.1 * 0.3, conv (conv ([1 0.05], [1 0.1]),
                                           [1 0.3]));
  u = levels (N, Ts, 20, 120, 0, 100); uv = levels (N, Ts, 20, 120, 0, 100);
  f = @(u) simc (G, u - 50, Ts) + 40 + 0.1 * randn (N, 1);
  y = f (u); yv = f (uv);
endfunction

function [u, y, uv, yv, Ts, nn] = rec_linv ()
  Ts = 0.005; N = 5000; nn = [1 2 0];
  u = levels (N, Ts, 0.1, 0.6, -1.5, 1.5); uv = levels (N, Ts, 0.1, 0.6,
                                                         -1.5, 1.5);
  y = motor (u, Ts, 0) + 3 * randn (N, 1);
  yv = motor (uv, Ts, 0) + 3 * randn (N, 1);
endfunction
