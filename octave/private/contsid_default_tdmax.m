## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn {} {@var{tdmax} =} contsid_default_tdmax (@var{t}, @var{y}, @var{u})
## Default upper bound of a delay search (tfsrivc, tfsrivc_init,
## procsrivc), as CONTSID documents it: "calculated by maximizing the
## cross correlation function of the input-output data".  The lag of the
## largest |r_yu(k)| = |sum_t y~(t + k) u~(t)| (y~, u~ without their
## means) over 0 <= k <= half the record, plus 10 sampling intervals (the
## input's own correlation, e.g. a PRBS clock period, can move the peak a
## few samples before the impulse response's), at least the smaller of a
## tenth of the record and 50 sampling intervals, at most half the
## record.  Irregular instants @var{t}: the signals are first put on a
## regular grid of their median interval (u held, y linear), unless that
## grid would have more than 10 times their number of samples.  @var{y} and
## @var{u} are the first output and input columns.
## @end deftypefn

function tdmax = contsid_default_tdmax (t, y, u)
  t = t(:);
  n = numel (t);
  T = t(end) - t(1);
  h = median (diff (t));
  tdmax = min (T / 10, 50 * h);
  if (n < 4 || ! (h > 0))
    return;
  endif
  y = y(:, 1);
  u = u(:, 1);
  if (max (abs (diff (t) - h)) > 1e-9 * h)
    if (T / h > 10 * n)                   # too sparse for a regular grid
      return;
    endif
    tg = (t(1):h:t(end)).';
    u = u(lookup (t, tg));
    y = interp1 (t, y, tg, "linear");
    n = numel (tg);
  endif
  y = y - mean (y);
  u = u - mean (u);
  L = 2 ^ nextpow2 (2 * n);
  r = real (ifft (fft (y, L) .* conj (fft (u, L))));
  K = floor ((n - 1) / 2);
  [~, k] = max (abs (r(1:K+1)));
  tdmax = max (tdmax, min ((k - 1 + 10) * h, T / 2));
endfunction
