## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn {} {@var{x} =} contsid_poly_inverse (@var{fname}, @var{beta}, @var{v})
## Invert the static polynomial of a Wiener block, sample by sample:
## @var{x}(k) solves g(x) = beta(1) x + beta(2) x^2 + .. + beta(L) x^L =
## @var{v}(k) (no constant term, as @code{hwsrivc}'s @code{NL_W}).
##
## When g is strictly monotonic (its derivative has no real root of odd
## multiplicity) the solution is unique and is found for all samples at
## once by Newton steps kept inside a bracket (bisection when a step
## leaves it), inside Fujiwara's bound of the roots; accurate to a
## few eps.  Otherwise each sample takes the real root of
## g(x) - v(k) nearest to the previous sample's solution (the first: the
## root nearest to v(1)), found by @code{roots}; no real root is
## @code{@var{fname}:numericalFailure}.  Errors carry the prefix
## @var{fname}.
## @end deftypefn

function x = contsid_poly_inverse (fname, beta, v)
  beta = double (beta(:).');
  last = find (beta != 0, 1, "last");
  if (isempty (last))
    error ([fname ":badInput"],
           "%s: the Wiener polynomial is identically zero", fname);
  endif
  beta = beta(1:last);
  x = zeros (size (v));
  if (isempty (v))
    return;
  endif
  if (numel (beta) == 1)
    x = v / beta;
    return;
  endif
  p = [fliplr(beta), 0];                 # g(x) in descending powers
  dp = polyder (p);
  r = roots (dp);
  tol = 1e-9 * (1 + abs (r));
  real_r = real (r(abs (imag (r)) <= tol));
  monotonic = true;
  for k = 1:numel (real_r)
    ## a real root of g' where g' changes sign ends monotonicity
    h = 1e-6 * (1 + abs (real_r(k)));
    if (polyval (dp, real_r(k) - h) * polyval (dp, real_r(k) + h) < 0)
      monotonic = false;
    endif
  endfor
  if (monotonic)
    x = bracketed_newton (p, dp, v);
  else
    x = nearest_roots (fname, p, v);
  endif
endfunction

function x = bracketed_newton (p, dp, v)
  sz = size (v);
  v = v(:);
  lead = p(1);
  n = numel (p) - 1;
  ## Fujiwara's bound on the roots of g(x) - v:
  ## 2 max (|c_(n-k) / c_n|^(1/k), |v / (2 c_n)|^(1/n))
  k = 1:n-1;
  fixed = max ([abs(p(2:end-1) / lead) .^ (1 ./ k), 0]);
  R = 2 * max (fixed, abs (v / (2 * lead)) .^ (1 / n));
  lo = -R; hi = R;
  rising = lead > 0;                     # a monotonic g has odd degree
  x = v / p(end-1);                      # linear guess, x = v / beta(1)
  bad = ! isfinite (x) | x <= lo | x >= hi;
  x(bad) = 0;
  for it = 1:200
    f = polyval (p, x) - v;
    above = (f > 0) == rising;            # x above the root
    hi(above) = x(above);
    lo(! above) = x(! above);
    step = f ./ polyval (dp, x);
    xn = x - step;
    out = ! (xn >= lo & xn <= hi) | ! isfinite (xn);
    xn(out) = (lo(out) + hi(out)) / 2;
    done = abs (xn - x) <= 4 * eps * max (1, abs (xn));
    x = xn;
    if (all (done))
      break;
    endif
  endfor
  x = reshape (x, sz);
endfunction

function x = nearest_roots (fname, p, v)
  x = zeros (size (v));
  prev = v(1);
  for k = 1:numel (v)
    q = p;
    q(end) = -v(k);
    r = roots (q);
    r = real (r(abs (imag (r)) <= 1e-8 * (1 + abs (r))));
    if (isempty (r))
      error ([fname ":numericalFailure"],
             "%s: the Wiener polynomial takes no value %g (sample %d)",
             fname, v(k), k);
    endif
    [~, i] = min (abs (r - prev));
    x(k) = r(i);
    prev = x(k);
  endfor
endfunction
