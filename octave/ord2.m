## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn  {} {[@var{num}, @var{den}] =} ord2 (@var{wn}, @var{z})
## @deftypefnx {} {[@var{a}, @var{b}, @var{c}, @var{d}] =} ord2 (@var{wn}, @
##   @var{z})
## Continuous-time second-order system of natural frequency @var{wn} and
## damping ratio @var{z} (MATLAB's @code{ord2}):
## @tex
## $$ G(s) = {1 \over s^2 + 2 z \omega_n s + \omega_n^2}. $$
## @end tex
## @ifnottex
## @code{G(s) = 1 / (s^2 + 2*z*wn*s + wn^2)}.
## @end ifnottex
##
## With two outputs, the transfer function's coefficient rows
## @code{num = 1}, @code{den = [1, 2*z*wn, wn^2]}; with four, the
## state-space matrices @code{a = [0 1; -wn^2 -2*z*wn]}, @code{b = [0; 1]},
## @code{c = [1 0]}, @code{d = 0}.  Note the static gain @code{1/wn^2}
## (MATLAB's definition); @code{wn^2 * num} gives unit gain.
##
## @strong{Example}
## @example
## @group
## [num, den] = ord2 (2, 0.5)
##   @result{} num = 1
##   @result{} den = 1   2   4
## @end group
## @end example
## @seealso{step, bode}
## @end deftypefn

function varargout = ord2 (varargin)
  varargout = contsid_guard ("ord2", @ord2_body, nargout, varargin);
endfunction

function [a, b, c, d, varargout] = ord2_body (wn, z, varargin)
  contsid_nargchk ("ord2", nargin, nargout, [0 Inf], 4);
  if (nargin != 2)
    error ("ord2:badInput",
           "ord2: takes 2 arguments, not %d", nargin);
  endif
  if (! (isnumeric (wn) && isscalar (wn) && isreal (wn) && isfinite (wn)
         && isnumeric (z) && isscalar (z) && isreal (z) && isfinite (z)))
    error ("ord2:badInput",
           "ord2: 'wn' and 'z' must be real finite scalars");
  endif
  if (! any (nargout == [0, 1, 2, 4]))
    error ("ord2:badInput",
           "ord2: returns [num, den] or [a, b, c, d], not %d outputs",
           nargout);
  endif
  wn = double (wn);
  z = double (z);
  if (nargout == 4)
    a = [0, 1; -wn^2, -2*z*wn];
    b = [0; 1];
    c = [1, 0];
    d = 0;
  else
    a = 1;
    b = [1, 2*z*wn, wn^2];
  endif
endfunction

%!test
%! [num, den] = ord2 (2, 0.5);
%! assert (num, 1);
%! assert (den, [1, 2, 4]);
%! [a, b, c, d] = ord2 (3, 0.2);
%! ## the same transfer function: c (sI - a)^-1 b + d at a few s
%! for s = [0.1, 1i, 2 + 3i]
%!   assert (c / (s * eye (2) - a) * b + d, 1 / polyval ([1, 1.2, 9], s),
%!           1e-14);
%! endfor
%! assert (sort (roots (den)), sort (eig ([0 1; -4 -2])), 1e-14);

%!error id=ord2:badInput ord2 ([1 2], 0.5)
%!error id=ord2:badInput ord2 (1, NaN)
%!error id=ord2:badInput ord2 (1i, 0.5)
%!error id=ord2:badInput [a, b, c] = ord2 (1, 0.5);
%!error id=ord2:badInput ord2 (1)
%!error id=ord2:badInput ord2 (1, 0.5, 3)

%!demo
%! [num, den] = ord2 (2, 0.3);
%! step (num, den)
