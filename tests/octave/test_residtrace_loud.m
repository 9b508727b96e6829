## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn {} {} test_residtrace_loud ()
## Every failure loud: on the simulated pendulum record
## (@code{devel/validation/lab_rigs.m}; torque motor V -> potentiometer angle in
## degrees, hanging at 180 degrees, m g l sin(theta)), with a user's model
## (@code{srivc} [1 2 0] on the raw record) and residtrace's defaults:
## @itemize
## @item no raw warning reaches the user (the drift candidate's segment
## fits are singular there, and Octave's solver would print "matrix
## singular to machine precision"); a candidate that cannot be
## estimated says "cannot test: ..." in its reason;
## @item no candidate reports a standard deviation of exactly 0, in any
## pass;
## @item @code{R.rmse_given} is the model as srivc returned it, with the
## output offset it estimated (180 degrees): the simulation of
## @code{simc} on the validation input plus that offset, computed here
## independently (without the offset, 180 degrees off).
## @end itemize
## It does not check residtrace's verdict (reported by
## @code{demos/residtrace_lab_rigs.m}).
## @end deftypefn

function test_residtrace_loud ()
  root = ctid_test_root ();
  addpath (fullfile (root, "octave"));
  addpath (fullfile (root, "demos"));
  addpath (fullfile (root, "devel", "validation"));
  rig = lab_rigs ("pendulum", 1, 0);
  [M, ~, ~, ~, ~, info] = srivc (rig.de, [1 2 0]);
  assert (info.output_offset);
  R = [];
  out = evalc ("R = residtrace (rig.de, M, 'validation', rig.dv);");
  printf ("%s", out);
  assert (isempty (strfind (out, "warning")),
          "residtrace printed a warning:\n%s", out);

  ## every evidence standard deviation of every pass: an estimate or NaN
  rows = R.ranking(:);
  for h = 1:numel (R.history)
    rows = [rows; R.history(h).ranking(:)];
  endfor
  for k = 1:numel (rows)
    ev = rows(k).evidence;
    if (isstruct (ev) && isfield (ev, "std") && isnumeric (ev.std))
      assert (! any (ev.std(:) == 0), "%s: a standard deviation of 0 (%s)",
              rows(k).effect, ev.text);
    endif
  endfor

  ## the given model's figure, with the levels it carries
  lev = get (M, "Report").DataUsed;
  assert (lev.OutputOffset, 180, 5);
  uv = get (rig.dv, "InputData");
  yv = get (rig.dv, "OutputData");
  ys = simc (M, uv - lev.InputOffset, rig.Ts, "Levels", "ignore") ...
       + lev.OutputOffset;
  given = sqrt (mean ((yv - ys) .^ 2));
  printf ("rmse_given %.4g deg (independent %.4g), rmse_before %.4g\n",
          R.rmse_given, given, R.rmse_before);
  assert (R.rmse_given, given, 1e-6 * given);
  assert (R.rmse_given < 30);           # not the 180-degree level
endfunction
