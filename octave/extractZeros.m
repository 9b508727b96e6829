## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn {} {@var{zeros} =} extractZeros (@var{B}, @var{DepB})
## Frozen zeros of a continuous-time LPV model at each sample of the
## scheduling signal.
##
## @var{B} (nb-by-n_dep) and @var{DepB} (n_dep-by-nb-by-N) are the
## numerator coefficients and basis functions of @code{simulLPVCT},
## @code{lpvsrivc} (@code{infos.Brivc}) and @code{lpvrivc}.  At sample k the
## frozen polynomial b1(rho_k) p^(nb-1) + .. + b_nb(rho_k), with
## b_i(rho_k) = sum_j B(i, j) DepB(j, i, k), is formed and its roots are
## column k of the (nb-1)-by-N complex matrix @var{zeros} (NaN where the
## leading coefficients vanish and the frozen numerator has fewer roots).
##
## @strong{Example}: the zero of (3 + 2 cos r) p + 5 - 3 sin(2 r)
## @example
## r = -1:0.01:1;
## DepB(:,1,:) = [ones(size(r)); cos(r)];
## DepB(:,2,:) = [ones(size(r)); sin(2*r)];
## Z = extractZeros ([3 2; 5 -3], DepB);
## plot (r, real (Z))
## @end example
## @seealso{extractPoles, simulLPVCT, lpvsrivc}
## @end deftypefn

function varargout = extractZeros (varargin)
  varargout = contsid_guard ("extractZeros", @extractZeros_body, nargout, varargin);
endfunction

function varargout = extractZeros_body (varargin)
  contsid_nargchk ("extractZeros", nargin, nargout, [2 2], 1);
  varargout{1} = lpv_frozen_roots ("extractZeros", varargin{1}, varargin{2},
                                   false);
endfunction

%!test
%! r = linspace (-1, 1, 7);
%! DepB = zeros (2, 2, 7);
%! DepB(:,1,:) = [ones(size(r)); cos(r)];
%! DepB(:,2,:) = [ones(size(r)); sin(2*r)];
%! Z = extractZeros ([3 2; 5 -3], DepB);
%! assert (size (Z), [1 7]);
%! assert (Z, -(5 - 3*sin (2*r)) ./ (3 + 2*cos (r)), 1e-12);

## The leading coefficient vanishes at one sample: one root fewer (NaN).
%!test
%! DepB = ones (1, 3, 2);
%! DepB(1,1,2) = 0;
%! Z = extractZeros ([1; 3; 2], DepB);
%! assert (sort (Z(:,1)), [-2; -1], 1e-12);
%! assert (Z(1,2), -2/3, 1e-12);
%! assert (isnan (Z(2,2)));

%!error id=extractZeros:dimensionMismatch extractZeros (ones (2, 3), ones (2, 2, 4))
%!error id=extractZeros:badInput extractZeros ([1 2], ones (2, 1, 4) * NaN)

%!demo
%! ## Frozen zero of (3 + 2 cos r) p + 5 - 3 sin(2 r), r in [-1, 1]
%! r = -1:0.01:1; DepB = zeros (2, 2, numel (r));
%! DepB(:,1,:) = [ones(size(r)); cos(r)];
%! DepB(:,2,:) = [ones(size(r)); sin(2*r)];
%! Z = extractZeros ([3 2; 5 -3], DepB);
%! plot (r, real (Z)); xlabel ("scheduling value"); ylabel ("zero");
