## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn {} {@var{band} =} contsid_focus_option (@var{fname}, @var{focus})
## The @code{Focus} option of the time-domain estimators (tfsrivc,
## tfsrivc_init, tfrivc, tfcoe, tfest, oe) read once, as the passband
## [w1 w2] (rad/s) that @code{contsid_focus_filter} prefilters the data
## with, or [] for no prefilter:
## @itemize
## @item a scalar fc > 0, CONTSID's form (its help: "cutoff frequency of
## the focus filter, implemented as a Butterworth filter"): the low-pass
## band [0 fc]; @code{Inf}, CONTSID's default, is the all-pass: [];
## @item a band [w1 w2] with 0 <= w1 < w2 (the SITB's passband form);
## @item @qcode{"simulation"} or @qcode{"prediction"} (the SITB's names;
## the same for an output-error model): [].
## @end itemize
## Anything else is @code{@var{fname}:badOption}.
## @end deftypefn

function band = contsid_focus_option (fname, focus)
  band = [];
  if (ischar (focus) && any (strcmpi (focus, {"simulation", "prediction"})))
    return;
  endif
  if (isnumeric (focus) && isreal (focus) && isscalar (focus)
      && ! isnan (focus) && focus > 0)
    if (isfinite (focus))
      band = [0, double(focus)];
    endif
    return;
  endif
  if (isnumeric (focus) && isreal (focus) && numel (focus) == 2
      && all (isfinite (focus)) && focus(1) >= 0 && focus(2) > focus(1))
    band = double (focus(:).');
    return;
  endif
  error ([fname ":badOption"], ["%s: Focus must be a cut-off frequency ", ...
         "fc > 0 (rad/s; Inf: no filter), a band [w1 w2] (0 <= w1 < w2) ", ...
         "or 'simulation'/'prediction'"], fname);
endfunction

%!assert (contsid_focus_option ("f", 5), [0 5])
%!assert (contsid_focus_option ("f", Inf), [])
%!assert (contsid_focus_option ("f", [1 5]), [1 5])
%!assert (contsid_focus_option ("f", "simulation"), [])
%!assert (contsid_focus_option ("f", "Prediction"), [])
%!error id=f:badOption contsid_focus_option ("f", 0)
%!error id=f:badOption contsid_focus_option ("f", -1)
%!error id=f:badOption contsid_focus_option ("f", NaN)
%!error id=f:badOption contsid_focus_option ("f", [5 1])
%!error id=f:badOption contsid_focus_option ("f", [0 Inf])
%!error id=f:badOption contsid_focus_option ("f", "bogus")
%!error id=f:badOption contsid_focus_option ("f", {1})
