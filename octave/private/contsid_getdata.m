## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn  {} {@var{d} =} contsid_getdata (@var{fname}, @var{data}, @dots{})
## @deftypefnx {} {[@var{d}, @var{missing}] =} contsid_getdata (@dots{})
## @deftypefnx {} {@var{d} =} contsid_getdata (@var{fname}, @var{y}, @
##   @var{u}, @var{Ts})
## @deftypefnx {} {@var{d} =} contsid_getdata (@var{fname}, @var{y}, @
##   @var{u}, @var{t})
## Read and check the data argument of the front-end @var{fname}.
##
## Every front-end reads its data here, passing its own name and its whole
## argument list (@code{varargin}); the data come either as one
## @code{iddata} object (built by this toolbox or by the control package;
## one experiment) or as three numeric arguments: output @var{y}, inputs
## @var{u} and the sampling interval @var{Ts} or a vector @var{t} of
## sampling instants.  Arguments after the data are left to the caller.
##
## @var{d} is a struct with fields
## @table @code
## @item y
## @var{N}-by-1 output (double).
## @item u
## @var{N}-by-@var{nu} inputs (double), @var{nu} >= 1.
## @item t
## @var{N}-by-1 sampling instants: @code{(0:N-1)' * Ts} when the data came
## with a sampling interval, the given instants otherwise.
## @item Ts
## sampling interval; @code{NaN} when the instants are irregular.
## @item uniform
## true when the samples are equally spaced.  Instants equally spaced up
## to rounding (16 eps of their class relative to their magnitude) count
## as uniform, with @code{Ts} their mean spacing.
## @item intersample
## @qcode{"zoh"} or @qcode{"foh"}, from the @code{iddata} object (for
## irregular instants without a given InterSample, chosen from the
## smoothness of the inputs: @code{contsid_intersample});
## @qcode{"zoh"} for numeric data.
## @item nconsumed
## how many of the arguments after @var{fname} were data: 1 for an
## @code{iddata} object, 3 for numeric data.
## @end table
##
## Missing samples: a caller that asks for the second output @var{missing}
## accepts NaN in @var{y} and @var{u} as missing samples; @var{missing} is
## then the @var{N}-by-1 logical mask of the samples where @var{y} or any
## input is NaN, and @var{d} still holds every sample (NaN included;
## @code{contsid_recursive_args} decides how to bridge them).  A caller
## with one output gets an error for a NaN, as for an Inf.
##
## Checks, with error identifiers @code{@var{fname}:badInput} or
## @code{@var{fname}:dimensionMismatch} and messages that start with
## @var{fname} and name the argument: @var{y}, @var{u}, @var{t} real,
## double or single, non-empty, finite; one output; @var{y} and @var{u}
## (and @var{t}) of equal lengths (a row vector counts as one signal);
## @var{Ts} a positive finite scalar; @var{t} increasing; an
## @code{iddata} object with one experiment, in the time domain, with a
## specified sampling interval and at least one input.
## @seealso{iddata, samplinginfo, contsid_options}
## @end deftypefn

