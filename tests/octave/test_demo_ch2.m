## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## The Chapter 2 demos (thesis sec. 2.3.5, 2.3.6 and 2.4.6) run and write
## their figures and results tables; two noise runs each keep it short
## (about 20 s in all on a 2-core machine).
function test_demo_ch2 ()
  run_demo_test (@check);
endfunction

function check (out, root)
  demo_ch2_similar_rates (out, 2);
  check_demo_outputs (out, {"fig_2_3_estimates.png", "fig_2_4_relerr.png",
                      "fig_2_5_lag_error.png", "fig_2_6_noise_error.png"},
                      "ch2_similar_rates.md", {"1.152", "0.8036", "0.2672"});
  demo_ch2_different_rates (out, 2);
  check_demo_outputs (out, {"fig_2_11_rlssvf.png", "fig_2_12_iv.png",
                      "fig_2_13_rlssvf_relerr.png", "fig_2_14_iv_relerr.png"},
                      "ch2_different_rates.md", {"23.8 / 9.6 / 14.0",
                      "3.7 / 2.9 / 0.7"});
  demo_ch2_closed_loop (out, 2);
  check_demo_outputs (out, {"fig_2_17_rlssvf.png", "fig_2_18_cliv.png",
                      "fig_2_19_rlssvf_relerr.png", "fig_2_20_cliv_relerr.png"},
                      "ch2_closed_loop.md", {"30.2 / 7.3 / 11.1",
                      "4.8 / 6.1 / 1.5"});
  ## Sanity of the numbers: RSRIVC's lag MSE after tsiv is far below
  ## RLSSVF's (implementation notes, item 8: 0.029 vs 0.286).
  table = fileread (fullfile (out, "ch2_similar_rates.md"));
  row = @(name) str2double (regexp (table, ['\| ' name ' \| ([0-9.]+) \| [0-9.]+ \| [^|]+ \| ([0-9.]+) \|'],
                                    "tokens", "once"));
  rls = row ("RLSSVF");
  srivc = row ("RSRIVC");
  assert (numel (rls) == 2 && numel (srivc) == 2);
  assert (srivc(2) < 0.5 * rls(2));
endfunction
