## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn {} {@var{p} =} pole (@var{M})
## Poles of a model (the control package's @code{pole} of @code{tf (M)},
## delays aside).
## @end deftypefn

function varargout = pole (varargin)
  varargout = contsid_guard ({"pole", "idmodel"}, @pole_body, nargout,
                             varargin);
endfunction

function [p, varargout] = pole_body (M, varargin)
  contsid_nargchk ("pole", nargin, nargout, [1 1], 1);
  [~, ~, ~, ~, ~, ~, P] = sys_data (M, "pole");
  p = pole (lti_of (P, ifelse_ss (P), "pole"));
endfunction

function f = ifelse_ss (P)
  f = "tf";
  if (strcmp (P.kind, "idss"))
    f = "ss";
  endif
endfunction

%!test
%! p = pole (idpoly (1, 2, 1, 1, [1 3 2], "Ts", 0));
%! assert (sort (p), [-2; -1], 1e-12);
%! p = pole (idss (diag ([-1 -3]), [1; 1], [1 1], 0));
%! assert (sort (p), [-3; -1], 1e-12);
%!error id=idfrd:notSupported pole (idfrd (1, 1))

%!demo
%! pole (idproc ("P2DU", "Kp", 1, "Tw", 0.5, "Zeta", 0.3))
