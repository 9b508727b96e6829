## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn  {} {@var{R} =} residtrace (@var{data}, @var{M})
## @deftypefnx {} {@var{R} =} residtrace (@var{data}, @var{M}, "validation", @var{datav}, @dots{})
## @deftypefnx {} {@var{R} =} residtrace (@var{y}, @var{u}, @var{Ts}, @var{M}, @dots{})
## Traces the residual of a continuous-time model to the effect it lacks,
## adds that effect, and reports the error before and after.
##
## @var{data}: the estimation record (an @code{iddata}, or @var{y},
## @var{u}, @var{Ts}), uniformly sampled; NaN in y or an input marks a
## missing sample, bridged as @code{srivc} bridges it (an input held or
## interpolated by its hold, the output interpolated linearly: see
## @code{residtrace_bridge}) and left out of every figure (RMSE, fit,
## residual tests: computed on the present samples; @code{R.missing}
## holds the masks of both records). @var{M}: an @code{idpoly} from
## @code{srivc}, @code{lssvf}, @code{ivsvf} (or an @code{idtf},
## @code{idproc}, @code{idctm} built by hand). Its
## coefficients of F that are exactly zero are structural (integrators, a
## missing damping term) and stay zero unless an effect frees them.
## @var{datav}: a validation record with the same inputs. Without it the
## last third of @var{data} is the validation record and the first two
## thirds the estimation record (option @code{"split"}).
##
## @strong{Effects} (a library of what a linear time-invariant model
## lacks), each fitted on the estimation record only:
## @table @asis
## @item 'offset'
## a constant entering with the input (the extra regressor 1) or added to
## the output.
## @item 'coulomb'
## the regressor sign(v), v the velocity (SVF derivative of the measured
## output, filtered forward and backward, or the output itself when it is
## a velocity: both variants, BIC), as the thesis does for the throttle
## (sec. 4.2, eq. 4.17); when none of these gives a friction (a gain
## opposing the motion), each also with the velocity of the model's own
## output instead of the measured one (at rest the measured velocity's
## sign is the noise's: a body that sticks), BIC choosing among the
## frictions. Simulated honestly: sign() of the model's own
## velocity, in sub-steps (option @code{"substeps"}). When sign(v) is
## explained by the input's levels (a two-level input through a velocity)
## the verdict is "not identifiable from these data".
## @item 'viscous'
## the velocity coefficient of F freed when the model has it fixed at zero.
## @item 'delay'
## the input delay nk raised by 1 .. @code{maxdelay} samples, then
## refined to a fraction of a sample (the held input delayed by f,
## (1 - f) u(k) + f u(k-1)) when the BIC, the fraction counted, says so:
## a transport delay is rarely a whole number of samples, and a rounded
## one leaves an error that an extra pole or zero would take.
## @item 'order'
## one or two more poles, zeros.
## @item 'static_nonlinearity'
## u^2, u^3, or the input clipped (saturation, dead zone) as extra
## regressors, or a polynomial of the model output.
## @item 'saturation'
## the output, or an inner node of the model (a tank that overflows, a
## valve at its end stop: F split into upstream and downstream sections),
## limited to levels that are estimated; or a state of a physical
## realisation: the output as a position held at an end stop with its
## velocity reset (the velocity a state of the observable canonical form
## when every channel's relative degree is at least two), or the inner
## state of a cascade of two first-order sections with square-root or
## linear outflows that overflows (two tanks; a share of the overflow,
## estimated, falls into the lower one), alone or with the outer state
## (the output) overflowing too. The cascade's initial level is one of its
## parameters. These two are simulated
## in sub-steps and fitted on their simulation error, levels included
## (Levenberg-Marquardt; the refined-IV engine has no regression form for
## a nonlinearity of an unmeasured state), and compete with the other
## variants by BIC.
## @item 'state_nonlinearity'
## a function of the output inside the dynamics: sqrt(y) (the outflow of a
## tank), y^2 (a time constant that depends on the operating point), y^3
## or y^2 and y^3 (a nonlinear spring), with a constant of their own when
## the record's levels are estimated; or square-root outflows at both
## nodes of a cascade of two first-order sections (two tanks; fitted on
## its simulation error).
## @item 'initial_state'
## the record did not start at rest: the model's free response from an
## initial state fitted on each record (declared: the simulations of such
## a model are "from the input plus an estimated initial state"; tested
## by the likelihood ratio of its least-squares fit). A property of the
## record rather than of the system: when significant it is added to
## the baseline (as the levels are) and the pass is run again; it is
## never counted as an effect (@code{R.initial_state} and the verdict say
## it was estimated).
## @item 'sinusoid'
## an additive sinusoid at the strongest line of the residual periodogram
## not shared with the input (Fisher's g test); on the validation record
## its amplitude and phase are unknown, so they are fitted on one half and
## applied to the other (two-fold cross-fitting). Only periods the
## records resolve are looked at: at least two cycles in the estimation
## record and one in each half of the validation record (a slower line is
## a level or a drift, not a sinusoid).
## @item 'drift'
## random-walk parameters tracked by the Kalman-filter IV update (thesis
## eq. 2.29), Qn by maximum likelihood (sec. 3.3); evidence from SRIVC
## fits on segments of the estimation record (chi^2 test of equal
## parameters). Its validation output is the model simulated with the
## parameters tracked on the validation record, each sample using only
## earlier estimates.
## @item 'colored_noise'
## an AR noise model: it does not change a simulated output, so its
## "after" RMSE is the one-step-ahead prediction RMSE; it is a candidate
## only when no deterministic effect is significant and the validation
## residual is independent of the input but not white.
## @end table
##
## @strong{Scoring.} Each candidate's validation error e1 is compared with
## the current model's e0 on the validation record: score = 1 -
## mean(e1^2)/mean(e0^2), the share of the residual's mean square it
## explains. Its significance: does the candidate's correction delta = e0
## - e1 (fitted on other data) explain part of e0? Under the null of an
## irrelevant candidate, delta is independent of e0 and sum e0 delta has
## mean 0 and the Bartlett variance sum_tau (N - |tau|) gamma_e0(tau)
## gamma_delta(tau), which accounts for both series being correlated in
## time; one-sided normal p-value. (The Diebold-Mariano test of equal
## accuracy with a Newey-West variance is reported as @code{p_dm}; it
## is far less powerful when the residual is periodic or slow.) A
## candidate is significant when p < alpha / (number of candidates of
## its group) (Bonferroni) and its score >= @code{minscore}. Before it is
## scored every candidate passes one acceptance check (all of this
## judgement is the core's, core/include/ctid/apps/residtrace/
## judgement.hpp): each term it adds determined on the
## estimation data (Wald z >= 2: its standard error well below its
## value) and the terms significant there (largest z >= 3); an effect
## that acts on part of the record (a saturation's level, a direction of
## motion) active on at least 1 % of the samples and inactive on at
## least 1 %; a friction with a velocity that reverses. A
## candidate that fails it is not tested, with the reason. A biproper M
## (a direct feedthrough) is analysed; the effects fed back from its
## output (Coulomb friction, state nonlinearity) are then not tested,
## with the reason (so is a candidate whose simulation the model's
## structure does not support); an improper M is
## @code{residtrace:notSupported}. The
## candidates form two groups ranked apart: those simulated from the
## input, and those that use the validation output itself (drift: a
## simulation with parameters tracked on the validation record; coloured
## noise: a prediction); the second group is looked at only when nothing
## in the first is significant. Within a group significant candidates are
## ranked by score; one that adds fewer parameters moves ahead of a candidate of
## the same kind above it unless that one's extra correction is
## significant by the same rules (p < alpha and a share >= minscore of
## what the simpler one leaves) (parsimony); two candidates of as many
## added parameters whose corrections neither significantly improves on
## the other's are ordered by their BIC on the estimation data, the
## added parameters counted (same footing). The
## variant of each effect (which delay, which nonlinearity, ...) is chosen
## on the estimation data by BIC. All models are estimated by SRIVC
## (thesis eqs. 2.8-2.13) with the added regressors; a real pole that a
## candidate's fit sends beyond what the samples can see (p Ts > 1000) is
## residualised (its mode at steady state) and the fit repeated in the
## lower order, so that no model is stiffer than its data (the
## re-estimates of the current model in its own structure keep its
## order); the model as given
## is re-estimated the same way first, and candidates are scored against
## that re-estimate, so that a better estimator is never credited to an
## effect.
##
## @strong{Speed.} Every candidate is first fitted with at most three
## SRIVC iterations per fit, started from the current model, on at most
## 20 000 samples of the estimation record, and scored on the whole
## validation record; only a candidate whose correction then has p < 0.2
## (or a score below -5 minscore, or whose screening fit failed) is
## fitted again on the whole record to convergence and scored on that
## fit, so
## every decision rests on converged fits. Within a candidate, variants
## are screened the same way and the two best by BIC iterated to
## convergence.
##
## @strong{Levels.} A record in raw units (option @code{levels}:
## @qcode{"auto"}, the default, decides it when the model has no
## integrator and the mean of the input or of the output lies more than
## three standard deviations from zero, or the output starts at rest away
## from zero and keeps that sign: its first five samples within 5 % of
## its range of each other, their median beyond 5 % of the range from
## zero (as @code{srivc}'s rule for an output offset) and 99 % of the
## samples of the same sign, a record whose zero is not its operating
## point, e.g. a temperature in degC starting at ambient;
## @qcode{"estimate"}, @qcode{"none"})
## has an input level removed from both records and an output offset
## estimated with the model, and @code{R.levels} says so. A model that
## carries the levels it was estimated with (@code{srivc} on a raw
## record: @code{M.Report.DataUsed.InputOffset}, @code{OutputOffset}
## nonzero) keeps them with @qcode{"auto"}: its input level is removed and
## the output level estimated with the model, started from M's (with an
## integrator the output level is an initial condition the fit has
## already), so that the baseline never loses a level M has and no
## effect is credited for putting it back. The levels and a declared
## initial state are part of the baseline, never an effect. The input level
## is the one @var{M} carries when it has one (@code{srivc} on a raw
## record: @code{M.Report.DataUsed.InputOffset}, where its simulation
## starts at rest), otherwise the estimation record's first input sample
## (the record is taken to start at rest there; otherwise see
## 'initial_state').
##
## @strong{Iteration.} The winner is added, the model re-estimated, and
## the tests run again, until no candidate is significant, the residual
## is white and independent of the input (Ljung-Box and prewhitened
## cross-correlation tests at level alpha), after drift or coloured noise
## (which end the search), or after @code{iterate} effects.
##
## @strong{Options}
## @table @code
## @item validation
## the validation record (iddata, or a cell @{y, u, Ts@}).
## @item split
## share of @var{data} used for estimation without a validation record
## (default 2/3).
## @item effects
## cell of effect names to test (default all).
## @item alpha
## significance level (default 0.01).
## @item minscore
## smallest share of the residual's mean square an effect must explain
## (default 0.01).
## @item maxlag
## largest lag of the residual correlations (default 25).
## @item maxdelay
## largest extra delay tried, in samples (default 10).
## @item iterate
## largest number of effects added (default 3; 1: a single pass).
## @item substeps
## sub-steps per sample when simulating Coulomb friction or a closed
## loop (default 10).
## @item lambda_v
## cut-off (rad/s) of the velocity's SVF derivative (default 10 times
## the fastest pole of M, at most a third of the Nyquist frequency).
## @item controller, r1, r2, r1v, r2v
## a closed loop u = r1 + C(q^-1) (r2 - y) (controller as in @code{simc});
## then every simulation (estimation and validation records) runs in that
## loop with the model's own output fed back: r1, r2 of the estimation
## record, r1v, r2v of the validation record (r2 default zero). The data's
## input must be the plant input u.
## @item verbose
## print the ranking of each pass (default false).
## @item table
## a file name: the before/after table is written there as Markdown.
## @item levels
## @qcode{"auto"} (default), @qcode{"estimate"} or @qcode{"none"}: see
## Levels.
## @end table
##
## @strong{Outputs}: @var{R} is a struct with
## @table @code
## @item effect
## the top-ranked effect of the first pass, or 'none'.
## @item ranking
## struct array of the first pass: the candidates simulated from the
## input, best first, then those that use the validation output (field
## @code{group}): effect, score, p, stat (the correlation test's p-value
## and z), p_dm, significant, variant, nadd (added parameters), rmse
## (validation simulation; NaN for the second group), rmse_tracked or
## rmse_prediction (second group), kind, applicable, reason, evidence,
## screened (true: its fits stopped after three SRIVC iterations, because
## that fit's correction was far from significant, p >= 0.2; see Speed),
## seconds (time spent on the candidate), failed (it applies to the
## model but its estimation failed: not tested), variants (the variants
## fitted on the estimation record, with their BIC, from which
## @code{variant} was chosen; empty for a candidate of one form).
## @item untested
## cell of the effects that could not be estimated in the pass that
## ended the search (found nothing): they were not tested, and the
## verdict names them ("not tested ..., their estimation failed"; when
## no candidate could be tested at all it begins "cannot tell").
## @item rmse_given, rmse_before, rmse_after
## validation RMSE of the output simulated from the input: of M as given
## (with the output and input offsets it carries, as @code{srivc} returns
## them on a raw record in @code{M.Report.DataUsed.OutputOffset} and
## @code{InputOffset}), of M re-estimated in its own structure (the
## baseline every effect is scored against), and of the model with the top
## effect added. Every
## RMSE field is a simulation from the input (plus an estimated initial
## state once 'initial_state' is added) unless its name says otherwise:
## when the top effect is drift or coloured noise, @code{rmse_after}
## stays the simulation of the time-invariant model and
## @code{rmse_after_tracked} (simulation with parameters tracked on the
## validation record) or @code{rmse_after_prediction} (one-step
## prediction) carries that effect's figure. @code{rmse_refit} is
## the re-estimate's RMSE without an initial state; when 'initial_state'
## is declared before the first effect, @code{rmse_before} includes it
## (and @code{rmse_after} too when nothing else is found).
## @code{initial_state}: true when the record's initial state was
## estimated (@code{initial_state_evidence}: what its test saw).
## An unstable M as given (a pole in the open right half-plane) is not
## simulated: @code{given_unstable} is true, @code{rmse_given} NaN, and
## the verdict begins "the given model is unstable".
## @item levels
## what was done about the record's levels (estimated, u0, y0, text).
## @item rivals
## the candidates the data do not tell from an effect that was found: for
## each pass's winner, the other significant candidates of its group
## whose validation error the winner's correction does not significantly
## improve on (the encompassing test residtrace ranks nested candidates
## by, and a share of at least @code{minscore}); struct array with
## fields @code{found} (the winner), @code{effect}, @code{variant},
## @code{score}, @code{p}; empty when every winner was told apart. The
## verdict names them ("...; not told apart by these data: saturation
## from static_nonlinearity").
## @item verdict
## one line: what was found, or why nothing could be tested.
## @item model
## the model with the top effect, as residtrace simulated it: an
## @code{idtraced} object (see @code{help idtraced}) that @code{simc},
## @code{sim}, @code{comparec}, @code{residc} and @code{present} take,
## with the fields (@code{M.F}, @code{get (M)}) @code{F}, @code{fixed}, @code{channels} (inputs and effect terms:
## type, numerator @code{B}, delay @code{nk}, parameter), output terms
## @code{out} (the output level, a polynomial, a sinusoid, a saturation,
## each with its coefficients @code{c} and standard deviations
## @code{cstd}), @code{phys} (a physical realisation: end stop, cascade),
## @code{ltv}, @code{noise}, @code{theta} and @code{cov} (the SRIVC
## covariance), @code{u0} (the input level removed from the records: the
## levels are part of the model), @code{params} (its physical reading with
## standard deviations, from @code{residtrace_physical}: gains, poles,
## and each effect in physical units), @code{npre}, @code{substeps},
## @code{closed_loop} (how it was simulated) and @code{linear}, its linear
## part as an @code{idpoly} (one input per channel, built by
## @code{idctm}). @code{comparec (datav, R.final_model)} simulates it
## on the validation record and reproduces @code{R.rmse_final} as its
## RMSE (@code{R.model}: @code{R.rmse_after}), as does
## @code{residtrace_sim (R, datav)}; @code{residtrace_plot} draws the
## before/after figure.
## @item evidence
## the winner's evidence (term, value, std, and what the test saw).
## @item effects, final_model, rmse_final
## all effects added by the iteration, the last model (fields as
## @code{model}) and the RMSE of its simulation
## (@code{rmse_final_tracked}, @code{rmse_final_prediction} when it ends
## with drift or coloured noise).
## @item sim
## the validation output @code{y} and the model outputs on it:
## @code{given} (M as given), @code{refit}, @code{before} (the refit
## with a declared initial state), @code{after} (top effect),
## @code{final} (a prediction or a tracked simulation where the effect's
## kind says so), @code{final_simulation}.
## @item history
## one entry per pass: effect, rmse, fit, white_p, indep_p, ranking,
## rivals.
## @item table, tests_before, tests_after, testable, reason
## the Markdown before/after table (see @code{residtrace_table}), the
## residual tests, and whether the residual could be tested at all.
## @end table
##
## Errors (identifiers @code{residtrace:badInput},
## @code{residtrace:dimensionMismatch}, @code{residtrace:badOption}): a
## model that is not a continuous-time single-output model, a validation
## record with other inputs, records too short for @code{maxlag},
## irregular sampling, unknown options or effects. A residual that is zero to rounding (a perfect
## model) or not finite gives @code{effect = 'none'} with
## @code{testable = false} and the reason.
##
## @strong{Example}
## @example
## Ts = 0.05; u = prbs (10, 6); N = numel (u);
## G = idctm (2, [1 1.2 1]);
## y = simc (G, u + 0.4, Ts) + 0.05 * randn (N, 1);    # an input offset
## M = srivc (iddata (y, u, Ts), [1 2 0]);
## R = residtrace (iddata (y, u, Ts), M);
## R.effect, [R.rmse_before, R.rmse_after]
## @end example
## @seealso{idtraced, residtrace_table, residtrace_sim, residtrace_plot, residc, comparec, srivc, rsrivc}
## @end deftypefn

