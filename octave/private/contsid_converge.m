## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn {} {[@var{tsiv}, @var{info}, @var{thm}, @var{yh}] =} contsid_converge (@var{fname}, @var{d}, @var{nn}, @var{rls}, @var{det}, @var{strict})
## Back-end of @code{rlsconverge} and of @code{"tsiv", "auto"} in the
## recursive IV routines: runs RLSSVF on the data @var{d} (from
## @code{contsid_getdata}) with the model [na nb nk] @var{nn} and the
## checked options @var{rls} (fields lambda_svf, adm, adg, th0, P0, svf, in
## the core order [a b]), and detects its convergence with the detector
## options @var{det} (a struct or a cell of name-value pairs, checked here;
## see @code{help rlsconverge}). When no convergence is detected it raises
## @code{@var{fname}:notConverged} if @var{strict}, else it warns with that
## identifier and returns @var{tsiv} = NaN. Every message starts with
## @var{fname}.
## @end deftypefn

function [tsiv, info, thm, yh] = contsid_converge (fname, d, nn, rls, det,
                                                  strict)
  defaults = struct ("blocklength", [], "nblocks", 10, "alpha", 0.05,
                     "tol_theta", 0.05, "eyfloor", 1e-3, "ptol", 1e-2,
                     "criteria", "all");
  if (isempty (det))
    det = {};
  endif
  opts = contsid_options (fname, defaults, det);
  t = d.t - d.t(1);
  T = t(end);
  Tb = opts.blocklength;
  if (isempty (Tb))
    ## The default window needs the cut-off before rlssvf (which checks
    ## it) runs.
    lam = rls.lambda_svf;
    if (isempty (lam))
      error ([fname ":badOption"], ...
             "%s: lambda_svf (the SVF cut-off, rad/s) is required", fname);
    elseif (! (isnumeric (lam) && isreal (lam) && isscalar (lam)
               && isfinite (lam) && lam > 0))
      error ([fname ":badInput"], ...
             "%s: lambda_svf must be a finite real scalar > 0", fname);
    endif
    Tb = 2 * 2 * pi / lam;               # two periods of the SVF cut-off
  endif
  positive (fname, Tb, "blocklength");
  if (d.uniform && Tb < 2 * d.Ts * (1 - 1e-12))
    error ([fname ":badInput"],
           "%s: blocklength (%g s) must hold at least two samples (Ts = %g s)",
           fname, Tb, d.Ts);
  endif
  n = opts.nblocks;
  if (! isnumeric (n) || ! isreal (n) || ! isscalar (n) || n != fix (n)
      || n < 3)
    error ([fname ":badInput"], "%s: nblocks must be an integer >= 3", fname);
  endif
  alpha = opts.alpha;
  positive (fname, alpha, "alpha");
  if (alpha >= 0.5)
    error ([fname ":badInput"], "%s: alpha must lie in (0, 0.5)", fname);
  endif
  positive (fname, opts.tol_theta, "tol_theta");
  floor_ = opts.eyfloor;
  if (! isnumeric (floor_) || ! isreal (floor_) || ! isscalar (floor_)
      || ! isfinite (floor_) || floor_ < 0)
    error ([fname ":badInput"], "%s: eyfloor must be a finite real >= 0",
           fname);
  endif
  positive (fname, opts.ptol, "ptol");
  crit = check_criteria (fname, opts.criteria);
  B = floor (T / Tb * (1 + 1e-12));
  if (B < n)
    error ([fname ":badInput"],
           ["%s: the training record (%g s) is too short for nblocks = %d ", ...
            "blocks of %g s"], fname, T, n, Tb);
  endif

  ## The RLSSVF run whose start-up is examined, with P0 explicit (rlssvf's
  ## default 1e4 I when not given) since the P index is relative to it.
  nu = (numel (nn) - 1) / 2;
  np = nn(1) + sum (nn(2:1+nu));
  P0 = rls.P0;
  if (isempty (P0))
    P0 = 1e4 * eye (np);
  endif
  if (d.uniform)
    timing = d.Ts;
  else
    timing = t;
  endif
  args = {"lambda_svf", rls.lambda_svf, "adm", rls.adm, "adg", rls.adg, ...
          "svf", rls.svf, "P0", P0};
  if (! isempty (rls.th0))
    args(end+1:end+2) = {"th0", rls.th0};
  endif
  use_P = any (strcmp (crit, "P"));
  try
    data = iddata (d.y, d.u, timing, "InterSample", d.intersample);
    if (use_P)
      [thm, yh, pset] = rlssvf (data, nn, args{:});
      ## trace (P) / trace (P0) after each recursion.
      trP = reshape (sum (reshape (pset, np * np, [])(1:np+1:end, :), 1),
                     [], 1) / trace (P0);
      clear pset;
    else
      [thm, yh] = rlssvf (data, nn, args{:});
      trP = [];
    endif
  catch err
    id = regexprep (err.identifier, '^rlssvf:', [fname ":"]);
    msg = regexprep (err.message, '^rlssvf:', [fname ": rlssvf:"]);
    error (struct ("message", msg, "identifier", id, "stack", err.stack));
  end_try_catch

  ## Block statistics and the three indices (the core's detector,
  ## recursive/convergence_detector.hpp: Cao and Rhinehart's steady-state
  ## test on the output error, the estimates' change, trace P).
  opts_det = struct ("blocklength", Tb, "nblocks", n, "alpha", alpha,
                     "tol_theta", opts.tol_theta, "eyfloor", floor_,
                     "ptol", opts.ptol,
                     "use_outputerror", any (strcmp (crit, "outputerror")),
                     "use_theta", any (strcmp (crit, "theta")),
                     "use_P", use_P);
  try
    r = rlssvf_mex (fname, "converge", t(:), double (d.y(:)), yh(:), thm,
                    trP, opts_det);
  catch err
    contsid_rethrow (err, fname);
  end_try_catch
  info = struct ("blocklength", Tb, "nblocks", n, "alpha", alpha,
                 "Rcrit", r.Rcrit, "tol_theta", opts.tol_theta,
                 "eyfloor", floor_, "ptol", opts.ptol, "criteria", {crit},
                 "causal", true,
                 "tblock", (1:r.nblocks)' * Tb, "ey_ms", r.ey_ms,
                 "y_ms", r.y_ms, "R", r.R, "dtheta", r.dtheta,
                 "theta_index", r.theta_index, "P_index", r.P_index,
                 "steady_ey", r.steady_ey, "steady_theta", r.steady_theta,
                 "small_P", r.small_P, "converged", r.converged,
                 "tsiv", NaN, "k", NaN);
  if (! r.converged)
    tsiv = NaN;
    msg = sprintf (["%s: no convergence of RLSSVF detected in %g s ", ...
                    "(%d blocks of %g s); give tsiv, or relax the ", ...
                    "thresholds (alpha, tol_theta, eyfloor, ptol)"],
                   fname, T, B, Tb);
    if (strict)
      error ([fname ":notConverged"], "%s", msg);
    endif
    warning ([fname ":notConverged"], "%s", msg);
    return;
  endif
  tsiv = r.tsiv;
  info.tsiv = tsiv;
  info.k = r.k;
endfunction

function positive (fname, v, what)
  if (! isnumeric (v) || ! isreal (v) || ! isscalar (v) || ! isfinite (v)
      || v <= 0)
    error ([fname ":badInput"], "%s: %s must be a finite real scalar > 0",
           fname, what);
  endif
endfunction

## The indices to use: "all" or one or several of "outputerror", "theta",
## "P" (a string or a cell of strings).
function crit = check_criteria (fname, c)
  known = {"outputerror", "theta", "P"};
  if (ischar (c) && strcmpi (c, "all"))
    crit = known;
    return;
  endif
  if (ischar (c))
    c = {c};
  endif
  ok = iscellstr (c) && ! isempty (c);
  crit = cell (1, 0);
  if (ok)
    for i = 1:numel (c)
      j = find (strcmpi (c{i}, known));
      ok = ok && ! isempty (j);
      if (ok)
        crit{end+1} = known{j};
      endif
    endfor
  endif
  if (! ok)
    error ([fname ":badOption"],
           ["%s: criteria must be 'all' or one or more of 'outputerror', ", ...
            "'theta', 'P'"], fname);
  endif
  crit = known(ismember (known, crit));    # known order, no repeats
endfunction
