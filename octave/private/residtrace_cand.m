## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn {} {@var{c} =} residtrace_cand (@var{effect})
## An empty candidate of @code{residtrace}: not applicable until a
## candidate function fills in the fitted @code{model}, the @code{variant}
## chosen on the estimation data, the number of added parameters
## @code{nadd}, the @code{kind} of its validation output
## (@qcode{"simulation"}, @qcode{"tracking"} or @qcode{"prediction"}) and
## its @code{evidence}; @code{insample} when its validation output fits
## parameters on the validation record itself (an initial state);
## @code{failed} when it applies to the model but its estimation failed
## (it was not tested: the verdict says so).
## @end deftypefn

function c = residtrace_cand (effect)
  c = struct ("effect", effect, "applicable", false, "reason", "",
              "variant", "", "model", [], "nadd", 0, "kind", "simulation",
              "evidence", struct ("text", ""), "variants", {{}},
              "insample", false, "failed", false);
endfunction
