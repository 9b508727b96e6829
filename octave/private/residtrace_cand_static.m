## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn {} {@var{c} =} residtrace_cand_static (@var{cur}, @var{ctx})
## Static-nonlinearity candidate of @code{residtrace}. Variants:
## @itemize
## @item on an input (Hammerstein): extra channels u^2, u^3 or both, or
## the input clipped to +-c (with the input's own channel this is a
## saturation or a dead zone; c at the 30, 50, 70, 85 and 95 %
## quantiles of |u|), each channel with as many numerator coefficients as
## the input's own; the best level is then refined between its grid
## neighbours by a golden-section search of the BIC. Not with an input of
## two levels only, through which
## every static map is affine. The polynomial u + a2 u^2 + a3 u^3 of a
## model that is only B(p)/F(p) u (one input, nb >= 2, no fixed
## coefficient, output term or initial state) is a Hammerstein model,
## B_k = a_k B: it is estimated by @code{hsrivc} (Laurain et al., the
## products separated with their covariance), which uses 2 nb - 2 fewer
## parameters than the unconstrained channels and predicts better
## (validation RMSE 0.35 against 0.46, 10 of 10 simulated runs); with
## nb = 1 the two structures coincide and the channels are fitted as
## such.
## @item on the output (Wiener): y = x + c2 x^2 + c3 x^3 with x the model
## output, by alternation with SRIVC.
## @end itemize
## (A nonlinearity of the output inside the dynamics is the effect
## 'state_nonlinearity', @code{residtrace_cand_state}.)
## The variant with the smallest BIC on the estimation data is kept.
## Evidence: the fitted coefficients with their standard deviations and
## the size of the nonlinear part (its RMS over that of the model output).
## The core does it: core/include/ctid/apps/residtrace/candidate_static.hpp.
## @end deftypefn

function c = residtrace_cand_static (cur, ctx)
  c = effect_sim_mex ("residtrace", "candidate", "static_nonlinearity", cur,
                      ctx.D, residtrace_fitopts (ctx));
endfunction
