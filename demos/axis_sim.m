## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn {} {@var{y} =} axis_sim (@var{r}, @var{Ts}, @var{p})
## A positioning axis with end stops: a drive with its position loop
## closed, seen from the reference voltage @var{r} (held over each
## sampling interval) to the carriage position y (mm),
## @example
## y'' = wn^2 (K r - y) - 2 zeta wn y',   ymin <= y <= ymax
## @end example
## The stops are inelastic: a carriage that reaches a stop stays there,
## at rest, as long as the drive pushes it into the stop. @var{p}: struct
## with wn, zeta, K, ymin, ymax, optionally y0 (default K r(1), at rest)
## and substeps (default 20). Each sub-step is exact for the held
## reference (matrix exponential); a sub-step that crosses a stop ends at
## the stop with zero velocity (the contact instant located to the
## sub-step).
## @end deftypefn

function y = axis_sim (r, Ts, p)
  S = 20;
  if (isfield (p, "substeps"))
    S = p.substeps;
  endif
  A = [0 1; -p.wn ^ 2, -2 * p.zeta * p.wn];
  B = [0; p.wn ^ 2 * p.K];
  E = expm ([A, B; 0 0 0] * Ts / S);
  Ad = E(1:2, 1:2); Bd = E(1:2, 3);
  if (isfield (p, "y0"))
    x = [p.y0; 0];
  else
    x = [min(max (p.K * r(1), p.ymin), p.ymax); 0];
  endif
  N = numel (r);
  y = zeros (N, 1);
  for i = 1:N
    y(i) = x(1);
    for s = 1:S
      at_top = x(1) >= p.ymax && p.K * r(i) >= p.ymax;
      at_bot = x(1) <= p.ymin && p.K * r(i) <= p.ymin;
      if (at_top || at_bot)
        x(2) = 0;                        # held against the stop
        continue;
      endif
      x = Ad * x + Bd * r(i);
      if (x(1) > p.ymax)
        x = [p.ymax; 0];
      elseif (x(1) < p.ymin)
        x = [p.ymin; 0];
      endif
    endfor
  endfor
endfunction
