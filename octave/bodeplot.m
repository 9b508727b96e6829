## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn  {} {} bodeplot (@var{sys})
## @deftypefnx {} {} bodeplot (@var{sys1}, @var{style1}, @var{sys2}, @
##   @var{style2}, @dots{}, @var{w}, @var{opt})
## @deftypefnx {} {@var{h} =} bodeplot (@dots{})
## Bode diagrams of several models in one figure (MATLAB's
## @code{bodeplot}, as CONTSID scripts call it:
## @code{bodeplot (M0, Moe, "g", Msrivc, "r", w, opt)}).
##
## @strong{Inputs}
## @table @var
## @item sys1, sys2, @dots{}
## control-package models (@code{tf}, @code{ss}, @code{zpk}, @code{frd}),
## continuous or discrete time, or any model object that @code{tf (sys)}
## (else @code{frd (sys)}) converts, such as the toolbox's identified
## models, or that has SITB's @code{idfrd} properties @code{ResponseData},
## @code{Frequency} and @code{Ts}.  A frequency-response-data model is
## drawn at its own frequencies.
## @item style
## line style of the model before it (@qcode{"r"}, @qcode{"b-"}, ...).
## @item w
## frequencies in rad/time unit, or @code{@{wmin, wmax@}}; default: the
## union of the control package's default ranges of the models.
## @item opt
## options from @code{bodeoptions} (see there for what is drawn).
## @end table
##
## Magnitude (dB by default) and phase (degrees, continuous along the
## frequency) of each input-output pair, in a grid of
## (2 @var{ny})-by-@var{nu} axes for the largest @var{ny}, @var{nu}.
## @var{h} returns the axes handles (magnitude axes first).  The response
## is @code{freqresp (sys, w)} of the control package.  Confidence regions
## are not drawn.
## @seealso{bodeoptions, stepplot, bode}
## @end deftypefn

function varargout = bodeplot (varargin)
  varargout = contsid_guard ("bodeplot", @bodeplot_body, nargout, varargin);
endfunction

function [h, varargout] = bodeplot_body (varargin)
  contsid_nargchk ("bodeplot", nargin, nargout, [0 Inf], 1);
  [systems, styles, range, opt] = ltiplot_args ("bodeplot", varargin);
  opt = read_options (opt);
  w = frequencies (systems, range);
  ny = max (cellfun ("rows", systems));
  nu = max (cellfun ("columns", systems));
  show = [strcmpi(opt.MagVisible, "on"), strcmpi(opt.PhaseVisible, "on")];
  nrow = ny * sum (show);
  if (nrow == 0)
    error ("bodeplot:badInput",
           "bodeplot: MagVisible and PhaseVisible are both off");
  endif
  ax = ltiplot_axes (nrow, nu);
  for k = 1:numel (systems)
    [H, wk] = response (systems{k}, w);
    x = wk;
    if (strcmpi (opt.FreqUnits, "Hz"))
      x = wk / (2*pi);
    endif
    style = styles{k};
    for i = 1:rows (systems{k})
      for j = 1:columns (systems{k})
        g = squeeze (H(i,j,:));
        r = (i - 1) * sum (show) + 1;
        if (show(1))
          plot (ax(r,j), x, magnitude (g, opt), style{:});
          r++;
        endif
        if (show(2))
          plot (ax(r,j), x, phase (g, opt), style{:});
        endif
      endfor
    endfor
  endfor
  decorate (ax, show, ny, opt);
  if (nargout > 0)
    h = ax;
  endif
endfunction

