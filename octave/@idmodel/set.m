## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn  {} {@var{M} =} set (@var{M}, @var{name}, @var{value}, @dots{})
## @deftypefnx {} {} set (@var{M})
## Sets properties of a model object (checked as in the constructors:
## monic denominators, delays >= 0, sizes); without values it lists the
## property names.
## @end deftypefn

function varargout = set (varargin)
  varargout = contsid_guard ({"set", "idmodel"}, @set_body, nargout, varargin);
endfunction

function [M, varargout] = set_body (M, varargin)
  contsid_nargchk ("set", nargin, nargout, [1 Inf], 1);
  P = pstruct (M);
  if (nargin == 1)
    if (nargout == 0)
      printf ("  %s\n", model_props (P.kind){:});
    endif
    return;
  endif
  if (mod (numel (varargin), 2) != 0)
    error ([P.kind ":badInput"], "%s: set needs name-value pairs", P.kind);
  endif
  for i = 1:2:numel (varargin)
    P = set_prop (P, match_prop (P, varargin{i}, P.kind), varargin{i+1},
                  P.kind);
  endfor
  for f = fieldnames (P).'
    M.(f{1}) = P.(f{1});
  endfor
endfunction

%!test
%! M = set (idtf (2, [1 3 2]), "IODelay", 0.5, "Name", "plant");
%! assert (M.IODelay, 0.5);
%! assert (M.Name, "plant");
%!error id=idtf:badInput set (idtf (2, [1 3 2]), "IODelay")
%!error id=idtf:badInput set (idtf (2, [1 3 2]), "IODelay", -2)
%!error id=idtf:badInput set (idtf (2, [1 3 2]), "Denominator", [2 3 2])
%!error id=idtf:badInput set (idtf (2, [1 3 2]), "InputName", {"a", "b"})
%!error id=idtf:badInput set (idtf (2, [1 3 2]), "Ts", -0.1)
%!error id=idtf:badInput set (idtf (2, [1 3 2]), "Report", 3)
%!error id=idtf:badInput set (idtf (2, [1 3 2]), "Report", struct ("Nothing", 1))
%!error id=idtf:badInput set (idtf (2, [1 3 2]), "NoiseVariance", -1)
%!error id=idpoly:badInput set (idpoly (1, 2, 1, 1, [1 3 2], 1, 0), "nk", Inf)
%!error id=idpoly:badInput set (idpoly (1, 2, 1, 1, [1 3 2], 1, 0), "nk", NaN)
%!error id=idpoly:badInput
%! set (idpoly (1, 4, 1, 1, [1 2.4 4], "Ts", 0), "theta", [4 2.4 NaN]);
%!error id=idpoly:badInput
%! set (idpoly (1, 4, 1, 1, [1 2.4 4], "Ts", 0), "theta", NaN);
%!error id=idpoly:badInput
%! set (idpoly (1, 4, 1, 1, [1 2.4 4], "Ts", 0), "covariance", -eye (3));
%!error id=idpoly:badInput
%! set (idpoly (1, 4, 1, 1, [1 2.4 4], "Ts", 0), "covariance", [1 2; 0 1]);
%!error id=idproc:badInput set (idproc ("P1D", "Kp", 2), "Kp", Inf)
%!error id=idproc:badInput idproc ("P1D", "Kp", -Inf)
%!test
%! M = set (idpoly (1, 4, 1, 1, [1 2.4 4], "Ts", 0), "covariance",
%!          int8 (eye (3)));
%! assert (getcov (M), eye (3));

%!demo
%! M = set (idpoly (1, 2, 1, 1, [1 1], "Ts", 0), "InputDelay", 0.3)
