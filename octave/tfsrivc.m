## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn  {} {@var{M} =} tfsrivc (@var{data}, @var{np}, @var{nz})
## @deftypefnx {} {@var{M} =} tfsrivc (@var{data}, @var{np}, @var{nz}, @var{IODelay})
## @deftypefnx {} {@var{M} =} tfsrivc (@var{data}, @var{Mi})
## @deftypefnx {} {@var{M} =} tfsrivc (@dots{}, @var{name}, @var{value}, @dots{})
## Continuous-time transfer function with a time delay,
## @example
## y(t) = B(p)/F(p) u(t - td) + e(t),   deg F = np, deg B = nz,
## @end example
## by the simplified refined instrumental-variable method (SRIVC, thesis
## eqs. 2.8-2.13; one engine, core/include/ctid/offline/refined_iv.hpp) with the
## delay td estimated by a grid search and Gauss-Newton refinement, or
## fixed. td may be any fraction of a sampling interval: the delayed input
## is filtered exactly under its ZOH or FOH rule (also on irregularly
## sampled data).
##
## @var{data}: an @code{iddata} with one output and one input (regular or
## irregular instants, InterSample 'zoh' or 'foh'). @var{np}, @var{nz}:
## orders (0 <= nz <= np). @var{IODelay}: the start delay (seconds) of the
## refinement, or the delay itself with 'FixTd','on'. @var{Mi}: an
## @code{idtf} whose orders, coefficients (the start; NaN: automatic) and
## IODelay are used (the model-in form).
##
## Options (name-value pairs, case-insensitive; CONTSID 7.3's names and,
## unless said, its defaults):
## @table @code
## @item FixTd
## 'on': keep the delay (default 'off').
## @item TdMin, TdMax, NumTd
## range and grid of the delay search without a start delay (default 0;
## TdMax from the input-output cross-correlation as CONTSID: the lag of
## the largest |r_yu| up to half the record plus 10 samples, at least the
## smaller of a tenth of the record and 50 sampling intervals (irregular
## data: on a regular grid of their median interval), at least twice
## TdMin and twice the start delay, at most half the record, extended
## while the grid's best delay lies at its upper end; 50 points).
## @item Lambda
## the SVF cut-off (rad/s) of the start (default: the engine's grid of
## cut-offs; CONTSID: 1/50 of the Nyquist frequency).
## @item MaxIter
## maximum SRIVC iterations, and of Gauss-Newton steps on td (100).
## @item TolPar, TolFun
## stop when the relative parameter change (SRIVC) and the delay step
## (in sampling intervals) fall below TolPar (1e-5), or the relative loss
## decrease below TolFun (1e-8); CONTSID's defaults are 1e-4 both.
## @item StepMax, StepReduction
## largest delay step (default one grid spacing, at least one sampling
## interval; CONTSID: inf) and the factor that shortens a step that does
## not decrease the loss: r > 1 divides it (CONTSID's convention, default
## 2), r in (0, 1) multiplies it.
## @item Integration
## 'on': an integrator is enforced (the denominator's last coefficient
## fixed at 0, a pole at s = 0); default 'off'. Not with a Focus filter
## (as CONTSID documents: @code{tfsrivc:badOption}).
## @item Focus, FocusOrder
## CONTSID's cut-off frequency fc (rad/s) of a Butterworth low-pass
## prefilter of order FocusOrder (default 5) applied to the output and
## input (default Inf: no filter); also a passband [w1 w2] (rad/s, 0 <=
## w1 < w2: a high-pass of cut-off w1 too) or 'simulation'/'prediction'
## (no filter). The filter is discretised by the prewarped Tustin map
## (MATLAB's @code{butter}); it needs regularly sampled data. As in
## CONTSID it serves the convergence of the delay (its demo: a coarse
## start delay that alone ends in a local minimum): the whole estimate
## (grid search or refinement from IODelay; SRIVC with its own adaptive
## prefilter 1/F) is first made on the prefiltered data, whose loss in
## td is smoother with a wider basin around the global minimum, and that
## model starts the estimate on the data as given, which is returned
## (Chen, Garnier & Gilson, J. Process Control 25, 2015). A cut-off of
## 1/10 to 1/2 of the system's bandwidth is CONTSID's rule of thumb; far
## below it only the static gain and the total lag are seen through the
## filter, and the start's delay and poles trade against each other.
## @code{Report.Parameters.FocusStart} (IODelay, num, den) is the model of
## the prefiltered data.
## @end table
##
## @var{M}: an @code{idtf} with IODelay = td, the covariance of [b; f]
## (@code{getcov}, sigma^2 (J' J)^-1 from the output sensitivities,
## including the coupling with td when td is estimated),
## @code{Report.Fit.LossFcn}, @code{.MSE}, @code{.FitPercent}, @code{.FPE},
## @code{Report.Parameters.IODelay} and @code{.IODelaySD} (standard
## deviation of td, 0 when fixed), @code{Report.Termination}
## (@code{Iterations}, @code{Converged}, @code{Reason}, @code{DelayGrid},
## @code{DelayGridLoss}). A model that did not converge comes with the
## warning @code{tfsrivc:notConverged}.
##
## @strong{Example}
## @example
## u = idinput (2000, "prbs", [0 0.05]);
## M0 = idtf (4, [1 1.2 4], "IODelay", 0.37);
## y = simc (M0, iddata ([], u, 0.05, "InterSample", "zoh"));
## M = tfsrivc (iddata (y, u, 0.05, "InterSample", "zoh"), 2, 0);
## @end example
## @seealso{tfsrivc_init, procsrivc, srivc, idtf}
## @end deftypefn

