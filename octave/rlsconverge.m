## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn  {} {@var{tsiv} =} rlsconverge (@var{data}, @var{nn}, "lambda_svf", @var{lam}, @dots{})
## @deftypefnx {} {[@var{tsiv}, @var{info}, @var{thm}, @var{yh}] =} rlsconverge (@dots{})
## @deftypefnx {} {} rlsconverge (@dots{})
## Detect when the RLSSVF estimates have converged on training data: the
## time t_s,iv at which the recursive IV methods (@code{rivsvf},
## @code{rsrivc}, @code{clrivsvf}, @code{clrsrivc}) may take over from
## their RLSSVF start (thesis sec. 3.2.1, Suggested procedure 3.4). The
## estimators call it for @code{"tsiv", "auto"}.
##
## @var{data} and @var{nn} = [na nb nk] are those of @code{rlssvf}, and so
## are the options @code{lambda_svf} (required), @code{adm}, @code{adg},
## @code{th0}, @code{P0} and @code{svf}: RLSSVF is run once with them, as
## the IV routines run it before t_s,iv (P0 defaults to 1e4 I as there).
## Detector options:
## @table @code
## @item blocklength
## length T_b (s) of the blocks the record is cut into (default
## 2 * 2 pi / lambda_svf, two periods of the SVF cut-off: a block's mean
## square of the output error then averages the noise and the error
## dynamics, whose time scale is that of the SVF).
## @item nblocks
## the number n of consecutive blocks tested together (default 10).
## @item alpha
## significance level of the steady-state test of the output error
## (default 0.05).
## @item eyfloor
## the output error also counts as settled once its RMS is below eyfloor
## times that of y in all n blocks (default 1e-3, -60 dB: noise-free data,
## whose output error keeps shrinking).
## @item tol_theta
## tolerance on the variability of the estimates (default 0.05, 5 %).
## @item ptol
## tolerance on the size of P (default 1e-2): the data must have shrunk
## trace (P) to ptol trace (P0).
## @item criteria
## @qcode{"all"} (default), or one or a cell of several of
## @qcode{"outputerror"}, @qcode{"theta"}, @qcode{"P"}: the indices below
## that must all pass.
## @end table
##
## @strong{Algorithm.} Blocks b = 1, 2, @dots{} of length T_b from the
## first sample. For each block: E_b, the mean square of the output error
## y - yh (eq. 1.60, yh the output of the estimated model simulated along
## the record, @code{rlssvf}'s second output), the block mean of the
## estimates and trace (P) / trace (P0) at its end. A window of the
## n blocks ending at block k passes when
## @enumerate
## @item (@qcode{"outputerror"}) the output error is in steady state: the
## statistic of Cao and Rhinehart (1995), R = 2 sum (X - mean (X))^2 /
## sum (diff (X))^2 over X = log E_b of the window (a ratio of two
## estimates of the variance, about 1 for independent values about a
## constant level, larger along a trend), is below
## R_crit = 2 / (2 - z sqrt (4 (n-2) / ((n+1) (n-1)))), z the upper alpha
## quantile of the normal distribution (R = 2/eta, eta von Neumann's
## ratio, of mean 2 and variance 4 (n-2)/((n+1)(n-1))); R_crit = 1.88 for
## n = 10, alpha = 0.05; or E_b is below the floor in the whole window;
## @item (@qcode{"theta"}) the estimates have stopped moving: the RMS over
## the window of |theta_b - theta_(b-1)| / |theta_b|, the change of the
## block means relative to their size (the variability of Delta theta at
## the block scale, cf. Bittencourt et al. 2015), is below tol_theta;
## @item (@qcode{"P"}) the data have brought information on every
## parameter: trace (P) / trace (P0) <= ptol at the end of every block of
## the window (the
## size of P, thesis sec. 3.2.1). Without it an unexcited start (u = 0:
## the model is fitted to the noise, the output error and the estimates
## are steady) passes the first two. With a confident start (small P0)
## leave it out or raise ptol.
## @end enumerate
## @var{tsiv} = k T_b for the first such k: the end of the first passing
## window. The detection is causal: the decision at k T_b uses data up to
## k T_b only (RLSSVF is run over the whole record, but only its part
## before @var{tsiv} is used), so it could run online. It cannot come
## before n T_b (default: 20 periods of the SVF cut-off). The "P" index
## needs the covariance of every sample during the run (np^2 N values,
## freed at once).
##
## The defaults were checked on the thesis' Chapter 2 examples (secs.
## 2.3.5, 2.3.6, 2.4.6; README and @code{demos/demo_ch3_hyperparameters.m}):
## in steady state about 1 - alpha of the windows pass, and over 20 noise
## runs each the detected times lie after the start-up of RLSSVF, at
## 0.5-1.8 % of the records: 43-71 s for 2.3.5, 9-13 s for 2.3.6, 10-18 s
## for 2.4.6 (the thesis took 100 s, 10 s and 10 s).
##
## When no window passes, the warning @code{rlsconverge:notConverged} is
## raised and @var{tsiv} is NaN (the IV routines raise the error
## @code{<name>:notConverged} instead).
##
## @strong{Outputs.} @var{tsiv} (s from the first sample); @var{info}, a
## struct with the options used (@code{blocklength}, @code{nblocks},
## @code{alpha}, @code{Rcrit}, @code{tol_theta}, @code{eyfloor},
## @code{ptol}, @code{criteria}), @code{causal} (true), and per block
## @code{tblock} (end times), @code{ey_ms} and @code{y_ms} (mean squares of
## y - yh and of y), @code{R} (statistic of the window ending there, NaN for
## the first n-1 blocks), @code{dtheta} (relative change of the block
## means), @code{theta_index} (its RMS over the window), @code{P_index}
## (trace (P) / trace (P0) at the end of the block), @code{steady_ey},
## @code{steady_theta}, @code{small_P}; @code{converged}, @code{tsiv} and
## @code{k} (the first sample at or after tsiv); @var{thm} and @var{yh},
## the RLSSVF run. Without outputs it plots the estimates, the output
## error per block and the three indices relative to their thresholds.
##
## @strong{Example}
## @example
## Ts = 0.05; u = prbs (11, 6); N = numel (u);
## y = simc (idctm (4, [1 2.4 4]), u, Ts) + 0.1 * randn (N, 1);
## data = iddata (y, u, Ts, "InterSample", "zoh");
## tsiv = rlsconverge (data, [2 1 0], "lambda_svf", 3)
## thm = rivsvf (data, [2 1 0], "lambda_svf", 3, "tsiv", "auto");
## @end example
## @seealso{rlssvf, rivsvf, rsrivc, svfcutoff}
## @end deftypefn

