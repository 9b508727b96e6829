## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn {} {@var{tf} =} isct (@var{M})
## True for a continuous-time model (Ts = 0).
## @end deftypefn

function varargout = isct (varargin)
  varargout = contsid_guard ({"isct", "idmodel"}, @isct_body, nargout,
                             varargin);
endfunction

function [r, varargout] = isct_body (M, varargin)
  contsid_nargchk ("isct", nargin, nargout, [1 1], 1);
  r = pstruct (M).Ts == 0;
endfunction

%!assert (isct (idtf (1, [1 1])))
%!assert (! isct (idpoly (1, 1, 1, 1, [1 -0.5], 1, 0.1)))

%!demo
%! isct (idtf (1, [1 1]))
