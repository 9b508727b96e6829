## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn {} {@var{c} =} residtrace_cand_drift (@var{cur}, @var{ctx})
## Parameter-drift candidate of @code{residtrace}: time variation that a
## frozen model cannot explain.
##
## Evidence on the estimation record: the model is re-estimated by SRIVC
## on K consecutive segments (K = 4 to 8, at least 40 samples per
## parameter each; the segments after the first with their initial state
## estimated, as they do not start at rest); under a constant parameter vector the statistic
## sum_k (theta_k - theta_bar)' P_k^-1 (theta_k - theta_bar), theta_bar
## the precision-weighted mean, is chi^2 with (K - 1) np degrees of
## freedom; the trend of each parameter over the segments is given with
## its t value. When that test does not reject (p >= alpha) the candidate
## stops there (not applicable, with the test in its reason).
##
## The drifting model has random-walk parameters with a diagonal Qn,
## tracked by the recursive IV estimator with a Kalman filter (thesis eq.
## 2.29). For a single-input model with all of F free and no output terms
## that is @code{rsrivc}, with Qn by maximum likelihood (@code{qnml},
## thesis sec. 3.3) started from the segment spread (increments of
## consecutive segments beyond their estimation variance, per sample, as
## a random walk averaged over a segment would give) within 1e-4 .. 1e4
## times it. For other models (more channels, fixed coefficients, output
## terms) it is @code{residtrace_track}, the same update with the
## prefilter and auxiliary model frozen at the current model, Qn the
## segment shape scaled by maximum likelihood of its innovations on a
## grid 10^(-2..2). Its validation output is the
## simulation of the model with the parameters tracked on the validation
## record, each sample using only the estimates of earlier samples, the
## tracker started where it ended on the estimation record.
## @end deftypefn

