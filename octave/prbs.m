## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn  {} {@var{u} =} prbs (@var{n})
## @deftypefnx {} {@var{u} =} prbs (@var{n}, @var{p})
## @deftypefnx {} {@var{u} =} prbs (@var{n}, @var{p}, @var{levels})
## @deftypefnx {} {@var{u} =} prbs (@var{n}, @var{p}, @var{levels}, @var{N})
## @deftypefnx {} {@var{u} =} prbs (@dots{}, "length", @var{N})
## @deftypefnx {} {[@var{u}, @var{taps}] =} prbs (@dots{})
## Pseudo-random binary sequence (CONTSID's @code{prbs}).
##
## A maximum-length sequence from an @var{n}-bit linear feedback shift
## register, each bit held for @var{p} samples.
##
## @strong{Inputs}
## @table @var
## @item n
## number of register bits, an integer from 2 to 32.  The sequence repeats
## every @code{2^@var{n} - 1} bits.
## @item p
## number of samples each bit is held (clock period in samples), a
## positive integer; default 1.
## @item levels
## @code{[low, high]}, the two values of the signal; default
## @code{[-1, 1]}.
## @item N
## number of samples wanted: the sequence is truncated, or repeated
## periodically, to @var{N} samples.  Default: one period,
## @code{(2^@var{n} - 1) * @var{p}} samples.  Give it for large @var{n}:
## one period of a 32-bit register has 4.3e9 samples.
## @end table
## Empty @var{p} or @var{levels} take the defaults.
##
## @strong{Outputs}
## @table @var
## @item u
## column vector of @var{N} samples, each @var{low} or @var{high}.
## @item taps
## the feedback taps, @code{taps(1) = n}: the bits @var{s} of the sequence
## (1 for @var{high}) obey
## @code{s(k) = xor (s(k - taps(1)), s(k - taps(2)), @dots{})}, and the
## polynomial @code{x^taps(1) + x^taps(2) + @dots{} + 1} is primitive over
## GF(2).
## @end table
##
## @strong{Algorithm.}  The register starts with all bits set, so the
## sequence starts with @var{n} bits at @var{high}; a set bit gives
## @var{high}, a clear bit @var{low}.  The feedback polynomials are the
## maximal-length taps tabulated in Xilinx application note XAPP052
## (P. Alfke, "Efficient shift registers, LFSR counters, and long
## pseudo-random sequence generators", 1996).  Over one period a set bit
## occurs @code{2^(@var{n}-1)} times and a clear bit one time less, and
## the periodic autocorrelation of the +/-1 sequence is 1 at lag 0 and
## @code{-1/(2^@var{n}-1)} at every other lag, which is what makes the
## sequence a good identification input.  The output is the same on every
## call.
##
## @strong{Example}
## @example
## @group
## u = prbs (4, 2, [0 5]);   # 15 bits held 2 samples: 30 samples in @{0, 5@}
## u(1:10).'
##   @result{} 5   5   5   5   5   5   5   5   0   0
## @end group
## @end example
## @seealso{iddata}
## @end deftypefn

function varargout = prbs (varargin)
  varargout = contsid_guard ("prbs", @prbs_body, nargout, varargin);
endfunction

