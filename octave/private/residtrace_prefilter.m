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
## the prefilter changes: the model keeps its own F.
## @end deftypefn

function Fp = residtrace_prefilter (F, wlo)
  r = roots (F(:).');
  scale = max ([abs(r); wlo]);
  for k = 1:numel (r)
    if (abs (r(k)) < 1e-9 * scale)
      r(k) = -wlo;
    endif
    m = abs (r(k));
    re = -abs (real (r(k)));
    re = min (re, -1e-3 * m);
    r(k) = complex (re, imag (r(k)));
  endfor
  r = separate (r);
  Fp = real (poly (r));
endfunction

function r = separate (r)
  s = 1e-2;
  real_ = abs (imag (r)) == 0;
  u = [r(real_); r(imag (r) > 0)];      # each conjugate pair once
  ispair = [false(sum (real_), 1); true(sum (imag (r) > 0), 1)];
  for k = find (ispair)'
    m = abs (u(k));
    if (imag (u(k)) < s / 2 * m)
      u(k) = complex (real (u(k)), s / 2 * m);
    endif
  endfor
  for pass = 1:10
    moved = false;
    for i = 1:numel (u)
      for j = i+1:numel (u)
        m = max (abs (u(i)), abs (u(j)));
        if (abs (u(i) - u(j)) < s * m)
          u(j) *= 1 + 2 * s;
          moved = true;
        endif
      endfor
    endfor
    if (! moved)
      break;
    endif
  endfor
  r = [u(! ispair); u(ispair); conj(u(ispair))];
endfunction
