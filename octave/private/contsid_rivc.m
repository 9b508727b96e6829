## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn {} {[@var{M}, @var{info}, @var{d}] =} contsid_rivc (@var{fname}, @var{args})
## Back-end of rivc, tfrivc, clrivc and cl2srivc: parses the arguments of
## the public function @var{fname} (its @code{varargin} @var{args}), runs
## the core (core/include/ctid/offline/refined_iv_bj.hpp through rivc_mex) and
## returns the plant model @var{M} (an @code{idpoly}, continuous time,
## with the covariance and Report; for tfrivc an @code{idtf}), the
## gateway's @var{info} (C, D, noise_variance, condition, ...) plus the
## derived RT2, YIC, AIC, and the data @var{d}. Every error identifier
## starts with @var{fname}.
## @end deftypefn

function [M, info, d] = contsid_rivc (fname, args)
  switch (fname)
    case "rivc"
      [M, info, d] = run_rivc (args);
    case "clrivc"
      [M, info, d] = run_clrivc (args);
    case "cl2srivc"
      [M, info, d] = run_cl2srivc (args);
    case "tfrivc"
      [M, info, d] = run_tfrivc (args);
    otherwise
      error ("contsid_rivc:badInput", "contsid_rivc: unknown caller %s",
             fname);
  endswitch
  ## the fit's status, made and reported as srivc's; stable: the plant's
  ## denominators (the noise model is discrete-time)
  if (isa (M, "idtf"))
    F = M.Denominator;
  else
    F = M.F;
  endif
  if (! iscell (F))
    F = {F};
  endif
  info.stable = all (cellfun (@(f) all (real (roots (f)) < 0), F));
  [info.status, M] = contsid_fit_status (info, M);
endfunction

## rivc (data, [nb nc nd nf nk], Name, Value) or rivc (data, Mi, ...)
function [M, info, d] = run_rivc (args)
  fname = "rivc";
  [d, rest] = read_data (fname, args, true);
  if (isempty (rest))
    error ("rivc:badInput", "rivc: expected the structure [nb nc nd nf nk]");
  endif
  nn = rest{1};
  nu = columns (d.u);
  theta_init = [];
  if (isa (nn, "idpoly"))
    Mi = nn;
    B = Mi.B;
    F = Mi.F;
    C = Mi.C;
    D = Mi.D;
    if (iscell (B) || iscell (F) || nu > 1)
      error ("rivc:notSupported",
             "rivc: an initial model is supported for one input only");
    endif
    nn = [numel(B), numel(C) - 1, numel(D) - 1, numel(F) - 1, Mi.nk(1)];
    theta_init = [F(2:end) / F(1), B / F(1)];
  endif
  if (nu > 1)
    ## CONTSID's MISO form [nb_1..nb_m nc nd nf_1..nf_m nk_1..nk_m]
    nn = read_orders (fname, nn, 3 * nu + 2,
                      "[nb_1..nb_m nc nd nf_1..nf_m nk_1..nk_m]");
    nn = {nn(1:nu), nn(nu+1), nn(nu+2), nn(nu+3:2*nu+2), nn(2*nu+3:end)};
    if (any (nn{4} < 1) || any (nn{1} < 1) || any (nn{1} > nn{4} + 1))
      error ("rivc:badInput",
             "rivc: every input needs nf_i >= 1 and 1 <= nb_i <= nf_i + 1");
    endif
  else
    nn = num2cell (read_orders (fname, nn, 5, "[nb nc nd nf nk]"));
  endif
  opts = read_options (fname, rest(2:end),
                       {"lambda", "Tol", "MaxIter", "InitMethod", ...
                        "ArmaMethod", "ArmaMaxIter"}, ...
                       {[], [], [], [], [], []});
  e = engine_options (opts, d);
  [e.nb, e.nc, e.nd, e.nf, e.nk] = nn{:};
  init = opts.InitMethod;
  if (isempty (init) && ! isempty (theta_init))
    init = theta_init;      # rivc (data, Mi): Mi starts the iterations
  endif
  start = contsid_init_method (fname, init, e);
  [e, start] = plant_start (fname, start, e, d, d.u);
  [theta, cov, info] = call_mex (fname, d, [], e);
  info = derived (info, d, theta, cov);
  M = plant_model (fname, theta, cov, info, d, e);
  M.Report.Parameters.InitMethod = start_report (start, info);
