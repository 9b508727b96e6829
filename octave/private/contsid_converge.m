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
  ## [] leaves an option to the core's default (rlssvf_convergence.hpp)
  defaults = struct ("blocklength", [], "nblocks", [], "alpha", [],
                     "tol_theta", [], "eyfloor", [], "ptol", [],
                     "criteria", "all");
  if (isempty (det))
    det = {};
  endif
  opts = contsid_options (fname, defaults, det);
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
  crit = check_criteria (fname, opts.criteria);

  ## The RLSSVF run whose start-up is examined and the detector
  ## (recursive/rlssvf_convergence.hpp: Cao and Rhinehart's steady-state
  ## test on the output error, the estimates' change, trace P / trace P0),
  ## which checks the detector's options before the run.
  timing = merge (d.uniform, d.Ts, d.t);
  args = {"lambda_svf", rls.lambda_svf, "adm", rls.adm, "adg", rls.adg, ...
          "svf", rls.svf, "P0", rls.P0};
  if (! isempty (rls.th0))
    args(end+1:end+2) = {"th0", rls.th0};
  endif
  p = contsid_rlssvf_args (fname, iddata (d.y, d.u, timing, "InterSample",
                                          d.intersample), nn, args{:});
  opts_det = struct ("blocklength", Tb, "nblocks", opts.nblocks,
                     "alpha", opts.alpha, "tol_theta", opts.tol_theta,
                     "eyfloor", opts.eyfloor, "ptol", opts.ptol,
                     "use_outputerror", any (strcmp (crit, "outputerror")),
                     "use_theta", any (strcmp (crit, "theta")),
                     "use_P", any (strcmp (crit, "P")));
  try
    [r, thm, yh] = rlssvf_mex (fname, "converge", p.data{:}, p.opts,
                               opts_det);
  catch err
    contsid_rethrow (err, fname);
  end_try_catch
  used = r.settings;
  info = struct ("blocklength", Tb, "nblocks", used.nblocks,
                 "alpha", used.alpha, "Rcrit", r.Rcrit,
                 "tol_theta", used.tol_theta, "eyfloor", used.eyfloor,
                 "ptol", used.ptol, "criteria", {crit}, "causal", true,
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
                   fname, d.t(end) - d.t(1), r.nblocks, Tb);
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
