## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn {} {[@var{M}, @var{RT2}, @var{YIC}, @var{info}] =} contsid_offline (@var{fname}, @var{args})
## Shared back-end of lssvf, ivsvf, srivc and clsrivc: parses the data,
## nn, the cut-off and the options, runs the refined-IV engine
## (@code{contsid_refined_iv}, core/include/ctid/offline/refined_iv.hpp) and builds
## the model (built by @code{idctm},
## which returns an @code{idpoly}, in @code{make_model}). Without a
## cut-off, srivc/clsrivc start from IVSVF at 12 cut-offs log-spaced
## between 5/T and 0.5*pi/Ts; SRIVC runs from the best starts (by
## simulation error) and keeps the best stable, converged result.
## A model that did not converge or is unstable comes with a warning
## (@var{fname}:notConverged, @var{fname}:unstable); one whose simulation
## loss converged while parameters kept moving in directions the data do
## not determine with @var{fname}:overParameterised. A fit whose slowest
## pole crept to p = 0 without converging is repeated with that pole
## declared (@code{integrator_refit}) and, when that converges to a lower
## loss, returned with @var{fname}:integratorDetected.
## @end deftypefn

function [M, RT2, YIC, info] = contsid_offline (fname, args)
  refined = any (strcmp (fname, {"srivc", "clsrivc"}));
  closed = strcmp (fname, "clsrivc");
  if (closed)
    ## clsrivc (data, datacl, nn, Mc, ...)
    if (numel (args) < 4)
      error ("clsrivc:badInput", "clsrivc: expected data, datacl, nn and Mc");
    endif
    datacl = args{2};
    Mc = args{4};
    args = [args(1), args(3), args(5:end)];
  endif
  if (refined)
    form = "f";
    ## [] leaves the option to the core (refined_iv_options.hpp)
    defaults = struct ("lambda_svf", [], "lambda", [], "Tol", [],
                       "MaxIter", [], "InitMethod", [],
                       "svf", "normalised", "InitialState", "zero",
                       "OutputOffset", "auto", "InputOffset", "auto",
                       "TimeScale", "auto", "MaxStarts", []);
  else
    form = "a";
    defaults = struct ("lambda_svf", [], "svf", "normalised");
  endif
  ## CONTSID's MISO form [nb1..nbm nf1..nfm nk1..nkm]: one denominator per
  ## input ('Different'); the parser reads its common-denominator twin.
  if (closed)
    ## where a single external signal r enters the loop: "input" (u = r +
    ## C (0 - y), CONTSID's closedloop demos) or "setpoint" (u = C (r - y))
    defaults.ReferenceAt = "input";
  endif
  if (refined && ! closed)
    ## CONTSID's srivc options that are checked or refused here
    defaults.Denominator = [];
    defaults.Integration = [];
    defaults.T0 = [];
  endif
  [args, nf_each] = different_denominators (fname, refined, args);
  [d, orders, opts] = contsid_recursive_args (fname, form, defaults, args{:});
  if (refined && ! closed)
    contsid_srivc_only_options (fname, opts, nf_each, columns (d.u));
  endif
  n = rows (d.y);
  nu = columns (d.u);
  na = orders.na;
  if (refined && ! isempty (opts.lambda))
    opts.lambda_svf = opts.lambda;
  endif
  t = merge (d.uniform, d.Ts, d.t);
  if (! ischar (opts.svf)
      || ! any (strcmpi (opts.svf, {"normalised", "normalized", "ordinary"})))
    error ([fname ":badOption"], "%s: svf must be 'normalised' or 'ordinary'",
           fname);
  endif

  e = struct ("nb", orders.nb, "nk", orders.nk,
              "intersample", d.intersample);
  if (isempty (nf_each))
    e.nf = na;
    e.group = ones (1, nu);
  else
    e.nf = nf_each;
    e.group = 1:nu;
  endif
  np = sum (e.nf) + sum (e.nb);
  lam = opts.lambda_svf;
  if (! isempty (lam))
    if (! isnumeric (lam) || ! isreal (lam) || ! isscalar (lam)
        || ! isfinite (lam) || lam <= 0)
      error ([fname ":badInput"], ...
             "%s: lambda must be a finite real scalar > 0", fname);
    endif
    e.cutoffs = lam;
    contsid_check_cutoff (fname, lam, d);
  elseif (! refined)
    error ([fname ":badOption"], ...
           "%s: the SVF cut-off lambda (rad/s) is required", fname);
  endif
  if (refined)
    e.method = "srivc";
  else
    e.method = fname;
  endif
  if (closed)
    read_loop ();
  endif

  auto_input_offset = false;
  start = [];
  if (refined)
    read_refined_options ();
    [theta0, start] = contsid_init_method (fname, start, e, d.y, d.u, t);
    if (! isempty (theta0))
      e.theta_init = theta0(:);
      auto_input_offset = false;
    endif
  endif
  [theta, cov, info] = contsid_refined_iv (fname, d.y, d.u, t, e);
  ## info.clipped: the returned iterate had to be pulled back into the
  ## stable region (its unconstrained IV solution is unstable)
  ## Raw units: an input whose mean is not zero (to 1e-8 of its standard
  ## deviation; a mean-removed record has none).
  raw_levels = any (abs (mean (d.u, 1)) > 1e-8 * max (std (d.u, 1, 1),
                                                         realmin));
  ## An operating point: the output offset is estimated and an input's
  ## mean lies more than 5 % of its range from zero (the output's rule,
  ## contsid_start_level). A record at rest there (y0 = G(0) u0 + c) is
  ## fitted without input offsets as a step of u0 from rest, whose
  ## transient the model then bends to fit: y = 13 + G (u - 5), G = 2 /
  ## (s^2 + 1.2 s + 1), noise 0.05, converged without them at RMSE 0.57
  ## with a gain of 1.36, silently (srivc.m %!test). The fit with input
  ## offsets is tried too and kept when it converges to a stable model
  ## whose loss is lower by more than BIC's price of the nu parameters
  ## added: n log (V / V2) > nu log (n).
  operating_point = (auto_input_offset && e.output_offset
                     && info.converged && info.stable
                     && any (abs (mean (d.u, 1))
                             > 0.05 * (max (d.u, [], 1) - min (d.u, [], 1))));
  if (auto_input_offset && (! info.stable
                            || (! info.converged
                                && (info.clipped || raw_levels))
                            || operating_point))
    ## An offset of the input (raw units, a force that does not average to
    ## zero on an integrating axis) drives the estimate toward an unstable
    ## model or keeps it from converging: the fit is repeated with input
    ## offsets and kept when it converges to a stable model with a smaller
    ## loss. (On raw units also after a fit that does not converge
    ## without being clipped: raw EMPS position [1 3 0], whose
    ## iterates cycle at R_T^2 -0.47 and which converges at 0.994 with an
    ## input offset.)
    e2 = e;
    e2.input_offset = true (1, nu);
    try
      [theta2, cov2, info2] = contsid_refined_iv (fname, d.y, d.u, t, e2);
      if (operating_point)
        better = (n * log (info.noise_variance / info2.noise_variance)
                  > nu * log (n));
      else
        better = info2.noise_variance < info.noise_variance;
      endif
      if (info2.converged && info2.stable && better)
        info2.reason = sprintf (["%s; input offset(s) %s estimated (the ", ...
                                 "fit without: %s)"], info2.reason,
                                mat2str (info2.input_offset, 4), info.reason);
        e = e2; theta = theta2; cov = cov2; info = info2;
      endif
    catch
      ## the fit without input offsets stands, with its warning
    end_try_catch
  endif
  info.integrators = zeros (1, numel (e.nf));
  if (refined && ! closed)
    [ok, e2, theta2, cov2, info2] = integrator_refit (fname, d, t, e, theta,
                                                      info);
    from = info2.integrator_refit;   # -1: from the fit, -2: its lowest run
    if (from == -1)
      reason = info2.reason;          # the core's: the refit was not better
    endif
    if (! ok && from < 0 && auto_input_offset && ! any (e.input_offset)
        && (from == -1 || raw_levels))
      ## raw units: the integrator integrates the input's offset too
      e3 = e;
      e3.input_offset = true (1, nu);
      [ok, e2, theta2, cov2, info2] = integrator_refit (fname, d, t, e3,
                                                        theta, info);
    endif
    if (ok)
      e = e2; theta = theta2; cov = cov2; info = info2;
    elseif (from == -1)
      info.reason = reason;
    endif
  endif

  info.lambda = info.cutoff;
  info.output_offset = isfield (e, "output_offset") && e.output_offset;
  if (info.output_offset)
    info.reason = sprintf ("%s; output offset c = %g estimated%s",
                           info.reason, info.offset,
                           merge (ischar (opts.OutputOffset),
                                  " (the record does not start at rest)",
                                  ""));
  endif
  if (refined && ! info.converged)
    warning ([fname ":notConverged"], "%s: %s; the last iterate is returned",
             fname, info.reason);
  endif
  if (! info.stable)
    warning ([fname ":unstable"], "%s: the estimated model is unstable",
             fname);
  endif
  if (! (isfinite (info.noise_variance) && info.noise_variance >= 0))
    error ([fname ":numericalFailure"],
           "%s: the noise variance of the estimate is %g (unstable model?)",
           fname, info.noise_variance);
  endif
  if (any (info.integrators))
    warning ([fname ":integratorDetected"],
             ["%s: the slowest pole of the declared structure moved toward ", ...
              "p = 0 without converging; the model returned has %s ", ...
              "(refitted with it declared: %s)"], fname,
             merge (sum (info.integrators) == 1, "a pole at p = 0",
                    "poles at p = 0"), info.reason);
  endif
  if (refined && info.converged && isfield (info, "determined")
      && ! info.determined)
    ## parameters that still moved when the loss stopped, or a real pole
    ## the data cannot see (the engine: offline/pole_determination.hpp)
    warning ([fname ":overParameterised"], "%s: %s; try a lower order",
             fname, info.reason);
  endif
  if (refined && info.noise_variance * (n - np) / n > 0.99 * var (d.y, 1))
    ## R_T^2 < 0.01: a fixed point of the iteration need not be a useful
    ## model
    warning ([fname ":noFit"],
             ["%s: the simulated output explains less than 1 %% of the ", ...
              "output's variance (R_T^2 < 0.01); try another structure ", ...
              "or start"], fname);
  endif
  M = make_model (fname, e, theta, cov, info, d, nu);
  if (refined)
    if (strcmp (start.Method, "sriv"))
      start.Lambda = info.cutoff;   # the SVF cut-off of the start kept
    endif
    M.Report.Parameters.InitMethod = start;
    info.start = start;
  endif
  M = carried_levels (M, info, nu);
  M = simulation_fit (M, d, np, info.simulated);
  ## the fit's status, one record for the model, info and srivcstruc
  if (refined)
    [info.status, M] = contsid_fit_status (info, M);
  endif
  ## The samples missing from the record (NaN in y or u), bridged by
  ## contsid_recursive_args: per-sample outputs (info.simulated) hold the
  ## present samples only.
  if (isfield (d, "missing"))
    info.missing = d.missing;
  else
    info.missing = false (n, 1);
  endif
  if (nargout > 1)
    s2 = info.noise_variance;
    vy = var (d.y, 1);
    RT2 = 1 - s2 * (n - np) / n / vy;
    th = theta(1:np);
    free = th != 0 | diag (cov(1:np, 1:np)) > 0;   # the declared p = 0 poles
    YIC = log (s2 / vy) + log (mean (diag (cov(free, free)) ./ th(free) .^ 2));
    ## Akaike's criterion as rivc's: log(sigma^2) + 2 (free parameters) / N
    info.AIC = log (max (s2, eps * vy)) + 2 * sum (free) / n;
  endif

  ## The refined-method options into the engine's struct e: the core
  ## checks them (refined_iv_options.hpp); here the words of CONTSID.
  function read_refined_options ()
    e.tol = opts.Tol;
    e.maxiter = opts.MaxIter;
    e.max_starts = opts.MaxStarts;
    start = contsid_init_method (fname, opts.InitMethod, e);
    e.theta_init = start.Theta(:);
    if (! any (strcmpi (opts.InitialState, {"zero", "estimate", "e", "z"})))
      error ([fname ":badOption"],
             "%s: InitialState must be 'zero' or 'estimate'", fname);
    endif
    e.initial_state = any (strcmpi (opts.InitialState, {"estimate", "e"}));
    if (ischar (opts.OutputOffset) && strcmpi (opts.OutputOffset, "auto"))
      ## A record that does not start at rest (raw units, an operating
      ## point) gets an output offset; one that starts at rest does not.
      e.output_offset = contsid_start_level (d.y);
    else
      e.output_offset = logical_option (opts.OutputOffset, "OutputOffset", 1);
    endif
    if (ischar (opts.InputOffset) && strcmpi (opts.InputOffset, "auto"))
      e.input_offset = false (1, nu);
      auto_input_offset = ! closed && isempty (e.theta_init);
    else
      e.input_offset = logical_option (opts.InputOffset, "InputOffset", nu);
    endif
    e.time_scale = opts.TimeScale;
    if (ischar (e.time_scale))
      if (! strcmpi (e.time_scale, "auto"))
        error ([fname ":badOption"],
               "%s: TimeScale must be 'auto' or a scale > 0 (rad/s)", fname);
      endif
      e.time_scale = [];
    endif
  endfunction

  function v = logical_option (v, name, count)
    if (! (islogical (v) || isnumeric (v)) || ! any (numel (v) == [1 count]))
      error ([fname ":badOption"], "%s: %s must be true/false", fname, name);
    endif
    v = logical (v(:).');
  endfunction

  ## clsrivc: the thesis' loop u = r1 + C (r2 - y) (eq. 2.49b) with a
  ## discrete controller or a continuous-time tf (CONTSID's form, datacl =
  ## iddata (y, r)). datacl holds [r1 r2], or one signal r that enters
  ## where opts.ReferenceAt says (r1 = r: "input", r2 = r: "setpoint").
  function read_loop ()
    if (nu != 1)
      error ("clsrivc:badInput", "clsrivc: one input only");
    endif
    at = opts.ReferenceAt;
    if (! ischar (at) || ! any (strcmpi (at, {"input", "setpoint"})))
      error ("clsrivc:badOption",
             "clsrivc: ReferenceAt must be 'input' or 'setpoint'");
    endif
    ## datacl is sampled as the data: with missing samples (bridged), its
    ## rows at the present samples
    present = true (n, 1);
    if (isfield (d, "missing"))
      present = ! d.missing;
    endif
    if (isa (Mc, "tf") && isct (Mc))
      [num, den] = tfdata (Mc, "vector");
      if (numel (num) > numel (den) || ! all (isfinite ([num(:); den(:)])))
        error ("clsrivc:badInput", "clsrivc: the controller must be proper");
      endif
      [r1, r2] = read_datacl (datacl, present, at);
      e.controller = struct ("num", num, "den", den);
      e.reference = [r1, r2];
      return;
    endif
    [r1, r2] = read_datacl (datacl, present, at);
    Ts = NaN;
    if (d.uniform)
      Ts = d.Ts;
    endif
    [c_num, c_den] = contsid_controller ("clsrivc", Mc, Ts);
    e.controller = struct ("num", c_num, "den", c_den, "discrete", true);
    e.reference = [r1, r2];
  endfunction
endfunction

## The engine's integrator refit of the fit (theta, info) (core
## refined_iv.hpp, refit_integrators). A fit whose slowest pole crept
## toward p = 0 without converging (info.integrator_suspected, per
## denominator) has the loss minimum of its structure on the stability
## boundary, an integrator the structure does not declare (an integrating
## plant, e.g. force -> position of an axis); so has a converged fit whose
## lowest-loss run from another start crept so (info.lowest_*;
## mean-removed EMPS position [2 3 0]: R_T^2 0.93 converged, 0.991
## creeping). The engine chooses which run the refit starts from, declares
## that pole at p = 0, and keeps the refit when it converges to a stable
## model whose simulation error is not larger: ok, with info2.integrators
## the poles declared; otherwise info2.integrator_refit says from where it
## was tried (-1 the fit, -2 its lowest run, 0 not at all).
function [ok, e2, theta2, cov2, info2] = integrator_refit (fname, d, t, e,
                                                          theta, info)
  e2 = e;
  e2.integrator_start = struct ("theta", theta, "converged", info.converged,
                                "stable", info.stable, "suspected",
                                double (info.integrator_suspected),
                                "simulated", info.simulated,
                                "reason", info.reason,
                                "lowest_theta", info.lowest_theta,
                                "lowest_suspected",
                                double (info.lowest_integrator_suspected),
                                "lowest_simulated", info.lowest_simulated);
  try
    [theta2, cov2, info2] = contsid_refined_iv (fname, d.y, d.u, t, e2);
  catch
    [theta2, cov2] = deal ([]);
    info2 = struct ("integrator_refit", 0);
  end_try_catch
  e2 = rmfield (e2, "integrator_start");
  ok = info2.integrator_refit == 1;
endfunction

## CONTSID's Denominator ('Common' or 'Different'), checked against the
## layout of nn (2m + 1 entries: common; 3m: one per input, CONTSID's
## default), and its Integration and T0, which srivc does not take.
function contsid_srivc_only_options (fname, opts, nf_each, nu)
  if (! isempty (opts.Denominator))
    v = opts.Denominator;
    if (! ischar (v) || ! any (strcmpi (v, {"common", "different"})))
      error ([fname ":badOption"],
             "%s: Denominator must be 'Common' or 'Different'", fname);
    endif
    diff = strcmpi (v, "different");
    if (nu > 1 && diff == isempty (nf_each))
      layout = merge (diff, "[nb_1..nb_m nf_1..nf_m nk_1..nk_m]",
                      "[nb_1..nb_m nf nk_1..nk_m]");
      error ([fname ":badInput"], "%s: Denominator '%s' needs nn = %s",
             fname, v, layout);
    endif
  endif
  if (! isempty (opts.Integration)
      && contsid_on_off (fname, "Integration", opts.Integration))
    error ([fname ":notSupported"], ["%s: 'Integration' is not taken: ", ...
           "srivc detects a pole at p = 0 itself and refits with it ", ...
           "declared (info.integrators); tfsrivc and tfcoe take it"], fname);
  endif
  if (! isempty (opts.T0))
    error ([fname ":notSupported"], ["%s: 'T0' is not taken: give the ", ...
           "record from its starting sample, data(n0:end)"], fname);
  endif
endfunction

function [args, nf_each] = different_denominators (fname, refined, args)
  nf_each = [];
  if (! refined || numel (args) < 2)
    return;
  endif
  if (isa (args{1}, "iddata"))
    k = 2;
    nu = size (get (args{1}, "InputData"), 2);
  elseif (numel (args) >= 4 && isnumeric (args{2}))
    k = 4;
    nu = min (size (args{2}));
    if (isvector (args{2}))
      nu = 1;
    endif
  else
    return;
  endif
  nn = args{k};
  if (nu > 1 && isnumeric (nn) && isvector (nn) && numel (nn) == 3 * nu
      && all (isfinite (nn)) && all (nn == fix (nn)))
    nn = nn(:).';
    nf_each = nn(nu+1:2*nu);
    if (any (nf_each < 1))
      error ([fname ":badInput"], "%s: nn: every nf must be >= 1", fname);
    endif
    if (any (nn(1:nu) > nf_each + 1))
      error ([fname ":badInput"], ...
             "%s: nn: nb_j must be <= nf_j + 1 (proper model)", fname);
    endif
    args{k} = [nn(1:nu), max(nf_each), nn(2*nu+1:end)];
  endif
endfunction

## The model, built in one place (the idctm call) from the engine's theta.
function M = make_model (fname, e, theta, cov, info, d, nu)
  Ts = [];
  if (d.uniform)
    Ts = d.Ts;
  endif
  B = info.B;
  F = info.F;
  np = sum (e.nf) + sum (e.nb);
  th = theta(1:np);
  P = cov(1:np, 1:np);
  report = fit_report (d.y, info.noise_variance, rows (d.y), np);
  if (numel (F) > 1)
    ## 'Different' denominators: a model with one F per input where the
    ## model class has them, else the exact common-denominator form
    ## B_j prod_(i != j) F_i / prod F_i.
    try
      M = idctm (struct ("B", {B}, "F", {F}, "nk", e.nk, "Ts", Ts,
                         "InterSample", d.intersample, "covariance", P,
                         "noise_variance", info.noise_variance,
                         "method", fname, "iterations", info.iterations,
                         "converged", info.converged, "Report", report));
      return;
    catch
    end_try_catch
    Fc = 1;
    for j = 1:nu
      Fc = conv (Fc, F{j});
    endfor
    for j = 1:nu
      Bj = B{j};
      for i = [1:j-1, j+1:nu]
        Bj = conv (Bj, F{i});
      endfor
      B{j} = Bj;
    endfor
    F = Fc;
    th = [F(2:end).'; cell2mat(cellfun (@(b) b(:), B(:), "UniformOutput",
                                        false))];
    P = [];                              # not in this parameterisation
  else
    F = F{1};
  endif
  if (numel (B) == 1)
    B = B{1};
  endif
  M = idctm (struct ("B", {B}, "F", F, "nk", e.nk, "Ts", Ts,
                     "InterSample", d.intersample, "covariance", P,
                     "noise_variance", info.noise_variance, "method", fname,
                     "iterations", info.iterations,
                     "converged", info.converged, "Report", report));
