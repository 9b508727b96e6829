## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn {} {@var{d} =} contsid_focus_filter (@var{fname}, @var{d}, @var{band}, @var{order})
## The @code{Focus} passband [w1 w2] (rad/s) of tfsrivc, tfcoe, tfest and
## oe on time-domain data: the output and input of @var{d} (from
## @code{contsid_getdata}) are prefiltered by a Butterworth band of
## @var{order} (a low-pass of cut-off w2 for w1 = 0, times a high-pass of
## cut-off w1 for w1 > 0; no low-pass when w2 is at or above the Nyquist
## frequency), discretised by the Tustin map with prewarping at the
## cut-off. Fitting L y by G L u then weights the output error by |L|^2,
## the band's weighting of the SITB's Focus.  @var{band} = [] leaves
## @var{d} as it is; irregular sampling gives
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
  Ts = d.Ts;
  wn = pi / Ts;
  b = 1;
  a = 1;
  if (band(2) < wn)
    [b, a] = butter_tustin (order, band(2), Ts, false);
  endif
  if (band(1) > 0)
    [bh, ah] = butter_tustin (order, band(1), Ts, true);
    b = conv (b, bh);
    a = conv (a, ah);
  endif
  d.y = filter (b, a, d.y);
  d.u = filter (b, a, d.u);
endfunction

function [b, a] = butter_tustin (n, wc, Ts, high)
  w = 2 / Ts * tan (wc * Ts / 2);              # prewarped
  k = 1:n;
  p = w * exp (1i * pi * (2 * k + n - 1) / (2 * n));
  ## Tustin map of each pole s = p: z = (1 + p Ts/2) / (1 - p Ts/2).
  zp = (1 + p * Ts / 2) ./ (1 - p * Ts / 2);
  a = real (poly (zp));
  if (high)
    b = poly (ones (1, n));                    # zeros at z = 1
    g = abs (polyval (a, -1) / polyval (b, -1));
  else
    b = poly (-ones (1, n));                   # zeros at z = -1
    g = abs (polyval (a, 1) / polyval (b, 1));
  endif
  b = b * g;
endfunction
