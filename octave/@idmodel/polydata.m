## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn  {} {[@var{A}, @var{B}, @var{C}, @var{D}, @var{F}] =} polydata (@var{M})
## @deftypefnx {} {[@var{A}, @var{B}, @var{C}, @var{D}, @var{F}, @var{dA}, @var{dB}, @var{dC}, @var{dD}, @var{dF}] =} polydata (@var{M})
## The polynomials of the idpoly form of a model (other classes are
## converted with @code{idpoly}) and their standard deviations (NaN
## without a covariance; 0 for the fixed leading 1s).  B and F are rows
## for one input, cells for several.
## @end deftypefn

function varargout = polydata (varargin)
  varargout = contsid_guard ({"polydata", "idmodel"}, @polydata_body, nargout,
                             varargin);
endfunction

function [A, B, C, D, F, dA, dB, dC, dD, dF, varargout] = ...
         polydata_body (M, varargin)
  contsid_nargchk ("polydata", nargin, nargout, [1 1], 10);
  if (! isa (M, "idpoly"))
    M = idpoly (M);
  endif
  P = pstruct (M);
  s = P.par;
  [A, C, D] = deal (s.A, s.C, s.D);
  [B, F] = deal (s.B, s.F);
  [~, sd] = getpvec (M);
  k = 0;
  dA = [0, take(numel (A) - 1)];
  dB = cellfun (@(b) take (numel (b)), B, "UniformOutput", false);
  dC = [0, take(numel (C) - 1)];
  dD = [0, take(numel (D) - 1)];
  dF = cellfun (@(f) [0, take(numel (f) - 1)], F, "UniformOutput", false);
  if (P.nu == 1)
    [B, F, dB, dF] = deal (B{1}, F{1}, dB{1}, dF{1});
  endif

  function v = take (n)
    v = sd(k+1:k+n).';
    k += n;
  endfunction
endfunction

%!test
%! [A, B, C, D, F, dA, dB] = polydata (idpoly (1, 2, 1, 1, [1 1.2 2], "Ts", 0));
%! assert ({A, B, C, D, F}, {1, 2, 1, 1, [1 1.2 2]});
%! assert (isnan (dB));
%! [A, B, C, D, F] = polydata (idtf (2, [1 3 2]));
%! assert ({B, F}, {2, [1 3 2]});
%!error id=idfrd:notSupported polydata (idfrd (1, 1))

%!demo
%! [A, B, C, D, F] = polydata (idtf (2, [1 3 2]))