function varargout = residtrace (varargin)
  varargout = contsid_guard ("residtrace", @residtrace_body, nargout, varargin);
endfunction

function [R, varargout] = residtrace_body (varargin)
  contsid_nargchk ("residtrace", nargin, nargout, [0 Inf], 1);
  fname = "residtrace";
  if (nargin < 2)
    error ("residtrace:badInput", "residtrace: expected data and a model");
  endif
  try
    [d, miss] = contsid_getdata (fname, varargin{:});   # NaN: missing
    d = residtrace_bridge (d, miss);
  catch err
    rethrow_as (err);
  end_try_catch
  if (numel (varargin) < d.nconsumed + 1)
    error ("residtrace:badInput", "residtrace: the model M is missing");
  endif
  M = varargin{d.nconsumed + 1};
  args = varargin(d.nconsumed + 2:end);
  all_effects = {"offset", "coulomb", "viscous", "delay", "order", ...
                 "static_nonlinearity", "saturation", "state_nonlinearity", ...
                 "initial_state", "sinusoid", "drift", "colored_noise"};
  defaults = struct ("validation", [], "split", 2/3, "effects", {all_effects},
                     "alpha", 0.01, "minscore", 0.01, "maxlag", 25,
                     "maxdelay", 10, "iterate", 3, "substeps", 10,
                     "lambda_v", [], "controller", [], "r1", [], "r2", [],
                     "r1v", [], "r2v", [], "verbose", false, "table", "",
                     "maxiter", 30, "levels", "auto");
  opts = contsid_options (fname, defaults, args);
  opts = check_options (opts, all_effects);
  if (! isobject (M) || isa (M, "iddata"))
    error ("residtrace:badInput",
           ["residtrace: M must be a model (idpoly from srivc, lssvf, ", ...
            "ivsvf; idtf, idproc, idctm), not a %s"], class (M));
  endif
  if (! d.uniform)
    error ("residtrace:badInput",
           "residtrace: the data must be uniformly sampled");
  endif
  Mst = model_struct (M, d.Ts);
  if (iscell (Mst.B))
    nbM = numel (Mst.B);
  else
    nbM = 1;
  endif
  if (nbM != columns (d.u))
    error ("residtrace:dimensionMismatch",
           "residtrace: M has %d input(s), the data %d", nbM, columns (d.u));
  endif
  [D, V] = records (d, opts);
  np = numel (Mst.theta);
  ## a constant output tells nothing, whatever the input: said so before
  ## any fit (the re-estimate would fail and seem to blame the input)
  for rec = {D.y, V.y; "estimation", "validation"}
    yr = rec{1};
    if (all (yr == yr(1)))
      error ("residtrace:badInput",
             ["residtrace: the output of the %s record is constant: it ", ...
              "carries no information on the model"], rec{2});
    endif
  endfor
  for rec = {D, V; "estimation", "validation"}
    Rr = rec{1};
    if (numel (Rr.y) < max (4 * opts.maxlag, 10 * np + 20))
      error ("residtrace:badInput",
             ["residtrace: the %s record has %d samples, too few for ", ...
              "maxlag = %d and %d parameters (at least %d)"],
             rec{2}, numel (Rr.y), opts.maxlag, np,
             max (4 * opts.maxlag, 10 * np + 20));
    endif
  endfor

  ## Context shared by the candidates.
  base = residtrace_base (Mst, d);
  n_f = numel (Mst.F) - 1;
  if (any ([base.channels.nb] > n_f + 1))
    error ("residtrace:notSupported",
           ["residtrace: M is improper (a numerator of higher degree ", ...
            "than its denominator): its simulation is not defined"]);
  endif
  if (any ([base.channels.nb] > n_f) && ! isempty (opts.controller))
    error ("residtrace:notSupported",
           ["residtrace: a biproper M (direct feedthrough) in a closed ", ...
            "loop: the loop would be algebraic"]);
  endif
  rts = roots (Mst.F);
  nz = abs (rts(abs (rts) > 1e-9 * max ([abs(rts); 1])));
  T = (numel (D.y) - 1) * D.Ts;
  if (isempty (nz))
    wlo = 2 * pi / T;
  else
    wlo = 0.2 * min (nz);
  endif
  Fp = residtrace_prefilter (Mst.F, wlo);
  ctx.opts = opts;
  ctx.wlo = wlo;
  ctx.maxiter = opts.maxiter;
  lam_v = opts.lambda_v;
  if (isempty (lam_v))
    lam_v = min (10 * max (abs (roots (Fp))), pi / D.Ts / 3);
  endif
  is_y = (numel (Mst.F) == 2);
  ctx.lam_v = lam_v;                  # the velocity's filter (Coulomb)
  ctx.vel_is_y = is_y;
  ## velocity columns: the default one (dy/dt, or y for a first-order
  ## model) and the output read as a velocity
  vel = @(y) [residtrace_velocity(y, D.Ts, lam_v, is_y), ...
              residtrace_velocity(y, D.Ts, lam_v, true)];
  if (isempty (V.pre))
    D.vhat = vel (D.y);
    V.vhat = vel (V.y);
  else
    ne = numel (D.y);
    v = vel ([D.y; V.y]);
    D.vhat = v(1:ne, :); V.vhat = v(ne+1:end, :);
  endif
  D.ysm = D.y; V.ysm = V.y;
  ## the record's levels (raw units): the input level is removed from
  ## both records, an output offset joins the re-estimated model
  Vraw = V;
  [c_given, u_given] = contsid_carried_levels (M, columns (d.u));
  lev = level_plan (D, Mst, opts.levels, u_given, c_given);
  D.u -= lev.u0; V.u -= lev.u0;
  if (! isempty (V.pre))
    V.pre = struct ("y", D.y, "u", D.u, "vhat", D.vhat, "ysm", D.ysm);
    Vraw.pre = V.pre;
    Vraw.pre.u = D.u + lev.u0;
  endif
  ctx.D = D;
  ctx.V = V;
  ## the figures leave the missing validation samples out
  vmask (V.missing);
  unmask = onCleanup (@() vmask ([]));
  ex = struct ("u0", lev.u0, "npre", 0, "closed", ! isempty (V.loop),
               "substeps", opts.substeps);
  if (! isempty (V.pre))
    ex.npre = numel (D.y);
  endif

  ## M as given, and M re-estimated by SRIVC in its own structure.
  base.np = np;
  ## M as the user has it: with the levels it was estimated with (srivc on
  ## a raw record: Report.DataUsed.OutputOffset and InputOffset, the
  ## offsets removed from the data), as comparec on data with them removed
  Vg = Vraw;
  Vg.u -= u_given;
  if (! isempty (Vg.pre))
    Vg.pre.u -= u_given;
  endif
  ## an unstable M as given is not simulated: its figure would be the
  ## size of its divergence, not an error (NaN, and the verdict says so)
  R = struct ();
  R.missing = struct ("estimation", D.missing, "validation", V.missing);
  R.given_unstable = ! stable_given (Mst.F);
  e_given = NaN (size (V.y));
  if (! R.given_unstable)
    try
      e_given = residtrace_valerror (base, Vg, ctx) - c_given;
    catch
    end_try_catch
  endif
  if (any (! isfinite (e_given)))
    e_given(:) = NaN;                  # M as given cannot be simulated
  endif
  R.rmse_given = rms_ (e_given);
  R.fit_given = fit_ (V.y, e_given);
  starts = {Mst.F};
  if (any (real (rts) >= 0 & abs (rts) > 1e-9 * max ([abs(rts); 1])))
    starts{end+1} = [];
  endif
  tmpl = base;
  if (lev.estimate)
    ## started at the level M carries (none: the engine's start)
    tmpl.out(end+1) = struct ("type", "offset", "c", c_given, "cstd", 0,
                              "omega", 0);
    tmpl.levels = true;
  endif
  t0 = tic ();
  ## the re-estimates in the current structure keep its order (see
  ## residtrace_fit)
  keep = setfield (ctx, "keep_order", true);
  cur = residtrace_fit (tmpl, D, keep, starts);
  if (opts.verbose)
    printf ("residtrace: M re-estimated in %.1f s\n", toc (t0));
  endif
  R.levels = level_report (lev, cur);
  if (! cur.ok)
    error ("residtrace:numericalFailure",
           ["residtrace: M could not be re-estimated on the estimation ", ...
            "data (does the input excite it?)"]);
  endif
  cur.effects = {};
  R.baseline = cur;
  R.params_before = residtrace_physical (refresh_cov (base, cur), D.Ts);

  history = struct ("effect", {}, "rmse", {}, "fit", {}, "white_p", {},
                    "indep_p", {}, "ranking", {}, "model", {},
                    "kind", {}, "evidence", {}, "rivals", {});
  [e0, ~] = residtrace_valerror (cur, V, ctx);
  R.rmse_before = rms_ (e0);
  R.fit_before = fit_ (V.y, e0);
  R.tests_before = residtrace_whiteness (e0, V.u, opts.maxlag,
                                         rms_ (V.y));
  R.tests_given = residtrace_whiteness (e_given, V.u, opts.maxlag,
                                        rms_ (V.y));
  R.testable = R.tests_before.testable;
  R.reason = R.tests_before.reason;
  if (R.testable)
    [R.testable, R.reason] = excitation (D, V, np);
  endif
  R.effect = "none";
  R.ranking = struct ([]);
  R.untested = {};
  R.rivals = struct ("found", {}, "effect", {}, "variant", {}, "score", {},
                     "p", {});
  R.rmse_after = R.rmse_before;
  R.rmse_after_kind = "simulation";
  R.rmse_after_tracked = NaN;
  R.rmse_after_prediction = NaN;
  R.model = export_model (cur, D.Ts, ex);
  R.evidence = struct ("text", "no effect found");
  R.effects = {};
  R.rmse_refit = R.rmse_before;
  R.sim = struct ("y", V.y, "given", V.y - e_given, "refit", V.y - e0,
                  "before", V.y - e0, "after", V.y - e0, "final", V.y - e0);
  steps = step_row (["M as given" ifelse_(R.given_unstable,
                                           " (unstable: not simulated)", "")],
                    e_given, V.y, R.tests_given, "simulation",
                    R.params_before);
  steps(2) = step_row (["M re-estimated (SRIVC)" R.levels.label], e0, V.y,
                       R.tests_before, "simulation",
                       residtrace_physical (cur, D.Ts));
  R.steps = steps;
  e_sim = e0;                           # the simulation error of cur
  if (! R.testable)
    R.verdict = [given_text(R) "cannot test: " R.reason];
    R.tests_after = R.tests_before;
    R.final_model = R.model;
    R.rmse_final = R.rmse_after;
    R.rmse_final_tracked = NaN;
    R.rmse_final_prediction = NaN;
    R.history = history;
    R.params_after = R.params_before;
    R.table = residtrace_table (R);
    return;
  endif

  pass = 0;
  x0row = [];
  while (pass < opts.iterate)
    pass++;
    tests = residtrace_whiteness (e0, V.u, opts.maxlag, rms_ (V.y));
    if (pass > 1 && tests.testable && tests.white_p > opts.alpha
        && tests.indep_p > opts.alpha)
      break;                          # the residual tests pass
    endif
    t0 = tic ();
    [ranking, winner, x0win] = run_pass (cur, ctx, e0, tests, opts);
    if (opts.verbose)
      print_ranking (pass, ranking);
      printf ("  (pass: %.1f s)\n", toc (t0));
    endif
    if (! isempty (x0win))
      ## the record's initial state: a property of the record, estimated
      ## (declared) with the baseline, then the pass is run again; never
      ## counted as an effect
      x0row = x0win;
      cur = x0win.model;
      e0 = x0win.e1;
      ## from now on every fit on the estimation record estimates its
      ## initial state with the model (the engine's free responses), and
      ## the current model is re-estimated so: a transient fitted after
      ## the estimation would have biased it, and every candidate would
      ## be scored against that biased baseline
      ctx.D.initial_state = true;
      keep.D = ctx.D;
      refit = residtrace_fit (cur, ctx.D, keep, {cur.F});
      if (refit.ok)
        e_re = residtrace_valerror (refit, V, ctx);
        if (all (isfinite (e_re)))
          refit.effects = cur.effects;
          cur = refit;
          e0 = e_re;
          x0row.model = cur;
          x0row.e1 = e0;
        endif
      endif
      e_sim = e0;
      R.steps(end+1) = step_row (sprintf ("initial state estimated (%s)",
                                          x0win.variant),
                                 e_sim, V.y,
                                 residtrace_whiteness (e0, V.u, opts.maxlag,
                                                       rms_ (V.y)),
                                 "simulation",
                                 residtrace_physical (cur, D.Ts));
      if (strcmp (R.effect, "none"))
        ## declared before any effect: the baseline includes it
        R.rmse_before = rms_ (e0);
        R.fit_before = fit_ (V.y, e0);
        R.sim.before = V.y - e0;
        R.rmse_after = R.rmse_before;
      endif
      pass--;
      continue;
    endif
    h = struct ("effect", "none", "rmse", rms_ (e0), "fit", fit_ (V.y, e0),
                "white_p", tests.white_p, "indep_p", tests.indep_p,
                "ranking", ranking, "model", [], "kind", "simulation",
                "evidence", [], "rivals", []);
    if (pass == 1)
      R.ranking = ranking;
    endif
    if (isempty (winner))
      history(end+1) = h;
      break;
    endif
    h.effect = winner.effect;
    h.model = winner.model;
    h.kind = winner.kind;
    h.evidence = winner.evidence;
    h.rivals = winner.rivals;
    history(end+1) = h;
    for v = winner.rivals(:).'
      R.rivals(end+1) = struct ("found", winner.effect, "effect", v.effect,
                                "variant", v.variant, "score", v.score,
                                "p", v.p);
    endfor
    next = winner.model;
    next.effects = [cur.effects, {winner.effect}];
    cur = next;
    e0 = winner.e1;
    simulated = strcmp (winner.kind, "simulation");
    if (simulated)
      e_sim = winner.e1;
    endif
    st = step_row (sprintf ("+ %s (%s)", winner.effect, winner.variant),
                   e_sim, V.y,
                   residtrace_whiteness (e0, V.u, opts.maxlag, rms_ (V.y)),
                   kind_text (winner.kind), residtrace_physical (cur, D.Ts));
    st.rmse_other = ifelse_ (simulated, NaN, rms_ (winner.e1));
    R.steps(end+1) = st;
    if (pass == 1)
      R.sim.after = V.y - winner.e1;
      R.effect = winner.effect;
      R.rmse_after = rms_ (e_sim);
      if (strcmp (winner.kind, "tracking"))
        R.rmse_after_tracked = rms_ (winner.e1);
      elseif (strcmp (winner.kind, "prediction"))
        R.rmse_after_prediction = rms_ (winner.e1);
      endif
      R.rmse_after_kind = kind_text (winner.kind);
      R.model = export_model (cur, D.Ts, ex);
      R.evidence = winner.evidence;
    endif
    if (! simulated)
      break;
    endif
  endwhile
  R.initial_state = ! isempty (x0row);
  R.initial_state_evidence = [];
  if (R.initial_state)
    R.initial_state_evidence = x0row.evidence;
  endif
  if (strcmp (R.effect, "none") && R.initial_state)
    ## the initial state is part of the baseline, not an effect: the
    ## model returned is the re-estimate with it
    R.rmse_after = rms_ (x0row.e1);
    R.sim.after = V.y - x0row.e1;
    R.model = export_model (x0row.model, D.Ts, ex);
  endif
  R.effects = cur.effects;
  if (! isempty (history) && strcmp (history(end).effect, "none")
      && ! isempty (history(end).ranking))
    ## the pass that ended the search: a candidate that could not be
    ## estimated there was never tested against the residual it left
    r = history(end).ranking;
    R.untested = {r([r.failed]).effect};
  endif
  R.verdict = [given_text(R) verdict_text(R, history)];
  R.final_model = export_model (cur, D.Ts, ex);
  R.rmse_final = rms_ (e_sim);
  R.rmse_final_tracked = NaN;
  R.rmse_final_prediction = NaN;
  if (! isempty (cur.ltv))
    R.rmse_final_tracked = rms_ (e0);
  elseif (! isempty (cur.noise))
    R.rmse_final_prediction = rms_ (e0);
  endif
  R.sim.final = V.y - e0;
  R.sim.final_simulation = V.y - e_sim;
  R.tests_after = residtrace_whiteness (e0, V.u, opts.maxlag, rms_ (V.y));
  R.params_after = residtrace_physical (cur, D.Ts);
  R.history = history;
  R.table = residtrace_table (R);
  if (! isempty (opts.table))
    residtrace_table (R, opts.table);
  endif