function opt = read_options (given)
  opt = bodeoptions ();
  if (isempty (given))
    return;
  endif
  if (! isscalar (given))
    error ("bodeplot:badInput", "bodeplot: 'opt' must be one options struct");
  endif
  drawn = {"Title", "XLabel", "YLabel", "Grid", "XLim", "XLimMode", ...
           "FreqUnits", "FreqScale", "MagUnits", "MagScale", "MagVisible", ...
           "PhaseUnits", "PhaseVisible", "PhaseWrapping"};
  default = opt;
  for [val, key] = given
    if (! isfield (opt, key))
      error ("bodeplot:badOption", "bodeplot: unknown option '%s'", key);
    endif
    if (! any (strcmp (key, drawn)) && ! isequal (val, default.(key)))
      warning ("bodeplot:notSupported",
               "bodeplot: option '%s' is not drawn", key);
    endif
    opt.(key) = val;
  endfor
  choices = {"FreqUnits",     {"rad/s", "rad/sec", "Hz"}
             "FreqScale",     {"log", "linear"}
             "MagUnits",      {"dB", "abs"}
             "MagScale",      {"log", "linear"}
             "MagVisible",    {"on", "off"}
             "PhaseUnits",    {"deg", "rad"}
             "PhaseVisible",  {"on", "off"}
             "PhaseWrapping", {"on", "off"}
             "Grid",          {"on", "off"}};
  for k = 1:rows (choices)
    val = opt.(choices{k,1});
    if (! (ischar (val) && any (strcmpi (val, choices{k,2}))))
      error ("bodeplot:badOption", "bodeplot: '%s' must be one of: %s",
             choices{k,1}, strjoin (choices{k,2}, ", "));
    endif
  endfor
endfunction

