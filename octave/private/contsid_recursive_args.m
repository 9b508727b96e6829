## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn {} {[@var{d}, @var{orders}, @var{opts}] =} contsid_recursive_args (@var{fname}, @var{form}, @var{defaults}, @dots{})
## Shared argument parsing of the estimators (rlssvf, rivsvf, rsrivc,
## lssvf, srivc, ...): the data (an iddata object or numeric @var{y},
## @var{u}, @var{Ts}), the structure @var{nn}: [na nb nk] when @var{form}
## is @qcode{"a"} (rlssvf, rivsvf), [nb nf nk] when it is @qcode{"f"}
## (rsrivc: nf denominator parameters); nb and nk one entry per input, nk
## may be omitted and is then 0; an optional positional @var{lambda_svf}
## (CONTSID 7.0/7.1 syntax) and name-value options checked against the
## fields of @var{defaults}, plus the option @qcode{"Missing"} that every
## estimator takes.  Every message starts with @var{fname}.
##
## @var{orders} has fields na, nb (row), nk (row) and np.  Every input of
## the data must enter the model: an input with nb = 0, or more inputs in
## the data than nb has entries, is an error
## (@code{@var{fname}:dimensionMismatch}) instead of an input silently
## ignored.  Orders are limited to na <= 30 (the SVF's lambda^na and the
## regressors' conditioning are meaningless beyond) and nk to fewer
## samples than the record has.
##
## The record must have more samples than the model has parameters and a
## non-constant output (@code{@var{fname}:badInput} otherwise): with
## fewer the noise variance is undefined, with a constant output the
## denominator is not identifiable.
##
## Missing samples: a NaN in @var{y} or in an input marks that sample as
## missing.  With @code{"Missing", "bridge"} (the default) @var{d} holds
## only the present samples, on their own (irregular) instants, so that
## the SVF and the recursions, which are continuous-time filters,
## propagate over the gap: a zero-order-hold input is held at its last
## present value across the gap, a first-order-hold input is interpolated
## linearly, and the recursive estimators make no update at a missing
## sample.  @var{d} then has the extra fields @code{missing} (the
## @var{N}-by-1 logical mask of the full record), @code{nfull} and
## @code{gap_interval} (1.5 times the median sampling interval of the full
## record: a longer interval between present samples is a gap); see
## @code{contsid_expand} for how per-sample outputs are brought back to
## @var{N} rows.  With @code{"Missing", "error"} a NaN is an error
## (@code{@var{fname}:badInput}).  Missing samples with a delay nk > 0
## are not supported (@code{@var{fname}:notSupported}).
## @end deftypefn

function [d, orders, opts] = contsid_recursive_args (fname, form, defaults,
                                                    varargin)
  if (numel (varargin) < 2)
    error ([fname ":badInput"], ...
           "%s: expected data and the model structure nn", fname);
  endif
  [d, missing] = contsid_getdata (fname, varargin{:});
  rest = varargin(d.nconsumed+1:end);
  if (isempty (rest))
    error ([fname ":badInput"], "%s: the model structure nn is missing", fname);
  endif
  orders = parse_orders (fname, rest{1}, columns (d.u), form, rows (d.y));
  rest(1) = [];
  if (! isempty (rest) && ! ischar (rest{1}) && ! isstruct (rest{1}))
    ## CONTSID 7.0/7.1: the cut-off frequency by position.
    if (isfield (defaults, "lambda_svf"))
      defaults.lambda_svf = rest{1};
    else
      error ([fname ":badOption"], ...
             "%s: unexpected positional argument after nn", fname);
    endif
    rest(1) = [];
  endif
  if (isfield (defaults, "Missing"))
    opts = contsid_options (fname, defaults, rest);
    how = opts.Missing;
  else
    defaults.Missing = "bridge";
    opts = contsid_options (fname, defaults, rest);
    how = opts.Missing;
    opts = rmfield (opts, "Missing");
    opts.given_(strcmp (opts.given_, "Missing")) = [];
  endif
  d = bridge_missing (fname, d, missing, how, orders);
  check_record (fname, d, orders);
endfunction

