## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn {} {@var{c} =} residtrace_cand_colored (@var{cur}, @var{ctx})
## Coloured-noise candidate of @code{residtrace}: an AR noise model
## A(q) e = eps for the residual (order <= 20 by BIC, least squares on the
## estimation residual; the AR fit of the core, core/include/ctid/apps/
## residtrace/statistics.hpp). A noise model does not change the simulated
## output: its validation output is the one-step-ahead prediction of y
## (model output plus the predicted residual from the past validation
## residuals), so its "after" RMSE is a prediction RMSE, not a simulation
## RMSE, and it ranks after every significant deterministic effect.
## Evidence: the AR order and the dominant pole, the lag-1
## autocorrelation of the residual.
## @end deftypefn

function c = residtrace_cand_colored (cur, ctx)
  c = residtrace_cand ("colored_noise");
  c.kind = "prediction";
  e = cur.e_est - mean (cur.e_est);
  N = numel (e);
  pmax = min (20, floor (N / 20));
  if (pmax < 1)
    c.reason = "too few samples for a noise model";
    return;
  endif
  a = effect_sim_mex ("residtrace", "ar", e(:), struct ("pmax", pmax));
  p_best = numel (a) - 1;
  if (p_best == 0)
    c.reason = "an AR model does not improve on white noise (BIC)";
    return;
  endif
  c.applicable = true;
  c.model = cur;
  c.model.noise = a;
  c.variant = sprintf ("AR(%d)", p_best);
  c.nadd = p_best;
  r1 = sum (e(2:end) .* e(1:end-1)) / sum (e .^ 2);
  pl = roots (a);
  [~, i] = max (abs (pl));
  c.evidence = struct ("term", "AR order", "value", p_best, "std", NaN,
                       "rho1", r1, "pole", pl(i),
                       "text", sprintf (["AR(%d) noise model, dominant ", ...
                                         "pole %s, lag-1 autocorrelation ", ...
                                         "%.2f"], p_best, num2str (pl(i), 3),
                                        r1));
endfunction
