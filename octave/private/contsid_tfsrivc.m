## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn {} {[@var{num}, @var{den}, @var{td}, @var{P}, @var{info}] =} contsid_tfsrivc (@var{fname}, @var{d}, @var{np}, @var{nz}, @var{o})
## Shared back-end of tfsrivc, tfsrivc_init and procsrivc: SRIVC on the
## refined-IV engine (core/include/ctid/offline/refined_iv.hpp, thesis eqs.
## 2.8-2.13) for B(p)/F(p) e^(-td p) with a continuous delay td (any
## fraction of a sample; the delayed ZOH/FOH input is filtered exactly).
##
## @var{d} from @code{contsid_getdata}; @var{o} a struct with fields
## @code{td0} (start delay or [] for the grid search), @code{fixtd},
## @code{tdmin}, @code{tdmax}, @code{numtd}, @code{lambda} ([] or a
## cut-off), @code{maxiter}, @code{tolpar}, @code{tolfun},
## @code{stepmax}, @code{stepreduction}, @code{theta0} ([] or [f; b]),
## @code{fixed}, @code{fixed_values} ([] or a mask over [f; b] and the
## values of the fixed entries, e.g. a pole at 0),
## @code{search_only} (the grid only: tfsrivc_init), and optionally
## @code{tdmax_auto} (true: tdmax is a default, extended while the grid's
## minimum lies at its upper end; @var{info}.tdmax the range used) and
## @code{noise} (tfrivc: [nd nc], a discrete ARMA noise model C/D
## estimated with the plant by RIVC, core refined_iv_bj.hpp through
## rivc_mex, at every delay; regular sampling only).
##
## Delay: the loss V(td) (simulation-error variance of the SRIVC model at
## td) is evaluated on a grid of @code{numtd} delays in [tdmin, tdmax];
## from the best, Gauss-Newton steps on td, td += (g' e)/(g' g) with the
## output sensitivity g = dy/dtd (central difference) and SRIVC
## re-estimated at every new td, halved (by @code{stepreduction}) while
## the loss does not decrease, bounded by @code{stepmax} and the range.
## Stops when the step is below @code{tolpar} sampling intervals or the
## relative loss decrease below @code{tolfun}. With a noise model the
## loss is the innovation variance of the RIVC model at td and the
## residual and sensitivities of the step are prefiltered by D/C(q^-1)
## (the whitening filter of the noise model, the discrete part of RIVC's
## prefilter: thesis sec. 2.1.2, eq. 2.9 for the Box-Jenkins model), so
## that the delay is estimated jointly with the plant and the noise model,
## as a prediction-error estimate.
##
## @var{P}: covariance of [f; b; td] (td estimated) or [f; b] (fixed),
## sigma^2 (J' J)^-1 with J the sensitivities of the simulated output
## (central differences; whitened by D/C with a noise model); for [f; b]
## alone this is SRIVC's eq. (2.13) covariance. @var{info}: loss, grid,
## grid_loss, iterations, converged, reason, simulated, engine (the
## engine's info).
## @end deftypefn

