## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn {} {} test_residtrace_stick ()
## Coulomb friction on a mass that sticks: a record of the random-effects
## study (@file{devel/validation/residtrace_effects_random.m}, seed 777,
## ninth Coulomb record): a mass on a spring with viscous and Coulomb
## friction 0.30 (input standard deviation 1), its position measured at
## 29 dB, driven by a staircase that leaves it stuck between the steps.
## At rest the sign of the measured velocity is the measurement noise's;
## fitted on it the friction's gain pushed along the motion, the friction
## was rejected and a static nonlinearity named. residtrace must name the
## Coulomb friction (fitted on the model's own velocity), with a level
## within a factor of two of the truth, and cut the validation error.
## @example
## octave --no-gui -q --eval \
##   "addpath tests/octave; test_residtrace_stick"
## @end example
## @end deftypefn

function test_residtrace_stick ()
  root = ctid_test_root ();
  addpath (fullfile (root, "octave"));
  addpath (fullfile (root, "demos"));
  addpath (fullfile (root, "devel", "validation"));
  d = tempname ();
  cleanup = onCleanup (@() confirm_rmdir (d));
  [~, C] = residtrace_effects_random (-9, 777, d, "coulomb", true);
  c = C(1);
  assert (! isempty (strfind (c.text, "Coulomb 0.30, position")));
  ws = warning ("off", "all");
  M = srivc (iddata (c.y - mean (c.y), c.u - mean (c.u), c.Ts), c.nn);
  warning (ws);
  M = idctm (M.B, M.F);
  R = residtrace (iddata (c.y, c.u, c.Ts), M,
                  "validation", iddata (c.yv, c.uv, c.Ts), "iterate", 1,
                  "effects", {"coulomb", "static_nonlinearity", "order"});
  printf ("%s: %s (%s), RMSE %.4g -> %.4g\n", c.text, R.effect,
          R.evidence.text, R.rmse_before, R.rmse_after);
  assert (R.effect, "coulomb");
  assert (R.evidence.physical > 0.15 && R.evidence.physical < 0.6);
  assert (R.rmse_after < 0.7 * R.rmse_before);
endfunction

function confirm_rmdir (d)
  if (exist (d, "dir"))
    confirm_recursive_rmdir (false, "local");
    rmdir (d, "s");
  endif
endfunction