function varargout = tfsrivc (varargin)
  varargout = contsid_guard ("tfsrivc", @tfsrivc_body, nargout, varargin);
endfunction

function [M, varargout] = tfsrivc_body (varargin)
  contsid_nargchk ("tfsrivc", nargin, nargout, [0 Inf], 1);
  M = contsid_tf_front ("tfsrivc", varargin);
endfunction

%!shared data, data_n, M0, u, Ts
%! Ts = 0.05;
%! u = prbs (10, 4);
%! u = [u; u](1:3000);
%! M0 = idtf ([0.5 4], [1 1.2 4], "IODelay", 0.37);     # 7.4 samples
%! du = iddata ([], u, Ts, "InterSample", "zoh");
%! y = simc (M0, du);
%! data = iddata (y, u, Ts, "InterSample", "zoh");
%! randn ("state", 1);
%! data_n = iddata (y + 0.1 * randn (size (y)), u, Ts, "InterSample", "zoh");

%!test
%! ## Noise-free record, delay fixed at the true value: exact recovery.
%! M = tfsrivc (data, 2, 1, 0.37, "FixTd", "on");
%! assert (M.IODelay, 0.37);
%! assert (getpvec (M), getpvec (M0), 1e-6);
%! assert (M.Report.Fit.LossFcn < 1e-12);

%!test
%! ## Delay estimated from the grid search: within 1e-4 samples.
%! M = tfsrivc (data, 2, 1);
%! assert (abs (M.IODelay - 0.37) < 1e-4 * Ts);
%! assert (getpvec (M), getpvec (M0), 1e-5);
%! assert (M.Report.Termination.Converged);

%!test
%! ## Noisy record: delay within a fraction of a sample, the truth inside
%! ## 4 reported standard deviations.
%! M = tfsrivc (data_n, 2, 1, 0.3);
%! sd = M.Report.Parameters.IODelaySD;
%! assert (sd > 0 && sd < 0.2 * Ts);
%! assert (abs (M.IODelay - 0.37) < 4 * sd);
%! [p, s] = getpvec (M);
%! assert (all (abs (p - getpvec (M0)) < 4 * s));
%! ys = simc (M, iddata ([], u, Ts));
%! assert (M.Report.Fit.MSE, mean ((data_n.y - ys) .^ 2), 1e-10);

