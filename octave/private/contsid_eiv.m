## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn {} {[@var{M}, @var{iterations}] =} contsid_eiv (@var{fname}, @var{args})
## Shared back-end of tocls and tocils: reads the data, @var{nn} = [nf nb
## nk] (denominator order, numerator degree, delay in samples), the
## positional CONTSID arguments and the name-value options, runs the
## core's cumulant estimator (core/include/ctid/offline/cumulant_eiv.hpp,
## through offline_mex) and returns the idpoly.  Every message starts
## with @var{fname}.
## @end deftypefn

function [M, iterations] = contsid_eiv (fname, args)
  iterative = strcmp (fname, "tocils");
  if (numel (args) < 2)
    error ([fname ":badInput"], "%s: expected data, nn and M", fname);
  endif
  data = args{1};
  if (! isa (data, "iddata"))
    error ([fname ":badInput"], "%s: the data must be an iddata object",
           fname);
  endif
  nn = args{2};
  if (! isnumeric (nn) || ! isreal (nn) || ! isvector (nn)
      || ! any (numel (nn) == [2 3]) || any (! isfinite (nn))
      || any (nn != fix (nn)))
    error ([fname ":badInput"], ...
           "%s: nn must be [nf nb nk]: three integers", fname);
  endif
  nn = double (nn(:).');
  if (numel (nn) == 2)
    nn(3) = 0;
  endif
  if (nn(1) < 1 || nn(2) < 0 || nn(2) > nn(1) || nn(3) < 0)
    error ([fname ":badInput"], ...
           ["%s: nn = [nf nb nk] needs nf >= 1, 0 <= nb <= nf (nb is the ", ...
            "numerator's degree) and nk >= 0"], fname);
  endif
  ## CONTSID's positional arguments after nn, then name-value pairs.
  if (iterative)
    positional = {"Lags", "MaxIter", "lambda_svf", "Tol"};
    defaults = struct ("Lags", [], "MaxIter", 20, "lambda_svf", 3,
                       "Tol", 1e-4);
  else
    positional = {"Lags", "lambda_svf", "Tol"};
    defaults = struct ("Lags", [], "lambda_svf", 3, "Tol", []);
  endif
  rest = args(3:end);
  k = 0;
  while (k < numel (rest) && k < numel (positional) && ! ischar (rest{k+1}))
    k += 1;
    if (! isempty (rest{k}))
      defaults.(positional{k}) = rest{k};
    endif
  endwhile
  rest = rest(k+1:end);
  [d, orders, opts] = contsid_recursive_args (fname, "a", defaults, data,
                                              [nn(1) nn(2)+1 nn(3)], rest{:});
  if (columns (d.u) != 1)
    error ([fname ":badInput"], "%s: the data must have a single input",
           fname);
  endif
  if (! d.uniform || isfield (d, "missing"))
    error ([fname ":badInput"], ...
           "%s: the data must be regularly sampled without missing samples",
           fname);
  endif
  lags = opts.Lags;
  if (isempty (lags))
    error ([fname ":badInput"], ...
           "%s: the number of cumulant lags M is required (50 to 150)", fname);
  endif
  check_scalar (fname, "M", lags, true);
  check_scalar (fname, "lambda", opts.lambda_svf, false);
  e = struct ("method", fname, "na", orders.na, "nb", orders.nb,
              "nk", orders.nk, "intersample", d.intersample,
              "lambda_svf", opts.lambda_svf, "lags", lags);
  if (iterative)
    check_scalar (fname, "maxiter", opts.MaxIter, true);
    check_scalar (fname, "tol", opts.Tol, false);
    e.maxiter = opts.MaxIter;
    e.tol = opts.Tol;
  elseif (! isempty (opts.Tol))
    check_scalar (fname, "tol", opts.Tol, false);
  endif
  try
    [theta, ~, ~, iterations, converged] = offline_mex (fname, d.y, d.u,
                                                        d.Ts, e);
  catch err
    contsid_rethrow (err);
  end_try_catch
  if (iterative && ! converged)
    warning ([fname ":notConverged"], ...
             "%s: no convergence in %d iterations (tol %g)", fname,
             iterations, opts.Tol);
  endif
  na = orders.na;
  F = [1, theta(1:na).'];
  B = theta(na+1:end).';
  report = struct ("DataUsed", struct ("Ts", d.Ts,
                                       "InputOffset", mean (d.u),
                                       "OutputOffset", mean (d.y)));
  M = idctm (struct ("B", B, "F", F, "nk", orders.nk, "Ts", d.Ts,
                     "InterSample", d.intersample, "method", fname,
                     "iterations", iterations, "converged", converged,
                     "Report", report));
endfunction

function check_scalar (fname, name, v, integer)
  if (! isnumeric (v) || ! isreal (v) || ! isscalar (v) || ! isfinite (v)
      || v <= 0 || (integer && v != fix (v)))
    if (integer)
      what = "a positive integer";
    else
      what = "a finite real scalar > 0";
    endif
    error ([fname ":badInput"], "%s: %s must be %s", fname, name, what);
  endif
endfunction
