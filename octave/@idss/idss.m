## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn  {} {@var{M} =} idss (@var{A}, @var{B}, @var{C}, @var{D})
## @deftypefnx {} {@var{M} =} idss (@var{A}, @var{B}, @var{C}, @var{D}, @var{K}, @var{x0}, @var{Ts})
## @deftypefnx {} {@var{M} =} idss (@dots{}, @var{name}, @var{value}, @dots{})
## @deftypefnx {} {@var{M} =} idss (@var{sys})
## State-space model with identifiable parameters (System Identification
## Toolbox semantics), continuous time by default (@var{Ts} = 0):
## @example
## x' = A x + B u + K e,   y = C x + D u + e
## @end example
## @var{K} (default zero) and @var{x0} (default zero) are optional;
## @var{sys} converts an @code{idpoly}, @code{idtf}, @code{idproc} or a
## control-package @code{ss}/@code{tf}.  Properties A, B, C, D, K, x0,
## StateName, StateUnit and those common to all models (read as
## @code{M.a} or @code{M.A}); methods as for @code{idpoly}; @code{sim}
## and @code{comparec} simulate it exactly for ZOH or FOH inputs.
##
## @strong{Example}
## @example
## M0 = idss ([-1 0; 1 -2], [1; 0], [0 1], 0);
## y = sim (M0, iddata ([], ones (200, 1), 0.05));
## @end example
## @seealso{idpoly, idtf, comparec}
## @end deftypefn

function varargout = idss (varargin)
  ## The precedence over the control package's models is declared here,
  ## in the constructor itself: Octave ignores it from a subfunction.
  try
    superiorto ("tf", "ss", "frd", "lti");
  catch
  end_try_catch
  varargout = contsid_guard ({"idss", "idss"}, @idss_body, nargout, varargin);
endfunction

function [M, varargout] = idss_body (varargin)
  contsid_nargchk ("idss", nargin, nargout, [0 Inf], 1);
  if (nargin > 0 && isobject (varargin{1}))
    M = convert (varargin{:});
    return;
  endif
  [pos, pairs, Tsp] = ctor_args ("idss", varargin, [4 7]);
  [A, B, C, D, K, x0, Ts] = pos{:};
  for v = {A, B, C, D, K, x0, Ts}
    if (! isnumeric (v{1}) || ! isreal (v{1}) || any (! isfinite (v{1}(:))))
      error ("idss:badInput", "idss: A, B, C, D, K, x0 must be finite real");
    endif
  endfor
  n = rows (A);
  if (isempty (D))
    D = zeros (rows (C), columns (B));
  endif
  if (isempty (K))
    K = zeros (n, rows (C));
  endif
  if (isempty (x0))
    x0 = zeros (n, 1);
  endif
  if (isempty (Ts))
    Ts = 0;
  endif
  if (columns (A) != n || rows (B) != n || columns (C) != n
      || ! isequal (size (D), [rows(C), columns(B)])
      || ! isequal (size (K), [n, rows(C)]) || numel (x0) != n)
    error ("idss:dimensionMismatch",
           ["idss: A (n-by-n), B (n-by-nu), C (ny-by-n), D (ny-by-nu), ", ...
            "K, x0 do not fit"]);
  endif
  par = struct ("A", double (A), "B", double (B), "C", double (C),
                "D", double (D), "K", double (K), "x0", double (x0(:)),
                "StateName", {repmat({""}, n, 1)},
                "StateUnit", {repmat({""}, n, 1)});
  M = class (struct (), "idss", idmodel ("idss", par, rows (C), columns (B)));
  if (! isempty (Tsp))
    Ts = Tsp;
  endif
  M = set (M, "Ts", Ts, pairs{:});
endfunction

function M = convert (sys, varargin)
  if (isa (sys, "idss"))
    M = set (sys, varargin{:});
    return;
  endif
  if (! isa (sys, "idmodel") && ! isa (sys, "lti"))
    error ("idss:badInput", "idss: cannot convert a %s", class (sys));
  endif
  G = ss (sys);
  [a, b, c, d] = ssdata (G);
  Ts = max (get (G, "tsam"), 0);
  M = idss (a, b, c, d, [], [], Ts, varargin{:});
  if (isa (sys, "idmodel"))
    delay = totaldelay (sys);
    if (any (any (delay != repmat (delay(1, :), rows (delay), 1))))
      error ("idss:notSupported",
             "idss: delays that differ between outputs cannot be kept");
    endif
    M = set (M, "InputDelay", delay(1, :).',
             "NoiseVariance", get (sys, "NoiseVariance"));
  endif
endfunction

%!test
%! M = idss ([-1 0; 1 -2], [1; 0], [0 1], 0);
%! assert (M.a, [-1 0; 1 -2]);
%! assert (M.C, [0 1]);
%! assert (M.Ts, 0);
%! assert (size (M.K), [2 1]);

%!test  # conversion keeps the transfer function
%! M = idss (idtf (2, [1 3 2]));
%! [n, d] = tfdata (M, "v");
%! assert (d, [1 3 2], 1e-12);
%! assert (n(end), 2, 1e-12);

%!error id=idss:badInput idss ()
%!error id=idss:badInput idss (1, 1, 1)
%!error id=idss:badInput idss ([-1 NaN], 1, 1, 0)
%!error id=idss:dimensionMismatch idss ([-1 0; 0 -2], [1; 0], [0 1 1], 0)
%!error id=idss:badInput idss (-1, 1, 1, 0, "bogus", 1)
%!error id=idss:badInput idss ("x")

%!demo
%! M0 = idss ([-1 0; 1 -2], [1; 0], [0 1], 0)
%! step (M0);
