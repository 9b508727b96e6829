## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn  {} {} idplot (@var{data})
## @deftypefnx {} {} idplot (@var{data}, @var{int})
## @deftypefnx {} {} idplot (@var{data}, @var{int}, @var{Ts})
## @deftypefnx {} {} idplot (@var{z}, @var{int}, @var{Ts}, @var{ny}, @var{pc})
## @deftypefnx {} {@var{ax} =} idplot (@dots{})
## Plot input-output data (the System Identification Toolbox's older
## @code{idplot}, used by CONTSID scripts: @code{idplot (data, 1:1000, Ts)}).
##
## @strong{Inputs}
## @table @var
## @item data, z
## a single-experiment time-domain @code{iddata} set, or a matrix
## @code{[y, u]} with the @var{ny} outputs first.
## @item int
## the sample indices to plot (default all), increasing.
## @item Ts
## sampling interval for the time axis: the samples are drawn at
## @code{(int - 1) * Ts}.  Default: the set's sampling instants (for a
## matrix, 1).
## @item ny
## number of output columns of @var{z} (default 1); ignored for an
## @code{iddata} set.
## @item pc
## @qcode{"zoh"} (default for a matrix; the set's @code{InterSample}
## otherwise) draws the inputs as stairs, @qcode{"foh"} as lines.
## @end table
##
## One axis per output, then one per input, stacked in the current figure;
## @var{ax} returns their handles.
## @seealso{plot, iddata}
## @end deftypefn

function varargout = idplot (varargin)
  varargout = contsid_guard ("idplot", @idplot_body, nargout, varargin);
endfunction

function [ax, varargout] = idplot_body (z, int = [], Ts = [], ny = 1,
                                        pc = "", varargin)
  contsid_nargchk ("idplot", nargin, nargout, [0 Inf], 1);
  if (nargin < 1 || nargin > 5)
    error ("idplot:badInput",
           "idplot: takes 1 to 5 arguments, not %d", nargin);
  endif
  if (isa (z, "iddata"))
    if (size (z, 4) != 1 || ! strcmp (get (z, "Domain"), "Time"))
      error ("idplot:badInput",
             "idplot: 'data' must be one time-domain experiment");
    endif
    y = z.y;
    u = z.u;
    t = z.SamplingInstants;
    if (isempty (pc))
      pc = z.InterSample;
    endif
    ynames = z.OutputName;
    unames = z.InputName;
  elseif ((isnumeric (z) || islogical (z)) && ismatrix (z) && isreal (z)
          && ! isempty (z))
    if (! (isnumeric (ny) && isscalar (ny) && ny >= 0 && ny == fix (ny)
           && ny <= columns (z)))
      error ("idplot:badInput",
             "idplot: 'ny' must be an integer from 0 to %d", columns (z));
    endif
    y = double (z(:,1:ny));
    u = double (z(:,ny+1:end));
    t = (0:rows (z)-1).';
    if (isempty (pc))
      pc = "zoh";
    endif
    ynames = repmat ({""}, ny, 1);
    unames = repmat ({""}, columns (u), 1);
  else
    error ("idplot:badInput",
           "idplot: 'data' must be an iddata set or a real matrix [y u]");
  endif
  n = rows (y);
  if (isempty (int))
    int = 1:n;
  elseif (! (isnumeric (int) && isreal (int) && isvector (int)
             && all (int == fix (int))
             && all (int >= 1 & int <= n) && all (diff (int) > 0)))
    error ("idplot:badInput",
           "idplot: 'int' must be increasing sample indices from 1 to %d", n);
  endif
  if (! isempty (Ts))
    if (! (isnumeric (Ts) && isscalar (Ts) && isreal (Ts) && Ts > 0))
      error ("idplot:badInput", "idplot: 'Ts' must be a positive scalar");
    endif
    t = (0:n-1).' * Ts;
  endif
  if (! (ischar (pc) && any (strcmpi (pc, {"zoh", "foh", "bl"}))))
    error ("idplot:badInput", "idplot: 'pc' must be \"zoh\" or \"foh\"");
  endif
  int = int(:);
  nax = columns (y) + columns (u);
  if (nax == 0)
    error ("idplot:badInput", "idplot: no signals to plot");
  endif
  ## Octave's axes cannot place ticks on a range near realmax (it runs out
  ## of memory): such values are refused, as times and frequencies above
  ## 1e100 are by the models' plots.
  big = @(v) any (abs (v(isfinite (v))) > 1e100);
  if (big (t(int)) || big (y(int,:)) || big (u(int,:)))
    error ("idplot:badInput",
           "idplot: times or values above 1e100 cannot be plotted");
  endif
  h = zeros (nax, 1);
  for c = 1:columns (y)
    h(c) = subplot (nax, 1, c);
    plot (h(c), t(int), y(int,c));
    ylabel (h(c), label (ynames, c, "y"));
  endfor
  for c = 1:columns (u)
    a = columns (y) + c;
    h(a) = subplot (nax, 1, a);
    if (strcmpi (pc, "zoh"))
      stairs (h(a), t(int), u(int,c));
    else
      plot (h(a), t(int), u(int,c));
    endif
    ylabel (h(a), label (unames, c, "u"));
  endfor
  xlabel (h(end), "Time");
  if (nargout > 0)
    ax = h;
  endif
