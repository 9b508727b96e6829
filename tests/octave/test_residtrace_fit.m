## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## residtrace_fit (private): a real pole
## that a fit leaves beyond what the samples can see (p Ts > 1000) is
## residualised and the model fitted again in the lower order (not in the
## re-estimates of the current structure).
## @itemize
## @item A record of a second-order system with a zero, fitted in a
## third-order structure started from the truth times a pole at p Ts =
## 1e4 (a mode gone within a hundredth of a sample): the model returned
## is of second order, and its F and B are the system's (to the noise's
## precision: relative 1e-2), its simulation error the noise's.
## @item The same with @code{ctx.keep_order} (residtrace's re-estimates
## of the current model in its own structure): the third order is kept.
## @item The same with the third pole at p Ts = 4 (a pole the samples
## see, like the Silverbox's order candidate's -2484 rad/s at Ts = 1.6
## ms): the third order is kept and the pole estimated within 10 %.
## @end itemize
function test_residtrace_fit ()
  root = ctid_test_root ();
  here = pwd ();
  unwind_protect
    cd (fullfile (root, "octave", "private"));   # the private functions
    check ();
  unwind_protect_cleanup
    cd (here);
  end_unwind_protect
endfunction

function check ()
  randn ("state", 90901);
  Ts = 0.01; N = 4000;
  u = filter (0.3, [1 -0.7], randn (N, 1));
  F2 = [1 1.2 4]; B2 = [2 10];
  x2 = simc (idctm (B2, F2), u, Ts);
  sn = 1e-3 * std (x2);
  ctx = struct ("maxiter", 30, "opts", struct ("substeps", 10));
  for pTs = [1e4 4]
    p = pTs / Ts;
    F3 = conv ([1 p], F2); B3 = p * B2;
    y = simc (idctm (B3, F3), u, Ts) + sn * randn (N, 1);
    D = struct ("y", y, "u", u, "Ts", Ts, "intersample", "zoh", "loop", [],
                "vhat", zeros (N, 2), "ysm", y);
    tmpl = residtrace_base (struct ("B", B3, "F", F3, "nk", 0),
                            struct ("intersample", "zoh", "Ts", Ts));
    m = residtrace_fit (tmpl, D, ctx, {F3});
    assert (m.ok);
    e = y - residtrace_simulate (m, u, Ts, [], 10);
    printf ("p Ts = %g: order %d, F %s, B %s, error RMS / noise %.3f\n",
            pTs, numel (m.F) - 1, mat2str (m.F, 5),
            mat2str (m.channels.B, 5), sqrt (mean (e .^ 2)) / sn);
    assert (sqrt (mean (e .^ 2)) < 1.2 * sn);
    if (pTs > 1000)
      assert (numel (m.F), 3);             # residualised
      assert (m.fixed, [false false]);
      assert (m.F, F2, 1e-2 * norm (F2));
      assert (m.channels.B, B2, 1e-2 * norm (B2));
      assert (m.np, 4);
      ctx.keep_order = true;
      m = residtrace_fit (tmpl, D, ctx, {F3});
      ctx.keep_order = false;
      assert (m.ok);
      assert (numel (m.F), 4);             # the current structure's order
    else
      assert (numel (m.F), 4);             # kept
      assert (max (abs (roots (m.F))), p, 0.1 * p);
    endif
  endfor
  check_initial_state_cov ();
  printf ("test_residtrace_fit: passed\n");
endfunction

## With the record's initial state estimated, a fit that the engine finds
## stationary at its first iteration must not come back with a covariance
## of zeros (standard deviations of exactly 0). A first-order
## record with a known free response: the fit with the initial state
## estimated must give the standard deviations of the fit, on the same
## noise, of the record with that free response removed exactly and no
## initial state (the same model; the free response adds one nuisance
## parameter of 2000 samples' worth, so within 25 %).
function check_initial_state_cov ()
  randn ("seed", 1);
  Ts = 0.05; N = 2000;
  u = kron (sign (randn (N / 10, 1)), ones (10, 1));
  F = [1 0.5]; B = 2;
  t = (0:N-1)' * Ts;
  a = exp (-0.5 * Ts);
  x = filter ([0 4 * (1 - a)], [1 -a], u);     # 2/(s+0.5), ZOH
  v = 0.02 * randn (N, 1);
  free = 3 * exp (-0.5 * t);
  ctx = struct ("maxiter", 30, "opts", struct ("substeps", 10),
                "keep_order", true);
  tmpl = residtrace_base (struct ("B", B, "F", F, "nk", 0),
                          struct ("intersample", "zoh", "Ts", Ts));
  sd = {};
  for with_x0 = [true false]
    y = x + v + with_x0 * free;
    D = struct ("y", y, "u", u, "Ts", Ts, "intersample", "zoh", "loop", [],
                "vhat", zeros (N, 2), "ysm", y, "initial_state", with_x0);
    m = residtrace_fit (tmpl, D, ctx, {[]});     # the engine's start
    assert (m.ok);
    sd{end+1} = sqrt (diag (m.cov));
    printf ("initial state %d: theta %s +- %s\n", with_x0,
            mat2str (m.theta(:).', 5), mat2str (sd{end}.', 3));
  endfor
  assert (all (sd{1} > 0));
  assert (sd{1} ./ sd{2} > 0.95 & sd{1} ./ sd{2} < 1.25);
endfunction
