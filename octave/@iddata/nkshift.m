## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn  {} {@var{d} =} nkshift (@var{data}, @var{nk})
## @deftypefnx {} {@var{d} =} nkshift (@var{data}, @var{nk}, "append")
## Shift the inputs of a time-domain @code{iddata} set by @var{nk} samples
## relative to the outputs (the control package's semantics).
##
## For @var{nk} > 0 the first @var{nk} outputs and the last @var{nk}
## inputs are dropped (@code{u(t - nk)} is paired with @code{y(t)}); for
## @var{nk} < 0 the other way round.  The kept samples keep the sampling
## instants of the outputs; for irregular sampling the stored instants are
## shortened with the signals (the control package's @code{nkshift} left
## them stale).  With a third argument the length is kept and the inputs
## are padded with @var{nk} zeros instead.  Frequency-domain data:
## @code{iddata:notSupported}.
## @seealso{iddata, diff}
## @end deftypefn

function varargout = nkshift (varargin)
  varargout = contsid_guard ({"nkshift", "iddata"}, @nkshift_body, nargout,
                             varargin);
endfunction

function [dat, varargout] = nkshift_body (dat, nk = 0, append, varargin)
  contsid_nargchk ("nkshift", nargin, nargout, [1 Inf], 1);
  if (nargin < 1 || nargin > 3)
    error ("iddata:badInput",
           "iddata: nkshift: takes 1 to 3 arguments, not %d", nargin);
  endif
  if (! (isnumeric (nk) && isscalar (nk) && isreal (nk) && nk == fix (nk)
         && isfinite (nk)))
    error ("iddata:badInput", "iddata: nkshift: 'nk' must be a scalar integer");
  endif
  nk = double (nk);                    # an integer type saturates below
  if (! dat.timedomain)
    error ("iddata:notSupported",
           "iddata: nkshift: frequency-domain data cannot be shifted");
  endif
  k = abs (nk);
  n = cellfun ("rows", dat.y);
  if (any (k >= n) && nargin == 2)
    error ("iddata:badInput",
           "iddata: nkshift: |nk| = %d leaves no samples (%d)", k, min (n));
  endif
  for e = 1:numel (dat.y)
    if (nargin == 2)
      if (nk >= 0)
        dat.y{e} = dat.y{e}(k+1:end,:);
        kept = k+1:n(e);
        if (! isempty (dat.u))
          dat.u{e} = dat.u{e}(1:end-k,:);
        endif
      else
        dat.y{e} = dat.y{e}(1:end-k,:);
        kept = 1:n(e)-k;
        if (! isempty (dat.u))
          dat.u{e} = dat.u{e}(k+1:end,:);
        endif
      endif
      if (! isempty (dat.w) && ! isempty (dat.w{e}))
        dat.w{e} = dat.w{e}(kept);
      endif
    elseif (! isempty (dat.u))
      m = columns (dat.u{e});
      k = min (k, n(e));
      if (nk >= 0)
        dat.u{e} = [zeros(k, m); dat.u{e}(1:end-k,:)];
      else
        dat.u{e} = [dat.u{e}(k+1:end,:); zeros(k, m)];
      endif
    endif
  endfor
endfunction

%!test
%! t = cumsum (0.1 + mod ((1:10).', 3) / 100);
%! d = iddata ((1:10).', (11:20).', "SamplingInstants", t);
%! s = nkshift (d, 2);
%! assert ([s.y, s.u], [(3:10).', (11:18).']);
%! assert (s.SamplingInstants, t(3:end));
%! s = nkshift (d, -2);
%! assert ([s.y, s.u], [(1:8).', (13:20).']);
%! assert (s.SamplingInstants, t(1:8));
%! s = nkshift (iddata ((1:10).', (11:20).', 1), 3, "append");
%! assert (s.u, [0; 0; 0; (11:17).']);

%!test
%! ## an integer-typed shift on a record longer than its type's range
%! d = iddata ((1:300).', (301:600).', 1);
%! assert (nkshift (d, int8 (2)).y, nkshift (d, 2).y);
%! assert (nkshift (d, int8 (-2), "append").u, nkshift (d, -2, "append").u);
%!error id=iddata:badInput nkshift (iddata ((1:5).', (1:5).', 1), 1.5)
%!error id=iddata:badInput nkshift (iddata ((1:5).', (1:5).', 1), Inf)
%!error id=iddata:badInput nkshift (iddata ((1:5).', (1:5).', 1), 5)
%!error id=iddata:notSupported nkshift (fft (iddata ((1:5).', (1:5).', 1)), 1)
%!error id=iddata:badInput nkshift (iddata ((1:5).', (1:5).', 1), 1, 1, 1)

%!demo
%! d = iddata ((1:6).', (1:6).', 0.1);
%! shifted = nkshift (d, 2);
%! [shifted.y, shifted.u]
