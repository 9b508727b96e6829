## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn {} {[@var{h2}, @var{h1}, @var{spill}] =} tanks_sim (@var{u}, @var{Ts}, @var{p})
## Two tanks in cascade (a coupled-tanks rig): the pump voltage @var{u}
## (V, held over each sampling interval) fills the upper tank, which drains
## through an orifice into the lower one, which drains out (Torricelli,
## square-root outflows); the upper tank overflows at its rim (the water
## above h1max is lost):
## @example
## h1' = k u - c1 sqrt(h1),   0 <= h1 <= h1max
## h2' = c1 sqrt(h1) - c2 sqrt(h2)
## @end example
## levels in cm, time in s. @var{p}: struct with k, c1, c2, h1max, and
## optionally h0 (initial levels [h1 h2], default at rest for u(1)),
## substeps (default 8). Integration: classical Runge-Kutta over each
## sub-step with the levels projected onto their bounds after it (at the
## rim the net inflow spills over). @var{spill}: the samples at which the
## upper tank is at its rim.
## @end deftypefn

function [h2, h1, spill] = tanks_sim (u, Ts, p)
  S = 8;
  if (isfield (p, "substeps"))
    S = p.substeps;
  endif
  h = Ts / S;
  if (isfield (p, "h0"))
    x = p.h0(:);
  else
    q = max (p.k * u(1), 0);
    x = [min((q / p.c1) ^ 2, p.h1max); (q / p.c2) ^ 2];
  endif
  N = numel (u);
  h1 = zeros (N, 1); h2 = zeros (N, 1); spill = false (N, 1);
  c1 = p.c1; c2 = p.c2; top = p.h1max;
  a = x(1); b = x(2);
  for i = 1:N
    h1(i) = a; h2(i) = b;
    spill(i) = a >= top;
    q = max (p.k * u(i), 0);            # a pump does not suck
    for s = 1:S                         # classical Runge-Kutta, inlined
      o1 = c1 * sqrt (max (a, 0)); a1 = q - o1;
      b1 = o1 - c2 * sqrt (max (b, 0));
      o2 = c1 * sqrt (max (a + h / 2 * a1, 0)); a2 = q - o2;
      b2 = o2 - c2 * sqrt (max (b + h / 2 * b1, 0));
      o3 = c1 * sqrt (max (a + h / 2 * a2, 0)); a3 = q - o3;
      b3 = o3 - c2 * sqrt (max (b + h / 2 * b2, 0));
      o4 = c1 * sqrt (max (a + h * a3, 0)); a4 = q - o4;
      b4 = o4 - c2 * sqrt (max (b + h * b3, 0));
      a += h / 6 * (a1 + 2 * a2 + 2 * a3 + a4);
      b += h / 6 * (b1 + 2 * b2 + 2 * b3 + b4);
      a = min (max (a, 0), top);
      b = max (b, 0);
    endfor
  endfor
endfunction
