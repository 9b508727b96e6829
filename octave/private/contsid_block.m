## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn {} {[@var{M}, @var{Infos}, @var{yhat}] =} contsid_block (@var{fname}, @var{args})
## The shared back-end of @code{hsrivc}, @code{hrivc} and @code{hwsrivc}
## (block-oriented models by refined IV, core
## @file{core/include/ctid/offline/hammerstein.hpp} through
## @code{hammerstein_mex}). @var{fname} names the caller in every error
## identifier; @var{args} is its argument list: data (an @code{iddata} or
## y, u, Ts), @var{nn}, then CONTSID's positional options (lambda0, t0,
## init_method, tol, maxiter, arma_method; [] for a default) or name-value
## pairs (@code{Tol}, @code{MaxIter}, @code{lambda}, @code{InitMethod},
## @code{ArmaMethod}). The start method is read by
## @code{contsid_init_method}; @code{Infos.InitMethod} and
## @code{Report.Parameters.InitMethod} say which start was used.
## @end deftypefn

function [M, Infos, yhat] = contsid_block (fname, args)
  d = contsid_getdata (fname, args{:});
  contsid_check_output (fname, d.y);
  rest = args(d.nconsumed+1:end);
  if (isempty (rest))
    error ([fname ":badInput"], "%s: the structure nn is missing", fname);
  endif
  nn = rest{1};
  rest = rest(2:end);
  if (! isnumeric (nn) || ! isreal (nn) || ! isvector (nn)
      || any (! isfinite (nn)) || any (nn != round (nn)) || any (nn < 0))
    error ([fname ":badInput"], ...
           "%s: nn must be a vector of non-negative integers", fname);
  endif
  nn = double (nn(:).');
  o = struct ("model", fname, "nc", 0, "nd", 0, "nw", 1);
  W = d.u;
  switch (fname)
    case "hsrivc"
      if (numel (nn) != 3)
        error ("hsrivc:badInput", "hsrivc: nn must be [nb nf nk]");
      endif
      [o.nb, o.nf, o.nk] = deal (nn(1), nn(2), nn(3));
    case "hrivc"
      if (numel (nn) != 5)
        error ("hrivc:badInput", "hrivc: nn must be [nb nc nd nf nk]");
      endif
      [o.nb, o.nc, o.nd, o.nf, o.nk] = deal (nn(1), nn(2), nn(3), nn(4),
                                            nn(5));
    case "hwsrivc"
      if (numel (nn) == 3)
        nn = [nn 3 3];
      elseif (numel (nn) != 5)
        error ("hwsrivc:badInput",
               "hwsrivc: nn must be [nb nf+1 nk] or [nb nf+1 nk lenH lenW]");
      endif
      if (columns (d.u) != 1)
        error ("hwsrivc:badInput", "hwsrivc: the data must have one input u");
      endif
      if (nn(2) < 2 || nn(4) < 1 || nn(5) < 1)
        error ("hwsrivc:badInput",
               "hwsrivc: nn(2) = nf + 1 must be >= 2, lenH and lenW >= 1");
      endif
      [o.nb, o.nf, o.nk, o.nw] = deal (nn(1), nn(2) - 1, nn(3), nn(5));
      W = d.u .^ (1:nn(4));
  endswitch
  if (o.nf < 1 || o.nb < 1)
    error ([fname ":badInput"], "%s: nb and nf must be >= 1", fname);
  endif
  if (any (all (W == 0, 1)))
    error ([fname ":badInput"], "%s: a basis column of the input is zero",
           fname);
  endif
  if (strcmp (fname, "hwsrivc"))
    o.maxiter = 100;      # the damped Wiener fixed point converges slowly
  endif
  o.intersample = double (strcmpi (d.intersample, "foh"));
  init = [];
  arma = "pem";
  read_options ();
  t = merge (d.uniform, d.Ts, d.t);
  ## The start of the first refined-IV pass: the MISO [f B_1 .. B_l] of
  ## the basis channels (contsid_init_method: the engine's, LSSVF, IVSVF
  ## or a model, e.g. a previous MISO model).
  l = columns (W);
  L = struct ("nf", o.nf, "nb", repmat (o.nb, 1, l),
              "nk", repmat (o.nk, 1, l),
              "intersample", merge (o.intersample == 1, "foh", "zoh"));
  if (isfield (o, "cutoffs"))
    L.cutoffs = o.cutoffs;
  endif
  if (strcmp (fname, "hwsrivc"))
    start = contsid_init_method (fname, init, L,
                                 {"ivgpmf", "lssvf", "model"},
                                 ["the first pass regresses on powers of ", ...
                                  "the measured y, which a one-step SVF ", ...
                                  "estimate cannot start; 'sriv' only"]);
  else
    start = contsid_init_method (fname, init, L);
  endif
  [theta0, start] = contsid_init_method (fname, start, L, d.y, W, t);
  if (! isempty (theta0))
    o.theta_init = theta0(:);
  endif
  if (strcmp (fname, "hrivc"))
    o.arma_method = arma;
  endif
  [sep, cov, info] = hammerstein_mex (fname, d.y, W, t, o);
  if (! info.converged)
    warning ([fname ":notConverged"], "%s: %s; the last iterate is returned",
             fname, info.reason);
  endif

  n = rows (d.y);
  l = numel (info.alpha);
  nf = o.nf;
  nb = o.nb;
  F = [1 info.f(:).'];
  b = info.b(:).';
  alpha = info.alpha(:).';
  if (d.uniform)
    Ts = d.Ts;
  else
    Ts = [];
  endif
  np = numel (sep);
  yh = info.simulated;
  report = fit_report (d.y, yh, np);
  report.Method = fname;
  report.Parameters.InitMethod = start;
  ilin = 1:(nf + nb);
  Mlin = idctm (struct ("B", b, "F", F, "nk", o.nk, "Ts", Ts,
                        "InterSample", d.intersample,
                        "covariance", cov(ilin, ilin),
                        "noise_variance", info.noise_variance,
                        "method", fname, "iterations", info.iterations,
                        "converged", info.converged, "Report", report));
  sd = sqrt (max (diag (cov), 0)).';
  yhat = yh;
  vy = var (d.y, 1);
  s2 = info.noise_variance;
  RT2 = 1 - s2 * (n - np) / n / vy;
  YIC = log (s2 / vy) + log (mean (diag (cov) ./ sep .^ 2));
  AIC = log (s2) + 2 * np / n;
  Infos = struct ("modelLin", Mlin, "InfoCriterion",
                  struct ("RT2", RT2, "YIC", YIC, "AIC", AIC),
                  "Cond_IPM", info.condition, "iternum", info.iterations,
                  "converged", info.converged, "reason", info.reason,
                  "theta", sep, "covariance", cov, "sd", sd,
                  "InitMethod", start, "ArmaMethod", arma);
  if (strcmp (fname, "hwsrivc"))
    Infos.NL_H = alpha(:);
    Infos.NL_W = info.beta(:);
    Infos.NL_H_sd = [0 sd(nf+nb+1:nf+nb+l-1)].';
    Infos.NL_W_sd = [0 sd(nf+nb+l:end)].';
    M = Mlin;
    return;
  endif
  Infos.NLinCoeff = alpha;
  Infos.NLinCoeff_sd = [0 sd(nf+nb+1:end)];
  Bm = info.theta_miso(nf+1:end);
  Bm = reshape (Bm, nb, l).';
  if (l == 1)
    Bc = Bm;
  else
    Bc = mat2cell (Bm, ones (1, l), nb);
  endif
  M = idctm (struct ("B", {Bc}, "F", F, "nk", o.nk * ones (1, l), "Ts", Ts,
                     "InterSample", d.intersample,
                     "covariance", info.cov_miso,
                     "noise_variance", info.noise_variance,
                     "method", fname, "iterations", info.iterations,
                     "converged", info.converged, "Report", report));
  if (strcmp (fname, "hrivc"))
    ## the innovations: the simulation residual whitened by D/C
    innov = filter (info.d(:).', info.c(:).', d.y - yh);
    Infos.Noisemodel = idpoly (1, [], info.c(:).', info.d(:).', [],
                               var (innov, 1), ifelse_ts (Ts));
  else
    Infos.Noisemodel = idpoly (1, [], 1, 1, [], info.noise_variance,
                               ifelse_ts (Ts));
  endif
  Infos.present = sprintf ("%s", evalc ("present (M)"));

  ## Options: CONTSID's positional list or name-value pairs.
  function read_options ()
    if (isempty (rest))
      return;
    endif
    if (ischar (rest{1}))
      if (mod (numel (rest), 2) != 0)
        error ([fname ":badOption"], ...
               "%s: options must be name-value pairs", fname);
      endif
      for k = 1:2:numel (rest)
        name = rest{k};
        if (! ischar (name))
          error ([fname ":badOption"], "%s: option names must be strings",
                 fname);
        endif
        set_option (lower (name), rest{k+1});
      endfor
      return;
    endif
    ## CONTSID's positional forms: hsrivc/hrivc (data, nn, lambda0, t0,
    ## init_method, tol, maxiter, arma_method); hwsrivc (data, nn, model,
    ## tol, maxiter), whose model is its start (init_method)
    if (strcmp (fname, "hwsrivc"))
      names = {"initmethod", "tol", "maxiter"};
    else
      names = {"lambda", "t0", "initmethod", "tol", "maxiter", "armamethod"};
    endif
    if (numel (rest) > numel (names))
      error ([fname ":badInput"], "%s: too many arguments", fname);
    endif
    for k = 1:numel (rest)
      if (! isempty (rest{k}))
        set_option (names{k}, rest{k});
      endif
    endfor
  endfunction

  function set_option (name, v)
    switch (name)
      case "tol"
        if (! isnumeric (v) || ! isscalar (v) || ! isreal (v) || ! (v > 0)
            || ! isfinite (v))
          error ([fname ":badOption"], "%s: Tol must be a scalar > 0", fname);
        endif
        o.tol = double (v);
      case "maxiter"
        if (! isnumeric (v) || ! isscalar (v) || ! isreal (v) || v < 1
            || v != round (v))
          error ([fname ":badOption"], "%s: MaxIter must be an integer >= 1",
                 fname);
        endif
        o.maxiter = double (v);
      case "lambda"
        if (! isnumeric (v) || ! isscalar (v) || ! isreal (v) || ! (v > 0)
            || ! isfinite (v))
          error ([fname ":badOption"], "%s: lambda must be a scalar > 0",
                 fname);
        endif
        o.cutoffs = double (v);
      case "t0"
        if (! isnumeric (v) || ! isscalar (v) || v != 0)
          error ([fname ":notSupported"], ...
                 "%s: only t0 = 0 (the whole record) is supported", fname);
        endif
      case "initmethod"
        init = v;           # read by contsid_init_method
      case "armamethod"
        if (! ischar (v) || ! any (strcmpi (v, {"pem", "ivarma"})))
          error ([fname ":badOption"],
                 "%s: ArmaMethod must be 'pem' or 'ivarma'", fname);
        endif
        arma = lower (v);
        if (! strcmp (fname, "hrivc") && strcmp (arma, "ivarma"))
          error ([fname ":notSupported"],
                 ["%s: ArmaMethod 'ivarma' is not supported: the noise ", ...
                  "is white here, there is no ARMA model to fit (hrivc ", ...
                  "has one)"], fname);
        endif
      otherwise
        error ([fname ":badOption"], "%s: unknown option '%s'", fname, name);
    endswitch
  endfunction
endfunction

function r = fit_report (y, yh, np)
  n = rows (y);
  e = y - yh(:);
  mse = mean (e .^ 2);
  r.Fit = struct ("MSE", mse, "LossFcn", mse,
                  "FitPercent", 100 * (1 - norm (e) / norm (y - mean (y))),
                  "FPE", mse * (1 + np / n) / (1 - np / n));
  r.DataUsed = struct ("Length", n);
endfunction

function Ts = ifelse_ts (Ts)
  if (isempty (Ts))
    Ts = 1;
  endif
endfunction
