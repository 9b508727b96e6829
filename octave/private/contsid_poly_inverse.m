## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn {} {@var{x} =} contsid_poly_inverse (@var{fname}, @var{beta}, @var{v})
## Invert the static polynomial of a Wiener block, sample by sample:
## @var{x}(k) solves g(x) = beta(1) x + beta(2) x^2 + .. + beta(L) x^L =
## @var{v}(k) (no constant term, as @code{hwsrivc}'s @code{NL_W}), by the
## core (base/polynomial_inverse.hpp): the unique root when g is strictly
## monotonic, else the real root nearest to the previous sample's; no real
## root is @code{@var{fname}:numericalFailure}.  Errors carry the prefix
## @var{fname}.
## @end deftypefn

function x = contsid_poly_inverse (fname, beta, v)
  try
    x = hammerstein_mex (fname, "poly_inverse", double (v),
                         struct ("beta", double (beta(:).')));
  catch err
    contsid_rethrow (err, fname);
  end_try_catch
endfunction
