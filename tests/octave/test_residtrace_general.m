## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn {} {} test_residtrace_general ()
## What residtrace must do on any record, whatever the effect:
## @itemize
## @item inputs it cannot use end in an identified error or a verdict,
## never in an index error: a biproper model (every candidate gives a
## verdict: tested, or not applicable with a reason), a model without an
## input, a constant output (named as the culprit, not the input);
## @item an unstable model as given is reported as such in the verdict,
## with no figure for its diverging simulation (NaN, not 1e146);
## @item missing samples (NaN) are bridged as srivc bridges them: the
## effect and the figures are those of the complete records within 5 %,
## computed on the present samples;
## @item the acceptance check (@file{octave/private/residtrace_accept.m},
## its own inline tests): an undetermined term, a saturation active on
## every sample, a friction without velocity reversals are rejected;
## @item the levels a given model carries (Report.DataUsed) are kept by
## the baseline: no offset is found that only restores them, and the
## baseline is not worse than M as given;
## @item the reproduction of the final figure by @code{residtrace_sim}
## and the figure of @code{residtrace_plot} are the inline tests of those
## functions.
## @end itemize
## @example
## octave --no-gui -q --eval \
##   "addpath tests/octave; test_residtrace_general"
## @end example
## @end deftypefn

function test_residtrace_general ()
  ctid_run_private_tests ("residtrace_accept.m");
  randn ("state", 31); rand ("state", 31);
  Ts = 0.05; u = prbs (9, 4); N = numel (u); uv = circshift (u, 200);
  G = idctm (2, [1 1.2 1]);
  x = simc (G, u, Ts); xv = simc (G, uv, Ts);
  biproper (u, uv, Ts, N);
  no_input (x, u, Ts);
  constant_output (u, Ts, N);
  unstable (x, u, Ts, N);
  carried_levels (u, uv, G, Ts, N);
  missing (x, xv, u, uv, Ts, N);
endfunction

## A biproper model (numerator of the denominator's degree) of a
## mass-spring-damper with Coulomb friction: every candidate, the Coulomb,
## drift and state candidates included, ends in a verdict (tested, or not
## applicable with a reason), never in an index error.
function biproper (u, uv, Ts, N)
  Tf = 0.02; Nf = 2000; t = (0:Nf-1)' * Tf;
  U = [sin(1.3 * t) + 0.5 * sin(3.1 * t + 1), ...
       sin(1.1 * t + 2) + 0.6 * sin(2.7 * t)];
  A = [0 1; -4 -0.8]; E = expm ([A, [0; 1]; 0 0 0] * Tf / 20);
  Y = zeros (Nf, 2);
  for j = 1:2
    z = [0; 0];
    for k = 1:Nf
      Y(k, j) = z(1);
      for s = 1:20
        z = E(1:2, 1:2) * z + E(1:2, 3) * (U(k, j) - 0.3 * sign (z(2)));
      endfor
    endfor
  endfor
  Y += 0.005 * randn (Nf, 2);
  Mb = idpoly (1, [0.01 0.02 1], 1, 1, [1 0.8 4], "Ts", 0);
  R = residtrace (iddata (Y(:, 1), U(:, 1), Tf), Mb, "validation",
                  iddata (Y(:, 2), U(:, 2), Tf), "iterate", 1,
                  "effects", {"coulomb", "drift", "state_nonlinearity", ...
                              "offset", "saturation"});
  for r = R.ranking(:).'
    assert (r.applicable || ! isempty (r.reason), r.effect);
    assert (isempty (regexp (r.reason, "index|out of bound|subscript",
                             "once")), r.reason);
  endfor
  k = strcmp ({R.ranking.effect}, "coulomb");
  assert (! isempty (strfind (R.ranking(k).reason, "biproper")));
  printf ("biproper: %s\n", R.verdict);
  ## an improper model: an identified error
  try
    residtrace (iddata (Y(:, 1), U(:, 1), Tf),
                idpoly (1, [1 0.01 0.02 1], 1, 1, [1 0.8 4], "Ts", 0));
    error ("test_residtrace_general: an improper model was accepted");
  catch err
    assert (err.identifier, "residtrace:notSupported");
  end_try_catch
endfunction

