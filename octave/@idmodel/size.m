## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn  {} {@var{sz} =} size (@var{M})
## @deftypefnx {} {[@var{ny}, @var{nu}] =} size (@var{M})
## Numbers of outputs and inputs of a model.
## @end deftypefn

function varargout = size (M, dim, varargin)
  contsid_nargchk ("size", nargin, nargout, [1 2], 2);
  P = pstruct (M);
  sz = [P.ny, P.nu];
  if (nargin > 1)
    if (! (isnumeric (dim) && isscalar (dim) && any (dim == [1 2])))
      error ([P.kind ":badInput"], "%s: size's dimension must be 1 or 2",
             P.kind);
    endif
    varargout{1} = sz(dim);
  elseif (nargout <= 1)
    varargout{1} = sz;
  else
    varargout = {sz(1), sz(2)};
  endif
endfunction

%!test
%! assert (size (idpoly (1, {1, 2}, 1, 1, {[1 1], [1 2]}, "Ts", 0)), [1 2]);
%! [ny, nu] = size (idss (-1, [1 2], [1; 1], zeros (2)));
%! assert ([ny nu], [2 2]);
%!error id=idtf:badInput size (idtf (1, [1 1]), 3)

%!demo
%! size (idss (-1, [1 2], [1; 1], zeros (2)))
