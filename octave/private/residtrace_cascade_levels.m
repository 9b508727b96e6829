## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn {} {[@var{z0}, @var{h0}] =} residtrace_cascade_levels (@var{P})
## The initial levels of a "cascade" realisation (@code{residtrace_physsim})
## from its parameters @var{P} (@code{model.phys}): @var{h0} =
## @code{P.h0} kept below the outer level (@code{P.yhi - P.c} when
## present), @var{z0} = @code{P.z0} when given, else the inner level at
## rest with h0 (g(z0) = gamma g(h0): gamma^2 max(h0, 0) for square-root
## nodes, gamma h0 for linear ones), kept below @code{P.hi}. Both NaN
## when the cascade has no initial level (it then starts at rest for the
## first sample's input, which only a simulation gives). Computed by
## @code{effect_sim_mex} (core/include/ctid/apps/residtrace/
## physical_fit.hpp).
## @end deftypefn

function [z0, h0] = residtrace_cascade_levels (P)
  [z0, h0] = effect_sim_mex ("residtrace", "cascadelevels", P, struct ());
endfunction

%!test  # square-root nodes: g(z0) = gamma g(h0), below the inner level
%! P = struct ("kind", "cascade", "g", "sqrt", "gamma", 0.5, "hi", 10,
%!             "c", 1, "h0", 4);
%! [z0, h0] = residtrace_cascade_levels (P);
%! assert ([z0, h0], [1, 4]);
%! P.hi = 0.5;
%! assert (residtrace_cascade_levels (P), 0.5);
%!test  # linear nodes; the outer level holds h0; a given z0 is kept
%! P = struct ("kind", "cascade", "g", "lin", "gamma", 0.5, "hi", Inf,
%!             "c", 1, "h0", 4, "yhi", 3);
%! [z0, h0] = residtrace_cascade_levels (P);
%! assert ([z0, h0], [1, 2]);
%! P.z0 = 7;
%! assert (residtrace_cascade_levels (P), 7);
%!test  # no initial level: at rest for the first input (a simulation)
%! [z0, h0] = residtrace_cascade_levels (struct ("kind", "cascade",
%!                                              "g", "sqrt", "h0", []));
%! assert (isnan ([z0, h0]));

%!error <must be a cascade> residtrace_cascade_levels (struct ("kind", "stop"))
