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
## The core does it: core/include/ctid/apps/residtrace/candidate_state.hpp
## (the cascade's template and fit stay residtrace_physcascade's and
## residtrace_physfit's).
## @end deftypefn

function c = residtrace_cand_state (cur, ctx)
  o = residtrace_fitopts (ctx);
  ## the cascade variant (its template is residtrace_physcascade's): only
  ## for a model without a nonlinearity of the output and a positive output
  if (isempty (cur.phys) && ! any (strcmp ({cur.channels.type}, "ypower"))
      && mean (ctx.D.y > 0) >= 0.95)
    t = residtrace_physcascade (cur, ctx, "sqrt", false);
    if (! isempty (t))
      m = residtrace_physfit (t, ctx.D, ctx);
      if (m.ok)
        m.fitted = true;
        o.cascade = m;
      endif
    endif
  endif
  c = effect_sim_mex ("residtrace", "candidate", "state_nonlinearity", cur,
                      ctx.D, o);
endfunction
