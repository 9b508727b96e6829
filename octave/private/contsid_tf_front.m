## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn {} {[@var{M}, @var{o}, @var{info}] =} contsid_tf_front (@var{fname}, @var{args})
## Argument parsing and model building of tfsrivc and tfsrivc_init (and of
## the start of tfrivc): (data, np, nz[, IODelay][, Name, Value]) or (data,
## Mi[, Name, Value]), the options of @code{help tfsrivc}, the estimate by
## @code{contsid_tfsrivc}, the @code{idtf} with covariance and Report.
## @var{o}: the options as @code{contsid_tfsrivc} reads them (the delay
## range actually searched in @code{tdmax}), those given checked and the
## rest filled in with CONTSID's tfsrivc defaults by the core's table
## (core/include/ctid/offline/tfsrivc_options.hpp, refined_iv_mex's method
## 'tf_options'); @var{info}: its info.
##
## A Focus filter (CONTSID's cut-off fc: a Butterworth low-pass of order
## FocusOrder) serves the convergence of the delay: the whole estimate
## (grid search or refinement from the start delay) is first made on the
## prefiltered data, whose loss in td is smoother, with a wider basin
## around the global minimum; it then starts the estimate on the data as
## given, which is the result (Chen, Garnier & Gilson, J. Process Control
## 25, 2015: the filter enlarges the convergence region, the unfiltered
## data give the statistically efficient estimate).
## @end deftypefn

