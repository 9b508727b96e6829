## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn {} {@var{rivals} =} residtrace_rivals (@var{winner}, @var{rows}, @var{opts})
## The candidates of a pass that the data do not tell from its
## @var{winner}: the other significant rows of @var{rows} (the winner's
## group: simulated effects, or those that use the validation output),
## of another effect, whose validation error the winner's correction does
## not significantly improve on. The test is the one @code{residtrace}
## ranks nested candidates by: the encompassing test of
## @code{residtrace_dmtest (rival.e1, winner.e1)}, "better" when p_corr <
## @var{opts}.alpha and the share of the rival's mean square it removes is
## at least @var{opts}.minscore. Two candidates that explain the same
## part of the residual (a clipped input and a saturated first state
## behind it, say) are then reported together instead of the first one
## alone.
##
## @var{rivals}: a struct array (possibly empty) with fields
## @code{effect}, @code{variant}, @code{score} (the rival's share of the
## residual mean square removed) and @code{p} (p_corr of the winner
## against it).
## @end deftypefn

function rivals = residtrace_rivals (winner, rows, opts)
  rivals = struct ("effect", {}, "variant", {}, "score", {}, "p", {});
  if (isempty (winner) || isempty (rows))
    return;
  endif
  for j = 1:numel (rows)
    r = rows(j);
    if (! r.significant || strcmp (r.effect, winner.effect)
        || ! all (isfinite (r.e1)))
      continue;
    endif
    t = residtrace_dmtest (r.e1, winner.e1);
    if (t.p_corr < opts.alpha && t.score >= opts.minscore)
      continue;                   # the winner explains more than the rival
    endif
    rivals(end+1) = struct ("effect", r.effect, "variant", r.variant,
                            "score", r.score, "p", t.p_corr);
  endfor
endfunction

%!shared opts, w, e_w, mk
%! randn ("state", 7);
%! N = 4000;
%! opts = struct ("alpha", 0.01, "minscore", 0.01);
%! e_w = 0.1 * randn (N, 1);                 # the winner's error
%! w = struct ("effect", "saturation", "variant", "v", "score", 0.9,
%!             "significant", true, "e1", e_w);
%! mk = @(eff, e, sig) struct ("effect", eff, "variant", "x", "score", 0.8,
%!                             "significant", sig, "e1", e);
%!test  # the same error up to a little independent noise (0.1 % of its
%! ## mean square, below minscore): not told apart
%! r = mk ("static_nonlinearity", e_w + 0.003 * randn (size (e_w)), true);
%! v = residtrace_rivals (w, [w; r], opts);
%! assert (numel (v), 1);
%! assert (v.effect, "static_nonlinearity");
%!test  # a rival that leaves a structured error the winner removes
%! t = (1:numel (e_w))';
%! r = mk ("order", e_w + 0.1 * sin (2 * pi * t / 400), true);
%! v = residtrace_rivals (w, [w; r], opts);
%! assert (isempty (v));
%!test  # rivals must be significant, of another effect, with finite errors
%! r1 = mk ("delay", e_w, false);
%! r2 = mk ("saturation", e_w, true);
%! r3 = mk ("coulomb", Inf (size (e_w)), true);
%! assert (isempty (residtrace_rivals (w, [w; r1; r2; r3], opts)));
%! assert (isempty (residtrace_rivals ([], [w; r1], opts)));
