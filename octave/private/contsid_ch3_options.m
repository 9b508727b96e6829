## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn {} {@var{o} =} contsid_ch3_options (@var{fname}, @var{opts}, @var{orders}, @var{d}, @var{o})
## Checks the Chapter 3 options shared by the recursive routines and adds
## them to @var{o} (the result of contsid_recursive_options), in the core's
## parameter order [a b]:
##
## @table @code
## @item scaling
## [] (none), a vector of np positive diagonal entries of M_s (core order),
## @qcode{"self"} (eq. 3.54 on the estimation data @var{d}) or a training
## record (iddata, or a cell @{y, u, Ts@}) for eq. (3.54).
## @item precision
## @qcode{"double"} or @qcode{"single"}.
## @item potter, Gamma, ic, tsls
## (rlssvf) square-root form, LMR regularisation, initial conditions,
## delayed start.
## @item antiwindup, antiwindup_lambda
## (IV routines) gamma of eq. (3.79) and the forgetting factor of the
## parallel RLSSVF-FF.
## @end table
## @end deftypefn

function o = contsid_ch3_options (fname, opts, orders, d, o)
  np = orders.np;
  o.scaling = scaling (fname, opts.scaling, orders, d, o);
  if (! ischar (opts.precision)
      || ! any (strcmpi (opts.precision, {"double", "single"})))
    error ([fname ":badOption"], ...
           "%s: precision must be 'double' or 'single'", fname);
  endif
  o.precision = lower (opts.precision);

  if (isfield (opts, "potter"))
    o.potter = logical_flag (fname, opts.potter, "potter");
    o.ic = logical_flag (fname, opts.ic, "ic");
    o.tsls = opts.tsls;
    if (! isnumeric (o.tsls) || ! isreal (o.tsls) || ! isscalar (o.tsls)
        || ! isfinite (o.tsls) || o.tsls < 0)
      error ([fname ":badInput"], "%s: tsls must be a finite scalar >= 0",
             fname);
    endif
    o.tsls = double (o.tsls);
    o.form = "standard";
    o.Gamma = [];
    if (strcmp (o.adm, "lmr"))
      o.form = "lmr";
      o.Gamma = square_matrix (fname, opts.Gamma, np, "Gamma");
      if (o.potter)
        error ([fname ":badOption"], ...
               "%s: potter and adm 'lmr' are different update forms", fname);
      endif
    elseif (! isempty (opts.Gamma))
      error ([fname ":badOption"], "%s: Gamma belongs to adm 'lmr'", fname);
    elseif (o.potter)
      o.form = "potter";
    endif
  else
    g = opts.antiwindup;
    if (isempty (g) || (isnumeric (g) && isscalar (g) && g == 0))
      g = 0;
    elseif (! isnumeric (g) || ! isreal (g) || ! isscalar (g)
            || ! isfinite (g) || g <= 1)
      error ([fname ":badInput"], ...
             ["%s: antiwindup (the threshold gamma on kappa_2(P), ", ...
              "eq. 3.79) must be a finite scalar > 1"], fname);
    endif
    o.antiwindup = double (g);
    l = opts.antiwindup_lambda;
    if (! isnumeric (l) || ! isreal (l) || ! isscalar (l) || ! (l > 0)
        || l > 1)
      error ([fname ":badInput"], ...
             "%s: antiwindup_lambda must be a scalar in (0, 1]", fname);
    endif
    o.antiwindup_lambda = double (l);
  endif
endfunction

function m = scaling (fname, s, orders, d, o)
  np = orders.np;
  m = [];
  if (isempty (s))
    return;
  endif
  if (ischar (s))
    if (! strcmpi (s, "self"))
      error ([fname ":badOption"], ...
             ["%s: scaling must be [], a vector of %d entries, 'self' or ", ...
              "a training record"], fname, np);
    endif
    m = svf_scaling (fname, d, orders, o);
  elseif (isnumeric (s))
    if (! isreal (s) || ! isvector (s) || any (! isfinite (s)) || any (s <= 0))
      error ([fname ":badInput"], ...
             "%s: the scaling M_s must be positive finite diagonal entries",
             fname);
    endif
    if (numel (s) != np)
      error ([fname ":dimensionMismatch"], ...
             "%s: the scaling M_s must have %d diagonal entries, got %d",
             fname, np, numel (s));
    endif
    m = double (s(:));
  else
    if (iscell (s))
      training = contsid_getdata (fname, s{:});
    else
      training = contsid_getdata (fname, s);
    endif
    if (columns (training.u) != columns (d.u))
      error ([fname ":dimensionMismatch"], ...
             "%s: the training record must have %d input(s)", fname,
             columns (d.u));
    endif
    m = svf_scaling (fname, training, orders, o);
  endif
endfunction

## Eq. (3.54) through the core (offline_mex's "scaling" method).
function m = svf_scaling (fname, d, orders, o)
  if (d.uniform)
    t = d.Ts;
  else
    t = d.t;
  endif
  try
    m = offline_mex (fname, d.y, d.u, t,
                     struct ("intersample", d.intersample, "na", orders.na,
                             "nb", orders.nb, "nk", orders.nk,
                             "lambda_svf", o.lambda_svf, "svf", o.svf,
                             "method", "scaling"));
  catch err
    contsid_rethrow (err);
  end_try_catch
endfunction

function tf = logical_flag (fname, v, what)
  if (! (islogical (v) || isnumeric (v)) || ! isscalar (v) || ! isreal (v)
      || ! any (v == [0 1]))
    error ([fname ":badInput"], "%s: %s must be true or false", fname, what);
  endif
  tf = logical (v);
endfunction

function M = square_matrix (fname, M, np, what)
  if (isempty (M))
    error ([fname ":badOption"], "%s: adm 'lmr' needs %s", fname, what);
  endif
  if (! isnumeric (M) || ! isreal (M) || ndims (M) > 2 || any (! isfinite (M(:))))
    error ([fname ":badInput"], "%s: %s must be a finite real matrix", fname,
           what);
  endif
  M = double (M);
  if (isscalar (M))
    M = M * eye (np);
  elseif (isvector (M) && numel (M) == np)
    M = diag (M);
  elseif (any (size (M) != [np np]))
    error ([fname ":dimensionMismatch"], "%s: %s must be %dx%d, got %dx%d",
           fname, what, np, np, size (M));
  endif
  if (norm (M - M.', 1) > 1e3 * eps * max (1, norm (M, 1))
      || min (eig ((M + M.') / 2)) < -1e3 * eps * max (1, norm (M, 1)))
    error ([fname ":badInput"], ...
           "%s: %s must be symmetric positive semi-definite", fname, what);
  endif
endfunction
