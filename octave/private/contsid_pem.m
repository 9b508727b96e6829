## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn {} {[@var{M}, @var{info}] =} contsid_pem (@var{fname}, @var{args})
## Back-end of the prediction-error estimators @code{tfcoe}, @code{tfest},
## @code{oe} and @code{arx}: reads the data (@code{contsid_getdata}), the
## orders and the options of @var{fname}, calls the core through
## @code{pem_mex} (core/include/ctid/offline/output_error.hpp) and builds the
## @code{idtf}/@code{idpoly} with covariance and Report (Fit.FitPercent,
## LossFcn, MSE, FPE as the SITB defines them; Termination with the
## iterations, convergence flag and reason).  @var{info} is the gateway's.
## @end deftypefn

function [M, info] = contsid_pem (fname, args)
  if (isempty (args))
    error ([fname ":badInput"], "%s: expected data and orders", fname);
  endif
  a1 = args{1};
  if (isa (a1, "idfrd") || (isa (a1, "iddata") && isfield_domain (a1)))
    if (! any (strcmp (fname, {"oe", "tfest"})))
      error ([fname ":notSupported"],
             "%s: frequency-domain data are not supported here (time domain)",
             fname);
    endif
    [M, info] = freq_model (fname, args);
    return;
  endif
  d = contsid_getdata (fname, args{:});
  contsid_check_output (fname, d.y);
  rest = args(d.nconsumed+1:end);
  if (size (d.u, 2) < 1)
    error ([fname ":badInput"], "%s: the data need an input", fname);
  endif
  switch (fname)
    case "arx"
      [M, info] = arx_model (fname, d, rest);
    case "oe"
      [M, info] = oe_model (fname, d, rest);
    otherwise
      [M, info] = tf_model (fname, d, rest);
  endswitch
endfunction

function tf = isfield_domain (dat)
  tf = false;
  try
    tf = strncmpi (get (dat, "Domain"), "f", 1);
  catch
  end_try_catch
endfunction

function ok = isorder (v)
  ok = isnumeric (v) && isreal (v) && all (isfinite (v(:))) ...
       && all (v(:) == fix (v(:))) && all (v(:) >= 0);
endfunction

## Name-value pairs or an options struct of oeOptions/tfestOptions.  The
## keys are those of oe/tfest (SITB) and tfcoe (CONTSID); TolPar and the
## delay-search, FocusOrder, Integration and TolFun keys are tfcoe's
## only (unknown options elsewhere).  o.band: the Focus passband or [].
function o = read_options (fname, rest, o)
  if (numel (rest) == 1 && isstruct (rest{1}))
    s = rest{1};
    if (! isfield (s, "OptionSet"))
      error ([fname ":badOption"], ["%s: the options struct must come ", ...
              "from oeOptions or tfestOptions"], fname);
    endif
    o.focus = s.Focus;
    o.maxiter = s.SearchOptions.MaxIterations;
    o.tol = s.SearchOptions.Tolerance;
    rest = {};
  endif
  if (mod (numel (rest), 2) != 0)
    error ([fname ":badOption"], "%s: options come in name-value pairs", fname);
  endif
  tfcoe_keys = {"tdmin", "numtd", "stepmax", "stepreduction", "focusorder", ...
                "integration", "tolfun"};
  is_tfcoe = strcmp (fname, "tfcoe");
  for i = 1:2:numel (rest)
    if (! ischar (rest{i}))
      error ([fname ":badOption"], "%s: option names must be strings", fname);
    endif
    key = lower (rest{i});
    switch (key)
      case {"focus", "maxiter", "tol", "lambda", "overpar", "tdmax"}
        o.(key) = rest{i+1};
      case "maxiterations"
        o.maxiter = rest{i+1};
      case "tolerance"
        o.tol = rest{i+1};
      otherwise
        if (is_tfcoe && strcmp (key, "tolpar"))
          o.tol = rest{i+1};
        elseif (is_tfcoe && any (strcmp (key, tfcoe_keys)))
          o.(key) = rest{i+1};
        else
          error ([fname ":badOption"], "%s: unknown option '%s'", fname,
                 rest{i});
        endif
    endswitch
  endfor
  scal = @(v) isnumeric (v) && isreal (v) && isscalar (v) && isfinite (v);
  if (! scal (o.maxiter) || o.maxiter != fix (o.maxiter) || o.maxiter < 0)
    error ([fname ":badOption"], "%s: MaxIter must be an integer >= 0", fname);
  endif
  if (! scal (o.tol) || o.tol <= 0)
    error ([fname ":badOption"], "%s: Tol must be a scalar > 0", fname);
  endif
  o.band = contsid_focus_option (fname, o.focus);
