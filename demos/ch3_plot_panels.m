## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn {} {} ch3_plot_panels (@var{file}, @var{panels}, @var{ncol})
## Helper of the Chapter 3 demos: writes a PNG with one panel per element
## of the cell array @var{panels}, laid out in @var{ncol} columns (default
## 1). Each panel is a struct with fields @code{t} (time vector),
## @code{series} (cell of vectors or matrices with rows(t) rows),
## @code{labels} (one legend entry per series; "true" is drawn thick
## black, "thesis" dashed) and optionally @code{title}, @code{ylabel},
## @code{xlabel} (default "time (s)"), @code{logy} (false), @code{logx}
## (false), @code{ylim}, @code{xlim}, @code{vlines} (times marked by
## dotted vertical lines), @code{styles} (cell of line styles, one per
## series) and @code{step} (draw every step-th sample, default 1).
## Uses gnuplot off-screen.
## @end deftypefn

function ch3_plot_panels (file, panels, ncol = 1)
  warning ("off", "Octave:gnuplot-graphics");
  graphics_toolkit ("gnuplot");
  np = numel (panels);
  nrow = ceil (np / ncol);
  f = figure ("visible", "off",
              "position", [0 0 (200 + 550 * ncol) (120 + 230 * nrow)]);
  colours = [0.85 0 0; 0 0 0.9; 0 0.6 0; 0.8 0 0.8; 0.9 0.5 0; 0 0.6 0.7];
  for p = 1:np
    pan = panels{p};
    subplot (nrow, ncol, p);
    step = field_or (pan, "step", 1);
    idx = 1:step:rows (pan.t);
    styles = field_or (pan, "styles", {});
    c = 0;
    for j = 1:numel (pan.series)
      v = pan.series{j};
      if (field_or (pan, "logy", false) && field_or (pan, "logx", false))
        h = loglog (pan.t(idx), v(idx, :));
      elseif (field_or (pan, "logy", false))
        h = semilogy (pan.t(idx), v(idx, :));
      elseif (field_or (pan, "logx", false))
        h = semilogx (pan.t(idx), v(idx, :));
      else
        h = plot (pan.t(idx), v(idx, :));
      endif
      label = pan.labels{j};
      if (strcmp (label, "true"))
        set (h, "color", [0 0 0], "linewidth", 1.5);
      else
        c = mod (c, rows (colours)) + 1;
        set (h, "color", colours(c, :));
      endif
      if (j <= numel (styles) && ! isempty (styles{j}))
        set (h, "linestyle", styles{j});
      endif
      hold on;
    endfor
    if (isfield (pan, "xlim"))
      xlim (pan.xlim);
    else
      xlim ([pan.t(1) pan.t(end)]);
    endif
    if (isfield (pan, "ylim"))
      ylim (pan.ylim);
    endif
    if (isfield (pan, "vlines"))
      yl = ylim ();
      for tv = pan.vlines(:)'
        plot ([tv tv], yl, ":", "color", [0.4 0.4 0.4]);
      endfor
    endif
    hold off;
    grid on;
    if (isfield (pan, "title"))
      title (pan.title);
    endif
    if (isfield (pan, "ylabel"))
      ylabel (pan.ylabel);
    endif
    xlabel (field_or (pan, "xlabel", "time (s)"));
    if (numel (pan.labels) > 1 || ! strcmp (pan.labels{1}, ""))
      legend (pan.labels{:}, "location", field_or (pan, "legend", "northeast"));
    endif
  endfor
  print (f, "-dpng", "-r80", file);
  close (f);
endfunction

function v = field_or (s, name, default)
  if (isfield (s, name))
    v = s.(name);
  else
    v = default;
  endif
endfunction