endfunction

## One pass: every candidate fitted, scored on the validation record and
## ranked; the winner (or []) with its validation error e1.
function [ranking, winner, x0win] = run_pass (cur, ctx, e0, tests, opts)
  ## Effects simulated from the input, and effects that use the validation
  ## output itself (tracking, prediction): two groups, each with its own
  ## Bonferroni level and ranking; the second is only looked at when
  ## nothing in the first is significant.
  usesv = {"drift", "colored_noise"};
  simset = setdiff (opts.effects, usesv, "stable");
  rows_ = [];
  ranking = [];
  winner = [];
  x0win = [];
  if (any (strcmp (simset, "initial_state")))
    ## first the record's initial state: when significant (at the level
    ## of a full pass) it is added and the pass run again
    c = guarded ("initial_state", @() residtrace_cand_x0 (cur, ctx));
    row = score (c, cur, ctx, e0);
    row.significant = effect_sim_mex ("residtrace", "declare", row,
                                      struct ("alpha", opts.alpha,
                                              "minscore", opts.minscore,
                                              "tests", numel (simset)));
    if (row.significant)
      x0win = row;
      ranking = row;
      return;
    endif
    rows_ = row;
    simset = setdiff (simset, {"initial_state"}, "stable");
  endif
  for k = 1:numel (simset)
    row = screened_row (simset{k}, cur, ctx, e0);
    rows_ = [rows_; row];
  endfor
  vrows = [];
  if (any (strcmp (opts.effects, "drift")))
    t0 = tic ();
    c = guarded ("drift", @() residtrace_cand_drift (cur, ctx));
    row = score (c, cur, ctx, e0);
    row.seconds = toc (t0);
    vrows = [vrows; row];
  endif
  ## coloured noise: only when nothing deterministic is significant and
  ## the residual is independent of the input but not white (the core's
  ## noise_gate)
  if (any (strcmp (opts.effects, "colored_noise")))
    c = guarded ("colored_noise", @() residtrace_cand_colored (cur, ctx));
    if (c.applicable)
      J = judge (rows_, vrows, opts);
      gate = struct ("significant", double (any (J.significant1)
                                            || any (J.significant2)),
                     "white_p", tests.white_p, "indep_p", tests.indep_p,
                     "alpha", opts.alpha);
      [c.applicable, why] = effect_sim_mex ("residtrace", "noise_gate", gate);
      if (! c.applicable)
        c.reason = why;
      endif
    endif
    row = score (c, cur, ctx, e0);
    vrows = [vrows; row];
  endif
  ## the pass judged by the core (judgement.hpp): each group's Bonferroni
  ## significance and ranking, the winner and its rivals
  J = judge (rows_, vrows, opts);
  r1 = judged (rows_, J.significant1, J.order1);
  r2 = judged (vrows, J.significant2, J.order2);
  ranking = [r1; r2];
  if (J.group == 1)
    winner = r1(1);
  elseif (J.group == 2)
    winner = r2(1);
  endif
  if (J.group > 0)
    winner.rivals = J.rivals;
  endif
