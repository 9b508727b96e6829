## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn {} {} test_irregular_intersample ()
## Irregularly sampled iddata without a given InterSample: the rule of the
## inputs between the instants is chosen from their smoothness, as
## CONTSID's simc documents (held when every change is followed by a
## sample without change, else linear).  Runs the inline tests of
## @file{contsid_intersample.m} and checks, against an independent
## simulation (the control package's @code{lsim} on a 1 ms grid with the
## input at the middle of each step, second-order accurate), that a
## multisine on irregular instants is simulated by @code{simc} within its
## linear-interpolation error (0.4 %; held between the instants it is 8 %
## off), and that @code{tfsrivc} on those noise-free data recovers the
## plant to within that interpolation error.
## @end deftypefn

function test_irregular_intersample ()
  ctid_run_private_tests ("contsid_intersample.m");
  root = ctid_test_root ();
  addpath (fullfile (root, "octave"));
  pkg load control
  rand ("seed", 3);
  t = cumsum ([0; 0.05 + 0.1 * rand(599, 1)]);
  w = [0.3 1 2.5];
  ms = @(tt) sum (sin (tt * w), 2);
  u = ms (t);
  G = idtf (4, [1 1.2 4]);
  h = 1e-3;
  tf_ = (0:h:t(end) + 2 * h)';
  ye = lsim (tf (4, [1 1.2 4]), ms (tf_ + h / 2), tf_);
  ye = interp1 (tf_, ye, t);
  y = simc (G, iddata ([], u, "SamplingInstants", t));
  err = norm (y - ye) / norm (ye);
  yz = simc (G, iddata ([], u, "SamplingInstants", t, "InterSample", "zoh"));
  errz = norm (yz - ye) / norm (ye);
  printf ("simc, irregular multisine: %.4f (held: %.4f) of the response\n",
          err, errz);
  if (! (err < 0.01 && errz > 0.03))
    error ("test_irregular_intersample: simc is %.4f (held %.4f) off", err,
           errz);
  endif
  ## the estimators read the same rule: the plant from the exact response
  M = tfsrivc (iddata (ye, u, "SamplingInstants", t), 2, 0, 0, "FixTd", "on");
  p = getpvec (M)(1:3);
  Mz = tfsrivc (iddata (ye, u, "SamplingInstants", t, "InterSample", "zoh"),
                2, 0, 0, "FixTd", "on");
  pz = getpvec (Mz)(1:3);
  dev = max (abs (p - [4; 1.2; 4]) ./ [4; 1.2; 4]);
  devz = max (abs (pz - [4; 1.2; 4]) ./ [4; 1.2; 4]);
  printf ("tfsrivc: largest relative error %.4f (held: %.4f)\n", dev, devz);
  if (! (dev < 0.01 && devz > 3 * dev))
    error ("test_irregular_intersample: tfsrivc is %.4f (held %.4f) off",
           dev, devz);
  endif
endfunction
