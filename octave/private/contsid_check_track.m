## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn {} {} contsid_check_track (@var{fname}, @var{outs})
## Refuse non-finite results of a recursive estimator: the tracks
## @code{@var{outs}@{1@}} and, when computed, the frozen-model output
## @code{@var{outs}@{2@}} must be finite.  Otherwise errors
## @code{@var{fname}:numericalFailure} naming the first sample where they
## are not (a cut-off far above the Nyquist frequency, a diverging
## recursion), instead of returning NaN or Inf silently.
## @end deftypefn

function contsid_check_track (fname, outs)
  names = {"the estimates thm are", "the frozen-model output yh is"};
  for k = 1:min (2, numel (outs))
    x = outs{k};
    if (isnumeric (x) && ! all (isfinite (x(:))))
      first = find (! all (isfinite (x), 2), 1);
      error ([fname ":numericalFailure"],
             ["%s: %s not finite from sample %d on (is lambda_svf ", ...
              "far above pi/Ts, or did the recursion diverge?)"], fname,
             names{k}, first);
    endif
  endfor
endfunction

%!error id=f:numericalFailure contsid_check_track ("f", {[1 2; NaN 3]})
%!error id=f:numericalFailure contsid_check_track ("f", {[1 2; 2 3], [1; Inf]})
%!test
%! contsid_check_track ("f", {[1 2; 2 3], [1; 2], NaN});