function varargout = rlsconverge (varargin)
  varargout = contsid_guard ("rlsconverge", @rlsconverge_body, nargout,
                             varargin);
endfunction

function [tsiv, info, thm, yh, varargout] = rlsconverge_body (varargin)
  contsid_nargchk ("rlsconverge", nargin, nargout, [0 Inf], 4);
  fname = "rlsconverge";
  ## [] leaves an option to the core's default (recursive_options.hpp).
  rdef = struct ("lambda_svf", [], "adm", [], "adg", [], "th0", [],
                 "P0", [], "svf", []);
  ddef = struct ("blocklength", [], "nblocks", 10, "alpha", 0.05,
                 "tol_theta", 0.05, "eyfloor", 1e-3, "ptol", 1e-2,
                 "criteria", "all");
  defaults = rdef;
  dnames = fieldnames (ddef);
  for i = 1:numel (dnames)
    defaults.(dnames{i}) = ddef.(dnames{i});
  endfor
  [d, orders, opts] = contsid_recursive_args (fname, "a", defaults,
                                              varargin{:});
  contsid_check_input (fname, d.u, orders.nb);
  rls = contsid_recursive_options (fname, opts, orders.np, d);
  det = struct ();
  for i = 1:numel (dnames)
    det.(dnames{i}) = opts.(dnames{i});
  endfor
  nn = [orders.na, orders.nb, orders.nk];
  [ts, inf_, th, y_h] = contsid_converge (fname, d, nn, rls, det, false);
  ex = contsid_expand ({th, y_h}, d);     # back to N rows over gaps
  [th, y_h] = ex{:};
  if (nargout > 0)
    tsiv = ts; info = inf_; thm = th; yh = y_h;
    return;
  endif
  plot_detection (d.t - d.t(1), th, inf_);