%!test
%! ## Irregular instants (on a 10 ms grid, simulated there exactly).
%! k = cumsum ([1; 3 + floor(5 * rand(1499, 1))]);
%! hf = 0.01;
%! ui = double (sin (0.09 * k) + sign (sin (0.23 * k + 1)) > 0.2);
%! uf = ui(cumsum (accumarray (k, 1))(1:k(end)));
%! Mi = idtf (2, [1 2], "IODelay", 0.123);
%! yf = simc (Mi, iddata ([], uf, hf, "InterSample", "zoh"));
%! di = iddata (yf(k), ui, "SamplingInstants", (k - 1) * hf,
%!              "InterSample", "zoh");
%! M = tfsrivc (di, 1, 0, "TdMax", 1);
%! assert (M.IODelay, 0.123, 1e-5);
%! assert (getpvec (M), [2; 2; M.IODelay], 1e-4);   # [b f IODelay]

%!test
%! ## FOH data.
%! df = iddata ([], u, Ts, "InterSample", "foh");
%! yf = simc (M0, df);
%! M = tfsrivc (iddata (yf, u, Ts, "InterSample", "foh"), 2, 1);
%! assert (M.IODelay, 0.37, 1e-5);
%! assert (getpvec (M), getpvec (M0), 1e-5);

%!test
%! ## Model-in form: one SRIVC iteration from a given model, delay fixed.
%! Mi = idtf ([0.5 4], [1 1.2 4], "IODelay", 0.37);
%! M = tfsrivc (data, Mi, "FixTd", "on", "MaxIter", 1);
%! assert (M.IODelay, 0.37);
%! assert (getpvec (M), getpvec (M0), 1e-6);

%!test
%! ## Monte Carlo (40 runs, ~15 s): spread vs reported sd, delay estimated,
%! ## relative degree 2 (the output is smooth in td; with relative degree 1
%! ## and ZOH input y(t_k) has kinks in td at whole samples and the sd of
%! ## td and b1 come out ~30 % low at 0.2 samples sd: devel/monte_carlo/tfsrivc_mc.m).
%! M1 = idtf (4, [1 1.2 4], "IODelay", 0.37);
%! y1 = simc (M1, iddata ([], u(1:2000), Ts, "InterSample", "zoh"));
%! R = 40;
%! P = zeros (R, 4);
%! S = P;
%! randn ("state", 7);
%! for r = 1:R
%!   d1 = iddata (y1 + 0.2 * randn (2000, 1), u(1:2000), Ts,
%!                "InterSample", "zoh");
%!   M = tfsrivc (d1, 2, 0, 0.3);
%!   [p, sd] = getpvec (M);       # [b f IODelay], the delay's sd with it
%!   assert (sd(end), M.Report.Parameters.IODelaySD, 1e-12);
%!   P(r, :) = p';
%!   S(r, :) = sd';
%! endfor
%! ratio = std (P) ./ mean (S);
%! printf ("MC std / reported sd: %s\n", num2str (ratio, 3));
%! assert (all (ratio > 0.8 & ratio < 1.25));
%! assert (abs (mean (P(:, 4)) - 0.37) < 3 * std (P(:, 4)) / sqrt (R));

