## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn {} {@var{P} =} getcov (@var{M})
## Covariance of the parameters (order of @code{getpvec}); @code{[]} for
## a model that was not estimated.
## @end deftypefn

function varargout = getcov (varargin)
  varargout = contsid_guard ({"getcov", "idmodel"}, @getcov_body, nargout,
                             varargin);
endfunction

function [C, varargout] = getcov_body (M, varargin)
  contsid_nargchk ("getcov", nargin, nargout, [1 1], 1);
  C = pstruct (M).cov;
endfunction

%!test
%! assert (getcov (idtf (2, [1 3 2])), []);
%! M = idctm (struct ("B", 2, "F", [1 3], "covariance", [1 0.5; 0.5 4]));
%! assert (getcov (M), [4 0.5; 0.5 1]);   # theta [f b] -> pvec [b f]

%!demo
%! M = idctm (struct ("B", 2, "F", [1 3], "covariance", diag ([0.1 0.2])));
%! getcov (M)
