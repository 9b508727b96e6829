## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn {} {@var{c} =} residtrace_cand_saturation (@var{cur}, @var{ctx})
## Saturation candidate of @code{residtrace}: a level that a signal of the
## system cannot pass, with the level(s) estimated.
## @itemize
## @item Output saturation (a sensor range, a position at its end stop):
## y = min (max (x, lo), hi), x the model output; upper, lower or both
## levels. Fitted as censored data (@code{residtrace_fit}): where the
## model output lies beyond a level the sample tells nothing about the
## linear part.
## @item Saturation of an inner state (a tank that overflows, a valve at
## its end stop): the model's denominator is split into its first-order
## sections (real poles, complex pairs), F = F_a F_b; the node z =
## F_a(0)/F_a(p) u (static gain 1, so its level is in input units) is
## clipped, and y = B(p)/F_b(p) clip(z) is re-estimated by SRIVC. Every
## split of the sections into upstream F_a and downstream F_b is tried
## (models of at most four sections, no integrators, open loop). The
## input itself (F_a = 1) is the static nonlinearity's clipped input.
## @end itemize
## Levels: for each variant, the level minimising the squared error of the
## current model with the clip (its gain refitted by least squares) on a
## grid of 25 quantiles of the clipped signal (between its median and its
## maximum, resp. minimum), refined by a golden-section search between the
## grid neighbours; the side (upper, lower, both) by the BIC of
## this screening. Each node's variant and the output's are then fitted
## and the one with the smallest BIC on the estimation data is kept; its
## level is searched again with the fitted model (the gain refitted with
## each level), and the model fitted again, while the BIC falls (at most
## three rounds). Evidence: the
## level(s), the share of samples at a level, the node's poles.
## @itemize
## @item An end stop: the output is a position, a state of the
## model's realisation (observable canonical form, x1 = y, the velocity
## a state when every channel's relative degree is at least two), held
## at a level with its velocity reset to zero while the model pushes it
## into the stop (@code{residtrace_physsim}, kind "stop").
## @item An inner state of a two-section cascade that overflows (a tank
## cascade): z' = b u + d - alpha g(z), z <= h, y = c + x with x' = g(z)
## - gamma g(x), g a square root (Torricelli) or linear, a share of the
## overflow falling into the outer section; and the same with the outer
## state limited too (y <= yhi: both tanks overflow)
## (@code{residtrace_physcascade}).
## @end itemize
## These two are fitted on their simulation error, all their parameters
## and levels together (@code{residtrace_physfit}), and compared with the
## other variants by the same BIC. A cascade whose inner state sits at its
## level on more than half of the estimation samples is dropped: that is
## not an overflow but another structure (the inner section held full
## and its spill feeding the outer one: a single tank).
## The candidate is built and fitted in the core
## (core/include/ctid/apps/residtrace/candidate_saturation.hpp,
## saturation_candidate, through @code{effect_sim_mex}, method
## "candidate").
## @end deftypefn

function c = residtrace_cand_saturation (cur, ctx)
  c = effect_sim_mex ("residtrace", "candidate", "saturation", cur, ctx.D,
                     residtrace_fitopts (ctx));
endfunction
