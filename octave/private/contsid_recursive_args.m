## -*- texinfo -*-
## @deftypefn {} {[@var{d}, @var{orders}, @var{opts}] =} contsid_recursive_args (@var{fname}, @var{form}, @var{defaults}, @dots{})
## Shared argument parsing of the recursive routines (rlssvf, rivsvf,
## rsrivc, ...): the data (an iddata object or numeric @var{y}, @var{u},
## @var{Ts}), the structure @var{nn}: [na nb nk] when @var{form} is
## @qcode{"a"} (rlssvf, rivsvf), [nb nf nk] when it is @qcode{"f"} (rsrivc:
## nf denominator parameters); nb and nk one entry per input, nk may be
## omitted and is then 0; an optional positional
## @var{lambda_svf} (CONTSID 7.0/7.1 syntax) and name-value options checked
## against the fields of @var{defaults}.  Every message starts with
## @var{fname}.
##
## @var{orders} has fields na, nb (row), nk (row) and np.
## @end deftypefn

function [d, orders, opts] = contsid_recursive_args (fname, form, defaults,
                                                    varargin)
  if (numel (varargin) < 2)
    error ([fname ":badInput"], ...
           "%s: expected data and the model structure nn", fname);
  endif
  d = contsid_getdata (fname, varargin{:});
  rest = varargin(d.nconsumed+1:end);
  if (isempty (rest))
    error ([fname ":badInput"], "%s: the model structure nn is missing", fname);
  endif
  orders = parse_orders (fname, rest{1}, columns (d.u), form);
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
  opts = contsid_options (fname, defaults, rest);
endfunction

function orders = parse_orders (fname, nn, nu, form)
  if (strcmp (form, "f"))
    shape = "[nb nf nk]";
  else
    shape = "[na nb nk]";
  endif
  if (! isnumeric (nn) || ! isreal (nn) || isempty (nn) || ! isvector (nn)
      || any (! isfinite (nn)) || any (nn != fix (nn)))
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
