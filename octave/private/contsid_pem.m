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

function t = time_arg (d)
  if (d.uniform)
    t = d.Ts;
  else
    t = d.t;
  endif
endfunction

function ok = isorder (v)
  ok = isnumeric (v) && isreal (v) && all (isfinite (v(:))) ...
       && all (v(:) == fix (v(:))) && all (v(:) >= 0);
endfunction

## Name-value pairs or an options struct of oeOptions/tfestOptions.
function o = read_options (fname, rest, o)
  if (numel (rest) == 1 && isstruct (rest{1}))
    s = rest{1};
    if (! isfield (s, "OptionSet"))
      error ([fname ":badOption"], ["%s: the options struct must come from ", ...
              "oeOptions or tfestOptions"], fname);
    endif
    o.focus = s.Focus;
    o.maxiter = s.SearchOptions.MaxIterations;
    o.tol = s.SearchOptions.Tolerance;
    rest = {};
  endif
  if (mod (numel (rest), 2) != 0)
    error ([fname ":badOption"], "%s: options come in name-value pairs", fname);
  endif
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
        error ([fname ":badOption"], "%s: unknown option '%s'", fname,
               rest{i});
    endswitch
  endfor
  scal = @(v) isnumeric (v) && isreal (v) && isscalar (v) && isfinite (v);
  if (! scal (o.maxiter) || o.maxiter != fix (o.maxiter) || o.maxiter < 0)
    error ([fname ":badOption"], "%s: MaxIter must be an integer >= 0", fname);
  endif
  if (! scal (o.tol) || o.tol <= 0)
    error ([fname ":badOption"], "%s: Tol must be a scalar > 0", fname);
  endif
  o.band = [];
  if (ischar (o.focus))
    if (! any (strcmpi (o.focus, {"simulation", "prediction"})))
      error ([fname ":badOption"], ["%s: Focus must be 'simulation', ", ...
             "'prediction' or a band [w1 w2] (rad/s)"], fname);
    endif
  elseif (isnumeric (o.focus) && isreal (o.focus) && numel (o.focus) == 2
          && all (isfinite (o.focus)) && o.focus(1) >= 0
          && o.focus(2) > o.focus(1))
    o.band = o.focus(:).';
  else
    error ([fname ":badOption"], ["%s: Focus must be 'simulation', ", ...
           "'prediction' or a band [w1 w2] (rad/s)"], fname);
  endif
endfunction

function [theta, P, info] = call_gateway (fname, d, opts)
  [theta, P, info] = pem_mex (fname, d.y, d.u, time_arg (d), opts);
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
  n = rows (d.y);
  e = d.y - sim_arx (A, B, d, nu);
  M = set_report (M, fname, d, e, numel (theta), 0, true, "linear LS", n);
endfunction

