## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn {} {@var{rule} =} contsid_filter_rule (@var{fname}, @var{d}, @var{given})
## The rule by which the recursive estimators filter the input: the data's
## InterSample (@code{@var{d}.intersample}) when @var{given} is empty,
## else @var{given}, one of @qcode{"zoh"} (exact zero-order hold),
## @qcode{"foh"} (exact first-order hold) or @qcode{"trapezoid"} (the
## trapezoidal, Tustin rule the thesis uses for a signal that is not
## piecewise constant, sec. 3.1.3, Suggested procedure 3.3).  Anything
## else is @code{@var{fname}:badOption}.
## @end deftypefn

function rule = contsid_filter_rule (fname, d, given)
  if (isempty (given))
    rule = d.intersample;
    return;
  endif
  if (! ischar (given) || ! any (strcmpi (given, {"zoh", "foh", "trapezoid"})))
    error ([fname ":badOption"],
           "%s: InterSample must be 'zoh', 'foh' or 'trapezoid'", fname);
  endif
  rule = lower (given);
endfunction

