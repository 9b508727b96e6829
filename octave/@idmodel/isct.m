## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn {} {@var{tf} =} isct (@var{M})
## True for a continuous-time model (Ts = 0).
## @end deftypefn

function [r, varargout] = isct (M, varargin)
  contsid_nargchk ("isct", nargin, nargout, [1 1], 1);
  r = pstruct (M).Ts == 0;
endfunction

%!assert (isct (idtf (1, [1 1])))
%!assert (! isct (idpoly (1, 1, 1, 1, [1 -0.5], 1, 0.1)))

%!demo
%! isct (idtf (1, [1 1]))
