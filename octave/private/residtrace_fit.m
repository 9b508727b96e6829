## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn {} {@var{model} =} residtrace_fit (@var{tmpl}, @var{D}, @var{ctx}, @var{starts})
## Estimates the parameters of the @code{residtrace} model structure
## @var{tmpl} on the record @var{D} (fields y, u, Ts, vhat: the velocity
## from the measured output; optional initial_state: true for a record
## that does not start at rest, whose initial state is then estimated
## with the model; optional missing: the mask of bridged samples, which
## carry no error) by SRIVC, the toolbox's refined-IV engine. The fit
## runs in the core (core/include/ctid/apps/residtrace/structure_fit.hpp,
## fit_structure, through @code{effect_sim_mex}); this function adds the
## refits around it described below.
##
## The channels (inputs, constant, sign of the velocity, powers, clipped
## input) are the regressors of the filtered linear regression; the
## coefficients of F that are fixed in @code{tmpl.fixed} keep their
## values. The record's output level (the first offset term when
## @code{tmpl.levels} is true) is estimated jointly with the model by the
## engine. Other output terms (an output offset, a polynomial in the model
## output, a sinusoid) enter by alternation: SRIVC on y minus the terms,
## then the terms by least squares on y minus the model output, three
## rounds. An output saturation (term @qcode{"sat"}, its levels fixed by
## the caller) is fitted as censored data: where the model output lies
## beyond a level, the measurement carries no information on the linear
## part, so SRIVC sees the model's own output there (imputation) and the
## other terms are fitted on the samples within the levels.
## @var{starts}: a cell of initial denominators (each of the template's
## order, started with the template's numerators; an empty entry is the
## engine's automatic start, tried only when no given start gives a stable
## estimate); the start giving the smallest residual variance is kept.
##
## Adds to the model: @code{theta}, @code{cov} (SRIVC covariance of the
## dynamic parameters), @code{out(k).c} with @code{out(k).cstd},
## @code{s2}, @code{np} (number of estimated parameters), @code{bic} =
## N log s2 + np log N, @code{ok}. Starts that end on an unstable F
## (apart from the model's integrators) are discarded. A real pole p of
## the fit with p Ts > 1000 (a mode gone within a sampling interval, which
## the samples cannot tell from an infinitely fast one) is residualised
## and the model fitted again in the order without it (see
## @code{residualised} below): the returned model may have a lower order
## than @var{tmpl}; not with @code{ctx.keep_order} true (the re-estimates
## of the current model in its own structure). A model with a
## physical realisation (@code{tmpl.phys}) is fitted by
## @code{residtrace_physfit} instead (simulation error).
## @end deftypefn