function [d, missing] = contsid_getdata (fname, varargin)
  if (nargin < 1 || ! (ischar (fname) && rows (fname) == 1))
    error ("contsid_getdata:badInput",
           "contsid_getdata: 'fname' must be the caller's name");
  endif
  if (isempty (varargin))
    error ([fname, ":badInput"],
           "%s: 'data' is missing: give an iddata object or y, u, Ts",
           fname);
  endif

  data = varargin{1};
  if (isa (data, "iddata"))
    [y, u, timing, intersample] = read_iddata (fname, data);
    nconsumed = 1;
    tname = "data.SamplingInstants";
  else
    if (numel (varargin) < 3)
      error ([fname, ":badInput"],
             "%s: expected an iddata object, or y, u and Ts (or t)", fname);
    endif
    [y, u, timing] = varargin{1:3};
    intersample = "zoh";
    nconsumed = 3;
    tname = "t";
  endif

  allow_nan = nargout > 1;
  y = real_signal (fname, y, "y", allow_nan);
  if (isrow (y))
    y = y.';
  endif
  n = rows (y);
  if (columns (y) != 1)
    error ([fname, ":badInput"],
           "%s: 'y' must hold a single output (one column), not %d",
           fname, columns (y));
  endif
  u = real_signal (fname, u, "u", allow_nan);
  if (isrow (u) && numel (u) == n && n > 1)
    u = u.';
  endif
  if (rows (u) != n)
    error ([fname, ":dimensionMismatch"],
           "%s: 'y' has %d samples but 'u' has %d rows", fname, n, rows (u));
  endif

  if (! (isnumeric (timing) && isreal (timing) && ! isempty (timing)
         && (isa (timing, "double") || isa (timing, "single"))
         && isvector (timing) && ! issparse (timing)))
    error ([fname, ":badInput"],
           "%s: 'Ts' must be a positive scalar or '%s' a vector of instants",
           fname, tname);
  endif
  if (isscalar (timing))
    ts = double (timing);
    if (! (isfinite (ts) && ts > 0))
      error ([fname, ":badInput"],
             "%s: sampling interval 'Ts' must be positive and finite", fname);
    endif
    t = (0:n-1).' * ts;
    uniform = true;
  else
    if (numel (timing) != n)
      error ([fname, ":dimensionMismatch"],
             "%s: 'y' has %d samples but '%s' has %d sampling instants",
             fname, n, tname, numel (timing));
    endif
    if (! all (isfinite (timing)))
      error ([fname, ":badInput"],
             "%s: sampling instants '%s' must be finite", fname, tname);
    endif
    tol = 16 * eps (class (timing)) * max (abs (timing([1, end])));
    t = double (timing(:));
    dt = diff (t);
    if (any (dt <= 0))
      error ([fname, ":badInput"],
             "%s: sampling instants '%s' must be strictly increasing",
             fname, tname);
    endif
    ts = (t(end) - t(1)) / (n - 1);
    uniform = all (abs (dt - ts) <= tol);
    if (! uniform)
      ts = NaN;
    endif
  endif

  d = struct ("y", y, "u", u, "t", t, "Ts", ts, "uniform", uniform,
              "intersample", intersample, "nconsumed", nconsumed);
  if (allow_nan)
    missing = isnan (y) | any (isnan (u), 2);
  endif
endfunction

## Signals and sampling of a single-experiment iddata object.  The fields
## are read with struct (), which does not depend on which iddata methods
## come first on the path, and the sampling with the toolbox's samplinginfo
## method (see help iddata for where it is stored).
function [y, u, timing, intersample] = read_iddata (fname, data)
  if (numel (data) != 1)
    error ([fname, ":badInput"],
           "%s: 'data' must be one iddata object, not an array of %d",
           fname, numel (data));
  endif
  s = struct (data);
  if (! s.timedomain)
    error ([fname, ":badInput"],
           "%s: 'data' must be time-domain data, not frequency-domain",
           fname);
  endif
  if (numel (s.y) != 1)
    error ([fname, ":badInput"],
           "%s: 'data' has %d experiments; select one with data(:,:,:,k)",
           fname, numel (s.y));
  endif
  if (isempty (s.u))
    error ([fname, ":badInput"],
           "%s: 'data' has no input signal 'u' (time series)", fname);
  endif
  y = s.y{1};
  u = s.u{1};
  info = samplinginfo (data);
  if (! info.Uniform)
    timing = info.SamplingInstants;
  elseif (info.Ts > 0)
    timing = info.Ts;
  else
    error ([fname, ":badInput"],
           "%s: 'data' has no sampling interval; build it as iddata (y, u, Ts)",
           fname);
  endif
  intersample = contsid_intersample (u, info);
endfunction

## x as a double matrix, after checking it is a real, finite (or NaN when
## allow_nan), non-empty, full double or single 2-D array.
function x = real_signal (fname, x, name, allow_nan)
  if (! ((isa (x, "double") || isa (x, "single")) && ndims (x) == 2))
    error ([fname, ":badInput"],
           "%s: '%s' must be a double or single matrix, not %s", fname,
           name, class (x));
  endif
  if (issparse (x))
    error ([fname, ":badInput"], "%s: '%s' must be a full matrix, not sparse",
           fname, name);
  endif
  if (isempty (x))
    error ([fname, ":badInput"], "%s: '%s' is empty", fname, name);
  endif
  if (! isreal (x))
    error ([fname, ":badInput"], "%s: '%s' must be real, not complex",
           fname, name);
  endif
  if (any (isinf (x(:))))
    error ([fname, ":badInput"], "%s: '%s' must be finite (it holds Inf)",
           fname, name);
  endif
  if (! allow_nan && any (isnan (x(:))))
    error ([fname, ":badInput"],
           ["%s: '%s' must be finite (it holds NaN; %s does not ", ...
            "bridge missing samples)"], fname, name, fname);
  endif
  x = double (x);
endfunction