function c = residtrace_cand_drift (cur, ctx)
  c = residtrace_cand ("drift");
  c.kind = "tracking";
  if (isfield (cur, "phys") && ! isempty (cur.phys))
    c.reason = "a physical realisation (end stop, cascade) is not tracked";
    return;
  endif
  D = ctx.D;
  N = numel (D.y);
  np = numel (cur.theta);
  K = min (8, floor (N / (40 * max (np, 1))));
  if (K < 3)
    c.reason = sprintf (["%d samples are too few for segment fits ", ...
                         "of %d parameters"], N, np);
    return;
  endif
  L = floor (N / K);
  th = zeros (K, np);
  P = zeros (np, np, K);
  ok = true (K, 1);
  for k = 1:K
    idx = (k - 1) * L + (1:L);
    Dk = slice (D, idx);
    m = residtrace_fit (cur, Dk, setfield (ctx, "keep_order", true),
                        {cur.F});
    if (! m.ok || numel (m.theta) != np)
      ok(k) = false;
      continue;
    endif
    th(k, :) = m.theta(:).';
    P(:, :, k) = m.cov;
  endfor
  if (sum (ok) < 3)
    c.reason = "the segment fits failed";
    c.failed = true;
    return;
  endif
  th = th(ok, :); P = P(:, :, ok); Kk = sum (ok);
  tmid = ((find (ok) - 0.5) * L) * D.Ts;
  Wsum = zeros (np); wth = zeros (np, 1);
  for k = 1:Kk
    Wk = pinv (P(:, :, k));
    Wsum += Wk; wth += Wk * th(k, :).';
  endfor
  tbar = pinv (Wsum) * wth;
  chi2 = 0;
  for k = 1:Kk
    d = th(k, :).' - tbar;
    chi2 += d.' * pinv (P(:, :, k)) * d;
  endfor
  dof = (Kk - 1) * np;
  pchi = gammainc (chi2 / 2, dof / 2, "upper");
  if (pchi >= ctx.opts.alpha)
    ## the segments agree: no evidence of a change on the estimation
    ## record, and the costly tracking (Qn by maximum likelihood) is
    ## not run
    c.reason = sprintf (["the segment fits agree (K = %d: chi^2 = %.1f ", ...
                         "on %d dof, p = %.2g >= alpha)"], Kk, chi2, dof,
                        pchi);
    return;
  endif
  ## per-parameter trend over the segments (weighted least squares)
  slope = zeros (1, np); tval = zeros (1, np);
  for i = 1:np
    v = squeeze (P(i, i, :));
    if (! all (v > 0 & isfinite (v)))
      slope(i) = NaN; tval(i) = NaN;   # a segment without a variance
      continue;
    endif
    X = [ones(Kk, 1), tmid(:)] ./ sqrt (v);
    [~, Rx] = qr (X, 0);
    if (rcond (Rx) < eps)
      slope(i) = NaN; tval(i) = NaN;
      continue;
    endif
    b = Rx \ (Rx' \ (X' * (th(:, i) ./ sqrt (v))));
    Cb = Rx \ (Rx' \ eye (2));
    slope(i) = b(2); tval(i) = b(2) / sqrt (Cb(2, 2));
  endfor
  ## Qn: shape from the segment increments, scale by ML
  dth = diff (th);
  vinc = zeros (1, np);
  for i = 1:np
    v = squeeze (P(i, i, :));
    vinc(i) = mean (dth(:, i) .^ 2 - (v(1:end-1) + v(2:end)));
  endfor
  shape = max (vinc, 1e-3 * diag (cur.cov).') / (2 * L / 3) / cur.s2;
  P0 = cur.cov / cur.s2;
  if (plain_model (cur))
    ltv = with_rsrivc (cur, D, ctx, shape, P0);
    if (! isempty (ltv))
      c.applicable = true;
      c.model = cur;
      c.model.ltv = ltv;
      c.variant = sprintf ("RSRIVC-KF, Qn = diag(%s) (qnml)",
                           mat2str (diag (ltv.Qn).', 2));
      c.nadd = np;
      [~, imax] = max (abs (tval));
      c.evidence = struct ("term", "segment chi^2", "value", chi2,
                           "std", NaN, "dof", dof, "p", pchi,
                           "segments", Kk, "theta_segments", th,
                           "slope", slope, "tval", tval,
                           "Qn", diag (ltv.Qn).', "ml_scale", NaN,
                           "text", sprintf (["segment fits (K = %d): ", ...
                                             "chi^2 = %.1f on %d dof, ", ...
                                             "p = %.2g; strongest trend: ", ...
                                             "parameter %d, t = %.1f; Qn ", ...
                                             "by qnml"],
                                            Kk, chi2, dof, pchi, imax,
                                            tval(imax)));
      return;
    endif
  endif
  best = [];
  for s = 10 .^ (-2:2)
    Qn = diag (s * shape);
    [thm, V, Pend] = residtrace_track (cur, D, ctx, Qn, cur.theta, P0);
    if (isfinite (V) && (isempty (best) || V < best.V))
      best = struct ("V", V, "s", s, "Qn", Qn, "th", thm(end, :), "P", Pend);
    endif
  endfor
  if (isempty (best))
    c.reason = "the tracking failed";
    return;
  endif
  c.applicable = true;
  c.model = cur;
  c.model.ltv = struct ("method", "kfiv", "Qn", best.Qn, "th0", best.th,
                        "P0", best.P, "scale", best.s);
  c.variant = sprintf ("KF-IV, Qn = diag(%s)", mat2str (diag (best.Qn).', 2));
  c.nadd = np;
  [~, imax] = max (abs (tval));
  c.evidence = struct ("term", "segment chi^2", "value", chi2, "std", NaN,
                       "dof", dof, "p", pchi, "segments", Kk,
                       "theta_segments", th, "slope", slope, "tval", tval,
                       "Qn", diag (best.Qn).', "ml_scale", best.s,
                       "text", sprintf (["segment fits (K = %d): chi^2 = ", ...
                                         "%.1f on %d dof, p = %.2g; ", ...
                                         "strongest trend: parameter %d, ", ...
                                         "t = %.1f; ML Qn scale %g"],
                                        Kk, chi2, dof, pchi, imax,
                                        tval(imax), best.s));
endfunction

## One input channel, F all free, no output terms: the model rsrivc
## estimates.
function ok = plain_model (m)
  ok = (numel (m.channels) == 1 && strcmp (m.channels.type, "input")
        && ! any (m.fixed) && isempty (m.out));
endfunction

## Qn by qnml (thesis sec. 3.3) for RSRIVC-KF started at the model, its
## shape from the segments (rescaled to RSRIVC's unit-gain prefilter, whose
## equation error is f_n e), bounds 1e-4 .. 1e4 times it; then RSRIVC over
## the estimation record gives the estimate and P to continue from.
function ltv = with_rsrivc (cur, D, ctx, shape, P0)
  ltv = [];
  ch = cur.channels;
  nb = ch.nb; nf = numel (cur.F) - 1;
  perm = [nf+1:nf+nb, 1:nf];          # [f b] -> rsrivc's [b f]
  fn = residtrace_prefilter (cur.F, ctx.wlo)(end);
  q0 = max (shape(perm) / fn ^ 2, realmin * 1e10);
  th0 = cur.theta(perm).';
  P0 = P0(perm, perm) / fn ^ 2;
  P0 = (P0 + P0.') / 2;
  A = residtrace_prefilter (cur.F, ctx.wlo);
  data = iddata (D.y, D.u(:, ch.col), D.Ts, "InterSample", D.intersample);
  nn = [nb nf ch.nk];
  ropts = {"A", A, "th0", th0, "P0", P0, "tsiv", 0};
  try
    Qn = qnml (data, nn, "method", "rsrivc", ropts{:}, "q0", q0,
               "lb", q0 * 1e-4, "ub", q0 * 1e4, "maxeval", 80);
    [thm, ~, pset] = rsrivc (data, nn, ropts{:}, "adm", "kf", "adg", Qn);
  catch
    return;
  end_try_catch
  if (any (! isfinite (thm(:))))
    return;
  endif
  Pend = pset(:, :, end);
  Pend = (Pend + Pend.') / 2;        # the IV update leaves P unsymmetric
  ltv = struct ("method", "rsrivc", "Qn", Qn, "nn", nn, "perm", perm,
                "th0", thm(end, :), "P0", Pend,
                "th_start", th0, "P_start", P0, "scale", NaN);
endfunction

function Dk = slice (D, idx)
  Dk = D;
  Dk.y = D.y(idx);
  Dk.u = D.u(idx, :);
  Dk.vhat = D.vhat(idx, :);
  Dk.ysm = D.ysm(idx);
  Dk.loop = [];
  Dk.initial_state = (idx(1) > 1);   # a segment does not start at rest
endfunction
