## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn  {} {@var{p} =} getpvec (@var{M})
## @deftypefnx {} {[@var{p}, @var{sd}] =} getpvec (@var{M})
## The model's parameters as a column, in the SITB order (idpoly: A, B,
## C, D, F without the leading 1s; idtf: numerators, denominators without
## their leading 1, then the IODelay (as the SITB's getpvec and nparams:
## @code{getpvec (idtf (1, [1 2]))} is [1; 2; 0]; CONTSID's advantage22
## reads an estimated delay as @code{param_est(4)}); idproc: Kp, Tp1, Tp2, Tp3, Tw, Zeta, Td, Tz of its type; idss: A, B,
## C, D column-wise), and their standard deviations (square roots of the
## covariance diagonal; NaN without a covariance).
## @end deftypefn

function varargout = getpvec (varargin)
  varargout = contsid_guard ({"getpvec", "idmodel"}, @getpvec_body, nargout,
                             varargin);
endfunction

function [p, sd, varargout] = getpvec_body (M, varargin)
  contsid_nargchk ("getpvec", nargin, nargout, [1 Inf], 2);
  P = pstruct (M);
  if (! isempty (varargin)
      && ! (ischar (varargin{1})
            && any (strcmpi (varargin{1}, {"free", "all"}))))
    error ([P.kind ":badInput"], "%s: getpvec's option is 'free' or 'all'",
           P.kind);
  endif
  p = pvec_of (P);
  if (isempty (P.cov))
    sd = NaN (size (p));
  else
    sd = sqrt (diag (P.cov));
  endif
endfunction

%!test
%! M = idpoly (1, [3 4], 1, 1, [1 1.2 2], "Ts", 0);
%! assert (getpvec (M), [3; 4; 1.2; 2]);
%! assert (getpvec (idtf (2, [1 3 2])), [2; 3; 2; 0]);
%! [p, sd] = getpvec (idtf (2, [1 3 2]));
%! assert (all (isnan (sd)));

%!test  # idtf: the IODelay is the last parameter; sizes agree with
%! # setpvec, setcov and getcov
%! M = idtf ([1 4], [1 2.4 4], "IODelay", 0.7);
%! p = getpvec (M);
%! assert (p, [1; 4; 2.4; 4; 0.7]);
%! M2 = setpvec (M, p + [0; 0; 0; 0; 0.3]);
%! assert (M2.IODelay, 1.0, 1e-15);
%! assert (totaldelay (M2), 1.0, 1e-15);
%! M3 = setcov (M, diag (1:5) / 100);
%! assert (size (getcov (M3)), [5 5]);
%! [~, sd] = getpvec (M3);
%! assert (sd, sqrt ((1:5).' / 100), 1e-15);
%! ## a MIMO idtf: one delay per I/O pair, after the coefficients
%! G = idtf ({1, 2}, {[1 1], [1 3]}, "IODelay", [0.5 1.5]);
%! assert (getpvec (G), [1; 2; 1; 3; 0.5; 1.5]);
%!error id=idtf:badInput getpvec (idtf (2, [1 3 2]), 3)

%!demo
%! getpvec (idproc ("P1D", "Kp", 2, "Tp1", 4, "Td", 1))