endfunction

function plot_detection (t, thm, info)
  ## The start of the record: up to four times tsiv (or two windows).
  tb = info.tblock;
  tmax = 2 * info.nblocks * info.blocklength;
  if (info.converged)
    tmax = max (tmax, 4 * info.tsiv);
  endif
  tmax = min (tmax, t(end));
  subplot (3, 1, 1);
  plot (t, thm);
  ## Limits from the estimates after the first block (the start-up of
  ## RLSSVF from theta0 would hide them).
  v = thm(t > tb(1) & t <= tmax, :);
  yl = [min(v(:)), max(v(:))];
  yl += [-0.1 0.1] * max (diff (yl), eps);
  hold on;
  if (info.converged)
    plot (info.tsiv * [1 1], yl, "k--");
    title (sprintf ("RLSSVF estimates; convergence detected at t_{s,iv} = %g s",
                    info.tsiv));
  else
    title ("RLSSVF estimates; no convergence detected");
  endif
  hold off;
  axis ([0 tmax yl]);
  grid on;
  subplot (3, 1, 2);
  semilogy (tb, sqrt (info.ey_ms), "o-", tb, info.eyfloor * sqrt (info.y_ms),
            ":");
  xlim ([0 tmax]);
  ylabel ("RMS (y - y_h)");
  legend ("output error per block", "floor", "location", "northeast");
  grid on;
  subplot (3, 1, 3);
  semilogy (tb, info.R / info.Rcrit, "o-", tb,
            info.theta_index / info.tol_theta, "s-", tb,
            info.P_index / info.ptol, "d-", [0 tmax], [1 1], "k");
  xlim ([0 tmax]);
  ylabel ("index / threshold");
  xlabel ("time (s)");
  legend ("R / R_{crit}", "\\Delta\\theta / tol", "tr P / ptol",
          "location", "northeast");
  grid on;
endfunction

%!shared Ts, u, N, t, x
%! Ts = 0.05; u = prbs (11, 6); N = numel (u); t = (0:N-1)' * Ts;
%! x = simc (idctm (4, [1 2.4 4]), u, Ts);

%!test  # a slow start-up (P0 = 1): detected after it, not much later
%! randn ("state", 1);
%! y = x + 0.1 * randn (N, 1);
%! opts = {"lambda_svf", 3, "adm", "kf", "adg", 1e-6, "P0", 1};
%! [tsiv, info, thm] = rlsconverge (iddata (y, u, Ts), [2 1 0], opts{:}, ...
%!                                  "blocklength", 2, "nblocks", 5);
%! err = sqrt (sumsq (thm - [2.4 4 4], 2)) / norm ([2.4 4 4]);
%! ## End of the start-up: the last time the true error exceeds three
%! ## times its steady level (95th percentile over the second half); it
%! ## lies at 12-30 s for seeds 1-5, whereas n T_b = 10 s.
%! ss = quantile (err(t > t(end) / 2), 0.95);
%! t_su = t(find (err > 3 * ss, 1, "last"));
%! assert (info.converged);
%! assert (tsiv >= t_su);
%! ## Not absurdly late: the IV stage keeps at least 80 % of the record.
%! assert (tsiv <= 0.2 * t(end));

%!test  # default options: the structure of the decision
%! randn ("state", 2);
%! y = x + 0.1 * randn (N, 1);
%! [tsiv, info, thm] = rlsconverge (iddata (y, u, Ts), [2 1 0], ...
%!                                  "lambda_svf", 3, "adm", "kf", "adg", 1e-6);
%! err = sqrt (sumsq (thm - [2.4 4 4], 2)) / norm ([2.4 4 4]);
%! ss = quantile (err(t > t(end) / 2), 0.95);
%! assert (max (err(t >= tsiv)) < 2 * ss);
%! assert (info.blocklength, 2 * 2 * pi / 3, 1e-12);
%! assert (info.Rcrit, 1.88, 0.005);     # n = 10, alpha = 0.05
%! assert (info.causal);
%! assert (info.criteria, {"outputerror", "theta", "P"});
%! assert (t(info.k) >= tsiv && t(info.k - 1) < tsiv);
%! ## tsiv ends the first window where all three indices pass.
%! k = round (tsiv / info.blocklength);
%! assert (tsiv, k * info.blocklength, 1e-9);
%! ok = info.steady_ey & info.steady_theta & info.small_P;
%! assert (ok(k) && ! any (ok(1:k-1)));
%! assert (k >= info.nblocks);
%! ## The indices, by hand, for the window ending at k.
%! w = k - info.nblocks + 1:k;
%! X = log (info.ey_ms(w));
%! assert (info.R(k), 2 * sumsq (X - mean (X)) / sumsq (diff (X)), 1e-12);
%! assert (info.theta_index(k), sqrt (mean (info.dtheta(w(2:end)) .^ 2)),
%!         1e-12);
%! b = t < info.blocklength;             # the first block
%! assert (info.ey_ms(1), mean ((y(b) - nthargout (2, @rlssvf, ...
%!         iddata (y, u, Ts), [2 1 0], "lambda_svf", 3, "adm", "kf", ...
%!         "adg", 1e-6)(b)) .^ 2), 1e-12);

