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
## @code{bound}. The statistics are the core's
## (core/include/ctid/apps/residtrace/statistics.hpp, through
## @code{effect_sim_mex}), their chi^2 tail probabilities too
## (judgement.hpp).
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
  [r, ~, xc, ~, reason, white_p, indep_p] = ...
    effect_sim_mex ("residtrace", "whiteness", e(:), u,
                    struct ("maxlag", m, "yscale", yscale));
  if (! isempty (reason))
    w.testable = false;
    w.reason = reason;
    return;
  endif
  w.autocorr = r;
  w.white_p = white_p;
  w.xcorr = xc;
  w.indep_p = indep_p;
endfunction
