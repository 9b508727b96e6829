## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn {} {@var{k} =} end (@var{data}, @var{pos}, @var{nidx})
## Last index for @code{data(@dots{}, end, @dots{})}: the number of samples
## (equal in every experiment), outputs, inputs or experiments, for
## @var{pos} = 1 to 4.
## @seealso{iddata, size}
## @end deftypefn

function [k, varargout] = end (dat, pos, nidx, varargin)
  contsid_nargchk ("end", nargin, nargout, [3 3], 1);
  if (! (isnumeric (pos) && isscalar (pos) && isnumeric (nidx)
         && isscalar (nidx) && any (pos == 1:4) && pos <= nidx))
    error ("iddata:badInput", "iddata: end (data, k, n) needs 1 <= k <= n");
  endif
  if (nidx > 4)
    error ("iddata:badInput",
           "iddata: index as data(samples, outputs, inputs, experiments)");
  endif
  k = size (dat, pos);
  if (pos == 1)
    if (any (k != k(1)))
      error ("iddata:dimensionMismatch",
             ["iddata: 'end' for samples needs the same number of samples ", ...
              "in every experiment"]);
    endif
    k = k(1);
  endif
endfunction

%!test
%! data = iddata ((1:6).', [(1:6).', (6:-1:1).'], 1);
%! assert (data(end).y, 6);
%! assert (data(end-1:end, 1, end).u, [2; 1]);
%! two = iddata ({(1:6).', (1:6).'}, {(1:6).', (1:6).'}, 1);
%! assert (size (two(:, :, :, end)), [6, 1, 1, 1]);

%!error id=iddata:badInput feval ("end", iddata (ones (3, 1), [], 1), {1}, 1)
%!error id=iddata:dimensionMismatch
%! data = iddata ({(1:6).', (1:4).'}, {(1:6).', (1:4).'}, 1);
%! data(end);
%!error id=iddata:badInput
%! data = iddata ((1:6).', (1:6).', 1);
%! data(end, 1, 1, 1, 1);

%!demo
%! data = iddata (randn (100, 1), randn (100, 1), 0.1);
%! validation = data(51:end)