endfunction

## The pass judged by the core (judgement.hpp, judge_pass): rows1 the
## candidates simulated from the input, rows2 those that use the
## validation output.
function J = judge (rows1, rows2, opts)
  J = effect_sim_mex ("residtrace", "judge", rows1, rows2,
                      struct ("alpha", opts.alpha,
                              "minscore", opts.minscore));
endfunction

## A group's rows with their significance, in the order of the ranking.
function r = judged (r, sig, order)
  if (isempty (r))
    return;
  endif
  sig = num2cell (sig);
  [r.significant] = sig{:};
  r = r(order);
endfunction

## A candidate fitted and scored in two stages (for speed): first
## with at most three SRIVC iterations per fit, each started from the
## current model (the one-step estimate from a consistent start is
## asymptotically as good as the iterated one), on at most the first
## 20 000 samples of the estimation record (the test is on the whole
## validation record, so its power is kept: the correction's estimate is
## only a little noisier); a candidate whose screened correction is far
## from significance (p >= 0.2, two hundred times the largest level a
## decision uses) without being clearly worse than the current model
## (score >= -5 minscore: a candidate that extends the model and scores
## far below it is a screening fit that has not converged), or whose
## terms lie within 1.5 standard deviations of
## zero on the estimation data (the candidates ask for 3), is reported
## so. Every other candidate, and one whose screening fit failed, is
## fitted again on the whole estimation record with the full iterations
## and scored on that fit: every decision is taken on converged fits.
## The row's field @code{screened} says which it was.
function row = screened_row (effect, cur, ctx, e0)
  t0 = tic ();
  row = screened_row_ (effect, cur, ctx, e0);
  row.seconds = toc (t0);
endfunction

function row = screened_row_ (effect, cur, ctx, e0)
  fn = ["residtrace_cand_" cand_file(effect)];
  if (biproper (cur) && any (strcmp (effect, fed_back_effects ())))
    c = residtrace_cand (effect);
    c.reason = ["not for a biproper model (direct feedthrough): the ", ...
                "effect is fed back from the output, which the ", ...
                "feedthrough would enter"];
    row = score (c, cur, ctx, e0);
    return;
  endif
  if (isfield (cur, "phys") && ! isempty (cur.phys)
      && ! strcmp (effect, "delay"))
    ## a physical realisation (end stop, cascade) holds its own levels
    ## and offsets, and no extra channel or output term: of the other
    ## effects only a delay has a meaning in it
    c = residtrace_cand (effect);
    c.reason = "the model's physical realisation does not hold it";
    row = score (c, cur, ctx, e0);
    return;
  endif
  if (ctx.maxiter > 3)
    [q, qcur] = screening_context (ctx, cur);
    c = guarded (effect, @() feval (fn, qcur, q));
    row = score (c, cur, ctx, e0);
    row.screened = true;
    if (row.applicable && row.p >= 0.2
        && row.score >= -5 * ctx.opts.minscore)
      return;
    endif
    if (! row.applicable && isfield (row.evidence, "tmax")
        && row.evidence.tmax < 1.5)
      return;                  # its terms are nowhere near significant
    endif
    if (! row.applicable
        && isempty (regexp (row.reason, ["estimation failed|not ", ...
                                          "significant on the estimation|", ...
                                          "not determined on the ", ...
                                          "estimation|", ...
                                          "validation failed|diverges"],
                            "once")))
      return;                  # not applicable for a structural reason
    endif
  endif
  c = guarded (effect, @() feval (fn, cur, ctx));
  row = score (c, cur, ctx, e0);
  row.screened = false;
endfunction

## A channel whose numerator has F's degree: a direct feedthrough.
function b = biproper (m)
  b = any ([m.channels.nb] > numel (m.F) - 1);
endfunction

## The effects simulated with the model's own output fed back (the
## sub-step simulator, residtrace_simulate): they need a strictly proper
## model. (Drift is tracked with the model's own structure; where its
## simulation needs the sub-step simulator, that says notSupported and
## the candidate is reported not tested, see guarded.)
function e = fed_back_effects ()
  e = {"coulomb", "state_nonlinearity"};
endfunction

