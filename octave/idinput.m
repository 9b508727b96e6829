## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn  {} {@var{u} =} idinput (@var{N})
## @deftypefnx {} {@var{u} =} idinput (@var{N}, @var{type})
## @deftypefnx {} {@var{u} =} idinput (@var{N}, @var{type}, @var{band})
## @deftypefnx {} {@var{u} =} idinput (@var{N}, @var{type}, @var{band}, @
##   @var{levels})
## @deftypefnx {} {[@var{u}, @var{freqs}] =} idinput (@var{N}, "sine", @
##   @var{band}, @var{levels}, @var{sinedata})
## Identification input signals (the System Identification Toolbox's
## @code{idinput}).
##
## @strong{Inputs}
## @table @var
## @item N
## number of samples; @code{[N, nu]} for @var{nu} inputs; @code{[P, nu, M]}
## for @var{M} periods of @var{P} samples (the signal is then periodic).
## @item type
## @table @asis
## @item @qcode{"rgs"} (default)
## random Gaussian signal: white noise filtered by an ideal band-pass
## (DFT bins outside @var{band} set to zero) over one period; @var{levels}
## = @code{[mu - sd, mu + sd]} give its mean and standard deviation.
## @item @qcode{"rbs"}
## random binary signal: the sign of the band-limited Gaussian signal,
## taking the values @var{levels}.
## @item @qcode{"prbs"}
## maximum-length pseudo-random binary sequence (@code{prbs}) with clock
## period @code{round (1/B)} samples for @var{band} = @code{[0, B]}; the
## register is the shortest whose period covers @var{P} samples, and the
## sequence is cut to @var{P}.
## @item @qcode{"sine"}
## sum of sinusoids at frequencies of the DFT grid @code{2*pi*k/P} inside
## @var{band}, with random phases chosen for the smallest peak, scaled to
## span @var{levels} exactly.
## @end table
## @item band
## @code{[lo, hi]}, the pass-band in fractions of the Nyquist frequency,
## @code{0 <= lo < hi <= 1}; default @code{[0, 1]}.
## @item levels
## @code{[a, b]}, @var{a} < @var{b}; default @code{[-1, 1]}.
## @item sinedata
## @code{[number of sinusoids, number of trials, grid skip]}, default
## @code{[10, 10, 1]}: the sinusoids are spread evenly over the grid
## frequencies in @var{band} (every skip-th), and the phases of the trial
## with the smallest peak are kept.
## @end table
##
## @strong{Outputs}
## @table @var
## @item u
## the signal, @var{N}-by-@var{nu} (@var{P}*@var{M}-by-@var{nu}).
## @item freqs
## for @qcode{"sine"}, the frequencies used in rad/sample (column).
## @end table
##
## The random types draw from @code{randn}/@code{rand} (seed them for a
## reproducible signal); @qcode{"prbs"} is deterministic.
##
## @strong{Example}
## @example
## @group
## u = idinput (500, "sine", [0 0.5]);
## [min(u), max(u)]
##   @result{} -1   1
## u = idinput ([1000 1], "prbs", [0 0.1], [-1 1]);  # clock period 10
## @end group
## @end example
## @seealso{prbs, iddata}
## @end deftypefn

function varargout = idinput (varargin)
  varargout = contsid_guard ("idinput", @idinput_body, nargout, varargin);
endfunction

