## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn {} {@var{Fp} =} residtrace_prefilter (@var{F}, @var{wlo})
## A stable denominator with well separated roots for the prefilter 1/Fp(p)
## and the auxiliary model of the SRIVC iterations of @code{residtrace}.
##
## Roots of @var{F} at the origin (integrators of the model) are moved to
## -@var{wlo}; roots in the right half-plane are reflected (as
## @code{srivc} does); every root gets a damping of at least 1e-3; roots
## closer than 1e-2 of their modulus to another are moved apart. Only
## the prefilter changes: the model keeps its own F. The roots are
## taken by modulus before they are separated, so the result does not
## depend on the order a root finder returns them in. Computed by the core
## (core/include/ctid/apps/residtrace/prefilter.hpp,
## prefilter_denominator, through @code{effect_sim_mex}, method
## "prefilter").
## @end deftypefn

function Fp = residtrace_prefilter (F, wlo)
  Fp = effect_sim_mex ("residtrace", "prefilter", F, struct ("wlo", wlo));
endfunction
