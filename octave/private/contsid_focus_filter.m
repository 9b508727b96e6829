## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn {} {@var{d} =} contsid_focus_filter (@var{fname}, @var{d}, @var{band}, @var{order})
## The @code{Focus} passband [w1 w2] (rad/s) of tfsrivc, tfcoe, tfest and
## oe on time-domain data: the output and input of @var{d} (from
## @code{contsid_getdata}) prefiltered by the core's Butterworth band of
## @var{order} (filters/focus_filter.hpp: a low-pass of cut-off w2 times,
## for w1 > 0, a high-pass of cut-off w1, prewarped Tustin).  @var{band} =
## [] leaves @var{d} as it is; irregular sampling gives
## @code{@var{fname}:notSupported}.
## @end deftypefn

function d = contsid_focus_filter (fname, d, band, order)
  if (isempty (band))
    return;
  endif
  if (! d.uniform)
    error ([fname ":notSupported"],
           "%s: a Focus band needs regularly sampled data", fname);
  endif
  try
    [d.y, d.u] = refined_iv_mex (fname, "focus_filter", double (d.y),
                                 double (d.u), struct ("ts", d.Ts,
                                                       "band", band,
                                                       "order", order));
  catch err
    contsid_rethrow (err, fname);
  end_try_catch
endfunction
