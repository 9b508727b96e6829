## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn {} {@var{c} =} residtrace_cand_viscous (@var{cur}, @var{ctx})
## Missing-viscous-friction candidate of @code{residtrace}: applicable
## when the model's coefficient of the velocity term is fixed at zero
## (a structural zero of F: the coefficient of p^1 for a model of order
## >= 2, whose output is read as a position; of p^0 for a first-order
## model, read as a velocity). The coefficient is freed, i.e. the
## regressor -p y_f (resp. -y_f) joins the filtered regression. Evidence:
## the fitted coefficient with its standard deviation and, for a
## numerator b0 alone, the viscous coefficient f / b0 in input units per
## unit velocity.
## @end deftypefn

function c = residtrace_cand_viscous (cur, ctx)
  c = residtrace_cand ("viscous");
  n = numel (cur.F) - 1;
  k = max (n - 1, 1);               # index of the velocity term in f1..fn
  if (! cur.fixed(k) || cur.F(k+1) != 0)
    c.reason = "the model's damping (velocity) coefficient is estimated";
    return;
  endif
  t = cur;
  t.fixed(k) = false;
  starts = {cur.F};
  m = residtrace_fit (t, ctx.D, ctx, starts);
  if (! m.ok)
    c.reason = "the estimation failed";
    c.failed = true;
    return;
  endif
  c.applicable = true;
  c.model = m;
  c.variant = sprintf ("free f%d", k);
  c.nadd = 1;
  i = sum (! t.fixed(1:k));        # position of f_k among the free f's
  val = m.theta(i); sd = sqrt (m.cov(i, i));
  b0 = m.channels(1).B;
  phys = NaN; psd = NaN;
  if (numel (b0) == 1)
    phys = val / b0; psd = sd / abs (b0);
  endif
  c.evidence = struct ("term", sprintf ("f%d (velocity coefficient)", k),
                       "value", val, "std", sd, "physical", phys,
                       "physical_std", psd,
                       "text", sprintf (["f%d = %.4g +- %.2g; viscous ", ...
                                         "coefficient %.4g +- %.2g (input ", ...
                                         "units per unit velocity)"],
                                        k, val, sd, phys, psd));
endfunction
