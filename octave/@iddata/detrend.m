## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn  {} {@var{d} =} detrend (@var{data})
## @deftypefnx {} {@var{d} =} detrend (@var{data}, @var{type})
## @deftypefnx {} {@var{d} =} detrend (@var{data}, @var{type}, @var{brkp})
## @deftypefnx {} {@var{d} =} detrend (@var{data}, @var{T})
## @deftypefnx {} {[@var{d}, @var{T}] =} detrend (@dots{})
## Remove offsets or trends from the signals of a time-domain
## @code{iddata} set (each output and input, each experiment).
##
## @strong{Inputs}
## @table @var
## @item type
## 0 or @qcode{"constant"} (default): remove the mean; 1 or
## @qcode{"linear"}: remove the least-squares straight line; an integer
## @var{p} > 1: remove the least-squares polynomial of degree @var{p} (the
## control package's form).
## @item brkp
## break points, sample indices (1 < @var{k} <= @var{N}).  With
## @var{type} 1 the trend is a continuous piecewise-linear function whose
## slope may change at each break point; with @var{type} 0 it is a
## constant on each segment @code{[1, k1-1], [k1, k2-1], @dots{}}.
## @item T
## a trend struct as returned below: its offsets and slopes are removed
## (MATLAB's @code{detrend (data, T)} with a TrendInfo).
## @end table
##
## @strong{Outputs}
## @table @var
## @item d
## the detrended set (sampling, @code{InterSample} and names kept).
## @item T
## for @var{type} 0 or 1 without break points, a struct (one element per
## experiment) with fields @code{OutputOffset}, @code{OutputSlope},
## @code{InputOffset}, @code{InputSlope} (rows, one entry per channel): the
## removed trend is @code{Offset + Slope * t}, with @code{t} the sampling
## instants.
## @end table
##
## The trend is fitted against the sampling instants, so that irregularly
## sampled data get the trend of the physical time (for regular sampling
## this is the same as fitting against the sample index).
## Frequency-domain data: @code{iddata:notSupported}.
## Missing samples (NaN) stay missing: each channel's trend is fitted on
## the samples it has.
## @seealso{iddata, detrend}
## @end deftypefn

function varargout = detrend (varargin)
  varargout = contsid_guard ({"detrend", "iddata"}, @detrend_body, nargout,
                             varargin);
endfunction

function [dat, trend, varargout] = detrend_body (dat, type = 0, brkp = [],
                                                 varargin)
  contsid_nargchk ("detrend", nargin, nargout, [1 Inf], 2);
  if (nargin > 3)
    error ("iddata:badInput",
           "iddata: detrend: takes 1 to 3 arguments, not %d", nargin);
  endif
  if (! dat.timedomain)
    error ("iddata:notSupported",
           "iddata: detrend: frequency-domain data cannot be detrended");
  endif
  info = samplinginfo (dat);
  nexp = numel (dat.y);
  if (isstruct (type))
    dat = remove_trend (dat, type, info);
    trend = type;
    return;
  endif
  order = trend_order (type);
  if (! isempty (brkp) || nargin == 3)
    if (! (isnumeric (brkp) && isreal (brkp) && isvector (brkp)
           && all (brkp == fix (brkp))))
      error ("iddata:badInput",
             "iddata: detrend: break points 'brkp' must be sample indices");
    endif
    if (order > 1)
      error ("iddata:notSupported",
             "iddata: detrend: break points need type 0 or 1");
    endif
    if (nargout > 1)
      error ("iddata:notSupported",
             "iddata: detrend: no trend struct with break points");
    endif
  endif
  trend = struct ("OutputOffset", cell (nexp, 1), "OutputSlope", [],
                  "InputOffset", [], "InputSlope", []);
  for e = 1:nexp
    t = info(e).SamplingInstants;
    n = numel (t);
    brk = unique (brkp(:));
    if (any (brk < 2 | brk > n))
      error ("iddata:badInput",
             "iddata: detrend: break points must lie in 2..%d (experiment %d)",
             n, e);
    endif
    ## centred and scaled time keeps the polynomial basis well conditioned
    if (n > 1)
      tau = (t - t(1)) / (t(end) - t(1)) * 2 - 1;
    else
      tau = zeros (n, 1);
    endif
    if (order + 1 + numel (brk) > n)
      error ("iddata:badInput",
             ["iddata: detrend: experiment %d has too few samples (%d) ", ...
              "for this trend"], e, n);
    endif
    basis = trend_basis (tau, order, brk);
    if (rank (basis) < columns (basis))
      error ("iddata:badInput",
             ["iddata: detrend: experiment %d has too few samples for ", ...
              "this trend"], e);
    endif
    [dat.y{e}, cy] = fit_out (basis, dat.y{e});
    if (! isempty (dat.u))
      [dat.u{e}, cu] = fit_out (basis, dat.u{e});
    else
      cu = zeros (columns (basis), 0);
    endif
    if (nargout > 1 && isempty (brk) && order <= 1)
      [trend(e).OutputOffset, trend(e).OutputSlope] = to_time (cy, t, order);
      [trend(e).InputOffset, trend(e).InputSlope] = to_time (cu, t, order);
    endif
  endfor
