## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn  {} {@var{res} =} demo_throttle_friction (@var{outdir})
## @deftypefnx {} {@var{res} =} demo_throttle_friction (@var{outdir}, @
##   @var{name}, @var{value}, @dots{})
## Hide the Coulomb friction of the
## throttle from a linear model of its mechanical part and let the tracing
## tool @code{residtrace} find it.
##
## @strong{Data.} Two records of the throttle loop (@code{throttlesim}, the
## true plant with friction Mc = 8e-3 N m, R = 1.4 Ohm constant), inside the
## linear spring region (4.16): for estimation 60 s, for validation 40 s.
## The set point rests 1 s, then ramps as a triangle wave (30-60 degrees
## with a 4 s period; 35-65 degrees with 3 s for validation), so that the
## plate moves for seconds with one sign of omega and the friction torque
## is a square wave. The angle noise has variance 1e-8 rad^2 (std 0.006
## degrees, a fine encoder), see "Noise" below.
##
## @strong{Model without friction.} Eq. (4.17) without its last term,
## (p^2 + a1 p + a2) phi = b i + const, written in deviations from the
## initial rest state (phi - phi0, i - i0, both the means over the first
## 0.5 s; the constant spring torque m_s1 and the holding current cancel
## there, so the model needs no constant input and starts consistently from
## rest): @code{M = srivc (data, [1 2 0])}, i.e. b / (p^2 + a1 p + a2) from
## the current to the angle. With the known J, a1 J, a2 J and b J estimate
## Kb, Ks1 and Kt Gr.
##
## @strong{Answer key} (what the tool should find): the same model with
## the missing term of (4.17) as a second input, sign(omega) (the filtered
## regression of eq. 4.17, as the thesis does), once with the true omega
## (an oracle only a simulation has) and once with omega from an SVF
## derivative of phi_m (50 rad/s); -b_2 / b_1 Kt Gr estimates Mc.
##
## @strong{Tracing.} If @code{residtrace} is on the path, @code{R =
## residtrace (data, M, "validation", datav)} is called and its top effect,
## ranking and validation RMSE before and after are written; the effect
## should be "coulomb". Without it, the table says so.
##
## @strong{Noise.} The same is repeated at the thesis' noise variance 1e-3
## rad^2 for the record: there the PID (about -34 (e_k - 1.09 e_(k-1)) at
## high frequencies) turns the noise into a voltage of 1.6 V std that
## reverses the plate's motion about 280 times per second (measured), and
## the current is correlated with the output noise through the loop, so
## the open-loop srivc fit is biased and the Coulomb term is not
## identifiable from i to phi.
##
## Options (for short checks): @code{"levels"}, the noise variances
## (default [1e-8 1e-3]); @code{"durations"}, the lengths of the estimation
## and validation records in s (default [60 40]); @code{"trace"}, false to
## skip @code{residtrace} even when it is on the path (it takes minutes on
## these 1 kHz records).
##
## Writes to @var{outdir} (default "results"): fig_throttle_friction.png
## and throttle_friction.md; returns a struct with the numbers.
## @end deftypefn

function res = demo_throttle_friction (outdir = "results", varargin)
  here = demo_prepare (outdir);
  opts = struct ("levels", [1e-8, 1e-3], "durations", [60 40], "trace", true);
  for k = 1:2:numel (varargin)
    opts.(varargin{k}) = varargin{k+1};
  endfor
  t_all = tic;
  Ts = 1e-3;
  use_trace = opts.trace && exist ("residtrace") > 0;
  for c = 1:numel (opts.levels)
    res.case(c) = trace_case (opts.levels(c), Ts, c == 1, outdir,
                              opts.durations, use_trace);
  endfor
  res.has_residtrace = exist ("residtrace") > 0;
  res.traced = use_trace;
  res.elapsed = toc (t_all);
  write_table (fullfile (outdir, "throttle_friction.md"), res);
  for c = 1:numel (res.case)
    k = res.case(c);
    printf ("throttle friction, noise variance %g: validation RMSE %.4f rad ",
            k.noisevar, k.rmse_linear);
    printf ("(linear), %.4f (+ sign(omega), true omega), %.4f (SVF omega); ",
            k.rmse_oracle, k.rmse_svf);
    printf ("Mc estimate %.4f / %.4f (true 0.008)\n", k.mc_oracle, k.mc_svf);
    printf ("  residtrace: %s\n", k.trace_text);
  endfor
  printf ("  %.1f s in all\n", res.elapsed);
endfunction