%!test  # no excitation for the first 200 s: detection only after it
%! randn ("state", 3);
%! u2 = u; u2(t < 200) = 0;
%! y = simc (idctm (4, [1 2.4 4]), u2, Ts) + 0.1 * randn (N, 1);
%! tsiv = rlsconverge (iddata (y, u2, Ts), [2 1 0], "lambda_svf", 3, ...
%!                     "adm", "kf", "adg", 1e-6);
%! assert (tsiv > 200);

%!test  # R_crit: 1 - alpha of windows of independent values pass
%! ## Monte Carlo of the statistic on independent normal values (log E_b
%! ## in steady state): the normal approximation of von Neumann's ratio
%! ## gives the stated level.
%! randn ("state", 4);
%! n = 10; M = 20000;
%! X = randn (n, M);
%! R = 2 * sumsq (X - mean (X), 1) ./ sumsq (diff (X), 1);
%! [~, info] = rlsconverge (iddata (x, u, Ts), [2 1 0], "lambda_svf", 3, ...
%!                          "alpha", 0.05, "nblocks", n);
%! assert (mean (R < info.Rcrit), 0.95, 0.01);
%! [~, info] = rlsconverge (iddata (x, u, Ts), [2 1 0], "lambda_svf", 3, ...
%!                          "alpha", 0.2, "nblocks", n);
%! assert (mean (R < info.Rcrit), 0.8, 0.02);

%!test  # noise-free data; the output-error test and its floor by hand
%! [tsiv, info] = rlsconverge (iddata (x, u, Ts), [2 1 0], "lambda_svf", 3, ...
%!                             "eyfloor", 2e-3);
%! assert (info.converged);
%! n = info.nblocks;
%! ## The start-up takes the first block (4.2 s): the first window without
%! ## it passes.
%! assert (tsiv <= (n + 1) * info.blocklength + 1e-9);
%! for k = n:numel (info.tblock)
%!   w = k - n + 1:k;
%!   fl = all (info.ey_ms(w) <= 4e-6 * info.y_ms(w));
%!   assert (info.steady_ey(k), info.R(k) < info.Rcrit || fl);
%!   assert (info.small_P(k), all (info.P_index(w) <= 1e-2));
%! endfor
%! [tsiv2, info2] = rlsconverge (iddata (x, u, Ts), [2 1 0], ...
%!                               "lambda_svf", 3, "criteria", "theta");
%! assert (tsiv2 <= tsiv);
%! assert (info2.criteria, {"theta"});
%! assert (all (isnan (info2.P_index)));

