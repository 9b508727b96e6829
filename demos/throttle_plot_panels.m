## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn {} {} throttle_plot_panels (@var{file}, @var{t}, @var{step}, @
##   @var{panels}, @var{ncol})
## Helper of the throttle demos: writes a PNG of the panels in the cell
## array @var{panels}, laid out in @var{ncol} columns (default 1). Each
## panel is a struct with fields @code{series} (cell of N-by-1 vectors),
## @code{labels} (legend entries; "true" is drawn thick black),
## @code{ylabel} (colours: "true" black, RLSSVF red, CLRSRIVC blue, others
## green, red, blue, magenta by position), and optionally @code{title},
## @code{ylim} and @code{vlines} (times marked by dotted lines). Every
## @var{step}-th sample is drawn. Uses gnuplot off-screen.
## @end deftypefn

function throttle_plot_panels (file, t, step, panels, ncol = 1)
  warning ("off", "Octave:gnuplot-graphics");
  graphics_toolkit ("gnuplot");
  n = numel (panels);
  nrow = ceil (n / ncol);
  f = figure ("visible", "off", "position", [0 0 (450 + 450 * ncol) ...
                                            (150 + 220 * nrow)]);
  idx = 1:step:numel (t);
  for k = 1:n
    pnl = panels{k};
    subplot (nrow, ncol, k);
    for j = 1:numel (pnl.series)
      h = plot (t(idx), pnl.series{j}(idx));
      set (h, "color", colour_of (pnl.labels{j}, j));
      if (strcmp (pnl.labels{j}, "true"))
        set (h, "linewidth", 1.5);
      endif
      hold on;
    endfor
    if (isfield (pnl, "ylim"))
      ylim (pnl.ylim);
    endif
    if (isfield (pnl, "vlines"))
      yl = ylim ();
      for tv = pnl.vlines(:)'
        plot ([tv tv], yl, ":", "color", [0.4 0.4 0.4]);
      endfor
    endif
    hold off;
    xlim ([t(1) t(end)]);
    ylabel (pnl.ylabel);
    grid on;
    if (isfield (pnl, "title"))
      title (pnl.title);
    endif
    if (numel (pnl.labels) > 1)
      legend (pnl.labels{:}, "location", "northeast", "orientation",
              "horizontal");
    endif
    if (k > n - ncol)
      xlabel ("time (s)");
    endif
  endfor
  print (f, "-dpng", "-r90", file);
  close (f);
endfunction

function c = colour_of (label, j)
  ## Fixed colours for the methods, else by position in the panel.
  switch (label)
    case "true"
      c = [0 0 0];
    case "RLSSVF"
      c = [0.85 0 0];
    case "CLRSRIVC"
      c = [0 0 0.9];
    otherwise
      palette = [0 0.6 0; 0.85 0 0; 0 0 0.9; 0.8 0 0.8];
      c = palette(mod (j - 1, rows (palette)) + 1, :);
  endswitch
endfunction