function k = trace_case (noisevar, Ts, plot_it, outdir, durations, use_trace)
  est = record (durations(1), 4, [30 60], 45, 11, noisevar, Ts);
  val = record (durations(2), 3, [35 65], 40, 12, noisevar, Ts);
  p = est.params;
  [data, dev_e] = deviations (est);
  [datav, dev_v] = deviations (val);
  M = srivc (data, [1 2 0], "lambda", 10);
  [yh, info] = comparec (datav, M);
  fit = info.Fit;
  rmse = info.RMSE;

  ## Answer key: the missing term of (4.17) as a second input.
  lam = 50;
  w_svf_e = svf_derivative (est.phi_m, lam, Ts);
  w_svf_v = svf_derivative (val.phi_m, lam, Ts);
  [Mo, rmse_o, yo] = augmented (data, datav, est.omega, val.omega);
  [Ms, rmse_s] = augmented (data, datav, w_svf_e, w_svf_v);
  mc = @(Ma) -Ma.B{2} / Ma.B{1} * p.Kt * p.Gr;

  k = struct ("noisevar", noisevar, "F", M.F, "B", M.B, "fit", fit,
              "rmse_linear", rmse, "Kb", M.F(2) * p.J, "Ks1", M.F(3) * p.J,
              "KtGr", M.B * p.J, "F_oracle", Mo.F{1}, "rmse_oracle", rmse_o,
              "mc_oracle", mc (Mo), "Kb_o", Mo.F{1}(2) * p.J,
              "Ks1_o", Mo.F{1}(3) * p.J, "KtGr_o", Mo.B{1} * p.J,
              "F_svf", Ms.F{1}, "rmse_svf", rmse_s,
              "mc_svf", mc (Ms), "converged", [Mo.converged, Ms.converged],
              "reversals", sum (diff (sign (est.omega)) != 0),
              "stuck", mean (est.omega == 0), "effect", "", "ranking", [],
              "rmse_before", NaN, "rmse_after", NaN,
              "trace_text", "residtrace is not on the path");
  if (exist ("residtrace") > 0 && ! use_trace)
    k.trace_text = "not called (option trace = false)";
  endif
  if (use_trace)
    try
      R = residtrace (data, M, "validation", datav);
      k.effect = R.effect;
      k.ranking = R.ranking;
      k.rmse_before = R.rmse_before;
      k.rmse_after = R.rmse_after;
      k.trace_text = sprintf ("top effect '%s', validation RMSE %.4g -> %.4g",
                              R.effect, R.rmse_before, R.rmse_after);
    catch err
      k.trace_text = sprintf ("residtrace failed: %s", err.message);
    end_try_catch
  endif

  if (plot_it)
    deg = 180 / pi;
    t = val.t;
    resid = (datav.y - yh) * deg;
    marks = sign (val.omega) * max (abs (resid));
    throttle_plot_panels (fullfile (outdir, "fig_throttle_friction.png"), t,
      5,
      {struct("series", {{datav.y * deg, yh * deg, yo * deg}},
              "labels", {{"measured", "linear model", "+ sign(omega)"}},
              "ylabel", "phi - phi_0 (deg)",
              "title", sprintf (["Validation record, noise variance %g: ", ...
                                 "the linear model without friction and ", ...
                                 "with the Coulomb term of (4.17)"],
                                noisevar)),
       struct("series", {{resid, marks}},
              "labels", {{"residual, linear model", "sign(omega), scaled"}},
              "ylabel", "deg")});
  endif
endfunction

function sim = record (duration, period, range, start, seed, noisevar, Ts)
  ## Rest at `start` degrees for 1 s, then a triangle wave over `range`
  ## starting at `start` and rising.
  t = (0:round (duration / Ts))' * Ts;
  lo = range(1); hi = range(2);
  phase = (start - lo) / (hi - lo) * period / 2;
  s = mod (t - 1 + phase, period) / period;
  tri = lo + (hi - lo) * (1 - abs (2 * s - 1));
  phi_d = start * ones (size (t));
  phi_d(t >= 1) = tri(t >= 1);
  randn ("state", seed);
  sim = throttlesim (phi_d * pi / 180, Ts, "R", 1.4, "noisevar", noisevar);
endfunction

function [data, dev] = deviations (sim)
  k0 = 1:round (0.5 / sim.Ts);
  dev = [mean(sim.phi_m(k0)), mean(sim.i(k0))];
  data = iddata (sim.phi_m - dev(1), sim.i - dev(2), sim.Ts,
                 "InterSample", "zoh");
endfunction

