## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn {} {@var{F} =} residtrace_physlin (@var{model})
## The denominator of a "cascade" realisation (@code{residtrace_physsim})
## linearised at its steady state for the mean of the record's channels
## (@code{phys.wbar}): poles alpha g'(z) and gamma g'(h); for square-root
## nodes alpha^2 / (2 q) and alpha gamma^2 / (2 q), q the mean inflow.
## Used for the free response of a declared initial state and for the
## linear part reported with the model. Computed by the core
## (@file{core/include/ctid/apps/residtrace/physical_fit.hpp}, gateway
## @code{effect_sim_mex}, method "physlin").
## @end deftypefn

function F = residtrace_physlin (m)
  [~, o] = residtrace_physopts (m, [], 1);
  F = effect_sim_mex ("residtrace", "physlin", o);
endfunction
