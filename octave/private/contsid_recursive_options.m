## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn {} {@var{o} =} contsid_recursive_options (@var{fname}, @
##   @var{opts}, @var{np}, @var{d})
## Checks and normalises the options shared by the recursive routines for a
## model with @var{np} parameters estimated on the record @var{d} (a
## struct of @code{contsid_getdata}):
##
## @table @code
## @item lambda_svf
## finite real scalar > 0 (required); above the Nyquist frequency of
## @var{d} a warning @code{@var{fname}:cutoffAboveNyquist}
## (@code{contsid_check_cutoff}).
## @item adm
## @qcode{"ff"} or @qcode{"kf"}; @qcode{"rw"} (CONTSID 7.0/7.1) means
## @qcode{"kf"}; @qcode{"lmr"} (LMR-RLSSVF, eq. 3.82) takes a forgetting
## factor like @qcode{"ff"} (the caller checks it is allowed).
## @item adg
## forgetting factor in (0, 1] (default 1) for @qcode{"ff"}; for
## @qcode{"kf"} the np-by-np Qn (default zeros), or a scalar q (q*I) or a
## vector of np diagonal entries.
## @item th0, P0
## np initial estimates (default 0) and the np-by-np P0 (default 1e4*I; a
## scalar p means p*I).
## @item svf
## @qcode{"normalised"} (default, thesis eq. 3.1) or @qcode{"ordinary"}
## (eq. 1.19).
## @item covariance_guard
## logical scalar (default true): the protection of P of
## @file{core/include/ctid/adaptation/covariance_guard.hpp} after each update of the
## standard form (see @code{rlssvf}).
## @item GapSettle
## seconds without update after a gap of missing samples (finite, >= 0;
## default [] = 20 / lambda_svf).
## @end table
## @end deftypefn

function o = contsid_recursive_options (fname, opts, np, d)
  o = opts;
  lam = opts.lambda_svf;
  if (isempty (lam))
    error ([fname ":badOption"], ...
           "%s: lambda_svf (the SVF cut-off, rad/s) is required", fname);
  endif
  if (! real_scalar (lam) || ! isfinite (lam) || lam <= 0)
    error ([fname ":badInput"], ...
           "%s: lambda_svf must be a finite real scalar > 0", fname);
  endif
  o.lambda_svf = double (lam);
  contsid_check_cutoff (fname, o.lambda_svf, d);

  adm = opts.adm;
  if (! ischar (adm) || ! any (strcmpi (adm, {"ff", "kf", "rw", "lmr"})))
    error ([fname ":badOption"], "%s: adm must be 'ff', 'kf', 'rw' or 'lmr'",
           fname);
  endif
  adm = lower (adm);
  if (strcmp (adm, "rw"))
    adm = "kf";
  endif
  o.adm = adm;

  adg = opts.adg;
  if (! isempty (adg) && (! isnumeric (adg) || ! isreal (adg)
                          || ndims (adg) > 2))
    error ([fname ":badInput"], "%s: adg must be a real numeric array", fname);
  endif
  adg = double (adg);
  if (any (strcmp (adm, {"ff", "lmr"})))
    if (isempty (adg))
      adg = 1;
    endif
    if (! isscalar (adg) || ! (adg > 0 && adg <= 1))
      error ([fname ":badInput"], ...
             "%s: adg (forgetting factor) must be a scalar in (0, 1]", fname);
    endif
  else
    if (isempty (adg))
      adg = zeros (np);
    elseif (isscalar (adg))
      adg = adg * eye (np);
    elseif (isvector (adg) && numel (adg) == np)
      adg = diag (adg);
    elseif (rows (adg) != columns (adg))
      error ([fname ":badInput"], ...
             "%s: adg (Qn) must be square, got %dx%d", fname, size (adg));
    elseif (rows (adg) != np)
      error ([fname ":dimensionMismatch"], ...
             "%s: adg (Qn) must be %dx%d (one row per parameter), got %dx%d",
             fname, np, np, size (adg));
    endif
    if (any (! isfinite (adg(:))))
      error ([fname ":badInput"], "%s: adg (Qn) must be finite", fname);
    endif
    if (norm (adg - adg.', 1) > 1e3 * eps * max (1, norm (adg, 1)))
      error ([fname ":badInput"], "%s: adg (Qn) must be symmetric", fname);
    endif
    if (min (eig ((adg + adg.') / 2)) < -1e3 * eps * max (1, norm (adg, 1)))
      error ([fname ":badInput"], ...
             "%s: adg (Qn) must be positive semi-definite", fname);
    endif
  endif
  o.adg = adg;

  th0 = opts.th0;
  if (! isempty (th0))
    if (! isnumeric (th0) || ! isreal (th0) || ! isvector (th0)
        || any (! isfinite (th0)))
      error ([fname ":badInput"], "%s: th0 must be a finite real vector",
             fname);
    endif
    if (numel (th0) != np)
      error ([fname ":dimensionMismatch"], ...
             "%s: th0 must have %d elements (one per parameter), got %d",
             fname, np, numel (th0));
    endif
    th0 = double (th0(:));
  endif
  o.th0 = th0;

  P0 = opts.P0;
  if (! isempty (P0))
    if (! isnumeric (P0) || ! isreal (P0) || ndims (P0) > 2
        || any (! isfinite (P0(:))))
      error ([fname ":badInput"], "%s: P0 must be a finite real matrix", fname);
    endif
    P0 = double (P0);
    if (isscalar (P0))
      P0 = P0 * eye (np);
    elseif (any (size (P0) != [np np]))
      error ([fname ":dimensionMismatch"], ...
             "%s: P0 must be %dx%d, got %dx%d", fname, np, np, size (P0));
    endif
  endif
  o.P0 = P0;

  if (! ischar (opts.svf)
      || ! any (strcmpi (opts.svf, {"normalised", "normalized", "ordinary"})))
    error ([fname ":badOption"], ...
           "%s: svf must be 'normalised' or 'ordinary'", fname);
  endif
  o.svf = lower (opts.svf);

  cg = true;
  if (isfield (opts, "covariance_guard"))
    cg = opts.covariance_guard;
  endif
  if (! ((islogical (cg) || (isnumeric (cg) && isreal (cg))) && isscalar (cg)
         && (cg == 0 || cg == 1)))
    error ([fname ":badOption"], ...
           "%s: covariance_guard must be true or false", fname);
  endif
  o.covariance_guard = logical (cg);

  if (isfield (opts, "GapSettle"))
    gs = opts.GapSettle;
    if (isempty (gs))
      gs = 20 / o.lambda_svf;
    elseif (! (real_scalar (gs) && isfinite (gs) && gs >= 0))
      error ([fname ":badOption"], ...
             "%s: GapSettle must be a finite real scalar >= 0 (seconds)",
             fname);
    endif
    o.GapSettle = double (gs);
  endif
endfunction

function tf = real_scalar (x)
  tf = isnumeric (x) && isreal (x) && isscalar (x);
endfunction
