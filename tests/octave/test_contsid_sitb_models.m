## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## The SITB model objects (idpoly, idtf, idproc, idss, idfrd) against
## independent computations: simulation, step and Bode of an idpoly/idtf
## equal the control package's on the same tf (lsim of the exact ZOH
## model, step, bode); c2d/d2c round trips; present's standard deviations
## are the square roots of the covariance diagonal and agree with the
## spread of SRIVC estimates over noise realisations; bad input raises
## identified errors; everything but the control-package methods works
## with the control package unloaded.
function test_contsid_sitb_models ()
  pkg load control
  Ts = 0.05;
  u = prbs (8, 4);
  N = numel (u);
  t = (0:N-1)' * Ts;

  ## simulation: idpoly and idtf (MISO with delays) vs lsim (c2d (tf))
  B = [1 4]; F = [1 2.4 4];
  G = tf (B, F);
  yc = lsim (c2d (G, Ts, "zoh"), u, t);
  M = idpoly (1, B, 1, 1, F, "Ts", 0);
  Y = sim (M, iddata (zeros (N, 0), u, Ts, "InterSample", "zoh"));
  err_sim = max (abs (Y.y - yc));
  printf ("sim idpoly vs lsim (c2d (tf)): max error %.2e\n", err_sim);
  assert (err_sim < 1e-10);
  u2 = [u, circshift(u, 37)];
  M2 = idpoly (1, {B, 2}, 1, 1, {F, [1 3]}, 0, 0, "InputDelay", [0; 3] * Ts);
  y2 = simc (M2, iddata (zeros (N, 0), u2, Ts));
  y2c = lsim (c2d (G, Ts), u2(:, 1), t) ...
        + lsim (c2d (tf (2, [1 3]), Ts), [0; 0; 0; u2(1:end-3, 2)], t);
  printf ("MISO idpoly with delays: max error %.2e\n", max (abs (y2 - y2c)));
  assert (y2, y2c, 1e-10);

  ## step and bode vs the control package on the same tf
  ts = (0:0.02:6)';
  assert (step (M, ts), step (G, ts)(:), 1e-10);
  assert (step (idtf (B, F), ts), step (G, ts)(:), 1e-10);
  w = logspace (-2, 2, 50)';
  [m1, p1] = bode (M, w);
  [mc, pc] = bode (G, w);
  printf ("bode magnitude: max relative error %.2e\n",
          max (abs (squeeze (m1) - mc(:)) ./ mc(:)));
  assert (squeeze (m1), mc(:), 1e-12 * max (mc));
  assert (squeeze (p1), pc(:), 1e-9);

  ## c2d / d2c round trips
  for method = {"zoh", "tustin"}
    Md = c2d (M, Ts, method{1});
    Mc = d2c (Md, method{1});
    printf ("c2d/d2c (%s): |F - F0| = %.2e\n", method{1},
            norm (Mc.F - M.F));
    assert (Mc.F, M.F, 1e-8);
    b = Mc.B;                          # tustin leaves a rounding-level s^2
    assert (all (abs (b(1:end-2)) < 1e-9));
    assert (b(end-1:end), M.B, 1e-8);
  endfor
  S = idss ([-1 2; -2 -1], [0; 1], [1 0], 0.5);
  Sc = d2c (c2d (S, Ts));
  assert (sort (eig (Sc.A)), sort (eig (S.A)), 1e-10);

  ## present: printed sd = sqrt (diag (getcov)); Monte Carlo spread
  M0 = idpoly (1, 2, 1, 1, [1 1.2 2], "Ts", 0);
  x = simc (M0, u, Ts);
  R = 40;
  P = zeros (R, 3);
  SD = zeros (R, 3);
  wb = [0.5; 1.4; 3];                  # below, at and above the resonance
  MAG = zeros (R, 3);
  SDMAG = zeros (R, 3);
  randn ("state", 11);
  for r = 1:R
    Me = srivc (iddata (x + 0.1 * randn (N, 1), u, Ts), [1 2 0],
                "lambda", 2);
    [P(r, :), SD(r, :)] = getpvec (Me);
    [m, ~, ~, sdm] = bode (Me, wb);
    MAG(r, :) = squeeze (m).';
    SDMAG(r, :) = squeeze (sdm).';
  endfor
  assert (SD(end, :).', sqrt (diag (getcov (Me))), 0);
  txt = present (Me);
  [p, sd] = getpvec (Me);
  expect = sprintf ("B(s) = %.4g (+/- %.4g)", p(1), sd(1));
  assert (! isempty (strfind (txt, expect)));
  ratio = std (P) ./ mean (SD);
  printf (["Monte Carlo (%d runs): spread / reported sd = %.2f %.2f %.2f", ...
           " (b0 f1 f2)\n"], R, ratio);
  ## 40 runs: the sample std has about 11 %% relative error (1 sigma).
  assert (all (ratio > 0.6 & ratio < 1.6));
  assert (abs (mean (P) - [2 1.2 2]) < 3 * std (P) / sqrt (R));
  ## bode's 'sd' band: spread of |G(jw)| against the propagated sd
  ratio = std (MAG) ./ mean (SDMAG);
  printf ("Monte Carlo: spread of |G| / bode's sd = %.2f %.2f %.2f\n", ratio);
  assert (all (ratio > 0.6 & ratio < 1.6));

  ## identified errors
  expect_error ("idpoly:badInput", @() idpoly (1, 2, 1, 1, [2 1], "Ts", 0));
  expect_error ("idpoly:badInput",
                @() idpoly (1, 2, 1, 1, [1 1], "Ts", 0, "InputDelay", -1));
  expect_error ("idtf:badInput", @() idtf (1, [1 1], "NoSuchProperty", 1));
  expect_error ("idfrd:notSupported", @() step (idfrd (1, 1)));
  expect_error ("simc:notSupported",
                @() simc (idpoly (1, 1, 1, 1, [1 -0.5], 1, 0.1), u, Ts));
  expect_error ("tf:notSupported", @() tf (idtf (1, [1 1], "IODelay", 1)));
  expect_error ("c2d:badInput", @() c2d (c2d (M, Ts), Ts));

  ## without the control package loaded
  pkg unload control
  M = idpoly (1, B, 1, 1, F, "Ts", 0);
  txt = evalc ("present (M)");
  y = simc (M, iddata (zeros (N, 0), u, Ts));
  [~, info] = comparec (iddata (y, u, Ts), M);
  assert (info.Fit, 100, 1e-8);
  [m2] = bode (M, w);                  # loads the control package
  assert (m2, m1, 1e-12);
endfunction

function expect_error (id, f)
  try
    f ();
  catch err
    assert (err.identifier, id);
    return;
  end_try_catch
  error ("test_contsid_sitb_models: expected error %s", id);
endfunction
