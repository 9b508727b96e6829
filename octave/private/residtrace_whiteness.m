## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn {} {@var{w} =} residtrace_whiteness (@var{e}, @var{u}, @var{maxlag}, @var{yscale})
## Residual tests of @code{residtrace}: is @var{e} white, and independent
## of the inputs @var{u} (N-by-nu)?
##
## Whiteness: the Ljung-Box statistic Q = N (N + 2) sum_(k=1..m) r_k^2 /
## (N - k) against chi^2(m). Independence: Haugh's test (J. Am. Stat.
## Assoc. 71 (1976) 378-385): e and each input are prewhitened by AR
## models of their own (orders <= 20 and <= 10 by BIC), so that under
## independence the cross-correlations r_eu(k), k = -m..m, of the two
## white series are independent with variance 1/N whatever the colour of
## e; S = N sum r_eu(k)^2 against chi^2(2m + 1). Also the
## CONTSID-style figures of @code{residc}: the normalised correlations
## and the 99 % bound 2.576/sqrt(N).
##
## @var{w}: @code{testable} (false with @code{reason} when e is not
## finite, or constant, or below 1e-10 @var{yscale} (the output's RMS):
## a model exact to rounding leaves nothing to test), @code{white_p},
## @code{indep_p}, @code{autocorr} (lags
## 0..m), @code{xcorr} (lags -m..m, both prewhitened, one column per
## input),
## @code{bound}.
## @end deftypefn

function w = residtrace_whiteness (e, u, maxlag, yscale)
  if (nargin < 4)
    yscale = 0;
  endif
  N = numel (e);
  m = maxlag;
  w = struct ("testable", true, "reason", "", "white_p", NaN,
              "indep_p", NaN, "autocorr", [], "xcorr", [],
              "bound", 2.576 / sqrt (N), "maxlag", m);
  if (any (! isfinite (e)))
    w.testable = false;
    w.reason = "the residual is not finite (the model output diverges)";
    return;
  endif
  ec = e - mean (e);
  if (sqrt (mean (e .^ 2)) <= 1e-10 * yscale)
    w.testable = false;
    w.reason = "the residual is zero to rounding: nothing left to test";
    return;
  endif
  if (all (ec == 0))
    w.testable = false;
    w.reason = "the residual is constant: nothing left to test";
    return;
  endif
  r = zeros (m + 1, 1);
  s0 = sum (ec .^ 2);
  for k = 0:m
    r(k+1) = sum (ec(1+k:end) .* ec(1:end-k)) / s0;
  endfor
  w.autocorr = r;
  Q = N * (N + 2) * sum (r(2:end) .^ 2 ./ (N - (1:m)'));
  w.white_p = chi2_sf (Q, m);
  nu = columns (u);
  w.xcorr = zeros (2 * m + 1, nu);
  S = 0;
  ew = filter (ar_whitener (ec, min (20, floor (N / 20))), 1, ec);
  for j = 1:nu
    uc = u(:, j) - mean (u(:, j));
    if (all (uc == 0))
      continue;
    endif
    a = ar_whitener (uc, min (10, floor (N / 20)));
    uw = filter (a, 1, uc);
    scale = sqrt (sum (uw .^ 2) * sum (ew .^ 2));
    for i = 1:2*m+1
      k = i - m - 1;               # e(t) against u(t - k)
      if (k >= 0)
        c = sum (ew(1+k:end) .* uw(1:end-k));
      else
        c = sum (ew(1:end+k) .* uw(1-k:end));
      endif
      w.xcorr(i, j) = c / scale;
    endfor
    S += N * sum (w.xcorr(:, j) .^ 2);
  endfor
  w.indep_p = chi2_sf (S, nu * (2 * m + 1));
endfunction

## A(q) of an AR model of x, order <= pmax chosen by BIC (least squares).
function a = ar_whitener (x, pmax)
  N = numel (x);
  best = Inf;
  a = 1;
  for p = 0:pmax
    if (p == 0)
      s2 = mean (x .^ 2);
      ap = 1;
    else
      X = zeros (N - p, p);
      for i = 1:p
        X(:, i) = x(p+1-i:N-i);
      endfor
      c = X \ x(p+1:N);
      s2 = mean ((x(p+1:N) - X * c) .^ 2);
      ap = [1, -c.'];
    endif
    bic = N * log (max (s2, realmin)) + p * log (N);
    if (bic < best)
      best = bic;
      a = ap;
    endif
  endfor
endfunction

function p = chi2_sf (x, k)
  p = gammainc (x / 2, k / 2, "upper");
endfunction