## A model with no input (an AR polynomial alone): an identified error.
function no_input (x, u, Ts)
  try
    residtrace (iddata (x, u, Ts), idpoly ([1 2.4 4], [], "Ts", 0));
    error ("test_residtrace_general: a model without input was accepted");
  catch err
    assert (err.identifier, "residtrace:badInput");
  end_try_catch
endfunction

## A constant output: the output is named, not the input.
function constant_output (u, Ts, N)
  try
    residtrace (iddata (3 * ones (N, 1), u, Ts), idctm (2, [1 1.2 1]));
    error ("test_residtrace_general: a constant output was accepted");
  catch err
    assert (err.identifier, "residtrace:badInput");
    assert (! isempty (strfind (err.message, "output")), err.message);
    assert (isempty (strfind (err.message, "input excite")), err.message);
  end_try_catch
endfunction

## An unstable model as given: said in the verdict, no absurd figure.
function unstable (x, u, Ts, N)
  y = x + 0.05 * randn (N, 1);
  for F = {[1 -0.5 1], [1 -30 1]}
    R = residtrace (iddata (y, u, Ts), idctm (2, F{1}), "effects", {"offset"});
    assert (R.given_unstable);
    assert (isnan (R.rmse_given));
    assert (strncmp (R.verdict, "the given model is unstable", 27), R.verdict);
    assert (R.rmse_before < 0.1);
    assert (isempty (regexp (R.table, '\de\+(\d{3}|[1-9]\d)', "once")));
  endfor
endfunction

## Missing samples in both records: bridged (the figures are those of
## the present samples: the noise level), as srivc bridges them.
function missing (x, xv, u, uv, Ts, N)
  y = x + 0.3 + 0.05 * randn (N, 1);
  yv = xv + 0.3 + 0.05 * randn (N, 1);
  R0 = residtrace (iddata (y, u, Ts), idctm (2, [1 1.2 1]), "validation",
                   iddata (yv, uv, Ts), "effects", {"offset", "delay"},
                   "iterate", 1);
  y(300:320) = NaN; yv(500:505) = NaN;
  M = srivc (iddata (y, u, Ts), [1 2 0]);      # srivc bridges the gap
  assert (all (isfinite (M.F)));
  R = residtrace (iddata (y, u, Ts), idctm (2, [1 1.2 1]), "validation",
                  iddata (yv, uv, Ts), "effects", {"offset", "delay"},
                  "iterate", 1);
  printf ("missing samples: %s, %.4g -> %.4g\n", R.effect, R.rmse_before,
          R.rmse_after);
  assert (isfinite (R.rmse_before) && isfinite (R.rmse_after));
  ## as on the complete records (the same effect, figures within 5 %)
  assert (R.effect, R0.effect);
  assert (R.rmse_before, R0.rmse_before, 0.05 * R0.rmse_before);
  assert (R.rmse_after, R0.rmse_after, 0.05 * R0.rmse_after);
  assert (R.missing.validation, isnan (yv));
  ## the figure is over the present samples: residtrace_sim agrees, and
  ## its error is zero at the missing ones
  [~, e, r] = residtrace_sim (R, iddata (yv, uv, Ts));
  assert (r, R.rmse_final, 1e-6 * R.rmse_final);
  assert (all (e(isnan (yv)) == 0));
  assert (r, sqrt (mean (e(! isnan (yv)) .^ 2)), 1e-12);
endfunction

## A model that carries its levels (estimated on a raw record, its
## Report.DataUsed says so) on a record whose levels the rules on the
## data alone would not see: the baseline keeps them.
function carried_levels (u, uv, G, Ts, N)
  y = 1.5 + simc (G, u - 0.4, Ts) + 0.05 * randn (N, 1);
  yv = 1.5 + simc (G, uv - 0.4, Ts) + 0.05 * randn (N, 1);
  Mt = G;
  r = get (Mt, "Report");
  r.DataUsed.OutputOffset = 1.5;
  r.DataUsed.InputOffset = 0.4;
  Mt.Report = r;
  R = residtrace (iddata (y, u, Ts), Mt, "validation", iddata (yv, uv, Ts),
                  "effects", {"offset", "delay"}, "iterate", 1);
  printf ("carried levels: given %.4g, before %.4g, %s\n", R.rmse_given,
          R.rmse_before, R.effect);
  assert (R.rmse_given < 0.06);
  assert (R.rmse_before < 1.2 * R.rmse_given);
  assert (R.effect, "none");
endfunction
