## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn  {} {@var{M} =} tfcoe (@var{data}, @var{np}, @var{nz})
## @deftypefnx {} {@var{M} =} tfcoe (@var{data}, @var{np}, @var{nz}, @var{td})
## @deftypefnx {} {@var{M} =} tfcoe (@dots{}, @var{name}, @var{value})
## @deftypefnx {} {[@var{M}, @var{info}] =} tfcoe (@dots{})
## Continuous-time output-error (COE) estimate of B(p)/F(p) e^(-td p),
## @var{np} poles and @var{nz} zeros, by prediction-error minimisation
## (thesis sec. 1.3.3, eq. 1.16 with H = 1): Levenberg-Marquardt on the
## simulation error, started from SRIVC (thesis eqs. 2.8-2.13), every
## iterate kept stable.
##
## The model is simulated exactly under the data's intersample rule (ZOH or
## FOH, regular or irregular sampling) and the Jacobian is exact (the
## sensitivity filters p^i u / F and p^j B u / F^2).  For a strictly
## proper model (@var{nz} < @var{np}) the delay is estimated too, by the
## delay search of @code{tfsrivc} (the same code): over its grid of
## delays in [TdMin, TdMax], then its Gauss-Newton refinement of the SRIVC
## loss, and with @var{td} also that refinement started at @var{td}.  Each
## delay and SRIVC model found starts the output-error iteration, in which
## the delay is a parameter kept in [TdMin, TdMax]; the lowest loss wins
## (on a ZOH input the loss has a kink at every whole number of samples of
## delay, where a gradient method can stop short of the delay).  For
## @var{nz} = @var{np} the model has the delay 0, not estimated.
##
## Options (name-value pairs; CONTSID 7.3's documented set, with its
## meaning; where this toolbox's default differs, it says so):
## @table @code
## @item TdMin
## Lower bound of the delay (s, default 0): the delay grid and its
## refinement, and the output-error iteration, keep td in [TdMin, TdMax]
## (a run that would leave below TdMin ends at the minimum over the
## coefficients with td = TdMin, the bound active).  Only for an estimated
## delay (@var{nz} < @var{np}).
## @item TdMax
## Upper bound of the delay (s; default: tfsrivc's, from the input-output
## cross-correlation, at least twice @var{td} and twice TdMin, at most
## half the record, extended while the grid's best delay lies at its upper
## end).
## @item NumTd
## The number of delays of the grid in [TdMin, TdMax] (default 50; the
## grid is searched with or without @var{td}; its delays and losses are in
## @code{Report.Termination.DelaySearch}).
## @item StepMax
## Largest delay step of the Gauss-Newton refinement (s).  Default: the
## grid step (TdMax - TdMin) / (NumTd - 1), at least one sample; CONTSID's
## default is Inf.
## @item StepReduction
## The factor r that reduces a delay step that does not lower the loss: r
## > 1 divides the step (CONTSID's convention, default 2); a value in (0,
## 1) multiplies it (this toolbox's former convention: 0.5 = 2).
## @item MaxIter
## Maximum output-error iterations (default 100).
## @item TolPar
## Tolerance of the stop test (also @code{Tol}): the relative parameter
## step and, with it, the relative loss decrease (one tolerance for both,
## the core's test).  Default 1e-8, tighter than CONTSID's 1e-4.
## @item TolFun
## Not supported (@code{tfcoe:notSupported}): the core has no separate
## loss-decrease tolerance (see TolPar).
## @item Integration
## @qcode{"on"} (or true) enforces an integrator: the last denominator
## coefficient is 0 (a pole at p = 0) in the SRIVC start and the output
## error, which fits B(p)/F'(p) to the integral of the input (exact for a
## ZOH input, the integral then being piecewise linear).  Default
## @qcode{"off"}.  Not applicable with a Focus filter
## (@code{tfcoe:badOption}, as CONTSID); needs a ZOH input, @var{np} >= 2,
## @var{nz} <= @var{np} - 2 and OverPar @qcode{"off"} (otherwise
## @code{tfcoe:notSupported}).
## @item Focus
## CONTSID's cut-off frequency fc (rad/s) of a Butterworth low-pass
## prefilter of the data (the band [0 fc]); Inf (CONTSID's default) or
## @qcode{"simulation"}: no filter (this toolbox's default); also a
## passband [w1 w2] (low-pass times high-pass, as @code{tfsrivc}'s Focus).
## @item FocusOrder
## The order of that filter, an integer 1..10 (default 5).
## @item OverPar
## @qcode{"off"} (default) or @qcode{"on"}, below.
## @item Lambda
## SVF cut-off of the SRIVC start (rad/s; default a grid).
## @end table
##
## @strong{OverPar.}  CONTSID's documentation of this option was not
## available to this implementation; its meaning here: @qcode{"on"} adds
## one start from an over-parametrised fit.  The output error of the
## structure with one pole and one zero more (@var{np} + 1, @var{nz} + 1,
## its delay searched as above) is fitted first: the output-error loss of
## an over-parametrised model has fewer non-global minima (Soderstrom and
## Stoica, "Some properties of the output error method", Automatica
## 18(1), 1982), and the extra pole-zero pair can take up a delay error
## (a first-order Pade term).  Its frequency response over the band of the
## record (2 pi / T to the Nyquist frequency) is reduced to the asked
## orders, with the delay, by @code{tffcoe}'s frequency-domain output
## error, and that model starts the output-error iteration beside the
## others; the lowest loss wins, so @qcode{"on"} never returns a higher
## loss than @qcode{"off"}, at about three times the cost.
##
## @var{M} is an @code{idtf} with covariance s^2 (J'J)^-1 (s^2 = e'e/(N -
## np)) and @code{Report} (Fit.FitPercent, LossFcn = MSE = e'e/N, FPE;
## Termination.Iterations, Converged, Reason; Parameters.IODelay and
## IODelaySD).  A run that does not converge warns
## @code{tfcoe:notConverged} and returns the last iterate.
##
## @strong{Example}
## @example
## u = prbs (10, 8); Ts = 0.05; N = numel (u);
## y = simc (idctm (4, [1 2.4 4]), u, Ts) + 0.1 * randn (N, 1);
## M = tfcoe (iddata (y, u, Ts), 2, 0)
## @end example
## @seealso{tfsrivc, srivc, tfest, oe}
## @end deftypefn

