## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn  {} {} dbode (@var{num}, @var{den}, @var{Ts})
## @deftypefnx {} {} dbode (@var{num}, @var{den}, @var{Ts}, @var{w})
## @deftypefnx {} {} dbode (@var{a}, @var{b}, @var{c}, @var{d}, @var{Ts}, @
##   @var{iu})
## @deftypefnx {} {} dbode (@var{a}, @var{b}, @var{c}, @var{d}, @var{Ts}, @
##   @var{iu}, @var{w})
## @deftypefnx {} {[@var{mag}, @var{phase}, @var{w}] =} dbode (@dots{})
## Bode diagram of a discrete-time system in the pre-LTI form of MATLAB's
## Control System Toolbox (@code{dbode (C, D, Ts)} in CONTSID scripts).
##
## @code{(num, den, Ts)} is @code{tf (num, den, Ts)} (coefficients in
## descending powers of @var{z}); @code{(a, b, c, d, Ts, iu)} is input
## @var{iu} of @code{ss (a, b, c, d, Ts)}.  @var{w}: frequencies in rad per
## time unit.  The result is the control package's @code{bode} of that
## model: a plot without outputs, else @var{mag} (absolute value) and
## @var{phase} (degrees), @code{numel (w)}-by-@var{ny}.
## @seealso{bode, step}
## @end deftypefn

function varargout = dbode (varargin)
  varargout = contsid_guard ("dbode", @dbode_body, nargout, varargin);
endfunction

function [mag, phase, w, varargout] = dbode_body (varargin)
  contsid_nargchk ("dbode", nargin, nargout, [0 Inf], 3);
  if (! exist ("tf"))
    error ("dbode:notSupported", "dbode: needs the control package");
  endif
  ok = cellfun (@is_finite_real, varargin);
  if (! all (ok) || ! any (nargin == [3, 4, 6, 7]))
    error ("dbode:badInput",
           ["dbode: use dbode (num, den, Ts[, w]) or ", ...
            "dbode (a, b, c, d, Ts, iu[, w])"]);
  endif
  varargin = cellfun (@double, varargin, "uniformoutput", false);
  if (nargin <= 4)
    ts = varargin{3};
    rest = varargin(4:end);
    model = @() tf (varargin{1}, varargin{2}, ts);
    iu = 1;
  else
    ts = varargin{5};
    iu = varargin{6};
    rest = varargin(7:end);
    model = @() ss (varargin{1:4}, ts);
  endif
  if (! (isscalar (ts) && ts > 0 && isfinite (ts)))
    error ("dbode:badInput", "dbode: 'Ts' must be a positive scalar");
  endif
  try
    sys = model ();
  catch err
    error ("dbode:badInput", "dbode: not a valid model: %s", err.message);
  end_try_catch
  if (! (isscalar (iu) && iu >= 1 && iu <= columns (sys) && iu == fix (iu)))
    error ("dbode:badInput", "dbode: 'iu' must be an input index");
  endif
  if (nargout == 0)
    for k = 1:rows (sys)
      if (rows (sys) > 1)
        subplot (1, rows (sys), k);
      endif
      bode (sys(k, iu), rest{:});
    endfor
    return;
  endif
  mag = [];
  phase = [];
  for k = 1:rows (sys)
    [m, p, w] = bode (sys(k, iu), rest{:});
    mag(:, k) = m(:);
    phase(:, k) = p(:);
  endfor
  w = w(:);
endfunction

function ok = is_finite_real (x)
  ok = isnumeric (x) && isreal (x) && all (isfinite (x(:)));
endfunction

%!test
%! pkg load control
%! w = [0.1 1 5 10];
%! [m, p] = dbode ([0 0.2], [1 -0.8], 0.1, w);
%! z = exp (1i * w * 0.1);
%! assert (m, abs (0.2 ./ (z - 0.8)).', 1e-12);
%! [m2, p2] = dbode (0.8, 1, 1, 0, 0.1, 1, w);
%! assert (m2, abs (1 ./ (z - 0.8)).', 1e-12);
%! assert (dbode ([0 0.2], [1 -0.8], single (0.5), w),
%!         dbode ([0 0.2], [1 -0.8], 0.5, w), 1e-12);

%!error id=dbode:badInput dbode (1, [1 -0.5])
%!error id=dbode:badInput dbode (1, [1 -0.5], 0)
%!error id=dbode:badInput dbode (1, [1 -0.5], "a")
%!error id=dbode:badInput dbode (1, [1 NaN], 1)
%!error id=dbode:badInput dbode (0.8, 1, 1, 0, 0.1, 2)
%!error id=dbode:badInput dbode (eye (2), 1, 1, 0, 0.1, 1)

%!demo
%! dbode ([0 0.2], [1 -0.8], 0.1)