function [u, taps, varargout] = prbs_body (varargin)
  contsid_nargchk ("prbs", nargin, nargout, [1 Inf], 2);
  npos = find (cellfun ("ischar", varargin), 1) - 1;
  if (isempty (npos))
    npos = nargin;
  endif
  npos = min (npos, 4);
  positional = [varargin(1:npos), cell(1, 4 - npos)];
  [n, p, levels, len] = positional{:};
  opts = contsid_options ("prbs", struct ("length", {len}),
                          varargin(npos+1:end));
  len = opts.length;
  if (isempty (p))
    p = 1;
  endif
  if (isempty (levels))
    levels = [-1, 1];
  endif

  if (! (is_integer_scalar (n) && n >= 2 && n <= 32))
    error ("prbs:badInput",
           "prbs: 'n' (register length) must be an integer from 2 to 32");
  endif
  if (! (is_integer_scalar (p) && p >= 1))
    error ("prbs:badInput",
           "prbs: 'p' (samples per bit) must be a positive integer");
  endif
  if (! (isnumeric (levels) && isreal (levels) && numel (levels) == 2
         && all (isfinite (levels)) && levels(1) != levels(2)))
    error ("prbs:badInput",
           "prbs: 'levels' must be two distinct finite reals [low, high]");
  endif
  period = 2^n - 1;
  if (isempty (len))
    len = period * p;
  elseif (! (is_integer_scalar (len) && len >= 1))
    error ("prbs:badInput",
           "prbs: 'length' (number of samples) must be a positive integer");
  endif

  taps = feedback_taps (n);
  bits = lfsr_bits (n, taps, min (period, ceil (len / p)));
  bit_of_sample = mod (floor ((0:len-1).' / p), period) + 1;
  levels = double (levels(:));
  u = levels(1 + bits(bit_of_sample));
endfunction

function tf = is_integer_scalar (x)
  tf = (isnumeric (x) && isreal (x) && isscalar (x) && isfinite (x)
        && x == fix (x));
endfunction

## Feedback taps [n, t2, ...] of a maximal-length LFSR of n bits: the
## polynomial x^n + x^t2 + ... + 1 is primitive over GF(2).  Source: Xilinx
## XAPP052 (1996), table 3.  The reciprocal polynomial, with taps n and
## n - t2, ..., is primitive too; of the two, the taps with the larger
## smallest tap are returned: lfsr_bits computes that many bits at once.
function taps = feedback_taps (n)
  persistent table = {[], [2 1], [3 2], [4 3], [5 3], [6 5], [7 6], ...
                      [8 6 5 4], [9 5], [10 7], [11 9], [12 6 4 1], ...
                      [13 4 3 1], [14 5 3 1], [15 14], [16 15 13 4], ...
                      [17 14], [18 11], [19 6 2 1], [20 17], [21 19], ...
                      [22 21], [23 18], [24 23 22 17], [25 22], ...
                      [26 6 2 1], [27 5 2 1], [28 25], [29 27], ...
                      [30 6 4 1], [31 28], [32 22 2 1]};
  taps = table{n};
  mirrored = [n, sort(n - taps(2:end), "descend")];
  if (min (mirrored) > min (taps))
    taps = mirrored;
  endif
endfunction

## First nbits bits of s(k) = xor over the taps t of s(k - t), starting
## from n set bits (the register's initial state).  Over GF(2) the square of
## the feedback polynomial is the polynomial in x^2, so the bits also obey
## the recurrence with every tap doubled, once k exceeds the doubled largest
## tap.  Bit k depends on bits k - min (taps) * scale and older only, so
## blocks of that many bits are computed in one vector step, and doubling
## the scale as the sequence grows keeps the number of steps proportional
## to log (nbits).
function s = lfsr_bits (n, taps, nbits)
  s = false (max (nbits, n), 1);
  s(1:n) = true;
  scale = 1;
  k = n + 1;
  while (k <= nbits)
    while (k - 1 >= 2 * scale * n)
      scale *= 2;
    endwhile
    lags = taps * scale;
    block = (k:min (k + min (lags) - 1, nbits)).';
    next = s(block - lags(1));
    for lag = lags(2:end)
      next = xor (next, s(block - lag));
    endfor
    s(block) = next;
    k = block(end) + 1;
  endwhile
  s = s(1:nbits);
endfunction

%!test
%! for n = 2:16
%!   u = prbs (n);
%!   period = 2^n - 1;
%!   assert (size (u), [period, 1]);
%!   assert (all (u == -1 | u == 1));
%!   assert (sum (u == 1), 2^(n-1));
%!   ## periodic autocorrelation: period at lag 0, -1 at every other lag
%!   r = round (real (ifft (abs (fft (u)).^2)));
%!   assert (r(1), period);
%!   assert (r(2:end), -ones (period - 1, 1));
%! endfor

%!test
%! u = prbs (5, 3, [0, 2]);
%! assert (numel (u), 31 * 3);
%! assert (unique (u), [0; 2]);
%! held = reshape (u, 3, []);
%! assert (all (held == held(1, :)));
%! assert (u(1:15), 2 * ones (15, 1));
%! assert (prbs (5, 3, [0, 2]), u);
%! assert (prbs (5, 3, [0, 2], 3 * 31), u);
%! assert (prbs (5, [], [], 4), [1; 1; 1; 1]);

%!test
%! u = prbs (4, 2);
%! assert (prbs (4, 2, [], 10), u(1:10));
%! assert (prbs (4, 2, "length", 75), [u; u; u(1:15)]);
%! assert (prbs (4, "Length", 7), prbs (4, 1, [-1 1], 7));
%! assert (prbs (3, 1, [1 -1]), -prbs (3));
%! assert (prbs (6, 1, single ([-2 3]))(1), 3);

%!function tf = is_primitive (taps)
%!  ## x^n + x^t2 + ... + 1 is primitive iff x^(2^n-1) = 1 modulo it and
%!  ## x^((2^n-1)/q) != 1 for every prime factor q of 2^n-1
%!  n = taps(1);
%!  poly = bitor (sum (bitshift (uint64 (1), taps)), uint64 (1));
%!  order = 2^n - 1;
%!  tf = powmod (order, poly, n) == 1;
%!  for q = unique (factor (order))
%!    tf = tf && powmod (order / q, poly, n) != 1;
%!  endfor
%!endfunction

%!function r = powmod (e, poly, n)
%!  r = uint64 (1);
%!  b = uint64 (2);
%!  while (e > 0)
%!    if (mod (e, 2))
%!      r = mulmod (r, b, poly, n);
%!    endif
%!    b = mulmod (b, b, poly, n);
%!    e = floor (e / 2);
%!  endwhile
%!endfunction

%!function r = mulmod (a, b, poly, n)
%!  r = uint64 (0);
%!  while (b > 0)
%!    if (bitand (b, 1))
%!      r = bitxor (r, a);
%!    endif
%!    b = bitshift (b, -1);
%!    a = bitshift (a, 1);
%!    if (bitand (bitshift (a, -n), 1))
%!      a = bitxor (a, poly);
%!    endif
%!  endwhile
%!endfunction

## every register length: the taps give a primitive polynomial (period
## exactly 2^n - 1) and the bits follow their recurrence
%!test
%! for n = 2:32
%!   [u, taps] = prbs (n, 1, [0 1], 3000);
%!   assert (taps(1), n);
%!   assert (is_primitive (taps));
%!   k = (n+1:3000).';
%!   next = false (size (k));
%!   for t = taps
%!     next = xor (next, u(k - t));
%!   endfor
%!   assert (u(k), double (next));
%! endfor

%!error id=prbs:badInput prbs ()
%!error id=prbs:badInput prbs (1)
%!error id=prbs:badInput prbs (33)
%!error id=prbs:badInput prbs (4.5)
%!error id=prbs:badInput prbs ([4 5])
%!error id=prbs:badInput prbs (4, 0)
%!error id=prbs:badInput prbs (4, 1.5)
%!error id=prbs:badInput prbs (4, 1, 1)
%!error id=prbs:badInput prbs (4, 1, [1 1])
%!error id=prbs:badInput prbs (4, 1, [0 1i])
%!error id=prbs:badInput prbs (4, 1, [0 Inf])
%!error id=prbs:badInput prbs (4, 1, [-1 1], 0)
%!error id=prbs:badInput prbs (4, 1, [-1 1], "length", 2.5)
%!error id=prbs:badOption prbs (4, 1, [-1 1], "period", 3)
%!error id=prbs:badOption prbs (4, 1, [-1 1], "length")
%!error id=prbs:badOption prbs (4, 1, [-1 1], 10, 3)

%!demo
%! ## a 7-bit PRBS held for 4 samples, on levels 0 and 1
%! u = prbs (7, 4, [0 1]);
%! t = (0:numel (u) - 1).' * 0.01;
%! stairs (t, u);
%! axis ([0, t(end), -0.2, 1.2]);
%! xlabel ("time (s)");
%! title ("prbs (7, 4, [0 1])");
