## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## The Chapter 3 hyperparameter demo (thesis secs. 3.1.2, 3.2.1) in
## reduced form: one noise run, ten segments, no tsiv sweep. It writes its
## figures and table, and
## on the thesis' examples, whose true parameters are known:
## - the suggested lambda_svf lies above the largest bandwidth of the local
##   models and within 25 % of the true maximum frozen bandwidth (the
##   thesis' choices are 1.072 and 1.015 times it);
## - the detected tsiv lies after the start-up of RLSSVF (the true error
##   has fallen to three times its steady level) and within 5 % of the
##   record (the thesis took 1.1 % and 1 %);
## - the constant b0 of example 2.3.6 is recognised as constant.
function test_demo_ch3_hyperparameters ()
  run_demo_test (@check);
endfunction

function check (out, root)
  res = demo_ch3_hyperparameters (out, 1, 10, false);
  figs = {"fig_ch3_bandwidth_235.png", "fig_ch3_bandwidth_236.png", ...
          "fig_ch3_tsiv_235.png", "fig_ch3_tsiv_236.png", ...
          "fig_ch3_tsiv_246.png"};
  for i = 1:numel (figs)
    f = fullfile (out, figs{i});
    assert (exist (f, "file") == 2, "missing %s", f);
    d = dir (f);
    assert (d.bytes > 1000, "empty figure %s", f);
  endfor
  txt = fileread (fullfile (out, "ch3_hyperparameters.md"));
  for s = {"| 2.3.5 | 100 s |", "| 2.3.6 | 10 s |", "| 2.4.6 | 10 s |", ...
           "| 3.2 |", "| 16 |"}
    assert (! isempty (strfind (txt, s{1})), "table lacks '%s'", s{1});
  endfor
  assert (numel (res) == 3);
  T = [9000 1000 1000];
  for e = 1:3
    r = res(e);
    if (e <= 2)
      lam = r.lam_runs(1);
      assert (lam >= 1.1 * r.K10.bwrange(2) * (1 - 1e-12));
      assert (abs (lam / r.bw_true(2) - 1) < 0.25,
              "%s: lambda %.3f vs true max bandwidth %.3f", r.name, lam,
              r.bw_true(2));
    endif
    assert (isfinite (r.tsiv(1)), "%s: no tsiv detected", r.name);
    assert (r.tsiv(1) >= r.t_su(1), "%s: tsiv %.1f before start-up end %.1f",
            r.name, r.tsiv(1), r.t_su(1));
    assert (r.tsiv(1) <= 0.05 * T(e), "%s: tsiv %.1f later than 5 %%",
            r.name, r.tsiv(1));
  endfor
  assert (res(2).spread.varying, [true true false]);
endfunction