function [num, den, td, P, info] = contsid_tfsrivc (fname, d, np, nz, o)
  if (columns (d.u) != 1)
    error ([fname ":notSupported"], "%s: one input only (got %d)", fname,
           columns (d.u));
  endif
  if (d.uniform)
    t = d.Ts;
    h = d.Ts;
  else
    t = d.t;
    h = median (diff (d.t));
  endif
  T = d.t(end) - d.t(1);
  e = struct ("nf", np, "nb", nz + 1, "nk", 0,
              "intersample", d.intersample, "maxiter", o.maxiter,
              "tol", o.tolpar);
  if (! isempty (o.lambda))
    e.cutoffs = o.lambda;
  endif
  if (! isempty (o.fixed))
    e.fixed = o.fixed;
    e.fixed_values = o.fixed_values;
  endif
  info = struct ("grid", [], "grid_loss", [], "iterations", 0,
                 "converged", true, "reason", "");
  noise = [];
  if (isfield (o, "noise"))
    noise = o.noise;
  endif

  if (! isempty (o.td0))
    tdgrid = [];
  else
    tdgrid = linspace (o.tdmin, o.tdmax, o.numtd);
  endif
  auto_tdmax = isfield (o, "tdmax_auto") && o.tdmax_auto;

  ## The grid search (tfsrivc_init, or tfsrivc without a start delay).
  if (! isempty (tdgrid))
    loss = Inf (size (tdgrid));
    fits = cell (size (tdgrid));
    for i = 1:numel (tdgrid)
      [fits{i}, loss(i)] = grid_point (tdgrid(i));
    endfor
    ## A default TdMax is a guess (from the cross-correlation, which a
    ## step input makes uninformative): while the grid's minimum lies at
    ## its upper end, the range is extended by the same grid step, to at
    ## most twice its length per round and half the record overall.
    [~, i] = min (loss);
    step = tdgrid(end) - tdgrid(max (end - 1, 1));
    while (auto_tdmax && i == numel (tdgrid) && step > 0 && o.tdmax < T / 2)
      hi = min (2 * o.tdmax - o.tdmin, T / 2);
      more = tdgrid(end) + step * (1:floor ((hi - tdgrid(end)) / step));
      if (isempty (more))
        more = hi;
      endif
      for td_k = more
        tdgrid(end+1) = td_k;
        [fits{end+1}, loss(end+1)] = grid_point (td_k);
      endfor
      o.tdmax = tdgrid(end);
      [~, i] = min (loss);
    endwhile
    info.grid = tdgrid;
    info.grid_loss = loss;
    if (all (! isfinite (loss)))
      error ([fname ":numericalFailure"],
             "%s: SRIVC failed at every delay of the grid [%g, %g]", fname,
             o.tdmin, o.tdmax);
    endif
    cur = fits{i};
    info.reason = sprintf ("grid search over %d delays", numel (tdgrid));
  else
    cur = fit (o.td0, o.theta0);
    info.reason = "delay fixed";
  endif

  ## Gauss-Newton refinement of the delay.
  if (! o.fixtd && ! o.search_only)
    info.converged = false;
    for it = 1:o.maxiter
      info.iterations = it;
      ## Variable-projection step: the td sensitivity with the part that
      ## the coefficients re-estimated by SRIVC absorb projected out.
      g = whiten (cur, sensitivity (cur, "td"));
      Jt = whiten (cur, theta_jacobian (cur));
      if (columns (Jt) > 0)
        g -= Jt * (Jt \ g);
      endif
      gg = g' * g;
      if (! (gg > 0))
        info.reason = "the output does not depend on the delay";
        break;
      endif
      step = (g' * whiten (cur, d.y - cur.sim)) / gg;
      step = sign (step) * min (abs (step), o.stepmax);
      accepted = false;
      for k = 1:10
        tdn = min (max (cur.td + step, o.tdmin), o.tdmax);
        if (tdn == cur.td)
          break;
        endif
        try
          nxt = fit (tdn, cur.theta);
          if (nxt.loss < cur.loss)
            accepted = true;
            break;
          endif
        catch err
          if (! any (strcmp (err.identifier, {[fname ":numericalFailure"],
                                               [fname ":notConverged"]})))
            rethrow (err);
          endif
        end_try_catch
        step *= o.stepreduction;
      endfor
      if (! accepted)
        info.converged = true;
        info.reason = sprintf (["delay refined in %d Gauss-Newton " ...
                                "step(s) (no further decrease)"], it - 1);
        break;
      endif
      dl = (cur.loss - nxt.loss) / cur.loss;
      dstep = abs (nxt.td - cur.td);
      cur = nxt;
      if (dstep < o.tolpar * h || dl < o.tolfun)
        info.converged = true;
        info.reason = sprintf ("delay refined in %d Gauss-Newton step(s)",
                               it);
        break;
      endif
    endfor
    if (! info.converged)
      info.reason = sprintf (["the delay did not converge in %d " ...
                              "Gauss-Newton steps"], o.maxiter);
    endif
  endif

  td = cur.td;
  info.tdmax = o.tdmax;
  nth = np + nz + 1;
  ## Covariance sigma^2 (J' J)^-1 from the output sensitivities.
  [J, idx] = theta_jacobian (cur);
  est_td = double (! o.fixtd && ! o.search_only);
  if (est_td)
    J(:, end+1) = sensitivity (cur, "td");
  endif
  J = whiten (cur, J);
  A = J' * J;
  if (rcond (A) > eps)
    C = cur.loss * inv (A);
  else
    C = NaN (columns (J));
  endif
  nP = nth + est_td;
  P = zeros (nP);
  sel = [idx(:); nth + (1:est_td)'];
  P(sel, sel) = (C + C') / 2;
  den = [1, cur.theta(1:np).'];
  num = cur.theta(np+1:end).';
  info.loss = cur.loss;
  info.simulated = cur.sim;
  info.engine = cur.info;
  info.delay_estimated = logical (est_td);

  ## SRIVC (RIVC with a noise model) at delay td from theta0 ([] = the
  ## engine's automatic start).
  function r = fit (td, theta0)
    if (! isempty (noise))
      r = fit_rivc (td, theta0);
      return;
    endif
    ee = e;
    ee.delay = td;
    if (! isempty (theta0))
      ee.theta_init = theta0;
    endif
    [th, ~, inf] = contsid_refined_iv (fname, d.y, d.u, t, ee);
    r = struct ("td", td, "theta", th, "loss", inf.noise_variance,
                "sim", inf.simulated, "info", inf);
    if (! inf.stable)
      r.loss = Inf;
    endif
  endfunction

  ## RIVC of the plant and the ARMA noise model C/D at delay td (nk whole
  ## samples and the fraction, filtered exactly); the loss is the
  ## innovation variance.
  function r = fit_rivc (td, theta0)
    ee = struct ("nf", np, "nb", nz + 1, "nd", noise(1), "nc", noise(2),
                 "nk", floor (td / d.Ts + 1e-9), "tol", o.tolpar,
                 "maxiter", o.maxiter, "arma_maxiter", 50,
                 "intersample", double (strcmpi (d.intersample, "foh")));
    ee.delay = max (td - ee.nk * d.Ts, 0);
    if (! isempty (theta0))
      ee.theta_init = theta0(:);
    endif
    if (isfield (e, "cutoffs"))
      ee.cutoffs = e.cutoffs;
    endif
    try
      [th, cv, inf] = rivc_mex (fname, double (d.y), double (d.u),
                                double (d.Ts), [], ee);
    catch err
      contsid_rethrow (err);
    end_try_catch
    inf.stable = all (real (roots ([1; th(1:np)])) < 0);
    inf.covariance = cv;
    r = struct ("td", td, "theta", th, "loss", inf.noise_variance,
                "sim", inf.simulated, "info", inf);
    if (! inf.stable || ! isfinite (r.loss))
      r.loss = Inf;
    endif
  endfunction

  ## x (columns) through the noise model's whitening filter D/C(q^-1);
  ## x itself without a noise model.
  function x = whiten (r, x)
    if (! isempty (noise) && ! isempty (x))
      x = filter (r.info.D, r.info.C, x);
    endif
  endfunction

  ## The model's output at theta, td (no iteration).
  function y = simulate (theta, td)
    ee = e;
    ee.delay = td;
    ee.theta_init = theta;
    ee.maxiter = 0;
    [~, ~, inf] = contsid_refined_iv (fname, d.y, d.u, t, ee);
    y = inf.simulated;
  endfunction

  ## The sensitivities of the output to the free coefficients.
  function [J, idx] = theta_jacobian (r)
    free = true (np + nz + 1, 1);
    if (! isempty (o.fixed))
      free = ! logical (o.fixed(:));
    endif
    idx = find (free);
    J = zeros (rows (d.y), numel (idx));
    for i = 1:numel (idx)
      J(:, i) = sensitivity (r, idx(i));
    endfor
  endfunction

  ## One point of the delay grid: the SRIVC fit from the user's start and
  ## its loss, or [] and Inf where SRIVC fails numerically or does not
  ## converge at that delay (other errors are raised).
  function [r, loss] = grid_point (td)
    r = [];
    loss = Inf;
    try
      r = fit (td, o.theta0);
      loss = r.loss;
    catch err
      if (! any (strcmp (err.identifier, {[fname ":numericalFailure"],
                                           [fname ":notConverged"]})))
        rethrow (err);
      endif
    end_try_catch
  endfunction

  ## dy/dp by central differences, p = theta(i) or "td".
  function g = sensitivity (r, which)
    if (ischar (which))
      dt = 1e-3 * h;
      lo = max (r.td - dt, 0);
      g = (simulate (r.theta, r.td + dt) - simulate (r.theta, lo)) ...
          / (r.td + dt - lo);
    else
      th = r.theta;
      dp = 1e-6 * max (abs (th(which)), 1e-3 * norm (th));
      tp = th;
      tp(which) += dp;
      tm = th;
      tm(which) -= dp;
      g = (simulate (tp, r.td) - simulate (tm, r.td)) / (2 * dp);
    endif
  endfunction
endfunction
