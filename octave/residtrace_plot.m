## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn  {} {} residtrace_plot (@var{R})
## @deftypefnx {} {} residtrace_plot (@var{R}, @var{file})
## @deftypefnx {} {@var{ax} =} residtrace_plot (@dots{})
## The before/after figure of a @code{residtrace} result @var{R} on its
## validation record: the upper axis holds the measured output, the linear
## model (the re-estimate every effect was scored against,
## @code{R.sim.before}) and the model with the effects added
## (@code{R.sim.final_simulation}, simulated from the input), each labelled
## with its RMSE; the lower axis the two residuals, measured minus each
## model. The time axis starts at 0 at the validation record's first
## sample.
##
## Without @var{file} the axes are drawn in the current figure (in a new
## invisible one when Octave has no display). With
## @var{file} (a name whose extension, e.g. @file{.png}, @file{.pdf} or
## @file{.svg}, gives the format) the figure is drawn invisible, written
## there by @code{print} and closed: this works without a display.
## @var{ax} returns the two axes' handles (invalid once a file is
## written).
##
## @strong{Example}
## @example
## Ts = 0.05; u = prbs (9, 4); N = numel (u);
## y = simc (idctm (2, [1 1.2 1]), u + 0.4, Ts) + 0.05 * randn (N, 1);
## R = residtrace (iddata (y, u, Ts), srivc (iddata (y, u, Ts), [1 2 0]),
##                 "effects", @{"offset", "delay"@});
## residtrace_plot (R, [tempname() ".png"]);
## @end example
## @seealso{residtrace, residtrace_table, residtrace_sim}
## @end deftypefn

function varargout = residtrace_plot (varargin)
  varargout = contsid_guard ("residtrace_plot", @residtrace_plot_body, nargout, varargin);
endfunction

function [ax, varargout] = residtrace_plot_body (R, file, varargin)
  contsid_nargchk ("residtrace_plot", nargin, nargout, [1 2], 1);
  if (! isstruct (R) || ! isscalar (R) || ! isfield (R, "sim")
      || ! isfield (R, "model") || ! isfield (R, "effects")
      || ! isstruct (R.sim) || ! isa (R.model, "idtraced")
      || ! all (isfield (R.sim, {"y", "before", "final_simulation"})))
    error ("residtrace_plot:badInput",
           "residtrace_plot: R must be the result of residtrace");
  endif
  to_file = nargin > 1;
  if (to_file && ! (ischar (file) && rows (file) == 1 && ! isempty (file)))
    error ("residtrace_plot:badInput",
           "residtrace_plot: FILE must be a file name");
  endif
  y = R.sim.y;
  lin = R.sim.before;
  fin = R.sim.final_simulation;
  n = numel (y);
  if (! (isnumeric (lin) && isnumeric (fin) && isnumeric (y)
         && numel (lin) == n && numel (fin) == n && n > 1
         && isscalar (R.model.Ts) && R.model.Ts > 0 && iscellstr (R.effects)))
    error ("residtrace_plot:badInput",
           "residtrace_plot: R must be the result of residtrace");
  endif
  t = (0:n-1)' * R.model.Ts;
  rms_ = @(e) sqrt (mean (e .^ 2));
  effects = "no effect added";
  if (! isempty (R.effects))
    effects = ["+ " strjoin(R.effects, ", ")];
  endif
  if (to_file || ! have_window_system ())
    fig = figure ("visible", "off");   # without a display: drawn unseen
  else
    fig = gcf ();
    clf (fig);
  endif
  unwind_protect
    ax(1) = subplot (2, 1, 1, "parent", fig);
    plot (ax(1), t, y, "k", t, lin, "b", t, fin, "r");
    legend (ax(1), {"measured", ...
                    sprintf("linear (RMSE %.4g)", rms_ (y - lin)), ...
                    sprintf("linear %s (RMSE %.4g)", effects,
                            rms_ (y - fin))}, "location", "northeastoutside");
    ylabel (ax(1), "output");
    title (ax(1), "residtrace: validation record");
    ax(2) = subplot (2, 1, 2, "parent", fig);
    plot (ax(2), t, y - lin, "b", t, y - fin, "r");
    legend (ax(2), {"residual, linear", "residual, with the effects"},
            "location", "northeastoutside");
    xlabel (ax(2), "time (s) from the validation record's start");
    ylabel (ax(2), "residual");
    if (to_file)
      try
        print (fig, file);
      catch err
        error ("residtrace_plot:badInput",
               "residtrace_plot: cannot write '%s' (%s)", file, err.message);
      end_try_catch
    endif
  unwind_protect_cleanup
    if (to_file)
      close (fig);
    endif
  end_unwind_protect
endfunction

%!test  # written without a display; the curves are those of R.sim
%! randn ("state", 3);
%! Ts = 0.05; u = prbs (9, 4); N = numel (u);
%! y = simc (idctm (2, [1 1.2 1]), u + 0.4, Ts) + 0.05 * randn (N, 1);
%! R = residtrace (iddata (y, u, Ts), srivc (iddata (y, u, Ts), [1 2 0]),
%!                 "effects", {"offset"}, "iterate", 1);
%! f = [tempname() ".png"];
%! unwind_protect
%!   residtrace_plot (R, f);
%!   s = dir (f);
%!   assert (numel (s), 1);
%!   assert (s.bytes > 1000);
%! unwind_protect_cleanup
%!   if (exist (f, "file"))
%!     delete (f);
%!   endif
%! end_unwind_protect
%! fig = figure ("visible", "off");
%! unwind_protect
%!   ax = residtrace_plot (R);
%!   l = get (ax(2), "children");
%!   yd = sort (cellfun (@(h) sum (get (h, "ydata") .^ 2), num2cell (l)));
%!   e = sort ([sum((R.sim.y - R.sim.before) .^ 2), ...
%!              sum((R.sim.y - R.sim.final_simulation) .^ 2)]);
%!   assert (yd(:), e(:), 1e-9 * max (e));
%! unwind_protect_cleanup
%!   close (fig);
%! end_unwind_protect

%!error id=residtrace_plot:badInput residtrace_plot (struct ("a", 1))
%!error id=residtrace_plot:badInput residtrace_plot (3)
