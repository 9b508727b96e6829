## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn  {} {@var{thm} =} rivsvf (@var{data}, @var{nn}, "lambda_svf", @var{lam}, @dots{})
## @deftypefnx {} {@var{thm} =} rivsvf (@var{data}, @var{nn}, @var{lam}, @dots{})
## @deftypefnx {} {[@var{thm}, @var{yh}, @var{pset}, @var{info}] =} rivsvf (@dots{})
## Recursive instrumental-variable state-variable filter estimation
## (RIVSVF) of a continuous-time model with time-varying parameters.
##
## Data, @var{nn} = [na nb nk], outputs and the options @code{lambda_svf},
## @code{adm}, @code{adg}, @code{th0}, @code{P0}, @code{svf} are those of
## @code{rlssvf}; @var{thm} is ordered [a1 .. a_na, b0 .. b_(nb-1)]. Further
## options:
## @table @code
## @item tsiv
## time (s from the first sample) at which the IV stage takes over from
## RLSSVF (default: a tenth of the record); the IV stage starts from the
## last RLSSVF estimate and P (thesis sec. 3.2.1). @qcode{"auto"}: the
## time at which @code{rlsconverge} detects the convergence of RLSSVF run
## with the same options (a struct of its detector options instead of
## @qcode{"auto"} sets them); @var{info} reports it in
## @code{tsiv_detector}; no detected convergence is the error
## @code{<name>:notConverged}.
## @item dtupdate
## period (s) at which the auxiliary model is refreshed from the estimates
## (default: every sample); not below the sampling interval.
## @item stability
## @qcode{"keep"} (default): an estimate whose A(p) is not Hurwitz does not
## reach the auxiliary model, the last stable one stays; @qcode{"reflect"}:
## its unstable roots are reflected into the left half plane (eq. 3.10).
## @item mtheta
## filter M_theta(q^-1) of the estimates fed back (sec. 3.2.3):
## @qcode{"delay"} (default, q^-1), @qcode{"none"}, FIR taps, or a struct
## with @code{num} and @code{den} in powers of q^-1 (unit static gain), e.g.
## @code{struct ("num", [0.04762 0.04762], "den", [1 -0.9048])}.
## @item scaling
## signal scaling with a diagonal M_s (eq. 3.74 for the IV stage, eq. 3.66
## for the RLSSVF start), given as in @code{rlssvf}: np diagonal entries
## ordered like @var{thm}, a training record for eq. (3.54), or
## @qcode{"self"}. The estimates are unchanged up to rounding;
## @code{info.kappa} is that of the scaled P_s.
## @item antiwindup
## conditional updating against estimator windup (sec. 3.6.2, eq. 3.79):
## the threshold gamma > 1 on kappa_2(P) of an RLSSVF-FF run in parallel on
## the same SVF regression (default 0: off). While kappa_2 >= gamma the
## estimates and P are held at th0 and P0; when excitation returns
## (kappa_2 < gamma) the estimator restarts with RLSSVF and switches to IV
## tsiv later. The test is armed when kappa_2 < gamma first holds at or
## after tsiv (when RLSSVF is taken to have converged), so the start-up of
## the parallel filter from P0 is not mistaken for poor excitation.
## @item antiwindup_lambda
## forgetting factor of that RLSSVF-FF (default 0.998, thesis Table 3.2).
## @item precision
## @qcode{"double"} (default) or @qcode{"single"}, as in @code{rlssvf}.
## @item InterSample
## the rule by which the filters treat the input: the data's InterSample
## (default), @qcode{"zoh"}, @qcode{"foh"} (the exact first-order hold) or
## @qcode{"trapezoid"} (the trapezoidal, Tustin rule the thesis uses for an
## input that is not piecewise constant, sec. 3.1.3).
## @item Missing
## @qcode{"bridge"} (default) or @qcode{"error"}: how a NaN in y or u (a
## missing sample) is treated, as in @code{rlssvf}.
## @item GapSettle
## seconds without update after a gap of missing samples (default 20 /
## lambda_svf), as in @code{rlssvf}.
## @item covariance_guard
## true (default) or false: the protection of P after each update (and of
## the parallel RLSSVF-FF's P with @code{antiwindup}), as in
## @code{rlssvf}: left untouched while its symmetric part is positive
## definite in correlation form, repaired there when it is not, variances
## held below sqrt(realmax) of the precision.
## @end table
## The fourth output @var{info} has the number of estimates refused by the
## stability test, the tsiv used, @code{kappa}, the N-by-1 condition
## number kappa_2(P) after each recursion (singular-value ratio, since the
## IV update makes P non-symmetric), @code{error} and @code{innovation} (the
## prediction error and its normalised variance 1 + phi_f^T P zeta_f, as
## in @code{rlssvf}), and with @code{antiwindup} @code{kappa_ff} (kappa_2
## of the parallel RLSSVF-FF), @code{updating} (1 where the estimates were
## updated, 0 where held) and @code{resets}; @code{covariance_guard},
## @code{guard_samples} and @code{guard_first}, what the covariance
## protection did (as in @code{rlssvf}; 0 while held); with missing samples
## @code{missing}, the N-by-1 logical mask of them.
##
## @strong{Algorithm.} Before tsiv: RLSSVF (eqs. 1.57/1.59). Then the IV
## update (2.29) (Kalman filter) or (2.30) (forgetting factor), with the
## regressors of the SVF (eq. 1.27) and the instruments (2.15)-(2.17) built
## from the auxiliary model A(p, theta) x_hat = B(p, theta) u, which runs
## from the first sample driven by the latest accepted estimate.
## Reference: A. Padilla, PhD thesis, Universite de Lorraine, 2017, sec.
## 2.2.3 and 2.3.3.
##
## @strong{Example}
## @example
## Ts = 0.05; u = prbs (10, 8); N = numel (u);
## y = simc (struct ("B", 4, "F", [1 2.4 4]), u, Ts) + 0.1 * randn (N, 1);
## data = iddata (y, u, Ts, "InterSample", "zoh");
## thm = rivsvf (data, [2 1 0], "lambda_svf", 3, "tsiv", 20);
## @end example
## @seealso{rlssvf, rsrivc, clrivsvf}
## @end deftypefn

