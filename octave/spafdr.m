## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn  {} {@var{G} =} spafdr (@var{data})
## @deftypefnx {} {@var{G} =} spafdr (@var{data}, @var{R}, @var{w})
## Frequency response by spectral analysis with frequency-dependent
## resolution, as the System Identification Toolbox's @code{spafdr}: the
## DFTs Y, U of the (mean-removed) record are averaged over a Hann window
## of width @var{R}(w) (rad/s) around each frequency w,
## G(w) = sum W Y conj(U) / sum W |U|^2.
## @var{w}: a vector (rad/s) or @{wmin, wmax, n@} (n log-spaced
## frequencies; default @{2 pi/T, pi/Ts, 100@}, T the record length);
## @var{R}: a scalar or one value per frequency, or [] for the default
## max(w/5, 4 pi/T) (a fifth of a decade-ish relative resolution, never
## below two DFT bins).  Returns an @code{idfrd} (Ts of the data) whose
## frequencies are @var{w}.  Plain Octave: an FFT and weighted sums.
##
## @strong{Example}
## @example
## u = sign (randn (2000, 1)); Ts = 0.05;
## y = simc (idctm (4, [1 2.4 4]), u, Ts);
## G = spafdr (iddata (y, u, Ts), [], @{0.1, 50, 200@});
## @end example
## @seealso{cra, idfrd, bode}
## @end deftypefn

function varargout = spafdr (varargin)
  varargout = contsid_guard ("spafdr", @spafdr_body, nargout, varargin);
endfunction

function [G, varargout] = spafdr_body (varargin)
  contsid_nargchk ("spafdr", nargin, nargout, [1 5], 1);
  d = contsid_getdata ("spafdr", varargin{:});
  rest = varargin(d.nconsumed+1:end);
  if (numel (rest) > 2)
    error ("spafdr:badInput", "spafdr: at most R and w after the data");
  endif
  rest(end+1:2) = {[]};
  [R, w] = rest{:};
  if (size (d.u, 2) != 1)
    error ("spafdr:notSupported", "spafdr: one input only");
  endif
  if (! d.uniform)
    error ("spafdr:badInput", "spafdr: needs regularly sampled data");
  endif
  n = rows (d.y);
  Ts = d.Ts;
  T = n * Ts;
  if (isempty (w))
    w = {2 * pi / T, pi / Ts, 100};
  endif
  if (iscell (w))
    good = @(v) isnumeric (v) && isscalar (v) && isreal (v) ...
                && isfinite (v) && v > 0;
    if (numel (w) < 2 || numel (w) > 3 || ! all (cellfun (good, w)))
      error ("spafdr:badInput", "spafdr: w = {wmin, wmax[, n]}, positive");
    endif
    if (numel (w) == 2)
      w{3} = 100;
    endif
    if (w{2} <= w{1} || w{3} != fix (w{3}) || w{3} < 2)
      error ("spafdr:badInput", "spafdr: need wmin < wmax and n >= 2");
    endif
    w = logspace (log10 (w{1}), log10 (w{2}), w{3});
  endif
  if (! isnumeric (w) || ! isreal (w) || isempty (w) || any (! isfinite (w))
      || any (w <= 0))
    error ("spafdr:badInput", "spafdr: frequencies w must be positive");
  endif
  w = w(:).';
  if (isempty (R))
    R = max (w / 5, 4 * pi / T);
  endif
  if (! isnumeric (R) || ! isreal (R) || any (! isfinite (R(:)))
      || any (R(:) <= 0) || ! (isscalar (R) || numel (R) == numel (w)))
    error ("spafdr:badInput",
           "spafdr: R must be positive, a scalar or one per frequency");
  endif
  R = R(:).' .* ones (size (w));
  y = d.y - mean (d.y);
  u = d.u - mean (d.u);
  Y = fft (y);
  U = fft (u);
  m = floor (n / 2);
  wk = 2 * pi / T * (0:m)';
  Y = Y(1:m+1);
  U = U(1:m+1);
  SYU = Y .* conj (U);
  SUU = abs (U) .^ 2;
  resp = zeros (size (w));
  for i = 1:numel (w)
    x = (wk - w(i)) / R(i);
    W = (abs (x) < 1) .* (0.5 + 0.5 * cos (pi * x));
    den = W' * SUU;
    if (! (den > 0))
      resp(i) = NaN;
    else
      resp(i) = (W' * SYU) / den;
    endif
  endfor
  if (all (isnan (resp)))
    error ("spafdr:numericalFailure",
           "spafdr: the input has no power near any requested frequency");
  endif
  G = idfrd (resp(:), w(:), Ts);
endfunction

%!test  # a known system is recovered where the input has power
%! randn ("state", 11);
%! Ts = 0.05; n = 8000;
%! u = randn (n, 1);
%! y = filter ([0 0.1], [1 -0.9], u);
%! G = spafdr (iddata (y, u, Ts), [], {0.2, 20, 30});
%! w = G.Frequency(:);
%! z = exp (1i * w * Ts);
%! g0 = 0.1 ./ (z - 0.9);
%! r = G.ResponseData(:);
%! assert (abs (r - g0) ./ abs (g0) < 0.1);

%!error id=spafdr:badInput spafdr (iddata ((1:50)', rand (50, 1), 1), -1)
%!error id=spafdr:badInput spafdr (iddata ((1:50)', rand (50, 1), 1), [], {2, 1})
%!error id=spafdr:badInput spafdr (iddata ((1:50)', rand (50, 1), 1), [], [0 1])
%!error id=spafdr:badInput spafdr (iddata ((1:50)', rand (50, 1), 1), [], [], 3)
%!error id=spafdr:notSupported spafdr (iddata ((1:50)', rand (50, 2), 1))
%!error id=spafdr:numericalFailure spafdr (iddata ((1:50)', zeros (50, 1), 1))

%!demo
%! u = sign (randn (2000, 1)); Ts = 0.05;
%! y = simc (idctm (4, [1 2.4 4]), u, Ts) + 0.05 * randn (2000, 1);
%! G = spafdr (iddata (y, u, Ts), [], {0.1, 50, 200});
%! bode (G);