function varargout = tfcoe (varargin)
  varargout = contsid_guard ("tfcoe", @tfcoe_body, nargout, varargin);
endfunction

function [M, info, varargout] = tfcoe_body (varargin)
  contsid_nargchk ("tfcoe", nargin, nargout, [3 Inf], 2);
  [M, info] = contsid_pem ("tfcoe", varargin);
endfunction

%!shared u, Ts, x, N
%! ## one period of a maximum-length PRBS (255 bits held 8 samples, 2040
%! ## samples, 102 s): the identities below are exact at any length, and
%! ## each call's delay search costs in proportion to N
%! u = prbs (8, 8); Ts = 0.05; N = numel (u);
%! x = simc (idctm ([1.5 4], [1 2.4 4]), u, Ts);

%!test  # noise-free: exact
%! M = tfcoe (iddata (x, u, Ts), 2, 1);
%! [num, den] = tfdata (M, "vector");
%! assert (den, [1 2.4 4], 1e-8);
%! assert (num(end-1:end), [1.5 4], 1e-8);
%! assert (M.Report.Termination.Converged, true);

%!test  # noisy: the optimum is stationary (gradient of the loss ~ 0)
%! randn ("state", 3);
%! y = x + 0.2 * randn (N, 1);
%! [M, info] = tfcoe (iddata (y, u, Ts), 2, 1);
%! assert (info.converged);
%! assert (info.gradient_norm < 1e-5);
%! p = [M.Report.Parameters.ParVector];
%! assert (M.Report.Fit.MSE, mean ((y - info.simulated) .^ 2), 1e-12);
%! sd = sqrt (diag (M.Report.Parameters.FullCovariance));
%! assert (all (sd > 0 & sd < 1));

