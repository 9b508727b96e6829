## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn {} {@var{o} =} contsid_recursive_options (@var{fname}, @
##   @var{opts}, @var{np}, @var{d})
## The Octave-side conversions of the options shared by the recursive
## routines, for a model with @var{np} parameters estimated on the record
## @var{d} (a struct of @code{contsid_getdata}). The options are declared,
## defaulted and validated once, in the core
## (@file{core/include/ctid/recursive/recursive_options.hpp}), by the
## gateway that receives them; what is absent or [] stays so and takes
## the core's default. Here only what Octave's calling forms need:
##
## @table @code
## @item lambda_svf
## a warning @code{@var{fname}:cutoffAboveNyquist} when it lies above the
## Nyquist frequency of @var{d} (@code{contsid_check_cutoff}).
## @item adm
## lower case; @qcode{"rw"} (CONTSID 7.0/7.1) means @qcode{"kf"};
## @qcode{"lmr"} (LMR-RLSSVF, eq. 3.82) is left for the caller.
## @item adg
## with @qcode{"kf"}, a scalar q means q*I and a vector of np entries the
## diagonal of Qn, so that the caller can reorder it.
## @item th0, P0
## th0 as a column; a scalar P0 p means p*I.
## @item svf
## lower case.
## @item GapSettle
## seconds without update after a gap of missing samples; [] means
## 20 / lambda_svf.
## @end table
## @end deftypefn

function o = contsid_recursive_options (fname, opts, np, d)
  o = opts;
  lam = opts.lambda_svf;
  if (real_scalar (lam) && isfinite (lam) && lam > 0)
    o.lambda_svf = double (lam);
    contsid_check_cutoff (fname, o.lambda_svf, d);
  endif

  adm = opts.adm;
  if (ischar (adm))
    adm = lower (adm);
    if (strcmp (adm, "rw"))
      adm = "kf";
    endif
  endif
  o.adm = adm;

  adg = opts.adg;
  if (ischar (adm) && strcmp (adm, "kf") && isnumeric (adg) && isreal (adg)
      && ! isempty (adg))
    adg = double (adg);
    if (isscalar (adg))
      adg = adg * eye (np);
    elseif (isvector (adg) && numel (adg) == np)
      adg = diag (adg);
    endif
  endif
  o.adg = adg;

  if (isnumeric (opts.th0) && isvector (opts.th0))
    o.th0 = double (opts.th0(:));
  endif
  if (isnumeric (opts.P0) && isscalar (opts.P0))
    o.P0 = double (opts.P0) * eye (np);
  endif
  if (ischar (opts.svf))
    o.svf = lower (opts.svf);
  endif

  if (isfield (opts, "GapSettle") && isempty (opts.GapSettle)
      && real_scalar (o.lambda_svf))
    o.GapSettle = 20 / o.lambda_svf;
  endif
endfunction

function tf = real_scalar (x)
  tf = isnumeric (x) && isreal (x) && isscalar (x);
endfunction
