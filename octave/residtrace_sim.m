## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn  {} {[@var{yh}, @var{e}, @var{rmse}] =} residtrace_sim (@var{R}, @var{data})
## @deftypefnx {} {[@dots{}] =} residtrace_sim (@var{R}, @var{y}, @var{u}, @var{Ts})
## @deftypefnx {} {[@dots{}] =} residtrace_sim (@dots{}, "model", @var{which})
## Simulates the model a @code{residtrace} result @var{R} returns (the
## linear part, the effects it added and the record's levels) on the
## record @var{data}, as @code{residtrace} simulated it to score it:
## @var{yh} is the simulated output, @var{e} = y - @var{yh} and @var{rmse}
## its root mean square. @var{which}: @qcode{"final"} (default,
## @code{R.final_model}, whose figure is @code{R.rmse_final}) or
## @qcode{"top"} (@code{R.model}, the top effect of the first pass, whose
## figure is @code{R.rmse_after}).
##
## The model (@code{R.final_model} or @code{R.model}) is an
## @code{idtraced} object, which @code{simc}, @code{sim} and
## @code{comparec} simulate the same way (this function is that
## simulation, kept for results of @code{residtrace} in a struct). It
## holds: @code{F},
## the @code{channels} (inputs and effect terms with their numerators
## @code{B} and delays @code{nk}), the output terms @code{out} (an output
## level, a polynomial, a sinusoid, a saturation), a physical
## realisation @code{phys} when one was added, @code{u0} (the input level
## removed from the records), @code{params} (the physical reading with
## standard deviations, @code{residtrace_physical}) and @code{linear} (its
## linear part as an @code{idpoly}). The simulation:
## @itemize
## @item subtracts @code{u0} from the input and simulates the model from
## rest (its output level is one of its output terms);
## @item when @code{R} came from a record split into estimation and
## validation parts (no validation record given; @code{model.npre} > 0,
## the estimation part's length) and @var{data} is that whole record,
## starts at its first sample and returns @var{e} and @var{rmse} over the
## validation part only (samples npre+1 onward), @var{yh} over all;
## @item fits the free response of an unknown initial state on the
## record when 'initial_state' was added, and the amplitudes of a
## sinusoid on each half of the record applied to the other, as
## @code{residtrace} does on a record not used to fit the model;
## @item bridges missing samples (NaN in y or an input) as residtrace
## does (@code{residtrace_bridge}): @var{e} is 0 there, and @var{rmse}
## is over the present samples;
## @item ignores drift and a noise model (they use the measured output:
## their figures are @code{R.rmse_final_tracked} and
## @code{R.rmse_final_prediction}); @var{rmse} is then the simulation
## figure @code{R.rmse_final}.
## @end itemize
## A result of a closed-loop run is @code{residtrace_sim:notSupported}.
##
## @strong{Example}
## @example
## Ts = 0.05; u = prbs (9, 4); N = numel (u); uv = circshift (u, 200);
## G = idctm (2, [1 1.2 1]);
## y = simc (G, u + 0.4, Ts) + 0.05 * randn (N, 1);
## yv = simc (G, uv + 0.4, Ts) + 0.05 * randn (N, 1);
## R = residtrace (iddata (y, u, Ts), srivc (iddata (y, u, Ts), [1 2 0]),
##                 "validation", iddata (yv, uv, Ts), "effects", @{"offset"@});
## [yh, e, rmse] = residtrace_sim (R, iddata (yv, uv, Ts));
## [rmse, R.rmse_final]
## @end example
## @seealso{idtraced, residtrace, residtrace_plot, residtrace_table, comparec}
## @end deftypefn

function varargout = residtrace_sim (varargin)
  varargout = contsid_guard ("residtrace_sim", @residtrace_sim_body, nargout, varargin);
endfunction

