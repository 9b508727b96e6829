## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn {} {@var{S} =} rivc_mc (@var{R}, @var{part})
## Monte Carlo of the Box-Jenkins refined IV estimators:
## for rivc, tfrivc (delay kept), clrivc and cl2srivc, @var{R} records
## (default 200) with coloured noise; per parameter the bias, the Monte
## Carlo standard deviation, the mean reported standard deviation and
## their ratio (bar: 0.8-1.25). For rivc the same records are also given
## to srivc (bar: rivc beats srivc on coloured noise): the MC standard
## deviations and RMSE of both, for low-pass ARMA(1,1) noise and for
## noise with a resonance above the plant's band. @var{part}: "all"
## (default; also false), "open" (stop after these; also true), "closed"
## (the closed-loop cases only) or "miso" (two inputs, one denominator each,
## ARMA(1,1) noise: the stacked-instrument covariance of rivc_miso).
## Run from the repository root:
## @example
## devel/run-study rivc_mc 200
## @end example
## @end deftypefn

function S = rivc_mc (R, part)
  if (nargin < 1)
    R = 200;
  endif
  if (nargin < 2 || isequal (part, false))
    part = "all";
  elseif (isequal (part, true))
    part = "open";
  endif
  pkg load control
  warning ("off", "all");
  S = struct ();

  if (any (strcmp (part, {"all", "open"})))
    ## rivc vs srivc: open loop, ARMA(1,1) noise with a slow pole; noise
    ## with a resonance above the plant's band, D = 1 - 1.6 q^-1 + 0.9
    ## q^-2 (about 10 rad/s), C = 1 + 0.3 q^-1; a slow drift, D = 1 - 0.98
    ## q^-1, C = 1 (seeded on its own, so its numbers do not depend on the
    ## cases run before it).
    Ts = 0.05; N = 3000;
    randn ("state", 1);
    u = kron (sign (randn (N / 10, 1)), ones (10, 1));
    x = lsim (c2d (tf ([1.5 4], [1 1.2 4]), Ts), u);
    th0 = [1.2 4 1.5 4];
    [S.rivc, S.srivc] = versus_srivc (R, x, u, Ts, th0, [2 1 1 2 0],
      @() filter ([1 0.5], [1 -0.9], 0.05 * randn (N, 1)), "");
    [S.rivc_res, S.srivc_res] = versus_srivc (R, x, u, Ts, th0,
      [2 1 2 2 0], @() filter ([1 0.3], [1 -1.6 0.9], 0.02 * randn (N, 1)),
      ", resonant noise");
    randn ("state", 3);
    [S.drift.rivc, S.drift.srivc] = versus_srivc (R, x, u, Ts, th0,
      [2 0 1 2 0], @() filter (1, [1 -0.98], 0.02 * randn (N, 1)),
      ", drift noise");
  endif
  if (strcmp (part, "open"))
    return;
  endif
  if (strcmp (part, "miso"))
    S.miso = miso (R);
    return;
  endif

  if (strcmp (part, "all"))
    ## tfrivc, delay 0.37 s kept.
    M0 = idtf (4, [1 1.2 4], "IODelay", 0.37);
    xd = simc (M0, iddata ([], u, Ts, "InterSample", "zoh"));
    [T, SD] = deal (zeros (R, 3));
    for i = 1:R
      v = filter ([1 0.5], [1 -0.9], 0.05 * randn (N, 1));
      MP = tfrivc (iddata (xd + v, u, Ts), 2, 0, 0.37, "FixTd", "on",
                   "NN", [1 1]);
      T(i, :) = [MP.num{1}, MP.den{1}(2:3)];
      SD(i, :) = sqrt (diag (getcov (MP)))(1:3).';  # then the IODelay
    endfor
    S.tfrivc = summary ("tfrivc 2,0 NN [1 1]", T, SD, [4 1.2 4], R);
  else
    randn ("state", 5);
  endif

  ## Closed loop: clrivc and cl2srivc on the same records. For cl2srivc
  ## both its reported sd (the two-stage covariance) and stage 2's SRIVC
  ## sd (white noise, u_hat exact: the covariance that ignores stage 1).
  Ts = 0.01; N = 6000;
  r = kron (sign (randn (N / 100, 1)), ones (100, 1));
  G = tf (3, [1 2 3]); Mc = tf ([0.5 1], [0.1 1 0]);
  yr = lsim (c2d (feedback (G * Mc, 1), Ts), r);
  ur = lsim (c2d (feedback (Mc, G), Ts), r);
  Sy = c2d (feedback (1, G * Mc), Ts);
  Su = c2d (feedback (Mc, G), Ts);
  [TC, SC, T2, S2, S2w] = deal (zeros (R, 3));
  for i = 1:R
    v = filter ([1 0.3], [1 -0.95], 0.005 * randn (N, 1));
    yc = yr + lsim (Sy, v);
    uc = ur - lsim (Su, v);
    M = clrivc (iddata (yc, uc, Ts, "InterSample", "foh"), r,
                [1 1 1 2 0], Mc, "ReferenceAt", "setpoint");
    TC(i, :) = M.theta; SC(i, :) = sqrt (diag (M.covariance)).';
    M2 = cl2srivc (iddata (yc, uc, Ts), r, [1 2 0], [4 4 0]);
    T2(i, :) = M2.theta; S2(i, :) = sqrt (diag (M2.covariance)).';
    S2w(i, :) = sqrt (diag (M2.Report.Parameters.Stage2Covariance)).';
  endfor
  S.clrivc = summary ("clrivc [1 1 1 2 0]", TC, SC, [2 3 3], R);
  S.cl2srivc = summary ("cl2srivc [1 2 0] [4 4 0]", T2, S2, [2 3 3], R);
  S.cl2srivc_stage2 = summary ("cl2srivc, stage 2's SRIVC sd", T2, S2w,
                               [2 3 3], R);
