## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn {} {@var{c} =} residtrace_cand_x0 (@var{cur}, @var{ctx})
## Unknown-initial-state candidate of @code{residtrace}: the record did
## not start at rest. The model's free response from an initial state x0
## (n basis functions: the output of the model in observable canonical
## form started from each unit state, no input) is fitted by least squares
## on each record's simulation error, as MATLAB's @code{compare} estimates
## x0: n parameters per record, declared in the result (every simulation
## of a model with this effect is "simulated from the input plus an
## estimated initial state"). Not with a split record (the validation part
## starts where the simulation of the estimation part left it) or a
## closed loop. Evidence: the share of the estimation residual's mean
## square the free response removes, and the estimated x0.
## @end deftypefn

function c = residtrace_cand_x0 (cur, ctx)
  c = residtrace_cand ("initial_state");
  if (cur.x0)
    c.reason = "the initial state is estimated already";
    return;
  endif
  if (! isempty (ctx.V.pre))
    c.reason = ["the validation record continues the estimation record: ", ...
                "its initial state comes from the simulation"];
    return;
  endif
  if (! isempty (ctx.D.loop))
    c.reason = "not in closed loop";
    return;
  endif
  n = numel (cur.F) - 1;
  X = residtrace_free (cur.F, numel (ctx.D.y), ctx.D.Ts);
  e = cur.e_est;
  x0 = X \ e;
  share = 1 - sum ((e - X * x0) .^ 2) / sum (e .^ 2);
  c.applicable = true;
  c.model = cur;
  c.model.x0 = true;
  c.insample = true;
  c.variant = sprintf ("x0 of %d states fitted on each record", n);
  c.nadd = n;
  c.evidence = struct ("term", "x0 (observable form)", "value", x0(:).',
                       "std", NaN, "share_estimation", share,
                       "text", sprintf (["the free response from x0 = %s ", ...
                                         "removes %.1f %% of the ", ...
                                         "estimation residual"],
                                        mat2str (x0(:).', 3), 100 * share));
endfunction
