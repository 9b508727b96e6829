## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn {} {@var{c} =} residtrace_cand_delay (@var{cur}, @var{ctx})
## Input-delay candidate of @code{residtrace}: the delay nk of an input
## channel raised by 1 .. @code{ctx.opts.maxdelay} samples. Every delay is
## screened with three SRIVC iterations from the current model, the two
## best are iterated to convergence from their screening estimates and
## the one with the smallest BIC on the estimation data is kept. A
## transport delay need not be a whole number of samples: the delay is
## then refined continuously between its neighbours (nk - 1, nk + 1),
## the fraction f of a sample entering as the held input delayed by f
## (@code{residtrace_channels}), by a golden-section search of the BIC,
## each delay screened with three SRIVC iterations, the best one iterated
## to convergence; it replaces the whole number when its BIC is lower by
## more than log N (the fraction counted as one more parameter), so that
## a delay of whole samples stays one. (Not in a closed loop, whose
## controlled input is formed sample by sample, nor in a physical
## realisation.) An extra pole or zero mimics a delay that is rounded to
## whole samples; with its fraction the delay is compared with the order
## candidate on the same footing. Evidence: the chosen delay (samples and
## seconds) and the lag at which the prewhitened cross-correlation of the
## current residual with the input peaks.
## A model with a physical realisation (an end stop or a tank cascade) is
## refitted by its own simulation error at each whole delay, without the
## fraction. The candidate is fitted in the core
## (core/include/ctid/apps/residtrace/candidate_delay.hpp, delay_candidate,
## through @code{effect_sim_mex}, method "candidate").
## @end deftypefn

function c = residtrace_cand_delay (cur, ctx)
  o = residtrace_fitopts (ctx);
  o.maxdelay = ctx.opts.maxdelay;
  o.maxlag = ctx.opts.maxlag;
  c = effect_sim_mex ("residtrace", "candidate", "delay", cur, ctx.D, o);
endfunction
