## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn  {} {} stepplot (@var{sys})
## @deftypefnx {} {} stepplot (@var{sys1}, @var{style1}, @var{sys2}, @
##   @var{style2}, @dots{}, @var{t})
## @deftypefnx {} {@var{h} =} stepplot (@dots{})
## Step responses of several models in one figure (MATLAB's
## @code{stepplot}, as CONTSID scripts call it:
## @code{h = stepplot (M0, Msrivc, "r", Marx, "g")}).
##
## @strong{Inputs}
## @table @var
## @item sys1, sys2, @dots{}
## control-package models (@code{tf}, @code{ss}, @code{zpk}), continuous
## or discrete time, or any model object that @code{tf (sys)} converts,
## such as the toolbox's identified models.
## @item style
## line style of the model before it.
## @item t
## final time (scalar) or, for continuous-time models, a time vector;
## default: the longest of the control package's default final times of
## the models, so that all responses share one time axis.
## @end table
##
## The responses are the control package's @code{step (sys, t)}, drawn as
## lines (continuous time) or stairs (discrete time) in a grid of
## @var{ny}-by-@var{nu} axes; @var{h} returns the axes handles.  A
## trailing options struct (MATLAB's @code{timeoptions}) is not supported
## (@code{stepplot:notSupported}).
## @seealso{bodeplot, step}
## @end deftypefn

function varargout = stepplot (varargin)
  varargout = contsid_guard ("stepplot", @stepplot_body, nargout, varargin);
endfunction

function [h, varargout] = stepplot_body (varargin)
  contsid_nargchk ("stepplot", nargin, nargout, [0 Inf], 1);
  [systems, styles, range, opt] = ltiplot_args ("stepplot", varargin);
  if (! isempty (opt))
    error ("stepplot:notSupported", "stepplot: no options struct");
  endif
  if (any (cellfun (@(s) isa (s, "frd"), systems)))
    error ("stepplot:notSupported",
           "stepplot: a frequency-response-data model has no step response");
  endif
  if (isempty (range))
    tfinal = 0;
    for k = 1:numel (systems)
      [~, t] = step (systems{k});
      tfinal = max (tfinal, t(end));
    endfor
    range = tfinal;
  elseif (! (isnumeric (range) && isreal (range) && isvector (range)
             && all (isfinite (range)) && all (range >= 0)
             && (isscalar (range) && range > 0 || all (diff (range) > 0))))
    error ("stepplot:badInput",
           "stepplot: 't' must be a positive final time or increasing times");
  endif
  ny = max (cellfun ("rows", systems));
  nu = max (cellfun ("columns", systems));
  ax = ltiplot_axes (ny, nu);
  for k = 1:numel (systems)
    sys = systems{k};
    [y, t] = step (sys, range);
    style = styles{k};
    for i = 1:rows (sys)
      for j = 1:columns (sys)
        if (isct (sys))
          plot (ax(i,j), t, y(:,i,j), style{:});
        else
          stairs (ax(i,j), t, y(:,i,j), style{:});
        endif
      endfor
    endfor
  endfor
  for i = 1:ny
    for j = 1:nu
      hold (ax(i,j), "off");
    endfor
    ylabel (ax(i,1), "Amplitude");
  endfor
  title (ax(1,1), "Step Response");
  for j = 1:nu
    xlabel (ax(end,j), "Time");
  endfor
  if (nargout > 0)
    h = ax;
  endif
endfunction

## the drawn curves are the control package's step responses
%!test
%! pkg load control
%! fig = figure ("visible", "off");
%! unwind_protect
%!   s1 = tf (1, [1 0.4 1]);
%!   s2 = tf (2, [1 2]);
%!   h = stepplot (s1, s2, "r");
%!   lines = flipud (findobj (h, "type", "line"));
%!   assert (numel (lines), 2);
%!   [~, t1] = step (s1);
%!   [y2, t2] = step (s2, t1(end));
%!   assert (get (lines(2), "xdata")(:), t2, 1e-12);
%!   assert (get (lines(2), "ydata")(:), y2, 1e-12);
%!   assert (get (lines(2), "ydata")(:), 1 - exp (-2 * t2), 1e-8);
%!   assert (get (lines(2), "color"), [1 0 0]);
%!   clf (fig);
%!   h = stepplot (c2d (s1, 0.5), ss ([-1 0; 0 -2], eye (2), eye (2), 0), 5);
%!   assert (size (h), [2, 2]);
%!   assert (max (get (findobj (h(1,1), "type", "line"), "xdata"){1}), 5,
%!           1e-12);
%! unwind_protect_cleanup
%!   close (fig);
%! end_unwind_protect

%!shared s
%! pkg load control
%! s = tf (1, [1 1]);
%!error id=stepplot:badInput stepplot ()
%!error id=stepplot:badInput stepplot (s, -1)
%!error id=stepplot:badInput stepplot (s, [3 1 2])
%!error id=stepplot:badInput stepplot (s, {1})
%!error id=stepplot:badInput stepplot (s, "r", "g")
%!error id=stepplot:badInput stepplot (s, "linear")
%!error id=stepplot:notSupported stepplot (s, struct ("a", 1))
%!error id=stepplot:notSupported stepplot (frd (s, 1:3))

%!demo
%! s0 = tf (1, [1 0.4 1]);
%! s1 = tf (1.1, [1 0.5 1.05]);
%! h = stepplot (s0, s1, "r");
