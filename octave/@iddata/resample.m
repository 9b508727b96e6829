## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn {} {@var{d} =} resample (@var{data}, @var{p}, @var{q})
## Resample a regularly sampled @code{iddata} set at @var{p}/@var{q} times
## its rate (new @code{Ts = Ts*q/p}): @code{idresamp (data, q/p)}, with
## the same filter and end handling.
##
## The control package's @code{resample} (which needs the signal package
## and keeps stale sampling instants) is replaced: irregularly sampled
## data are @code{iddata:notSupported} (error from @code{idresamp}).  The
## control package's fourth argument (filter order or impulse response) is
## not supported.
## @seealso{idresamp, iddata}
## @end deftypefn

function varargout = resample (varargin)
  varargout = contsid_guard ({"resample", "iddata"}, @resample_body, nargout,
                             varargin);
endfunction

function [dat, varargout] = resample_body (dat, p, q, varargin)
  contsid_nargchk ("resample", nargin, nargout, [1 Inf], 1);
  if (nargin != 3)
    if (nargin == 4)
      error ("iddata:notSupported",
             "iddata: resample: no filter argument; use idresamp's 'order'");
    endif
    error ("iddata:badInput",
           "iddata: resample: takes 3 arguments, not %d", nargin);
  endif
  ok = @(x) isnumeric (x) && isscalar (x) && isreal (x) && x >= 1 ...
            && x == fix (x);
  if (! (ok (p) && ok (q)))
    error ("iddata:badInput",
           "iddata: resample: 'p' and 'q' must be positive integers");
  endif
  dat = idresamp (dat, q / p, 10, 1e-12);
endfunction

%!test
%! t = (0:399).' * 0.05;
%! d = iddata (sin (t), cos (0.5 * t), 0.05, "InterSample", "foh");
%! r = resample (d, 1, 4);
%! assert (r.Ts, 0.2, 1e-15);
%! assert (struct (r), struct (idresamp (d, 4)));
%! r = resample (d, 3, 2);
%! assert (r.Ts, 0.05 * 2 / 3, 1e-15);
%! tr = (0:r.N-1).' * r.Ts;
%! assert (r.y(20:end-20), sin (tr(20:end-20)), 1e-4);

%!error id=iddata:badInput resample (iddata ((1:9).', [], 1), 1.5, 1)
%!error id=iddata:notSupported resample (iddata ((1:9).', [], 1), 1, 2, 10)
%!error id=resample:notSupported
%! resample (iddata ((1:3).', [], [0 1 3]), 1, 2);
%!error id=iddata:badInput resample (iddata ((1:9).', [], 1), 1)

%!demo
%! d = iddata (sin ((0:199).' / 10), [], 0.1);
%! r = resample (d, 1, 2);
%! [r.N, r.Ts]
