## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn {} {@var{o} =} residtrace_fitopts (@var{ctx}, @var{starts})
## The options of @code{effect_sim_mex}'s residtrace fits and candidates
## (methods "fitmodel", "select", "candidate"; read by
## mex/residtrace_candidate_io.hpp, read_context) from the context
## @var{ctx} of @code{residtrace}: @code{starts} (the cell @var{starts}),
## @code{maxiter}, @code{keep_order}, @code{substeps} (of
## @code{ctx.opts}; 1 without them) and, when the context has them,
## @code{wlo}, @code{lam_v} and @code{vel_is_y}.
## @end deftypefn

function o = residtrace_fitopts (ctx, starts)
  substeps = 1;
  if (isfield (ctx, "opts"))
    substeps = ctx.opts.substeps;
  endif
  o = struct ("maxiter", ctx.maxiter,
              "keep_order", isfield (ctx, "keep_order") && ctx.keep_order,
              "substeps", substeps);
  if (nargin > 1)
    o.starts = starts;
  endif
  for f = {"wlo", "lam_v", "vel_is_y"}
    if (isfield (ctx, f{1}))
      o.(f{1}) = ctx.(f{1});
    endif
  endfor
endfunction
