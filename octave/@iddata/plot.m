## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn  {} {} plot (@var{data})
## @deftypefnx {} {} plot (@var{d1}, @var{style1}, @var{d2}, @var{style2}, @
##   @dots{})
## @deftypefnx {} {} plot (@var{data}, @var{exp})
## @deftypefnx {} {@var{ax} =} plot (@dots{})
## Plot the signals of one or several @code{iddata} sets, as MATLAB does:
## one axis per output channel, then one per input channel, stacked in
## the current figure, the sets overlaid with their line styles
## (@code{plot (datadet(400:700), "b", data(400:700), "r")}).
##
## Time-domain signals are drawn against their sampling instants (the time
## axis is @code{data.SamplingInstants}; with @code{Ts} unspecified, the
## sample index), inputs as stairs for @code{InterSample}
## @qcode{"zoh"} and as lines for @qcode{"foh"} and @qcode{"bl"}.
## Frequency-domain signals are drawn as magnitudes in dB against the
## frequency.  Experiments of a multi-experiment set are overlaid; the
## control package's form @code{plot (data, exp)} selects experiments
## first.  Channels are matched by position: a set with fewer channels
## leaves the others empty.
##
## @var{ax} returns the handles of the axes, outputs first.  The sets must
## be all in the time domain or all in the frequency domain
## (@code{iddata:badInput}).
## @seealso{idplot, iddata}
## @end deftypefn

function varargout = plot (varargin)
  varargout = contsid_guard ({"plot", "iddata"}, @plot_body, nargout, varargin);
endfunction

function [ax, varargout] = plot_body (varargin)
  contsid_nargchk ("plot", nargin, nargout, [0 Inf], 1);
  [sets, styles] = parse_args (varargin);
  timedomain = cellfun (@(d) struct (d).timedomain, sets);
  if (any (timedomain != timedomain(1)))
    error ("iddata:badInput",
           ["iddata: plot: cannot plot time- and frequency-domain sets ", ...
            "together"]);
  endif
  ny = max (cellfun (@(d) size (d, 2), sets));
  nu = max (cellfun (@(d) size (d, 3), sets));
  nax = ny + nu;
  if (nax == 0)
    error ("iddata:badInput", "iddata: plot: the sets have no signals");
  endif
  h = zeros (nax, 1);
  for a = 1:nax
    h(a) = subplot (nax, 1, a);
    hold (h(a), "on");
  endfor
  for k = 1:numel (sets)
    draw_set (sets{k}, styles{k}, h, ny);
  endfor
  for a = 1:nax
    hold (h(a), "off");
  endfor
  first = struct (sets{1});
  labels = [channel_labels(first.outname, ny, "y"), ...
            channel_labels(first.inname, nu, "u")];
  for a = 1:nax
    ylabel (h(a), labels{a});
  endfor
  if (timedomain(1))
    xlabel (h(end), time_label (first.timeunit));
  else
    xlabel (h(end), "Frequency (rad/time unit)");
  endif
  if (nargout > 0)
    ax = h;
  endif
endfunction

function [sets, styles] = parse_args (args)
  if (numel (args) == 2 && isa (args{1}, "iddata") && isnumeric (args{2}))
    sets = {index_data(args{1}, {":", ":", ":", args{2}})};
    styles = {""};
    return;
  endif
  sets = {};
  styles = {};
  for k = 1:numel (args)
    if (isa (args{k}, "iddata"))
      sets{end+1} = args{k};
      styles{end+1} = "";
    elseif (ischar (args{k}) && rows (args{k}) <= 1 && ! isempty (sets)
            && isempty (styles{end}))
      [~, valid] = __pltopt__ ("plot", args{k}, false);
      if (! valid)
        error ("iddata:badInput",
               "iddata: plot: argument %d: '%s' is not a line style", k,
               args{k});
      endif
      styles{end} = args{k};
    else
      error ("iddata:badInput",
             ["iddata: plot: argument %d: expected an iddata set or a ", ...
              "line style after one"], k);
    endif
  endfor