endfunction

## Report.Fit of the model: s2 is the simulation-error variance with
## n - np degrees of freedom, so the mean square error is s2 (n - np) / n.
function r = fit_report (y, s2, n, np)
  mse = s2 * (n - np) / n;
  r.Fit = struct ("MSE", mse, "LossFcn", mse,
                  "FitPercent", 100 * (1 - sqrt (mse / var (y, 1))),
                  "FPE", mse * (1 + np / n) / (1 - np / n));
  r.DataUsed = struct ("Length", n);
endfunction

## The levels the model was estimated with, in MATLAB's
## Report.DataUsed.OutputOffset and InputOffset (the offsets removed from
## the data: y - OutputOffset = M (u - InputOffset)), so that the model as
## estimated can be simulated on raw data (without them, residtrace and
## srivcstruc would simulate a raw-record model 180 degrees off):
## OutputOffset = c, InputOffset = -d (the engine's u + d).
function M = carried_levels (M, info, nu)
  c = 0;
  if (isfield (info, "output_offset") && info.output_offset
      && isfield (info, "offset"))
    c = info.offset;
  endif
  din = zeros (1, nu);
  if (isfield (info, "input_offset") && numel (info.input_offset) == nu)
    din = info.input_offset(:).';
  endif
  r = M.Report;
  r.DataUsed.OutputOffset = c;
  r.DataUsed.InputOffset = -din;
  M.Report = r;
