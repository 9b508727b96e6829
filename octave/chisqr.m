## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn {} {@var{x} =} chisqr (@var{M}, @var{N}, @var{V})
## An @var{M}-by-@var{N} matrix of independent chi-square random deviates
## with @var{V} degrees of freedom (CONTSID's @code{chisqr}; its
## errors-in-variables demo draws a non-Gaussian input with
## @code{u0 = chisqr (5000, 1, 2)}).
##
## A chi-square variable with V degrees of freedom is 2 G with G gamma
## distributed of shape V/2 and unit scale; for integer V it is the sum of
## the squares of V independent standard normal variables.  The deviates
## are drawn as 2 * @code{randg} (V/2, M, N), so any real V > 0 is
## accepted and the generator state is @code{randg}'s
## (@code{randg ("state", s)} makes a draw reproducible).  Mean V,
## variance 2V.
##
## @var{M} and @var{N} are non-negative integers (at most 1e8 values in
## all); @var{V} a positive finite real scalar.
## @seealso{randg, randn, prbs}
## @end deftypefn

function varargout = chisqr (varargin)
  varargout = contsid_guard ("chisqr", @chisqr_body, nargout, varargin);
endfunction

function [x, varargout] = chisqr_body (varargin)
  contsid_nargchk ("chisqr", nargin, nargout, [3 3], 1);
  [M, N, V] = varargin{:};
  M = count (M, "M");
  N = count (N, "N");
  if (M * N > 1e8)
    error ("chisqr:badInput", "chisqr: at most 1e8 values, asked %g", M * N);
  endif
  if (! isnumeric (V) || ! isreal (V) || ! isscalar (V) || ! isfinite (V)
      || V <= 0)
    error ("chisqr:badInput",
           "chisqr: 'V' (degrees of freedom) must be a positive finite scalar");
  endif
  x = 2 * randg (double (V) / 2, M, N);
endfunction

function n = count (n, name)
  if (! isnumeric (n) || ! isreal (n) || ! isscalar (n) || ! isfinite (n)
      || n < 0 || n != fix (n))
    error ("chisqr:badInput",
           "chisqr: '%s' must be a non-negative integer", name);
  endif
  n = double (n);
endfunction

%!test  # moments and the distribution function (gammainc)
%! randg ("state", 11);
%! V = 3; n = 2e5;
%! x = chisqr (n, 1, V);
%! assert (size (x), [n 1]);
%! assert (all (x > 0));
%! ## mean V, variance 2V: within 5 standard errors
%! assert (abs (mean (x) - V) < 5 * sqrt (2 * V / n));
%! ## (the relative variance of the sample variance is (2 + 12/V) / n)
%! assert (abs (var (x) / (2 * V) - 1) < 5 * sqrt ((2 + 12 / V) / n));
%! ## Kolmogorov-Smirnov distance to P(V/2, x/2): 1.95/sqrt(n) is the 0.1%
%! ## critical value
%! xs = sort (x);
%! F = gammainc (xs / 2, V / 2);
%! D = max (max ((1:n)' / n - F), max (F - (0:n-1)' / n));
%! assert (D < 1.95 / sqrt (n));

%!test  # V = 1: the square of a standard normal (same distribution)
%! randg ("state", 2); randn ("state", 2);
%! n = 1e5;
%! x = sort (chisqr (n, 1, 1));
%! z = sort (randn (n, 1) .^ 2);
%! ## two-sample KS at the 0.1% level: 1.95 sqrt(2/n)
%! q = [x; z];
%! Fx = lookup (x, q) / n; Fz = lookup (z, q) / n;
%! assert (max (abs (Fx - Fz)) < 1.95 * sqrt (2 / n));

%!test  # shapes, the demo's call, non-integer V
%! assert (size (chisqr (5000, 1, 2)), [5000 1]);
%! assert (size (chisqr (2, 3, 0.5)), [2 3]);
%! assert (size (chisqr (0, 4, 2)), [0 4]);

%!error id=chisqr:badInput chisqr (2, 3)
%!error id=chisqr:badInput chisqr (-1, 1, 2)
%!error id=chisqr:badInput chisqr (1.5, 1, 2)
%!error id=chisqr:badInput chisqr (1, NaN, 2)
%!error id=chisqr:badInput chisqr (1, 1, 0)
%!error id=chisqr:badInput chisqr (1, 1, Inf)
%!error id=chisqr:badInput chisqr (1, 1, [1 2])
%!error id=chisqr:badInput chisqr (1, 1, "a")
%!error id=chisqr:badInput chisqr (1e5, 1e5, 2)
%!error id=chisqr:badInput [a, b] = chisqr (1, 1, 2)

%!demo
%! u0 = chisqr (5000, 1, 2);
%! hist (u0, 50); title (sprintf ("chi-square, 2 dof: mean %.3f", mean (u0)));
