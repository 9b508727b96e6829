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
## delays in [0, TdMax], then its Gauss-Newton refinement of the SRIVC
## loss, and with @var{td} also that refinement started at @var{td}.  Each
## delay and SRIVC model found starts the output-error iteration, in which
## the delay is a parameter kept in [0, TdMax]; the lowest loss wins (on a
## ZOH input the loss has a kink at every whole number of samples of
## delay, where a gradient method can stop short of the delay).  For @var{nz} = @var{np}
## the model has the delay @var{td} (default 0), not estimated.
##
## Options: @code{Lambda} (SVF cut-off of the SRIVC start, rad/s; default
## a grid), @code{MaxIter} (default 100), @code{Tol} (relative step and
## loss decrease, default 1e-8), @code{TdMax} (default: tfsrivc's, from the
## input-output cross-correlation, at least twice @var{td}, at most half
## the record), @code{Focus} (@qcode{"simulation"}, or a passband [w1 w2]
## in rad/s: the data are prefiltered as in @code{tfsrivc}'s Focus, a
## fourth-order Butterworth band), @code{OverPar} (@qcode{"off"} or
## @qcode{"on"}, below).
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

function [M, info, varargout] = tfcoe (varargin)
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
%!error id=tfcoe:notSupported tfcoe (iddata (x, [u u], Ts), 2, 1)
%!error id=tfcoe:badInput tfcoe (1, 2, 3, 4, 5, 6, 7, 8)
%!warning id=tfcoe:notConverged
%! ## an in-band disturbance (0.05 rad/sample = 1 rad/s): the output-error
%! ## minimum is not the SRIVC start, one iteration does not reach it
%! tfcoe (iddata (x + 0.1 * sin (0.05 * (1:N))', u, Ts), 2, 1, 0.1,
%!        "MaxIter", 1, "Tol", 1e-15);

%!demo
%! u = prbs (10, 8); Ts = 0.05; N = numel (u);
%! y = simc (idtf (4, [1 2.4 4], "IODelay", 0.12), u, Ts) ...
%!     + 0.1 * randn (N, 1);
%! M = tfcoe (iddata (y, u, Ts), 2, 0, 0.05)    # delay estimated from 0.05
%! M.Report.Fit
