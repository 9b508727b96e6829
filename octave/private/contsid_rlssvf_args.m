## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn {} {@var{p} =} contsid_rlssvf_args (@var{fname}, @dots{})
## Argument preparation of rlssvf, shared with qnml: parses the data,
## [na nb nk] and the options (messages start with @var{fname}) and returns
## @var{p} with @code{data} = @{y, u, t@} and @code{opts}, the options
## struct of rlssvf_mex (fields in mex/estimator_args.hpp), @code{d} and
## @code{orders}.
## @end deftypefn

function p = contsid_rlssvf_args (fname, varargin)
  ## [] leaves an option to the core's default (recursive_options.hpp).
  defaults = struct ("lambda_svf", [], "adm", [], "adg", [], "th0", [],
                     "P0", [], "svf", [], "potter", false, "Gamma", [],
                     "scaling", [], "ic", [], "tsls", [], "precision", [],
                     "covariance_guard", [], "GapSettle", [],
                     "InterSample", "");
  [d, orders, opts] = contsid_recursive_args (fname, "a", defaults,
                                             varargin{:});
  contsid_check_input (fname, d.u, orders.nb);
  ## The filters' rule for the input: the data's InterSample, or the
  ## option's (e.g. "trapezoid" for the thesis' Tustin filtering).
  d.intersample = contsid_filter_rule (fname, d, opts.InterSample);
  o = contsid_recursive_options (fname, opts, orders.np, d);
  o = contsid_ch3_options (fname, opts, orders, d, o);
  o = extend_for_initial_conditions (o, orders);
  t = merge (d.uniform, d.Ts, d.t);
  adm = o.adm;
  if (ischar (adm) && strcmp (adm, "lmr"))
    adm = "ff";                          # the forgetting factor of eq. 3.82
  endif
  p = struct ("d", d, "orders", orders);
  p.data = {d.y, d.u, t};
  ## The gateway's options struct (mex/estimator_args.hpp), field by field.
  g.intersample = d.intersample;
  g.na = orders.na;
  g.nb = orders.nb;
  g.nk = orders.nk;
  g.lambda_svf = o.lambda_svf;
  g.svf = o.svf;
  g.adm = adm;
  g.adg = o.adg;
  g.th0 = o.th0;
  g.P0 = o.P0;
  g.form = o.form;
  g.Gamma = o.Gamma;
  g.scaling = o.scaling;
  g.ic = o.ic;
  g.tsls = o.tsls;
  g.precision = o.precision;
  g.covariance_guard = o.covariance_guard;
  [g.gap_interval, g.gap_settle] = gap_options (d, o);
  p.opts = g;
endfunction

## With initial conditions the core estimates [theta; c_1 .. c_na]: the
## np-size options are extended (c_i: start 0, P0 1e4, Qn 0, no
## regularisation, no scaling).
function o = extend_for_initial_conditions (o, orders)
  if (! (isscalar (o.ic) && (islogical (o.ic) || isnumeric (o.ic)) && o.ic))
    return;
  endif
  na = orders.na;
  if (ischar (o.adm) && strcmp (o.adm, "kf") && ! isempty (o.adg)
      && isnumeric (o.adg))
    o.adg = blkdiag (o.adg, zeros (na));
  endif
  if (! isempty (o.th0) && isnumeric (o.th0))
    o.th0 = [o.th0(:); zeros(na, 1)];
  endif
  if (! isempty (o.P0) && isnumeric (o.P0))
    o.P0 = blkdiag (o.P0, 1e4 * eye (na));
  endif
  if (! isempty (o.Gamma) && isnumeric (o.Gamma))
    o.Gamma = blkdiag (o.Gamma, zeros (na));
  endif
  if (! isempty (o.scaling) && isnumeric (o.scaling))
    o.scaling = [o.scaling(:); ones(na, 1)];
  endif
endfunction


## Gaps of missing samples (contsid_recursive_args bridged them): no update
## for GapSettle seconds after each (default 20 / lambda_svf).
function [interval, settle] = gap_options (d, o)
  interval = 0;
  settle = o.GapSettle;                  # [] unless given or gaps bridged
  if (isfield (d, "gap_interval"))
    interval = d.gap_interval;
  endif
endfunction
