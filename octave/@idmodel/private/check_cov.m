## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn {} {@var{C} =} check_cov (@var{C}, @var{fname})
## The covariance matrix @var{C} of a model's parameters as a double
## matrix, after checking that it is real, square, finite, symmetric and
## positive semi-definite (@code{setcov} and @code{set (M, "covariance",
## C)}); errors @code{@var{fname}:badInput}.
## @end deftypefn

function C = check_cov (C, fname)
  if (! (isnumeric (C) || islogical (C)) || ! isreal (C) || ndims (C) != 2
      || rows (C) != columns (C))
    error ([fname ":badInput"], "%s: the covariance must be a square matrix",
           fname);
  endif
  C = full (double (C));
  if (any (! isfinite (C(:))) || norm (C - C.', 1) > 1e-10 * norm (C, 1)
      || any (eig ((C + C.') / 2) < -1e-10 * max (norm (C, 1), realmin)))
    error ([fname ":badInput"],
           "%s: the covariance must be symmetric positive semi-definite",
           fname);
  endif
endfunction
