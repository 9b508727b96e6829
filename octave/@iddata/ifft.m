## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn {} {@var{data} =} ifft (@var{dataf})
## Time-domain set of a frequency-domain @code{iddata} set built by
## @code{fft}: the inverse of @code{fft} for real signals.
##
## The frequencies of each experiment must be @code{(0:M-1)' * dw} (from
## zero, equally spaced).  The number of samples is @code{2*(M-1)} when
## the last frequency is the Nyquist frequency @code{pi/Ts}, and
## @code{2*M-1} otherwise; with @code{Ts = 0} (continuous-time
## frequencies) it is taken as even, and @code{Ts = pi / w(end)}.  A
## time-domain set is returned unchanged.  (The control package's
## @code{ifft} gives one sample too many for half of the lengths.)
## @seealso{fft, iddata}
## @end deftypefn

function varargout = ifft (varargin)
  varargout = contsid_guard ({"ifft", "iddata"}, @ifft_body, nargout, varargin);
endfunction

function [dat, varargout] = ifft_body (dat, varargin)
  contsid_nargchk ("ifft", nargin, nargout, [1 Inf], 1);
  if (nargin != 1)
    error ("iddata:badInput",
           "iddata: ifft: takes 1 argument, not %d", nargin);
  endif
  if (dat.timedomain)
    return;
  endif
  if (! all (cellfun (@(x) all (isfinite (x(:))), [dat.y(:); dat.u(:)])))
    error ("iddata:notSupported",
           ["iddata: ifft: the data hold NaN or Inf; the inverse ", ...
            "transform would spread them over every sample"]);
  endif
  for e = 1:numel (dat.y)
    w = dat.w{e};
    m = numel (w);
    dw = w(end) / max (m - 1, 1);
    if (m < 2 || abs (w(1)) > 1e-12 * w(end)
        || any (abs (diff (w) - dw) > 1e-9 * w(end)))
      error ("iddata:badInput",
             ["iddata: ifft: experiment %d: the frequencies must start at ", ...
              "0 and be equally spaced"], e);
    endif
    ts = dat.tsam{e};
    if (ts > 0)
      even = abs (w(end) * ts - pi) < 1e-9;
    else
      even = true;
      ts = pi / w(end);
    endif
    n = 2 * (m - 1) + ! even;
    dat.y{e} = full_inverse (dat.y{e}, n);
    if (! isempty (dat.u))
      dat.u{e} = full_inverse (dat.u{e}, n);
    endif
    dat.tsam{e} = ts;
  endfor
  dat.w = {};
  dat.timedomain = true;
endfunction

function x = full_inverse (X, n)
  m = rows (X);
  mirror = X(n - m + 1:-1:2, :);
  x = real (ifft ([X; conj(mirror)], [], 1)) * sqrt (n);
endfunction

%!test
%! for n = [64, 63]
%!   x = [sin((1:n).'), cos((1:n).'/3)];
%!   v = (1:n).' / n;
%!   d = iddata (x, v, 0.2, "InterSample", "foh");
%!   back = ifft (fft (d));
%!   assert (back.y, x, 1e-12);
%!   assert (back.u, v, 1e-12);
%!   assert (back.Ts, 0.2, 1e-15);
%!   assert (back.InterSample, "foh");
%! endfor
%! x = sin ((1:64).');
%! D = fft (iddata (x, [], 0.2));
%! D.Ts = 0;
%! back = ifft (D);
%! assert (back.Ts, 0.2, 1e-12);
%! assert (back.y, x, 1e-12);

%!error id=iddata:badInput
%! ifft (iddata ([1; 2; 3], [], 1, "Frequency", [1; 2; 3]));
%!error id=iddata:notSupported
%! ifft (iddata ([1; NaN; 3], [1; 2; 3], 1, "Frequency", [0; pi/2; pi]));
%!error id=iddata:badInput
%! ifft (iddata ([1; 2; 3], [], 1, "Frequency", [0; 1; 3]));
%!error id=iddata:badInput ifft (fft (iddata ((1:4).', [], 1)), 2)

%!demo
%! d = iddata (randn (100, 1), randn (100, 1), 0.1);
%! back = ifft (fft (d));
%! max (abs (back.y - d.y))
