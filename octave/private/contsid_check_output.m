## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn {} {} contsid_check_output (@var{fname}, @var{y})
## The check every estimator makes of the output it read (after
## @code{contsid_getdata}): an output whose present samples (NaN marks a
## missing one) are all equal identifies no model, whatever the
## structure, so it is an error @code{@var{fname}:badInput} instead of a
## model fitted to nothing (from a constant output the estimators would
## give models with an infinite noise variance or a meaningless
## denominator).  The
## non-parametric analyses (@code{cra}, @code{spafdr}) and the
## simulations (@code{simc}, @code{comparec}) do not call it.
## @end deftypefn

function contsid_check_output (fname, y)
  yp = y(! isnan (y));
  if (isempty (yp) || all (yp == yp(1)))
    error ([fname ":badInput"],
           "%s: the output 'y' is constant: the model is not identifiable",
           fname);
  endif
endfunction