## The screening's context: three iterations per fit, the estimation
## record cut to its first 20 000 samples (and the current model's
## estimation residual with it).
function [q, qcur] = screening_context (ctx, cur)
  q = ctx;
  q.maxiter = 3;
  qcur = cur;
  Nq = 20000;
  D = ctx.D;
  if (numel (D.y) <= Nq)
    return;
  endif
  k = 1:Nq;
  D.y = D.y(k); D.u = D.u(k, :); D.vhat = D.vhat(k, :); D.ysm = D.ysm(k);
  D.missing = D.missing(k);
  if (! isempty (D.loop))
    D.loop.r1 = D.loop.r1(k); D.loop.r2 = D.loop.r2(k);
  endif
  q.D = D;
  qcur.e_est = cur.e_est(k);
endfunction

function row = score (c, cur, ctx, e0)
  row = struct ("effect", c.effect, "score", NaN, "p", NaN, "stat", NaN,
                "p_dm", NaN,
                "significant", false, "variant", c.variant, "nadd", c.nadd,
                "rmse", NaN, "kind", c.kind, "applicable", c.applicable,
                "reason", c.reason, "evidence", c.evidence, "model", [],
                "e1", [], "rmse_tracked", NaN, "rmse_prediction", NaN,
                "screened", false, "seconds", NaN, "failed", c.failed,
                "group", ifelse_ (strcmp (c.kind, "simulation"),
                                  "simulated from the input",
                                  "uses the validation output"),
                "variants", {c.variants});
  row.evidence = unknown_std (row.evidence);
  if (! c.applicable)
    return;
  endif
  ## the one acceptance check of every candidate: its terms determined,
  ## the effect active on part of the record and not on all of it
  [ok, why, tmax] = residtrace_accept (c, cur, numel (ctx.D.y));
  if (isstruct (row.evidence))
    row.evidence.tmax = tmax;
  endif
  if (! ok)
    row.applicable = false;
    row.reason = why;
    return;
  endif
  try
    e1 = guarded ("", @() residtrace_valerror (c.model, ctx.V, ctx));
  catch err
    row.applicable = false;
    row.failed = true;
    row.reason = ["cannot test: validation failed: " err.message];
    return;
  end_try_catch
  if (any (! isfinite (e1)))
    row.applicable = false;
    row.reason = "the model's validation output diverges";
    return;
  endif
  ## the share of e0's mean square removed and the encompassing test's
  ## p-value (a correction fitted on the validation record itself: the
  ## likelihood-ratio test), by the core (judgement.hpp, score_candidate)
  v = effect_sim_mex ("residtrace", "score", e0(:), e1(:),
                      struct ("insample", double (c.insample),
                              "nadd", c.nadd));
  row.score = v(1);
  row.p = v(2);
  row.stat = v(3);
  row.p_dm = v(4);
  switch (c.kind)
    case "tracking"
      row.rmse_tracked = rms_ (e1);
    case "prediction"
      row.rmse_prediction = rms_ (e1);
    otherwise
      row.rmse = rms_ (e1);
  endswitch
  row.model = c.model;
  row.e1 = e1;
endfunction

## A standard deviation of exactly 0 in a candidate's evidence is not an
## estimate (a fit whose covariance was not computed): it becomes NaN,
## in evidence.std and in its text, and the text says why. Never a
## silent 0.
function ev = unknown_std (ev)
  if (! isstruct (ev) || ! isfield (ev, "std") || ! isnumeric (ev.std)
      || ! any (ev.std(:) == 0))
    return;
  endif
  ev.std(ev.std == 0) = NaN;
  if (isfield (ev, "text") && ischar (ev.text))
    t = regexprep (ev.text, '\+- -?0(?![\d.eE])', "+- NaN");
    do                                 # +- [0 0] -> +- [NaN NaN]
      t0 = t;
      t = regexprep (t, '(\+- \[(NaN )*)0(?=[ \]])', "$1NaN", "once");
    until (strcmp (t, t0))
    ev.text = [t "; standard deviation not available (the fit gave no " ...
               "covariance for it)"];
  endif
endfunction

## The numerical warnings that mean a result is not to be trusted (a
## solve with a singular matrix): raised as errors inside a candidate.
function ids = numerical_warnings ()
  ids = {"Octave:singular-matrix", "Octave:nearly-singular-matrix"};
endfunction

## f () (a candidate, or a validation simulation) with the numerical
## warnings raised as errors: a fit inside that catches its errors treats
## the solve as failed; one that reaches here gives, for a candidate
## (effect not empty), an explicit verdict "cannot test: ..." (a raw
## warning would print "matrix singular to machine precision" several
## times, e.g. for the drift candidate on a pendulum record); with effect
## "" the error
## is passed on (the caller says what failed). Never a raw warning.
function out = guarded (effect, f)
  ids = numerical_warnings ();
  state = warning ();
  unwind_protect
    for i = 1:numel (ids)
      warning ("error", ids{i});
    endfor
    try
      out = f ();
    catch err
      if (! isempty (effect)
          && strcmp (err.identifier, "residtrace:notSupported"))
        ## a structure the candidate cannot simulate: a verdict
        out = residtrace_cand (effect);
        out.reason = ["not supported: ", ...
                      regexprep(err.message, '^residtrace: ', '')];
        return;
      endif
      if (isempty (effect) || ! any (strcmp (err.identifier, ids)))
        rethrow (err);
      endif
      where = "";
      if (! isempty (err.stack))
        where = [" in " err.stack(1).name];
      endif
      out = residtrace_cand (effect);
      out.failed = true;
      out.reason = sprintf ("cannot test: numerical failure%s (%s)", where,
                            err.message);
    end_try_catch
  unwind_protect_cleanup
    warning (state);
  end_unwind_protect
endfunction

function f = cand_file (effect)
  switch (effect)
    case "static_nonlinearity"
      f = "static";
    case "state_nonlinearity"
      f = "state";
    case "initial_state"
      f = "x0";
    otherwise
      f = effect;
  endswitch
endfunction

function [D, V] = records (d, opts)
  D = struct ("y", d.y, "u", d.u, "Ts", d.Ts, "intersample", d.intersample,
              "loop", [], "vhat", [], "ysm", [], "pre", [],
              "missing", d.missing);
  if (isempty (opts.validation))
    N = numel (d.y);
    Ne = round (opts.split * N);
    V = D;
    V.y = d.y(Ne+1:end); V.u = d.u(Ne+1:end, :);
    V.missing = d.missing(Ne+1:end);
    V.pre = true;                     # filled once the velocity is known
    D.y = d.y(1:Ne); D.u = d.u(1:Ne, :); D.missing = d.missing(1:Ne);
    if (! isempty (opts.controller))
      error ("residtrace:badOption",
             "residtrace: a closed loop needs a separate validation record");
    endif
  else
    dv = opts.validation;
    try
      if (iscell (dv))
        [dv, mv] = contsid_getdata ("residtrace", dv{:});
      else
        [dv, mv] = contsid_getdata ("residtrace", dv);
      endif
      dv = residtrace_bridge (dv, mv);
    catch err
      rethrow_as (err);
    end_try_catch
    if (columns (dv.u) != columns (d.u))
      error ("residtrace:dimensionMismatch",
             ["residtrace: the validation record has %d input(s), the ", ...
              "estimation record %d"], columns (dv.u), columns (d.u));
    endif
    if (! dv.uniform)
      error ("residtrace:badInput",
             "residtrace: the validation data must be uniformly sampled");
    endif
    V = struct ("y", dv.y, "u", dv.u, "Ts", dv.Ts,
                "intersample", dv.intersample, "loop", [], "vhat", [],
                "ysm", [], "pre", [], "missing", dv.missing);
  endif
  if (! isempty (opts.controller))
    [num, den] = contsid_controller ("residtrace", opts.controller, d.Ts);
    D.loop = loop_of (num, den, opts.r1, opts.r2, numel (D.y), "r1", "r2");
    V.loop = loop_of (num, den, opts.r1v, opts.r2v, numel (V.y), "r1v",
                      "r2v");
  endif
endfunction

function L = loop_of (num, den, r1, r2, N, n1, n2)
  if (isempty (r1))
    error ("residtrace:badOption",
           "residtrace: a closed loop needs '%s' for each record", n1);
  endif
  if (isempty (r2))
    r2 = zeros (N, 1);
  endif
  if (! isnumeric (r1) || ! isnumeric (r2) || numel (r1) != N
      || numel (r2) != N || any (! isfinite ([r1(:); r2(:)])))
    error ("residtrace:dimensionMismatch",
           "residtrace: %s and %s must be finite with %d samples", n1, n2, N);
  endif
  L = struct ("num", num, "den", den, "r1", r1(:), "r2", r2(:));
endfunction

function opts = check_options (opts, all_effects)
  a = opts.alpha;
  if (! isnumeric (a) || ! isscalar (a) || ! (a > 0 && a < 0.5))
    error ("residtrace:badInput", "residtrace: alpha must lie in (0, 0.5)");
  endif
  for f = {"maxlag", "iterate", "substeps", "maxiter"}
    v = opts.(f{1});
    if (! isnumeric (v) || ! isscalar (v) || v != fix (v) || v < 1)
      error ("residtrace:badInput", "residtrace: %s must be an integer >= 1",
             f{1});
    endif
  endfor
  v = opts.maxdelay;
  if (! isnumeric (v) || ! isscalar (v) || v != fix (v) || v < 0)
    error ("residtrace:badInput",
           "residtrace: maxdelay must be an integer >= 0");
  endif
  s = opts.split;
  if (! isnumeric (s) || ! isscalar (s) || ! (s > 0.2 && s < 0.9))
    error ("residtrace:badInput", "residtrace: split must lie in (0.2, 0.9)");
  endif
  ms = opts.minscore;
  if (! isnumeric (ms) || ! isscalar (ms) || ! (ms >= 0 && ms < 1))
    error ("residtrace:badInput", "residtrace: minscore must lie in [0, 1)");
  endif
  e = opts.effects;
  if (ischar (e))
    e = {e};
  endif
  if (! iscellstr (e) || isempty (e))
    error ("residtrace:badOption",
           "residtrace: effects must be a cell of effect names");
  endif
  bad = setdiff (e, all_effects);
  if (! isempty (bad))
    error ("residtrace:badOption", "residtrace: unknown effect '%s'", bad{1});
  endif
  opts.effects = e;
  lv = opts.lambda_v;
  if (! isempty (lv) && (! isnumeric (lv) || ! isscalar (lv) || ! (lv > 0)))
    error ("residtrace:badInput", "residtrace: lambda_v must be > 0");
  endif
  if (! ischar (opts.levels)
      || ! any (strcmp (opts.levels, {"auto", "estimate", "none"})))
    error ("residtrace:badOption",
           "residtrace: levels must be 'auto', 'estimate' or 'none'");
  endif
  if (! (ischar (opts.table)))
    error ("residtrace:badInput", "residtrace: table must be a file name");
  endif
