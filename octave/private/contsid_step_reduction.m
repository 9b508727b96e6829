## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn {} {@var{m} =} contsid_step_reduction (@var{fname}, @var{r})
## The @code{StepReduction} option of the delay search (tfsrivc,
## tfsrivc_init, tfcoe) as the multiplier @var{m} in (0, 1) that
## @code{contsid_tfsrivc} applies to a delay step that does not lower the
## loss: CONTSID's factor r > 1 divides the step (m = 1 / r); a factor in
## (0, 1), the toolbox's older convention, multiplies it (m = r).
## Anything else is @code{@var{fname}:badOption}.
## @end deftypefn

function m = contsid_step_reduction (fname, r)
  if (! (isnumeric (r) && isreal (r) && isscalar (r) && isfinite (r)
         && r > 0 && r != 1))
    error ([fname ":badOption"], ["%s: StepReduction must be a factor > 1 ", ...
           "(the delay step is divided by it) or in (0, 1) (multiplied)"],
           fname);
  endif
  m = r;
  if (r > 1)
    m = 1 / r;
  endif
endfunction

%!assert (contsid_step_reduction ("f", 2), 0.5)
%!assert (contsid_step_reduction ("f", 0.25), 0.25)
%!error id=f:badOption contsid_step_reduction ("f", 1)
%!error id=f:badOption contsid_step_reduction ("f", 0)
%!error id=f:badOption contsid_step_reduction ("f", -2)
%!error id=f:badOption contsid_step_reduction ("f", Inf)
%!error id=f:badOption contsid_step_reduction ("f", "2")
