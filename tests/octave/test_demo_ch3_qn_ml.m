## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## demo_ch3_qn_ml (thesis sec. 3.3.3) runs in reduced form (3 noise runs,
## 2 per alternative PRBS clock) and its results hold:
## - every ML q lies within the bounds [1e-6, 1e-4];
## - on run 1 the cost at the ML q is no worse than at any point of a
##   41-point grid over the bounds (up to 1e-9 relative: the search stops
##   when log10 q moves by less than 1e-3, and V is smooth there);
## (the time of the search, required under 30 s, is measured by
## bench/qnml_octave_bench.m, not here: no timing in tests);
## - the thesis' q = 3.3e-5 lies within the range the PRBS clocks give.
function test_demo_ch3_qn_ml ()
  run_demo_test (@check);
endfunction

function check (out, root)
  res = demo_ch3_qn_ml (out, 3, 2);
  check_demo_outputs (out, {"fig_3_3_data.png", "fig_3_4_cost.png", ...
                      "fig_3_5_rsrivc.png"},
                      "ch3_qn_ml.md", {"3.3e-5", "prbs (8, 40)"});
  allq = vertcat (res.sens.q);
  assert (all (allq >= 1e-6 & allq <= 1e-4));
  assert (res.V <= min (res.Vgrid) + 1e-9 * abs (res.V));
  assert (min (allq) < 3.3e-5 && max (allq) > 3.3e-5);
endfunction