%!test  # delay estimated from a start 0.07 s away
%! xd = simc (idtf ([1.5 4], [1 2.4 4], "IODelay", 0.12), u, Ts);
%! M = tfcoe (iddata (xd, u, Ts), 2, 1, 0.05);
%! assert (get (M, "IODelay"), 0.12, 1e-6);

%!test  # delay searched without a start (tfsrivc's grid), 10.6 samples
%! xd = simc (idtf ([1.5 4], [1 2.4 4], "IODelay", 0.53), u, Ts);
%! M = tfcoe (iddata (xd, u, Ts), 2, 1);
%! assert (get (M, "IODelay"), 0.53, 1e-6);
%! [num, den] = tfdata (M, "vector");
%! assert (den, [1 2.4 4], 1e-6);
%! ## from a start 8 samples too far
%! M = tfcoe (iddata (xd, u, Ts), 2, 1, 0.93);
%! assert (get (M, "IODelay"), 0.53, 1e-6);

%!test  # Focus band: the output error of the prefiltered data (= tfest's)
%! randn ("state", 5);
%! y = x + 0.05 * randn (N, 1);
%! M = tfcoe (iddata (y, u, Ts), 2, 1, 0, "Focus", [0 8], "TdMax", 0.2);
%! Me = tfest (iddata (y, u, Ts), 2, 1, tfestOptions ("Focus", [0 8]));
%! assert (abs (get (M, "IODelay")) < 0.02);
%! assert (getpvec (M), getpvec (Me), 0.05 * norm (getpvec (Me)));

%!error id=tfcoe:badInput tfcoe (iddata (x, u, Ts), 0, 0)
%!error id=tfcoe:badInput tfcoe (iddata (x, u, Ts), 2, 3)
%!error id=tfcoe:badInput tfcoe (iddata (x, u, Ts), 2, 1, -1)
%!error id=tfcoe:badInput tfcoe (iddata (x, u, Ts), 2, 2, 0.1)
%!error id=tfcoe:badInput tfcoe (iddata (x, u, Ts), 2, 1, 1e4)
%!error id=tfcoe:badInput tfcoe (iddata (x, u, Ts), 2)
%!error id=tfcoe:badInput tfcoe (iddata (x, u, Ts), realmax, 2, 1)
%!error id=tfcoe:badOption tfcoe (iddata (x, u, Ts), 2, 1, "Bogus", 1)
%!error id=tfcoe:badOption tfcoe (iddata (x, u, Ts), 2, 1, "MaxIter", -1)
%!error id=tfcoe:badOption tfcoe (iddata (x, u, Ts), 2, 1, "Tol", 0)
%!error id=tfcoe:badOption tfcoe (iddata (x, u, Ts), 2, 1, "Lambda", -1)
%!error id=tfcoe:badOption tfcoe (iddata (x, u, Ts), 2, 1, "Focus", [1 0])
%!error id=tfcoe:badOption tfcoe (iddata (x, u, Ts), 2, 1, 0.1, "TdMax", -1)
%!error id=tfcoe:badOption tfcoe (iddata (x, u, Ts), 2, 1, "MaxIter")
%!error id=tfcoe:badOption tfcoe (iddata (x, u, Ts), 2, 1, "OverPar", "yes")