function model = residtrace_fit (tmpl, D, ctx, starts)
  model = tmpl;
  if (isfield (model, "nlin"))
    model = rmfield (model, "nlin");   # a Hammerstein fit's, now stale
  endif
  if (isfield (tmpl, "phys") && ! isempty (tmpl.phys))
    ## a physical realisation: fitted on its simulation error
    model = residtrace_physfit (tmpl, D, ctx);
    return;
  endif
  ## the fit itself: core/include/ctid/apps/residtrace/structure_fit.hpp
  o = residtrace_channels (tmpl.channels);
  o.B = {tmpl.channels.B};
  kinds = {"offset", "poly", "sinusoid", "sat"};
  o.out_kind = zeros (1, numel (tmpl.out));
  for k = 1:numel (tmpl.out)
    o.out_kind(k) = find (strcmp (kinds, tmpl.out(k).type)) - 1;
  endfor
  o.out_c = {tmpl.out.c};
  o.out_omega = [tmpl.out.omega];
  o.ts = D.Ts;
  o.rule = lower (D.intersample);
  o.vhat = D.vhat;
  o.ysm = D.ysm;
  o.initial_state = isfield (D, "initial_state") && D.initial_state;
  if (isfield (D, "missing") && numel (D.missing) == numel (D.y))
    o.missing = double (D.missing(:));
  endif
  o.F = tmpl.F;
  o.fixed = double (tmpl.fixed);
  o.levels = isfield (tmpl, "levels") && tmpl.levels;
  o.starts = starts;
  o.maxiter = ctx.maxiter;
  r = effect_sim_mex ("residtrace", "fit", D.u, D.y, o);
  if (! r.ok)
    model.ok = false;
    if (r.failed_round == 1
        && ! (isfield (ctx, "keep_order") && ctx.keep_order))
      model = refit_without_fast_poles (tmpl, D, ctx, model);
    endif
    return;
  endif
  for k = find (r.out_fitted)
    model.out(k).c = r.out_c{k};
    model.out(k).cstd = r.out_cstd{k};
  endfor
  model.F = r.F;
  for j = 1:numel (model.channels)
    model.channels(j).B = r.B{j};
  endfor
  model.np = r.np;
  model.s2 = r.s2;
  model.theta = r.theta;
  model.cov = r.cov;
  model.bic = r.bic;
  model.e_est = r.e;
  model.ok = true;
  if (! (isfield (ctx, "keep_order") && ctx.keep_order))
    red = residualised (model, D.Ts);
    if (! isempty (red))
      ## a pole beyond what the samples can see: the fit is repeated in the
      ## structure without it, started from the residualised model
      m = residtrace_fit (red, D, ctx, {red.F});
      if (m.ok)
        model = m;
        return;
      endif
    endif
  endif
  if (any (strcmp ({tmpl.channels.type}, "ypower"))
      && ! (isfield (ctx, "ysim_") && ctx.ysim_))
    model = refit_simulated (model, D, ctx);
  endif
endfunction

## A function of the output inside the dynamics (a "ypower" channel) is
## first fitted with the measured output as its signal. The engine then
## integrates that signal open loop: its noise, and the error of a start
## from rest, are integrated too, which a model with little damping of its
## own (a tank whose outflow is its only damping, F(0) = 0 with a
## sqrt(y) term) cannot forget, so the fit keeps a spurious damping and
## its loss is not the loss of the model as residtrace simulates and
## scores it (its own output fed back). Here the signal is the model's
## simulated output (plus its free response when the initial state is
## estimated, as residtrace_valerror does), the model is fitted again,
## and so on while the simulation error on the estimation record falls
## (at most three rounds); the residual variance and BIC are then those of
## that simulation, for every variant of the candidate alike.
function model = refit_simulated (model, D, ctx)
  ctx.ysim_ = true;
  x0 = isfield (D, "initial_state") && D.initial_state;
  [e, yh] = sim_error (model, D, ctx, x0);
  s = sum (e .^ 2);
  for round = 1:3
    if (! isfinite (s))
      break;
    endif
    Dk = D;
    Dk.ysm = yh;
    m = residtrace_fit (model, Dk, ctx, {model.F});
    if (! m.ok)
      break;
    endif
    [e2, yh2] = sim_error (m, D, ctx, x0);
    s2 = sum (e2 .^ 2);
    if (! (s2 < s))
      break;
    endif
    model = m;
    e = e2; yh = yh2; s = s2;
  endfor
  if (! isfinite (s))
    model.ok = false;
    return;
  endif
  N = numel (D.y);
  model.s2 = s / max (N - model.np, 1);
  model.bic = N * log (model.s2) + model.np * log (N);
  model.e_est = e;
endfunction

## The model simulated on the estimation record (its own output fed back),
## with its free response fitted when the initial state is estimated.
function [e, yh] = sim_error (model, D, ctx, x0)
  try
    yh = residtrace_simulate (model, D.u, D.Ts, D.loop, ctx.opts.substeps);
  catch
    yh = Inf (size (D.y));
  end_try_catch
  e = D.y - yh;
  if (x0 && all (isfinite (e)))
    X = residtrace_free (model.F, numel (e), D.Ts);
    f = X * (X \ e);
    yh += f;
    e -= f;
  endif
  if (! all (isfinite (e)))
    e = Inf (size (D.y));
  elseif (isfield (D, "missing") && numel (D.missing) == numel (e))
    e(D.missing) = 0;          # bridged samples carry no error
  endif
