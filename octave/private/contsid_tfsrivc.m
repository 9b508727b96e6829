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
## @code{tdmax_limit} (> tdmax: the grid extended up to it while its
## minimum lies at its upper end, as for the data's default TdMax of
## @code{refined_iv_mex}'s method 'delay_range'; @var{info}.tdmax the range
## used) and
## @code{noise} (tfrivc: [nd nc], a discrete ARMA noise model C/D
## estimated with the plant by RIVC, core refined_iv_bj.hpp through
## rivc_mex, at every delay; regular sampling only).
##
## The search is the core's (refined_iv_mex's method 'delay_search',
## core/include/ctid/offline/refined_iv_delay.hpp and delay_search.hpp):
## the loss V(td) (simulation-error variance of the SRIVC model at td;
## with a noise model the innovation variance of the RIVC model) on a
## grid of @code{numtd} delays in [tdmin, tdmax], then from the best
## Gauss-Newton steps on td with SRIVC (RIVC) re-estimated at every new
## td, reduced by @code{stepreduction} while the loss does not decrease,
## bounded by @code{stepmax} and the range; stops when the step is below
## @code{tolpar} sampling intervals or the relative loss decrease below
## @code{tolfun}.
##
## @var{P}: covariance of [f; b; td] (td estimated) or [f; b] (fixed),
## sigma^2 (J' J)^-1 with J the sensitivities of the simulated output
## (whitened by D/C with a noise model); for [f; b] alone this is SRIVC's
## eq. (2.13) covariance. @var{info}: loss, grid, grid_loss, iterations,
## converged, reason, simulated, tdmax, delay_estimated, engine (the
## engine's info at the delay kept).
## @end deftypefn

function [num, den, td, P, info] = contsid_tfsrivc (fname, d, np, nz, o)
  if (columns (d.u) != 1)
    error ([fname ":notSupported"], "%s: one input only (got %d)", fname,
           columns (d.u));
  endif
  t = merge (d.uniform, d.Ts, d.t);
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
  if (! isempty (o.theta0))
    e.theta_init = o.theta0;
  endif
  limit = 0;
  if (isfield (o, "tdmax_limit"))
    limit = o.tdmax_limit;
  endif
  noise = [];
  if (isfield (o, "noise"))
    noise = o.noise;
  endif
  e.delay_search = struct ("td0", o.td0, "tdmin", o.tdmin, "tdmax", o.tdmax,
                           "numtd", o.numtd,
                           "refine", ! o.fixtd && ! o.search_only,
                           "tdmax_limit", limit, "maxiter", o.maxiter,
                           "tolpar", o.tolpar, "tolfun", o.tolfun,
                           "stepmax", o.stepmax,
                           "stepreduction", o.stepreduction,
                           "noise", noise);
  [theta, ~, engine] = contsid_refined_iv (fname, d.y, d.u, t, e);
  s = engine.delay_search;
  td = s.delay;
  P = s.covariance;
  den = [1, theta(1:np).'];
  num = theta(np+1:end).';
  info = struct ("grid", s.grid, "grid_loss", s.grid_loss,
                 "iterations", s.iterations, "converged", s.converged,
                 "reason", s.reason, "tdmax", s.tdmax, "loss", s.loss,
                 "simulated", s.simulated, "engine", rmfield (engine,
                                                             "delay_search"),
                 "delay_estimated", s.delay_estimated);
endfunction
