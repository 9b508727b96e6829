## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn {} {@var{z} =} zero (@var{M})
## Zeros of a model (the control package's @code{zero}).
## @end deftypefn

function varargout = zero (varargin)
  varargout = contsid_guard ({"zero", "idmodel"}, @zero_body, nargout,
                             varargin);
endfunction

function [z, varargout] = zero_body (M, varargin)
  contsid_nargchk ("zero", nargin, nargout, [1 1], 1);
  [~, ~, ~, ~, ~, ~, P] = sys_data (M, "zero");
  z = zero (lti_of (P, "tf", "zero"));
endfunction

%!test
%! assert (zero (idtf ([1 4], [1 3 2])), -4, 1e-12);
%!error id=idfrd:notSupported zero (idfrd (1, 1))

%!demo
%! zero (idtf ([1 4], [1 3 2]))
