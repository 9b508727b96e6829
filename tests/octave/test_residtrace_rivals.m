## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn {} {} test_residtrace_rivals ()
## The candidates residtrace cannot tell from a pass's winner
## (@code{R.rivals}, found by the core's judgement,
## core/include/ctid/apps/residtrace/judgement.hpp, whose rules its
## GoogleTest tests check on constructed errors): on the simulated
## mixing_delay rig (a 12.4-sample transport delay, srivc's [1 2 11]: a
## second pole stands in for part of the delay), the delay found is not told apart from the order candidate:
## @code{R.rivals} names it, the verdict says so, and the encompassing
## test recomputed from the pass's ranking agrees (the winner's
## correction does not significantly improve on the rival's error).
## @example
## octave --no-gui -q --eval \
##   "addpath tests/octave; test_residtrace_rivals"
## @end example
## @end deftypefn

function test_residtrace_rivals ()
  root = ctid_test_root ();
  addpath (fullfile (root, "octave"));
  addpath (fullfile (root, "demos"));
  addpath (fullfile (root, "devel", "validation"));
  private_dir = fullfile (root, "octave", "private");
  addpath (private_dir);
  cleanup = onCleanup (@() rmpath (private_dir));
  rig = lab_rigs ("mixing_delay");
  ws = warning ("off", "all");
  M = srivc (rig.de, [1 2 11]);
  warning (ws);
  R = residtrace (rig.de, M, "validation", rig.dv);
  printf ("mixing_delay: %s\n", R.verdict);
  assert (numel (R.rivals) >= 1, "no rival reported");
  r = R.rivals(1);
  assert (fieldnames (R.rivals), {"found"; "effect"; "variant"; "score"; "p"});
  assert (! isempty (strfind (R.verdict, sprintf (
    "not told apart by these data: %s from %s", r.found, r.effect))),
    R.verdict);
  h = R.history(strcmp ({R.history.effect}, r.found));
  assert (numel (h), 1);
  assert ({h.rivals.effect}, {R.rivals(strcmp ({R.rivals.found},
                                               r.found)).effect});
  rk = h.ranking;
  win = rk(strcmp ({rk.effect}, r.found));
  riv = rk(strcmp ({rk.effect}, r.effect));
  assert (win.significant && riv.significant);
  ## the encompassing test (statistics.hpp): v = [score stat p bandwidth
  ## z p_corr]
  v = effect_sim_mex ("residtrace", "dmtest", riv.e1, win.e1, struct ());
  assert (! (v(6) < 0.01 && v(1) >= 0.01));
  assert (r.p, v(6), 1e-12);
  printf ("test_residtrace_rivals: %s rival of %s, p = %.3g, share %.3g\n",
          r.effect, r.found, v(6), v(1));
endfunction
