## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn  {} {} bode (@var{num}, @var{den})
## @deftypefnx {} {} bode (@var{num}, @var{den}, @var{w})
## @deftypefnx {} {} bode (@var{a}, @var{b}, @var{c}, @var{d})
## @deftypefnx {} {} bode (@var{a}, @var{b}, @var{c}, @var{d}, @var{iu})
## @deftypefnx {} {} bode (@var{a}, @var{b}, @var{c}, @var{d}, @var{iu}, @
##   @var{w})
## @deftypefnx {} {[@var{mag}, @var{phase}, @var{w}] =} bode (@dots{})
## Bode diagram in the pre-LTI forms of MATLAB's Control System Toolbox,
## as CONTSID scripts call it: @code{bode (Nc, Dc)},
## @code{m1 = bode (a, b, c, d, iu, w)}.
##
## This is a method of the class @code{double}: Octave calls it only when
## no argument is an object, i.e. for exactly the calls that the control
## package's @code{bode} rejects.  Calls with a model go to the control
## package (or the model's class) unchanged.
## The other built-in classes (@code{single}, the integer types,
## @code{logical}, @code{char}, @code{cell}, @code{struct},
## @code{function_handle}) link to this file: Octave sends a call whose
## arguments are all built-in to the method of the highest of their
## classes, so every such call comes here (numbers of any numeric class
## are read as double, anything else is an identified error) instead of
## reaching the control package's function, which fails on it without an
## identifier.
##
## @code{(num, den)} is the continuous-time @code{tf (num, den)};
## @code{(a, b, c, d)} the continuous-time @code{ss (a, b, c, d)}, input
## @var{iu} (default 1, as the pre-LTI toolbox).  @var{w}: frequencies in
## rad/s.  Without outputs the diagram is plotted (each output of a
## state-space model in turn is drawn by the control package's
## @code{bode}).
##
## @var{mag} (absolute value) and @var{phase} (degrees, continuous along
## @var{w}) are @code{numel (w)}-by-@var{ny}, the pre-LTI layout.
## @seealso{step, bodeplot}
## @end deftypefn

function varargout = bode (varargin)
  varargout = contsid_guard ({"bode", "double"}, @bode_body, nargout, varargin);
endfunction

function [mag, phase, w, varargout] = bode_body (varargin)
  contsid_nargchk ("bode", nargin, nargout, [2 6], 3);
  [sys, iu, w] = pre_lti_args ("bode", varargin);
  if (isempty (iu))
    iu = 1;
  endif
  ny = rows (sys);
  wargs = {};
  if (! isempty (w))
    wargs = {w(:).'};
  endif
  if (nargout == 0)
    for k = 1:ny
      if (ny > 1)
        subplot (1, ny, k);
      endif
      bode (sys(k, iu), wargs{:});
    endfor
    return;
  endif
  mag = [];
  phase = [];
  for k = 1:ny
    [m, p, w] = bode (sys(k, iu), wargs{:});
    mag(:, k) = m(:);
    phase(:, k) = p(:);
  endfor
  w = w(:);
endfunction

## the same numbers as the control package on the same model, and as the
## frequency response evaluated directly
%!test
%! pkg load control
%! w = logspace (-2, 2, 50);
%! [m, p, ww] = bode ([2 1], [1 3 2], w);
%! [mc, pc] = bode (tf ([2 1], [1 3 2]), w);
%! assert (m, mc(:), 1e-12);
%! assert (p, pc(:), 1e-12);
%! assert (ww, w(:));
%! H = polyval ([2 1], 1i * w) ./ polyval ([1 3 2], 1i * w);
%! assert (m, abs (H(:)), 1e-12);
%! a = [0 1; -2 -3]; b = [0 1; 1 0]; c = [1 0; 1 1]; d = zeros (2);
%! m1 = bode (a, b, c, d, 2, w);
%! assert (size (m1), [50, 2]);
%! for k = 1:50
%!   G2(k,:) = abs ((c / (1i * w(k) * eye (2) - a) * b)(:, 2)).';
%! endfor
%! assert (m1, G2, 1e-12);
%! m0 = bode (a, b, c, d, [], w);
%! for k = 1:50
%!   G1(k,:) = abs ((c / (1i * w(k) * eye (2) - a) * b)(:, 1)).';
%! endfor
%! assert (m0, G1, 1e-12);

## forwarding: calls with a model are the control package's own
%!test
%! pkg load control
%! sys = tf (1, [1 2 1]);
%! [m1, p1, w1] = bode (sys);
%! control = fileparts (fileparts (which ("tf")));
%! assert (which ("bode"), fullfile (control, "bode.m"));
%! assert (m1(:), abs (1 ./ polyval ([1 2 1], 1i * w1(:))), 1e-12);
%! h = figure ("visible", "off");
%! unwind_protect
%!   bode (1, [1 1]);
%!   assert (! isempty (findobj (h, "type", "line")));
%! unwind_protect_cleanup
%!   close (h);
%! end_unwind_protect

%!error id=bode:badInput bode (1)
%!error id=bode:badInput bode (4, [1 2.4 4], {1})
%!error id=bode:badInput bode (4, uint8 ([1 2 4]), struct ())
%!error id=bode:badInput bode (1, [0 0])
%!error id=bode:badInput bode (1, [1 1], [1 Inf])
%!error id=bode:dimensionMismatch bode (eye (2), [1; 1], [1 0 0], 0)
%!error id=bode:badInput bode (-1, 1, 1, 0, 3, 1:3)
%!error id=bode:badInput [a, b, c, d] = bode (1, [1 1])

%!demo
%! ## a CONTSID script's pre-LTI call
%! bode ([0.5 1], [1 1.2 1])
