## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn  {} {} sigma (@var{num}, @var{den})
## @deftypefnx {} {} sigma (@var{num}, @var{den}, @var{w})
## @deftypefnx {} {} sigma (@var{a}, @var{b}, @var{c}, @var{d})
## @deftypefnx {} {} sigma (@var{a}, @var{b}, @var{c}, @var{d}, @var{w})
## @deftypefnx {} {[@var{sv}, @var{w}] =} sigma (@dots{})
## Singular values of the frequency response in the pre-LTI forms of
## MATLAB's Control System Toolbox (@code{sigma (A, B, C, D)} in CONTSID
## scripts).
##
## A method of the class @code{double}: Octave calls it only when no
## argument is an object, i.e. for the calls the control package's
## @code{sigma} rejects; calls with a model go to the control package
## unchanged.  @code{(num, den)} is @code{tf (num, den)}, @code{(a, b, c,
## d)} is @code{ss (a, b, c, d)}, both continuous-time.  @var{w}
## (rad/s, positive and increasing) chooses the frequencies; without it
## the control package chooses them from the poles and zeros.  The result
## is the control package's @code{sigma} of that model: @var{sv} has
## @code{min (p, m)} rows (p outputs, m inputs), one column per frequency,
## the singular values of @math{G(j\omega)} in decreasing order; without
## outputs the singular value plot is drawn.
##
## Example (a 2-by-2 system):
## @example
## a = [-1 0; 0 -2]; b = eye (2); c = [1 1; 0 1]; d = zeros (2);
## [sv, w] = sigma (a, b, c, d, logspace (-1, 2, 50));
## @end example
## @seealso{bode, step, pzmap}
## @end deftypefn

function varargout = sigma (varargin)
  varargout = contsid_guard ({"sigma", "double"}, @sigma_body, nargout, varargin);
endfunction

function [sv, w, varargout] = sigma_body (varargin)
  contsid_nargchk ("sigma", nargin, nargout, [2 5], 2);
  args = varargin;
  if (numel (args) == 5)
    ## sigma (a, b, c, d, w): no input index in this form.
    args = [args(1:4), {[]}, args(5)];
  endif
  [sys, ~, wgiven] = pre_lti_args ("sigma", args);
  if (isempty (wgiven))
    wargs = {};
  else
    wargs = {wgiven(:).'};
  endif
  if (nargout == 0)
    sigma (sys, wargs{:});
  else
    [sv, w] = sigma (sys, wargs{:});
    w = w(:);
  endif
endfunction

%!test
%! pkg load control
%! ## SISO: the singular value is |G(jw)|.
%! w = [0.1; 1; 10];
%! [sv, wo] = sigma ([1 2], [1 4 3], w);
%! G = polyval ([1 2], 1i * w) ./ polyval ([1 4 3], 1i * w);
%! assert (sv(:), abs (G), 1e-12);
%! assert (wo, w);

%!test
%! pkg load control
%! ## MIMO: svd of C (jwI - A)^-1 B + D at each frequency.
%! a = [-1 0; 0 -2]; b = eye (2); c = [1 1; 0 1]; d = [0 0.5; 0 0];
%! w = logspace (-1, 2, 7);
%! sv = sigma (a, b, c, d, w);
%! assert (size (sv), [2, 7]);
%! for k = 1:numel (w)
%!   G = c / (1i * w(k) * eye (2) - a) * b + d;
%!   assert (sv(:, k), svd (G), 1e-12);
%! endfor
%! [sv2, w2] = sigma (a, b, c, d);
%! [sv3, w3] = sigma (ss (a, b, c, d));
%! assert (sv2, sv3, 1e-12);
%! assert (w2, w3(:));

%!error id=sigma:badInput sigma (1)
%!error id=sigma:badInput sigma (1, 2, 3, 4, 5, 6)
%!error id=sigma:badInput sigma (1, [0 0])
%!error id=sigma:badInput sigma (1, [1 1], [1 -1 2])
%!error id=sigma:badInput sigma (1, [1 NaN])
%!error id=sigma:dimensionMismatch sigma (eye (2), [1; 1], [1 0 0], 0)
%!error id=sigma:badInput [a, b, c] = sigma (1, [1 1])

%!demo
%! sigma ([-1 0; 0 -2], eye (2), [1 1; 0 1], zeros (2))
