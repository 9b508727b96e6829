## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn  {} {@var{d} =} diff (@var{data})
## @deftypefnx {} {@var{d} =} diff (@var{data}, @var{k})
## @var{k}-th differences (default 1) of the signals of a time-domain
## @code{iddata} set, @code{x(t) - x(t-1)}: @var{k} samples fewer.
##
## Sample @var{i} of the result is the difference ending at sample
## @var{i}+@var{k} of @var{data} and keeps its sampling instant; for
## irregular sampling the stored instants are shortened with the signals
## (the control package's @code{diff} left them stale).  Frequency-domain
## data: @code{iddata:notSupported}.
## @seealso{iddata, nkshift}
## @end deftypefn

function varargout = diff (varargin)
  varargout = contsid_guard ({"diff", "iddata"}, @diff_body, nargout, varargin);
endfunction

function [dat, varargout] = diff_body (dat, k = 1, varargin)
  contsid_nargchk ("diff", nargin, nargout, [1 Inf], 1);
  if (nargin < 1 || nargin > 2)
    error ("iddata:badInput",
           "iddata: diff: takes 1 or 2 arguments, not %d", nargin);
  endif
  if (! (isnumeric (k) && isscalar (k) && isreal (k) && ! issparse (k)
         && k >= 0 && k == fix (k)))
    error ("iddata:badInput",
           "iddata: diff: 'k' must be a non-negative integer");
  endif
  if (! dat.timedomain)
    error ("iddata:notSupported",
           "iddata: diff: frequency-domain data cannot be differenced");
  endif
  if (any (cellfun ("rows", dat.y) <= k))
    error ("iddata:badInput",
           "iddata: diff: order %d leaves no samples", k);
  endif
  dat.y = cellfun (@(x) diff (x, k, 1), dat.y, "uniformoutput", false);
  dat.u = cellfun (@(x) diff (x, k, 1), dat.u, "uniformoutput", false);
  for e = 1:numel (dat.w)
    dat.w{e} = dat.w{e}(k+1:end);
  endfor
endfunction

%!test
%! t = cumsum (0.1 + mod ((1:10).', 3) / 100);
%! d = diff (iddata ((1:10).'.^2, (11:20).', "SamplingInstants", t), 2);
%! assert (d.y, 2 * ones (8, 1));
%! assert (d.u, zeros (8, 1));
%! assert (d.SamplingInstants, t(3:end));
%! d = diff (iddata ((1:10).'.^2, [], 0.5));
%! assert (d.y, (3:2:19).');
%! assert (d.Ts, 0.5);

%!error id=iddata:badInput diff (iddata ((1:5).', (1:5).', 1), sparse (1))
%!error id=iddata:badInput diff (iddata ((1:5).', (1:5).', 1), -1)
%!error id=iddata:badInput diff (iddata ((1:5).', (1:5).', 1), 5)
%!error id=iddata:notSupported diff (fft (iddata ((1:5).', (1:5).', 1)))
%!error id=iddata:badInput diff (iddata ((1:5).', (1:5).', 1), 1, 1)

%!demo
%! d = iddata (cumsum (randn (100, 1)), randn (100, 1), 0.1);
%! increments = diff (d);
%! increments.N