%!test  # OverPar 'on': exact on noise-free data with a delay, and on noisy
%! # data its loss is not above the default's (the lowest-loss start wins)
%! M0 = idtf (4, [1 2.4 4], "IODelay", 0.37);
%! us = u(1:1500);
%! y = simc (M0, iddata ([], us, Ts, "InterSample", "zoh"));
%! M = tfcoe (iddata (y, us, Ts), 2, 0, 0.1, "OverPar", "on");
%! assert (getpvec (M), getpvec (M0), 1e-6);
%! randn ("state", 12);
%! dn = iddata (y + 0.2 * randn (1500, 1), us, Ts);
%! Mon = tfcoe (dn, 2, 0, 0.1, "OverPar", "on");
%! Moff = tfcoe (dn, 2, 0, 0.1);
%! assert (Mon.Report.Fit.LossFcn <= Moff.Report.Fit.LossFcn * (1 + 1e-12));
%! [p, sd] = getpvec (Mon);
%! assert (all (abs (p - getpvec (M0)) < 5 * sd));
%! ## nz = np (no delay estimated): the reduced start competes with the
%! ## default one
%! Mon = tfcoe (dn, 2, 2, "OverPar", "on");
%! Moff = tfcoe (dn, 2, 2);
%! assert (Mon.Report.Fit.LossFcn <= Moff.Report.Fit.LossFcn * (1 + 1e-12));
%!error id=tfcoe:notSupported tfcoe (iddata (x, [u u], Ts), 2, 1)
%!error id=tfcoe:badInput tfcoe (1, 2, 3, 4, 5, 6, 7, 8)
%!warning id=tfcoe:notConverged
%! ## an in-band disturbance (0.05 rad/sample = 1 rad/s): the output-error
%! ## minimum is not the SRIVC start, one iteration does not reach it
%! tfcoe (iddata (x + 0.1 * sin (0.05 * (1:N))', u, Ts), 2, 1, 0.1,
%!        "MaxIter", 1, "Tol", 1e-15);

%!test  # Focus: a scalar cut-off is the band [0 fc]; Inf is no filter
%! randn ("state", 5);
%! dn = iddata (x(1:1000) + 0.05 * randn (1000, 1), u(1:1000), Ts);
%! Mb = tfcoe (dn, 2, 1, 0, "Focus", [0 8], "TdMax", 0.2);
%! Mf = tfcoe (dn, 2, 1, 0, "Focus", 8, "TdMax", 0.2);
%! assert (getpvec (Mf), getpvec (Mb));
%! M0 = tfcoe (dn, 2, 1, 0, "TdMax", 0.2);
%! Mi = tfcoe (dn, 2, 1, 0, "Focus", Inf, "TdMax", 0.2);
%! assert (getpvec (Mi), getpvec (M0));
%! ## FocusOrder reaches the filter (default 5)
%! M5 = tfcoe (dn, 2, 1, 0, "Focus", 8, "TdMax", 0.2, "FocusOrder", 5);
%! M2 = tfcoe (dn, 2, 1, 0, "Focus", 8, "TdMax", 0.2, "FocusOrder", 2);
%! assert (getpvec (M5), getpvec (Mf));
%! assert (! isequal (getpvec (M2), getpvec (Mf)));

%!test  # StepReduction: r > 1 divides the step, so 2 is 0.5; NumTd grid
%! randn ("state", 7);
%! xd = simc (idtf ([1.5 4], [1 2.4 4], "IODelay", 0.37), u(1:1000), Ts);
%! dn = iddata (xd + 0.1 * randn (1000, 1), u(1:1000), Ts);
%! Md = tfcoe (dn, 2, 1, 0.1, "StepReduction", 2, "NumTd", 12);
%! Mm = tfcoe (dn, 2, 1, 0.1, "StepReduction", 0.5, "NumTd", 12);
%! assert (getpvec (Mm), getpvec (Md));
%! assert (get (Mm, "IODelay"), get (Md, "IODelay"));
%! M = tfcoe (dn, 2, 1, "NumTd", 7, "TdMax", 1);
%! assert (numel (M.Report.Termination.DelaySearch.Grid), 7);
%! assert (M.Report.Termination.DelaySearch.Grid([1 end]), [0 1]);

%!test  # TdMin excludes the true delay 0.37 s below it
%! xd = simc (idtf ([1.5 4], [1 2.4 4], "IODelay", 0.37), u(1:1000), Ts);
%! M = tfcoe (iddata (xd, u(1:1000), Ts), 2, 1, "TdMin", 0.5);
%! assert (get (M, "IODelay") >= 0.5);
%! assert (M.Report.Termination.DelaySearch.Grid(1), 0.5);
%! M = tfcoe (iddata (xd, u(1:1000), Ts), 2, 1, "TdMin", 0.2);
%! assert (get (M, "IODelay"), 0.37, 1e-6);

%!test  # Integration 'on': 2/(p (p + 3)) e^(-0.37 p) recovered exactly
%! M0 = idtf (2, [1 3 0], "IODelay", 0.37);
%! us = u(1:1000);
%! y = simc (M0, iddata ([], us, Ts, "InterSample", "zoh"));
%! M = tfcoe (iddata (y, us, Ts), 2, 0, "Integration", "on");
%! [num, den] = tfdata (M, "vector");
%! assert (den(end), 0);
%! assert (den, [1 3 0], 1e-6);
%! assert (num(end), 2, 1e-6);
%! assert (get (M, "IODelay"), 0.37, 1e-6);
%! M = tfcoe (iddata (y, us, Ts), 2, 0, "Integration", true);
%! assert (tfdata (M, "vector")(end), 2, 1e-6);

%!error id=tfcoe:badOption tfcoe (iddata (x, u, Ts), 2, 0, "Integration", "yes")
%!error id=tfcoe:badOption tfcoe (iddata (x, u, Ts), 2, 0, "Integration", 2)
%!error id=tfcoe:badOption
%! tfcoe (iddata (x, u, Ts), 2, 0, "Integration", "on", "Focus", 8);
%!error id=tfcoe:notSupported
%! tfcoe (iddata (x, u, Ts), 2, 1, "Integration", "on");
%!error id=tfcoe:notSupported
%! tfcoe (iddata (x, u, Ts), 2, 0, "Integration", "on", "OverPar", "on");
%!error id=tfcoe:notSupported tfcoe (iddata (x, u, Ts), 2, 1, "TolFun", 1e-4)
%!error id=tfcoe:badOption tfcoe (iddata (x, u, Ts), 2, 1, "TolPar", 0)
%!error id=tfcoe:badOption tfcoe (iddata (x, u, Ts), 2, 1, "TdMin", -1)
%!error id=tfcoe:badOption
%! tfcoe (iddata (x, u, Ts), 2, 1, "TdMin", 0.5, "TdMax", 0.4);
%!error id=tfcoe:badOption tfcoe (iddata (x, u, Ts), 2, 2, "TdMin", 0.5)
%!error id=tfcoe:badInput tfcoe (iddata (x, u, Ts), 2, 1, 0.1, "TdMin", 0.5)
%!error id=tfcoe:badOption tfcoe (iddata (x, u, Ts), 2, 1, "NumTd", 1)
%!error id=tfcoe:badOption tfcoe (iddata (x, u, Ts), 2, 1, "NumTd", 2.5)
%!error id=tfcoe:badOption tfcoe (iddata (x, u, Ts), 2, 1, "StepMax", 0)
%!error id=tfcoe:badOption tfcoe (iddata (x, u, Ts), 2, 1, "StepReduction", 1)
%!error id=tfcoe:badOption tfcoe (iddata (x, u, Ts), 2, 1, "StepReduction", 0)
%!error id=tfcoe:badOption tfcoe (iddata (x, u, Ts), 2, 1, "FocusOrder", 11)
%!error id=tfcoe:badOption tfcoe (iddata (x, u, Ts), 2, 1, "FocusOrder", 2.5)
%!error id=tfcoe:badOption tfcoe (iddata (x, u, Ts), 2, 1, "Focus", 0)

%!demo
%! u = prbs (10, 8); Ts = 0.05; N = numel (u);
%! y = simc (idtf (4, [1 2.4 4], "IODelay", 0.12), u, Ts) ...
%!     + 0.1 * randn (N, 1);
%! M = tfcoe (iddata (y, u, Ts), 2, 0, 0.05)    # delay estimated from 0.05
%! M.Report.Fit