endfunction

function order = trend_order (type)
  if (ischar (type))
    switch (lower (type))
      case "constant"
        order = 0;
      case "linear"
        order = 1;
      otherwise
        error ("iddata:badInput",
               "iddata: detrend: type must be \"constant\" or \"linear\"");
    endswitch
  elseif (isnumeric (type) && isscalar (type) && isreal (type)
          && type >= 0 && type == fix (type))
    order = double (type);
  else
    error ("iddata:badInput",
           ["iddata: detrend: type must be 0, 1, \"constant\", ", ...
            "\"linear\" or a polynomial degree"]);
  endif
endfunction

function basis = trend_basis (tau, order, brk)
  n = numel (tau);
  if (isempty (brk))
    basis = tau .^ (0:order);
  elseif (order == 0)
    edges = [1; brk; n + 1];
    basis = zeros (n, numel (edges) - 1);
    for k = 1:numel (edges) - 1
      basis(edges(k):edges(k+1)-1, k) = 1;
    endfor
  else
    basis = [ones(n, 1), tau, max(tau - tau(brk).', 0)];
  endif
endfunction

## The trend of each channel is fitted on the samples it has: a missing
## sample (NaN) stays missing instead of spreading over the record.
function [x, c] = fit_out (basis, x)
  c = zeros (columns (basis), columns (x));
  for j = 1:columns (x)
    have = ! isnan (x(:,j));
    if (rank (basis(have,:)) < columns (basis))
      error ("iddata:badInput",
             ["iddata: detrend: a channel has too few samples that are ", ...
              "not missing (NaN) for this trend"]);
    endif
    c(:,j) = basis(have,:) \ x(have,j);
  endfor
  x = x - basis * c;
endfunction

## offset and slope of the trend c0 + c1*tau in the time t
function [offset, slope] = to_time (c, t, order)
  n = numel (t);
  if (order == 0 || n < 2)
    offset = c(1,:);
    slope = zeros (1, columns (c));
    return;
  endif
  scale = 2 / (t(end) - t(1));
  slope = c(2,:) * scale;
  offset = c(1,:) - c(2,:) * (t(1) * scale + 1);
endfunction

function dat = remove_trend (dat, trend, info)
  need = {"OutputOffset", "OutputSlope", "InputOffset", "InputSlope"};
  if (! all (isfield (trend, need)) || numel (trend) != numel (dat.y))
    error ("iddata:badInput",
           ["iddata: detrend: 'T' must be a trend struct (fields %s), ", ...
            "one element per experiment"], strjoin (need, ", "));
  endif
  for e = 1:numel (dat.y)
    t = info(e).SamplingInstants;
    dat.y{e} = dat.y{e} - line_values (trend(e).OutputOffset,
                                       trend(e).OutputSlope, t,
                                       columns (dat.y{e}));
    if (! isempty (dat.u))
      dat.u{e} = dat.u{e} - line_values (trend(e).InputOffset,
                                         trend(e).InputSlope, t,
                                         columns (dat.u{e}));
    endif
  endfor
endfunction

function v = line_values (offset, slope, t, nch)
  if (isempty (slope))
    slope = zeros (1, nch);
  endif
  if (! (isnumeric (offset) && isnumeric (slope) && numel (offset) == nch
         && numel (slope) == nch))
    error ("iddata:dimensionMismatch",
           "iddata: detrend: the trend has not one offset per channel (%d)",
           nch);
  endif
  v = offset(:).' + t * slope(:).';
endfunction

%!shared t, y, u
%! t = (0:199).' * 0.1;
%! y = [3 + 0.5 * t + sin(2 * t), -1 + cos(3 * t)];
%! u = 2 - 0.1 * t + sign (sin (t));

## against a direct least-squares fit (polyfit) of each column
%!test
%! d = detrend (iddata (y, u, 0.1, "InterSample", "foh"), "linear");
%! for c = 1:2
%!   p = polyfit (t, y(:,c), 1);
%!   assert (d.y(:,c), y(:,c) - polyval (p, t), 1e-10);
%! endfor
%! assert (d.u, u - polyval (polyfit (t, u, 1), t), 1e-10);
%! assert (d.InterSample, "foh");
%! d0 = detrend (iddata (y, u, 0.1));
%! assert (d0.y, y - mean (y), 1e-12);
%! assert (struct (detrend (iddata (y, u, 0.1), 0)), struct (d0));
%! d2 = detrend (iddata (y, u, 0.1), 2);
%! assert (d2.u, u - polyval (polyfit (t, u, 2), t), 1e-10);

## irregular sampling: the trend of the physical time
%!test
%! ti = t + 0.04 * sin (7 * t);
%! d = detrend (iddata (2 + 3 * ti, [], "SamplingInstants", ti), 1);
%! assert (d.y, zeros (200, 1), 1e-12);
%! [d, T] = detrend (iddata (y, u, "SamplingInstants", ti), 1);
%! p = polyfit (ti, u, 1);
%! assert ([T.InputOffset, T.InputSlope], [p(2), p(1)], 1e-10);
%! assert (T.OutputSlope(1), polyfit (ti, y(:,1), 1)(1), 1e-10);
%! back = detrend (iddata (y, u, "SamplingInstants", ti), T);
%! assert (back.u, d.u, 1e-10);

## break points: an exact continuous piecewise-linear trend is removed
%!test
%! trend = 1 + 0.3 * t - 0.8 * max (t - t(60), 0) + 0.5 * max (t - t(150), 0);
%! noise = sin (5 * t);
%! d = detrend (iddata (trend, [], 0.1), 1, [60 150]);
%! assert (d.y, zeros (200, 1), 1e-10);
%! d = detrend (iddata (trend + noise, [], 0.1), 1, [60 150]);
%! basis = [ones(200, 1), t, max(t - t(60), 0), max(t - t(150), 0)];
%! assert (d.y, noise - basis * (basis \ noise), 1e-10);
%! d = detrend (iddata (trend, [], 0.1), 0, 101);
%! assert (d.y, trend - [mean(trend(1:100)) * ones(100, 1);
%!                       mean(trend(101:end)) * ones(100, 1)], 1e-12);

%!test
%! ## missing samples stay missing; the trend is fitted on the others
%! tt = (0:99).' * 0.1;
%! yy = 2 + 0.5 * tt + sin (3 * tt);
%! yy(30:40) = NaN;
%! uu = cos (tt);
%! d = detrend (iddata (yy, uu, 0.1), 1);
%! have = ! isnan (yy);
%! p = polyfit (tt(have), yy(have), 1);
%! assert (isnan (d.y), ! have);
%! assert (d.y(have), yy(have) - polyval (p, tt(have)), 1e-12);
%! assert (d.u, uu - polyval (polyfit (tt, uu, 1), tt), 1e-12);
%! d0 = detrend (iddata (yy, uu, 0.1));
%! assert (d0.y(have), yy(have) - mean (yy(have)), 1e-12);
%!error id=iddata:badInput detrend (iddata ([NaN; NaN; 3], (1:3).', 1), 1)
%!error id=iddata:badInput detrend (iddata (y, u, 0.1), "cubic")
%!error id=iddata:badInput detrend (iddata (y, u, 0.1), -1)
%!error id=iddata:badInput detrend (iddata (y, u, 0.1), 1, [1 300])
%!error id=iddata:badInput detrend (iddata (y, u, 0.1), 1, 2.5)
%!error id=iddata:badInput detrend (iddata (y, u, 0.1), struct ("a", 1))
%!error id=iddata:badInput detrend (iddata ([1; 2], [], 1), 3)
%!error id=iddata:badInput detrend (iddata ([1; 2], [], 1), 1e12)
%!error id=iddata:notSupported detrend (iddata (y, u, 0.1), 2, 50)
%!error id=iddata:notSupported [a, b] = detrend (iddata (y, u, 0.1), 1, 50);
%!error id=iddata:notSupported detrend (fft (iddata (y, u, 0.1)))
%!error id=iddata:dimensionMismatch
%! detrend (iddata (y, u, 0.1), struct ("OutputOffset", 1, "OutputSlope", 0,
%!                                      "InputOffset", 1, "InputSlope", 0));
%!error id=iddata:badInput detrend (iddata (y, u, 0.1), 1, 50, 4)

%!demo
%! t = (0:0.1:50).';
%! u = 1 + 0.02 * t + sign (sin (t));
%! y = filter (0.1, [1 -0.9], u) + 5;
%! [d, T] = detrend (iddata (y, u, 0.1), 1);
%! T