%!test  # Focus band: the start is the fit of data prefiltered by an
%! ## independent Butterworth (table coefficients, control package's
%! ## prewarped c2d), the result that of the data as given
%! y = simc (M0, iddata ([], u, Ts, "InterSample", "zoh"));
%! randn ("state", 11);
%! y += 0.1 * randn (size (y));
%! d = iddata (y, u, Ts, "InterSample", "zoh");
%! c = [1 2.613125929752753 3.414213562373095 2.613125929752753 1];
%! lp = @(w) tf (w ^ 4, c .* w .^ (0:4));           # 4th-order low-pass
%! hp = @(w) tf ([1 0 0 0 0], c .* w .^ (0:4));     # and high-pass
%! Mn = tfsrivc (d, 2, 1, 0.37, "FixTd", "on");
%! for band = {[0 6], [0.5 6]}
%!   w = band{1};
%!   L = c2d (lp (w(2)), Ts, "prewarp", w(2));
%!   if (w(1) > 0)
%!     L = L * c2d (hp (w(1)), Ts, "prewarp", w(1));
%!   endif
%!   [bL, aL] = tfdata (L, "vector");
%!   df = iddata (filter (bL, aL, y), filter (bL, aL, u), Ts,
%!                "InterSample", "zoh");
%!   Mf = tfsrivc (d, 2, 1, 0.37, "FixTd", "on", "Focus", w,
%!                 "FocusOrder", 4);
%!   Mr = tfsrivc (df, 2, 1, 0.37, "FixTd", "on");
%!   fs = Mf.Report.Parameters.FocusStart;
%!   assert ([fs.num(end-1:end), fs.den], [Mr.num{1}(end-1:end), Mr.den{1}],
%!           1e-6 * norm (getpvec (Mr)));
%!   assert (getpvec (Mf), getpvec (Mn), 1e-6 * norm (getpvec (Mn)));
%! endfor
%! ## CONTSID's form: a cut-off fc, Butterworth of order 5 by default
%! c5 = [1 3.2360679774997896 5.2360679774997896 5.2360679774997896 ...
%!       3.2360679774997896 1];
%! L = c2d (tf (6 ^ 5, c5 .* 6 .^ (0:5)), Ts, "prewarp", 6);
%! [bL, aL] = tfdata (L, "vector");
%! df = iddata (filter (bL, aL, y), filter (bL, aL, u), Ts,
%!              "InterSample", "zoh");
%! Mf = tfsrivc (d, 2, 1, 0.37, "FixTd", "on", "Focus", 6);
%! Mr = tfsrivc (df, 2, 1, 0.37, "FixTd", "on");
%! fs = Mf.Report.Parameters.FocusStart;
%! assert ([fs.num(end-1:end), fs.den], [Mr.num{1}(end-1:end), Mr.den{1}],
%!         1e-6 * norm (getpvec (Mr)));
%! ## Focus Inf is CONTSID's default, no filter
%! assert (getpvec (tfsrivc (d, 2, 1, 0.37, "FixTd", "on", "Focus", Inf)),
%!         getpvec (Mn));

%!test  # CONTSID's time-delay demo, shortened: from the coarse start
%! ## delay 1 s (true 8 s) the estimate alone ends in a local minimum; with
%! ## the Focus filter (fc = 0.1 rad/s) it is the global minimum, the
%! ## estimate started at the true delay
%! M8 = idtf (12, [1 4 4], "IODelay", 8);
%! u8 = prbs (8, 10);
%! y8 = simc (M8, iddata ([], u8, 0.1, "InterSample", "zoh"));
%! randn ("state", 5);
%! y8 += 10 ^ (-15 / 20) * std (y8) * randn (size (y8));
%! d8 = iddata (y8, u8, 0.1, "InterSample", "zoh");
%! Mt = tfsrivc (d8, 2, 0, 8, "Lambda", 2);
%! [pt, st] = getpvec (Mt);
%! assert (abs (pt - getpvec (M8)) < 4 * st);
%! Mf = tfsrivc (d8, 2, 0, 1, "Lambda", 2, "Focus", 0.1);
%! assert (all (abs (getpvec (Mf) - pt) < 0.01 * st));

%!test  # StepReduction: CONTSID's divisor r > 1 is the multiplier 1 / r
%! M1 = tfsrivc (data_n, 2, 1, 0.3, "StepReduction", 4);
%! M2 = tfsrivc (data_n, 2, 1, 0.3, "StepReduction", 0.25);
%! assert (M1.IODelay, M2.IODelay);
%! assert (getpvec (M1), getpvec (M2));

