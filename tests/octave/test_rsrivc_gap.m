## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## RSRIVC with a gap of missing samples tracks as without the gap, within
## the noise. The system of thesis sec. 2.3.5,
## 4 / (p^2 + 2.4 p + 4), Ts = 0.05 s, N = 20000 samples (1000 s), a
## random binary input held 20 samples, output noise of standard deviation
## 0.1; RSRIVC-KF ([nb nf nk] = [1 2 0], lambda_svf = 3, Qn = 1e-7 I, so
## the estimator keeps tracking). The gap: y and u NaN over 5 % of the
## record in the middle (samples 9501-10500, 50 s); the front-end bridges
## it (contsid_recursive_args: the filters propagate over the true elapsed
## time, the input held, no update at a missing sample).
##
## Tolerance from the estimates' own spread: over 6 noise seeds, sigma_p
## is the RMS over the window (from 20 s after the gap to the end) of the
## seed-to-seed standard deviation of the no-gap estimate of parameter p;
## d_p the RMS over seeds and window of (gap run - no-gap run). Required:
## d_p < sigma_p for every parameter (the gap run differs from the no-gap
## run by less than two no-gap runs on different noise typically differ
## from their mean). 20 s is 17 time constants of the slowest pole
## (1/1.2 s) and 60 of the SVF (1/3 s): the filters have forgotten the gap.
## The test discriminates: the same present samples treated as uniformly
## sampled (the gap's 50 s ignored, i.e. filters not propagated over the
## elapsed time) must fail the same bound; and the run on the gap must
## mark the missing samples and hold the estimates over them.
function test_rsrivc_gap ()
  Ts = 0.05;
  N = 20000;
  gap = 9501:10500;
  settle = round (20 / Ts);
  window = (gap(end) + settle):N;
  nn = [1 2 0];
  opts = {"lambda_svf", 3, "adm", "kf", "adg", 1e-7, "tsiv", 50};
  G = struct ("B", 4, "F", [1 2.4 4]);
  seeds = 1:6;
  full = gapped = naive = zeros (numel (window), 3, numel (seeds));
  for s = seeds
    rand ("state", s);
    randn ("state", s);
    u = kron (2 * (rand (N / 20, 1) > 0.5) - 1, ones (20, 1));
    y = simc (G, u, Ts) + 0.1 * randn (N, 1);
    th = rsrivc (iddata (y, u, Ts, "InterSample", "zoh"), nn, opts{:});
    full(:, :, s) = th(window, :);
    yg = y;
    ug = u;
    yg(gap) = NaN;
    ug(gap) = NaN;
    [th, ~, ~, info] = rsrivc (iddata (yg, ug, Ts, "InterSample", "zoh"),
                               nn, opts{:});
    gapped(:, :, s) = th(window, :);
    if (s == 1)
      miss = false (N, 1);
      miss(gap) = true;
      assert (isequal (info.missing, miss));
      assert (all (all (th(gap, :) == th(gap(1) - 1, :))),
              "estimates not held over the gap");
      assert (all (info.innovation(gap) == 0));
    endif
    keep = true (N, 1);
    keep(gap) = false;
    th = rsrivc (iddata (y(keep), u(keep), Ts, "InterSample", "zoh"), nn,
                 opts{:});
    th = [th(1:gap(1)-1, :); repmat(th(gap(1)-1, :), numel (gap), 1);
          th(gap(1):end, :)];
    naive(:, :, s) = th(window, :);
  endfor
  sigma = sqrt (mean (std (full, 0, 3) .^ 2, 1));
  rms_diff = @(a) sqrt (mean (mean ((a - full) .^ 2, 3), 1));
  d = rms_diff (gapped);
  dn = rms_diff (naive);
  printf ("  noise spread sigma [%s], gap run d [%s], naive d [%s]\n",
          num2str (sigma, "%.3g "), num2str (d, "%.3g "),
          num2str (dn, "%.3g "));
  assert (all (d < sigma), "gap run off by [%s] > spread [%s]",
          num2str (d, "%.3g "), num2str (sigma, "%.3g "));
  assert (any (dn >= sigma), "the test does not see a gap ignored");
endfunction
