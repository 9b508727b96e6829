## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn {} {@var{c} =} residtrace_cand_state (@var{cur}, @var{ctx})
## State-dependent-dynamics candidate of @code{residtrace}: a function of
## the output acting inside the dynamics, F(p) y = B(p) u + sum_k g_k
## y^(q_k), the terms entering like an input (gain g_k/F(p)):
## @itemize
## @item q = 1/2 (sign(y) sqrt|y|): the outflow of a tank through an
## orifice (Torricelli), a square-root law; only when the output is
## positive on at least 95 % of the samples (a level measured from its
## physical zero);
## @item q = 2: a time constant that depends on the operating point
## (y' = -(a0 + a1 y) y + b u);
## @item q = 3, and q = 2 with 3: a hardening or softening spring
## (Duffing's equation).
## @end itemize
## y is the measured output (its noise biases the coefficients towards
## zero, as errors in variables do); the simulation uses the model's own
## output (plus its output offset), re-evaluated at each sub-step. The
## variant with the smallest BIC on the estimation data is kept; whether
## its terms are determined is @code{residtrace_accept}'s general check.
## With the record's levels
## estimated the terms come with a constant (F(0) = 0 needs one to
## balance B(0) u0). A further variant puts the nonlinearity at an inner
## node: two first-order sections with square-root outflows (two tanks,
## @code{residtrace_physcascade}), fitted on its simulation error.
## Evidence: the coefficients g_k with their standard deviations.
## @end deftypefn

function c = residtrace_cand_state (cur, ctx)
  c = residtrace_cand ("state_nonlinearity");
  if (any (strcmp ({cur.channels.type}, "ypower"))
      || ! isempty (cur.phys))
    c.reason = "the model has a nonlinearity of the output already";
    return;
  endif
  y = ctx.D.y;
  pw = {[2], [3], [2 3]};
  if (mean (y > 0) >= 0.95)
    pw = [{0.5}, pw];
  endif
  tmpls = {}; names = {}; starts = {};
  ## a record in raw units has its input level u0 removed and an output
  ## offset c estimated: F(p)(y - c) = B(p)(u - u0) + g(y) has then
  ## nothing to balance B(0) u0 where F(0) = 0 (a tank whose only damping
  ## is its outflow), so the terms come with a constant of their own
  lev = isfield (cur, "levels") && cur.levels ...
        && ! any (strcmp ({cur.channels.type}, "const"));
  for k = 1:numel (pw)
    t = cur;
    if (lev)
      t.channels(end+1) = residtrace_chan ("const", 0, [], 1, 0, "1");
    endif
    for p = pw{k}
      if (p == 0.5)
        nm = "sqrt(y)";
      else
        nm = sprintf ("y^%d", p);
      endif
      t.channels(end+1) = residtrace_chan ("ypower", 0, p, 1, 0, nm);
    endfor
    tmpls{end+1} = t; starts{end+1} = {cur.F};
    names{end+1} = ["output in the dynamics: " ...
                    strjoin({t.channels(end-numel(pw{k})+1:end).name}, ", ")];
  endfor
  ## the nonlinearity at an inner node: two first-order sections with
  ## square-root outflows (two tanks), fitted on its simulation error
  if (mean (y > 0) >= 0.95)
    t = residtrace_physcascade (cur, ctx, "sqrt", false);
    if (! isempty (t))
      m = residtrace_physfit (t, ctx.D, ctx);
      if (m.ok)
        m.fitted = true;
        tmpls{end+1} = m; starts{end+1} = {};
        names{end+1} = "square-root outflows of a two-section cascade";
      endif
    endif
  endif
  [m, c.variants] = residtrace_select (tmpls, names, ctx.D, ctx, starts);
  if (isempty (m))
    c.reason = "the estimation failed";
    c.failed = true;
    return;
  endif
  nadd = m.np - cur.np;
  if (! isempty (m.phys))
    ## a realisation fitted on its simulation error: its parameters are
    ## not added terms (no three-sigma test)
    c.applicable = true;
    c.model = m;
    c.variant = m.variant_;
    c.nadd = max (nadd, 1);
    P = m.phys;
    c.evidence = struct ("term", "alpha, gamma, inner level", "value",
                         [P.alpha P.gamma P.hi], "std", NaN,
                         "text", sprintf (["%s: alpha %.4g, gamma %.4g, ", ...
                                           "output level %.4g"], c.variant,
                                          P.alpha, P.gamma, P.c));
    return;
  endif
  nlin = sum (strcmp ({m.channels.type}, "ypower"));
  val = m.theta(end-nlin+1:end);
  sd = sqrt (diag (m.cov))(end-nlin+1:end);
  c.applicable = true;
  c.model = m;
  c.variant = m.variant_;
  c.nadd = nadd;
  c.evidence = struct ("term", "gains of the output terms", "value",
                       val(:).', "std", sd(:).',
                       "text", sprintf ("%s: coefficients %s +- %s",
                                        c.variant, mat2str (val(:).', 4),
                                        mat2str (sd(:).', 2)));
endfunction
