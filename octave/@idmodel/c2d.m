## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn  {} {@var{Md} =} c2d (@var{M}, @var{Ts})
## @deftypefnx {} {@var{Md} =} c2d (@var{M}, @var{Ts}, @var{method})
## Discretises a continuous-time model with the control package's
## @code{c2d} (@var{method} @qcode{"zoh"} by default, or any method
## control accepts: @qcode{"foh"}, @qcode{"tustin"}, @qcode{"impulse"},
## @qcode{"matched"}).  The result has the class of @var{M} (an
## @code{idproc} gives an @code{idtf}); delays become sample delays and
## must be whole multiples of @var{Ts} (else @code{c2d:notSupported}).
## The covariance is not carried over.
## @end deftypefn

function varargout = c2d (varargin)
  varargout = contsid_guard ({"c2d", "idmodel"}, @c2d_body, nargout, varargin);
endfunction

function [Md, varargout] = c2d_body (M, Ts, method, varargin)
  contsid_nargchk ("c2d", nargin, nargout, [1 3], 1);
  if (nargin < 3)
    method = "zoh";
  elseif (! (ischar (method)
              && any (strcmpi (method, {"zoh", "foh", "tustin", "impulse", ...
                                        "matched"}))))
    error ("c2d:badInput",
           ["c2d: method must be 'zoh', 'foh', 'tustin', 'impulse' or ", ...
            "'matched'"]);
  endif
  P = pstruct (M);
  if (P.Ts > 0)
    error ("c2d:badInput", "c2d: the model is already discrete-time");
  endif
  if (nargin < 2 || ! isnumeric (Ts) || ! isscalar (Ts) || issparse (Ts)
      || ! isreal (Ts) || ! (Ts > 0) || ! isfinite (Ts))
    error ("c2d:badInput", "c2d: Ts must be a real finite scalar > 0");
  endif
  [G, delay] = lti_of (P, form_of (P), "c2d");
  nk = round (delay / Ts);
  if (any (abs (nk(:) - delay(:) / Ts) > 1e-9 * max (1, abs (nk(:)))))
    error ("c2d:notSupported",
           "c2d: the delays %s s are not multiples of Ts = %g",
           mat2str (delay, 4), Ts);
  endif
  ## exp (p Ts) of an unstable pole p overflows beyond Ts Re(p) = 709, and
  ## the control package then hangs (c2d (tf (1, [1 -1]), 1e300)).
  rate = max ([0; real(pole (G))(:)]) * Ts;
  if (rate > log (realmax))
    error ("c2d:numericalFailure",
           "c2d: exp (p Ts) overflows: Ts = %g times an unstable pole", Ts);
  endif
  try
    Gd = c2d (G, Ts, method);
  catch err
    ## The control package's errors carry no identifier (e.g. SLICOT's
    ## "DELTA too large" when Ts times the model's norm overflows expm).
    error ("c2d:numericalFailure",
           "c2d: the control package could not discretise at Ts = %g: %s",
           Ts, err.message);
  end_try_catch
  Md = back (P, Gd, nk);
endfunction

function f = form_of (P)
  f = "tf";
  if (strcmp (P.kind, "idss"))
    f = "ss";
  endif
endfunction

%!test  # against the exact ZOH discretisation, and the round trip
%! Ts = 0.1;
%! M = idpoly (1, [1 4], 1, 1, [1 2.4 4], "Ts", 0, "InputDelay", 0.3);
%! Md = c2d (M, Ts);
%! assert (class (Md), "idpoly");
%! assert ({Md.Ts, Md.InputDelay}, {Ts, 3});
%! ## ZOH: step responses agree at the sampling instants
%! t = (0:40)' * Ts;
%! assert (step (Md, t), step (M, t), 1e-10);
%! Mc = d2c (Md);
%! assert (Mc.F, M.F, 1e-9);
%! assert (Mc.B, M.B, 1e-9);
%! assert (Mc.InputDelay, 0.3, 1e-12);
%! S = c2d (idss ([-1 0; 1 -2], [1; 0], [0 1], 0), Ts);
%! assert (class (S), "idss");
%! assert (S.A, expm ([-1 0; 1 -2] * Ts), 1e-12);

%!error id=c2d:badInput c2d (idtf (1, [1 1]), sparse (1))
%!error id=c2d:badInput c2d (idtf (1, [1 1]), 0.1, 3)
%!error id=c2d:badInput c2d (idtf (1, [1 1]), 0.1, "bogus")
%!error id=c2d:badInput c2d (idtf (1, [1 1]), -1)
%!error id=c2d:badInput c2d (idtf (1, [1 1]), 1 + 2i)
%!error id=c2d:numericalFailure c2d (idtf (1, [1 2 1]), realmax)
%!error id=c2d:numericalFailure c2d (idtf (1, [1 -1]), 1e300)
%!error id=c2d:badInput c2d (idpoly (1, [0 1], 1, 1, [1 -0.5], 1, 0.1), 0.1)
%!error id=c2d:notSupported c2d (idtf (1, [1 1], "IODelay", 0.15), 0.1)

%!demo
%! Md = c2d (idtf (2, [1 3 2], "IODelay", 0.2), 0.1)