%!test  # irregular sampling instants: blocks by time
%! ti = cumsum ([0; 0.04 + 0.02 * mod((1:N-1)', 2)]);
%! randn ("state", 7);
%! y = simc (idctm (4, [1 2.4 4]), u, ti) + 0.1 * randn (N, 1);
%! [tsiv, info, thm] = rlsconverge (y, u, ti, [2 1 0], "lambda_svf", 3, ...
%!                                  "adm", "kf", "adg", 1e-6);
%! err = sqrt (sumsq (thm - [2.4 4 4], 2)) / norm ([2.4 4 4]);
%! assert (max (err(ti >= tsiv)) < 2 * quantile (err(ti > ti(end) / 2), 0.95));
%! assert (info.tblock(end) <= ti(end));
%! assert (ti(info.k) >= tsiv && ti(info.k - 1) < tsiv);

%!test  # the IV routines: 'auto' is rlsconverge's time, Qn in THM order
%! randn ("state", 5);
%! y = x + 0.1 * randn (N, 1);
%! d = iddata (y, u, Ts);
%! Qn = diag ([1e-6 2e-6 3e-6]);                   # [a1 a2 b0]
%! t0 = rlsconverge (d, [2 1 0], "lambda_svf", 3, "adm", "kf", "adg", Qn);
%! [thm, ~, ~, info] = rivsvf (d, [2 1 0], "lambda_svf", 3, "adm", "kf", ...
%!                             "adg", Qn, "tsiv", "auto");
%! assert (info.tsiv, t0);
%! assert (info.tsiv_detector.tsiv, t0);
%! ## Before tsiv RIVSVF is RLSSVF.
%! ls = rlssvf (d, [2 1 0], "lambda_svf", 3, "adm", "kf", "adg", Qn);
%! k = info.tsiv_detector.k - 1;
%! assert (thm(1:k, :), ls(1:k, :), 0);
%! [~, ~, ~, info] = rsrivc (d, [1 2 0], "lambda_svf", 3, "adm", "kf", ...
%!                           "adg", Qn([3 1 2], [3 1 2]), "tsiv", "auto");
%! assert (info.tsiv, t0);
%! [~, ~, ~, info] = rsrivc (d, [1 2 0], "lambda_svf", 3, "tsiv", ...
%!                           struct ("blocklength", 2, "nblocks", 5));
%! t1 = rlsconverge (d, [2 1 0], "lambda_svf", 3, "blocklength", 2, ...
%!                   "nblocks", 5);
%! assert (info.tsiv, t1);
%! assert (info.tsiv_detector.blocklength, 2);
%! [~, ~, ~, info] = rivsvf (d, [2 1 0], "lambda_svf", 3, "tsiv", 50);
%! assert (isempty (info.tsiv_detector));

%!test  # closed loop: the RLSSVF start runs on the measured u
%! Ts2 = 0.01; r1 = prbs (12, 20); r1 = r1(1:30000); n2 = numel (r1);
%! C = struct ("kp", 0.5, "ki", 2, "kd", 0);
%! randn ("state", 6);
%! [y, ~, u2] = simc (struct ("B", 200, "F", [1 10 160]), r1, Ts2, ...
%!                    "controller", C, "r2", zeros (n2, 1), "noisevar", 0.01);
%! d = iddata (y, u2, Ts2);
%! t0 = rlsconverge (d, [2 1 0], "lambda_svf", 16);
%! [~, ~, ~, info] = clrivsvf (d, [2 1 0], "lambda_svf", 16, ...
%!                             "controller", C, "r1", r1, "tsiv", "auto");
%! assert (info.tsiv, t0);
%! [~, ~, ~, info] = clrsrivc (d, [1 2 0], "lambda_svf", 16, ...
%!                             "controller", C, "r1", r1, "tsiv", "auto");
%! assert (info.tsiv, t0);

%!warning <no convergence> tsiv = rlsconverge (iddata (x + 0.1 * randn (N, 1), u, Ts), [2 1 0], "lambda_svf", 3, "tol_theta", 1e-9);
%!test
%! warning ("off", "rlsconverge:notConverged", "local");
%! [tsiv, info] = rlsconverge (iddata (x + 0.1 * randn (N, 1), u, Ts), ...
%!                             [2 1 0], "lambda_svf", 3, "tol_theta", 1e-9);
%! assert (isnan (tsiv));
%! assert (! info.converged);
%! assert (isnan (info.tsiv) && isnan (info.k));

%!error id=rivsvf:notConverged rivsvf (iddata (x + 0.1 * randn (N, 1), u, Ts), [2 1 0], "lambda_svf", 3, "tsiv", struct ("tol_theta", 1e-9))
%!error id=rsrivc:notConverged rsrivc (iddata (x + 0.1 * randn (N, 1), u, Ts), [1 2 0], "lambda_svf", 3, "tsiv", struct ("tol_theta", 1e-9))
%!error id=rsrivc:badOption rsrivc (iddata (x, u, Ts), [1 2 0], "lambda_svf", 3, "tsiv", struct ("bogus", 1))
%!error id=rivsvf:badInput rivsvf (iddata (x, u, Ts), [2 1 0], "lambda_svf", 3, "tsiv", struct ("nblocks", 2))
%!error id=rivsvf:badInput rivsvf (iddata (x, u, Ts), [2 1 0], "lambda_svf", 3, "tsiv", "automatic")
%!error id=rlsconverge:badOption rlsconverge (iddata (x, u, Ts), [2 1 0])
%!error id=rlsconverge:badInput rlsconverge (iddata (x, u, Ts), [2 1 0], "lambda_svf", -3)
%!error id=rlsconverge:badInput rlsconverge (iddata (x, u, Ts), [2 1 0], "lambda_svf", 3, "blocklength", 0)
%!error id=rlsconverge:badInput rlsconverge (iddata (x, u, Ts), [2 1 0], "lambda_svf", 3, "blocklength", Ts)
%!error id=rlsconverge:badInput rlsconverge (iddata (x, u, Ts), [2 1 0], "lambda_svf", 3, "nblocks", 2)
%!error id=rlsconverge:badInput rlsconverge (iddata (x, u, Ts), [2 1 0], "lambda_svf", 3, "nblocks", 4.5)
%!error id=rlsconverge:badInput rlsconverge (iddata (x, u, Ts), [2 1 0], "lambda_svf", 3, "alpha", 0)
%!error id=rlsconverge:badInput rlsconverge (iddata (x, u, Ts), [2 1 0], "lambda_svf", 3, "alpha", 0.5)
%!error id=rlsconverge:badInput rlsconverge (iddata (x, u, Ts), [2 1 0], "lambda_svf", 3, "tol_theta", -1)
%!error id=rlsconverge:badInput rlsconverge (iddata (x, u, Ts), [2 1 0], "lambda_svf", 3, "ptol", 0)
%!error id=rlsconverge:badInput rlsconverge (iddata (x, u, Ts), [2 1 0], "lambda_svf", 3, "eyfloor", -1)
%!error id=rlsconverge:badInput rlsconverge (iddata (x, u, Ts), [2 1 0], "lambda_svf", 3, "eyfloor", [1 2])
%!error id=rlsconverge:badOption rlsconverge (iddata (x, u, Ts), [2 1 0], "lambda_svf", 3, "criteria", "magic")
%!error id=rlsconverge:badOption rlsconverge (iddata (x, u, Ts), [2 1 0], "lambda_svf", 3, "criteria", {"P", "magic"})
%!error id=rlsconverge:badOption rlsconverge (iddata (x, u, Ts), [2 1 0], "lambda_svf", 3, "criteria", {})
%!error id=rlsconverge:badOption rlsconverge (iddata (x, u, Ts), [2 1 0], "lambda_svf", 3, "criteria", 3)
%!error id=rlsconverge:badOption rlsconverge (iddata (x, u, Ts), [2 1 0], "lambda_svf", 3, "bogus", 1)
%!error <too short> rlsconverge (iddata (x, u, Ts), [2 1 0], "lambda_svf", 3, "blocklength", 100)
%!error id=rlsconverge:badInput rlsconverge (iddata (x, u, Ts), [2 1 0], "lambda_svf", 3, "blocklength", 100)
%!error id=rlsconverge:dimensionMismatch rlsconverge (iddata (x, u, Ts), [2 1 0], "lambda_svf", 3, "th0", [1 2])
%!error id=rlsconverge:badInput rlsconverge (iddata (x, u, Ts), [2 4 0], "lambda_svf", 3)

%!demo
%! ## When has RLSSVF converged? A drifting resonance (cf. thesis 2.3.5).
%! Ts = 0.05; u = prbs (12, 10); N = numel (u); t = (0:N-1)' * Ts;
%! wn = 2 * (1 + 0.3 * cos (2 * pi * t / t(end)));
%! y = simc ([1.2 * wn, wn .^ 2, wn .^ 2], [2 1 0], u, Ts) ...
%!     + 0.1 * randn (N, 1);
%! rlsconverge (iddata (y, u, Ts, "InterSample", "zoh"), [2 1 0], ...
%!              "lambda_svf", 3, "adm", "kf", "adg", 1e-5);