endfunction

## Levels of a raw record: with "auto", a model without integrators on a
## record whose input or output mean lies more than three standard
## deviations from zero (a record in raw units, not around its operating
## point); "estimate" always, "none" never. The input level removed is the
## one the given model was estimated with when it carries one
## (U_CARRIED, srivc's InputOffset on a raw record: the model starts at
## rest there, and that level fits the record's start, which a record
## need not begin at rest); otherwise the estimation record's first
## sample (the record starts at rest there). The output offset is
## estimated with the model.
function L = level_plan (D, Mst, mode, u_carried, c_carried)
  L = struct ("estimate", false, "u0", zeros (1, columns (D.u)),
              "why", "");
  carried = any (u_carried != 0) || c_carried != 0;
  switch (mode)
    case "none"
      return;
    case "estimate"
      L.estimate = true;
      L.why = "asked for";
    otherwise
      if (carried)
        ## M was estimated with levels removed (srivc on a raw record): its
        ## input level is removed here too and its output level estimated
        ## with the model (started from M's), so the baseline keeps what
        ## M has; with an integrator the output level is an initial
        ## condition the fit has already
        L.u0 = u_carried;
        L.estimate = Mst.F(end) != 0;
        L.why = ["the model carries the levels it was estimated with; ", ...
                 "the model's input level"];
        return;
      endif
      if (Mst.F(end) == 0)
        return;                     # an integrator: levels are initial states
      endif
      mu = mean (D.u, 1); su = std (D.u, 0, 1);
      raw_u = any (abs (mu) > 3 * su);
      raw_y = abs (mean (D.y)) > 3 * std (D.y);
      ## an output at rest at its first samples, away from zero, that
      ## never comes back to zero (a heated block: 22 degC at 0 W, its
      ## mean only 2.7 standard deviations from zero)
      [away, level] = contsid_start_level (D.y);
      y1 = D.y(1:min (5, numel (D.y)));
      span = max (D.y) - min (D.y);
      at_level = span > 0 && max (y1) - min (y1) <= 0.05 * span && away ...
                 && mean (sign (D.y) == sign (level)) >= 0.99;
      if (raw_u || raw_y)
        L.why = "the record is in raw units (means far from zero)";
      elseif (at_level)
        L.why = sprintf (["the output starts at rest at %.4g and keeps ", ...
                          "its sign"], level);
      else
        return;
      endif
      L.estimate = true;
  endswitch
  if (any (u_carried != 0))
    L.u0 = u_carried;             # the level the model was estimated with
    L.why = [L.why "; the model's input level"];
  else
    L.u0 = D.u(1, :);             # the record starts at rest at its first input
  endif
endfunction

function r = level_report (L, cur)
  r = struct ("estimated", L.estimate, "u0", L.u0, "y0", 0, "label", "",
              "text", "");
  if (! L.estimate && any (L.u0 != 0))
    r.text = sprintf (["levels handled (%s): input level %s removed ", ...
                       "from both records"], L.why, mat2str (L.u0, 4));
  endif
  if (! L.estimate || ! cur.ok)
    return;
  endif
  k = find (strcmp ({cur.out.type}, "offset"), 1);
  r.y0 = cur.out(k).c;
  r.label = ", levels estimated";
  r.text = sprintf (["levels handled (%s): input level %s removed from ", ...
                     "both records, output offset %.4g estimated with ", ...
                     "the model"], L.why, mat2str (L.u0, 4), r.y0);
endfunction

## Can the records tell anything? A constant input (or output) cannot.
function [ok, why] = excitation (D, V, np)
  ok = true; why = "";
  for rec = {D, V; "estimation", "validation"}
    Rr = rec{1};
    for j = 1:columns (Rr.u)
      u = Rr.u(:, j);
      if (max (u) - min (u) <= 1e-12 * max (abs (u)) || all (u == u(1)))
        ok = false;
        why = sprintf ("input %d of the %s record is constant", j, rec{2});
        return;
      endif
    endfor
    if (all (Rr.y == Rr.y(1)))
      ok = false;
      why = sprintf ("the output of the %s record is constant", rec{2});
      return;
    endif
  endfor
endfunction

function s = verdict_text (R, history)
  if (isempty (R.effects) && ! isempty (R.untested)
      && ! any (isfinite ([history(end).ranking.score])))
    s = "cannot tell: no candidate of the library could be tested";
  elseif (isempty (R.effects))
    s = "no effect of the library explains the residual";
    if (! isempty (R.untested))
      s = [s " among the candidates tested"];
    endif
  else
    s = ["found: " strjoin(R.effects, ", ")];
    if (! isempty (R.rivals))
      parts = {};
      for f = unique ({R.rivals.found}, "stable")
        k = strcmp ({R.rivals.found}, f{1});
        parts{end+1} = sprintf ("%s from %s", f{1},
                                strjoin ({R.rivals(k).effect}, ", "));
      endfor
      s = sprintf ("%s; not told apart by these data: %s", s,
                   strjoin (parts, "; "));
    endif
  endif
  if (! isempty (R.untested))
    s = sprintf ("%s; not tested%s, their estimation failed: %s", s,
                 ifelse_ (isempty (R.effects), "", " in the last pass"),
                 strjoin (R.untested, ", "));
  endif
  if (R.initial_state)
    s = [s "; the record did not start at rest: its initial state is " ...
         "estimated with the model (part of the baseline, not an effect)"];
  endif
  if (! isempty (R.levels.text))
    s = [s "; " R.levels.text];
  endif
endfunction

## M as given is stable when no pole lies in the open right half-plane
## (integrators and undamped pairs are allowed: they are structural).
function ok = stable_given (F)
  z = roots (F);
  ok = all (real (z) <= 1e-9 * max ([abs(z); 1]));
endfunction

function s = given_text (R)
  s = "";
  if (R.given_unstable)
    s = ["the given model is unstable (a pole in the right half-plane): ", ...
         "not simulated, the analysis starts from its re-estimate; "];
  endif
endfunction

function m = refresh_cov (base, cur)
  m = base;
  m.cov = NaN (numel (cur.theta));
  if (isequal (size (cur.theta), size (base.theta)) || isempty (base.theta))
    m.cov = cur.cov;
  endif
endfunction

## M read by contsid_model as the struct residtrace_base reads (B, F, nk,
## theta): continuous time, one output, one denominator.
function Mst = model_struct (M, Ts)
  m = contsid_model ("residtrace", M, Ts);
  if (! strcmp (m.kind, "tf") || m.ny != 1 || m.Ts > 0 || ! m.common)
    error ("residtrace:badInput",
           ["residtrace: M must be a continuous-time model with one ", ...
            "output and one denominator"]);
  endif
  if (m.nu < 1 || isempty (m.F) || isempty (m.B))
    error ("residtrace:badInput",
           ["residtrace: M has no input (a time-series model): there is ", ...
            "nothing to simulate from the input"]);
  endif
  B = m.B;
  if (numel (B) == 1)
    B = B{1};
  endif
  theta = m.theta;
  if (isempty (theta))
    theta = [m.F{1}(2:end), m.B{:}];
  endif
  Mst = struct ("B", {B}, "F", m.F{1}, "nk", m.nk, "theta", theta);
endfunction

## The model as returned to the user: an idtraced holding the struct,
## its linear part as an idctm with one input per channel, the levels and
## the physical reading.
function out = export_model (m, Ts, ex)
  out = rmfield (m, intersect (fieldnames (m), {"e_est", "variant_"}));
  ## what residtrace_sim needs to simulate it as residtrace scored it: the
  ## input level removed from the records, how the validation record was
  ## formed, a closed loop; and the physical reading with uncertainties
  out.u0 = ex.u0;
  out.npre = ex.npre;
  out.closed_loop = ex.closed;
  out.substeps = ex.substeps;
  out.params = residtrace_physical (m, Ts);
  B = {m.channels.B};
  F = m.F;
  if (numel (B) == 1)
    B = B{1};
  endif
  lin = struct ("B", {B}, "F", F, "nk", [m.channels.nk], "Ts", Ts,
                "InterSample", m.intersample, "theta", m.theta(:).',
                "covariance", m.cov, "noise_variance", m.s2,
                "method", "residtrace");
  try
    out.linear = idctm (lin);
  catch err
    if (isempty (strfind (err.message, "covariance")))
      rethrow (err);
    endif
    ## The fit's covariance is not positive semi-definite (a direction the
    ## data do not determine): the linear part is returned without one.
    lin.covariance = [];
    out.linear = idctm (lin);
  end_try_catch
  out = idtraced (out);
endfunction

function s = step_row (label, e, y, tests, kind, params)
  s = struct ("label", label, "rmse", rms_ (e), "rmse_other", NaN,
              "kind", kind,
              "fit", fit_ (y, e), "white_p", tests.white_p,
              "indep_p", tests.indep_p, "params", {params});
endfunction

function s = kind_text (kind)
  switch (kind)
    case "prediction"
      s = "one-step prediction";
    case "tracking"
      s = "simulation with tracked parameters";
    otherwise
      s = "simulation";
  endswitch
endfunction

function print_ranking (pass, r)
  printf ("residtrace pass %d:\n", pass);
  for k = 1:numel (r)
    if (r(k).applicable)
      printf ("  %-20s score %9.4g  p %8.2g  %s  %s (%.1f s%s)\n",
              r(k).effect, r(k).score, r(k).p,
              ifelse_ (r(k).significant, "*", " "), r(k).variant,
              r(k).seconds, ifelse_ (r(k).screened, ", screened", ""));
    else
      printf ("  %-20s (not tested: %s) (%.1f s)\n", r(k).effect,
              r(k).reason, r(k).seconds);
    endif
  endfor
endfunction

function s = ifelse_ (c, a, b)
  if (c)
    s = a;
  else
    s = b;
  endif
endfunction

## The mask of the validation record's missing samples (bridged, see
## residtrace_bridge), which every figure leaves out: set once per call.
function m = vmask (set)
  persistent mask = [];
  if (nargin > 0)
    mask = set;
  endif
  m = mask;
endfunction

function x = present_ (x)
  m = vmask ();
  if (numel (m) == numel (x) && any (m))
    x = x(! m);
  endif
endfunction

function v = rms_ (e)
  e = present_ (e);
  v = sqrt (mean (e .^ 2));
endfunction

