## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn  {} {@var{dataf} =} fft (@var{data})
## @deftypefnx {} {@var{dataf} =} fft (@var{data}, @var{n})
## Frequency-domain set of the discrete Fourier transform of a
## time-domain @code{iddata} set, as MATLAB and the control package define
## it.
##
## For each experiment of @var{N} samples (or @var{n}: a scalar, or one
## per experiment, padding with zeros or truncating), the signals become
## @code{fft (x, n)(1:fix (n/2)+1, :) / sqrt (n)}, at the frequencies
## @code{(0:fix (n/2))' * 2*pi / (n*Ts)} (rad per time unit; the Nyquist
## frequency @code{pi/Ts} is the last one when @var{n} is even).
## @code{Ts}, @code{InterSample} (e.g. @qcode{"bl"}), names and units are
## kept; set @code{dataf.Ts = 0} to declare the frequencies continuous-time
## ones.  A frequency-domain set is returned unchanged.
##
## Irregularly sampled data have no DFT (@code{iddata:notSupported}), nor
## have data with missing samples (NaN) or Inf, which the transform would
## spread over every frequency (@code{iddata:notSupported}, as
## @code{resample}); an unspecified @code{Ts} counts as 1.
## @seealso{ifft, iddata}
## @end deftypefn

function varargout = fft (varargin)
  varargout = contsid_guard ({"fft", "iddata"}, @fft_body, nargout, varargin);
endfunction

function [dat, varargout] = fft_body (dat, n = [], varargin)
  contsid_nargchk ("fft", nargin, nargout, [1 Inf], 1);
  if (nargin < 1 || nargin > 2)
    error ("iddata:badInput",
           "iddata: fft: takes 1 or 2 arguments, not %d", nargin);
  endif
  if (! dat.timedomain)
    return;
  endif
  info = samplinginfo (dat);
  if (! all ([info.Uniform]))
    error ("iddata:notSupported",
           "iddata: fft: irregularly sampled data have no DFT; resample first");
  endif
  nexp = numel (dat.y);
  if (! all (cellfun (@(x) all (isfinite (x(:))), [dat.y(:); dat.u(:)])))
    error ("iddata:notSupported",
           ["iddata: fft: the data hold missing samples (NaN) or Inf; the ", ...
            "transform would spread them over every frequency: fill them ", ...
            "first"]);
  endif
  if (isempty (n))
    n = cellfun ("rows", dat.y(:));
  elseif (isnumeric (n) && isreal (n) && any (numel (n) == [1, nexp])
          && all (n(:) >= 1 & n(:) == fix (n(:))))
    n = double (n(:)) .* ones (nexp, 1);
  else
    error ("iddata:badInput",
           ["iddata: fft: 'n' must be a positive integer, or one per ", ...
            "experiment"]);
  endif
  nchan = columns (dat.y{1}) + numel (dat.inname);
  if (any (n * max (nchan, 1) > 2^28))
    error ("iddata:badInput",
           "iddata: fft: %g points per signal is too many", max (n));
  endif
  half = @(x, n) fft (x, n, 1)(1:fix (n/2)+1, :) / sqrt (n);
  w = cell (nexp, 1);
  for e = 1:nexp
    dat.y{e} = half (dat.y{e}, n(e));
    if (! isempty (dat.u))
      dat.u{e} = half (dat.u{e}, n(e));
    endif
    w{e} = (0:fix (n(e)/2)).' * (2*pi / (n(e) * abs (dat.tsam{e})));
  endfor
  dat.w = w;
  dat.timedomain = false;
endfunction

%!test
%! x = [sin((1:64).'), cos((1:64).'/3)];
%! v = (1:64).' / 64;
%! d = fft (iddata (x, v, 0.2, "InterSample", "bl"));
%! X = fft (x) / 8;
%! V = fft (v) / 8;
%! assert (d.y, X(1:33, :), 1e-12);
%! assert (d.u, V(1:33), 1e-12);
%! assert (d.Frequency, (0:32).' * 2*pi / (64 * 0.2), 1e-12);
%! assert (d.Frequency(end), pi / 0.2, 1e-12);
%! assert (d.Domain, "Frequency");
%! assert (d.InterSample, "bl");
%! assert (d.Ts, 0.2);
%! d.Ts = 0;
%! assert (d.Ts, 0);
%! assert (struct (fft (d)), struct (d));
%! d5 = fft (iddata (x(1:63, :), v(1:63), 1), 70);
%! X = fft (x(1:63, :), 70) / sqrt (70);
%! assert (d5.y, X(1:36, :), 1e-12);

%!error id=iddata:notSupported fft (iddata ((1:3).', (1:3).', [0 1 3]))
%!error id=iddata:notSupported fft (iddata ([1; NaN; 3], (1:3).', 1))
%!error id=iddata:notSupported fft (iddata ((1:3).', [1; 2; Inf], 1))
%!error id=iddata:badInput fft (iddata ((1:3).', (1:3).', 1), 0)
%!error id=iddata:badInput fft (iddata ((1:3).', (1:3).', 1), [2 2])
%!error id=iddata:badInput fft (iddata ((1:3).', (1:3).', 1), 1e12)
%!error id=iddata:badInput fft (iddata ((1:3).', (1:3).', 1), 3, 1)

%!demo
%! u = iddata ([], randn (512, 1), 0.01, "InterSample", "bl");
%! U = fft (u);
%! U.Ts = 0;          # continuous-time frequencies
%! plot (U)
