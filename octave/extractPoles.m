## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn {} {@var{poles} =} extractPoles (@var{A}, @var{DepA})
## Frozen poles of a continuous-time LPV model at each sample of the
## scheduling signal.
##
## @var{A} ((na+1)-by-n_dep) and @var{DepA} (n_dep-by-na-by-N) are the
## denominator coefficients and basis functions of @code{simulLPVCT},
## @code{lpvsrivc} (@code{infos.Arivc}) and @code{lpvrivc}.  At sample k
## the frozen polynomial a0 p^na + a1(rho_k) p^(na-1) + .. + a_na(rho_k),
## with a_i(rho_k) = sum_j A(i+1, j) DepA(j, i, k), is formed and its
## roots are column k of the na-by-N complex matrix @var{poles} (NaN where
## a trailing-coefficient degeneracy leaves fewer roots).  Frozen poles
## describe the time-invariant model at a fixed scheduling value; they do
## not decide the stability of the time-varying system.
##
## @strong{Example}: the poles of s^2 + (2 - 1.5 r + 2 r^2) s + 5 + 3 r
## for r from -1 to 1
## @example
## r = -1:0.01:1;
## DepA(:,1,:) = [ones(size(r)); r; r.^2];
## DepA(:,2,:) = [ones(size(r)); r; zeros(size(r))];
## P = extractPoles ([1 0 0; 2 -1.5 2; 5 3 0], DepA);
## plot (real (P(:)), imag (P(:)), ".")
## @end example
## @seealso{extractZeros, simulLPVCT, lpvsrivc}
## @end deftypefn

function varargout = extractPoles (varargin)
  varargout = contsid_guard ("extractPoles", @extractPoles_body, nargout, varargin);
endfunction

function varargout = extractPoles_body (varargin)
  contsid_nargchk ("extractPoles", nargin, nargout, [2 2], 1);
  varargout{1} = lpv_frozen_roots ("extractPoles", varargin{1}, varargin{2},
                                   true);
endfunction

%!test
%! r = [-1 0 0.5];
%! DepA = zeros (3, 2, 3);
%! DepA(:,1,:) = [ones(size(r)); r; r.^2];
%! DepA(:,2,:) = [ones(size(r)); r; zeros(size(r))];
%! A = [1 0 0; 2 -1.5 2; 5 3 0];
%! P = extractPoles (A, DepA);
%! assert (size (P), [2 3]);
%! for k = 1:3
%!   a = [1, 2 - 1.5*r(k) + 2*r(k)^2, 5 + 3*r(k)];
%!   assert (sort (P(:,k)), sort (roots (a)), 1e-12);
%!   assert (abs (polyval (a, P(:,k))) < 1e-10);
%! endfor

## A leading coefficient other than 1 scales the polynomial, not the poles:
## 2 p^2 + 6 p + 4 = 2 (p + 1)(p + 2) at every sample.
%!test
%! P = extractPoles ([2 0; 6 0; 4 0], ones (2, 2, 4));
%! assert (sort (P, 1), repmat ([-2; -1], 1, 4), 1e-12);

%!error <Invalid call|called with> extractPoles (1)
%!error id=extractPoles:dimensionMismatch extractPoles (ones (2, 3), ones (3, 2, 4))
%!error id=extractPoles:badInput extractPoles ("a", ones (3, 2, 4))

%!demo
%! ## Frozen poles of s^2 + (2 - 1.5 r + 2 r^2) s + 5 + 3 r, r in [-1, 1]
%! r = -1:0.01:1; DepA = zeros (3, 2, numel (r));
%! DepA(:,1,:) = [ones(size(r)); r; r.^2];
%! DepA(:,2,:) = [ones(size(r)); r; zeros(size(r))];
%! P = extractPoles ([1 0 0; 2 -1.5 2; 5 3 0], DepA);
%! plot (real (P(:)), imag (P(:)), "."); xlabel ("real"); ylabel ("imaginary");
