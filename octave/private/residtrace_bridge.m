## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn {} {@var{d} =} residtrace_bridge (@var{d}, @var{missing})
## The record @var{d} (fields y, u, intersample, as
## @code{contsid_getdata} returns them) with its missing samples
## (@var{missing}, the N-by-1 mask of the samples where y or an input is
## NaN) bridged as the toolbox's estimators bridge a gap
## (@code{contsid_recursive_args}; @code{srivc} runs its continuous-time
## filters over it): a sample with y or an input missing is missing as a
## whole (it is left out of every figure); a missing zero-order-hold
## input is held at its last present value (@code{contsid_expand}, the
## expansion the recursive estimators use), a first-order-hold input and
## the output (the refined-IV engine's output rule is first-order hold)
## are interpolated linearly; before the first present sample the first
## present value is held, after the last the last. Unlike @code{srivc},
## an input present at a sample whose output is missing is kept:
## residtrace simulates the model from the input, and dropping a known
## input would leave a transient after the gap. The fits replace the
## bridged outputs by the model's own output (@code{residtrace_fit}),
## so that they carry no error. residtrace keeps the record on its
## uniform grid (its simulators, tests and candidates need one) and gives
## @var{d} the field
## @code{missing}: every figure residtrace reports (RMSE, fit, residual
## tests) leaves those samples out (a zero error there), so only the
## present samples are scored. A record with no present sample, or with
## fewer than two, is @code{residtrace:badInput}.
## @end deftypefn

function d = residtrace_bridge (d, missing)
  missing = logical (missing(:));
  d.missing = missing;
  if (! any (missing))
    return;
  endif
  present = ! missing;
  if (nnz (present) < 2)
    error ("residtrace:badInput",
           "residtrace: the record has fewer than two present samples");
  endif
  n = numel (missing);
  ## the inputs: bridged where one is missing; where only y is missing
  ## the input is known and kept (the model is simulated from it)
  umiss = any (isnan (d.u), 2);
  if (any (umiss))
    if (nnz (! umiss) < 2)
      error ("residtrace:badInput",
             "residtrace: the record has fewer than two present inputs");
    endif
    if (strcmpi (d.intersample, "foh"))
      d.u = lin (find (! umiss), d.u(! umiss, :), n);
    else
      held = contsid_expand ({d.u(! umiss, :)},
                             struct ("missing", umiss, "y", d.y(! umiss)));
      d.u = held{1};
    endif
  endif
  d.y = lin (find (present), d.y(present), n);
endfunction

## Linear interpolation over 1..n from the rows at k, the end values held.
function x = lin (k, v, n)
  if (numel (k) == 1)
    x = repmat (v, n, 1);
    return;
  endif
  x = interp1 (k, v, (1:n)', "linear");
  lo = (1:n)' < k(1);
  hi = (1:n)' > k(end);
  x(lo, :) = repmat (v(1, :), nnz (lo), 1);
  x(hi, :) = repmat (v(end, :), nnz (hi), 1);
endfunction

%!test  # held (ZOH) or interpolated (FOH) inputs, interpolated output
%! d = struct ("y", [1; NaN; NaN; 4; 5], "u", [1 10; 2 20; NaN 30; 4 40; 5 50],
%!             "intersample", "zoh");
%! m = isnan (d.y) | any (isnan (d.u), 2);
%! b = residtrace_bridge (d, m);
%! assert (b.missing, [false; true; true; false; false]);
%! assert (b.u, [1 10; 2 20; 2 20; 4 40; 5 50]);   # a known input kept
%! assert (b.y, (1:5)', 1e-12);
%! d.intersample = "foh";
%! d.u(2, 1) = NaN;
%! b = residtrace_bridge (d, m);
%! assert (b.u, [1 10; 2 20; 3 30; 4 40; 5 50], 1e-12);

%!test  # missing at the ends: the nearest present value
%! d = struct ("y", [NaN; 2; 3; NaN], "u", [NaN; 1; 2; NaN],
%!             "intersample", "zoh");
%! b = residtrace_bridge (d, isnan (d.y));
%! assert (b.y, [2; 2; 3; 3]);
%! assert (b.u, [1; 1; 2; 2]);

%!error id=residtrace:badInput residtrace_bridge (struct ("y", [NaN; 1; NaN], "u", [1; 1; 1], "intersample", "zoh"), [true; false; true])
