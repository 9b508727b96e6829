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
## stops there (not applicable, with the test in its reason). The
## segment test runs in the core (core/include/ctid/apps/residtrace/
## candidate_drift.hpp, through @code{effect_sim_mex}); the tracking below
## runs here.
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
  np = numel (cur.theta);
  o = residtrace_fitopts (ctx);
  o.alpha = ctx.opts.alpha;
  seg = effect_sim_mex ("residtrace", "driftsegments", cur, D, o);
  if (! isempty (seg.reason))
    ## too few samples, failed segment fits, or the segments agree: no
    ## evidence of a change on the estimation record, and the costly
    ## tracking (Qn by maximum likelihood) is not run
    c.reason = seg.reason;
    c.failed = seg.failed;
    return;
  endif
  th = seg.theta; Kk = seg.segments; chi2 = seg.chi2; dof = seg.dof;
  pchi = seg.p; slope = seg.slope; tval = seg.tval; shape = seg.shape;
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
