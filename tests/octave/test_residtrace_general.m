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
## figures are finite and computed on the present samples;
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

## A biproper model (numerator of the denominator's degree): every
## candidate, the Coulomb, drift and state candidates included, ends in a
## verdict; the simulations keep the direct feedthrough.
function biproper (u, uv, Ts, N)
  Gb = idpoly (1, [0.5 1 2], 1, 1, [1 1.2 1], "Ts", 0);
  y = simc (Gb, u, Ts) + 0.02 * randn (N, 1);
  yv = simc (Gb, uv, Ts) + 0.02 * randn (N, 1);
  R = residtrace (iddata (y, u, Ts), Gb, "validation", iddata (yv, uv, Ts),
                  "iterate", 1, "effects", {"coulomb", "drift",
                                            "state_nonlinearity", "offset"});
  assert (R.rmse_given < 0.03);                # the feedthrough is kept
  assert (R.rmse_before < 0.03);
  for r = R.ranking(:).'
    assert (r.applicable || ! isempty (r.reason), r.effect);
    assert (isempty (strfind (r.reason, "index")), r.reason);
    assert (isempty (strfind (r.reason, "out of bound")), r.reason);
  endfor
  printf ("biproper: %s\n", R.verdict);
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
  y(300:320) = NaN; yv(500:505) = NaN;
  M = srivc (iddata (y, u, Ts), [1 2 0]);
  R = residtrace (iddata (y, u, Ts), M, "validation", iddata (yv, uv, Ts),
                  "effects", {"offset", "delay"}, "iterate", 1);
  assert (isfinite (R.rmse_before) && isfinite (R.rmse_after));
  assert (R.effect, "offset");
  assert (R.rmse_after, 0.05, 0.01);
  assert (R.missing.validation, isnan (yv));
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
