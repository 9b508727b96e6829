## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn {} {@var{F} =} residtrace_physlin (@var{model})
## The denominator of a "cascade" realisation (@code{residtrace_physsim})
## linearised at its steady state for the mean of the record's channels
## (@code{phys.wbar}): poles alpha g'(z) and gamma g'(h); for square-root
## nodes alpha^2 / (2 q) and alpha gamma^2 / (2 q), q the mean inflow.
## Used for the free response of a declared initial state and for the
## linear part reported with the model.
## @end deftypefn

function F = residtrace_physlin (m)
  P = m.phys;
  b = arrayfun (@(c) c.B(end), m.channels)(:);
  q = P.wbar(:).' * b + P.d;
  if (strcmp (P.g, "sqrt"))
    q = max (q, 1e-9 * (abs (P.d) + 1));
    p1 = P.alpha ^ 2 / (2 * q);
    p2 = P.alpha * P.gamma ^ 2 / (2 * q);
  else
    p1 = P.alpha;
    p2 = P.gamma;
  endif
  F = conv ([1 p1], [1 p2]);
endfunction
