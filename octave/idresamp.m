## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn  {} {@var{datar} =} idresamp (@var{data}, @var{R})
## @deftypefnx {} {@var{datar} =} idresamp (@var{data}, @var{R}, @var{order})
## @deftypefnx {} {@var{datar} =} idresamp (@var{data}, @var{R}, @
##   @var{order}, @var{tol})
## @deftypefnx {} {[@var{datar}, @var{Ract}] =} idresamp (@dots{})
## Resample data on a sampling interval @var{R} times the original
## (System Identification Toolbox's @code{idresamp}).
##
## @strong{Inputs}
## @table @var
## @item data
## a regularly sampled time-domain @code{iddata} set (every experiment), or
## a matrix with one signal per column.
## @item R
## resampling factor, positive: @var{R} > 1 decimates (@code{Ts * R}),
## @var{R} < 1 interpolates.
## @item order
## half-length of the anti-aliasing filter in periods of the slower of the
## two rates; default 10.
## @item tol
## tolerance of the rational approximation @code{R = Q/P}
## (@code{rat (R, tol)}); default @code{1e-6 * R}.  @var{P} and @var{Q}
## must not exceed 1000.
## @end table
##
## @strong{Outputs}
## @table @var
## @item datar
## the resampled set: @code{Ts*Ract}, samples at the instants
## @code{(0:M-1)' * Ts*Ract} that lie in the original record, names,
## units and @code{InterSample} kept.
## @item Ract
## the factor used, @code{Q/P}.
## @end table
##
## @strong{Algorithm.}  Polyphase resampling: the signal is up-sampled by
## @var{P} (zeros inserted), filtered by a zero-phase low-pass FIR filter
## (Kaiser-windowed sinc, beta 8, cut-off at the lower of the two Nyquist
## frequencies, gain @var{P}) and every @var{Q}-th sample is kept.  To
## reduce the end effects each signal is first extended at both ends by its
## point reflection (continuing its value and slope).  A signal
## band-limited below about 0.7 times the lower Nyquist frequency is
## reproduced at the new instants to about 1e-4 of its amplitude, except
## within @var{order} samples of either end, where the error reaches about
## 1 %.
##
## Irregularly sampled, frequency-domain and unspecified-@code{Ts} data:
## @code{idresamp:notSupported}.
##
## @strong{Example}
## @example
## @group
## data = iddata (sin ((0:999)' / 50), cos ((0:999)' / 50), 0.01);
## datar = idresamp (data, 10);
## [datar.N, datar.Ts]
##   @result{} 100.0000  0.1000
## @end group
## @end example
## @seealso{iddata, resample}
## @end deftypefn

function varargout = idresamp (varargin)
  varargout = contsid_guard ("idresamp", @idresamp_body, nargout, varargin);
endfunction

function [datar, ract, varargout] = idresamp_body (data, R, order = 10,
                                                   tol = [], varargin)
  contsid_nargchk ("idresamp", nargin, nargout, [0 Inf], 2);
  if (nargin < 2 || nargin > 4)
    error ("idresamp:badInput",
           "idresamp: takes 2 to 4 arguments, not %d", nargin);
  endif
  if (! (isnumeric (R) && isreal (R) && isscalar (R) && R > 0
         && isfinite (R)))
    error ("idresamp:badInput",
           "idresamp: 'R' must be a positive finite scalar");
  endif
  R = double (R);
  if (! (isnumeric (order) && isscalar (order) && isreal (order)
         && order >= 1 && order == fix (order) && order <= 1000))
    error ("idresamp:badInput",
           "idresamp: 'order' must be an integer from 1 to 1000");
  endif
  if (isempty (tol))
    tol = 1e-6 * R;
  elseif (! (isnumeric (tol) && isscalar (tol) && isreal (tol) && tol > 0))
    error ("idresamp:badInput", "idresamp: 'tol' must be a positive scalar");
  endif
  [q, p] = rat (R, tol);
  if (p > 1000 || q > 1000)
    error ("idresamp:badInput",
           ["idresamp: 'R' = %g needs the ratio %d/%d; give a larger ", ...
            "'tol'"], R, q, p);
  endif
  ract = q / p;

  if (isnumeric (data) || islogical (data))
    if (! (ndims (data) == 2 && isreal (data) && all (isfinite (data(:)))))
      error ("idresamp:badInput",
             "idresamp: 'data' must be a real finite matrix or an iddata set");
    endif
    if (isrow (data))
      data = data.';
    endif
    datar = resample_columns (double (data), p, q, order);
    return;
  endif
  if (! isa (data, "iddata"))
    error ("idresamp:badInput",
           "idresamp: 'data' must be an iddata set or a matrix, not %s",
           class (data));
  endif
  if (! strcmp (get (data, "Domain"), "Time"))
    error ("idresamp:notSupported",
           "idresamp: frequency-domain data cannot be resampled");
  endif
  info = samplinginfo (data);
  if (! all ([info.Uniform]) || any ([info.Ts] <= 0))
    error ("idresamp:notSupported",
           ["idresamp: 'data' must be regularly sampled with a known Ts ", ...
            "(every experiment)"]);
  endif
  s = struct (data);
  if (any (cellfun (@(x) any (! isfinite (x(:))), [s.y(:); s.u(:)])))
    error ("idresamp:notSupported",
           ["idresamp: 'data' holds missing samples (NaN) or Inf; the ", ...
            "resampling filter would spread them over the record"]);
  endif
  y = cellfun (@(x) resample_columns (x, p, q, order), s.y,
               "uniformoutput", false);
  if (isempty (s.u))
    u = {};
  else
    u = cellfun (@(x) resample_columns (x, p, q, order), s.u,
                 "uniformoutput", false);
  endif
  ts = num2cell ([info.Ts] * ract);
  datar = set (data, "y", y, "u", u, "Ts", ts);
