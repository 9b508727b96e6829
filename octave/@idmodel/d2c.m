## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn  {} {@var{Mc} =} d2c (@var{M})
## @deftypefnx {} {@var{Mc} =} d2c (@var{M}, @var{method})
## Continuous-time model of a discrete-time one with the control
## package's @code{d2c} (@qcode{"zoh"} by default); the result has the
## class of @var{M}, sample delays become delays in seconds.  The
## covariance is not carried over.
## @end deftypefn

function varargout = d2c (varargin)
  varargout = contsid_guard ({"d2c", "idmodel"}, @d2c_body, nargout, varargin);
endfunction

function [Mc, varargout] = d2c_body (M, method, varargin)
  contsid_nargchk ("d2c", nargin, nargout, [1 2], 1);
  if (nargin < 2)
    method = "zoh";
  elseif (! (ischar (method)
              && any (strcmpi (method, {"zoh", "tustin", "matched"}))))
    error ("d2c:badInput", "d2c: method must be 'zoh', 'tustin' or 'matched'");
  endif
  P = pstruct (M);
  if (P.Ts == 0)
    error ("d2c:badInput", "d2c: the model is already continuous-time");
  endif
  f = "tf";
  if (strcmp (P.kind, "idss"))
    f = "ss";
  endif
  [G, delay] = lti_of (P, f, "d2c");
  try
    Gc = d2c (G, method);
  catch err
    ## The control package's errors carry no identifier (e.g. a pole at
    ## z = 0 or on the negative real axis has no ZOH continuous equivalent).
    error ("d2c:numericalFailure",
           "d2c: the control package could not convert the model: %s",
           err.message);
  end_try_catch
  Mc = back (P, Gc, delay * P.Ts);
endfunction

%!test  # first order, exact: z-pole 0.9 <-> s-pole log (0.9) / Ts
%! Ts = 0.1;
%! M = idtf (0.1, [1 -0.9], Ts, "IODelay", 2);
%! Mc = d2c (M);
%! assert (Mc.Denominator{1}, [1, -log(0.9) / Ts], 1e-9);
%! assert (Mc.IODelay, 0.2, 1e-12);
%! g = polyval (Mc.Numerator{1}, 0) / polyval (Mc.Denominator{1}, 0);
%! assert (g, 1, 1e-9);
%!error id=d2c:badInput d2c (idtf (1, [1 -0.5], 0.1), "foh")
%!error id=d2c:badInput d2c (idtf (1, [1 1]))

%!demo
%! Mc = d2c (idpoly (1, [0 0.5], 1, 1, [1 -0.5], 1, 0.1))