function w = frequencies (systems, range)
  if (iscell (range))
    if (numel (range) != 2 || ! all (cellfun (@is_positive_scalar, range))
        || range{1} >= range{2})
      error ("bodeplot:badInput",
             "bodeplot: {wmin, wmax} must be two increasing positive scalars");
    endif
    w = logspace (log10 (range{1}), log10 (range{2}), 500);
  elseif (! isempty (range))
    if (! (isreal (range) && isvector (range) && all (range > 0)
           && all (isfinite (range))))
      error ("bodeplot:badInput",
             "bodeplot: 'w' must be positive finite frequencies");
    endif
    w = sort (double (range(:).'));
  else
    lo = Inf;
    hi = 0;
    for k = 1:numel (systems)
      if (isa (systems{k}, "frd"))
        wk = systems{k}.w;
      else
        [~, ~, wk] = bode (systems{k}(1,1));
      endif
      lo = min (lo, min (wk(wk > 0)));
      hi = max (hi, max (wk));
    endfor
    w = logspace (log10 (lo), log10 (hi), 500);
  endif
endfunction

function ok = is_positive_scalar (v)
  ok = isnumeric (v) && isreal (v) && isscalar (v) && v > 0 && isfinite (v);
endfunction

function [H, w] = response (sys, w)
  if (isa (sys, "frd"))
    w = sys.w(:).';
    H = sys.H;
  else
    H = freqresp (sys, w);
  endif
endfunction

function m = magnitude (g, opt)
  m = abs (g);
  if (strcmpi (opt.MagUnits, "dB"))
    m = 20 * log10 (m);
  endif
endfunction

function p = phase (g, opt)
  p = unwrap (angle (g));
  if (strcmpi (opt.PhaseWrapping, "on"))
    p = mod (p + pi, 2*pi) - pi;
  endif
  if (strcmpi (opt.PhaseUnits, "deg"))
    p = p * 180 / pi;
  endif
endfunction

function decorate (ax, show, ny, opt)
  funits = opt.FreqUnits;
  xscale = opt.FreqScale;
  ylabels = opt.YLabel.String;
  if (ischar (ylabels))
    ylabels = {ylabels, ylabels};
  endif
  munit = {" (dB)", ""}{1 + strcmpi (opt.MagUnits, "abs")};
  punit = {" (deg)", " (rad)"}{1 + strcmpi (opt.PhaseUnits, "rad")};
  for r = 1:rows (ax)
    is_mag = show(1) && mod (r - 1, sum (show)) == 0;
    for c = 1:columns (ax)
      a = ax(r,c);
      hold (a, "off");
      set (a, "xscale", xscale);
      if (is_mag)
        set (a, "yscale", opt.MagScale);
      endif
      grid (a, opt.Grid);
      if (! isequal (opt.XLim, {[1 10]}))
        xl = opt.XLim;
        if (iscell (xl))
          xl = xl{1};
        endif
        xlim (a, xl);
      endif
      if (c == 1)
        if (is_mag)
          ylabel (a, [ylabels{1}, munit]);
        else
          ylabel (a, [ylabels{2}, punit]);
        endif
      endif
    endfor
  endfor
  title (ax(1,1), opt.Title.String);
  for c = 1:columns (ax)
    xlabel (ax(end,c), sprintf ("%s (%s)", opt.XLabel.String, funits));
  endfor
endfunction

## the drawn curves are the frequency responses, in the chosen units
%!test
%! pkg load control
%! fig = figure ("visible", "off");
%! unwind_protect
%!   s1 = tf (1, [1 0.4 1]);
%!   s2 = ss (-2, 1, 2, 0);
%!   w = logspace (-1, 1, 40);
%!   h = bodeplot (s1, s2, "r", w, bodeoptions ());
%!   assert (size (h), [2, 1]);
%!   lines = flipud (findobj (h(1), "type", "line"));
%!   assert (numel (lines), 2);
%!   H1 = 1 ./ polyval ([1 0.4 1], 1i * w);
%!   assert (get (lines(1), "ydata"), 20 * log10 (abs (H1)), 1e-10);
%!   assert (get (lines(2), "ydata"), 20 * log10 (abs (2 ./ (1i * w + 2))),
%!           1e-10);
%!   plines = flipud (findobj (h(2), "type", "line"));
%!   assert (get (plines(1), "ydata"), unwrap (angle (H1)) * 180 / pi, 1e-10);
%!   assert (get (lines(2), "color"), [1 0 0]);
%!   clf (fig);
%!   opt = bodeoptions;
%!   opt.FreqUnits = "Hz";
%!   opt.MagUnits = "abs";
%!   opt.PhaseVisible = "off";
%!   h = bodeplot (s1, {0.1, 10}, opt);
%!   assert (numel (h), 1);
%!   l = findobj (h, "type", "line");
%!   x = get (l, "xdata");
%!   assert (x([1 end]), [0.1, 10] / (2*pi), 1e-12);
%!   assert (get (l, "ydata"), abs (1 ./ polyval ([1 0.4 1], 2i*pi*x)), 1e-10);
%!   clf (fig);
%!   ## a discrete model, a MIMO model and a frequency-response data model
%!   f = frd (s1, w);
%!   h = bodeplot (c2d (s1, 0.1), ss ([-1 0; 0 -2], eye (2), eye (2), 0), f);
%!   assert (size (h), [4, 2]);
%!   clf (fig);
%!   ## an object with idfrd's properties (a struct stands in for one)
%!   g = struct ("ResponseData", reshape (freqresp (s1, w), 1, 1, []),
%!               "Frequency", w(:), "Ts", 0);
%!   h = bodeplot (g, s1, "r", w);
%!   lines = flipud (findobj (h(1), "type", "line"));
%!   assert (get (lines(1), "ydata"), get (lines(2), "ydata"), 1e-10);
%!   opt = bodeoptions;
%!   opt.PhaseMatching = "on";
%!   lastwarn ("");
%!   evalc ("bodeplot (s1, opt);");
%!   [~, id] = lastwarn ();
%!   assert (id, "bodeplot:notSupported");
%! unwind_protect_cleanup
%!   close (fig);
%! end_unwind_protect

%!shared s
%! pkg load control
%! s = tf (1, [1 1]);
%!error id=bodeplot:badInput bodeplot ()
%!error id=bodeplot:badInput bodeplot ("r", s)
%!error id=bodeplot:badInput bodeplot (s, "r", "b")
%!error id=bodeplot:badInput bodeplot (s, "linear")
%!error id=bodeplot:badInput bodeplot (s, 1:3, s)
%!error id=bodeplot:badInput bodeplot (s, 1:3, 1:3)
%!error id=bodeplot:badInput bodeplot (s, bodeoptions (), 1:3)
%!error id=bodeplot:badInput bodeplot (s, [-1 1])
%!error id=bodeplot:badInput bodeplot (s, {2, 1})
%!error id=bodeplot:badInput bodeplot (s, @sin)
%!error id=bodeplot:badOption bodeplot (s, struct ("Bogus", 1))
%!error id=bodeplot:badOption bodeplot (s, struct ("FreqUnits", "kHz"))
%!error id=bodeplot:badInput
%! bodeplot (s, struct ("MagVisible", "off", "PhaseVisible", "off"));

%!demo
%! s0 = tf (1, [1 0.4 1]);
%! s1 = tf (1.1, [1 0.5 1.05]);
%! opt = bodeoptions;
%! opt.FreqUnits = "Hz";
%! bodeplot (s0, s1, "r", logspace (-1, 1, 200), opt)