function [u, freqs, varargout] = idinput_body (N, type = "rgs",
                                               band = [0, 1], levels = [-1, 1],
                                               sinedata = [10, 10, 1], varargin)
  contsid_nargchk ("idinput", nargin, nargout, [0 Inf], 2);
  if (nargin < 1 || nargin > 5)
    error ("idinput:badInput",
           "idinput: takes 1 to 5 arguments, not %d", nargin);
  endif
  if (! (isnumeric (N) && isreal (N) && any (numel (N) == [1, 2, 3])
         && all (N(:) >= 1 & N(:) == fix (N(:)) & isfinite (N(:)))))
    error ("idinput:badInput",
           "idinput: 'N' must be N, [N nu] or [P nu M], positive integers");
  endif
  N = double ([N(:).', 1, 1](1:3));
  [P, nu, M] = deal (N(1), N(2), N(3));
  if (P * nu * M > 1e8)                # 800 MB; a session must survive
    error ("idinput:badInput", "idinput: %g samples is too many",
           P * nu * M);
  endif
  if (isempty (type))
    type = "rgs";
  endif
  if (! ischar (type))
    error ("idinput:badOption", "idinput: 'type' must be a string");
  endif
  if (isempty (band))
    band = [0, 1];
  endif
  if (! (isnumeric (band) && isreal (band) && numel (band) == 2
         && band(1) >= 0 && band(1) < band(2) && band(2) <= 1))
    error ("idinput:badInput",
           "idinput: 'band' must be [lo hi] with 0 <= lo < hi <= 1");
  endif
  if (isempty (levels))
    levels = [-1, 1];
  endif
  if (! (isnumeric (levels) && isreal (levels) && numel (levels) == 2
         && all (isfinite (levels)) && levels(1) < levels(2)))
    error ("idinput:badInput",
           "idinput: 'levels' must be [a b] with a < b, finite");
  endif
  band = double (band(:).');
  levels = double (levels(:).');
  freqs = [];
  switch (lower (type))
    case "rgs"
      x = band_noise (P, nu, band);
      x = x ./ std (x, 1);
      x = mean (levels) + diff (levels) / 2 * x;
    case "rbs"
      x = band_noise (P, nu, band);
      x = levels(1 + (x >= 0));
      x = reshape (x, P, nu);
    case "prbs"
      if (band(1) != 0)
        error ("idinput:badInput",
               "idinput: 'prbs' needs band = [0 B] (B = 1/clock period)");
      endif
      clock = max (1, round (1 / band(2)));
      n = max (2, ceil (log2 (ceil (P / clock) + 1)));
      if (n > 32)
        error ("idinput:badInput",
               "idinput: P = %d needs a register longer than 32 bits", P);
      endif
      x = repmat (prbs (n, clock, levels, P), 1, nu);
    case "sine"
      [x, freqs] = sum_of_sines (P, nu, band, levels, sinedata);
    otherwise
      error ("idinput:badOption",
             "idinput: unknown type '%s' (rgs, rbs, prbs, sine)", type);
  endswitch
  u = repmat (x, M, 1);
endfunction

## white Gaussian noise, P-by-nu, with the DFT bins outside the band
## (fractions of Nyquist) set to zero
function x = band_noise (P, nu, band)
  k = (0:P-1).';
  f = 2 * min (k, P - k) / P;
  keep = f >= band(1) - 1e-12 & f <= band(2) + 1e-12;
  if (! any (keep))
    error ("idinput:badInput",
           "idinput: no DFT frequency of a %d-sample period lies in the band",
           P);
  endif
  if (all (keep) || P == 1)
    x = randn (P, nu);
  else
    X = fft (randn (P, nu));
    X(! keep, :) = 0;
    x = real (ifft (X));
  endif
  if (any (std (x, 1) == 0))
    error ("idinput:badInput",
           "idinput: the band keeps only the mean of a %d-sample period", P);
  endif
endfunction

function [x, w] = sum_of_sines (P, nu, band, levels, sinedata)
  if (! (isnumeric (sinedata) && isreal (sinedata) && numel (sinedata) == 3
         && all (sinedata(:) >= 1 & sinedata(:) == fix (sinedata(:)))))
    error ("idinput:badInput",
           ["idinput: 'sinedata' must be [number of sinusoids, trials, ", ...
            "grid skip], positive integers"]);
  endif
  [nsin, ntrials, skip] = deal (sinedata(1), sinedata(2), sinedata(3));
  k = (skip:skip:fix (P / 2)).';
  f = 2 * k / P;
  k = k(f >= band(1) - 1e-12 & f <= band(2) + 1e-12);
  if (isempty (k))
    error ("idinput:badInput",
           "idinput: no grid frequency of a %d-sample period in the band", P);
  endif
  if (numel (k) > nsin)
    k = k(unique (round (linspace (1, numel (k), nsin))));
  endif
  w = 2 * pi * k / P;
  t = (0:P-1).';
  x = zeros (P, nu);
  for c = 1:nu
    best = Inf;
    for trial = 1:ntrials
      s = sum (sin (t * w.' + 2 * pi * rand (1, numel (w))), 2);
      peak = max (s) - min (s);
      if (peak < best && peak > 0)
        best = peak;
        x(:,c) = s;
      endif
    endfor
    if (! isfinite (best))
      error ("idinput:badInput",
             "idinput: the sinusoids vanish at the samples (Nyquist only)");
    endif
    x(:,c) = levels(1) + (x(:,c) - min (x(:,c))) ...
             * diff (levels) / (max (x(:,c)) - min (x(:,c)));
  endfor
endfunction

## rgs: all the power in the band, mean and deviation from the levels
%!test
%! randn ("seed", 1);
%! u = idinput ([1000 2], "rgs", [0.2 0.4], [1 5]);
%! assert (size (u), [1000, 2]);
%! U = abs (fft (u - mean (u))).^2;
%! f = 2 * min ((0:999).', 1000 - (0:999).') / 1000;
%! out = f < 0.2 - 1e-9 | f > 0.4 + 1e-9;
%! assert (sum (U(out,:)) ./ sum (U), [0 0], 1e-20);
%! assert (mean (u), [3 3], 1e-12);
%! assert (std (u, 1), [2 2], 1e-12);

## rbs: two levels; clipping spreads power out of the band, but about 80 %
## stays in it (20 % for a white binary signal)
%!test
%! randn ("seed", 2);
%! u = idinput (4000, "rbs", [0 0.2], [0 3]);
%! assert (unique (u), [0; 3]);
%! U = abs (fft (u - mean (u))).^2;
%! f = 2 * min ((0:3999).', 4000 - (0:3999).') / 4000;
%! assert (sum (U(f <= 0.2)) / sum (U) > 0.7);

## prbs: clock period 1/B, levels, the maximum-length sequence of prbs
%!test
%! u = idinput (1000, "prbs", [0 0.1], [-1 1]);
%! assert (size (u), [1000, 1]);
%! assert (unique (u), [-1; 1]);
%! held = reshape (u, 10, []);
%! assert (all (held == held(1,:)));
%! assert (u, prbs (7, 10, [-1 1], 1000));
%! u = idinput ([127 1 3], "prbs");
%! assert (u, repmat (prbs (7), 3, 1));

## sine: only grid frequencies in the band, levels met exactly; periodic
%!test
%! rand ("seed", 3);
%! [u, w] = idinput (500, "sine", [0 0.5]);
%! assert ([min(u), max(u)], [-1, 1], 1e-12);
%! assert (numel (w), 10);
%! assert (all (w > 0 & w <= 0.5 * pi + 1e-12));
%! U = abs (fft (u - mean (u)));
%! bins = round (w * 500 / (2*pi)) + 1;
%! other = setdiff (1:251, bins);
%! assert (max (U(other)) / max (U(bins)) < 1e-10);
%! [u3, w3] = idinput ([100 2 3], "sine", [0.5 1], [0 1], [4 2 2]);
%! assert (size (u3), [300, 2]);
%! assert (u3(1:100,:), u3(201:300,:));
%! assert (mod (round (w3 * 100 / (2*pi)), 2), zeros (4, 1));
%! assert (all (w3 >= 0.5 * pi - 1e-12));

%!error id=idinput:badInput idinput (0)
%!error id=idinput:badInput idinput ([10 1 1 1])
%!error id=idinput:badInput idinput (10.5)
%!error id=idinput:badInput idinput (1e6 * [1e3 1])
%!error id=idinput:badOption idinput (10, 3)
%!error id=idinput:badOption idinput (10, "chirp")
%!error id=idinput:badInput idinput (10, "rgs", [0.5 0.2])
%!error id=idinput:badInput idinput (10, "rgs", [0 2])
%!error id=idinput:badInput idinput (10, "rgs", [0 1], [1 1])
%!error id=idinput:badInput idinput (10, "rgs", [0 1], [0 Inf])
%!error id=idinput:badInput idinput (10, "prbs", [0.1 0.5])
%!error id=idinput:badInput idinput (10, "sine", [0 1], [-1 1], [1 2])
%!error id=idinput:badInput idinput (10, "sine", [0.01 0.05])
%!error id=idinput:badInput idinput (10, "rgs", [0.01 0.05])
%!error id=idinput:badInput idinput (10, "rgs", [0 0.05])
%!error id=idinput:badInput idinput ()
%!error id=idinput:badInput idinput (10, "rgs", [0 1], [-1 1], [10 10 1], 6)

%!demo
%! ## a PRBS with clock period 10 and a multisine in the lower half band
%! u1 = idinput (1000, "prbs", [0 0.1], [-1 1]);
%! u2 = idinput (1000, "sine", [0 0.5]);
%! subplot (2, 1, 1); stairs (u1(1:200));
%! subplot (2, 1, 2); plot (u2(1:200));