function [yh, e, rmse, varargout] = residtrace_sim_body (R, varargin)
  fname = "residtrace_sim";
  contsid_nargchk (fname, nargin, nargout, [2 Inf], 3);
  if (nargin < 2 || ! isstruct (R) || ! isscalar (R)
      || ! isfield (R, "final_model") || ! isfield (R, "model"))
    error ("residtrace_sim:badInput",
           "residtrace_sim: expected a result of residtrace and a record");
  endif
  try
    [d, miss] = contsid_getdata (fname, varargin{:});
    d = residtrace_bridge (d, miss);
  catch err
    error (struct ("message", regexprep (err.message, '^[^:]*:', [fname ':']),
                   "identifier",
                   regexprep (err.identifier, '^[^:]*:', [fname ':'])));
  end_try_catch
  opts = contsid_options (fname, struct ("model", "final"),
                          varargin(d.nconsumed+1:end));
  switch (opts.model)
    case "final"
      m = R.final_model;
    case "top"
      m = R.model;
    otherwise
      error ("residtrace_sim:badOption",
             "residtrace_sim: model must be 'final' or 'top'");
  endswitch
  if (isa (m, "idtraced"))
    m = get (m);
  endif
  [yh, e, rmse] = residtrace_model_sim (fname, m, d);
endfunction

%!shared Ts, u, uv, G, N
%! Ts = 0.05; u = prbs (9, 4); N = numel (u);
%! uv = circshift (u, 200);
%! G = idctm (2, [1 1.2 1]);

%!test  # the final figure reproduced: an output saturation
%! randn ("state", 16);
%! y = min (simc (G, u, Ts), 0.4) + 0.03 * randn (N, 1);
%! yv = min (simc (G, uv, Ts), 0.4) + 0.03 * randn (N, 1);
%! M = srivc (iddata (y, u, Ts), [1 2 0]);
%! R = residtrace (iddata (y, u, Ts), M, "validation", iddata (yv, uv, Ts),
%!                 "effects", {"saturation", "offset"}, "iterate", 2);
%! assert (R.effect, "saturation");
%! [yh, e, r] = residtrace_sim (R, iddata (yv, uv, Ts));
%! assert (r, R.rmse_final, 1e-6 * R.rmse_final);
%! assert (yh, yv - e, 1e-12);
%! assert (yh, R.sim.final_simulation, 1e-9 * max (abs (yv)));
%! [~, ~, r] = residtrace_sim (R, yv, uv, Ts, "model", "top");
%! assert (r, R.rmse_after, 1e-6 * R.rmse_after);

%!test  # a record in raw units: the levels are part of the model
%! randn ("state", 15);
%! y = 20 + simc (G, u - u(1), Ts) + 0.05 * randn (N, 1);
%! yv = 20 + simc (G, uv - u(1), Ts) + 0.05 * randn (N, 1);
%! R = residtrace (iddata (y, u + 5, Ts), idctm (2, [1 1.2 1]),
%!                 "validation", iddata (yv, uv + 5, Ts),
%!                 "effects", {"offset", "delay"}, "iterate", 1);
%! assert (R.levels.estimated);
%! assert (R.final_model.u0, u(1) + 5);
%! [~, ~, r] = residtrace_sim (R, iddata (yv, uv + 5, Ts));
%! assert (r, R.rmse_final, 1e-6 * R.rmse_final);
%! assert (r < 0.07);

%!test  # a split record: the whole record, the figure on its last third
%! randn ("state", 22);
%! y = simc (G, u, Ts) + 0.2 * sin (0.9 * (0:N-1)' * Ts) + 0.03 * randn (N, 1);
%! R = residtrace (iddata (y, u, Ts), G, "effects", {"sinusoid", "delay"},
%!                 "iterate", 1);
%! assert (R.final_model.npre > 0);
%! [yh, e, r] = residtrace_sim (R, iddata (y, u, Ts));
%! assert (numel (yh), N);
%! assert (numel (e), N - R.final_model.npre);
%! assert (r, R.rmse_final, 1e-6 * R.rmse_final);

%!error id=residtrace_sim:badInput residtrace_sim (struct (), iddata ((1:10)', (1:10)', 1))
%!error id=residtrace_sim:badInput residtrace_sim (1)
