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
## The candidate is fitted in the core
## (core/include/ctid/apps/residtrace/candidate_colored.hpp,
## colored_candidate, through @code{effect_sim_mex}, method "candidate").
## @end deftypefn

function c = residtrace_cand_colored (cur, ctx)
  o = residtrace_fitopts (ctx);
  c = effect_sim_mex ("residtrace", "candidate", "colored_noise", cur, ctx.D,
                     o);
endfunction
