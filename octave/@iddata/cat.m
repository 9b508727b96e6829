## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn {} {@var{data} =} cat (@var{dim}, @var{d1}, @var{d2}, @dots{})
## Join @code{iddata} sets: @var{dim} = 1 appends the samples
## (@code{[d1; d2]}), 2 the channels (@code{[d1, d2]}), 3 the experiments
## (@code{merge}).
##
## Unlike the control package's @code{cat}, the result keeps
## @code{InterSample} and the sampling instants, and whatever cannot be
## kept is an identified error:
## @itemize
## @item sets with inputs and different @code{InterSample}:
## @code{iddata:notSupported};
## @item samples of two regularly sampled sets with different @code{Ts}:
## @code{iddata:badInput} (use @code{merge} to keep them as experiments);
## joining irregular sets needs the instants of each set to follow those of
## the set before (the result has the joined instants; a regular set
## counts from time 0);
## @item channels of sets sampled differently, or with different numbers
## of samples: @code{iddata:badInput}, @code{iddata:dimensionMismatch};
## @item time- and frequency-domain sets together: @code{iddata:badInput}.
## @end itemize
## Frequency-domain sets join in the same way (@code{[Y, U]} gives the
## outputs of @var{Y} and the inputs of @var{U} at their common
## frequencies).  Empty @code{[]} arguments are skipped.
## @seealso{vertcat, horzcat, merge, iddata}
## @end deftypefn

function varargout = cat (varargin)
  varargout = contsid_guard ({"cat", "iddata"}, @cat_body, nargout, varargin);
endfunction

function [dat, varargout] = cat_body (dim, varargin)
  contsid_nargchk ("cat", nargin, nargout, [1 Inf], 1);
  if (! (isnumeric (dim) && isscalar (dim) && any (dim == [1, 2, 3])))
    error ("iddata:badInput",
           ["iddata: cat: 'dim' must be 1 (samples), 2 (channels) or 3 ", ...
            "(experiments)"]);
  endif
  dat = concat_sets (dim, varargin, "iddata: cat");
endfunction

%!shared d1, d2
%! d1 = iddata ((1:4).', (11:14).', 0.5, "InterSample", "foh");
%! d2 = iddata ((5:7).', (15:17).', 0.5, "InterSample", "foh");

%!test
%! d = cat (1, d1, d2);
%! assert (d.y, (1:7).');
%! assert (d.InterSample, "foh");
%! assert (d.Ts, 0.5);
%! assert (size (cat (3, d1, d2)), [7, 1, 1, 2]);
%! assert (struct (cat (1, d1)), struct (d1));

%!error id=iddata:badInput cat (4, d1, d2)
%!error id=iddata:badInput cat ("a", d1, d2)
%!error id=iddata:badInput cat (1, d1, 3)

%!demo
%! d1 = iddata (randn (100, 1), randn (100, 1), 0.1, "InterSample", "foh");
%! d2 = iddata (randn (50, 1), randn (50, 1), 0.1, "InterSample", "foh");
%! d = cat (1, d1, d2);
%! [d.N, d.Ts]
%! d.InterSample
