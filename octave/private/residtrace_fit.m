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
## runs in the core (core/include/ctid/apps/residtrace/model_fit.hpp,
## fit_model, around structure_fit.hpp's fit_structure, through
## @code{effect_sim_mex}, method "fitmodel"), with the refits described
## below; this function converts the arguments.
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
## and the model fitted again in the order without it (singular
## perturbation: the mode at its steady state, each numerator divided by
## p): the returned model may have a lower order than @var{tmpl}. When
## every start fails, the template with its real poles beyond the Nyquist
## frequency (p Ts > pi) residualised is fitted instead. Neither with
## @code{ctx.keep_order} true (the re-estimates of the current model in
## its own structure). A model with a function of its output inside the
## dynamics (a @qcode{"ypower"} channel) is then fitted again with the
## model's simulated output (@code{residtrace_simulate}, its free response
## added when the initial state is estimated) as that signal, while the
## simulation error on @var{D} falls (at most three rounds); its
## @code{s2}, @code{bic} and @code{e_est} are then those of the
## simulation. A model with a physical realisation (@code{tmpl.phys}) is
## fitted by @code{residtrace_physfit} instead (simulation error).
## @end deftypefn

function model = residtrace_fit (tmpl, D, ctx, starts)
  if (isfield (tmpl, "phys") && ! isempty (tmpl.phys))
    ## a physical realisation: fitted on its simulation error
    model = residtrace_physfit (tmpl, D, ctx);
    return;
  endif
  if (isfield (tmpl, "nlin"))
    tmpl = rmfield (tmpl, "nlin");     # a Hammerstein fit's, now stale
  endif
  model = effect_sim_mex ("residtrace", "fitmodel", tmpl, D,
                         residtrace_fitopts (ctx, starts));
endfunction
