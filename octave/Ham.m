## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn  {} {@var{ubar} =} Ham (@var{u})
## @deftypefnx {} {@var{NL_H} =} Ham ()
## The static input (Hammerstein) nonlinearity of CONTSID's
## Hammerstein-Wiener demo:
## @example
## ubar = f(u) = u - 2 u^2 + 0.8 u^3,
## @end example
## applied element by element to the real finite array @var{u} (any size; the
## result has its size).  Without argument, the coefficients
## @var{NL_H} = [1 -2 0.8] of u, u^2, u^3 (the form of @code{hwsrivc}'s
## @code{Infos.NL_H}, as a row).  The demo stores the handle
## (@code{hwmodel.fh_ham = @@Ham}) for @code{simc_hw} and plots
## @code{Ham (ushow)}.
## @seealso{Wie, simc_hw, hwsrivc}
## @end deftypefn

function varargout = Ham (varargin)
  varargout = contsid_guard ("Ham", @Ham_body, nargout, varargin);
endfunction

function [ubar, varargout] = Ham_body (varargin)
  contsid_nargchk ("Ham", nargin, nargout, [0 1], 1);
  NL_H = [1, -2, 0.8];
  if (nargin == 0)
    ubar = NL_H;
    return;
  endif
  u = varargin{1};
  if (! (isnumeric (u) || islogical (u)) || ! isreal (u))
    error ("Ham:badInput", "Ham: 'u' must be a real numeric array");
  endif
  u = double (u);
  if (any (! isfinite (u(:))))
    error ("Ham:badInput", "Ham: 'u' must be finite");
  endif
  ubar = u .* (NL_H(1) + u .* (NL_H(2) + u * NL_H(3)));
endfunction

%!test  # the polynomial, term by term
%! u = linspace (-2, 2, 41);
%! assert (Ham (u), u - 2 * u.^2 + 0.8 * u.^3, 8 * eps);
%! assert (size (Ham (ones (3, 2))), [3 2]);
%! assert (Ham (), [1 -2 0.8]);
%! assert (polyval ([fliplr(Ham ()), 0], u), Ham (u), 1e-14);
%! assert (Ham (single (1)), 1 - 2 + 0.8, 1e-15);
%! assert (isempty (Ham ([])));

%!error id=Ham:badInput Ham ("a")
%!error id=Ham:badInput Ham (1i)
%!error id=Ham:badInput Ham ([0 NaN])
%!error id=Ham:badInput Ham (-Inf)
%!error id=Ham:badInput Ham ({1})
%!error id=Ham:badInput Ham (1, 2)
%!error id=Ham:badInput [a, b] = Ham (1)

%!demo
%! u = linspace (-0.5, 0.5, 101);
%! plot (u, Ham (u)); xlabel ("u"); ylabel ("Ham(u)");
%! title (["f(u) with NL_H = " mat2str(Ham ())]);