function f = fit_ (y, e)
  y = present_ (y); e = present_ (e);
  f = 100 * (1 - norm (e) / norm (y - mean (y)));
endfunction

function rethrow_as (err)
  id = regexprep (err.identifier, '^[^:]*:', 'residtrace:');
  msg = regexprep (err.message, '^[^:]*:', 'residtrace:');
  error (struct ("message", msg, "identifier", id));
endfunction

%!shared Ts, u, uv, G, N, x, xv
%! Ts = 0.05; u = prbs (9, 4); N = numel (u);
%! uv = circshift (u, 200);
%! G = idctm (2, [1 1.2 1]);
%! x = simc (G, u, Ts); xv = simc (G, uv, Ts);

%!test  # an undeclared input offset: found, sized, RMSE cut, table written
%! randn ("state", 11);
%! y = simc (G, u + 0.3, Ts) + 0.05 * randn (N, 1);
%! yv = simc (G, uv + 0.3, Ts) + 0.05 * randn (N, 1);
%! M = srivc (iddata (y, u, Ts), [1 2 0]);
%! ## srivc has estimated the input level: M has the offset, and it is
%! ## kept, not found again
%! assert (get (M, "Report").DataUsed.InputOffset, -0.3, 0.02);
%! R = residtrace (iddata (y, u, Ts), M, "validation", iddata (yv, uv, Ts),
%!                 "effects", {"offset", "delay", "order"});
%! assert (R.effect, "none");
%! assert (R.rmse_before, R.rmse_given, 0.05 * R.rmse_given);
%! ## the same dynamics without the level: the offset is the effect
%! M = idctm (M.B, M.F);
%! f = [tempname() ".md"];
%! R = residtrace (iddata (y, u, Ts), M, "validation", iddata (yv, uv, Ts),
%!                 "effects", {"offset", "delay", "order"}, "table", f);
%! assert (R.effect, "offset");
%! assert (R.evidence.physical, 0.3, 5 * R.evidence.physical_std + 0.01);
%! assert (R.rmse_after < 0.2 * R.rmse_before);
%! assert (R.rmse_after, 0.05, 0.01);        # down to the noise level
%! assert (R.ranking(1).significant);
%! assert (isa (R.model.linear, "idpoly"));
%! md = fileread (f);
%! delete (f);
%! assert (! isempty (strfind (md, "| + offset (input offset) |")));
%! assert (! isempty (strfind (md, "input offset b_c/b0")));

%!test  # no validation record: the last third validates; clean data: none
%! randn ("state", 12);
%! y = x + 0.05 * randn (N, 1);
%! M = srivc (iddata (y, u, Ts), [1 2 0]);
%! R = residtrace (iddata (y, u, Ts), M, "effects", {"offset", "delay"});
%! assert (R.effect, "none");
%! assert (R.rmse_after, R.rmse_before);
%! assert (R.testable);
%! assert (R.rmse_before, 0.05, 0.01);   # the split record starts mid-run

%!test  # a delay, numeric data form, and the scores' definition
%! randn ("state", 13);
%! y = [zeros(3, 1); x(1:end-3)] + 0.05 * randn (N, 1);
%! yv = [zeros(3, 1); xv(1:end-3)] + 0.05 * randn (N, 1);
%! M = srivc (iddata (y, u, Ts), [1 2 0]);
%! R = residtrace (y, u, Ts, M, "validation", {yv, uv, Ts},
%!                 "effects", {"delay", "offset"}, "iterate", 1);
%! assert (R.effect, "delay");
%! assert (R.evidence.value, 3);
%! r = R.ranking(1);
%! assert (r.score, 1 - r.rmse ^ 2 / R.rmse_refit ^ 2, 1e-12);

%!test  # a perfect model: nothing to test, said so
%! R = residtrace (iddata (x, u, Ts), G, "validation", iddata (xv, uv, Ts));
%! assert (R.effect, "none");
%! assert (! R.testable);
%! assert (! isempty (R.reason));

%!test  # an unstable model as given: said so, not simulated, refit helps
%! randn ("state", 14);
%! y = x + 0.05 * randn (N, 1);
%! R = residtrace (iddata (y, u, Ts), idctm (2, [1 -0.5 1]),
%!                 "effects", {"offset"});
%! assert (R.given_unstable);
%! assert (isnan (R.rmse_given));
%! assert (strncmp (R.verdict, "the given model is unstable", 27));
%! assert (R.rmse_before < 0.1);
%! assert (R.rmse_refit, R.rmse_before);
%! R = residtrace (iddata (y, u, Ts), idctm (2, [1 -30 1]),
%!                 "effects", {"offset"});
%! assert (isnan (R.rmse_given));
%! assert (R.rmse_before < 0.1);

%!test  # raw units: levels estimated and said; the baseline is the re-fit
%! randn ("state", 15);
%! y = 20 + simc (G, u - u(1), Ts) + 0.05 * randn (N, 1); # at rest at u(1)
%! yv = 20 + simc (G, uv - u(1), Ts) + 0.05 * randn (N, 1);
%! R = residtrace (iddata (y, u + 5, Ts), idctm (2, [1 1.2 1]),
%!                 "validation", iddata (yv, uv + 5, Ts),
%!                 "effects", {"offset", "saturation"});
%! assert (R.levels.estimated);
%! assert (! isempty (strfind (R.levels.text, "raw units")));
%! assert (R.effect, "none");
%! assert (R.rmse_before < 0.07);      # the noise level, levels handled
%! assert (R.rmse_given > 1);          # M as given ignores the levels
%! ## srivc's model carries the levels it estimated: its figure is that of
%! ## the model with them (without them: 180 deg off)
%! y = 20 + simc (G, u, Ts) + 0.05 * randn (N, 1);
%! yv = 20 + simc (G, uv, Ts) + 0.05 * randn (N, 1);
%! Ms = srivc (iddata (y, u, Ts), [1 2 0]);
%! lv = get (Ms, "Report").DataUsed;
%! assert (lv.OutputOffset, 20, 0.05);
%! R = residtrace (iddata (y, u, Ts), Ms, "validation", iddata (yv, uv, Ts),
%!                 "effects", {"offset"});
%! ys = simc (Ms, uv - lv.InputOffset, Ts, "Levels", "ignore") ...
%!      + lv.OutputOffset;
%! assert (R.rmse_given, sqrt (mean ((yv - ys) .^ 2)), 1e-9);
%! assert (R.rmse_given < 0.06);       # the noise level (0.05)

%!test  # the input level the model carries is the one removed: a record
%! ## that does not start at rest at its first input (as a simulated
%! ## cascaded-tanks record: started at rest at u(1), the re-estimate of
%! ## srivc's model would be 6 times worse than the model; here 0.55
%! ## against 0.05)
%! randn ("state", 19);
%! y = 20 + simc (G, 3 * u, Ts) + 0.05 * randn (N, 1);  # at rest at 5
%! yv = 20 + simc (G, 3 * uv, Ts) + 0.05 * randn (N, 1);
%! Mt = G;                                 # the true model, with its levels
%! r = get (Mt, "Report");
%! r.DataUsed.OutputOffset = 20;
%! r.DataUsed.InputOffset = 5;
%! Mt.Report = r;
%! assert (5 + 3 * u(1) != 5);             # the record starts off its rest
%! R = residtrace (iddata (y, 5 + 3 * u, Ts), Mt,
%!                 "validation", iddata (yv, 5 + 3 * uv, Ts),
%!                 "effects", {"offset"});
%! assert (R.levels.u0, 5);
%! assert (! isempty (strfind (R.levels.text, "the model's input level")));
%! assert (R.rmse_given < 0.06);           # the noise level (0.05)
%! assert (R.rmse_before < 0.06);

%!test  # an output that starts at rest at its ambient level: levels
%! ## handled although the output's mean is within 3 sd of zero (as a
%! ## heated block: 22 degC at 0 W, mean 2.7 sd from zero)
%! randn ("state", 18);
%! t = (0:N-1)' * Ts;                      # 0 / 50 W, from 0 W
%! ue = 50 * (sin (2 * pi * t / 20 - 0.2) > 0);
%! uve = 50 * (sin (2 * pi * t / 27 - 0.2) > 0);
%! y = 22 + simc (G, ue, Ts) + 0.05 * randn (N, 1);
%! yv = 22 + simc (G, uve, Ts) + 0.05 * randn (N, 1);
%! assert (abs (mean (y)) < 3 * std (y));   # the mean rule does not fire
%! R = residtrace (iddata (y, ue, Ts), idctm (2, [1 1.2 1]),
%!                 "validation", iddata (yv, uve, Ts),
%!                 "effects", {"offset", "initial_state"});
%! assert (R.levels.estimated);
%! assert (! isempty (strfind (R.levels.text, "starts at rest at 22")));
%! assert (R.levels.y0, 22, 0.1);
%! assert (R.effect, "none");
%! assert (R.rmse_before < 0.07);          # the noise level (0.05)

%!test  # a line slower than two cycles of the record is not a sinusoid
%! ## (0.00014 Hz, under one cycle of a heated block's record, must not
%! ## be named)
%! randn ("state", 17);
%! T = N * Ts;
%! slow = @(t) 0.3 * sin (2 * pi * t / (0.8 * T) + 0.5);   # 1.25 cycles
%! t = (0:N-1)' * Ts;
%! y = x + slow (t) + 0.02 * randn (N, 1);
%! yv = xv + slow (t) + 0.02 * randn (N, 1);
%! R = residtrace (iddata (y, u, Ts), G, "validation", iddata (yv, uv, Ts),
%!                 "effects", {"sinusoid"}, "iterate", 1);
%! r = R.ranking(1);
%! assert (! r.applicable || r.evidence.freq_hz * T >= 2 - 1e-9);
%! ## a line of three cycles is still one
%! y = x + 0.3 * sin (2 * pi * 3 * t / T) + 0.02 * randn (N, 1);
%! yv = xv + 0.3 * sin (2 * pi * 3 * t / T + 1) + 0.02 * randn (N, 1);
%! R = residtrace (iddata (y, u, Ts), G, "validation", iddata (yv, uv, Ts),
%!                 "effects", {"sinusoid"}, "iterate", 1);
%! assert (R.effect, "sinusoid");
%! assert (R.ranking(1).evidence.freq_hz * T, 3, 0.2);   # a fifth of a bin

