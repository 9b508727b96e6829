## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn {} {@var{d} =} getexp (@var{data}, @var{k})
## Experiments @var{k} (indices or names) of a multi-experiment
## @code{iddata} set, with their sampling and @code{InterSample}; the same
## as @code{data(:, :, :, k)}.
## @seealso{merge, iddata}
## @end deftypefn

function varargout = getexp (varargin)
  varargout = contsid_guard ({"getexp", "iddata"}, @getexp_body, nargout,
                             varargin);
endfunction

function [d, varargout] = getexp_body (dat, k, varargin)
  contsid_nargchk ("getexp", nargin, nargout, [1 Inf], 1);
  if (nargin != 2)
    error ("iddata:badInput",
           "iddata: getexp: takes 2 arguments, not %d", nargin);
  endif
  d = index_data (dat, {":", ":", ":", k});
endfunction

%!test
%! m = iddata ({(1:3).', (1:5).'}, {(1:3).', (1:5).'}, {1, 0.5},
%!             "ExperimentName", {"a", "b"});
%! assert (getexp (m, 2).y, (1:5).');
%! assert (getexp (m, "a").Ts, 1);
%! assert (getexp (m, [2 1]).N, [5, 3]);

%!error id=iddata:badInput getexp (iddata (1, 1, 1), 2)
%!error id=iddata:badInput getexp (iddata (1, 1, 1), "c")
%!error id=iddata:badInput getexp (iddata (1, 1, 1))
%!error id=iddata:badInput getexp (iddata (1, 1, 1), 1, 2)

%!demo
%! m = merge (iddata (randn (10, 1), [], 1), iddata (randn (20, 1), [], 2));
%! second = getexp (m, 2)
