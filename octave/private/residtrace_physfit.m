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
## (@file{core/include/ctid/apps/residtrace/physical_fit.hpp}, gateway
## @code{effect_sim_mex}, method "physfit"); this function converts the
## arguments.
## @end deftypefn

function model = residtrace_physfit (tmpl, D, ctx)
  model = tmpl;
  model.ok = false;
  [W, o] = residtrace_physopts (tmpl, D.u, D.Ts);
  o.initial_state = isfield (D, "initial_state") && D.initial_state;
  o.maxiter = ctx.maxiter;
  [fit, e] = effect_sim_mex ("residtrace", "physfit", W, D.y(:), o);
  if (! fit.ok)
    return;
  endif
  P = model.phys;
  if (strcmp (P.kind, "stop"))
    model.F = fit.F;
    for j = 1:numel (model.channels)
      nb = numel (model.channels(j).B);
      model.channels(j).B = fit.B(end-nb+1:end, j).';
    endfor
    k = find (strcmp ({model.out.type}, "offset"), 1);
    if (! isempty (k))
      model.out(k).c = fit.offset;
    endif
    P.lo = fit.lo; P.hi = fit.hi;
  else
    for j = 1:numel (model.channels)
      model.channels(j).B = fit.b(j);
    endfor
    model.F = fit.F;
    for f = {"d", "alpha", "gamma", "c", "hi", "yhi", "spill", "h0", "z0"}
      if (! isempty (fit.(f{1})) || isfield (P, f{1}))
        P.(f{1}) = fit.(f{1});
      endif
    endfor
  endif
  th = fit.theta;
  np = numel (th);
  model.np = np;
  model.s2 = fit.s2;
  model.bic = fit.bic;
  model.e_est = e;
  P.theta = th;
  P.cov = fit.cov;
  model.phys = P;
  ## the linear part's parameters as every model carries them (free f's,
  ## then the numerators): for an end stop the first ones of th; for a
  ## cascade its linearisation (no covariance)
  nl = sum (! model.fixed) + sum ([model.channels.nb]);
  if (strcmp (P.kind, "stop"))
    model.theta = th(1:nl);
    model.cov = fit.cov(1:nl, 1:nl);
  else
    F = model.F / model.F(1);
    model.theta = [F(1 + find (! model.fixed)), ...
                   [model.channels.B] / model.F(1)](:);
    model.cov = NaN (nl);
  endif
  model.ok = true;
endfunction