%!test  # an output that saturates: level estimated
%! randn ("state", 16);
%! y = min (simc (G, u, Ts), 0.4) + 0.03 * randn (N, 1);
%! yv = min (simc (G, uv, Ts), 0.4) + 0.03 * randn (N, 1);
%! M = srivc (iddata (y, u, Ts), [1 2 0]);
%! R = residtrace (iddata (y, u, Ts), M, "validation", iddata (yv, uv, Ts),
%!                 "effects", {"saturation", "offset"}, "iterate", 1);
%! assert (R.effect, "saturation");
%! assert (R.evidence.value(2), 0.4, 0.02);
%! assert (R.rmse_after < 0.5 * R.rmse_before);

%!function y = residtrace_test_act (u, Tn)
%! ## an actuator z' = (u - z)/1.5 limited to [0, 100], then
%! ## T' = (0.4 z - T)/20, y = 10 + T, at rest at u(1)
%! h = Tn / 10; z = min (max (u(1), 0), 100); T = 0.4 * z;
%! y = zeros (numel (u), 1);
%! for k = 1:numel (u)
%!   y(k) = 10 + T;
%!   for s = 1:10
%!     z = min (max (z + h * (u(k) - z) / 1.5, 0), 100);
%!     T += h * (0.4 * z - T) / 20;
%!   endfor
%! endfor
%!endfunction

%!test  # an actuator at its end stops: an inner node's saturation
%! ## (a node variant's numerator started at zero would fail in the
%! ## engine, and the input polynomial would win, as on a flow-loop valve)
%! randn ("state", 19); rand ("state", 19);
%! Tn = 0.5;
%! lev = @() kron (rand (75, 1) * 160 - 30, ones (40, 1));
%! ua = lev (); uva = lev ();   # not the shared u, uv
%! ya = residtrace_test_act (ua, Tn) + 0.1 * randn (3000, 1);
%! yva = residtrace_test_act (uva, Tn) + 0.1 * randn (3000, 1);
%! M = srivc (iddata (ya - mean (ya), ua - mean (ua), Tn), [1 2 0]);
%! R = residtrace (iddata (ya, ua, Tn), M, "validation", iddata (yva, uva, Tn),
%!                 "iterate", 1, "levels", "estimate",
%!                 "effects", {"saturation", "static_nonlinearity"});
%! assert (R.effect, "saturation");
%! assert (! isempty (strfind (R.ranking(1).variant, "inner node")));
%! assert (R.rmse_after < 0.8 * R.rmse_before);

%!test  # a square-root outflow (a tank): a state nonlinearity
%! randn ("state", 17); rand ("state", 17);
%! Tt = 1; q = 1 + 3 * (prbs (9, 20) > 0) .* rand (numel (prbs (9, 20)), 1);
%! Nq = numel (q); h = zeros (Nq, 1); z = (q(1) / 0.8) ^ 2;
%! for k = 1:Nq
%!   h(k) = z;
%!   for s = 1:10
%!     z += 0.1 * (q(k) - 0.8 * sqrt (z)) / 2;
%!   endfor
%! endfor
%! y = h + 0.05 * randn (Nq, 1);
%! n2 = floor (Nq / 2);
%! d = iddata (y(1:n2), q(1:n2), Tt); dv = iddata (y(n2+1:end), q(n2+1:end), Tt);
%! M = srivc (iddata (y(1:n2) - mean (y(1:n2)), q(1:n2) - mean (q(1:n2)), Tt),
%!            [1 1 0]);
%! R = residtrace (d, M, "validation", dv, "iterate", 1, "levels", "estimate",
%!                 "effects", {"state_nonlinearity", "order", "offset"});
%! assert (R.effect, "state_nonlinearity");  # sqrt(y) or a power of y:
%! ## over one operating range BIC may prefer y^2 to the square root
%! assert (R.rmse_after < 0.5 * R.rmse_before);

%!test  # a record that did not start at rest: the initial state
%! randn ("state", 18);
%! y0 = [3; -2];                        # observable-form initial state
%! F = [1 1.2 1];
%! E = expm ([-F(2:3)', [1; 0]] * Ts);
%! f = zeros (N, 1); z = y0;
%! for k = 1:N
%!   f(k) = z(1); z = E * z;
%! endfor
%! y = simc (G, u, Ts) + f + 0.03 * randn (N, 1);
%! yv = simc (G, uv, Ts) + f + 0.03 * randn (N, 1);
%! R = residtrace (iddata (y, u, Ts), idctm (2, F), "validation",
%!                 iddata (yv, uv, Ts), "effects", {"initial_state", "delay"},
%!                 "iterate", 1);
%! ## part of the baseline, never an effect
%! assert (R.effect, "none");
%! assert (R.initial_state);
%! assert (isempty (R.effects));
%! assert (! isempty (strfind (R.verdict, "did not start at rest")));
%! assert (R.rmse_before < 0.5 * R.rmse_refit);
%! assert (R.rmse_after, R.rmse_before, 1e-12);
%! ## not down to the noise (0.03): the estimation fit has no initial state
%! ## of its own, so the start transient biases the re-estimated model

%!test  # a pure output offset scores (the test keeps the means)
%! randn ("state", 19);
%! y = x + 0.3 + 0.05 * randn (N, 1);
%! yv = xv + 0.3 + 0.05 * randn (N, 1);
%! R = residtrace (iddata (y, u, Ts), G, "validation", iddata (yv, uv, Ts),
%!                 "effects", {"offset"}, "iterate", 1);
%! assert (R.effect, "offset");
%! assert (R.ranking(1).p < 1e-6);

%!test  # Coulomb with a two-level input through a fast velocity: sign(v)
%! ## follows sign(u), the friction is a lower gain: not identifiable
%! randn ("state", 20);
%! ub = prbs (6, 60); Nb = numel (ub); Tb = 0.01; v = zeros (Nb, 1); w = 0;
%! for k = 1:Nb
%!   v(k) = w;
%!   for s = 1:10
%!     w += Tb / 10 * (-50 * w + 100 * ub(k) - 20 * sign (w));
%!   endfor
%! endfor
%! y = v + 0.01 * randn (Nb, 1);
%! yv = circshift (v, 300) + 0.01 * randn (Nb, 1);
%! M = srivc (iddata (y, ub, Tb), [1 1 0]);
%! R = residtrace (iddata (y, ub, Tb), M, "validation",
%!                 iddata (yv, circshift (ub, 300), Tb),
%!                 "effects", {"coulomb"}, "iterate", 1);
%! assert (R.effect, "none");
%! assert (strfind (R.ranking(1).reason, "not identifiable") > 0);

%!error id=residtrace:badInput residtrace (iddata (x, u, Ts))
%!error id=residtrace:badInput residtrace (iddata (x, u, Ts), idss (-1, 1, 1, 0))
%!error id=residtrace:badInput residtrace (iddata (x, u, Ts), iddata (x, u, Ts))
%!error id=residtrace:badInput residtrace (iddata (x, u, Ts), struct ("B", 1, "F", [1 1]))
%!error id=residtrace:badInput residtrace (iddata (NaN (N, 1), u, Ts), G)
%!error id=residtrace:badInput residtrace (iddata (x(1:60), u(1:60), Ts), G)
%!error id=residtrace:badInput residtrace (iddata (x, u, Ts), G, "validation", iddata (xv(1:60), uv(1:60), Ts))
%!error id=residtrace:badInput residtrace (iddata (x, u, Ts), G, "maxlag", 0)
%!error id=residtrace:badInput residtrace (iddata (x, u, Ts), G, "alpha", 2)
%!error id=residtrace:badInput residtrace (iddata (x, u, Ts), G, "split", 1)
%!error id=residtrace:badInput residtrace (iddata (x, u, Ts), G, "iterate", 0)
%!error id=residtrace:badInput residtrace (iddata (x, u, Ts), G, "minscore", -1)
%!error id=residtrace:badInput residtrace (iddata (x, u, Ts), G, "maxdelay", -1)
%!error id=residtrace:badInput residtrace (iddata (x, u, Ts), G, "lambda_v", 0)
%!error id=residtrace:badInput residtrace (iddata (x, u, Ts), G, "table", 3)
%!error id=residtrace:badInput residtrace (iddata (x, u, (0:N-1)' .^ 1.01 * Ts), G)
%!error id=residtrace:dimensionMismatch residtrace (iddata (x, u, Ts), G, "validation", iddata (xv, [uv uv], Ts))
%!error id=residtrace:dimensionMismatch residtrace (iddata (x, [u u], Ts), G)
%!error id=residtrace:badOption residtrace (iddata (x, u, Ts), G, "effects", {"magic"})
%!error id=residtrace:badOption residtrace (iddata (x, u, Ts), G, "effects", 3)
%!error id=residtrace:badOption residtrace (iddata (x, u, Ts), G, "bogus", 1)
%!error id=residtrace:badOption residtrace (iddata (x, u, Ts), G, "levels", "raw")
%!error id=residtrace:badOption residtrace (iddata (x, u, Ts), G, "controller", struct ("kp", 1, "ki", 0, "kd", 0))
%!error id=residtrace:badOption residtrace (iddata (x, u, Ts), G, "validation", {xv, uv, Ts}, "controller", struct ("kp", 1, "ki", 0, "kd", 0))
%!error id=residtrace:dimensionMismatch residtrace (iddata (x, u, Ts), G, "validation", {xv, uv, Ts}, "controller", struct ("kp", 1, "ki", 0, "kd", 0), "r1", 1, "r1v", uv)
%!error id=residtrace:numericalFailure residtrace (iddata (x, zeros (N, 1), Ts), G)

%!demo
%! ## A mass-spring-damper with Coulomb friction 0.3, modelled as linear:
%! ## residtrace finds the friction, adds sign(v) and simulates it.
%! Ts = 0.02; N = 2000; t = (0:N-1)' * Ts;
%! U = [sin(1.3 * t) + 0.5 * sin(3.1 * t + 1), ...
%!      sin(1.1 * t + 2) + 0.6 * sin(2.7 * t)];
%! A = [0 1; -4 -0.8]; E = expm ([A, [0; 1]; 0 0 0] * Ts / 20);
%! Y = zeros (N, 2);
%! for j = 1:2                  # 20 sub-steps per sample, sign(v) held
%!   z = [0; 0];
%!   for k = 1:N
%!     Y(k, j) = z(1);
%!     for s = 1:20
%!       z = E(1:2, 1:2) * z + E(1:2, 3) * (U(k, j) - 0.3 * sign (z(2)));
%!     endfor
%!   endfor
%! endfor
%! Y += 0.005 * randn (N, 2);
%! data = iddata (Y(:, 1), U(:, 1), Ts);
%! M = srivc (data, [1 2 0]);
%! R = residtrace (data, M, "validation", iddata (Y(:, 2), U(:, 2), Ts));
%! residtrace_table (R)