## One-step prediction of the ARX model, for its Report.Fit (the SITB
## reports the prediction fit for ARX).
function e = sim_arx (A, B, d, nu)
  if (! iscell (B))
    B = {B};
  endif
  yp = filter ([0 -A(2:end)], 1, d.y);
  for j = 1:nu
    yp += filter (B{j}, 1, d.u(:, j));
  endfor
  e = d.y - yp;
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
                    struct ("focus", "simulation", "maxiter", 100,
                            "tol", 1e-8, "lambda", [], "overpar", "off",
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
    if (! isempty (o.(keys{i})) && ! strcmpi (o.(keys{i}), "off"))
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
  o = read_options (fname, rest,
                    struct ("focus", "simulation", "maxiter", 100,
                            "tol", 1e-8, "lambda", [], "overpar", "off",
                            "tdmax", []));
  if (strcmp (fname, "tfest"))
    check_unused (fname, o, {"lambda", "overpar", "tdmax"});
  endif
  if (! (ischar (o.overpar) && any (strcmpi (o.overpar, {"on", "off"}))))
    error ([fname ":badOption"], "%s: OverPar must be 'on' or 'off'", fname);
  endif
  overpar = strcmpi (o.overpar, "on");
  if (! isempty (o.lambda) && ! (isnumeric (o.lambda) && isscalar (o.lambda)
                                 && isreal (o.lambda) && o.lambda > 0
                                 && isfinite (o.lambda)))
    error ([fname ":badOption"], "%s: Lambda must be a scalar > 0 (rad/s)",
           fname);
  endif
  estimate = strcmp (fname, "tfcoe") && ! isempty (td);
  td_given = td;
  tdmax_given = ! isempty (o.tdmax);
  if (isempty (o.tdmax))
    o.tdmax = T / 2;
  elseif (! (isnumeric (o.tdmax) && isscalar (o.tdmax) && o.tdmax >= 0
             && isfinite (o.tdmax)))
    error ([fname ":badOption"], "%s: TdMax must be a scalar >= 0", fname);
  endif
  if (isempty (td))
    td = zeros (1, nu);
  endif
  if (any (td > T / 2) || (estimate && td > o.tdmax))
    error ([fname ":badInput"], "%s: the delay %g exceeds %g s", fname,
           max (td), min (T / 2, o.tdmax));
  endif
  if (estimate && nz >= np)
    error ([fname ":badInput"],
           "%s: estimating the delay needs nz < np (strictly proper)", fname);
  endif
  df = contsid_focus_filter (fname, d, o.band, 4);
  rule = double (strcmpi (d.intersample, "foh"));
  opts = struct ("model", "oe_ct", "nf", np, "nb", nz + 1, "nk", 0 * np,
                 "delay", td, "intersample", rule, "maxiter", o.maxiter,
                 "tol", o.tol, "estimate_delay", estimate,
                 "delay_max", o.tdmax, "cutoff", 0);
  if (! isempty (o.lambda))
    opts.cutoff = o.lambda;
  endif
  if (strcmp (fname, "tfcoe") && nz < np)
    ## The delay located by tfsrivc's search (its grid, then its
    ## Gauss-Newton refinement; with td also that refinement from td), then
    ## refined with the coefficients by the output-error minimisation from
    ## each start; the lowest loss wins.  (On a ZOH input the loss has a
    ## kink at every whole number of samples of delay, where a local
    ## minimum can hold a gradient method: from td alone the TFCOE demo
    ## stays at 7.4994 s for a true 8 s.)
    [starts, o.tdmax] = srivc_delay_start (fname, df, np, nz, td_given,
                                           o, tdmax_given);
    if (overpar)
      starts{end+1} = overpar_start (fname, d, np, nz, td_given, o);
      starts = starts(! cellfun ("isempty", starts));
    endif
    estimate = true;
    opts.estimate_delay = true;
    opts.delay_max = o.tdmax;
    best = Inf;
    for k = 1:numel (starts)
      opts.delay = starts{k}(end);
      opts.theta_init = starts{k};
      [th, Pk, ik] = call_gateway (fname, df, opts);
      if (k == 1 || ik.loss < best)
        best = ik.loss;
        theta = th;
        P = Pk;
        info = ik;
      endif
    endfor
    if (theta(end) <= 1e-6 * median (diff (d.t)))
      ## At its bound 0 (to 1e-6 samples) the delay is no free parameter (an
      ## active constraint): the minimum over the coefficients with td = 0.
      estimate = false;
      opts.estimate_delay = false;
      opts.delay = 0;
      opts.theta_init = theta(1:end-1);
      [theta, P, info] = call_gateway (fname, df, opts);
      td = 0;
    endif
  else
    [theta, P, info] = call_gateway (fname, df, opts);
    th0 = [];
    if (overpar)
      th0 = overpar_start (fname, d, np, nz, td_given, o);
    endif
    if (! isempty (th0))
      opts.theta_init = th0(1:end-1);
      [th, Pk, ik] = call_gateway (fname, df, opts);
      if (ik.loss < info.loss)
        [theta, P, info] = deal (th, Pk, ik);
      endif
    endif
  endif
  if (nu > 1)
    M = tf_multi (theta, P, np, nz, td);
  else
    den = [1 theta(1:np).'];
    num = theta(np+(1:nz+1)).';
    if (estimate)
      td = theta(end);
    endif
    M = idtf (num, den, "IODelay", td);
    perm = [np + (1:nz+1), 1:np];
    if (estimate)
      perm(end+1) = np + nz + 2;        # getpvec ends with the IODelay
    endif
    M = set_cov (M, P(perm, perm), theta(perm));
  endif
  e = df.y - info.simulated;
  M = set_report (M, fname, d, e, numel (theta), info.iterations,
                  info.converged, info.reason, rows (d.y));
  r = get (M, "Report");
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
## (contsid_tfsrivc): over its grid of delays in [0, TdMax] (TdMax by
## default from the input-output cross-correlation, as tfsrivc, at least
## 2 td0) then refined by Gauss-Newton, and, when td0 is given, refined
## from td0.
function [starts, tdmax] = srivc_delay_start (fname, d, np, nz, td0, o,
                                              tdmax_given)
  tdmax = o.tdmax;
  if (! tdmax_given)
    tdmax = contsid_default_tdmax (d.t, d.y, d.u);
    if (! isempty (td0))
      tdmax = max (tdmax, 2 * td0);
    endif
    tdmax = min (tdmax, o.tdmax);
  endif
  h = median (diff (d.t));
  numtd = 30;
  s = struct ("td0", [], "fixtd", false, "tdmin", 0, "tdmax", tdmax,
              "numtd", numtd, "lambda", o.lambda, "maxiter", 30,
              "tolpar", 1e-5, "tolfun", 1e-8,
              "stepmax", max (tdmax / (numtd - 1), h),
              "stepreduction", 0.5, "theta0", [], "fixed", [],
              "fixed_values", [], "search_only", false,
              "tdmax_auto", ! tdmax_given);
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
  endfor
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
                    struct ("focus", "simulation", "maxiter", 100,
                            "tol", 1e-8, "lambda", [], "overpar", "off",
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
## (np + 1, nz + 1; its delay searched as tfcoe's) is fitted first: the
## output-error loss of an over-parametrised model has fewer non-global
## minima (Soderstrom and Stoica, "Some properties of the output error
## method", Automatica 18(1), 1982), and the extra pole-zero pair can take
## up a delay error (a first-order Pade term).  Its frequency response over
## the band of the record (2 pi / T to the Nyquist frequency) is then
## reduced to the asked orders, the delay with them, by tffcoe's
## frequency-domain output error (contsid_freq), which gives the start.
function th = overpar_start (fname, d, np, nz, td, o)
  args = {np + 1, nz + 1};
  if (! isempty (td))
    args{end+1} = td;
  endif
  args = [args, {"MaxIter", o.maxiter, "Tol", o.tol, "TdMax", o.tdmax}];
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
  T = d.t(end) - d.t(1);
  w = logspace (log10 (2 * pi / T), log10 (pi / h), 200).';
  G = polyval (num, 1i * w) ./ polyval (den, 1i * w) ...
      .* exp (-1i * w * get (Mo, "IODelay"));
  fr = idfrd (G, w, "Ts", 0);
  if (nz < np)
    Mr = contsid_freq ("tffcoe", {fr, np, nz, "TdMax", o.tdmax});
  else
    Mr = contsid_freq ("tffcoe", {fr, np, nz, get(Mo, "IODelay"),
                                  "FixTd", "on"});
  endif
  [num, den] = tfdata (Mr, "vector");
  num = num(end-nz:end);
  th = [den(2:end), num, get(Mr, "IODelay")].';
  if (any (real (roots (den)) >= 0))
    th = [];                            # no stable start: not used
  endif
endfunction