endfunction

function xr = resample_columns (x, p, q, order)
  n = rows (x);
  m = floor ((n - 1) * p / q) + 1;
  if (n == 0)
    xr = zeros (0, columns (x));
    return;
  endif
  if (n < 2)
    xr = repmat (x, m, 1);
    return;
  endif
  ## zero-phase low-pass FIR at the lower Nyquist frequency, gain p
  half = order * max (p, q);
  k = (-half:half).';
  fc = 1 / max (p, q);
  h = fc * p * sinc (fc * k) .* kaiser_window (2 * half + 1, 8);
  ## point reflection at both ends, long enough to cover the filter
  ext = min (n - 1, ceil (half / p) + 1);
  head = 2 * x(1,:) - x(ext+1:-1:2,:);
  tail = 2 * x(end,:) - x(end-1:-1:end-ext,:);
  xe = [head; x; tail];
  up = zeros (rows (xe) * p, columns (x));
  up(1:p:end,:) = xe;
  full = conv2 (up, h);
  ## sample j (0-based) of the original sits at up index (j+ext)*p+1,
  ## and the filter delays it by half
  idx = ((0:m-1).' * q + ext * p) + 1 + half;
  xr = full(idx,:);
endfunction

function w = kaiser_window (len, beta)
  r = (0:len-1).' / (len - 1) * 2 - 1;
  w = besseli (0, beta * sqrt (1 - r.^2)) / besseli (0, beta);
endfunction

## a band-limited signal is reproduced at the new instants
%!test
%! Ts = 0.01;
%! t = (0:1999).' * Ts;
%! x = @(t) [sin(2*pi*0.7*t) + 0.5*cos(2*pi*1.9*t + 1), cos(2*pi*0.3*t)];
%! data = iddata (x(t)(:,1), x(t)(:,2), Ts, "InterSample", "foh");
%! [datar, ract] = idresamp (data, 10);
%! assert (ract, 10);
%! assert (datar.Ts, 0.1, 1e-15);
%! assert (datar.N, 200);
%! assert (datar.InterSample, "foh");
%! tr = (0:199).' * 0.1;
%! xr = x(tr);
%! ## inside: the filter's pass-band ripple; the first and last 'order'
%! ## samples: the end effect of the reflection (documented 1 %)
%! inner = 20:180;
%! assert (datar.y(inner), xr(inner,1), 1e-4);
%! assert (datar.u(inner), xr(inner,2), 1e-4);
%! assert (datar.y, xr(:,1), 1e-2 * 1.5);
%! assert (datar.u, xr(:,2), 1e-2);
%! ## interpolation by 2.5 (R = 0.4) of the decimated record
%! [up, r2] = idresamp (datar, 0.4);
%! assert (r2, 0.4, 1e-12);
%! tu = (0:up.N-1).' * 0.04;
%! assert (up.N, 498);
%! assert (up.u(50:450), x(tu(50:450))(:,2), 1e-4);

## matrix form, multi-experiment sets, the identity R = 1
%!test
%! x = randn (50, 2);
%! assert (idresamp (x, 1), x, 1e-12);
%! m = merge (iddata (sin ((1:100).' / 9), [], 1),
%!            iddata (cos ((1:60).' / 9), [], 2));
%! r = idresamp (m, 2);
%! assert (r.N, [50, 30]);
%! assert (r.Ts, {2; 4});

%!error id=idresamp:notSupported idresamp (iddata ([1; NaN; 3; 4], (1:4)', 1), 2)
%!error id=idresamp:badInput idresamp (ones (10, 1), 0)
%!error id=idresamp:badInput idresamp (ones (10, 1), [1 2])
%!error id=idresamp:badInput idresamp (ones (10, 1), 2, 0)
%!error id=idresamp:badInput idresamp (ones (10, 1), 2, 10, -1)
%!error id=idresamp:badInput idresamp (ones (10, 1), pi, 10, 1e-12)
%!error id=idresamp:badInput idresamp ([1 NaN], 2)
%!error id=idresamp:badInput idresamp ({1}, 2)
%!error id=idresamp:badInput idresamp (ones (10, 1), 2, 10, 1e-3, 5)
%!error id=idresamp:notSupported
%! idresamp (iddata ((1:3).', (1:3).', [0 1 3]), 2);
%!error id=idresamp:notSupported idresamp (iddata ((1:3).', (1:3).'), 2)
%!error id=idresamp:notSupported idresamp (fft (iddata ((1:8).', [], 1)), 2)

%!demo
%! Ts = 0.01;
%! t = (0:999).' * Ts;
%! data = iddata (sin (2*pi*t), sign (sin (2*pi*0.5*t)), Ts);
%! datar = idresamp (data, 10);
%! plot (data, "b", datar, "r")
