## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn {} {@var{S} =} closed_loop_mc (@var{R}, @var{cases})
## Monte Carlo of the closed-loop refined IV estimators' reported standard
## deviations (target: spread / mean reported sd in 0.8-1.25) on
## data that meet the estimators' intersample assumptions, so that the
## spread is not dominated by an intersample bias (as it is on the
## CONTSID closedloop demos' data, where u jumps with r and is continuous
## between the jumps).
##
## Cases (@var{cases}, a cell of names; default all):
## @table @code
## @item "dt"
## the thesis' loop u = r1 - C(q^-1) y with a discrete PI controller
## (eq. 2.55, backward Euler), the plant ZOH-exact at the samples
## (c2d), white measurement noise e in y fed back through C: u is
## piecewise constant, the data are exact. clsrivc with the discrete
## controller.
## @item "ct"
## the loop u = C(p) (r - y) (r the setpoint) with a strictly proper continuous
## controller C = (0.5 s + 1) / (0.1 s^2 + s), r ZOH, a white
## output disturbance v held over each sample (ZOH) so that y(t_k) =
## G u (t_k) + v_k exactly; the closed loop is sampled exactly (c2d of
## the loop's transfer functions). u = C (r - y) is smooth (C strictly
## proper), FOH reproduces it to O((w Ts)^2): the noise-free estimate's
## error is printed against the spread. clsrivc (data 'foh'), clrivc
## [1 0 0 2 0] (both with "ReferenceAt", "setpoint") and cl2srivc [1 2 0]
## [4 4 0].
## @item "ctc"
## the same loop with coloured noise v = (1 + 0.3 q^-1) / (1 - 0.95
## q^-1) e: clrivc [1 1 1 2 0] and cl2srivc (clsrivc's white-noise sd do
## not apply).
## @item "demo"
## the loop of CONTSID's closedloop1 demo as the family replay builds it
## (G = (s + 1)/(s^2 + 0.5 s + 1), C = (10 s + 15)/s, r = prbs (4, 500),
## Ts = 0.005, white FOH disturbance at 20 dB): u = r - C y, r at the
## plant input. clsrivc and clrivc [2 0 0 2 0] called as the demo calls
## them (r at the plant input, their default "ReferenceAt"), and clsrivc
## told the wrong loop ("ReferenceAt", "setpoint": the instruments of u =
## C (r - y), not optimal; the covariance is the IV sandwich, so its sd
## must still match its own, larger, spread).
## @end table
##
## Per estimator and parameter: the bias, the Monte Carlo sd, the mean
## reported sd and their ratio. Run from the repository root (minutes):
## @example
## devel/run-study closed_loop_mc 100
## @end example
## @end deftypefn

function S = closed_loop_mc (R, cases)
  if (nargin < 1)
    R = 100;
  endif
  if (nargin < 2)
    cases = {"dt", "ct", "ctc", "demo"};
  endif
  cases = cellstr (cases);
  pkg load control
  warning ("off", "all");
  S = struct ();
  if (any (strcmp (cases, "dt")))
    S.dt = discrete_loop (R);
  endif
  if (any (strcmp (cases, "ct")))
    S.ct = continuous_loop (R, false);
  endif
  if (any (strcmp (cases, "ctc")))
    S.ctc = continuous_loop (R, true);
  endif
  if (any (strcmp (cases, "demo")))
    S.demo = demo_loop (R);
  endif
endfunction

## closedloop1's loop u = r - C y (r at the plant input).
function s = demo_loop (R)
  N0 = [0 1 1]; D0 = [1 0.5 1]; Nc = [10 15]; Dc = [1 0];
  Acl = conv (D0, Dc) + conv (N0, Nc);
  M0yr = idpoly (1, conv (N0, Dc), 1, 1, Acl, "Ts", 0);
  M0ur = idpoly (1, conv (D0, Dc), 1, 1, Acl, "Ts", 0);
  M0ud = idpoly (1, conv (D0, Nc), 1, 1, Acl, "Ts", 0);
  Mc = tf (Nc, Dc);
  th0 = [0.5 1 1 1];
  randn ("state", 26);
  r = [0; prbs(4, 500)]; Ts = 0.005; N = numel (r);
  datar = iddata ([], r, Ts, "InterSample", "zoh");
  ydet = simc (M0yr, datar); udet = simc (M0ur, datar);
  Cy = lsim (c2d (Mc, Ts, "foh"), ydet);
  printf (["demo loop: |u - (r - C y)| / |u| = %.2g, ", ...
           "|u - C (r - y)| / |u| = %.2g\n"],
          norm (udet - (r - Cy)) / norm (udet),
          norm (udet - lsim (c2d (Mc, Ts), r) + Cy) / norm (udet));
  [T, SD, Tc, SDc, Tw, SDw] = deal (zeros (R, 4));
  t0 = cputime ();
  for i = 1:R
    e = randn (N, 1);
    d = (e - mean (e)) / std (e) * std (ydet) / 10;
    y = ydet + simc (M0ur, iddata ([], d, Ts, "InterSample", "foh"));
    u = udet + simc (M0ud, iddata ([], -d, Ts, "InterSample", "foh"));
    data_yu = iddata (y, u, Ts, "InterSample", "zoh");
    data_yr = iddata (y, r, Ts, "InterSample", "zoh");
    M = clsrivc (data_yu, data_yr, [2 2 0], Mc);
    T(i, :) = M.theta; SD(i, :) = sqrt (diag (M.covariance)).';
    M = clrivc (data_yu, data_yr, [2 0 0 2 0], Mc, 1);
    Tc(i, :) = M.theta; SDc(i, :) = sqrt (diag (M.covariance)).';
    M = clsrivc (data_yu, data_yr, [2 2 0], Mc, "ReferenceAt", "setpoint");
    Tw(i, :) = M.theta; SDw(i, :) = sqrt (diag (M.covariance)).';
  endfor
  printf ("demo loop: %.1f s CPU for %d runs\n", cputime () - t0, R);
  s.as_demo = summary ("demo loop: clsrivc [2 2 0] as the demo calls it", T,
                       SD, th0);
  s.clrivc = summary ("demo loop: clrivc [2 0 0 2 0] as the demo calls it",
                      Tc, SDc, th0);
  s.wrong_loop = summary (["demo loop: clsrivc told ReferenceAt = ", ...
                           "setpoint (another loop)"], Tw, SDw, th0);
