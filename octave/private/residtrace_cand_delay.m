## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn {} {@var{c} =} residtrace_cand_delay (@var{cur}, @var{ctx})
## Input-delay candidate of @code{residtrace}: the delay nk of an input
## channel raised by 1 .. @code{ctx.opts.maxdelay} samples. Every delay is
## screened with three SRIVC iterations from the current model, the two
## best are iterated to convergence from their screening estimates and
## the one with the smallest BIC on the estimation data is kept. Evidence: the chosen delay (samples and
## seconds) and the lag at which the prewhitened cross-correlation of the
## current residual with the input peaks.
## @end deftypefn

function c = residtrace_cand_delay (cur, ctx)
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
  nk = best.channels(bj).nk;
  c.variant = sprintf ("nk = %d on %s", nk, best.channels(bj).name);
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
                       "text", sprintf (["delay nk = %d samples (%.4g s, ", ...
                                         "+%d); residual-input ", ...
                                         "cross-correlation peaks at lag ", ...
                                         "%d"],
                                        nk, nk * ctx.D.Ts, bd, peak));
endfunction