function varargout = rivsvf (varargin)
  varargout = contsid_guard ("rivsvf", @rivsvf_body, nargout, varargin);
endfunction

function varargout = rivsvf_body (varargin)
  contsid_nargchk ("rivsvf", nargin, nargout, [0 Inf], 4);
  [varargout{1:max(1, nargout)}] = contsid_riv ("rivsvf", nargout, varargin{:});
endfunction

%!shared Ts, u, x, data, N
%! Ts = 0.05; u = prbs (10, 8); N = numel (u);
%! x = simc (struct ("B", 4, "F", [1 2.4 4]), u, Ts);
%! data = iddata (x, u, Ts, "InterSample", "zoh");

%!test  # before tsiv RIVSVF is RLSSVF, sample by sample
%! a = rivsvf (data, [2 1 0], "lambda_svf", 3, "tsiv", 100);
%! b = rlssvf (data, [2 1 0], "lambda_svf", 3);
%! k = round (100 / Ts);   # samples at t < 100 s
%! assert (a(1:k, :), b(1:k, :), 0);
%! assert (any (any (a(k+2:end, :) != b(k+2:end, :))));

%!test  # noise-free LTI system: recovered
%! thm = rivsvf (data, [2 1 0], "lambda_svf", 3);
%! assert (thm(end, :), [2.4 4 4], 2e-3 * 4);

%!test  # with noise the IV estimate is far less biased than RLSSVF's
%! randn ("state", 3);
%! y = x + 0.3 * randn (N, 1);
%! d = iddata (y, u, Ts, "InterSample", "zoh");
%! ls = rlssvf (d, [2 1 0], "lambda_svf", 3);
%! iv = rivsvf (d, [2 1 0], "lambda_svf", 3, "tsiv", 50);
%! last = N - 2000 + 1:N;
%! e_ls = norm (mean (ls(last, :)) - [2.4 4 4]);
%! e_iv = norm (mean (iv(last, :)) - [2.4 4 4]);
%! assert (e_iv < e_ls / 2);

