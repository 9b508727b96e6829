## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn  {} {@var{h} =} freqs (@var{b}, @var{a}, @var{w})
## @deftypefnx {} {[@var{h}, @var{w}] =} freqs (@var{b}, @var{a})
## @deftypefnx {} {[@var{h}, @var{w}] =} freqs (@var{b}, @var{a}, @var{n})
## @deftypefnx {} {} freqs (@dots{})
## Frequency response of the analog filter (continuous-time transfer
## function) B(s)/A(s), b and a the coefficient rows in descending powers
## of s, at the frequencies @var{w} (rad/s):
## @example
## h = polyval (b, 1i*w) ./ polyval (a, 1i*w)
## @end example
## (MATLAB's and Octave's signal package @code{freqs}, which CONTSID's
## frequency-domain demos call as @code{Gdet = freqs (B, F, w)} and
## @code{freqs (M0.B, M0.F, w)}; this toolbox carries it because the
## signal package is not installed by default).  @var{h} has the shape of
## @var{w}.
##
## A positive integer scalar @var{n} (default 200) asks for @var{n}
## logarithmically spaced frequencies, from a decade below the smallest
## non-zero root magnitude of a and b to a decade above the largest (1 to
## 10 rad/s around them when there are none), returned in @var{w}.  With no
## output, plots magnitude (log-log) and phase (degrees).  A zero of A(j w)
## gives an infinite response (Inf), as the polynomials say.
## @seealso{freqresp, bode, idfrd}
## @end deftypefn

function varargout = freqs (varargin)
  varargout = contsid_guard ("freqs", @freqs_body, nargout, varargin);
endfunction

function [h, w, varargout] = freqs_body (varargin)
  contsid_nargchk ("freqs", nargin, nargout, [2 3], 2);
  b = coefficients (varargin{1}, "b");
  a = coefficients (varargin{2}, "a");
  if (all (a == 0))
    error ("freqs:badInput", "freqs: 'a' must not be all zeros");
  endif
  n = 200;
  w = [];
  if (nargin == 3)
    w = varargin{3};
    if (! isnumeric (w) || ! isreal (w) || isempty (w) || ! isvector (w)
        || any (! isfinite (w)))
      error ("freqs:badInput",
             "freqs: 'w' must be a non-empty real finite vector");
    endif
    if (isscalar (w) && w == fix (w) && w >= 1)
      n = w;
      w = [];
      if (n > 1e7)
        error ("freqs:badInput", "freqs: at most 1e7 frequencies");
      endif
    endif
  endif
  if (isempty (w))
    r = abs ([roots(b); roots(a)]);
    r = r(r > 0 & isfinite (r));
    if (isempty (r))
      lo = 0; hi = 1;
    else
      lo = floor (log10 (min (r))) - 1;
      hi = ceil (log10 (max (r))) + 1;
    endif
    w = logspace (lo, hi, n);
  endif
  w = double (w);
  s = 1i * w;
  h = polyval (b, s) ./ polyval (a, s);
  if (nargout == 0)
    subplot (2, 1, 1);
    loglog (w, abs (h));
    ylabel ("magnitude");
    subplot (2, 1, 2);
    semilogx (w, unwrap (angle (h(:))) * 180 / pi);
    ylabel ("phase (deg)"); xlabel ("frequency (rad/s)");
    clear h w;
  endif
endfunction

function c = coefficients (c, name)
  if (! isnumeric (c) || isempty (c) || ! isvector (c)
      || any (! isfinite (c)))
    error ("freqs:badInput",
           "freqs: '%s' must be a non-empty finite coefficient vector", name);
  endif
  c = double (c(:).');
endfunction

%!test  # the Rao-Garnier benchmark against the control package
%! pkg load control
%! B = [-6400 1600]; F = [1 5 408 416 1600];
%! w = logspace (-1, 2, 250)';
%! h = freqs (B, F, w);
%! assert (size (h), [250 1]);
%! assert (h, squeeze (freqresp (tf (B, F), w)), 1e-12 * max (abs (h)));

%!test  # first order by hand; automatic frequencies
%! w = [0 1 10];
%! assert (freqs (2, [1 2], w), 2 ./ (1i * w + 2), 1e-15);
%! [h, w] = freqs (1, [1 10 100]);
%! assert (numel (w), 200);
%! assert ([w(1) w(end)], [1 100], 1e-12);     # the roots: abs 10
%! assert (h, 1 ./ ((1i * w).^2 + 10i * w + 100), 1e-15);
%! [h, w] = freqs (1, [1 1], 5);
%! assert (numel (w), 5);
%! assert (freqs (1, [1 0], 0), Inf);

%!error id=freqs:badInput freqs (1)
%!error id=freqs:badInput freqs ([], 1, 1)
%!error id=freqs:badInput freqs (1, [0 0], 1)
%!error id=freqs:badInput freqs (1, [1 NaN], 1)
%!error id=freqs:badInput freqs (1, [1 1], [1 NaN])
%!error id=freqs:badInput freqs (1, [1 1], "w")
%!error id=freqs:badInput freqs (1, [1 1], 1e9)
%!error id=freqs:badInput [a, b, c] = freqs (1, [1 1], 1)

%!demo
%! freqs ([-6400 1600], [1 5 408 416 1600], logspace (-1, 2, 250));
