## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn {} {@var{p} =} residtrace_physical (@var{model}, @var{Ts})
## Physical reading of a @code{residtrace} model, a struct array with
## fields @code{name}, @code{value}, @code{std} (NaN when not available;
## ratios by the first-order delta method from the SRIVC covariance):
## static gain (or, with integrators, the gain of the rest), poles as time
## constants (real) or natural frequency and damping (pairs), zeros, the
## delay, and for a numerator b0 alone with one integrator and order 2 the
## mass 1/b0 and viscous coefficient f1/b0; then each added effect in
## input units of the first input (offset b_c/b0, Coulomb level -b_s/b0,
## nonlinear coefficients b_k/b0), output terms, Qn, the noise model.
## Computed by @code{effect_sim_mex} (core/include/ctid/apps/residtrace/
## physical_reading.hpp).
##
## @example
## @group
## ch = struct ("name", "u1", "type", "input", "col", 1, "param", [],
##              "nb", 1, "nk", 0, "B", 2);
## m = struct ("F", [1 0.5], "fixed", false, "channels", ch, "out", [],
##             "noise", [], "ltv", [], "phys", [], "cov", []);
## p = residtrace_physical (m, 0.1);
## @{p.name@}
##   @result{} @{ "static gain", "time constant (s)" @}
## @end group
## @end example
## @end deftypefn

function p = residtrace_physical (model, Ts)
  p = effect_sim_mex ("residtrace", "physical", model, struct ("ts", Ts));
endfunction

%!test
%! ## a pole pair p = -1 +- 3i: natural frequency sqrt(10), damping
%! ## 1/sqrt(10); F(0) = 10, so the static gain is b0/10
%! ch = struct ("name", "u1", "type", "input", "col", 1, "param", [],
%!              "nb", 1, "nk", 2, "B", 4);
%! m = struct ("F", [1 2 10], "fixed", [false false], "channels", ch,
%!             "out", [], "noise", [], "ltv", [], "phys", [], "cov", []);
%! p = residtrace_physical (m, 0.5);
%! assert ({p.name}, {"static gain", "natural frequency (rad/s)", ...
%!                    "damping ratio", "delay (s)"});
%! assert ([p.value], [0.4, sqrt(10), 1/sqrt(10), 1], 1e-12);
%! assert (all (isnan ([p.std])));

%!error <must be a 1x1 struct> residtrace_physical (1, 0.1)
