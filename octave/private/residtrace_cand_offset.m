## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn {} {@var{c} =} residtrace_cand_offset (@var{cur}, @var{ctx})
## Offset candidate of @code{residtrace}: a constant entering with the
## input (an extra regressor 1 in the filtered regression, its own gain
## b_c/F(p)) or added to the output (y = x + c; not with an integrating
## model, where a constant output is an initial condition). The variant
## with the smaller BIC on the estimation data is kept. Evidence: the
## constant with its standard deviation, in input units (b_c over the
## input's static numerator) for the input offset.
## @end deftypefn

function c = residtrace_cand_offset (cur, ctx)
  c = residtrace_cand ("offset");
  tmpls = {}; names = {}; starts = {};
  if (cur.levels)
    c.reason = "the record's levels are estimated with the model already";
    return;
  endif
  if (! any (strcmp ({cur.channels.type}, "const")))
    t = cur;
    t.channels(end+1) = residtrace_chan ("const", 0, [], 1, 0, "offset");
    tmpls{end+1} = t; names{end+1} = "input offset"; starts{end+1} = {cur.F};
  endif
  if (cur.F(end) != 0 && ! any (strcmp ({cur.out.type}, "offset")))
    t = cur;
    t.out(end+1) = struct ("type", "offset", "c", 0, "cstd", 0, "omega", 0);
    tmpls{end+1} = t; names{end+1} = "output offset";
    starts{end+1} = {cur.F};
  endif
  if (isempty (tmpls))
    c.reason = "the model has its offsets already";
    return;
  endif
  [m, c.variants] = residtrace_select (tmpls, names, ctx.D, ctx, starts);
  if (isempty (m))
    c.reason = "the estimation failed";
    c.failed = true;
    return;
  endif
  c.applicable = true;
  c.model = m;
  c.variant = m.variant_;
  c.nadd = 1;
  bu = cur.channels(1).B(end);
  if (strcmp (c.variant, "input offset"))
    k = numel (m.theta);            # the constant's gain is the last one
    val = m.theta(k); sd = sqrt (m.cov(k, k));
    bu = m.channels(1).B(end);
    c.evidence = struct ("term", "b_c (gain of the constant input)",
                         "value", val, "std", sd,
                         "physical", val / bu, "physical_std", sd / abs (bu),
                         "text", sprintf (["input offset %.4g +- %.2g ", ...
                                           "(input units; b_c = %.4g +- ", ...
                                           "%.2g)"],
                                          val / bu, sd / abs (bu), val, sd));
  else
    o = m.out(end);
    c.evidence = struct ("term", "output offset", "value", o.c,
                         "std", o.cstd, "physical", o.c,
                         "physical_std", o.cstd,
                         "text", sprintf ("output offset %.4g +- %.2g",
                                          o.c, o.cstd));
  endif
endfunction