## The present samples of d, on their own instants, when some are missing.
function d = bridge_missing (fname, d, missing, how, orders)
  if (! (ischar (how) && any (strcmpi (how, {"bridge", "error"}))))
    error ([fname ":badOption"], "%s: Missing must be 'bridge' or 'error'",
           fname);
  endif
  if (! any (missing))
    return;
  endif
  if (strcmpi (how, "error"))
    error ([fname ":badInput"],
           "%s: the data hold %d missing samples (NaN), the first at %d",
           fname, nnz (missing), find (missing, 1));
  endif
  if (any (orders.nk > 0))
    error ([fname ":notSupported"],
           ["%s: missing samples with a delay nk > 0: shift the input by ", ...
            "nk samples and give nk = 0"], fname);
  endif
  present = ! missing;
  d.missing = missing;
  d.nfull = rows (d.y);
  if (numel (d.t) > 1)
    d.gap_interval = 1.5 * median (diff (d.t));
  else
    d.gap_interval = 0;
  endif
  d.y = d.y(present);
  d.u = d.u(present, :);
  d.t = d.t(present);
  if (numel (d.t) > 1)
    dt = diff (d.t);
    d.uniform = all (abs (dt - dt(1)) <= 16 * eps * max (abs (d.t([1 end]))));
  endif
  if (d.uniform && numel (d.t) > 1)
    d.Ts = (d.t(end) - d.t(1)) / (numel (d.t) - 1);
  else
    d.uniform = false;
    d.Ts = NaN;
  endif
endfunction

## A record that can identify the model: more samples than parameters and
## an output that moves.
function check_record (fname, d, orders)
  n = rows (d.y);
  if (n <= orders.np)
    error ([fname ":badInput"],
           ["%s: the record has %d (present) samples, fewer than needed ", ...
            "for %d parameters (at least %d)"], fname, n, orders.np,
           orders.np + 1);
  endif
  contsid_check_output (fname, d.y);
endfunction

function orders = parse_orders (fname, nn, nu, form, n)
  if (strcmp (form, "f"))
    shape = "[nb nf nk]";
  else
    shape = "[na nb nk]";
  endif
  if (! isnumeric (nn) || ! isreal (nn) || isempty (nn) || ! isvector (nn)
      || issparse (nn) || any (! isfinite (nn)) || any (nn != fix (nn)))
    error ([fname ":badInput"], ...
           "%s: nn must be a vector of integers %s", fname, shape);
  endif
  nn = double (nn(:).');
  if (numel (nn) != 1 + 2 * nu && numel (nn) != 1 + nu)
    error ([fname ":dimensionMismatch"], ...
           "%s: nn must be %s with nb and nk of length %d (inputs)",
           fname, shape, nu);
  endif
  if (strcmp (form, "f"))
    nb = nn(1:nu);
    na = nn(nu+1);
  else
    na = nn(1);
    nb = nn(2:1+nu);
  endif
  if (numel (nn) == 1 + 2 * nu)
    nk = nn(2+nu:end);
  else
    nk = zeros (1, nu);
  endif
  if (na < 1)
    error ([fname ":badInput"],
           "%s: nn: the model order (na or nf) must be >= 1, got %d",
           fname, na);
  endif
  if (any (nb < 0) || any (nk < 0))
    error ([fname ":badInput"], "%s: nn: nb and nk must be >= 0", fname);
  endif
  if (na > 30)
    error ([fname ":badInput"],
           "%s: nn: the model order %d is beyond what the SVF can handle (30)",
           fname, na);
  endif
  if (any (nk >= n))
    error ([fname ":badInput"],
           "%s: nn: the delay nk = %d is not shorter than the record (%d)",
           fname, max (nk), n);
  endif
  if (nu > 1 && any (nb == 0))
    error ([fname ":dimensionMismatch"],
           ["%s: nn: input %d has nb = 0: the model would ignore it; ", ...
            "give nb >= 1 for each of the %d inputs (nn = %s with nb and ", ...
            "nk of length %d) or remove the input from the data"],
           fname, find (nb == 0, 1), nu, shape, nu);
  endif
  if (any (nb > na + 1))
    error ([fname ":badInput"], ...
           "%s: nn: nb = %d gives an improper model (nb must be <= na + 1)",
           fname, max (nb));
  endif
  if (sum (nb) == 0)
    error ([fname ":badInput"], "%s: nn: the model needs nb >= 1", fname);
  endif
  orders = struct ("na", na, "nb", nb, "nk", nk, "np", na + sum (nb));
endfunction
