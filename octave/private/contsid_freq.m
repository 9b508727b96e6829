## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn {} {[@var{M}, @var{info}] =} contsid_freq (@var{fname}, @var{args})
## The shared back-end of the frequency-domain estimators (core
## @file{core/include/ctid/offline/freq_srivc.hpp} through @code{freq_srivc_mex}):
## @code{srivc} on an @code{idfrd} or frequency-domain @code{iddata}
## (@var{args} = @{data, nn, name, value, ..@}, an @code{idpoly}), and
## @code{tffsrivc}/@code{tffcoe} (@var{args} = @{data, np, nz [, IODelay],
## name, value, ..@} or @{data, Mi, ..@}, an @code{idtf}) on those or on
## regular time-domain relay-feedback data, whose limit cycle is turned
## into frequency data first (see @code{tffsrivc}). @var{fname} names the
## caller in every error identifier.
## @end deftypefn

function [M, info] = contsid_freq (fname, args)
  if (numel (args) < 2)
    error ([fname ":badInput"], "%s: expected the data and the structure",
           fname);
  endif
  data = args{1};
  opts = struct ("Tol", [], "MaxIter", [], "TdMin", 0, "TdMax", [],
                 "NumTd", [], "FixTd", "off", "IntSamp", "on",
                 "TolPar", [], "TolFun", [], "StepMax", [],
                 "StepReduction", [], "Lambda", []);
  o = struct ();
  theta_init = [];
  td0 = [];
  pem = any (strcmp (fname, {"oe", "tfest"}));
  band = [];
  if (pem)
    ## oe/tfest: orders and options already read by contsid_pem (spec)
    spec = args{2};
    [na, nb, band] = deal (spec.na, spec.nb, spec.band);
    td0 = spec.delay;
    opts.FixTd = "on";
    opts.MaxIter = spec.maxiter;
    opts.Tol = spec.tol;
    rest = {};
  elseif (strcmp (fname, "srivc"))
    nn = args{2};
    if (! isnumeric (nn) || ! isreal (nn) || ! any (numel (nn) == [2 3])
        || any (nn != round (nn)) || any (nn < 0))
      error ("srivc:badInput",
             "srivc: on frequency data nn must be [nb nf] or [nb nf 0]");
    endif
    if (numel (nn) == 3 && nn(3) != 0)
      error ("srivc:notSupported",
             "srivc: a delay nk on frequency data is not supported");
    endif
    [nb, na] = deal (nn(1), nn(2));
    rest = args(3:end);
  else
    if (isa (args{2}, "idtf"))
      Mi = args{2};
      [num, den] = tfdata (Mi, "v");
      num = num(find (num != 0, 1):end);
      na = numel (den) - 1;
      nb = max (numel (num), 1);
      if (all (isfinite ([num(:); den(:)])) && ! isempty (num))
        theta_init = [den(2:end) / den(1), num / den(1)];
      endif
      td0 = get (Mi, "IODelay");
      rest = args(3:end);
    else
      if (numel (args) < 3)
        error ([fname ":badInput"], "%s: expected data, np and nz", fname);
      endif
      [np, nz] = deal (args{2:3});
      if (! isnumeric (np) || ! isscalar (np) || np != round (np) || np < 1
          || ! isnumeric (nz) || ! isscalar (nz) || nz != round (nz)
          || nz < 0 || nz > np)
        error ([fname ":badInput"],
               "%s: np must be an integer >= 1 and nz one in 0..np", fname);
      endif
      na = double (np);
      nb = double (nz) + 1;
      rest = args(4:end);
      if (! isempty (rest) && isnumeric (rest{1}))
        td0 = rest{1};
        rest = rest(2:end);
        if (! isscalar (td0) || ! isreal (td0) || ! (td0 >= 0)
            || ! isfinite (td0))
          error ([fname ":badInput"], "%s: IODelay must be a scalar >= 0",
                 fname);
        endif
      endif
    endif
  endif
  if (any (na < 1) || any (nb < 1) || any (nb > na + 1))
    error ([fname ":badInput"], ["%s: the orders must be nf >= 1 and "
           "1 <= nb <= nf + 1"], fname);
  endif
  opts = contsid_options (fname, opts, rest);
  fix_td = onoff (opts.FixTd, "FixTd");
  intsamp = onoff (opts.IntSamp, "IntSamp");

  [w, Y, U, period, Ts] = frequency_data (data);
  ## the Focus band, the rows of zero input and the default TdMax: the
  ## core's (freq_srivc_options.hpp, freq_fit_data)
  o.na = na;
  o.nb = nb;
  o.band = band;
  if (isfinite (period))
    o.period = period;
  endif
  tol = opts.Tol;
  if (isempty (tol))
    tol = opts.TolPar;
  endif
  if (! isempty (tol))
    check_positive (tol, "Tol");
    o.tol = tol;
  endif
  if (! isempty (opts.MaxIter))
    if (! isscalar (opts.MaxIter) || opts.MaxIter < 1
        || opts.MaxIter != round (opts.MaxIter))
      error ([fname ":badOption"], "%s: MaxIter must be an integer >= 1",
             fname);
    endif
    o.maxiter = opts.MaxIter;
  endif
  if (! isempty (theta_init))
    o.theta_init = theta_init;
  endif
  estimate_td = ! strcmp (fname, "srivc") && ! fix_td;
  if (fix_td && isempty (td0))
    error ([fname ":badInput"], "%s: FixTd 'on' needs the IODelay", fname);
  endif
  if (! isempty (td0))
    o.delay = td0;
  endif
  if (estimate_td)
    o.estimate_delay = true;
    check_scalar (opts.TdMin, "TdMin");
    o.td_min = opts.TdMin;
    if (! isempty (opts.TdMax))
      check_scalar (opts.TdMax, "TdMax");
      o.td_max = opts.TdMax;
    endif
    if (! isempty (opts.NumTd))          # (default: the core's table)
      if (! isscalar (opts.NumTd) || opts.NumTd < 2
          || opts.NumTd != round (opts.NumTd))
        error ([fname ":badOption"], "%s: NumTd must be an integer >= 2",
               fname);
      endif
      o.num_td = opts.NumTd;
    endif
    o.grid = isempty (td0);
  endif
  o.output_error = strcmp (fname, "tffcoe") || pem;

  [theta, P, info] = freq_srivc_mex (fname, w, Y, U, o);
  [w, Y, U] = deal (info.w, info.Y, info.U);   # the frequencies used
  if (! info.converged)
    warning ([fname ":notConverged"], "%s: %s; the last iterate is returned",
             fname, info.reason);
  endif
  ## theta = [a_1; ..; a_nu; b_1; ..; b_nu] (several inputs: oe, tfest)
  nu = numel (na);
  Fs = cell (1, nu); bs = cell (1, nu);
  at = 0; bt = sum (na);
  delays = info.delay;
  if (nu > 1)
    delays = td0;
  endif
  for j = 1:nu
    Fs{j} = [1 theta(at+(1:na(j))).'];
    bs{j} = theta(bt+(1:nb(j))).';
    at += na(j);
    bt += nb(j);
  endfor
  [F, b] = deal (Fs{1}, bs{1});
  K = numel (w);
  npar = numel (theta);
  mse = info.loss;                      # mean |Y - G U|^2 (the core's)
  fit = struct ("FitPercent", 100 * (1 - sqrt (K * mse) / norm (Y)),
                "LossFcn", mse, "MSE", mse,
                "FPE", mse * (1 + npar / (2 * K)) / (1 - npar / (2 * K)));
  ## getpvec's order: the numerators, then the denominators
  perm = [sum(na) + (1:sum (nb)), 1:sum(na)];
  if (strcmp (fname, "oe"))
    if (nu > 1)
      M = idpoly (1, bs, 1, 1, Fs, info.noise_variance, 0);
    else
      M = idpoly (1, b, 1, 1, F, info.noise_variance, 0);
    endif
    C = P(perm, perm);
    if (all (isfinite (C(:))))
      M = setcov (M, (C + C.') / 2);
    endif
    rep = struct ("Method", "OE",
                  "Status", "Estimated using OE (frequency domain)",
                  "Fit", fit,
                  "Parameters", struct ("ParVector", getpvec (M)),
                  "Termination", struct ("Iterations", info.iterations,
                                         "Converged", info.converged,
                                         "Reason", info.reason),
                  "DataUsed", struct ("Length", K, "Domain", "Frequency",
                                      "Ts", 0, "InterSample", "bl"));
    M = set (M, "Report", rep);
    return;
  endif
  if (strcmp (fname, "srivc"))
    report = struct ("Fit", fit, "Method", "srivc (frequency domain)",
                     "DataUsed", struct ("Length", K, "Domain", "Frequency"));
    M = idctm (struct ("B", b, "F", F, "nk", 0, "Ts", [],
                       "covariance", P, "noise_variance",
                       info.noise_variance, "method", "srivc",
                       "iterations", info.iterations,
                       "converged", info.converged, "Report", report));
    return;
  endif
  if (nu > 1)
    M = idtf (bs, Fs, "IODelay", delays);
  else
    M = idtf (b, F, "IODelay", info.delay);
  endif
  if (estimate_td)
    perm(end+1) = sum (na) + sum (nb) + 1;  # getpvec ends with the IODelay
  endif
  C = P(perm, perm);
  if (all (isfinite (C(:))))
    if (nu > 1)
      Cf = zeros (numel (getpvec (M)));   # the fixed IODelays last
      Cf(1:numel (theta), 1:numel (theta)) = C;
      M = setcov (M, Cf);
    else
      M = setcov (M, C);
    endif
  endif
  tdsd = 0;
  if (estimate_td)
    tdsd = sqrt (P(end, end));
  endif
  rep = struct ("Fit", fit,
                "Parameters", struct ("ParVector", getpvec (M),
                                      "FreeParCovariance", C,
                                      "IODelay", delays,
                                      "IODelaySD", tdsd),
                "Termination", struct ("Iterations", info.iterations,
                                       "Converged", info.converged,
                                       "Reason", info.reason),
                "DataUsed", struct ("Length", K, "Ts", Ts,
                                    "Harmonics", w));
  rep.Method = fname;
  rep.Status = sprintf ("Estimated using %s", upper (fname));
  M = set (M, "NoiseVariance", info.noise_variance, "Report", rep);

  function v = onoff (v, name)
    if (islogical (v) || isnumeric (v))
      v = logical (v);
    elseif (ischar (v) && any (strcmpi (v, {"on", "off"})))
      v = strcmpi (v, "on");
    else
      error ([fname ":badOption"], "%s: %s must be 'on' or 'off'", fname,
             name);
    endif
  endfunction

  function check_positive (v, name)
    if (! isnumeric (v) || ! isscalar (v) || ! isreal (v) || ! (v > 0)
        || ! isfinite (v))
      error ([fname ":badOption"], "%s: %s must be a scalar > 0", fname, name);
    endif
  endfunction

  ## (a finite scalar for the gateway; its range is the core's)
  function check_scalar (v, name)
    if (! isnumeric (v) || ! isscalar (v) || ! isreal (v) || ! isfinite (v))
      error ([fname ":badOption"], "%s: %s must be a finite scalar >= 0",
             fname, name);
    endif
  endfunction

  ## w, Y, U from an idfrd, frequency-domain iddata, or (tffsrivc/tffcoe)
  ## regular time-domain data with a periodic (relay) input.
  function [w, Y, U, period, Ts] = frequency_data (data)
    period = Inf;
    Ts = 0;
    U = [];
    if (isa (data, "idfrd"))
      R = get (data, "ResponseData");
      nu = size (R, 2);
      if (size (R, 1) != 1 || (nu != 1 && ! (pem && nu == numel (na))))
        error ([fname ":notSupported"], "%s: the idfrd must be SISO%s",
               fname, ifelse (pem, " or have one output", ""));
      endif
      w = get (data, "Frequency");
      Y = R(:);
      if (nu > 1)
        ## one output, several inputs: the responses G_j stacked, each
        ## the output of the unit input j (U = 0 for the others), so that
        ## sum |Y - sum_j G_j U_j|^2 is the sum of the inputs' fits
        K = numel (w);
        Y = reshape (permute (R, [3 2 1]), [], 1);
        U = kron (eye (nu), ones (K, 1));
        w = repmat (w(:), nu, 1);
      endif
      if (get (data, "Ts") != 0)
        error ([fname ":notSupported"],
               "%s: the idfrd must be continuous-time (Ts = 0)", fname);
      endif
    elseif (isa (data, "iddata") && strcmp (get (data, "Domain"),
                                             "Frequency"))
      y = get (data, "OutputData");
      u = get (data, "InputData");
      if (columns (y) != 1
          || (columns (u) != 1 && ! (pem && columns (u) == numel (na))))
        error ([fname ":notSupported"],
               "%s: the frequency data must have one output and %s",
               fname, ifelse (pem, sprintf ("%d input(s)", numel (na)),
                              "one input"));
      endif
      if (get (data, "Ts") != 0)
        error ([fname ":notSupported"], ["%s: set data.Ts = 0 to declare "
               "the frequencies continuous-time"], fname);
      endif
      w = get (data, "Frequency");
      Y = y;
      U = u;
    elseif (! strcmp (fname, "srivc") && isa (data, "iddata"))
      [w, Y, U, period, Ts] = relay_frequency_data (data);
    else
      error ([fname ":badInput"], ...
             "%s: the data must be an idfrd or frequency-domain iddata%s",
             fname, ifelse (strcmp (fname, "srivc"), "",
                            " or regular time-domain iddata"));
    endif
    w = double (w(:));
    Y = double (Y(:));
    if (! isempty (U))
      if (rows (U) != numel (Y))
        error ([fname ":dimensionMismatch"],
               "%s: U and Y need one row per frequency", fname);
      endif
      U = double (U);
    endif
  endfunction

  ## The limit cycle of a relay-feedback record as frequency data: its
  ## harmonics, the input corrected for its hold (core
  ## relay_frequency_data.hpp); with IntSamp 'on' (y_k the mean of y over
  ## the interval) the output likewise.
  function [w, Y, U, period, Ts] = relay_frequency_data (data)
    Ts = get (data, "Ts");
    y = get (data, "OutputData");
    u = get (data, "InputData");
    if (! isscalar (Ts) || ! (Ts > 0) || columns (y) != 1 || columns (u) != 1)
      error ([fname ":badInput"], ["%s: time-domain data must be regular "
             "with one output and one input"], fname);
    endif
    [w, Y, U, period] = freq_srivc_mex (fname, "relay", double (y),
                                        double (u),
                                        struct ("Ts", Ts, "intsamp", intsamp));
  endfunction
endfunction

function s = ifelse (c, a, b)
  if (c)
    s = a;
  else
    s = b;
  endif
endfunction
