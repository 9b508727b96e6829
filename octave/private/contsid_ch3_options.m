## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn {} {@var{o} =} contsid_ch3_options (@var{fname}, @var{opts}, @var{orders}, @var{d}, @var{o})
## The Octave-side conversions of the Chapter 3 options of the recursive
## routines, added to @var{o} (the result of contsid_recursive_options) in
## the core's parameter order [a b]. They are validated by the core
## (@file{core/include/ctid/recursive/recursive_options.hpp}); here only
## what Octave's calling forms need:
##
## @table @code
## @item scaling
## @qcode{"self"} (eq. 3.54 on the estimation data @var{d}) or a training
## record (iddata, or a cell @{y, u, Ts@}) becomes the np diagonal entries
## of M_s; a vector is a column.
## @item precision
## lower case.
## @item potter, Gamma
## (rlssvf) the update form: @code{potter} true gives
## @qcode{"potter"}, adm @qcode{"lmr"} gives @qcode{"lmr"} with
## Gamma (a scalar g means g*I, a vector its diagonal).
## @end table
## @end deftypefn

function o = contsid_ch3_options (fname, opts, orders, d, o)
  np = orders.np;
  o.scaling = scaling (fname, opts.scaling, orders, d, o);
  if (ischar (opts.precision))
    o.precision = lower (opts.precision);
  endif
  if (isfield (opts, "potter"))
    o.potter = logical_flag (fname, opts.potter, "potter");
    o.form = "standard";
    o.Gamma = opts.Gamma;
    if (ischar (o.adm) && strcmp (o.adm, "lmr"))
      o.form = "lmr";
      o.Gamma = square_matrix (opts.Gamma, np);
      if (o.potter)
        error ([fname ":badOption"], ...
               "%s: potter and adm 'lmr' are different update forms", fname);
      endif
    elseif (o.potter)
      o.form = "potter";
    endif
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
    m = s(:);
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
  t = merge (d.uniform, d.Ts, d.t);
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

function M = square_matrix (M, np)
  if (isnumeric (M) && isreal (M) && ! isempty (M))
    M = double (M);
    if (isscalar (M))
      M = M * eye (np);
    elseif (isvector (M) && numel (M) == np)
      M = diag (M);
    endif
  endif
endfunction
