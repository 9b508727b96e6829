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
## itself, smoothed the same way without the derivative.
## @end deftypefn

function v = residtrace_velocity (y, Ts, lambda, is_y)
  D = residtrace_filter ([1 lambda], y, Ts, "foh");
  if (is_y)
    f = lambda * D(:, 1);
  else
    f = lambda * D(:, 2);
  endif
  b = residtrace_filter ([1 lambda], flipud (f), Ts, "foh");
  v = flipud (lambda * b(:, 1));
endfunction
