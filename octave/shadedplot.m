## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn  {} {} shadedplot (@var{t}, @var{y}, @var{ys})
## @deftypefnx {} {[@var{hfill}, @var{hy}, @var{hys}] =} shadedplot (@dots{})
## Plot a measured output @var{y} and a model output @var{ys} against
## @var{t}, with the gap between them shaded: the picture of the CONTSID
## demos after @code{comparec} (RIVC, tutorials 1 and 2:
## @code{shadedplot (t, data.y, ys)}).  The shaded band is the model
## error y - ys; where the two coincide it vanishes.
##
## @var{t}, @var{y} and @var{ys} are real vectors of the same length (the
## instants, the measured output, the simulated output); @var{y} and
## @var{ys} may also be N-by-1 matrices.  Non-finite values are bad input.
## Draws into the current axes (holding them while it draws, leaving the
## hold state as it found it); returns the handles of the patch and of
## the two lines.
## @seealso{comparec, plot, fill}
## @end deftypefn

function varargout = shadedplot (varargin)
  varargout = contsid_guard ("shadedplot", @shadedplot_body, nargout, varargin);
endfunction

function [hfill, hy, varargout] = shadedplot_body (varargin)
  contsid_nargchk ("shadedplot", nargin, nargout, [3 3], 3);
  [t, y, ys] = varargin{:};
  t = vec_of (t, "t");
  y = vec_of (y, "y");
  ys = vec_of (ys, "ys");
  if (numel (y) != numel (t) || numel (ys) != numel (t))
    error ("shadedplot:dimensionMismatch",
           "shadedplot: 't', 'y' and 'ys' must have the same length (%d, %d, %d)",
           numel (t), numel (y), numel (ys));
  endif
  ax = gca ();
  held = ishold (ax);
  hf = fill (ax, [t; flipud(t)], [y; flipud(ys)], [1 0.85 0.85],
             "EdgeColor", "none");
  hold (ax, "on");
  h1 = plot (ax, t, y, "b-");
  h2 = plot (ax, t, ys, "r-", "LineWidth", 1.5);
  if (! held)
    hold (ax, "off");
  endif
  legend ([h1, h2, hf], {"measured output", "model output", "error"});
  xlabel (ax, "time");
  if (nargout > 0)
    hfill = hf;
    hy = h1;
    varargout = {h2};
  endif
endfunction

function v = vec_of (v, name)
  if (! isnumeric (v) || ! isreal (v) || isempty (v) || ! isvector (v)
      || any (! isfinite (v)))
    error ("shadedplot:badInput",
           "shadedplot: '%s' must be a non-empty real finite vector", name);
  endif
  v = double (v(:));
endfunction

%!test  # the patch encloses y - ys; the lines carry the data
%! h = figure ("visible", "off");
%! unwind_protect
%!   t = (0:0.1:2)'; y = sin (t); ys = 0.9 * sin (t);
%!   [hf, hy, hys] = shadedplot (t, y, ys);
%!   assert (get (hy, "xdata")(:), t);
%!   assert (get (hy, "ydata")(:), y);
%!   assert (get (hys, "ydata")(:), ys);
%!   xd = get (hf, "xdata"); yd = get (hf, "ydata");
%!   assert (xd(:), [t; flipud(t)]);
%!   assert (yd(:), [y; flipud(ys)]);
%!   ## the shoelace area of the band is the integral of |y - ys| (here
%!   ## y >= ys), by the trapezoidal rule
%!   A = abs (sum (xd(:) .* circshift (yd(:), -1)
%!                 - circshift (xd(:), -1) .* yd(:))) / 2;
%!   assert (A, trapz (t, y - ys), 1e-12);
%!   assert (! ishold ());
%!   hold on; shadedplot (t, y, ys); assert (ishold ());
%!   shadedplot (t', y', ys');         # rows are accepted
%! unwind_protect_cleanup
%!   close (h);
%! end_unwind_protect

%!error id=shadedplot:badInput shadedplot (1:3, 1:3)
%!error id=shadedplot:badInput shadedplot ("abc", 1:3, 1:3)
%!error id=shadedplot:badInput shadedplot (1:3, [1 NaN 2], 1:3)
%!error id=shadedplot:badInput shadedplot (1:3, ones (3), 1:3)
%!error id=shadedplot:badInput shadedplot ([], [], [])
%!error id=shadedplot:dimensionMismatch shadedplot (1:3, 1:3, 1:4)
%!error id=shadedplot:badInput [a, b, c, d] = shadedplot (1:3, 1:3, 1:3)

%!demo
%! t = (0:0.05:10)';
%! y = exp (-0.3 * t) .* sin (2 * t) + 0.05 * randn (size (t));
%! ys = exp (-0.3 * t) .* sin (2 * t);
%! shadedplot (t, y, ys);
