## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn {} {@var{M} =} setcov (@var{M}, @var{C})
## Sets the covariance of the parameters (order of @code{getpvec}):
## symmetric positive semi-definite, np-by-np; @code{[]} removes it.  For
## an @code{idtf}, whose parameter vector ends with its IODelay entries
## (as in the SITB), the covariance of the coefficients alone may be given:
## the delays are then fixed parameters (zero rows and columns).
## Errors: @code{<class>:dimensionMismatch}, @code{<class>:badInput}.
## @end deftypefn

function varargout = setcov (varargin)
  varargout = contsid_guard ({"setcov", "idmodel"}, @setcov_body, nargout,
                             varargin);
endfunction

function [M, varargout] = setcov_body (M, C, varargin)
  contsid_nargchk ("setcov", nargin, nargout, [2 2], 1);
  P = pstruct (M);
  np = numel (pvec_of (P));
  if (isempty (C))
    M.cov = [];
    return;
  endif
  nd = 0;
  if (strcmp (P.kind, "idtf"))
    nd = numel (P.par.IODelay);
  endif
  if (nd > 0 && isnumeric (C) && isequal (size (C), [np-nd np-nd]))
    ## an idtf's coefficients alone: its IODelay is fixed (variance 0)
    C = blkdiag (C, zeros (nd));
  endif
  if (! isnumeric (C) || ! isreal (C) || ! isequal (size (C), [np np]))
    error ([P.kind ":dimensionMismatch"],
           "%s: the covariance must be %d-by-%d", P.kind, np, np);
  endif
  M.cov = check_cov (C, P.kind);
endfunction

%!test
%! M = setcov (idtf (2, [1 3]), diag ([0.04 0.01]));
%! [~, sd] = getpvec (M);
%! assert (sd, [0.2; 0.1; 0], 1e-15);    # the fixed IODelay: sd 0
%!test  # an idtf's coefficient block: the (fixed) delay gets variance 0
%! M = setcov (idtf (2, [1 3], "IODelay", 0.4), diag ([0.04 0.01]));
%! assert (getcov (M), diag ([0.04 0.01 0]));
%! M = setcov (M, diag ([0.04 0.01 0.0025]));
%! [p, sd] = getpvec (M);
%! assert ([p sd], [2 0.2; 3 0.1; 0.4 0.05], 1e-15);
%!error id=idtf:dimensionMismatch setcov (idtf (2, [1 3]), 1)
%!error id=idpoly:badInput
%! setcov (idpoly (1, 4, 1, 1, [1 2.4 4], "Ts", 0), int8 (-eye (3)));
%!test
%! M = setcov (idpoly (1, 4, 1, 1, [1 2.4 4], "Ts", 0), int8 (zeros (3)));
%! assert (getcov (M), zeros (3));
%!error id=idtf:badInput setcov (idtf (2, [1 3]), [1 2; 0 1])

%!demo
%! M = setcov (idtf (2, [1 3]), diag ([0.04 0.01]));
%! present (M)