function w = svf_derivative (y, lam, Ts)
  ## lam^2 p / (p + lam)^2 applied to y - y(1), by the bilinear map.
  y = y - y(1);
  a = lam * Ts / 2;
  num = lam ^ 2 * (Ts / 2) * conv ([1 -1], [1 1]) / (1 + a) ^ 2;
  den = conv ([1, -(1 - a) / (1 + a)], [1, -(1 - a) / (1 + a)]);
  w = filter (num, den, y);
endfunction

function [Ma, rmse, yh] = augmented (data, datav, w_e, w_v)
  ## Non-convergence is reported in the table (Ma.converged).
  warning ("off", "srivc:notConverged", "local");
  Ts = data.Ts;
  de = iddata (data.y, [data.u, sign(w_e)], Ts, "InterSample", "zoh");
  dv = iddata (datav.y, [datav.u, sign(w_v)], Ts, "InterSample", "zoh");
  Ma = srivc (de, [1 1 2 0 0], "lambda", 10);
  [yh, info] = comparec (dv, Ma);
  rmse = info.RMSE;
endfunction

function write_table (file, res)
  fid = fopen (file, "w");
  fprintf (fid, ["## Throttle: the Coulomb friction hidden from a linear ", ...
                 "model\n\n"]);
  fprintf (fid, ["Estimation and validation records of the throttle loop ", ...
                 "(R = 1.4 Ohm, triangle-wave set points inside (4.16)); ", ...
                 "the linear model b / (p^2 + a1 p + a2) from the current ", ...
                 "to the angle (eq. 4.17 without sign(omega)), fitted by ", ...
                 "`srivc` on deviations from the initial rest state. ", ...
                 "Answer key: the same with sign(omega) as a second input ", ...
                 "(true omega, or omega from an SVF derivative of phi_m). ", ...
                 "True values: Kb = 4.98e-3, Ks1 = 0.1049, ", ...
                 "Kt Gr = 0.2456, Mc = 8e-3. %.1f s in all.\n\n"],
           res.elapsed);
  fprintf (fid, ["| noise variance (rad^2) | sign(omega) changes / stuck ", ...
                 "share (est.) | linear model: Kb / Ks1 / Kt Gr | ", ...
                 "validation RMSE (rad), linear | + sign(omega), true ", ...
                 "omega: RMSE / Mc | its Kb / Ks1 / Kt Gr | ", ...
                 "+ sign(omega), SVF omega: RMSE / Mc | residtrace |\n", ...
                 "|---|---|---|---|---|---|---|---|\n"]);
  for c = 1:numel (res.case)
    k = res.case(c);
    fprintf (fid, ["| %g | %d / %.3f | %.4f / %.4f / %.4f | %.4f | ", ...
                   "%.4f / %.4f | %.4f / %.4f / %.4f | %.4f / %.4f | ", ...
                   "%s |\n"],
             k.noisevar, k.reversals, k.stuck, k.Kb, k.Ks1, k.KtGr,
             k.rmse_linear, k.rmse_oracle, k.mc_oracle, k.Kb_o, k.Ks1_o,
             k.KtGr_o, k.rmse_svf, k.mc_svf, k.trace_text);
  endfor
  fprintf (fid, "\n");
  for c = 1:numel (res.case)
    k = res.case(c);
    if (! all (k.converged))
      fprintf (fid, ["At noise variance %g SRIVC did not converge in 20 ", ...
                     "iterations for the model with sign(omega) (%s ", ...
                     "omega); the last iterate is shown.\n\n"],
               k.noisevar, ch2_ifelse_str (! k.converged(1), "true", "SVF"));
    endif
  endfor
  if (res.has_residtrace && ! res.traced)
    fprintf (fid, "`residtrace` was not called (option trace = false).\n");
  elseif (! res.has_residtrace)
    fprintf (fid, ["`residtrace` is not on the path: ", ...
                   "the records, the model without friction and the ", ...
                   "answer key are ready, and the call ", ...
                   "`R = residtrace (data, M, \"validation\", datav)` is ", ...
                   "made as soon as it exists; it should report ", ...
                   "R.effect = \"coulomb\".\n"]);
  else
    found = strcmp (res.case(1).effect, "coulomb");
    fprintf (fid, ["At noise variance %g `residtrace` %s the Coulomb ", ...
                   "friction (top effect '%s').\n"], res.case(1).noisevar,
             ch2_ifelse_str (found, "**finds**", "**does not find**"),
             res.case(1).effect);
  endif
  fclose (fid);
endfunction
