## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn  {} {@var{n} =} numel (@var{data})
## @deftypefnx {} {@var{n} =} numel (@var{data}, @var{idx1}, @dots{})
## Number of @code{iddata} objects in @var{data} (1 for a single data set);
## with indices, 1: @code{data(i).Name} yields one value, not one per
## selected sample.  Octave asks @code{numel} how many values an indexing
## expression such as @code{data(1:100).y} produces.
## @seealso{iddata, size}
## @end deftypefn

function [n, varargout] = numel (dat, varargin)
  contsid_nargchk ("numel", nargin, nargout, [1 Inf], 1);
  if (nargin == 1)
    n = builtin ("numel", dat);
  else
    n = 1;
  endif
endfunction

%!test
%! data = iddata ((1:10).', (1:10).', 0.1, "InterSample", "foh");
%! assert (numel (data), 1);
%! assert (numel (data, 1:5), 1);
%! assert (data(1:5).InterSample, "foh");
%! assert (data(2:3).y, [2; 3]);

%!demo
%! data = iddata ((1:10).', (1:10).', 0.1);
%! first = data(1:5).y     # one value although five samples are selected
