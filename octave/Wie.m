## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn  {} {@var{x} =} Wie (@var{xbar})
## @deftypefnx {} {@var{NL_W} =} Wie ()
## The static output (Wiener) nonlinearity of CONTSID's
## Hammerstein-Wiener demo, x = g^-1(xbar), where
## @example
## xbar = g(x) = x + 1.5 x^2 + x^3.
## @end example
## The demo's diagram is u -> f -> ubar -> G(s) -> xbar -> Wien. -> x,
## y = x + e; it plots @code{Wie (zshow)} over the range of xbar with the
## label "x = Wie(xbar)", and @code{hwsrivc} estimates the coefficients of
## g (@code{Infos.NL_W}, compared with NL_W0 = [1 1.5 1]).  So @code{Wie}
## returns the solution x of g(x) = @var{xbar}, element by element (any
## real finite array; the result has its size).  g is strictly increasing
## (g'(x) = 1 + 3x + 3x^2 >= 1/4), so the solution is unique; it is found
## by bracketed Newton steps to a few eps.
##
## Without argument, the coefficients @var{NL_W} = [1 1.5 1] of x, x^2,
## x^3 in g (the form of @code{Infos.NL_W}, as a row).
## @seealso{Ham, simc_hw, hwsrivc}
## @end deftypefn

function varargout = Wie (varargin)
  varargout = contsid_guard ("Wie", @Wie_body, nargout, varargin);
endfunction

function [x, varargout] = Wie_body (varargin)
  contsid_nargchk ("Wie", nargin, nargout, [0 1], 1);
  NL_W = [1, 1.5, 1];
  if (nargin == 0)
    x = NL_W;
    return;
  endif
  xbar = varargin{1};
  if (! (isnumeric (xbar) || islogical (xbar)) || ! isreal (xbar))
    error ("Wie:badInput", "Wie: 'xbar' must be a real numeric array");
  endif
  xbar = double (xbar);
  if (any (! isfinite (xbar(:))))
    error ("Wie:badInput", "Wie: 'xbar' must be finite");
  endif
  x = contsid_poly_inverse ("Wie", NL_W, xbar);
endfunction

%!test  # g(Wie(xbar)) = xbar, and the real root of the cubic
%! xbar = linspace (-5, 5, 201);
%! x = Wie (xbar);
%! assert (x + 1.5 * x.^2 + x.^3, xbar, 1e-13 * max (1, max (abs (xbar))));
%! for v = [-3.7, -0.2, 0, 0.3, 12]
%!   r = roots ([1 1.5 1 -v]);
%!   r = real (r(abs (imag (r)) < 1e-9));
%!   assert (Wie (v), r, 1e-12 * max (1, abs (r)));
%! endfor
%! assert (Wie (), [1 1.5 1]);
%! assert (size (Wie (ones (2, 3))), [2 3]);
%! assert (Wie (0), 0);
%! assert (Wie (1e200), 1e200 ^ (1/3), 1e-12 * 1e200 ^ (1/3));

%!test  # the inverse of the forward map on a grid of x
%! x = linspace (-3, 3, 61);
%! assert (Wie (x + 1.5 * x.^2 + x.^3), x, 1e-12);

%!error id=Wie:badInput Wie ("a")
%!error id=Wie:badInput Wie (1i)
%!error id=Wie:badInput Wie (NaN)
%!error id=Wie:badInput Wie ([1 Inf])
%!error id=Wie:badInput Wie (1, 2)
%!error id=Wie:badInput [a, b] = Wie (1)

%!demo
%! xbar = linspace (-1, 3, 101);
%! plot (xbar, Wie (xbar)); xlabel ("xbar"); ylabel ("x = Wie(xbar)");
%! title (["g(x) = xbar with NL_W = " mat2str(Wie ())]);
