## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn  {} {@var{M} =} idtf (@var{num}, @var{den})
## @deftypefnx {} {@var{M} =} idtf (@var{num}, @var{den}, @var{Ts})
## @deftypefnx {} {@var{M} =} idtf (@dots{}, @var{name}, @var{value}, @dots{})
## @deftypefnx {} {@var{M} =} idtf (@var{sys})
## Transfer-function model with identifiable parameters (System
## Identification Toolbox semantics), continuous time by default
## (@var{Ts} = 0; then @var{num} and @var{den} are in descending powers
## of s) or discrete time (descending powers of z).
##
## @var{num}, @var{den}: rows (one input, one output) or ny-by-nu cells of
## rows; @var{den} is normalised to a leading coefficient 1 (and @var{num}
## with it).  Name-value pairs set properties: @code{IODelay} (ny-by-nu),
## @code{InputDelay} (nu; seconds in continuous time), @code{Ts},
## @code{NoiseVariance}, names, @dots{}
## @var{sys} converts an @code{idpoly}, @code{idproc}, @code{idss} or a
## control-package @code{tf}/@code{ss}.
##
## Properties: Numerator, Denominator, IODelay, Variable and those common
## to all models (see @code{help idpoly}); methods as for @code{idpoly}.
##
## @strong{Example}
## @example
## M0 = idtf (2, [1 3 2], "IODelay", 0.5);      # 2 e^(-0.5 s)/(s^2+3s+2)
## y = sim (M0, iddata ([], ones (100, 1), 0.05));
## @end example
## @seealso{idpoly, idproc, idss, tfsrivc}
## @end deftypefn

function varargout = idtf (varargin)
  ## The precedence over the control package's models is declared here,
  ## in the constructor itself: Octave ignores it from a subfunction.
  try
    superiorto ("tf", "ss", "frd", "lti");
  catch
  end_try_catch
  varargout = contsid_guard ({"idtf", "idtf"}, @idtf_body, nargout, varargin);
endfunction

function [M, varargout] = idtf_body (varargin)
  contsid_nargchk ("idtf", nargin, nargout, [0 Inf], 1);
  if (nargin > 0 && isobject (varargin{1}))
    M = convert (varargin{:});
    return;
  endif
  [pos, pairs, Tsp] = ctor_args ("idtf", varargin, [2 3]);
  [num, den, Ts] = pos{:};
  if (! isempty (Tsp))
    Ts = Tsp;
  elseif (isempty (Ts))
    Ts = 0;
  endif
  if (! iscell (num))
    num = {num};
  endif
  if (! iscell (den))
    den = repmat ({den}, size (num));
  endif
  if (isempty (num))
    error ("idtf:badInput", "idtf: num and den must not be empty");
  endif
  if (! isequal (size (num), size (den)))
    error ("idtf:dimensionMismatch",
           "idtf: num and den must have the same ny-by-nu size");
  endif
  for k = 1:numel (den)
    d = den{k};
    if (! isnumeric (d) || isempty (d) || ! isreal (d) || d(1) == 0)
      error ("idtf:badInput",
             "idtf: each denominator must be a real row, leading term != 0");
    endif
    if (! isnumeric (num{k}))
      error ("idtf:badInput", "idtf: numerators must be real rows");
    endif
    num{k} = num{k} / d(1);
    den{k} = d / d(1);
  endfor
  [ny, nu] = size (num);
  par = struct ("Numerator", {repmat({0}, ny, nu)},
                "Denominator", {repmat({1}, ny, nu)},
                "IODelay", zeros (ny, nu));
  M = class (struct (), "idtf", idmodel ("idtf", par, ny, nu));
  M = set (M, "Ts", Ts, "Numerator", num, "Denominator", den, pairs{:});
endfunction

function M = convert (sys, varargin)
  if (isa (sys, "idtf"))
    M = set (sys, varargin{:});
    return;
  endif
  if (! isa (sys, "idmodel") && ! isa (sys, "lti"))
    error ("idtf:badInput", "idtf: cannot convert a %s", class (sys));
  endif
  [num, den] = tfdata (sys);
  if (isa (sys, "idmodel"))
    Ts = get (sys, "Ts");
    delay = totaldelay (sys);
  else
    Ts = max (get (sys, "tsam"), 0);
    delay = zeros (size (num));
  endif
  M = idtf (num, den, Ts, "IODelay", delay, varargin{:});
  if (isa (sys, "idmodel"))
    M = set (M, "NoiseVariance", get (sys, "NoiseVariance"),
             "Name", get (sys, "Name"));
  endif
endfunction

%!test
%! M = idtf (2, [2 6 4], "IODelay", 0.5);
%! assert (M.Numerator, {1});
%! assert (M.Denominator, {[1 3 2]});
%! assert (M.IODelay, 0.5);
%! assert (M.Ts, 0);
%! M2 = idtf (2, [1 3 2], "InputDelay", 0.2);
%! assert (totaldelay (M2), 0.2);

%!test  # idtf of an idpoly and of an idproc
%! P = idpoly (1, [1 2], 1, 1, [1 3 2], 0, 0, "InputDelay", 0.3);
%! M = idtf (P);
%! assert (M.Numerator{1}, [1 2]);
%! assert (totaldelay (M), 0.3);
%! Q = idproc ("P1D", "Kp", 2, "Tp1", 4, "Td", 1);
%! G = idtf (Q);
%! assert (G.Denominator{1}, [1 0.25], 1e-15);
%! assert (G.Numerator{1}, 0.5, 1e-15);
%! assert (G.IODelay, 1);

%!error id=idtf:badInput idtf ()
%!error id=idtf:badInput idtf (1)
%!error id=idtf:badInput idtf (1, [0 1])
%!error id=idtf:badInput idtf (1, [1 1], "IODelay", -1)
%!error id=idtf:badInput idtf (1, [1 1], "bogus", 2)
%!error id=idtf:badInput idtf ("a", [1 1])
%!error id=idtf:dimensionMismatch idtf ({1, 2}, {[1 1]; [1 2]})
%!error id=idtf:badInput idtf (struct ())
%!error id=idtf:badInput idtf ({}, {})

%!demo
%! M0 = idtf (2, [1 3 2], "IODelay", 0.5)
%! step (M0);
