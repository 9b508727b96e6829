## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn {} {@var{ok} =} residtrace_hurwitz (@var{F})
## True when the polynomial @var{F} = [1 f1 .. fn] has all its roots in
## the open left half-plane: closed forms up to order 3, the Routh array
## above (no eigenvalues, so that it is cheap enough for every sample of
## a recursive estimate).
## @end deftypefn

function ok = residtrace_hurwitz (F)
  F = F / F(1);
  n = numel (F) - 1;
  switch (n)
    case 0
      ok = true;
    case 1
      ok = F(2) > 0;
    case 2
      ok = F(2) > 0 && F(3) > 0;
    case 3
      ok = F(2) > 0 && F(3) > 0 && F(4) > 0 && F(2) * F(3) > F(4);
    otherwise
      ok = all (F > 0);
      if (! ok)
        return;
      endif
      a = F(1:2:end);
      b = F(2:2:end);
      for k = 1:n
        if (! (b(1) > 0))
          ok = false;
          return;
        endif
        m = numel (a);
        c = zeros (1, max (m - 1, 0));
        for i = 1:numel (c)
          bi = 0;
          if (i + 1 <= numel (b))
            bi = b(i+1);
          endif
          c(i) = a(i+1) - a(1) / b(1) * bi;
        endfor
        a = b;
        b = c;
        if (isempty (b))
          break;
        endif
      endfor
  endswitch
endfunction