endfunction

## tfcoe's CONTSID options: those given checked, the rest filled in, by
## the core's table of tfsrivc's (core/include/ctid/offline/
## tfsrivc_options.hpp, refined_iv_mex's method 'tf_options'): the same
## defaults; StepReduction as the multiplier in (0, 1) (o.srmult),
## Integration as a flag (o.integ).  NumTd >= 2, TdMin below half the
## record and TolFun are tfcoe's own rules.
function o = tfcoe_options (fname, o, T)
  given = struct ();
  for key = {"tdmin", "tdmax", "numtd", "stepmax", "stepreduction", ...
             "focusorder", "integration", "lambda"}
    if (isfield (o, key{1}))
      given.(key{1}) = o.(key{1});
    endif
  endfor
  if (isfield (given, "integration"))
    given.integration = contsid_on_off (fname, "Integration",
                                        given.integration);
  endif
  c = refined_iv_mex (fname, "tf_options", given);
  if (isfield (o, "tolfun") && ! isempty (o.tolfun))
    error ([fname ":notSupported"], ["%s: TolFun cannot be honoured: the ", ...
           "output-error iteration (pem_mex) stops on one tolerance, met ", ...
           "by the relative step and the relative loss decrease together ", ...
           "(TolPar)"], fname);
  endif
  if (c.tdmin >= T / 2)
    error ([fname ":badOption"], "%s: TdMin must lie below half the record",
           fname);
  endif
  if (c.numtd < 2)
    error ([fname ":badOption"], "%s: NumTd must be an integer >= 2", fname);
  endif
  [o.tdmin, o.tdmax, o.numtd, o.stepmax, o.srmult, o.focusorder, o.integ, ...
   o.lambda] = deal (c.tdmin, c.tdmax, c.numtd, c.stepmax, c.stepreduction,
                     c.focusorder, c.integration, c.lambda);
  o.search = c;
endfunction

function [theta, P, info] = call_gateway (fname, d, opts)
  [theta, P, info] = pem_mex (fname, d.y, d.u, merge (d.uniform, d.Ts, d.t),
                              opts);
endfunction