%!test  # Integration 'on': a pole at s = 0 enforced, exact on noise-free
%! ## data of an integrating plant with a delay
%! Gi = idtf (2, [1 3 0], "IODelay", 0.23);
%! ui = prbs (9, 6); ui = ui - mean (ui);
%! yi = simc (Gi, iddata ([], ui, Ts, "InterSample", "zoh"));
%! Mi = tfsrivc (iddata (yi, ui, Ts, "InterSample", "zoh"), 2, 0, 0.2,
%!               "Integration", "on");
%! assert (Mi.den{1}(end), 0);
%! assert ([Mi.num{1}(end), Mi.den{1}], [2 1 3 0], 1e-6);
%! assert (Mi.IODelay, 0.23, 1e-6);
%! sd = sqrt (diag (getcov (Mi)));
%! assert (sd(end-1), 0);                 # the fixed coefficient

%!error id=tfsrivc:badInput tfsrivc (data)
%!error id=tfsrivc:badInput tfsrivc (data, 2, 3)
%!error id=tfsrivc:badInput tfsrivc (data, -1, 0)
%!error id=tfsrivc:badInput tfsrivc (data, realmax, 1)
%!error id=tfsrivc:badInput tfsrivc (data, 2, 1, -0.1)
%!error id=tfsrivc:badInput tfsrivc (data, 2, 1, "FixTd", "on")
%!error id=tfsrivc:badOption tfsrivc (data, 2, 1, "Bogus", 1)
%!error id=tfsrivc:badOption tfsrivc (data, 2, 1, "TdMin", 2, "TdMax", 1)
%!error id=tfsrivc:badOption tfsrivc (data, 2, 1, 5, "TdMax", 1)
%!error id=tfsrivc:badOption tfsrivc (data, 2, 1, "Focus", [5 1])
%!error id=tfsrivc:badOption tfsrivc (data, 2, 1, "Focus", "bogus")
%!error id=tfsrivc:badOption tfsrivc (data, 2, 1, "FocusOrder", 0)
%!error id=tfsrivc:badOption tfsrivc (data, 2, 1, "Focus", 0)
%!error id=tfsrivc:badOption tfsrivc (data, 2, 1, "StepReduction", 1)
%!error id=tfsrivc:badOption tfsrivc (data, 2, 1, "Integration", "yes")
%!error id=tfsrivc:badOption
%! tfsrivc (data, 2, 1, "Integration", "on", "Focus", 5)
%!error id=tfsrivc:notSupported
%! tfsrivc (iddata ([1:50]', randn (50, 1), [], "SamplingInstants",
%!                  cumsum (0.1 + rand (50, 1) / 10)), 1, 0, "Focus", [0 5])
%!error id=tfsrivc:badInput tfsrivc (data, idpoly (1, 1, 1, 1, [1 1], "Ts", 0))
%!error id=tfsrivc:notSupported
%! tfsrivc (iddata ((1:50)', zeros (50, 2), 0.1), 1, 0)
%!error id=tfsrivc:numericalFailure
%! tfsrivc (iddata (sin ((1:100)'), zeros (100, 1), 0.1), 1, 0)
%!error id=tfsrivc:badInput  # a constant output identifies nothing
%! tfsrivc (iddata (ones (100, 1), zeros (100, 1), 0.1), 1, 0)

%!demo
%! ## A second-order system with a delay of 7.4 samples, noisy ZOH data.
%! Ts = 0.05; u = prbs (10, 4); u = [u; u](1:3000);
%! M0 = idtf ([0.5 4], [1 1.2 4], "IODelay", 0.37);
%! y = simc (M0, iddata ([], u, Ts, "InterSample", "zoh"));
%! data = iddata (y + 0.1 * randn (size (y)), u, Ts, "InterSample", "zoh");
%! M = tfsrivc (data, 2, 1);
%! present (M)
%! printf ("IODelay %.4f (+/- %.4f), true 0.37\n", M.IODelay, ...
%!         M.Report.Parameters.IODelaySD);