endfunction

## The thesis' loop with a discrete PI controller, exact at the samples.
function s = discrete_loop (R)
  randn ("state", 7);
  Ts = 0.01; N = 4000;
  G = tf (200, [1 10 160]);           # the clsrivc example's plant
  th0 = [10 160 200];
  kp = 0.5; ki = 2;
  C = struct ("kp", kp, "ki", ki, "kd", 0);
  ## backward Euler PI: C(q^-1) = (kp + ki Ts - kp q^-1) / (1 - q^-1)
  Cd = tf ([kp + ki * Ts, -kp], [1 -1], Ts);
  Gd = c2d (G, Ts, "zoh");
  r1 = kron (sign (randn (N / 50, 1)), ones (50, 1));
  ## y = Gd u + e, u = r1 - Cd y
  Syr = feedback (Gd, Cd);            # r1 -> y
  Sur = feedback (1, Gd * Cd);        # r1 -> u
  Sye = feedback (1, Gd * Cd);        # e -> y
  Sue = -feedback (Cd, Gd);           # e -> u
  yr = lsim (Syr, r1); ur = lsim (Sur, r1);
  M = clsrivc (iddata (yr, ur, Ts), r1, [1 2 0], C);
  printf ("dt loop, noise-free clsrivc: relative error %.2g\n",
          norm (M.theta - th0) / norm (th0));
  sd_e = 0.1 * std (yr);
  [T, SD] = deal (zeros (R, 3));
  for i = 1:R
    e = sd_e * randn (N, 1);
    y = yr + lsim (Sye, e); u = ur + lsim (Sue, e);
    M = clsrivc (iddata (y, u, Ts), r1, [1 2 0], C);
    T(i, :) = M.theta; SD(i, :) = sqrt (diag (M.covariance)).';
  endfor
  s.clsrivc = summary ("dt loop: clsrivc [1 2 0], discrete PI", T, SD, th0);
endfunction

## The CONTSID loop with a continuous controller, sampled exactly.
function s = continuous_loop (R, coloured)
  randn ("state", 5 + coloured);
  Ts = 0.01; N = 6000;
  G = tf (3, [1 2 3]); Mc = tf ([0.5 1], [0.1 1 0]);
  th0 = [2 3 3];
  r = kron (sign (randn (N / 100, 1)), ones (100, 1));
  ## r and v ZOH: y = G u + v, u = Mc (r - y), each map sampled exactly.
  yr = lsim (c2d (feedback (G * Mc, 1), Ts), r);
  ur = lsim (c2d (feedback (Mc, G), Ts), r);
  Sy = c2d (feedback (1, G * Mc), Ts);
  Su = c2d (feedback (Mc, G), Ts);
  if (coloured)
    noise = @() filter ([1 0.3], [1 -0.95], 0.005 * randn (N, 1));
    what = "ct loop, coloured noise";
  else
    noise = @() 0.05 * randn (N, 1);
    what = "ct loop, white noise";
  endif
  fit = @(y, u) {clsrivc(iddata (y, u, Ts, "InterSample", "foh"),
                         iddata (y, r, Ts), [1 2 0], Mc,
                         "ReferenceAt", "setpoint"),
                 clrivc(iddata (y, u, Ts, "InterSample", "foh"), r,
                        [1 coloured coloured 2 0], Mc,
                        "ReferenceAt", "setpoint"),
                 cl2srivc(iddata (y, u, Ts), r, [1 2 0], [4 4 0])};
  names = {"clsrivc [1 2 0]", ...
           sprintf("clrivc [1 %d %d 2 0]", coloured, coloured), ...
           "cl2srivc [1 2 0] [4 4 0]"};
  M = fit (yr, ur);
  for k = 1:3
    printf ("%s, noise-free %s: error %s\n", what, names{k},
            mat2str (M{k}.theta - th0, 3));
  endfor
  T = SD = repmat ({zeros(R, 3)}, 1, 3);
  for i = 1:R
    v = noise ();
    y = yr + lsim (Sy, v); u = ur - lsim (Su, v);
    M = fit (y, u);
    for k = 1:3
      T{k}(i, :) = M{k}.theta;
      SD{k}(i, :) = sqrt (diag (M{k}.covariance)).';
    endfor
  endfor
  for k = 1:3
    s.(strtok (names{k})) = summary ([what ": " names{k}], T{k}, SD{k}, th0);
  endfor
endfunction

## The statistics of one estimator, printed at once.
function s = summary (name, T, SD, th0)
  s.name = name;
  s.bias = mean (T) - th0;
  s.mc_sd = std (T);
  s.rep_sd = mean (SD);
  s.ratio = s.mc_sd ./ s.rep_sd;
  printf ("%s (R = %d)\n", s.name, rows (T));
  printf ("  bias      %s\n  MC sd     %s\n  rep. sd   %s\n",
          mat2str (s.bias, 3), mat2str (s.mc_sd, 3), mat2str (s.rep_sd, 3));
  printf ("  ratio     %s\n", mat2str (s.ratio, 3));
  fflush (stdout);
endfunction
