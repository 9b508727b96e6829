## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn {} {@var{c} =} residtrace_cand_order (@var{cur}, @var{ctx})
## Order candidate of @code{residtrace}: a missing pole or zero. The
## variants raise the denominator order by 1 or 2 and the numerator
## order of every input channel by 0, 1 or 2 (strictly proper models
## only); the model's integrators stay, other structural zeros of F are
## freed. Each variant is started from the current F times a factor at
## 1/3 and 3 times (order + 1) or 1/2 and 2 times (order + 2) the
## geometric mean of the current poles' moduli, and from the SVF start;
## the variant with the smallest BIC on the estimation data is kept; a
## variant whose fit sends an added pole beyond the samples (residualised
## by @code{residtrace_fit}) is not that variant and is dropped.
## Evidence: the poles and zeros of the chosen model and the drop in BIC.
## @end deftypefn

function c = residtrace_cand_order (cur, ctx)
  c = residtrace_cand ("order");
  n = numel (cur.F) - 1;
  r = 0;
  while (r < n && cur.fixed(n-r) && cur.F(n-r+1) == 0)
    r++;
  endwhile
  ins = find (strcmp ({cur.channels.type}, "input"));
  Fp = residtrace_prefilter (cur.F, ctx.wlo);
  wg = exp (mean (log (abs (roots (Fp)))));
  steps = [1 0; 1 1; 0 1; 2 0; 2 1; 2 2];
  tmpls = {}; names = {}; starts = {};
  for s = 1:rows (steps)
    da = steps(s, 1); db = steps(s, 2);
    nn = n + da;
    nbs = [cur.channels(ins).nb] + db;
    if (any (nbs > nn))
      continue;
    endif
    switch (da)
      case 0
        st = {cur.F};
      case 1
        st = {conv(cur.F, [1 wg/3]), conv(cur.F, [1 3*wg]), []};
      case 2
        st = {conv(cur.F, [1 0.3*wg (wg/2)^2]), ...
              conv(cur.F, [1 1.2*wg (2*wg)^2]), []};
    endswitch
    t = cur;
    t.F = [1, zeros(1, nn)];
    t.fixed = false (1, nn);
    t.fixed(nn-r+1:nn) = true;
    t.order_floor_ = nn;      # a fit that drops the added poles is not it
    for j = ins
      t.channels(j).nb += db;
      t.channels(j).B = [zeros(1, db), t.channels(j).B];
    endfor
    tmpls{end+1} = t;
    names{end+1} = sprintf ("na + %d, nb + %d", da, db);
    starts{end+1} = st;
  endfor
  if (isempty (tmpls))
    c.reason = "no admissible order";
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
  c.nadd = m.np - cur.np;
  p = roots (m.F);
  z = roots (m.channels(1).B);
  c.evidence = struct ("term", "poles", "value", p, "std", NaN,
                       "zeros", z, "bic_drop", cur.bic - m.bic,
                       "text", sprintf (["%s: poles %s, zeros %s; ", ...
                                         "BIC %.1f lower"],
                                        c.variant, num2str (p.', 4),
                                        num2str (z.', 4), cur.bic - m.bic));
endfunction
