## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## demo_ch3_initial_conditions (thesis sec. 3.4.3, Table 3.1) runs and
## writes its figures and table; the overshoots keep the thesis' ordering.
##
## The record is noise-free and deterministic, so the overshoots without
## initial conditions are compared with the thesis' printed values at the
## printed precision (integers: within 0.5 percentage points). With i.c.
## the thesis' claim is "significantly reduced": required at least ten
## times smaller for a1 and b0; with t_s,ls = 2 s both below 0.1 %
## (thesis 0.0052 / 0.0193 %). c1 estimates y(0) = 18.103 to within the
## trapezoidal rule's error for y, (lambda Ts)^2/12 = 1.3e-4 relative,
## with a margin: 1e-3.
function test_demo_ch3_initial_conditions ()
  run_demo_test (@check);
endfunction

function check (out, root)
  res = demo_ch3_initial_conditions (out);
  check_demo_outputs (out, {"fig_3_6_data.png", "fig_3_7_estimates.png", ...
                      "fig_3_8_c1.png", "fig_3_9_tsls.png"},
                      "ch3_initial_conditions.md", {"6561", "5177", "0.0193"});
  assert (abs (res.without - [6561 5177]) < 0.5);
  assert (all (res.with_ic < res.without / 10));
  assert (all (abs (res.tsls) < 0.1));
  y0 = 20 * tanh (1.5);
  assert (abs (res.c1_end - y0) / y0 < 1e-3);
  assert (res.periodic_err < 1e-9);
endfunction
