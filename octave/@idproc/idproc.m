## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn  {} {@var{M} =} idproc (@var{type})
## @deftypefnx {} {@var{M} =} idproc (@var{type}, @var{name}, @var{value}, @dots{})
## Continuous-time process model (System Identification Toolbox
## semantics):
## @example
## G(s) = Kp (1 + Tz s) / ((1 + Tp1 s)(1 + Tp2 s)(1 + Tp3 s)) e^(-Td s)
## @end example
## @var{type} is @qcode{"P"}, the number of poles 0..3, and any of the
## letters D (delay Td), Z (zero Tz), U (underdamped: Tp1, Tp2 replaced by
## 1 + 2 Zeta Tw s + (Tw s)^2), I (integrator 1/s), e.g. @qcode{"P2DU"},
## @qcode{"P1D"}.  Name-value pairs give the parameters (@code{Kp},
## @code{Tp1}, @code{Tp2}, @code{Tp3}, @code{Tw}, @code{Zeta}, @code{Td},
## @code{Tz}) or any other property.  Parameters not given are NaN (to be
## estimated, as in the SITB).
##
## @code{Structure} holds for each parameter a struct with
## @code{Value}, @code{Minimum}, @code{Maximum} and @code{Free}
## (@code{init_sys.Structure.Td.Maximum = 2}); the parameter properties
## read and write its @code{Value}.  A model with NaN parameters cannot be
## simulated (@code{idproc:badInput}).
##
## @strong{Example}
## @example
## init_sys = idproc ("P2DU");
## init_sys.Structure.Td.Value = 0.2;
## M0 = idproc ("P1D", "Kp", 2, "Tp1", 4, "Td", 1);
## @end example
## @seealso{idtf, idpoly, procsrivc}
## @end deftypefn

function varargout = idproc (varargin)
  ## The precedence over the control package's models is declared here,
  ## in the constructor itself: Octave ignores it from a subfunction.
  try
    superiorto ("tf", "ss", "frd", "lti");
  catch
  end_try_catch
  varargout = contsid_guard ({"idproc", "idproc"}, @idproc_body, nargout,
                             varargin);
endfunction

function [M, varargout] = idproc_body (varargin)
  contsid_nargchk ("idproc", nargin, nargout, [0 Inf], 1);
  if (nargin == 0 || ! ischar (varargin{1}))
    if (nargin == 1 && isa (varargin{1}, "idproc"))
      M = varargin{1};
      return;
    endif
    error ("idproc:badInput", "idproc: expected a type such as 'P2DU'");
  endif
  type = upper (varargin{1});
  names = proc_names (type);   # @idmodel/private, linked here
  pairs = varargin(2:end);
  if (mod (numel (pairs), 2) != 0)
    error ("idproc:badInput",
           "idproc: properties must come in name-value pairs");
  endif
  S = struct ();
  for i = 1:numel (names)
    lo = 0;
    if (strcmp (names{i}, "Kp"))
      lo = -Inf;
    endif
    S.(names{i}) = struct ("Value", NaN, "Minimum", lo, "Maximum", Inf,
                           "Free", true);
  endfor
  par = struct ("Type", type, "Integration", any (type == "I"),
                "Structure", S);
  M = class (struct (), "idproc", idmodel ("idproc", par, 1, 1));
  M = set (M, pairs{:});
endfunction

%!test
%! M = idproc ("P2DU");
%! assert (M.Type, "P2DU");
%! assert (fieldnames (M.Structure)', {"Kp", "Tw", "Zeta", "Td"});
%! assert (isnan (M.Kp));
%! M = idproc ("p1d", "Kp", 2, "Tp1", 4, "Td", 1);
%! assert ([M.Kp M.Tp1 M.Td], [2 4 1]);
%! assert (getpvec (M), [2; 4; 1]);
%! M2 = idproc ("P2UD");
%! assert (M2.Type, "P2UD");

%!error id=idproc:badInput idproc ()
%!error id=idproc:badInput idproc ("P4")
%!error id=idproc:badInput idproc ("P1U")
%!error id=idproc:badInput idproc ("P2DD")
%!error id=idproc:badInput idproc ("P1", "Td", 1)
%!error id=idproc:badInput idproc ("P1D", "Td", -1)
%!error id=idproc:badInput idproc ("P1D", "Kp")

%!demo
%! M0 = idproc ("P2DU", "Kp", 1, "Tw", 0.5, "Zeta", 0.3, "Td", 0.2)
%! step (M0);