endfunction

## A real pole p with p Ts > 1000 decays by e^-1000 over one sampling
## interval: the samples cannot tell it from an infinitely fast one (its
## in-band effect is a relative change of at most pi / (p Ts) < 0.3 %,
## which the refit absorbs). A fit whose loss is flat in that direction
## lets such a pole run off (Silverbox: the order candidate's
## pole at -2484 rad/s went to -5.8e10 when the cubic spring was added,
## F = [1 5.8e10 2.8e12 1.1e16]), and the companion-form realisation the
## simulator and the free responses use is then so ill conditioned that
## its simulation is wrong (validation RMSE 0.0101 V with 10 sub-steps,
## 0.0103 with 40, 0.0082 with the pole removed) and every fit started
## from it fails. Such poles are residualised (singular perturbation: the
## mode at its steady state, F / (p + s) -> F / p, each numerator divided
## by p) when every channel stays strictly proper; returns the reduced
## template, or [] when there is nothing to remove. The fixed
## coefficients of F other than its integrators lose their meaning in the
## reduced order and are freed. Not for the re-estimates of the current
## model in its own structure (ctx.keep_order, set by residtrace): its
## order is the user's, and a pole that the re-estimate without an
## initial state runs off is needed back by the refit with it (a
## simulated two-tank record). Bringing the pole back to p Ts = 1000
## instead of removing it does worse: on the Silverbox the fits from there
## chose y^3 and an output offset, 0.0069 V after three effects against
## 0.0063.
##
## With @var{limit} and @var{trim} (the retry of a fit that failed from
## every start, see @code{refit_without_fast_poles}): the poles with p Ts
## > @var{limit}, and a numerator that would no longer be strictly proper
## is cut to its nn lowest-order coefficients (the in-band part: its
## static gain and low-frequency terms; the fit re-estimates them all).
function red = residualised (model, Ts, limit = 1000, trim = false)
  red = [];
  F = model.F / model.F(1);
  n = numel (F) - 1;
  z = roots (F);
  fast = imag (z) == 0 & -real (z) * Ts > limit;
  nn = n - sum (fast);
  if (! any (fast) || nn < 1 || (! trim && any ([model.channels.nb] > nn)))
    return;
  endif
  r = 0;
  while (r < n && model.fixed(n-r) && F(n-r+1) == 0)
    r++;
  endwhile
  if (nn < r)
    return;
  endif
  red = model;
  red.F = real (poly (z(! fast)));
  red.F(end-r+1:end) = 0;
  red.fixed = false (1, nn);
  red.fixed(nn-r+1:nn) = true;
  g = prod (-real (z(fast)));
  for j = 1:numel (red.channels)
    B = red.channels(j).B / g;
    if (numel (B) > nn)
      B = B(end-nn+1:end);
      red.channels(j).nb = nn;
    endif
    red.channels(j).B = B;
  endfor
endfunction

## Every start of a fit failed: typically the engine found its
## instruments rank deficient because a pole of the start lies far beyond
## what the samples resolve (its filtered regressors vanish; on a
## simulated cascaded-tanks record a user's [3 3 0] model with a pole at
## p Ts = 68 made every candidate's fit fail, and residtrace could test
## none).
## The template with its real poles beyond the Nyquist frequency (p Ts >
## pi) residualised is fitted instead: the candidate is then tested in
## the order the samples determine. @var{model} (failed) is returned when
## there is no such pole or that fit fails too.
function model = refit_without_fast_poles (tmpl, D, ctx, model)
  red = residualised (tmpl, D.Ts, pi, true);
  if (! isempty (red))
    m = residtrace_fit (red, D, ctx, {red.F});
    if (m.ok)
      model = m;
    endif
  endif
endfunction