endfunction

## clrivc (data_yu, data_yr, [nb nc nd nf nk], Mc[, T0, tol, maxiter]
##         [, "ReferenceAt", at])
function [M, info, d] = run_clrivc (args)
  fname = "clrivc";
  [d, rest] = read_data (fname, args);
  if (numel (rest) < 3)
    error ("clrivc:badInput",
           "clrivc: expected data_yu, data_yr, [nb nc nd nf nk] and Mc");
  endif
  ## a trailing name-value pair after the positional arguments
  named = find (cellfun (@ischar, rest(4:end)), 1);
  at = "input";
  init = [];
  if (! isempty (named))
    o = read_options (fname, rest(3+named:end), {"ReferenceAt", ...
                      "InitMethod"}, {at, []});
    at = o.ReferenceAt;
    init = o.InitMethod;
    rest = rest(1:2+named);
    if (! ischar (at) || ! any (strcmpi (at, {"input", "setpoint"})))
      error ("clrivc:badOption",
             "clrivc: ReferenceAt must be 'input' or 'setpoint'");
    endif
  endif
  r = read_loop_signals (fname, rest{1}, rows (d.y), at);
  nn = read_orders (fname, rest{2}, 5, "[nb nc nd nf nk]");
  [num, den] = read_controller (fname, rest{3});
  pos = {"T0", "tol", "maxiter"};
  if (numel (rest) > 6)
    error ("clrivc:badInput", "clrivc: takes at most 7 arguments");
  endif
  opts = struct ("lambda", [], "Tol", [], "MaxIter", [], "ArmaMaxIter", []);
  positional (fname, rest(4:end), pos);
  if (numel (rest) >= 5 && ! isempty (rest{5}))
    opts.Tol = rest{5};
  endif
  if (numel (rest) >= 6 && ! isempty (rest{6}))
    opts.MaxIter = rest{6};
  endif
  e = engine_options (opts, d);
  e.nb = nn(1); e.nc = nn(2); e.nd = nn(3); e.nf = nn(4); e.nk = nn(5);
  if (e.nk != 0)
    error ("clrivc:notSupported", "clrivc: the closed loop takes nk = 0");
  endif
  e.controller_num = num;
  e.controller_den = den;
  ## 'lssvf'/'ivgpmf': the open-loop estimate of y on the measured u
  ## (biased by the loop's noise, but only the start of the iterations)
  start = contsid_init_method (fname, init, e);
  [e, start] = plant_start (fname, start, e, d, d.u);
  [theta, cov, info] = call_mex (fname, d, r, e);
  info = derived (info, d, theta, cov);
  M = plant_model (fname, theta, cov, info, d, e);
  M.Report.Parameters.InitMethod = start_report (start, info);
endfunction

## cl2srivc (data_yu, data_ur, nn_ol, nn_cl[, model, T0, init, tol, maxiter])
function [M, info, d] = run_cl2srivc (args)
  fname = "cl2srivc";
  [d, rest] = read_data (fname, args);
  if (numel (rest) < 3)
    error ("cl2srivc:badInput",
           "cl2srivc: expected data_yu, data_ur, nn_ol and nn_cl");
  endif
  if (numel (rest) > 8)
    error ("cl2srivc:badInput", "cl2srivc: takes at most 9 arguments");
  endif
  ## data_ur = iddata (u, r): its input is the reference r.
  r = read_reference (fname, rest{1}, rows (d.y), 2);
  nol = read_orders (fname, rest{2}, 3, "nn_ol = [nb nf nk]");
  ncl = read_orders (fname, rest{3}, 3, "nn_cl = [nb nf nk]");
  if (nol(1) > nol(2) + 1 || ncl(1) > ncl(2) + 1 || nol(2) < 1
      || ncl(2) < 1)
    error ("cl2srivc:badInput",
           "cl2srivc: each stage needs nf >= 1 and nb <= nf + 1");
  endif
  if (numel (rest) >= 4 && ! isempty (rest{4}))
    error ("cl2srivc:notSupported",
           "cl2srivc: an initial model is not supported; pass []");
  endif
  positional (fname, rest(5:min (end, 5)), {"T0"});
  init = [];
  if (numel (rest) >= 6)
    init = rest{6};
  endif
  ## one method starts both stages (a model could start only one of them)
  start = contsid_init_method (fname, init,
                               struct ("nf", nol(2), "nb", nol(1)), {"model"},
                               ["init_method names the start of both ", ...
                                "stages: 'sriv', 'ivgpmf' or 'lssvf'"]);
  opts = struct ("lambda", [], "Tol", [], "MaxIter", [], "ArmaMaxIter", []);
  if (numel (rest) >= 7 && ! isempty (rest{7}))
    opts.Tol = rest{7};
  endif
  if (numel (rest) >= 8 && ! isempty (rest{8}))
    opts.MaxIter = rest{8};
  endif
  e = engine_options (opts, d);
  e.method = "cl2srivc";
  e.nb = nol(1); e.nf = nol(2); e.nk = nol(3);
  e.cl_nb = ncl(1); e.cl_nf = ncl(2); e.cl_nk = ncl(3);
  ## u_hat is the output of a continuous model: smooth between samples.
  e.intersample = 1;
  [e, start] = two_stage_start (fname, start, e, d, r);
  [theta, cov, info] = call_mex (fname, d, r, e);
  info = derived (info, d, theta, cov);
  M = plant_model (fname, theta, cov, info, d, e);
  M.Report.Parameters.InitMethod = start;
  ## cov is the two-stage estimator's; stage 2's own SRIVC covariance
  ## (white noise, u_hat exact) for comparison.
  M.Report.Parameters.Stage2Covariance = info.stage2_covariance;
  M.Report.Parameters.CovarianceLags = info.covariance_lags;