function [M, o, info] = contsid_tf_front (fname, args)
  init = strcmp (fname, "tfsrivc_init");
  if (numel (args) < 2)
    error ([fname ":badInput"], "%s: expected data and np, nz (or a model)",
           fname);
  endif
  d = contsid_getdata (fname, args{:});
  contsid_check_output (fname, d.y);
  rest = args(d.nconsumed+1:end);
  if (isempty (rest))
    error ([fname ":badInput"], "%s: expected np, nz or a model", fname);
  endif
  theta0 = [];
  td0 = [];
  if (isobject (rest{1}))
    Mi = rest{1};
    if (! isa (Mi, "idtf") || init)
      error ([fname ":badInput"], "%s: the model must be an idtf", fname);
    endif
    [num, den] = tfdata (Mi, "vector");
    if (iscell (num))
      num = num{1};
      den = den{1};
    endif
    k = find (num != 0, 1);
    if (isempty (k))
      k = numel (num);
    endif
    num = num(k:end);
    np = numel (den) - 1;
    nz = numel (num) - 1;
    th = [den(2:end)(:); num(:)];
    if (all (isfinite (th)) && np >= 1)
      theta0 = th;
    endif
    td0 = get (Mi, "IODelay");
    if (! isfinite (td0))
      td0 = [];
    endif
    rest = rest(2:end);
  else
    if (numel (rest) < 2)
      error ([fname ":badInput"], "%s: expected np and nz", fname);
    endif
    np = rest{1};
    nz = rest{2};
    rest = rest(3:end);
    if (! isempty (rest) && isnumeric (rest{1}))
      if (init)
        error ([fname ":badInput"], ["%s: no start delay here (use TdMin, ", ...
               "TdMax)"], fname);
      endif
      td0 = rest{1};
      rest = rest(2:end);
      if (! isreal (td0) || ! isscalar (td0) || ! isfinite (td0) || td0 < 0)
        error ([fname ":badInput"], "%s: IODelay must be a real scalar >= 0",
               fname);
      endif
    endif
  endif
  if (! isnumeric (np) || ! isscalar (np) || np != fix (np) || np < 1
      || np > 30
      || ! isnumeric (nz) || ! isscalar (nz) || nz != fix (nz) || nz < 0
      || nz > np)
    ## (30: the order limit of every estimator, contsid_recursive_args)
    error ([fname ":badInput"], ...
           "%s: np must be an integer in 1..30 and nz an integer in 0..np",
           fname);
  endif
  T = d.t(end) - d.t(1);
  ## The options given, forwarded to the core's table of CONTSID's tfsrivc
  ## defaults (core/include/ctid/offline/tfsrivc_options.hpp), which checks
  ## them and fills in the rest; Focus is read here (a cut-off, a band or a
  ## word).
  if (mod (numel (rest), 2) != 0)
    error ([fname ":badOption"], "%s: options come in name-value pairs",
           fname);
  endif
  given = struct ("focus", Inf);
  init_keys = {"tdmin", "tdmax", "lambda", "numtd", "integration"};
  for i = 1:2:numel (rest)
    name = rest{i};
    if (! ischar (name))
      error ([fname ":badOption"], "%s: option names must be strings", fname);
    elseif (! isvarname (name) || init && ! any (strcmpi (name, init_keys)))
      error ([fname ":badOption"], "%s: unknown option '%s'", fname, name);
    endif
    given.(lower (name)) = rest{i+1};
  endfor
  for key = {"fixtd", "FixTd"; "integration", "Integration"}.'
    if (isfield (given, key{1}))
      given.(key{1}) = contsid_on_off (fname, key{2}, given.(key{1}));
    endif
  endfor
  band = contsid_focus_option (fname, given.focus);
  o = refined_iv_mex (fname, "tf_options", rmfield (given, "focus"));
  if (o.integration && ! isempty (band))
    error ([fname ":badOption"], ["%s: Integration is not applicable with ", ...
           "a Focus filter (as CONTSID documents)"], fname);
  endif
  df = contsid_focus_filter (fname, d, band, o.focusorder);
  if (o.fixtd && isempty (td0))
    error ([fname ":badInput"], "%s: FixTd 'on' needs the delay (IODelay)",
           fname);
  endif
  if (! isempty (td0) && ! o.fixtd && ! isempty (o.tdmax)
      && (td0 < o.tdmin || td0 > o.tdmax))
    error ([fname ":badOption"], ["%s: the start delay %g is outside ", ...
           "[TdMin, TdMax] = [%g, %g]"], fname, td0, o.tdmin, o.tdmax);
  endif
  ## TdMax and StepMax not given: the data's (core delay_search_defaults.hpp)
  r = refined_iv_mex (fname, "delay_range", d.y, d.u,
                      merge (d.uniform, d.Ts, d.t),
                      struct ("tdmin", o.tdmin, "numtd", o.numtd,
                              "tdmax", o.tdmax, "stepmax", o.stepmax,
                              "td0", td0));
  [o.tdmax, o.stepmax, o.tdmax_limit] = deal (r.tdmax, r.stepmax,
                                              r.tdmax_limit);
  if (td0 > T / 2)
    error ([fname ":badInput"],
           ["%s: the delay %g exceeds half the record ", ...
           "(%g s)"], fname, td0, T);
  endif
  o.td0 = td0;
  o.theta0 = theta0;
  o.fixed = [];
  o.fixed_values = [];
  if (o.integration)
    ## an integrator enforced: f_np = 0, the pole at s = 0
    o.fixed = false (np + nz + 1, 1);
    o.fixed(np) = true;
    o.fixed_values = zeros (np + nz + 1, 1);
    if (! isempty (theta0))
      theta0(np) = 0;
    endif
    o.theta0 = theta0;
  endif
  o.search_only = init;

  if (! isempty (band))
    ## the estimate on the prefiltered data starts the one on the data
    [num, den, td, ~, info] = contsid_tfsrivc (fname, df, np, nz, o);
    o.td0 = td;
    o.theta0 = [den(2:end), num].';
    o.tdmax = max (o.tdmax, info.tdmax);
    o.tdmax_limit = 0;
    grid = {info.grid, info.grid_loss};
    focus_start = struct ("IODelay", td, "num", num, "den", den);
  endif
  [num, den, td, P, info] = contsid_tfsrivc (fname, d, np, nz, o);
  o.tdmax = info.tdmax;
  if (! isempty (band))
    ## the delay grid searched (on the prefiltered data)
    [info.grid, info.grid_loss] = grid{:};
  endif

  ## The idtf: parameters [b; f; td] (SITB order), covariance mapped from
  ## [f; b (; td)] (a fixed delay: variance 0).
  M = idtf (num, den, "IODelay", td);
  nth = np + nz + 1;
  perm = [np + (1:nz+1), 1:np];
  if (info.delay_estimated)
    perm(end+1) = nth + 1;
  endif
  C = P(perm, perm);
  if (all (isfinite (C(:))))
    M = setcov (M, C);
  endif
  n = rows (d.y);
  res = d.y - info.simulated;
  mse = mean (res .^ 2);
  npar = nth + info.delay_estimated;
  fit = struct ("FitPercent", 100 * (1 - norm (res) / norm (d.y - mean (d.y))),
                "LossFcn", mse, "MSE", mse,
                "FPE", mse * (1 + npar / n) / (1 - npar / n));
  tdsd = 0;
  if (info.delay_estimated)
    tdsd = sqrt (P(end, end));
  endif
  Ts = d.Ts;
  converged = info.converged && info.engine.converged;
  reason = info.reason;
  if (! info.engine.converged)
    reason = [reason "; SRIVC: " info.engine.reason];
  endif
  rep = struct ("Fit", fit,
                "Parameters", struct ("ParVector", getpvec (M),
                                      "FreeParCovariance", C,
                                      "IODelay", td, "IODelaySD", tdsd),
                "Termination", struct ("Iterations", info.iterations,
                                       "Converged", converged,
                                       "Reason", reason,
                                       "DelayGrid", info.grid,
                                       "DelayGridLoss", info.grid_loss),
                "DataUsed", struct ("Length", n, "Ts", Ts,
                                    "InterSample", d.intersample));
  if (! isempty (band))
    rep.Parameters.FocusStart = focus_start;
  endif
  rep.Method = fname;
  rep.Status = sprintf ("Estimated using %s", upper (fname));
  M = set (M, "NoiseVariance", mse, "Report", rep);
  ## the fit's status, made and reported as srivc's (the engine's stable and
  ## determined at the delay kept)
  st = info.engine;
  st.converged = converged;
  st.reason = reason;
  [~, M] = contsid_fit_status (st, M);
  if (! converged && ! init)
    warning ([fname ":notConverged"], "%s: %s; the last iterate is returned",
             fname, reason);
  endif
endfunction
