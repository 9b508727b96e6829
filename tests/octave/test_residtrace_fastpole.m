## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn {} {} test_residtrace_fastpole ()
## Every failure loud, on a simulated Cascaded Tanks record
## (@code{devel/validation/cascaded_tanks_sim.m}, strong nonlinearity, record 1)
## with the user's @code{srivc} [3 3 0] model of the raw record. That
## model has a real pole far beyond the Nyquist frequency (p Ts of about
## 68); every candidate's fit started from it fails (instrument matrix
## rank deficient), and residtrace must not report "no effect of the
## library explains the residual" having tested none. Checked here:
## @itemize
## @item the case is the one meant: the model has a real pole with p Ts
## > pi;
## @item the candidates are tested: at least five have a finite score,
## and only the drift candidate (which keeps the model's order) may fail;
## @item a candidate whose estimation failed is never silent: its row
## says @code{failed}, it is listed in @code{R.untested} when the
## verdict found nothing, and the verdict names it. With the drift
## candidate alone (whose segment fits fail here) the verdict must begin
## "cannot tell" and name it, instead of "no effect explains the
## residual".
## @end itemize
## It does not check which effect residtrace names (the figures on these
## records are in @code{demos/residtrace_cascaded_tanks.m}).
## @end deftypefn

function test_residtrace_fastpole ()
  root = ctid_test_root ();
  addpath (fullfile (root, "octave"));
  addpath (fullfile (root, "demos"));
  addpath (fullfile (root, "devel", "validation"));
  [de, dv] = cascaded_tanks_sim ("records", 1, "strong");
  M = [];
  evalc ("M = srivc (de, [3 3 0]);");
  Ts = get (de, "Ts");
  p = roots (M.F);
  fast = imag (p) == 0 & -real (p) * Ts > pi;
  assert (any (fast), "the model has no pole beyond Nyquist: not the case");

  R = [];
  evalc ("R = residtrace (de, M, 'validation', dv);");
  r = R.ranking;
  tested = isfinite ([r.score]);
  failed = [r.failed];
  printf ("tested: %s\nfailed: %s\n", strjoin ({r(tested).effect}, ", "),
          strjoin ({r(failed).effect}, ", "));
  assert (sum (tested) >= 5, "only %d candidates tested", sum (tested));
  assert (all (strcmp ({r(failed).effect}, "drift")),
          "failed candidates: %s", strjoin ({r(failed).effect}, ", "));
  check_untested_named (R);

  ## the drift candidate alone: its failure must reach the verdict
  evalc ("R = residtrace (de, M, 'validation', dv, 'effects', {'drift'});");
  r = R.ranking;
  k = strcmp ({r.effect}, "drift");
  printf ("drift alone: %s\n", R.verdict);
  assert (r(k).failed || isfinite (r(k).score), "drift neither tested nor failed");
  if (r(k).failed)
    assert (isempty (R.effects));
    assert (R.untested, {"drift"});
    assert (strncmp (R.verdict, "cannot tell", 11), R.verdict);
  endif
  check_untested_named (R);
endfunction

## Every candidate of R.untested is a failed row of the last pass and is
## named in the verdict, which says that it was not tested.
function check_untested_named (R)
  if (isempty (R.untested))
    return;
  endif
  assert (! isempty (strfind (R.verdict, "not tested")), R.verdict);
  last = R.history(end).ranking;
  for j = 1:numel (R.untested)
    name = R.untested{j};
    assert (! isempty (strfind (R.verdict, name)), "%s not named", name);
    k = strcmp ({last.effect}, name);
    assert (any (k) && last(k).failed, "%s is not a failed row", name);
  endfor
endfunction
