## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn {} {@var{M} =} setpvec (@var{M}, @var{p})
## Sets the parameters of a model from a vector in the order of
## @code{getpvec} (an @code{idtf}'s ends with its IODelay entries, >= 0);
## the covariance is kept (it describes the same parameters).  A vector
## of the wrong length: @code{<class>:dimensionMismatch}; NaN or Inf
## entries (an @code{idproc} may hold NaN, a parameter not yet known):
## @code{<class>:badInput}.
## @end deftypefn

function varargout = setpvec (varargin)
  varargout = contsid_guard ({"setpvec", "idmodel"}, @setpvec_body, nargout,
                             varargin);
endfunction

function [M, varargout] = setpvec_body (M, p, varargin)
  contsid_nargchk ("setpvec", nargin, nargout, [2 2], 1);
  P = pstruct (M);
  p0 = pvec_of (P);
  if (! isnumeric (p) || ! isreal (p) || numel (p) != numel (p0))
    error ([P.kind ":dimensionMismatch"],
           "%s: setpvec needs %d real parameters", P.kind, numel (p0));
  endif
  P = pvec_set (P, double (p(:)));
  M.par = P.par;
endfunction

%!test
%! M = setpvec (idpoly (1, [3 4], 1, 1, [1 1.2 2], "Ts", 0), [1 2 3 4]);
%! assert ({M.B, M.F}, {[1 2], [1 3 4]});
%! P = setpvec (idproc ("P1D"), [2 4 1]);
%! assert ([P.Kp P.Tp1 P.Td], [2 4 1]);
%! M = setpvec (idtf (1, [1 2]), [1; 5; 0.25]);   # [num den(2) IODelay]
%! [~, den] = tfdata (M, "vector");
%! assert ({den, M.IODelay}, {[1 5], 0.25});
%!error id=idtf:dimensionMismatch setpvec (idtf (2, [1 3 2]), [1 2])
%!error id=idtf:dimensionMismatch setpvec (idtf (2, [1 3 2]), [1 2 3])
%!error id=idtf:badInput setpvec (idtf (2, [1 3 2]), [1 2 3 -1])
## NaN or Inf coefficients: refused (the control package's pole and
## realisation routines would not return on them)
%!error id=idpoly:badInput
%! setpvec (idpoly (1, 4, 1, 1, [1 2.4 4], "Ts", 0), [4; 2.4; NaN]);
%!error id=idpoly:badInput
%! setpvec (idpoly (1, 4, 1, 1, [1 2.4 4], "Ts", 0), [4; Inf; 4]);
%!error id=idtf:badInput setpvec (idtf (2, [1 3 2]), [NaN 3 2 0])
%!error id=idss:badInput setpvec (idss (-1, 1, 1, 0), [NaN 1 1 0])
%!error id=idproc:badInput setpvec (idproc ("P1D"), [2 Inf 1])
%!test
%! ## an idproc's NaN is a parameter not yet known
%! P = setpvec (idproc ("P1D"), [2 NaN 1]);
%! assert (isnan (P.Tp1));

%!demo
%! M = setpvec (idtf (2, [1 3 2]), [4 3 2 0.5])
