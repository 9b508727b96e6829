## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn  {} {@var{y} =} sim (@var{M}, @var{data})
## @deftypefnx {} {@var{y} =} sim (@var{M}, @var{u}, @var{Ts})
## Simulates a model @code{residtrace} returned (@code{R.model},
## @code{R.final_model}) as @code{residtrace} simulated it to score it:
## the input level @code{M.u0} subtracted from the input, the linear part
## with the effects, from rest, the output level added (the data and
## @var{y} are in the record's raw units). @var{data}: an @code{iddata}
## set with the model's sampling interval, input-only
## (@code{iddata ([], u, Ts)}) or with the measured output; @var{y} is
## then an output-only @code{iddata} set. Numeric @var{u} (N-by-nu) and
## @var{Ts} give a numeric @var{y}. This is @code{simc (M, @dots{})}:
##
## When @var{data} carries the measured output, what @code{residtrace}
## fits on a record it did not fit the model on is fitted to it: the free
## response of an initial state when the model declares one
## (@code{M.x0}), the amplitude and phase of a sinusoid on each half of
## the record applied to the other; NaN samples are bridged as
## @code{residtrace} bridges them; and a record longer than
## @code{M.npre} > 0 (the model was scored on the last part of a record
## it split) is simulated from its start. Without an output the model is
## simulated from the input alone (a sinusoid with the amplitude and
## phase fitted on the estimation record). A model without an initial
## state or a sinusoid gives the same @var{y} either way. Drift and a
## noise model are not simulated (they use the measured output: their
## figures are @code{R.rmse_final_tracked},
## @code{R.rmse_final_prediction}).
##
## Errors: @code{idtraced:badInput} (data of another sampling interval,
## an empty model), @code{idtraced:dimensionMismatch},
## @code{idtraced:notSupported} (a model found in closed loop).
##
## @strong{Example}
## @example
## Ts = 0.05; u = prbs (9, 4); N = numel (u); G = idctm (2, [1 1.2 1]);
## y = simc (G, u + 0.3, Ts) + 0.03 * randn (N, 1);
## R = residtrace (iddata (y, u, Ts), G, "effects", @{"offset"@});
## ys = sim (R.final_model, iddata ([], u, Ts));   # an iddata
## ys = sim (R.final_model, u, Ts);                # numeric
## @end example
## @seealso{idtraced, simc, comparec}
## @end deftypefn

function varargout = sim (varargin)
  varargout = contsid_guard ({"sim", "idtraced"}, @sim_body, nargout,
                             varargin);
endfunction

function [y, varargout] = sim_body (M, varargin)
  contsid_nargchk ("sim", nargin, nargout, [2 3], 1);
  if (nargin == 2 && ! isa (varargin{1}, "iddata"))
    error ("idtraced:badInput",
           "idtraced: sim (M, data) needs an iddata set, or sim (M, u, Ts)");
  endif
  try
    y = simc (M, varargin{:});
  catch err
    error (struct ("identifier", regexprep (err.identifier, '^simc:',
                                            'idtraced:'),
                   "message", regexprep (err.message, '^simc:',
                                         'idtraced:')));
  end_try_catch
  if (nargin == 2)
    data = varargin{1};
    y = iddata (y, [], get (data, "Ts"), "TimeUnit", get (data, "TimeUnit"));
  endif
endfunction

%!shared M, u, Ts, N
%! Ts = 0.1; N = 200;
%! u = double (sin (0.3 * (1:N)') > 0);
%! s = struct ("F", [1 1], "fixed", false,
%!             "channels", struct ("name", "u1", "type", "input", "col", 1,
%!                                 "param", [], "nb", 1, "nk", 0, "B", 2),
%!             "out", struct ("type", "offset", "c", 20, "cstd", 0.1,
%!                            "omega", 0),
%!             "intersample", "zoh", "Ts", Ts, "ltv", [], "noise", [],
%!             "phys", [], "x0", false, "u0", 5, "npre", 0, "substeps", 10,
%!             "closed_loop", false, "params", [],
%!             "linear", idctm (2, [1 1]));
%! M = idtraced (s);

%!test  # 20 + (2 / (s + 1)) (u - 5): the exact ZOH response
%! pkg load control
%! x = lsim (ss (c2d (tf (2, [1 1]), Ts)), u, (0:N-1)' * Ts);
%! y = sim (M, u + 5, Ts);
%! assert (y, 20 + x, 1e-10);
%! yd = sim (M, iddata ([], u + 5, Ts));
%! assert (isa (yd, "iddata"));
%! assert (get (yd, "OutputData"), y, 1e-12);
%! yd = sim (M, iddata (y, u + 5, Ts));     # no effect left to the record
%! assert (get (yd, "OutputData"), y, 1e-12);

%!error id=idtraced:badInput sim (M, u)
%!error id=idtraced:badInput sim (M, u, 2 * Ts)
%!error id=idtraced:dimensionMismatch sim (M, [u u], Ts)
%!error id=idtraced:badInput sim (idtraced (), u, Ts)
