## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn {} {} test_residtrace_model ()
## The model @code{residtrace} returns (@code{idtraced}) with the
## toolbox's ordinary functions:
## @itemize
## @item an output that saturates: @code{comparec}, @code{simc},
## and @code{sim} of @code{R.final_model} on the
## validation record give @code{R.rmse_final} to 1e-6 relative
## (@code{R.model}: @code{R.rmse_after}), as @code{residtrace_sim} does;
## the simulated output equals the linear part simulated by the control
## package (c2d, lsim) and clipped at the saturation levels written here,
## to 1e-8 of the output's range; @code{comparec} without outputs prints
## the same fit; @code{present} shows the saturation;
## @item a raw record (input about 2 V, output about 3 V) with a
## saturation: the model carries the levels (fit above 80 %, where its
## linear part alone, without them, is below -100 %) and its output is
## c + sat (G (u - u0)) with G, c, u0 and the levels read from it, by
## lsim;
## @item a record split into estimation and validation parts, with a
## saturation and with a sinusoid (whose amplitude and phase are fitted on
## the record): @code{comparec} on the whole record over samples npre+1
## onward gives @code{R.rmse_final};
## @item options the model does not take are identified errors.
## @end itemize
## @end deftypefn

function test_residtrace_model ()
  pkg load control
  Ts = 0.05; u = prbs (9, 4); N = numel (u);
  uv = circshift (u, 200);
  G = idctm (2, [1 1.2 1]);

  ## an output that saturates
  randn ("state", 16);
  y = min (simc (G, u, Ts), 0.4) + 0.03 * randn (N, 1);
  yv = min (simc (G, uv, Ts), 0.4) + 0.03 * randn (N, 1);
  d = iddata (y, u, Ts); dv = iddata (yv, uv, Ts);
  R = residtrace (d, srivc (d, [1 2 0]), "validation", dv,
                  "effects", {"saturation", "offset"}, "iterate", 2);
  assert (R.effect, "saturation");
  M = R.final_model;
  assert (isa (M, "idtraced"));
  assert (isa (M.linear, "idpoly"));
  tol = 1e-6 * R.rmse_final;
  [ys, info] = comparec (dv, M);
  assert (info.RMSE, R.rmse_final, tol);
  assert (sqrt (mean ((yv - simc (M, dv)) .^ 2)), R.rmse_final, tol);
  assert (sqrt (mean ((yv - simc (M, uv, Ts)) .^ 2)), R.rmse_final, tol);
  ysim = get (sim (M, dv), "OutputData");
  assert (sqrt (mean ((yv - ysim) .^ 2)), R.rmse_final, tol);
  [~, ~, r] = residtrace_sim (R, dv);
  assert (r, R.rmse_final, tol);
  [~, info] = comparec (dv, R.model);
  assert (info.RMSE, R.rmse_after, 1e-6 * R.rmse_after);
  ## independent: the linear part by the control package, then clipped
  yind = independent (M, uv, Ts);
  assert (ys, yind, 1e-8 * (max (yv) - min (yv)));
  assert (any (ys >= max (ys) - 1e-12 & ys > 0.35));   # the clip is active
  ## the printed figure and the plot (no window: off-screen)
  warning ("off", "Octave:gnuplot-graphics", "local");
  h = figure ("visible", "off");
  out = evalc ("comparec (dv, M)");
  close (h);
  assert (! isempty (strfind (out, sprintf ("fit = %.2f %%", info.Fit))));
  t = present (M);
  assert (! isempty (strfind (t, "effects added: saturation")));
  assert (! isempty (strfind (t, "output saturation")));

  ## a raw record: levels of several volts, carried by the model
  randn ("state", 21);
  y = 3 + max (simc (G, u - u(1), Ts), -2.4) + 0.02 * randn (N, 1);
  yv = 3 + max (simc (G, uv - u(1), Ts), -2.4) + 0.02 * randn (N, 1);
  d = iddata (y, u + 2, Ts); dv = iddata (yv, uv + 2, Ts);
  R = residtrace (d, srivc (d, [1 2 0]), "validation", dv,
                  "effects", {"saturation", "offset"}, "iterate", 1);
  assert (R.levels.estimated);
  M = R.final_model;
  assert (abs (M.u0) > 1);
  [ys, info] = comparec (dv, M);
  assert (info.RMSE, R.rmse_final, 1e-6 * R.rmse_final);
  assert (info.Fit > 80);
  [~, lin] = comparec (dv, M.linear);   # the linear part has no levels
  assert (lin.Fit < -100);
  assert (ys, independent (M, uv + 2, Ts), 1e-8 * (max (yv) - min (yv)));
  t = present (M);
  assert (! isempty (strfind (t, sprintf ("input level u0 = %.5g", M.u0))));

  ## a split record: the figure on the samples after the estimation part
  randn ("state", 22);
  y = min (simc (G, u, Ts), 0.4) + 0.03 * randn (N, 1);
  d = iddata (y, u, Ts);
  R = residtrace (d, G, "effects", {"saturation", "offset"}, "iterate", 1);
  M = R.final_model;
  assert (M.npre > 0);
  [ys, info] = comparec (d, M, M.npre+1:N);
  assert (numel (ys), N - M.npre);
  assert (info.RMSE, R.rmse_final, 1e-6 * R.rmse_final);
  ## with a sinusoid, whose amplitude and phase are fitted on the record
  ## (each half of the validation part applied to the other)
  randn ("state", 22);
  y = simc (G, u, Ts) + 0.2 * sin (0.9 * (0:N-1)' * Ts) ...
      + 0.03 * randn (N, 1);
  d = iddata (y, u, Ts);
  R = residtrace (d, G, "effects", {"sinusoid", "delay"}, "iterate", 1);
  assert (R.effect, "sinusoid");
  M = R.final_model;
  [~, info] = comparec (d, M, M.npre+1:N);
  assert (info.RMSE, R.rmse_final, 1e-6 * R.rmse_final);

  ## what the model does not take
  fails (@() comparec (dv, M, "InitialCondition", "e"),
         "comparec:notSupported");
  fails (@() comparec (dv, M, "Levels", "ignore"), "comparec:notSupported");
  fails (@() simc (M, uv, Ts, "SNR", 10), "simc:notSupported");
  fails (@() simc (M, uv, 2 * Ts), "simc:badInput");
  fails (@() simc (M, [uv uv], Ts), "simc:dimensionMismatch");
endfunction

## The model's output written out: each input channel's B/F simulated by
## the control package (exact ZOH: c2d, lsim) on the input less M.u0,
## delayed by its nk samples, the output level added, then the
## saturation. Only the terms these records give (input channels, an
## output level, a saturation) are written.
function y = independent (M, u, Ts)
  N = rows (u);
  t = (0:N-1)' * Ts;
  x = zeros (N, 1);
  ch = M.channels;
  for j = 1:numel (ch)
    assert (ch(j).type, "input");
    w = u(:, ch(j).col) - M.u0(ch(j).col);
    w = [zeros(ch(j).nk, 1); w(1:end-ch(j).nk)];
    x += lsim (c2d (tf (ch(j).B, M.F), Ts), w, t);
  endfor
  out = M.out;
  lo = -Inf; hi = Inf;
  for k = 1:numel (out)
    switch (out(k).type)
      case "offset"
        x += out(k).c(1);
      case "sat"
        lo = out(k).c(1); hi = out(k).c(2);
      otherwise
        error ("test_residtrace_model: an output term '%s'", out(k).type);
    endswitch
  endfor
  assert (isempty (M.phys));
  y = min (max (x, lo), hi);
endfunction

function fails (f, id)
  try
    f ();
  catch err
    assert (err.identifier, id);
    return;
  end_try_catch
  error ("test_residtrace_model: no error %s", id);
endfunction
