## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn {} {@var{v} =} residtrace_velocity (@var{y}, @var{Ts}, @var{lambda}, @var{is_y})
## The velocity of the measured output for the Coulomb-friction regressor
## of @code{residtrace}: the SVF derivative p lambda/(p + lambda) y run
## forward, then lambda/(p + lambda) run backward, so that the result is
## p lambda^2 / (lambda^2 + w^2) y without phase lag (the zero crossings
## that sign(v) depends on are not delayed). With @var{is_y} (a
## first-order model, whose output is read as a velocity) the output
## itself, smoothed the same way without the derivative. Computed by
## @code{effect_sim_mex} (core/include/ctid/apps/residtrace/responses.hpp).
## @end deftypefn

function v = residtrace_velocity (y, Ts, lambda, is_y)
  v = effect_sim_mex ("residtrace", "velocity", y(:),
                      struct ("ts", Ts, "lambda", lambda,
                              "output_itself", logical (is_y)));
endfunction

%!test
%! ## a sine well below lambda: the velocity is its derivative, scaled by
%! ## lambda^2 / (lambda^2 + w^2), in phase (away from the ends)
%! Ts = 0.01; t = (0:2000)' * Ts; w = 2; lambda = 40;
%! v = residtrace_velocity (sin (w * t), Ts, lambda, false);
%! k = 500:1500;
%! g = lambda ^ 2 / (lambda ^ 2 + w ^ 2);
%! assert (v(k), g * w * cos (w * t(k)), 2e-3);
%! s = residtrace_velocity (sin (w * t), Ts, lambda, true);
%! assert (s(k), g * sin (w * t(k)), 2e-3);

%!error <bandwidth> residtrace_velocity ((1:10)', 0.1, -1, false)