endfunction

function draw_set (dat, style, h, ny)
  s = struct (dat);
  style_args = {};
  if (! isempty (style))
    style_args = {style};
  endif
  if (s.timedomain)
    info = samplinginfo (dat);
  endif
  for e = 1:numel (s.y)
    if (s.timedomain)
      x = info(e).SamplingInstants;
      if (info(e).Uniform && info(e).Ts < 0)
        x = (1:rows (s.y{e})).';
      endif
      ysig = s.y{e};
    else
      x = s.w{e};
      ysig = 20 * log10 (abs (s.y{e}));
    endif
    for c = 1:columns (ysig)
      plot (h(c), x, ysig(:,c), style_args{:});
    endfor
    if (isempty (s.u))
      continue;
    endif
    for c = 1:columns (s.u{e})
      if (! s.timedomain)
        plot (h(ny + c), x, 20 * log10 (abs (s.u{e}(:,c))), style_args{:});
      elseif (strcmp (info(e).InterSample, "zoh"))
        stairs (h(ny + c), x, s.u{e}(:,c), style_args{:});
      else
        plot (h(ny + c), x, s.u{e}(:,c), style_args{:});
      endif
    endfor
  endfor
endfunction

function names = channel_labels (names, n, prefix)
  names = names(:).';
  names(end+1:n) = {""};
  for k = find (cellfun ("isempty", names))
    names{k} = sprintf ("%s%d", prefix, k);
  endfor
endfunction

function str = time_label (unit)
  if (isempty (unit))
    str = "Time";
  else
    str = sprintf ("Time (%s)", unit);
  endif
endfunction

%!shared fig, y, u
%! y = sin ((0:99).' / 10);
%! u = sign (y);

%!test  # sets with different numbers of inputs: one axis per channel
%! v = sin ((1:40)' / 5);
%! f = figure ("visible", "off");
%! h = plot (iddata (v, v, 1), iddata (v, [v 2*v], 1));
%! assert (numel (h), 3);
%! close (f);

%!test
%! fig = figure ("visible", "off");
%! unwind_protect
%!   d1 = iddata (y, u, 0.1);
%!   d2 = iddata (2 * y, u, 0.1, "InterSample", "foh");
%!   ax = plot (d1(40:70), "b", d2(40:70), "r");
%!   assert (numel (ax), 2);
%!   lines = findobj (ax(1), "type", "line");
%!   assert (numel (lines), 2);
%!   assert (sort (cellfun (@(v) max (v), get (lines, "ydata"))),
%!           sort ([max(y(40:70)); 2*max(y(40:70))]));
%!   assert (get (lines(end), "xdata")(:), (0:30).' * 0.1, 1e-12);
%!   clf (fig);
%!   ax = plot (iddata ([y, -y], [], 0.1));
%!   assert (numel (ax), 2);
%!   clf (fig);
%!   ax = plot (fft (iddata (y, u, 0.1)));
%!   assert (numel (ax), 2);
%!   clf (fig);
%!   ax = plot (merge (d1, d1), 2);
%!   assert (numel (findobj (ax(1), "type", "line")), 1);
%! unwind_protect_cleanup
%!   close (fig);
%! end_unwind_protect

%!error id=iddata:badInput plot (iddata (y, u, 0.1), "b", "r")
%!error id=iddata:badInput plot (iddata (y, u, 0.1), "linear")
%!error id=iddata:badInput plot (iddata (y, u, 0.1), 3, iddata (y, u, 0.1))
%!error id=iddata:badInput plot (iddata (y, u, 0.1), fft (iddata (y, u, 0.1)))

%!demo
%! t = (0:0.1:30).';
%! u = sign (sin (0.5 * t));
%! data = iddata (filter (0.1, [1 -0.9], u) + 0.05 * randn (size (t)), u, 0.1);
%! datadet = iddata (filter (0.1, [1 -0.9], u), u, 0.1);
%! plot (datadet(100:200), "b", data(100:200), "r")
