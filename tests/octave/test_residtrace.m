## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## Undeclared-effect suite of residtrace: on each dataset
## of residtrace_cases (1) the single effect present must rank first and
## cut the validation RMSE, the clean control must give 'none', and the
## evidence must point at the true effect (its size within a tolerance
## set by what the data can tell, not by what the tool returned).
function test_residtrace ()
  cases = residtrace_cases (1);
  failures = {};
  for k = 1:numel (cases)
    c = cases(k);
    R = residtrace (c.data, c.M, "validation", c.datav, "iterate", 1);
    printf (["%-20s -> %-20s RMSE %.4g -> %.4g (tracked %.4g, ", ...
             "prediction %.4g)\n"], c.effect, R.effect, R.rmse_before,
            R.rmse_after, R.rmse_after_tracked, R.rmse_after_prediction);
    if (! strcmp (R.effect, c.effect))
      failures{end+1} = sprintf ("%s: found '%s'", c.effect, R.effect);
      continue;
    endif
    if (strcmp (c.effect, "none"))
      assert (R.rmse_after, R.rmse_before, 0);
      assert (! any ([R.ranking.significant]));
      continue;
    endif
    ## the figure of the effect's own kind: a simulation, or for drift a
    ## simulation with tracked parameters, for coloured noise a prediction
    after = R.rmse_after;
    switch (c.effect)
      case "drift"
        after = R.rmse_after_tracked;
        assert (R.rmse_after, R.rmse_before, 0);   # the simulation: same
      case "colored_noise"
        after = R.rmse_after_prediction;
        assert (R.rmse_after, R.rmse_before, 0);
    endswitch
    if (! (after < 0.8 * R.rmse_before))
      failures{end+1} = sprintf ("%s: RMSE %.4g -> %.4g", c.effect,
                                 R.rmse_before, after);
    endif
    msg = check_evidence (c, R);
    if (! isempty (msg))
      failures{end+1} = sprintf ("%s: %s", c.effect, msg);
    endif
  endfor
  if (! isempty (failures))
    error ("test_residtrace: %s", strjoin (failures, "; "));
  endif
endfunction

## The evidence against the generator's truth. Tolerances: a few standard
## deviations where the tool gives one; for the Coulomb level 15 % (the
## tool's sign(v) regressor uses the SVF velocity of the noisy output, so
## it sees the friction only where v is clearly away from zero); for the
## saturation level 10 % (the BIC of the clipping level is flat near the
## optimum).
function msg = check_evidence (c, R)
  msg = "";
  ev = R.evidence;
  t = c.truth;
  switch (c.effect)
    case "offset"
      if (abs (ev.physical - t.input_offset) > 5 * ev.physical_std + 0.02)
        msg = sprintf ("input offset %.4g, true %.4g", ev.physical,
                       t.input_offset);
      endif
    case "coulomb"
      if (abs (ev.physical - t.coulomb) > 0.15 * t.coulomb)
        msg = sprintf ("Coulomb level %.4g, true %.4g", ev.physical, t.coulomb);
      endif
    case "viscous"
      tol = 5 * ev.physical_std + 0.02 * t.viscous;
      if (abs (ev.physical - t.viscous) > tol)
        msg = sprintf ("viscous %.4g, true %.4g", ev.physical, t.viscous);
      endif
    case "delay"
      if (ev.value != t.nk)
        msg = sprintf ("nk %d, true %d", ev.value, t.nk);
      endif
    case "order"
      p = sort (roots (R.model.F));
      q = sort (roots (t.F));
      if (numel (p) != numel (q) || max (abs (p - q) ./ abs (q)) > 0.05)
        msg = sprintf ("poles %s, true %s", mat2str (p.', 3), mat2str (q.', 3));
      endif
    case "static_nonlinearity"
      lev = R.model.channels(end).param;
      if (! strcmp (R.model.channels(end).type, "clip")
          || abs (lev - t.clip) > 0.1 * t.clip)
        msg = sprintf ("variant %s, true clip level %.3g", R.ranking(1).variant,
                       t.clip);
      endif
    case "sinusoid"
      if (abs (ev.freq_hz - t.freq_hz) > 0.01 * t.freq_hz
          || abs (ev.value - t.amplitude) > 5 * ev.std + 0.02 * t.amplitude)
        msg = sprintf ("line %.4g Hz amplitude %.4g, true %.4g Hz %.4g",
                       ev.freq_hz, ev.value, t.freq_hz, t.amplitude);
      endif
    case "drift"
      if (! (ev.p < 1e-3))
        msg = sprintf ("segment test p = %.2g", ev.p);
      endif
    case "colored_noise"
      if (abs (ev.pole - t.ar) > 0.05)
        msg = sprintf ("AR pole %.3g, true %.3g", ev.pole, t.ar);
      endif
  endswitch
endfunction
