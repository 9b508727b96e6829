## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn {} {@var{model} =} residtrace_physfit (@var{tmpl}, @var{D}, @var{ctx})
## Fits a @code{residtrace} model with a physical realisation
## (@code{tmpl.phys}, see @code{residtrace_physsim}) on the record @var{D}
## by minimising its simulation error (output error, Levenberg-Marquardt
## with a forward-difference Jacobian), started from @var{tmpl}'s values.
## The refined-IV engine cannot fit these models: their nonlinearity acts
## on a state that is not measured (an end stop that resets a velocity,
## an inner tank that overflows), so there is no regression form; the
## simulation error is the criterion every candidate is scored by.
##
## Parameters: for "stop", the free coefficients of F, every channel's
## numerator, the output offset (when the model has one) and the finite
## levels; for "cascade", every channel's gain, the constant inflow d,
## log alpha, log gamma, the output level c (square-root nodes), the
## inner level (when finite), the outer level @code{yhi} and the share
## @code{spill} of the inner overflow (when present) and the initial
## level @code{h0} (when present; with @code{D.initial_state} the inner
## one @code{z0} too, else at rest with h0: the cascade's initial state,
## so no free response is added). A share is kept in [0, 1] by
## projecting each step onto it (a step rejected at the bound would stall
## the others). With @code{D.initial_state} the free
## response of the model's (linearised) F is fitted on the error by least
## squares, as for every other model. At most @code{ctx.maxiter}
## iterations (three while residtrace screens) and at most max(8, 48 000 /
## n) on the n <= 6000 samples fitted (the first ones; a budget for speed
## that grows as n falls: eight whatever n would leave the cascades' fits
## short of their minimum on records of a few thousand samples); the residual
## variance, BIC and @code{e_est} are those of the whole record.
## @code{phys.theta}, @code{phys.cov}: the parameters above and their
## Gauss-Newton covariance s^2 (J'J)^+ (J at the estimate, s^2 on the
## samples fitted); @code{theta}, @code{cov}: those of
## the linear part (for a cascade, its linearisation, without covariance).
## The fit is the core's
## (@file{core/include/ctid/apps/residtrace/physical_model.hpp},
## fit_physical_model, on @file{physical_fit.hpp}; gateway
## @code{effect_sim_mex}, method "physmodelfit").
## @end deftypefn

function model = residtrace_physfit (tmpl, D, ctx)
  model = effect_sim_mex ("residtrace", "physmodelfit", tmpl, D,
                         struct ("maxiter", ctx.maxiter));
endfunction
