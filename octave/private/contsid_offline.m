## -*- texinfo -*-
## @deftypefn {} {[@var{M}, @var{RT2}, @var{YIC}] =} contsid_offline (@var{fname}, @var{args})
## Shared back-end of lssvf, ivsvf, srivc and clsrivc: parses the data,
## nn, the cut-off and the options, calls the compiled gateway and builds
## the idctm model. For srivc/clsrivc without a cut-off, SRIVC is started
## from IVSVF at 12 cut-offs log-spaced between 5/T and 0.5*pi/Ts and the
## result with the smallest simulation-error variance is kept.
## @end deftypefn

function [M, RT2, YIC] = contsid_offline (fname, args)
  refined = any (strcmp (fname, {"srivc", "clsrivc"}));
  closed = strcmp (fname, "clsrivc");
  c_num = []; c_den = []; r1 = []; r2 = [];
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
    defaults = struct ("lambda_svf", [], "lambda", [], "Tol", 1e-6,
                       "MaxIter", 20, "InitMethod", "ivsvf",
                       "svf", "normalised");
  else
    form = "a";
    defaults = struct ("lambda_svf", [], "svf", "normalised");
  endif
  [d, orders, opts] = contsid_recursive_args (fname, form, defaults, args{:});
  n = rows (d.y);
  np = orders.np;
  na = orders.na;
  if (refined && ! isempty (opts.lambda))
    opts.lambda_svf = opts.lambda;
  endif
  if (d.uniform)
    t = d.Ts;
  else
    t = d.t;
  endif
  if (closed)
    [r1, r2] = read_datacl (datacl, n);
    [c_num, c_den] = read_controller (Mc, d);
  endif
  if (! ischar (opts.svf)
      || ! any (strcmpi (opts.svf, {"normalised", "normalized", "ordinary"})))
    error ([fname ":badOption"], "%s: svf must be 'normalised' or 'ordinary'",
           fname);
  endif
  tol = 1e-6; maxiter = 20; theta_init = [];
  if (refined)
    tol = opts.Tol; maxiter = opts.MaxIter;
    if (! isnumeric (tol) || ! isreal (tol) || ! isscalar (tol) || ! (tol > 0))
      error ([fname ":badInput"], "%s: Tol must be a real scalar > 0", fname);
    endif
    if (! isnumeric (maxiter) || ! isscalar (maxiter)
        || maxiter != fix (maxiter) || maxiter < 1)
      error ([fname ":badInput"], "%s: MaxIter must be an integer >= 1", fname);
    endif
    theta_init = init_estimate (fname, opts.InitMethod, orders);
  endif

  lam = opts.lambda_svf;
  if (isempty (lam))
    if (! refined)
      error ([fname ":badOption"], ...
             "%s: the SVF cut-off lambda (rad/s) is required", fname);
    endif
    T = t(end) - t(1);
    if (d.uniform)
      T = (n - 1) * d.Ts;
      nyquist = pi / d.Ts;
    else
      nyquist = pi / median (diff (d.t));
    endif
    candidates = logspace (log10 (5 / T), log10 (0.5 * nyquist), 12);
  else
    if (! isnumeric (lam) || ! isreal (lam) || ! isscalar (lam)
        || ! isfinite (lam) || lam <= 0)
      error ([fname ":badInput"], ...
             "%s: lambda must be a finite real scalar > 0", fname);
    endif
    candidates = lam;
  endif
  g = struct ("intersample", d.intersample, "na", na, "nb", orders.nb,
              "nk", orders.nk, "svf", lower (opts.svf), "method", fname);
  if (refined)
    g.tol = tol;
    g.maxiter = maxiter;
    g.theta_init = theta_init;
  endif
  if (closed)
    g.controller_num = c_num;
    g.controller_den = c_den;
    g.r1 = r1;
    g.r2 = r2;
  endif
  best = [];
  for lam_i = candidates
    g.lambda_svf = lam_i;
    try
      [theta, cov, s2, iters, conv] = offline_mex (fname, d.y, d.u, t, g);
    catch err
      if (numel (candidates) > 1 && ! isempty (strfind (err.identifier,
                                                         "numericalFailure")))
        continue;                        # that cut-off failed; try the next
      endif
      contsid_rethrow (err);
    end_try_catch
    if (isempty (best) || s2 < best.s2)
      best = struct ("theta", theta, "cov", cov, "s2", s2, "iters", iters,
                     "conv", conv, "lambda", lam_i);
    endif
  endfor
  if (isempty (best))
    error ([fname ":numericalFailure"], ...
           "%s: no cut-off frequency gave an estimate", fname);
  endif
  if (! best.conv)
    warning ([fname ":notConverged"], ...
             ["%s: no convergence in %d iterations; the last iterate ", ...
              "is returned"],
             fname, best.iters);
  endif
  a = best.theta(1:na).';
  B = {};
  off = na;
  for j = 1:numel (orders.nb)
    B{j} = best.theta(off+1:off+orders.nb(j)).';
    off += orders.nb(j);
  endfor
  if (numel (B) == 1)
    B = B{1};
  endif
  Ts = [];
  if (d.uniform)
    Ts = d.Ts;
  endif
  M = idctm (struct ("B", {B}, "F", [1 a], "nk", orders.nk, "Ts", Ts,
                     "InterSample", d.intersample, "covariance", best.cov,
                     "noise_variance", best.s2, "method", fname,
                     "iterations", best.iters, "converged", best.conv,
                     "Report", fit_report (d.y, best.s2, n, np)));
  if (nargout > 1)
    RT2 = 1 - best.s2 * (n - np) / n / var (d.y, 1);
    YIC = log (best.s2 / var (d.y, 1)) ...
          + log (mean (diag (best.cov) ./ best.theta .^ 2));
  endif
endfunction

## Report.Fit of the model: best.s2 is the simulation-error variance with
## n - np degrees of freedom, so the mean square error is s2 (n - np) / n.
function r = fit_report (y, s2, n, np)
  mse = s2 * (n - np) / n;
  r.Fit = struct ("MSE", mse, "LossFcn", mse,
                  "FitPercent", 100 * (1 - sqrt (mse / var (y, 1))),
                  "FPE", mse * (1 + np / n) / (1 - np / n));
  r.DataUsed = struct ("Length", n);
endfunction

function theta = init_estimate (fname, init, orders)
  theta = [];
  if (ischar (init) && strcmpi (init, "ivsvf"))
    return;
  endif
  if (isa (init, "idpoly"))
    init = init.theta;
  endif
  if (! isnumeric (init) || ! isreal (init) || numel (init) != orders.np
      || any (! isfinite (init)))
    error ([fname ":badOption"], ...
           "%s: InitMethod must be 'ivsvf', an idpoly or %d values [f b]",
           fname, orders.np);
  endif
  theta = double (init(:));
  if (any (real (roots ([1; theta(1:orders.na)])) >= 0))
    error ([fname ":badInput"], "%s: the initial model must be stable", fname);
  endif
endfunction

function [r1, r2] = read_datacl (datacl, n)
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
           "clsrivc: datacl must be %d-by-1 (r1) or %d-by-2 ([r1 r2])", n, n);
  endif
  r1 = double (datacl(:, 1));
  if (columns (datacl) == 2)
    r2 = double (datacl(:, 2));
  else
    r2 = zeros (n, 1);
  endif
endfunction

function [num, den] = read_controller (C, d)
  Ts = NaN;
  if (d.uniform)
    Ts = d.Ts;
  endif
  [num, den] = contsid_controller ("clsrivc", C, Ts);
endfunction