endfunction

## Report.Fit as the SITB defines it: the fit of the model's simulation
## (from rest, the data's input and hold, at the levels it carries) to the
## estimation output, the numbers comparec reports on the same data.
## Where comparec's simulator
## fails (simc on stiff high-order models, e.g. coefficients ~1e11), the
## engine's own simulation of the model (exact ZOH/FOH filters) is used.
function M = simulation_fit (M, d, np, simulated)
  if (d.uniform)
    data = iddata (d.y, d.u, d.Ts, "InterSample", d.intersample);
  else
    data = iddata (d.y, d.u, "SamplingInstants", d.t,
                   "InterSample", d.intersample);
  endif
  try
    [~, est] = comparec (data, M);
    mse = est.MSE;
    fit = est.Fit;
  catch
    e = d.y - simulated(:);
    mse = mean (e .^ 2);
    fit = 100 * (1 - norm (e) / norm (d.y - mean (d.y)));
  end_try_catch
  n = rows (d.y);
  r = M.Report;
  r.Fit = struct ("MSE", mse, "LossFcn", mse, "FitPercent", fit,
                  "FPE", mse * (1 + np / n) / (1 - np / n));
  M.Report = r;
endfunction

## [r1 r2] from datacl: N-by-2 [r1 r2], or one signal r placed by `at`
## ("input": r1 = r, r2 = 0; "setpoint": r1 = 0, r2 = r). CONTSID: datacl
## = iddata (y, r), the reference is its input.
function [r1, r2] = read_datacl (datacl, present, at)
  n = numel (present);
  if (isa (datacl, "iddata"))
    datacl = get (datacl, "InputData");
    if (iscell (datacl))
      datacl = datacl{1};
    endif
  endif
  if (! isnumeric (datacl) || ! isreal (datacl) || ndims (datacl) > 2
      || any (! isfinite (datacl(:))))
    error ("clsrivc:badInput", ...
           ["clsrivc: datacl must hold the external signals [r1 r2] ", ...
            "(finite, real)"]);
  endif
  if (isvector (datacl))
    datacl = datacl(:);
  endif
  if (rows (datacl) != n || columns (datacl) > 2)
    error ("clsrivc:dimensionMismatch", ...
           "clsrivc: datacl must be %d-by-1 (r) or %d-by-2 ([r1 r2])", n, n);
  endif
  r1 = double (datacl(present, 1));
  if (columns (datacl) == 2)
    r2 = double (datacl(present, 2));
  elseif (strcmpi (at, "setpoint"))
    r2 = r1;
    r1 = zeros (size (r2));
  else
    r2 = zeros (size (r1));
  endif
endfunction
