## -*- texinfo -*-
## @deftypefn  {} {@var{p} =} getpvec (@var{M})
## @deftypefnx {} {[@var{p}, @var{sd}] =} getpvec (@var{M})
## The model's parameters as a column, in the SITB order (idpoly: A, B,
## C, D, F without the leading 1s; idtf: numerators then denominators;
## idproc: Kp, Tp1, Tp2, Tp3, Tw, Zeta, Td, Tz of its type; idss: A, B,
## C, D column-wise), and their standard deviations (square roots of the
## covariance diagonal; NaN without a covariance).
## @end deftypefn

function [p, sd, varargout] = getpvec (M, varargin)
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
%! assert (getpvec (idtf (2, [1 3 2])), [2; 3; 2]);
%! [p, sd] = getpvec (idtf (2, [1 3 2]));
%! assert (all (isnan (sd)));
%!error id=idtf:badInput getpvec (idtf (2, [1 3 2]), 3)

%!demo
%! getpvec (idproc ("P1D", "Kp", 2, "Tp1", 4, "Td", 1))