function [M, info] = arx_model (fname, d, rest)
  if (isempty (rest) || ! isorder (rest{1}))
    error ([fname ":badInput"], "%s: expected orders [na nb nk]", fname);
  endif
  nn = rest{1};
  nu = size (d.u, 2);
  if (numel (nn) != 1 + 2 * nu)
    error ([fname ":dimensionMismatch"],
           "%s: [na nb nk] needs 1 + 2*%d entries for %d input(s)", fname,
           nu, nu);
  endif
  if (numel (rest) > 1)
    error ([fname ":badOption"], "%s: no options are taken in this form",
           fname);
  endif
  if (! d.uniform)
    error ([fname ":badInput"], "%s: ARX needs regularly sampled data",
           fname);
  endif
  na = nn(1); nb = nn(2:1+nu); nk = nn(2+nu:end);
  [theta, P, info] = call_gateway (fname, d,
                                   struct ("model", "arx", "na", na,
                                           "nb", nb, "nk", nk));
  A = [1 theta(1:na).'];
  B = cell (1, nu);
  at = na;
  for j = 1:nu
    B{j} = [zeros(1, nk(j)) theta(at+(1:nb(j))).'];
    at += nb(j);
  endfor
  if (nu == 1)
    B = B{1};
  endif
  M = idpoly (A, B, 1, 1, 1, info.noise_variance, d.Ts);
  free = 1:na;
  at = na;
  for j = 1:nu
    free = [free, at + nk(j) + (1:nb(j))];
    at += nk(j) + nb(j);
  endfor
  M = set_cov (M, P, theta, free);
  ## the one-step prediction error (the SITB reports the prediction fit)
  M = set_report (M, fname, d, info.prediction_error, numel (theta), 0, true,
                  "linear LS", rows (d.y));
endfunction

## The covariance in getpvec's layout: P is over the free parameters
## (theta); entries of getpvec that are fixed (the leading zeros of an
## idpoly's B, the delay) get zero rows and columns.  free: the indices of
## theta in getpvec (M), or [] when they coincide.
function M = set_cov (M, P, theta, free)
  p = getpvec (M);
  if (nargin < 4 || isempty (free))
    free = 1:numel (theta);
  endif
  if (numel (free) != numel (theta) || ! all (isfinite (P(:))))
    return;
  endif
  C = zeros (numel (p));
  C(free, free) = P;
  M = setcov (M, C);
endfunction

function M = set_report (M, fname, d, e, npar, iters, conv, reason, n)
  mse = mean (e .^ 2);
  fit = struct ("FitPercent", 100 * (1 - norm (e) / norm (d.y - mean (d.y))),
                "LossFcn", mse, "MSE", mse,
                "FPE", mse * (1 + npar / n) / (1 - npar / n));
  rep = struct ("Method", upper (fname),
                "Status", sprintf ("Estimated using %s", upper (fname)),
                "Fit", fit,
                "Parameters", struct ("ParVector", getpvec (M)),
                "Termination", struct ("Iterations", iters,
                                       "Converged", conv,
                                       "Reason", reason),
                "DataUsed", struct ("Length", n, "Ts", d.Ts,
                                    "InterSample", d.intersample));
  M = set (M, "Report", rep);
endfunction

## oe (data, [nb nf nk]): nb, nf, nk one entry per input (y = sum_j
## B_j/F_j u_j(t - nk_j), each input with its own F_j, as the SITB's oe);
## B and F are cells for several inputs.
function [M, info] = oe_model (fname, d, rest)
  nu = size (d.u, 2);
  if (isempty (rest) || ! isorder (rest{1}) || isempty (rest{1})
      || ! isvector (rest{1}) || mod (numel (rest{1}), 3) != 0)
    error ([fname ":badInput"], "%s: expected orders [nb nf nk]", fname);
  endif
  nn = rest{1};
  if (numel (nn) != 3 * nu)
    error ([fname ":dimensionMismatch"],
           "%s: [nb nf nk] needs 3*%d entries for %d input(s), got %d",
           fname, nu, nu, numel (nn));
  endif
  if (! d.uniform)
    error ([fname ":badInput"], ["%s: a discrete-time OE model needs ", ...
           "regularly sampled data"], fname);
  endif
  nb = nn(1:nu); nf = nn(nu+1:2*nu); nk = nn(2*nu+1:end);
  if (any (nb < 1))
    error ([fname ":badInput"], "%s: nb must be >= 1", fname);
  endif
  o = read_options (fname, rest(2:end),
                    struct ("focus", "simulation",
                            "maxiter", contsid_pem_default ("maxiter"),
                            "tol", contsid_pem_default ("tol"),
                            "lambda", [], "overpar", "off",
                            "tdmax", []));
  check_unused (fname, o, {"lambda", "overpar", "tdmax"});
  df = contsid_focus_filter (fname, d, o.band, 4);
  [theta, P, info] = call_gateway (fname, df,
                                   struct ("model", "oe_dt", "nf", nf,
                                           "nb", nb, "nk", nk,
                                           "maxiter", o.maxiter,
                                           "tol", o.tol));
  ## theta = [f_1; ..; f_nu; b_1; ..; b_nu]; getpvec (M) = [B_1 .. B_nu
  ## (with their nk leading zeros), F_1(2:end) .. F_nu(2:end)]
  B = cell (1, nu); F = cell (1, nu);
  perm = []; free = [];
  at = 0; bt = sum (nf);
  for j = 1:nu
    B{j} = [zeros(1, nk(j)) theta(bt+(1:nb(j))).'];
    perm = [perm, bt + (1:nb(j))];
    free = [free, at + nk(j) + (1:nb(j))];
    at += nk(j) + nb(j);
    bt += nb(j);
  endfor
  ft = 0;
  for j = 1:nu
    F{j} = [1 theta(ft+(1:nf(j))).'];
    perm = [perm, ft + (1:nf(j))];
    free = [free, at + (1:nf(j))];
    at += nf(j);
    ft += nf(j);
  endfor
  if (nu == 1)
    B = B{1}; F = F{1};
  endif
  M = idpoly (1, B, 1, 1, F, info.noise_variance, d.Ts);
  M = set_cov (M, P(perm, perm), theta, free);
  e = df.y - info.simulated;
  M = set_report (M, fname, d, e, sum (nb) + sum (nf), info.iterations,
                  info.converged, info.reason, rows (d.y));
  warn_unconverged (fname, info);
endfunction

function check_unused (fname, o, keys)
  for i = 1:numel (keys)
    if (isfield (o, keys{i}) && ! isempty (o.(keys{i}))
        && ! strcmpi (o.(keys{i}), "off"))
      error ([fname ":badOption"], "%s: option '%s' is not one of %s's",
             fname, keys{i}, fname);
    endif
  endfor
endfunction

function warn_unconverged (fname, info)
  if (! info.converged)
    warning ([fname ":notConverged"], "%s: %s; the last iterate is returned",
             fname, info.reason);
  endif
endfunction

## tfest (data, np, nz[, iodelay][, opt]) and tfcoe (data, np, nz[, td][,
## Name, Value]): continuous-time idtf; tfcoe estimates a given delay.
function [M, info] = tf_model (fname, d, rest)
  nu = size (d.u, 2);
  if (numel (rest) < 2 || ! isorder (rest{1}) || ! isvector (rest{1})
      || ! isorder (rest{2}) || ! isvector (rest{2}))
    error ([fname ":badInput"], "%s: expected np and nz (integers)", fname);
  endif
  ## np, nz (and the IODelay): scalars for every input or one per input
  ## (y = sum_j B_j/F_j u_j(t - td_j), each input with its own F_j)
  np = per_input (fname, rest{1}, nu, "np");
  nz = per_input (fname, rest{2}, nu, "nz");
  if (any (np < 1) || any (nz > np) || any (np > 30))
    ## (30: the order limit of every estimator, contsid_recursive_args)
    error ([fname ":badInput"],
           "%s: need 1 <= np <= 30 and 0 <= nz <= np", fname);
  endif
  if (nu != 1 && ! strcmp (fname, "tfest"))
    error ([fname ":notSupported"], "%s: one input only", fname);
  endif
  rest = rest(3:end);
  td = [];
  if (! isempty (rest) && isnumeric (rest{1}))
    td = rest{1};
    rest = rest(2:end);
    if (! isnumeric (td) || ! isreal (td) || isempty (td) || ! isvector (td)
        || ! all (isfinite (td)) || any (td < 0))
      error ([fname ":badInput"], "%s: IODelay must be real and >= 0",
             fname);
    endif
    td = per_input (fname, td, nu, "IODelay");
  endif
  T = d.t(end) - d.t(1);
  dflt = struct ("focus", "simulation",
                 "maxiter", contsid_pem_default ("maxiter"),
                 "tol", contsid_pem_default ("tol"), "overpar", "off");
  is_tfcoe = strcmp (fname, "tfcoe");
  o = read_options (fname, rest, dflt);
  if (is_tfcoe)
    o = tfcoe_options (fname, o, T);
    forder = o.focusorder;
  else
    check_unused (fname, o, {"lambda", "overpar", "tdmax"});
    [o.tdmin, o.tdmax, o.lambda, o.integ] = deal (0, [], [], false);
    forder = 4;
  endif
  if (! (ischar (o.overpar) && any (strcmpi (o.overpar, {"on", "off"}))))
    error ([fname ":badOption"], "%s: OverPar must be 'on' or 'off'", fname);
  endif
  overpar = strcmpi (o.overpar, "on");
  estimate = strcmp (fname, "tfcoe") && ! isempty (td);
  td_given = td;
  tdmax_given = ! isempty (o.tdmax);
  if (! tdmax_given)
    o.tdmax = T / 2;
  endif
  if (o.tdmin > 0 && nz >= np)
    error ([fname ":badOption"], ["%s: TdMin applies to an estimated ", ...
           "delay (nz < np)"], fname);
  endif
  if (isempty (td))
    td = zeros (1, nu);
  endif
  if (any (td > T / 2) || (estimate && td > o.tdmax))
    error ([fname ":badInput"], "%s: the delay %g exceeds %g s", fname,
           max (td), min (T / 2, o.tdmax));
  endif
  if (estimate && td < o.tdmin)
    error ([fname ":badInput"], "%s: the delay %g lies below TdMin = %g s",
           fname, td, o.tdmin);
  endif
  if (estimate && nz >= np)
    error ([fname ":badInput"],
           "%s: estimating the delay needs nz < np (strictly proper)", fname);
  endif
  if (o.integ)
    check_integration (fname, d, np, nz, o);
  endif
  df = contsid_focus_filter (fname, d, o.band, forder);
  rule = "zoh";
  if (strcmpi (df.intersample, "foh"))
    rule = "foh";
  endif
  ## Integration 'on': B(p)/(p F'(p)) fitted by the core as B/F' on the
  ## integral of the ZOH input (check_integration), f_np = 0 fixed.
  opts = struct ("model", "oe_ct", "nf", np, "nb", nz + 1, "nk", 0 * np,
                 "delay", td, "intersample", rule, "maxiter", o.maxiter,
                 "tol", o.tol, "estimate_delay", estimate,
                 "delay_max", o.tdmax, "cutoff", 0, "integrate", o.integ);
  if (! isempty (o.lambda))
    opts.cutoff = o.lambda;
  endif
  if (strcmp (fname, "tfcoe") && nz < np)
    ## The delay located by tfsrivc's search (its grid, then its
    ## Gauss-Newton refinement; with td also that refinement from td), then
    ## refined with the coefficients by the output-error minimisation from
    ## each start, td kept in [TdMin, TdMax]; the lowest loss wins (core
    ## output_error_starts.hpp).  (On a ZOH input the loss has a kink at
    ## every whole number of samples of delay, where a local minimum can
    ## hold a gradient method: from td alone the TFCOE demo stays at 7.4994
    ## s for a true 8 s.)
    [starts, o.tdmax, search] = srivc_delay_start (fname, df, np, nz,
                                                   td_given, o, tdmax_given);
    if (overpar)
      starts{end+1} = overpar_start (fname, d, np, nz, td_given, o);
    endif
    opts.starts = [starts{:}];
    opts.estimate_delay = true;
    opts.delay_max = o.tdmax;
    opts.delay_min = o.tdmin;
  elseif (overpar)
    th0 = overpar_start (fname, d, np, nz, td_given, o);
    if (! isempty (th0))
      opts.starts = th0(1:end-1);
      opts.default_start = true;
    endif
  endif
  [theta, P, info] = call_gateway (fname, df, opts);
  estimate = info.delay_estimated;
  if (opts.estimate_delay)
    td = info.delay;
  endif
  npar = info.free_parameters;
  if (nu > 1)
    M = tf_multi (theta, P, np, nz, td);
  else
    M = idtf (theta(np+(1:nz+1)).', [1 theta(1:np).'], "IODelay", td);
    perm = [np + (1:nz+1), 1:np];
    if (estimate)
      perm(end+1) = np + nz + 2;        # getpvec ends with the IODelay
    endif
    M = set_cov (M, P(perm, perm), theta(perm));
  endif
  e = df.y - info.simulated;
  M = set_report (M, fname, d, e, npar, info.iterations,
                  info.converged, info.reason, rows (d.y));
  r = get (M, "Report");
  if (is_tfcoe && nz < np)
    r.Termination.DelaySearch = search;
  endif
  r.Parameters.IODelay = td;
  r.Parameters.IODelaySD = NaN;
  if (estimate)
    r.Parameters.IODelaySD = sqrt (P(end, end));
  endif
  r.Parameters.FullCovariance = P;
  r.Termination.Start = info.start;
  M = set (M, "NoiseVariance", info.noise_variance, "Report", r);
  warn_unconverged (fname, info);
endfunction

## A scalar order (or delay) v for each of the nu inputs, or one per input.
function v = per_input (fname, v, nu, name)
  if (isscalar (v))
    v = repmat (v, 1, nu);
  elseif (numel (v) != nu)
    error ([fname ":dimensionMismatch"],
           "%s: %s needs 1 or %d entries (one per input), got %d", fname,
           name, nu, numel (v));
  endif
  v = double (v(:).');
endfunction

## The idtf of several inputs from theta = [f_1; ..; f_nu; b_1; ..; b_nu]:
## one numerator and denominator per input; getpvec (M) = [num_1 ..
## num_nu, den_1(2:end) .. den_nu(2:end), IODelay], the delays fixed.
function M = tf_multi (theta, P, np, nz, td)
  nu = numel (np);
  num = cell (1, nu); den = cell (1, nu);
  perm = [];
  bt = sum (np);
  for j = 1:nu
    num{j} = theta(bt+(1:nz(j)+1)).';
    perm = [perm, bt + (1:nz(j)+1)];
    bt += nz(j) + 1;
  endfor
  ft = 0;
  for j = 1:nu
    den{j} = [1 theta(ft+(1:np(j))).'];
    perm = [perm, ft + (1:np(j))];
    ft += np(j);
  endfor
  M = idtf (num, den, "IODelay", td);
  M = set_cov (M, P(perm, perm), theta(perm), 1:numel (theta));
endfunction

## tfcoe's starts [f; b; td]: SRIVC at the delay of tfsrivc's search
## (contsid_tfsrivc): over its grid of NumTd delays in [TdMin, TdMax]
## (TdMax by default from the input-output cross-correlation, as tfsrivc,
## at least 2 td0 and 2 TdMin) then refined by Gauss-Newton (steps bounded
## by StepMax, reduced by StepReduction), and, when td0 is given, refined
## from td0.  Integration 'on': f_np fixed at 0.  search: the grid and its
## losses (Report.Termination.DelaySearch).
function [starts, tdmax, search] = srivc_delay_start (fname, d, np, nz, td0,
                                                      o, tdmax_given)
  ## TdMax not given and StepMax: the data's (core delay_search_defaults.hpp)
  given = struct ("tdmin", o.tdmin, "numtd", o.numtd, "stepmax", o.stepmax,
                  "td0", td0);
  if (tdmax_given)
    given.tdmax = o.tdmax;
  endif
  r = refined_iv_mex (fname, "delay_range", d.y, d.u,
                      merge (d.uniform, d.Ts, d.t), given);
  tdmax = r.tdmax;
  ## tfsrivc's options (the core's table: its tolerances), 30 iterations
  s = o.search;
  [s.td0, s.fixtd, s.tdmax, s.maxiter, s.stepmax, s.tdmax_limit, s.theta0, ...
   s.fixed, s.fixed_values, s.search_only] = deal ([], false, tdmax, 30,
                                                   r.stepmax, r.tdmax_limit,
                                                   [], [], [], false);
  if (o.integ)
    s.fixed = false (np + nz + 1, 1);
    s.fixed(np) = true;                 # f_np = 0: the pole at p = 0
    s.fixed_values = zeros (np + nz + 1, 1);
  endif
  starts = {};
  td0s = {[]};
  if (! isempty (td0))
    td0s{2} = td0;
  endif
  for k = 1:numel (td0s)
    s.td0 = td0s{k};
    [num, den, td, ~, si] = contsid_tfsrivc (fname, d, np, nz, s);
    starts{end+1} = [den(2:end), num, td].';
    tdmax = max (tdmax, si.tdmax);
    if (k == 1)
      search = struct ("Grid", si.grid, "GridLoss", si.grid_loss,
                       "Reason", si.reason);
    endif
  endfor
endfunction

## Integration 'on' (tfcoe): the model B(p)/(p F'(p)) e^(-td p) is fitted
## as B/F' on the integral v of the input; v is then an exact FOH signal
## (piecewise linear) only for a ZOH input, and B/F' must be strictly
## proper for the delay estimate (the gateway's d y/d td = -p y).
function check_integration (fname, d, np, nz, o)
  if (! isempty (o.band))
    error ([fname ":badOption"], ["%s: Integration 'on' is not applicable ", ...
           "with a Focus filter (as in CONTSID)"], fname);
  endif
  if (strcmpi (o.overpar, "on"))
    error ([fname ":notSupported"], ["%s: Integration 'on' with OverPar ", ...
           "'on' is not supported (the over-parametrised start has no ", ...
           "integrator)"], fname);
  endif
  if (! strcmpi (d.intersample, "zoh"))
    error ([fname ":notSupported"], ["%s: Integration 'on' needs a ZOH ", ...
           "input (the integral of a FOH input is not FOH)"], fname);
  endif
  if (np < 2 || nz > np - 2)
    error ([fname ":notSupported"], ["%s: Integration 'on' needs np >= 2 ", ...
           "and nz <= np - 2 (B/F' of the integrated input, F' of order ", ...
           "np - 1, must be strictly proper for the delay estimate)"], fname);
  endif
endfunction

## oe (data, [nb nf (0)][, opt]) and tfest (data, np, nz[, iodelay][, opt])
## on an idfrd or continuous-time frequency-domain iddata: the orders and
## options read here, the fit (SRIVC start, then output error on the
## frequency response) by contsid_freq, which receives them as one struct.
function [M, info] = freq_model (fname, args)
  if (numel (args) < 2)
    error ([fname ":badInput"], "%s: expected data and orders", fname);
  endif
  nu = freq_inputs (args{1});
  rest = args(2:end);
  td = zeros (1, nu);
  if (strcmp (fname, "oe"))
    ## [nb nf] or [nb nf nk] with nk = 0, one entry of each per input
    nn = rest{1};
    if (! isorder (nn) || isempty (nn) || ! isvector (nn)
        || ! any (numel (nn) == [2 3]  * nu))
      error ([fname ":badInput"], ["%s: on continuous-time frequency data ", ...
             "the orders are [nb nf] (or [nb nf 0]), one entry each per ", ...
             "input (%d)"], fname, nu);
    endif
    if (numel (nn) == 3 * nu && any (nn(2*nu+1:end) != 0))
      error ([fname ":notSupported"], ["%s: a delay nk on continuous-time ", ...
             "frequency data is not supported"], fname);
    endif
    nb = nn(1:nu); na = nn(nu+1:2*nu);
    rest = rest(2:end);
  else
    if (numel (rest) < 2 || ! isorder (rest{1}) || ! isvector (rest{1})
        || ! isorder (rest{2}) || ! isvector (rest{2}))
      error ([fname ":badInput"], "%s: expected np and nz (integers)", fname);
    endif
    na = per_input (fname, rest{1}, nu, "np");
    nb = per_input (fname, rest{2}, nu, "nz") + 1;
    rest = rest(3:end);
    if (! isempty (rest) && isnumeric (rest{1}))
      td = rest{1};
      rest = rest(2:end);
      if (! isreal (td) || isempty (td) || ! isvector (td)
          || ! all (isfinite (td)) || any (td < 0))
        error ([fname ":badInput"], "%s: IODelay must be real and >= 0",
               fname);
      endif
      td = per_input (fname, td, nu, "IODelay");
    endif
  endif
  if (any (na < 1) || any (nb < 1) || any (nb > na + 1))
    error ([fname ":badInput"], "%s: need nf >= 1 and 1 <= nb <= nf + 1",
           fname);
  endif
  o = read_options (fname, rest,
                    struct ("focus", "simulation",
                            "maxiter", contsid_pem_default ("maxiter"),
                            "tol", contsid_pem_default ("tol"),
                            "lambda", [], "overpar", "off",
                            "tdmax", []));
  check_unused (fname, o, {"lambda", "overpar", "tdmax"});
  spec = struct ("na", double (na(:).'), "nb", double (nb(:).'),
                 "delay", td, "band", o.band, "maxiter", max (o.maxiter, 1),
                 "tol", o.tol);
  [M, info] = contsid_freq (fname, {args{1}, spec});
endfunction

## The number of inputs of frequency data (1 when it cannot be read: the
## data are checked by contsid_freq).
function nu = freq_inputs (data)
  nu = 1;
  try
    if (isa (data, "idfrd"))
      nu = max (size (get (data, "ResponseData"), 2), 1);
    else
      nu = max (columns (get (data, "InputData")), 1);
    endif
  catch
  end_try_catch
endfunction

## tfcoe's OverPar 'on': one more start [f; b; td] from an over-parametrised
## fit.  The output error of the structure with one pole and one zero more
## (np + 1, nz + 1; its delay searched as tfcoe's) is fitted first; the
## core (output_error_starts.hpp, reduced_start) reduces its frequency
## response over the band of the record (2 pi / T to the Nyquist
## frequency) to the asked orders, the delay with them, by the
## frequency-domain output error (tffcoe's): fewer non-global minima
## (Soderstrom and Stoica, Automatica 18(1), 1982), and the extra
## pole-zero pair can take up a delay error.  [] when that is unstable.
function th = overpar_start (fname, d, np, nz, td, o)
  args = {np + 1, nz + 1};
  if (! isempty (td))
    args{end+1} = td;
  endif
  args = [args, {"MaxIter", o.maxiter, "Tol", o.tol, "TdMax", o.tdmax, ...
                 "TdMin", o.tdmin, "NumTd", o.numtd, ...
                 "StepReduction", o.srmult, "FocusOrder", o.focusorder}];
  if (! isempty (o.stepmax))
    args = [args, {"StepMax", o.stepmax}];
  endif
  if (! isempty (o.lambda))
    args = [args, {"Lambda", o.lambda}];
  endif
  if (! isempty (o.band))
    args = [args, {"Focus", o.band}];
  endif
  ## only a start: its own (ill-conditioned, a near pole-zero
  ## cancellation) non-convergence is no news for the user
  state = warning ("off", [fname ":notConverged"]);
  unwind_protect
    Mo = tf_model (fname, d, args);
  unwind_protect_cleanup
    warning (state);
  end_unwind_protect
  [num, den] = tfdata (Mo, "vector");
  h = median (diff (d.t));
  band = [2 * pi / (d.t(end) - d.t(1)), pi / h];
  th = pem_mex (fname, "reduce", den(2:end), num,
                struct ("nf", np, "nb", nz + 1, "band", band,
                        "td", get (Mo, "IODelay"), "search_delay", nz < np,
                        "delay_max", o.tdmax));
endfunction
