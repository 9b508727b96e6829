## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn  {} {} damp (@var{M})
## @deftypefnx {} {[@var{wn}, @var{zeta}, @var{p}] =} damp (@var{M})
## Natural frequencies, damping ratios and poles of a model (computed from
## @code{pole}); printed without outputs.
## @end deftypefn

function varargout = damp (varargin)
  varargout = contsid_guard ({"damp", "idmodel"}, @damp_body, nargout,
                             varargin);
endfunction

function [wn, zeta, p, varargout] = damp_body (M, varargin)
  contsid_nargchk ("damp", nargin, nargout, [1 1], 3);
  P = pstruct (M);
  p = pole (M);
  if (P.Ts > 0)
    s = log (p) / P.Ts;
  else
    s = p;
  endif
  w = abs (s);
  z = -real (s) ./ w;
  z(w == 0) = -1;
  [w, k] = sort (w);
  z = z(k);
  p = p(k);
  if (nargout > 0)
    [wn, zeta] = deal (w, z);
    return;
  endif
  printf ("%14s %14s %14s\n", "pole", "damping", "frequency");
  for i = 1:numel (p)
    printf ("%14s %14.4g %14.4g\n", num2str (p(i), 4), z(i), w(i));
  endfor
endfunction

%!test
%! [wn, z] = damp (idtf (4, [1 2.4 4]));
%! assert (wn, [2; 2], 1e-12);
%! assert (z, [0.6; 0.6], 1e-12);
%!error id=idfrd:notSupported damp (idfrd (1, 1))

%!demo
%! damp (idtf (4, [1 2.4 4]))
