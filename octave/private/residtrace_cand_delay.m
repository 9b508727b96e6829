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
## The candidate is fitted in the core
## (core/include/ctid/apps/residtrace/candidate_delay.hpp, delay_candidate,
## through @code{effect_sim_mex}, method "candidate"), except for a
## physical realisation (its fit, @code{residtrace_physfit}, is not a
## function of the core yet): its whole delays are searched here, without
## the fraction.
## @end deftypefn

function c = residtrace_cand_delay (cur, ctx)
  if (isfield (cur, "phys") && ! isempty (cur.phys))
    c = physical_delay (cur, ctx);
    return;
  endif
  o = residtrace_fitopts (ctx);
  o.maxdelay = ctx.opts.maxdelay;
  o.maxlag = ctx.opts.maxlag;
  c = effect_sim_mex ("residtrace", "candidate", "delay", cur, ctx.D, o);
endfunction

## The delay of a physical realisation: each whole delay fitted by
## residtrace_fit (the realisation's own fit), as in the core's
## delay_candidate without the fraction of a sample.
function c = physical_delay (cur, ctx)
  c = residtrace_cand ("delay");
  D = ctx.opts.maxdelay;
  cols = find (strcmp ({cur.channels.type}, "input"));
  if (D < 1 || isempty (cols))
    c.reason = "no delay to try";
    return;
  endif
  quick = ctx;
  quick.maxiter = max (1, min (3, floor (ctx.maxiter / 3)));
  trials = [];
  fits = {};
  for j = cols
    for dd = 1:D
      t = cur;
      t.channels(j).nk += dd;
      m = residtrace_fit (t, ctx.D, quick, {cur.F});
      if (m.ok)
        trials = [trials; j, dd, m.bic];
        fits{end+1} = m;
      endif
    endfor
  endfor
  if (isempty (trials))
    c.reason = "the estimation failed";
    c.failed = true;
    return;
  endif
  [~, order] = sort (trials(:, 3));
  best = [];
  for i = order(1:min (2, end))'
    j = trials(i, 1);
    m = residtrace_fit (fits{i}, ctx.D, ctx, {fits{i}.F});
    if (m.ok && (isempty (best) || m.bic < best.bic))
      best = m;
      bj = j; bd = trials(i, 2);
    endif
  endfor
  if (isempty (best))
    c.reason = "the estimation failed";
    c.failed = true;
    return;
  endif
  c.applicable = true;
  c.model = best;
  nk = best.channels(bj).nk + frac (best.channels(bj));
  if (nk == fix (nk))
    c.variant = sprintf ("nk = %d on %s", nk, best.channels(bj).name);
  else
    c.variant = sprintf ("nk = %.2f on %s", nk, best.channels(bj).name);
  endif
  c.nadd = 1;
  w = residtrace_whiteness (cur.e_est, ctx.D.u(:, cur.channels(bj).col),
                           max (ctx.opts.maxlag, D + 1));
  peak = NaN;
  if (w.testable)
    m = w.maxlag;
    [~, i] = max (abs (w.xcorr(m+1:end, 1)));
    peak = i - 1;
  endif
  c.evidence = struct ("term", "nk", "value", nk, "std", NaN,
                       "physical", nk * ctx.D.Ts, "physical_std", NaN,
                       "xcorr_peak_lag", peak,
                       "text", sprintf (["delay nk = %.4g samples (%.4g s, ", ...
                                         "+%d); residual-input ", ...
                                         "cross-correlation peaks at lag ", ...
                                         "%d"],
                                        nk, nk * ctx.D.Ts, bd, peak));
endfunction

## The fraction of a sample of an input channel's delay (0: whole samples).
function f = frac (ch)
  f = 0;
  if (! isempty (ch.param) && isnumeric (ch.param))
    f = ch.param;
  endif
endfunction
