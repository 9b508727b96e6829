## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn  {} {} get (@var{M})
## @deftypefnx {} {@var{v} =} get (@var{M}, @var{name})
## @deftypefnx {} {[@var{v1}, @var{v2}, @dots{}] =} get (@var{M}, @var{name1}, @var{name2}, @dots{})
## @deftypefnx {} {@var{s} =} get (@var{M})
## Properties of a model object.  Without a name it lists them all (or
## returns them as a struct); names are case-insensitive with unique
## prefixes.
## @end deftypefn

function varargout = get (varargin)
  varargout = contsid_guard ({"get", "idmodel"}, @get_body, nargout, varargin);
endfunction

function varargout = get_body (M, varargin)
  contsid_nargchk ("get", nargin, nargout, [1 Inf], max (1, nargin - 1));
  P = pstruct (M);
  if (nargin == 1)
    names = model_props (P.kind);
    s = struct ();
    for i = 1:numel (names)
      try
        s.(names{i}) = get_prop (P, names{i});
      catch
        s.(names{i}) = [];         # e.g. nk of a CT model without data Ts
      end_try_catch
    endfor
    if (nargout == 0)
      disp (s);
    else
      varargout{1} = s;
    endif
    return;
  endif
  for i = 1:numel (varargin)
    varargout{i} = get_prop (P, match_prop (P, varargin{i}, P.kind));
  endfor
endfunction

%!test
%! M = idpoly (1, 2, 1, 1, [1 1.2 2], "Ts", 0);
%! assert (get (M, "Ts"), 0);
%! [b, f] = get (M, "b", "F");
%! assert ({b, f}, {2, [1 1.2 2]});
%! s = get (M);
%! assert (s.NoiseVariance, 1);
%!error id=idpoly:badInput get (idpoly (1, 2, 1, 1, [1 1]), "nothing")
%!error id=idpoly:badInput get (idpoly (1, 2, 1, 1, [1 1]), 3)

%!demo
%! M = idtf (2, [1 3 2]);
%! get (M)
