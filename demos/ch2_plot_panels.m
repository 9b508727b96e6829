## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn {} {} ch2_plot_panels (@var{file}, @var{t}, @var{step}, @var{cols})
## Helper of the Chapter 2 demos: writes a PNG with one row per parameter
## (a1, a2, b0) and one column per element of the cell array @var{cols}.
## Each column is a struct with fields @code{series} (cell of N-by-3
## matrices), @code{labels} (their legend entries; "true" is drawn thick
## black), @code{title}, and optionally @code{logy} (false),
## @code{unit} (appended to the y labels), @code{ylims} (1-by-3 upper
## limits; otherwise the limits leave head room for the legend) and
## @code{vlines} (times marked by dotted vertical lines). Every
## @var{step}-th sample is drawn. Uses gnuplot off-screen.
## @end deftypefn

function ch2_plot_panels (file, t, step, cols)
  warning ("off", "Octave:gnuplot-graphics");
  graphics_toolkit ("gnuplot");
  ncol = numel (cols);
  f = figure ("visible", "off", "position", [0 0 (500 + 400 * ncol) 700]);
  names = {"a_1", "a_2", "b_0"};
  idx = 1:step:numel (t);
  for c = 1:ncol
    col = cols{c};
    logy = isfield (col, "logy") && col.logy;
    unit = "";
    if (isfield (col, "unit"))
      unit = col.unit;
    endif
    for i = 1:3
      subplot (3, ncol, (i - 1) * ncol + c);
      for j = 1:numel (col.series)
        if (logy)
          h = semilogy (t(idx), col.series{j}(idx, i));
        else
          h = plot (t(idx), col.series{j}(idx, i));
        endif
        set (h, "color", colour_of (col.labels{j}));
        if (strcmp (col.labels{j}, "true"))
          set (h, "linewidth", 1.5);
        endif
        hold on;
      endfor
      ## Head room for the legend above the curves.
      v = cellfun (@(z) z(idx, i), col.series, "uniformoutput", false);
      v = vertcat (v{:});
      v = v(isfinite (v));
      if (isfield (col, "ylims") && ! isempty (col.ylims))
        yl = [0 col.ylims(i)];
      elseif (logy)
        v = v(v > 0);
        yl = [max(min (v) / 2, max (v) * 1e-4), max(v) * 30];
      else
        yl = [min(0, min (v)), 1.4 * max(v)];
      endif
      if (isfield (col, "vlines"))
        for tv = col.vlines(:)'
          plot ([tv tv], yl, ":", "color", [0.4 0.4 0.4]);
        endfor
      endif
      hold off;
      ylim (yl);
      xlim ([t(1) t(end)]);
      ylabel ([names{i} unit]);
      grid on;
      if (i == 1)
        title (col.title);
        legend (col.labels{:}, "location", "northeast", "orientation",
                "horizontal");
      endif
      if (i == 3)
        xlabel ("time (s)");
      endif
    endfor
  endfor
  print (f, "-dpng", "-r90", file);
  close (f);
endfunction

function c = colour_of (label)
  switch (label)
    case "true"
      c = [0 0 0];
    case {"RLSSVF", "RLSSVF noise-free", "RLSSVF noisy"}
      c = [0.85 0 0];
    case {"RIVSVF", "CLRIVSVF"}
      c = [0.8 0 0.8];
    case {"RSRIVC", "CLRSRIVC"}
      c = [0 0 0.9];
    otherwise
      c = [0 0.6 0];
  endswitch
endfunction