endfunction

## Two inputs, B1/F1 = (1.5 s + 4)/(s^2 + 1.2 s + 4), B2/F2 = 2/(s + 0.5)
## (2 samples of delay), ARMA(1,1) noise.
function s = miso (R)
  randn ("state", 8);
  Ts = 0.05; N = 3000;
  u1 = kron (sign (randn (N / 10, 1)), ones (10, 1));
  u2 = kron (sign (randn (N / 15, 1)), ones (15, 1));
  x = lsim (c2d (tf ([1.5 4], [1 1.2 4]), Ts), u1) ...
      + lsim (c2d (tf (2, [1 0.5]), Ts), [0; 0; u2(1:end-2)]);
  th0 = [1.2 4 0.5 1.5 4 2];
  [T, SD] = deal (zeros (R, 6));
  for i = 1:R
    v = filter ([1 0.5], [1 -0.9], 0.05 * randn (N, 1));
    M = rivc (iddata (x + v, [u1 u2], Ts), [2 1 1 1 2 1 0 2]);
    T(i, :) = M.theta; SD(i, :) = sqrt (diag (M.covariance)).';
  endfor
  s = summary ("rivc MISO [2 1 1 1 2 1 0 2]", T, SD, th0, R);
endfunction

## rivc against srivc on the same R records x + noise ().
function [sr, ss] = versus_srivc (R, x, u, Ts, th0, nn, noise, what)
  [TR, SR, TS, SS] = deal (zeros (R, 4));
  for i = 1:R
    data = iddata (x + noise (), u, Ts);
    M = rivc (data, nn);
    TR(i, :) = M.theta; SR(i, :) = sqrt (diag (M.covariance)).';
    Ms = srivc (data, [2 2 0]);
    TS(i, :) = Ms.theta; SS(i, :) = sqrt (diag (Ms.covariance)).';
  endfor
  sr = summary (sprintf ("rivc %s%s", mat2str (nn), what), TR, SR, th0, R);
  ss = summary ("srivc [2 2 0] (same records)", TS, SS, th0, R);
endfunction

## The statistics of one estimator, printed at once.
function s = summary (name, T, SD, th0, R)
  s.name = name;
  s.bias = mean (T) - th0;
  s.mc_sd = std (T);
  s.rep_sd = mean (SD);
  s.ratio = s.mc_sd ./ s.rep_sd;
  s.rmse = sqrt (mean ((T - th0) .^ 2));
  printf ("%s (R = %d)\n", s.name, R);
  printf ("  bias      %s\n  MC sd     %s\n  rep. sd   %s\n",
          mat2str (s.bias, 3), mat2str (s.mc_sd, 3), mat2str (s.rep_sd, 3));
  printf ("  ratio     %s\n  RMSE      %s\n", mat2str (s.ratio, 3),
          mat2str (s.rmse, 3));
  fflush (stdout);
endfunction