%!test  # four outputs, M_theta and dtupdate options
%! [thm, yh, pset, info] = rivsvf (data, [2 1 0], "lambda_svf", 3, ...
%!   "mtheta", struct ("num", [0.04762 0.04762], "den", [1 -0.9048]), ...
%!   "dtupdate", 10 * Ts, "stability", "reflect");
%! assert (size (pset), [3 3 N]);
%! assert (isfield (info, "stability_rejections"));
%! assert (size (info.kappa), [N 1]);
%! assert (all (info.kappa >= 1));
%! assert (thm(end, :), [2.4 4 4], 1e-2 * 4);

%!error id=rivsvf:badInput rivsvf (data, [2 1 0], "lambda_svf", 3, "tsiv", -1)
## an input zero at every sample: no excitation
%!error id=rivsvf:badInput
%! rivsvf (iddata (x, zeros (N, 1), Ts), [2 1 0], "lambda_svf", 3);
## a cut-off far above pi/Ts: a warning, and non-finite frozen outputs
## are an error
%!warning id=rivsvf:cutoffAboveNyquist
%! thm = rivsvf (data, [2 1 0], "lambda_svf", 100);
%!error id=rivsvf:numericalFailure
%! warning ("off", "rivsvf:cutoffAboveNyquist", "local");
%! [thm, yh] = rivsvf (data, [2 1 0], "lambda_svf", 1e9, "tsiv", 5);
%!error id=rivsvf:badInput rivsvf (data, [2 1 0], "lambda_svf", 3, "tsiv", 1e6)
%!error id=rivsvf:badInput rivsvf (data, [2 1 0], "lambda_svf", 3, "tsiv", "a")
%!error id=rivsvf:badInput rivsvf (data, [2 1 0], "lambda_svf", 3, "dtupdate", Ts / 2)
%!error id=rivsvf:badInput rivsvf (data, [2 1 0], "lambda_svf", 3, "dtupdate", NaN)
%!error id=rivsvf:badOption rivsvf (data, [2 1 0], "lambda_svf", 3, "stability", "x")
%!error id=rivsvf:badInput rivsvf (data, [2 1 0], "lambda_svf", 3, "mtheta", {1})
%!error id=rivsvf:badInput rivsvf (data, [2 1 0], "lambda_svf", 3, "mtheta", struct ("num", [1 1], "den", 1))
%!error id=rivsvf:badOption rivsvf (data, [2 1 0], "lambda_svf", 3, "A", [1 3 2])
%!error id=rivsvf:badOption rivsvf (data, [2 1 0], "lambda_svf", 3, "r1", u)
%!error id=rivsvf:badOption rivsvf (data, [2 1 0])
%!error id=rivsvf:badInput rivsvf (data, [2 4 0], "lambda_svf", 3)

%!demo
%! Ts = 0.05; u = prbs (11, 8); N = numel (u); t = (0:N-1)' * Ts;
%! theta = [2 + t / t(end), 4 * ones(N, 1), 4 * ones(N, 1)];
%! y = simc (theta, [2 1 0], u, Ts) + 0.2 * randn (N, 1);
%! data = iddata (y, u, Ts, "InterSample", "zoh");
%! opts = {"lambda_svf", 3, "adm", "kf", "adg", diag([1e-5 1e-7 1e-7])};
%! ls = rlssvf (data, [2 1 0], opts{:});
%! iv = rivsvf (data, [2 1 0], opts{:}, "tsiv", 50);
%! plot (t, theta(:, 1), "k", t, ls(:, 1), "b", t, iv(:, 1), "r");
%! legend ("true a_1", "RLSSVF", "RIVSVF"); xlabel ("t (s)");