endfunction

function str = label (names, c, prefix)
  str = names{c};
  if (isempty (str))
    str = sprintf ("%s%d", prefix, c);
  endif
endfunction

%!test
%! fig = figure ("visible", "off");
%! unwind_protect
%!   y = sin ((1:100).' / 5);
%!   u = sign (y);
%!   ax = idplot (iddata (y, u, 0.5), 11:60, 0.5);
%!   assert (numel (ax), 2);
%!   line = findobj (ax(1), "type", "line");
%!   assert (get (line, "xdata")(:), (10:59).' * 0.5, 1e-12);
%!   assert (get (line, "ydata")(:), y(11:60));
%!   clf (fig);
%!   ax = idplot ([y, 2*y, u], 1:20, 2, 2, "foh");
%!   assert (numel (ax), 3);
%!   assert (get (findobj (ax(3), "type", "line"), "ydata")(:), u(1:20));
%!   clf (fig);
%!   t = cumsum (0.1 + (1:100).' / 1000);
%!   ax = idplot (iddata (y, u, "SamplingInstants", t));
%!   assert (get (findobj (ax(1), "type", "line"), "xdata")(:), t, 1e-12);
%! unwind_protect_cleanup
%!   close (fig);
%! end_unwind_protect

%!error id=idplot:badInput idplot (realmax)
%!error id=idplot:badInput idplot ([1 2; 3 4], [], realmax)
%!error id=idplot:badInput idplot ({1})
%!error id=idplot:badInput idplot (ones (5, 2), 0:2)
%!error id=idplot:badInput idplot (ones (5, 2), [3 2])
%!error id=idplot:badInput idplot (ones (5, 2), 1i)
%!error id=idplot:badInput idplot (ones (5, 2), 1:3, -1)
%!error id=idplot:badInput idplot (ones (5, 2), 1:3, 1, 3)
%!error id=idplot:badInput idplot (ones (5, 2), 1:3, 1, 1, "x")
%!error id=idplot:badInput idplot (merge (iddata (1, 1, 1), iddata (1, 1, 1)))
%!error id=idplot:badInput idplot ()
%!error id=idplot:badInput idplot (ones (5, 2), 1:3, 1, 1, "zoh", 6)

%!demo
%! Ts = 0.05;
%! u = prbs (7, 4);
%! y = filter (0.1, [1 -0.9], u);
%! data = iddata (y, u, Ts, "InterSample", "zoh");
%! idplot (data, 1:300, Ts)