endfunction

## tfrivc (data, np, nz[, IODelay][, Name, Value]), 'NN', [nd nc]: the
## start by tfsrivc's front-end (delay search, Focus), then the delay
## refined together with RIVC's plant and noise model (contsid_tfsrivc
## with the noise model: Gauss-Newton steps on td on the whitened
## output error, RIVC re-estimated at every delay).
function [M, info, d] = run_tfrivc (args)
  fname = "tfrivc";
  [d, rest] = read_data (fname, args);
  if (numel (rest) < 2)
    error ("tfrivc:badInput", "tfrivc: expected data, np and nz");
  endif
  np = read_orders (fname, rest{1}, 1, "np");
  nz = read_orders (fname, rest{2}, 1, "nz");
  if (np < 1 || nz > np)
    error ("tfrivc:badInput", "tfrivc: need np >= 1 and 0 <= nz <= np");
  endif
  rest = rest(3:end);
  td = [];
  if (! isempty (rest) && isnumeric (rest{1}))
    td = rest{1};
    if (! isreal (td) || ! isscalar (td) || ! isfinite (td) || td < 0)
      error ("tfrivc:badInput", "tfrivc: IODelay must be a scalar >= 0");
    endif
    rest = rest(2:end);
  endif
  ## 'NN' is ours; every other option goes to tfsrivc's front-end (the
  ## plant start and the delay refinement).
  NN = [0 0];
  pass = {};
  if (mod (numel (rest), 2) != 0)
    error ("tfrivc:badInput", "tfrivc: options must be name-value pairs");
  endif
  init = [];
  lambda = [];
  for i = 1:2:numel (rest)
    name = rest{i};
    if (! ischar (name))
      error ("tfrivc:badInput", "tfrivc: option names must be strings");
    endif
    if (strcmpi (name, "NN"))
      NN = read_orders (fname, rest{i+1}, 2, "NN = [nd nc]");
    elseif (strcmpi (name, "InitMethod"))
      init = rest{i+1};
    elseif (strcmpi (name, "Integration"))
      if (contsid_on_off (fname, "Integration", rest{i+1}))
        error ("tfrivc:notSupported", ["tfrivc: Integration 'on' is not ", ...
               "supported (the RIVC iterations cannot hold a coefficient ", ...
               "fixed); tfsrivc and tfcoe enforce an integrator"]);
      endif
    else
      pass(end+1:end+2) = rest(i:i+1);
      if (strcmpi (name, "Lambda"))
        lambda = rest{i+1};
      endif
    endif
  endfor
  start = contsid_init_method (fname, init,
                               struct ("nf", np, "nb", nz + 1));
  data = iddata (d.y, d.u, d.Ts, "InterSample", d.intersample);
  if (isempty (td))
    targs = {data, np, nz, pass{:}};
  else
    targs = {data, np, nz, td, pass{:}};
  endif
  [Ms, o] = contsid_tf_front (fname, targs);
  [num, den] = tfdata (Ms, "vector");
  num = num(end - nz:end);
  tdel = Ms.IODelay;
  opts = struct ("lambda", [], "Tol", o.tolpar, "MaxIter", o.maxiter,
                 "ArmaMaxIter", []);
  e = engine_options (opts, d);
  e.nf = np; e.nb = nz + 1; e.nd = NN(1); e.nc = NN(2);
  e.nk = floor (tdel / d.Ts + 1e-9);
  e.delay = max (tdel - e.nk * d.Ts, 0);
  e.theta_init = [den(2:end) / den(1), num / den(1)];
  ## 'sriv': tfsrivc's model; otherwise the named start at tfsrivc's delay
  ## (tfsrivc's Lambda, when given, is the start's cut-off)
  if (! isempty (lambda))
    e.cutoffs = lambda;
  endif
  if (! strcmp (start.Method, "sriv"))
    [e, start] = plant_start (fname, start, e, d, d.u);
  else
    start.Theta = e.theta_init;
  endif
  ## RIVC at the delay (FixTd 'on') or with the delay refined jointly
  o.noise = NN;
  o.td0 = tdel;
  o.theta0 = e.theta_init(:);
  [num, den, tdel, P, tinfo] = contsid_tfsrivc (fname, d, np, nz, o);
  info = tinfo.engine;
  info.start = Ms;
  theta = [den(2:end), num].';
  nth = np + nz + 1;
  cov = info.covariance;
  if (tinfo.delay_estimated)
    cov = P;                  # [f b td], the whitened output sensitivities
  endif
  f = theta(1:np).';
  b = theta(np+1:end).';
  M = idtf (b, [1 f], "IODelay", tdel);
  ## idtf's parameter order is [b; f (; td)].
  perm = [np + (1:nz+1), 1:np];
  if (tinfo.delay_estimated)
    perm(end+1) = nth + 1;
  endif
  ## (an ill-conditioned fit, e.g. an over-parametrised one, may have no
  ## covariance to report: NaN or not positive semi-definite)
  C = cov(perm, perm);
  if (all (isfinite (C(:))))
    C = (C + C.') / 2;
    if (min (eig (C)) >= -1e-10 * max (norm (C, 1), realmin))
      M = setcov (M, C);
    endif
  endif
  info = derived (info, d, theta, cov(1:nth, 1:nth));
  M.Report.Fit = fit_struct (info, d, numel (theta));
  M.Report.Parameters.IODelay = tdel;
  tdsd = 0;
  if (tinfo.delay_estimated)
    tdsd = sqrt (max (P(end, end), 0));
  endif
  M.Report.Parameters.IODelaySD = tdsd;
  M.Report.Status = "Estimated using TFRIVC";
  M.Report.Method = "tfrivc";
  converged = info.converged && tinfo.converged;
  reason = sprintf ("RIVC: %s; delay: %s", info.reason, tinfo.reason);
  M.Report.Termination = struct ("Iterations", info.iterations,
                                 "DelayIterations", tinfo.iterations,
                                 "Converged", converged,
                                 "Reason", reason);
  M.Report.Parameters.NoiseModel = struct ("C", info.C, "D", info.D,
                                "NoiseVariance", info.noise_variance);
  M.Report.Parameters.InitMethod = start;
  if (! converged)
    warning ("tfrivc:notConverged",
             "tfrivc: no convergence (%s); the last iterate is returned",
             reason);
  endif
endfunction

function [d, rest] = read_data (fname, args, multi = false)
  if (isempty (args))
    error ([fname ":badInput"], "%s: expected the data", fname);
  endif
  d = contsid_getdata (fname, args{1});
  contsid_check_output (fname, d.y);
  rest = args(2:end);
  if (! d.uniform)
    error ([fname ":notSupported"],
           "%s: regularly sampled data only (the noise model is discrete)",
           fname);
  endif
  if (columns (d.u) != 1 && ! multi)
    error ([fname ":notSupported"], "%s: one input only", fname);
  endif
endfunction

function nn = read_orders (fname, nn, count, what)
  if (! isnumeric (nn) || ! isreal (nn) || numel (nn) != count
      || any (! isfinite (nn(:))) || any (nn(:) != fix (nn(:)))
      || any (nn(:) < 0))
    error ([fname ":badInput"],
           "%s: %s must be %d non-negative integers", fname, what, count);
  endif
  nn = double (nn(:).');
endfunction

function r = read_reference (fname, data, n, ~)
  if (isa (data, "iddata"))
    r = get (data, "InputData");
    if (iscell (r))
      r = r{1};
    endif
  else
    r = data;
  endif
  if (! isnumeric (r) || ! isreal (r) || ! isvector (r)
      || any (! isfinite (r(:))))
    error ([fname ":badInput"],
           "%s: the closed-loop data must hold one finite reference r",
           fname);
  endif
  if (numel (r) != n)
    error ([fname ":dimensionMismatch"],
           "%s: the reference r needs %d samples, got %d", fname, n,
           numel (r));
  endif
  r = double (r(:));
endfunction

## Mc: a continuous-time tf/idpoly/idtf, or a struct with num and den
## (descending powers of s).
function [num, den] = read_controller (fname, Mc)
  num = [];
  den = [];
  if (isstruct (Mc) && isscalar (Mc) && isfield (Mc, "num")
      && isfield (Mc, "den"))
    num = Mc.num;
    den = Mc.den;
  elseif (isobject (Mc))
    try
      if (! isa (Mc, "tf"))
        Mc = tf (Mc);
      endif
      if (! isct (Mc))
        error ([fname ":badInput"], "%s: the controller must be continuous",
               fname);
      endif
      [num, den] = tfdata (Mc, "vector");
    catch err
      if (strncmp (err.identifier, fname, numel (fname)))
        rethrow (err);
      endif
      error ([fname ":badInput"],
             "%s: the controller Mc must be a continuous-time tf (%s)",
             fname, err.message);
    end_try_catch
  endif
  if (! isnumeric (num) || ! isnumeric (den) || isempty (num)
      || isempty (den) || ! isreal (num) || ! isreal (den)
      || any (! isfinite ([num(:); den(:)])))
    error ([fname ":badInput"],
           ["%s: the controller Mc must be a continuous-time tf or a ", ...
            "struct with finite num and den"], fname);
  endif
  num = double (num(:).');
  den = double (den(:).');
  k = find (den != 0, 1);
  if (isempty (k))
    error ([fname ":badInput"], "%s: the controller denominator is zero",
           fname);
  endif
  den = den(k:end);
  k = find (num != 0, 1);
  if (isempty (k))
    num = 0;
  else
    num = num(k:end);
  endif
  if (numel (num) > numel (den))
    error ([fname ":badInput"], "%s: the controller must be proper", fname);
  endif
endfunction

## [r1 r] (N-by-2) of the loop u = r1 + C (r - y) from data_yr: an
## iddata (y, r) or a matrix, N-by-2 [r1 r] or one signal that enters where
## `at` says ("input": r1, CONTSID's closedloop demos; "setpoint": r).
function r = read_loop_signals (fname, data, n, at)
  if (isa (data, "iddata"))
    data = get (data, "InputData");
    if (iscell (data))
      data = data{1};
    endif
  endif
  if (isnumeric (data) && isvector (data))
    data = data(:);
  endif
  if (! isnumeric (data) || ! isreal (data) || ndims (data) > 2
      || isempty (data) || columns (data) > 2 || any (! isfinite (data(:))))
    error ([fname ":badInput"],
           "%s: the closed-loop data must hold r or [r1 r] (finite, real)",
           fname);
  endif
  if (rows (data) != n)
    error ([fname ":dimensionMismatch"],
           "%s: the reference r needs %d samples, got %d", fname, n,
           rows (data));
  endif
  data = double (data);
  if (columns (data) == 2)
    r = data;
  elseif (strcmpi (at, "setpoint"))
    r = [zeros(n, 1), data];
  else
    r = [data, zeros(n, 1)];
  endif
endfunction

## CONTSID's positional T0: the first sample used; only 1 (all samples).
function positional (fname, vals, names)
  if (! isempty (vals) && ! isempty (vals{1}))
    T0 = vals{1};
    if (! isnumeric (T0) || ! isscalar (T0) || ! isreal (T0) || T0 != 1)
      error ([fname ":notSupported"],
             "%s: T0 must be 1 (estimation on the whole record)", fname);
    endif
  endif
endfunction

function opts = read_options (fname, args, names, defaults)
  opts = cell2struct (defaults(:), names(:), 1);
  if (mod (numel (args), 2) != 0)
    error ([fname ":badInput"], "%s: options must be name-value pairs",
           fname);
  endif
  for i = 1:2:numel (args)
    if (! ischar (args{i}))
      error ([fname ":badInput"], "%s: option names must be strings", fname);
    endif
    k = find (strcmpi (args{i}, names));
    if (isempty (k))
      error ([fname ":badOption"], "%s: unknown option '%s'", fname,
             args{i});
    endif
    opts.(names{k}) = args{i+1};
  endfor
endfunction

## The options of rivc_mex (checked there, rivc_options of
## core/include/ctid/offline/refined_iv_options.hpp; [] is its default).
function e = engine_options (opts, d)
  e = struct ("intersample", double (strcmpi (d.intersample, "foh")));
  e.tol = opts.Tol;
  e.maxiter = opts.MaxIter;
  e.cutoffs = opts.lambda;
  if (isfield (opts, "ArmaMaxIter"))
    e.arma_maxiter = opts.ArmaMaxIter;
  endif
  if (isfield (opts, "ArmaMethod"))
    e.arma_method = opts.ArmaMethod;
    if (ischar (e.arma_method))
      e.arma_method = lower (e.arma_method);
    endif
  endif
endfunction

## cl2srivc's starts: stage 1 (u on r) from the named start of u on r;
## stage 2 (y on u_hat) from the named start of y on u_hat, u_hat the
## simulation of stage 1's SRIVC run from its start, as the gateway runs
## it (cl2srivc of refined_iv_bj.hpp: the same settings, at least 30
## iterations). start.Stage1Theta reports stage 1's start.
function [e, start] = two_stage_start (fname, start, e, d, r)
  start.Stage1Theta = [];
  if (strcmp (start.Method, "sriv"))
    return;
  endif
  e1 = struct ("nf", e.cl_nf, "nb", e.cl_nb, "nk", e.cl_nk,
               "intersample", 0);
  if (isfield (e, "cutoffs"))
    e1.cutoffs = e.cutoffs;
  endif
  [e1, start1] = plant_start (fname, start, e1,
                              struct ("y", d.u, "Ts", d.Ts), r);
  e.cl_theta_init = e1.theta_init;
  o = struct ("nf", e.cl_nf, "nb", e.cl_nb, "nk", e.cl_nk,
              "theta_init", e1.theta_init, "tol", e.tol,
              "maxiter", max (e.maxiter, 30));
  [~, ~, i1] = contsid_refined_iv (fname, d.u, r, d.Ts, o);
  [e, start] = plant_start (fname, start, e, d, i1.simulated);
  start.Stage1Theta = start1.Theta;
  start.Stabilised = start.Stabilised || start1.Stabilised;
endfunction

## The start of the plant iterations named by start (contsid_init_method)
## on the record d with the input(s) W: e.theta_init, empty for the
## engine's own SRIVC (CLSRIVC) start.
function [e, start] = plant_start (fname, start, e, d, W, rule = [])
  L = struct ("nf", e.nf, "nb", e.nb, "nk", e.nk);
  if (numel (e.nf) > 1)
    L.group = 1:numel (e.nf);
  endif
  if (isempty (rule))
    rule = e.intersample;
  endif
  L.intersample = merge (rule == 1, "foh", "zoh");
  if (isfield (e, "cutoffs"))
    L.cutoffs = e.cutoffs;
  endif
  if (isfield (e, "delay"))
    L.delay = e.delay;
  endif
  [theta0, start] = contsid_init_method (fname, start, L, d.y, W, d.Ts);
  if (! isempty (theta0))
    e.theta_init = theta0;
  endif
endfunction

## Report.Parameters.InitMethod: the start used (Method, Requested,
## Lambda, Theta, Stabilised); the engine's own start reports the SRIVC
## model it found.
function r = start_report (start, info)
  r = start;
  if (strcmp (start.Method, "sriv") && isfield (info, "start_theta"))
    r.Theta = info.start_theta(:).';
  endif
endfunction

function [theta, cov, info] = call_mex (fname, d, r, e)
  if (isfield (e, "theta_init"))
    e.theta_init = e.theta_init(:);
    np = sum (e.nf) + sum (e.nb);
    if (numel (e.theta_init) != np)
      error ([fname ":badInput"], "%s: the initial model needs %d values",
             fname, np);
    endif
    at = cumsum ([0, e.nf]);
    for i = 1:numel (e.nf)
      if (any (real (roots ([1; e.theta_init(at(i)+1:at(i+1))])) >= 0))
        error ([fname ":badInput"], "%s: the initial model must be stable",
               fname);
      endif
    endfor
  endif
  [theta, cov, info] = rivc_mex (fname, double (d.y), double (d.u),
                                 double (d.Ts), r, e);
  if (! info.converged)
    warning ([fname ":notConverged"],
             "%s: no convergence (%s); the last iterate is returned", fname,
             info.reason);
  endif
endfunction

function info = derived (info, d, theta, cov)
  n = rows (d.y);
  np = numel (theta);
  vy = var (d.y, 1);
  sim_err = d.y - info.simulated;
  info.RT2 = 1 - mean (sim_err .^ 2) / vy;
  s2 = max (info.noise_variance, eps * vy);
  th = theta(:);
  info.YIC = log (mean (sim_err .^ 2) / vy) ...
             + log (mean (diag (cov) ./ th .^ 2));
  nparam = np + max (numel (info.C) - 1, 0) + max (numel (info.D) - 1, 0);
  info.AIC = log (s2) + 2 * nparam / n;
endfunction

function F = fit_struct (info, d, np)
  n = rows (d.y);
  e = d.y - info.simulated;
  mse = mean (e .^ 2);
  F = struct ("MSE", mse, "LossFcn", info.noise_variance,
              "FitPercent", 100 * (1 - norm (e) / norm (d.y - mean (d.y))),
              "FPE", info.noise_variance * (1 + np / n) / (1 - np / n));
endfunction

## The continuous plant as an idpoly (idctm) with the covariance of [f b]
## (M.theta, M.covariance: in CONTSID's order [f b]); the noise model
## (rivc, clrivc) in M.C, M.D (q^-1 at Ts: a hybrid model, marked by
## Report.Parameters.NoiseModel.Ts, which present and display read) and
## M.NoiseVariance, with the ARMA covariance in getcov's order (b c d f).
## The plant/noise cross-covariance is not estimated (zero; in open loop
## the two are asymptotically uncorrelated for a Box-Jenkins model).
function M = plant_model (fname, theta, cov, info, d, e)
  nf = sum (e.nf);
  if (numel (e.nf) > 1)
    ## MISO: theta = [f_1 .. f_m b_1 .. b_m], one B_i/F_i per input
    fat = cumsum ([0, e.nf]);
    bat = nf + cumsum ([0, e.nb]);
    F = arrayfun (@(i) [1, theta(fat(i)+1:fat(i+1)).'], 1:numel (e.nf),
                  "UniformOutput", false);
    B = arrayfun (@(i) theta(bat(i)+1:bat(i+1)).', 1:numel (e.nb),
                  "UniformOutput", false);
  else
    F = [1, theta(1:nf).'];
    B = theta(nf+1:end).';
  endif
  report = struct ();
  report.Fit = fit_struct (info, d, numel (theta));
  report.DataUsed = struct ("Length", rows (d.y), "Ts", d.Ts);
  report.Parameters.NoiseModel = struct ("C", info.C, "D", info.D,
                              "NoiseVariance", info.noise_variance,
                              "Ts", d.Ts);
  report.Termination = struct ("Iterations", info.iterations,
                               "Converged", info.converged,
                               "Reason", info.reason);
  M = idctm (struct ("B", {B}, "F", {F}, "nk", e.nk, "Ts", d.Ts,
                     "InterSample", d.intersample, "covariance", cov,
                     "noise_variance", info.noise_variance, "method", fname,
                     "iterations", info.iterations,
                     "converged", info.converged, "Report", report));
  if (numel (info.C) > 1 || numel (info.D) > 1)
    nb = sum (e.nb);
    nc = numel (info.C) - 1;
    nd = numel (info.D) - 1;
    M = set (M, "C", info.C, "D", info.D);
    full = zeros (nb + nc + nd + nf);
    ## [f b] in getpvec's order [b c d f] (MISO: [b_1 .. b_m c d f_1 .. f_m])
    plant = [nb + nc + nd + (1:nf), 1:nb];
    noise = [nb + nc + (1:nd), nb + (1:nc)];  # [d c]
    full(plant, plant) = cov;
    full(noise, noise) = info.noise_covariance;
    M = setcov (M, (full + full.') / 2);
  endif
endfunction
