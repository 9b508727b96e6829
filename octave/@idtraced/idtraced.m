## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn  {} {@var{M} =} idtraced (@var{s})
## @deftypefnx {} {@var{M} =} idtraced ()
## The model @code{residtrace} returns (@code{R.model}, @code{R.final_model}):
## a continuous-time model identified by @code{residtrace}, made of a
## linear part, the effects it added (nonlinear, time-varying or
## additive terms, a physical realisation), with their physical
## parameters and standard deviations, and the record's levels. It is
## simulated by the toolbox's ordinary functions exactly as
## @code{residtrace} simulated it to score it:
## @table @code
## @item simc (M, data), simc (M, u, Ts)
## the simulated output (CONTSID's forms; see @code{help idtraced/sim}
## for what the measured output in @var{data} is used for);
## @item sim (M, data), sim (M, u, Ts)
## the same, as an output-only @code{iddata} for an @code{iddata};
## @item comparec (data, M), comparec (data, M, INT)
## measured against simulated output, Fit, RT2, RMSE (plotted without
## outputs), as for any model: on the validation record residtrace scored
## it on, @code{estInfo.RMSE} is @code{R.rmse_final} (@code{R.rmse_after}
## for @code{R.model}); for a model scored on the last part of a record
## it split (@code{M.npre} > 0), compare that whole record on
## @code{INT = M.npre+1:N};
## @item residc (data, M)
## the residual tests of that simulation error;
## @item present (M)
## the linear part, the effects with their physical parameters +/- one
## standard deviation, the levels.
## @end table
##
## The name: an identified (@code{id}) model as @code{residtrace} traced
## it; it is not one of the linear model classes (@code{idpoly},
## @code{idtf}, ...), whose methods (@code{bode}, @code{pole}, ...) would
## ignore its effects: the linear part alone is @code{M.linear}, an
## @code{idpoly} (one input per channel, built by @code{idctm}), for them.
##
## @code{M.name} reads a field (see @code{get (M)} for all): @code{F},
## @code{fixed}, @code{channels} (the inputs and the effect terms: type,
## numerator @code{B}, delay @code{nk}, parameter), @code{out} (output
## terms: the output level, a polynomial, a sinusoid, a saturation, each
## with its coefficients @code{c} and standard deviations @code{cstd}),
## @code{phys} (a physical realisation: end stop, cascade), @code{effects}
## (the names of the effects added), @code{theta}, @code{cov}, @code{s2},
## @code{u0} (the input level removed from the input: the levels are part
## of the model), @code{levels} (true when the output level was
## estimated), @code{x0} (true when an initial state is fitted on each
## record), @code{params} (the physical reading: @code{name},
## @code{value}, @code{std}), @code{linear}, @code{Ts} (the sampling
## interval it was simulated with), @code{intersample}, @code{npre},
## @code{substeps}, @code{closed_loop}.
##
## @var{s}: the struct of those fields (as @code{get (M)} returns it);
## @code{idtraced ()} is an empty model (for @code{load}), which no
## function simulates. Errors: @code{idtraced:badInput}.
##
## @strong{Example}
## @example
## Ts = 0.05; u = prbs (9, 4); N = numel (u); uv = circshift (u, 200);
## G = idctm (2, [1 1.2 1]);
## y = min (simc (G, u, Ts), 0.4) + 0.03 * randn (N, 1);   # saturates
## yv = min (simc (G, uv, Ts), 0.4) + 0.03 * randn (N, 1);
## R = residtrace (iddata (y, u, Ts), srivc (iddata (y, u, Ts), [1 2 0]),
##                 "validation", iddata (yv, uv, Ts),
##                 "effects", @{"saturation"@}, "iterate", 1);
## M = R.final_model;
## present (M)
## [~, info] = comparec (iddata (yv, uv, Ts), M);
## [info.RMSE, R.rmse_final]       # the same figure
## comparec (iddata (yv, uv, Ts), M)   # the "after" figure
## @end example
## @seealso{residtrace, residtrace_sim, comparec, simc}
## @end deftypefn

function varargout = idtraced (varargin)
  varargout = contsid_guard ({"idtraced", "idtraced"}, @idtraced_body,
                             nargout, varargin);
endfunction

function [M, varargout] = idtraced_body (varargin)
  contsid_nargchk ("idtraced", nargin, nargout, [0 Inf], 1);
  if (nargin == 0)
    M = class (struct ("model", struct ()), "idtraced");
    return;
  endif
  if (nargin == 1 && isa (varargin{1}, "idtraced"))
    M = varargin{1};
    return;
  endif
  need = {"F", "channels", "out", "u0", "Ts", "npre", "substeps", ...
          "closed_loop", "params", "linear"};
  s = varargin{1};
  if (nargin != 1 || ! isstruct (s) || ! isscalar (s)
      || ! all (isfield (s, need)))
    error ("idtraced:badInput",
           ["idtraced: expected the struct of a residtrace model (fields ", ...
            "%s)"], strjoin (need, ", "));
  endif
  if (! isnumeric (s.Ts) || ! isscalar (s.Ts) || ! isfinite (s.Ts)
      || ! (s.Ts > 0) || ! isnumeric (s.F) || isempty (s.F)
      || ! all (isfinite (s.F)) || ! isnumeric (s.u0)
      || ! all (isfinite (s.u0)) || ! isnumeric (s.npre)
      || ! isscalar (s.npre) || ! (s.npre >= 0) || ! isfinite (s.npre)
      || ! isstruct (s.channels) || isempty (s.channels)
      || ! isstruct (s.out) || ! isa (s.linear, "idpoly"))
    error ("idtraced:badInput",
           "idtraced: the struct is not a model residtrace returned");
  endif
  M = class (struct ("model", s), "idtraced");
endfunction

%!test  # an empty model, and a model from residtrace's struct
%! M = idtraced ();
%! assert (isa (M, "idtraced"));
%! s = struct ("F", [1 1], "channels", struct ("type", "input", "B", 1),
%!             "out", struct ("type", {}), "u0", 0, "Ts", 0.1, "npre", 0,
%!             "substeps", 10, "closed_loop", false, "params", [],
%!             "linear", idctm (1, [1 1]));
%! M = idtraced (s);
%! assert (M.F, [1 1]);
%! assert (isa (M.linear, "idpoly"));
%! assert (isa (idtraced (M), "idtraced"));

%!error id=idtraced:badInput idtraced (1)
%!error id=idtraced:badInput idtraced (struct ("F", [1 1]))
%!error id=idtraced:badInput idtraced (struct ("F", [1 1]), 2)

%!demo
%! ## an output that saturates at 0.4: the model residtrace returns,
%! ## compared with the validation record (the "after" figure)
%! Ts = 0.05; u = prbs (9, 4); N = numel (u); uv = circshift (u, 200);
%! G = idctm (2, [1 1.2 1]);
%! y = min (simc (G, u, Ts), 0.4) + 0.03 * randn (N, 1);
%! yv = min (simc (G, uv, Ts), 0.4) + 0.03 * randn (N, 1);
%! d = iddata (y, u, Ts); dv = iddata (yv, uv, Ts);
%! R = residtrace (d, srivc (d, [1 2 0]), "validation", dv,
%!                 "effects", {"saturation"}, "iterate", 1);
%! M = R.final_model
%! comparec (dv, M);
%! printf ("residtrace's figure: RMSE %.4g\n", R.rmse_final);
