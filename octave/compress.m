## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn  {} {[@var{zc}, @var{tc}] =} compress (@var{z}, @var{Ts}, @var{Dy})
## @deftypefnx {} {[@var{zc}, @var{tc}, @var{index}] =} compress (@dots{})
## Irregular sampling at a constant quantisation step (send-on-delta, or
## Lebesgue, sampling) of a regularly sampled record, as CONTSID's
## @code{compress}: a sample is kept when one of its signals has moved by
## more than the step since the last kept sample.
##
## @var{z} is the N-by-m record (e.g. @code{[y u]}), sampled every
## @var{Ts} seconds from t = 0; @var{Dy} the quantisation step, a positive
## scalar for all columns or a row with one per column (@code{Inf} for a
## column that must not trigger samples).  Sample 1 is kept; sample k is
## kept when
## @example
## max_j |z(k,j) - z(l,j)| / Dy(j) > 1,
## @end example
## l the last kept sample.  Every column takes part, so that the instants
## where a piecewise-constant input jumps are kept too (with
## @code{[y u]} and a step input, the step's instant is a sample of the
## irregular record: the delayed output's first change alone would shift
## the input's jump and hide the delay).
##
## @var{zc} holds the kept rows of @var{z}, @var{tc} their instants
## (k - 1) @var{Ts} (a column), @var{index} their indices k.  Build the
## irregular data as CONTSID's advantage22 demo does:
## @code{iddata (zc(:,1), zc(:,2), "SamplingInstants", tc, "Intersample", "zoh")}.
## @seealso{iddata, procsrivc, srivc}
## @end deftypefn

function varargout = compress (varargin)
  varargout = contsid_guard ("compress", @compress_body, nargout, varargin);
endfunction

function [zc, tc, varargout] = compress_body (varargin)
  contsid_nargchk ("compress", nargin, nargout, [3 3], 3);
  [z, Ts, Dy] = varargin{:};
  if (! isnumeric (z) || ! isreal (z) || ndims (z) != 2 || isempty (z)
      || any (! isfinite (z(:))))
    error ("compress:badInput",
           "compress: 'z' must be a non-empty real finite N-by-m matrix");
  endif
  if (isvector (z))
    z = z(:);
  endif
  z = double (z);
  if (! isnumeric (Ts) || ! isreal (Ts) || ! isscalar (Ts) || ! isfinite (Ts)
      || Ts <= 0)
    error ("compress:badInput",
           "compress: 'Ts' must be a positive finite scalar");
  endif
  m = columns (z);
  if (! isnumeric (Dy) || ! isreal (Dy) || isempty (Dy) || ! isvector (Dy)
      || any (isnan (Dy)) || any (Dy <= 0))
    error ("compress:badInput",
           "compress: 'Dy' must be positive (a scalar or one per column)");
  endif
  if (isscalar (Dy))
    Dy = repmat (double (Dy), 1, m);
  elseif (numel (Dy) != m)
    error ("compress:dimensionMismatch",
           "compress: 'Dy' has %d steps for %d columns", numel (Dy), m);
  endif
  Dy = double (Dy(:).');
  N = rows (z);
  keep = false (N, 1);
  keep(1) = true;
  last = z(1, :);
  for k = 2:N
    if (any (abs (z(k, :) - last) > Dy))
      keep(k) = true;
      last = z(k, :);
    endif
  endfor
  index = find (keep);
  zc = z(index, :);
  tc = (index - 1) * double (Ts);
  if (nargout > 2)
    varargout{1} = index;
  endif
endfunction

%!test  # against the definition, sample by sample
%! randn ("state", 5);
%! z = cumsum (0.05 * randn (400, 2));
%! Dy = [0.1 0.3];
%! [zc, tc, k] = compress (z, 0.01, Dy);
%! assert (k(1), 1);
%! assert (zc, z(k, :));
%! assert (tc, (k - 1) * 0.01, 1e-15);
%! for i = 2:numel (k)
%!   ## the samples skipped since the last kept one stayed within the steps
%!   between = z(k(i-1)+1:k(i)-1, :) - z(k(i-1), :);
%!   assert (all (all (abs (between) <= Dy)));
%!   assert (any (abs (z(k(i), :) - z(k(i-1), :)) > Dy));
%! endfor
%! tail = z(k(end)+1:end, :) - z(k(end), :);
%! assert (all (all (abs (tail) <= Dy)));

%!test  # advantage22: a delayed step response; the input's jump is kept
%! Ts = 0.01;
%! u = [zeros(30, 1); ones(300, 1)];
%! t = (0:329)' * Ts;
%! y = 2 * (1 - exp (-(t - 1))) .* (t >= 1);
%! [zc, tc] = compress ([y u], Ts, 0.1);
%! assert (any (abs (tc - 0.30) < 1e-12));
%! assert (zc(tc < 0.3 - 1e-12, 2), zeros (sum (tc < 0.3 - 1e-12), 1));
%! dt = diff (tc);
%! assert (min (dt) >= Ts - 1e-12);
%! ## output increments are above the step, except at the input's jump
%! dy = abs (diff (zc(:, 1)));
%! assert (all (dy(abs (tc(2:end) - 0.3) > 1e-12) > 0.1));
%! assert (numel (tc) < 60);

%!test  # a constant record keeps its first sample; Inf steps ignore a column
%! [zc, tc] = compress (ones (10, 1), 1, 0.5);
%! assert (zc, 1); assert (tc, 0);
%! [zc, tc] = compress ([(1:5)', zeros(5, 1)], 2, [Inf 1]);
%! assert (tc, 0);
%! [zc, tc] = compress ((1:5)', 2, 0.5);
%! assert (tc, (0:2:8)');

%!error id=compress:badInput compress ([1 2; 3 4], 1)
%!error id=compress:badInput compress ([], 1, 1)
%!error id=compress:badInput compress ([1 NaN], 1, 1)
%!error id=compress:badInput compress ("ab", 1, 1)
%!error id=compress:badInput compress (ones (3, 2), 0, 1)
%!error id=compress:badInput compress (ones (3, 2), [1 2], 1)
%!error id=compress:badInput compress (ones (3, 2), 1, 0)
%!error id=compress:badInput compress (ones (3, 2), 1, NaN)
%!error id=compress:badInput compress (ones (3, 2), 1, [])
%!error id=compress:dimensionMismatch compress (ones (3, 2), 1, [1 2 3])
%!error id=compress:badInput [a, b, c, d] = compress (ones (3, 2), 1, 1)

%!demo
%! Ts = 0.01; t = (0:999)' * Ts;
%! y = sin (2 * pi * 0.5 * t) .* exp (-0.3 * t);
%! [yc, tc] = compress (y, Ts, 0.1);
%! plot (t, y, "b", tc, yc, "or");
%! title (sprintf ("%d of %d samples kept", numel (tc), numel (t)));
