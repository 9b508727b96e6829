## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn {} {@var{y} =} local_filter3 (@var{B}, @var{A}, @var{x})
## Two-dimensional recursive (quarter-plane) filter of the array @var{x}
## along its rows (first index, e.g. time) and columns (second index, e.g.
## space):
##
## @example
## sum_ij A(i,j) y(k-i+1, l-j+1) = sum_ij B(i,j) x(k-i+1, l-j+1)
## @end example
##
## i.e. @code{y = B(q1,q2) / A(q1,q2) x} with @code{B(i,j)} and
## @code{A(i,j)} the coefficients of @code{q1^-(i-1) q2^-(j-1)}.  The
## values before the first row or column are zero.  @code{A(1,1)} must be
## nonzero.  A separable filter is the outer product of two
## one-dimensional ones: @code{B = bt(:) * bs(:).'}, @code{A = at(:) *
## as(:).'} filters by @code{bt/at} along the rows and @code{bs/as} along
## the columns, like @code{filter} applied along each dimension.  This is
## how CONTSID's heat-equation demo colours a noise field.
##
## Example (noise with the time AR part (1 - 1.2 q_t^-1 + 0.4 q_t^-2) and
## the space AR part (1 - 0.3 q_x^-1)):
## @example
## e = randn (500, 50);
## v = local_filter3 ([1 0 0]' * [1 0 0], [1 -1.2 0.4]' * [1 -0.3 0], e);
## @end example
## @seealso{filter, filter2, conv2, sim_heat}
## @end deftypefn

function varargout = local_filter3 (varargin)
  varargout = contsid_guard ("local_filter3", @local_filter3_body, nargout, varargin);
endfunction

function [y, varargout] = local_filter3_body (varargin)
  contsid_nargchk ("local_filter3", nargin, nargout, [3 3], 1);
  [B, A, x] = varargin{:};
  names = {"B", "A", "x"};
  args = {B, A, x};
  for k = 1:3
    v = args{k};
    if (! (isnumeric (v) && isreal (v) && ismatrix (v) && ! isempty (v)))
      error ("local_filter3:badInput",
             "local_filter3: %s must be a non-empty real matrix", names{k});
    endif
    if (! all (isfinite (v(:))))
      error ("local_filter3:badInput", "local_filter3: %s must be finite",
             names{k});
    endif
  endfor
  if (A(1, 1) == 0)
    error ("local_filter3:badInput",
           "local_filter3: the leading coefficient A(1,1) must be nonzero");
  endif
  y = pde_mex ("local_filter3", full (double (x)),
               struct ("num", full (double (B)), "den", full (double (A))));
endfunction

%!test
%! ## Separable filter = filter along the rows, then along the columns.
%! x = randn (60, 15);
%! bt = [1 0.5];  at = [1 -1.2 0.4];  bs = [2 -1 0.3];  as = [1 -0.3];
%! y = local_filter3 (bt(:) * bs, at(:) * as, x);
%! ref = filter (bs, as, filter (bt, at, x), [], 2);
%! assert (y, ref, 1e-12 * max (abs (ref(:))));

%!test
%! ## FIR: the leading block of the full 2-D convolution (conv2, and filter2
%! ## with the kernel turned by 180 degrees).
%! x = randn (20, 12);  B = randn (3, 4);
%! y = local_filter3 (B, 2, x);
%! ref = conv2 (x, B) / 2;
%! assert (y, ref(1:20, 1:12), 1e-12);
%! xp = [zeros(2, 15); zeros(20, 3), x];
%! ref2 = filter2 (rot90 (B, 2), xp, "valid") / 2;
%! assert (y, ref2, 1e-12);

%!test
%! ## A non-separable denominator against the recursion written out.
%! x = randn (15, 10);  B = [1 0.2; -0.1 0.3];  A = [2 -0.4; 0.3 0.1];
%! y = local_filter3 (B, A, x);
%! ref = zeros (size (x));
%! for l = 1:columns (x)
%!   for k = 1:rows (x)
%!     s = 0;
%!     for i = 1:2
%!       for j = 1:2
%!         if (k - i + 1 >= 1 && l - j + 1 >= 1)
%!           s += B(i, j) * x(k-i+1, l-j+1);
%!           if (i + j > 2)
%!             s -= A(i, j) * ref(k-i+1, l-j+1);
%!           endif
%!         endif
%!       endfor
%!     endfor
%!     ref(k, l) = s / A(1, 1);
%!   endfor
%! endfor
%! assert (y, ref, 1e-12);

%!error id=local_filter3:badInput local_filter3 (1, [0 1], ones (3))
%!error id=local_filter3:badInput local_filter3 ([], 1, ones (3))
%!error id=local_filter3:badInput local_filter3 (1, 1, [1 NaN])
%!error id=local_filter3:badInput local_filter3 (1, 1, {1})
%!error id=local_filter3:badInput local_filter3 (1, 1)
%!error id=local_filter3:numericalFailure local_filter3 (1, [1 -1e200], ones (50, 3))

%!demo
%! e = local_filter3 (1, [1 -1.2 0.4]' * [1 -0.3], randn (400, 60));
%! imagesc (e'); xlabel ("time index"); ylabel ("space index");
%! title ("noise coloured along time and space");
