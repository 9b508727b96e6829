## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn  {} {} residc (@var{data}, @var{M})
## @deftypefnx {} {} residc (@var{data}, @var{THM}, @var{nn})
## @deftypefnx {} {} residc (@var{data}, @var{M}, @var{m})
## @deftypefnx {} {@var{R} =} residc (@dots{}, "maxlag", @var{m})
## Residual analysis of a continuous-time model: the simulation error
## e = y - yh, its autocorrelation and its cross-correlation with each
## input, with 99% confidence bounds.
##
## The model is given as for @code{comparec} (an @code{idpoly},
## @code{idtf}, @code{idproc}, @code{idss} with one output, @code{idctm},
## a struct with B and F, a control @code{tf}/@code{ss}, or THM with
## @var{nn}); a number after a model is the largest lag @var{m}. @var{R}
## is a struct:
## @table @code
## @item e
## the residual (N-by-1).
## @item lags, autocorr
## lags 0..m and the normalised autocorrelation of e (autocorr(1) = 1).
## @item xlags, xcorr
## lags -m..m and the normalised cross-correlation between e(t) and
## u_j(t - lag), one column per input.
## @item bound
## the 99% confidence bound 2.576/sqrt(N) of a white residual
## independent of the input.
## @item white, independent
## true when no autocorrelation at lags 1..m, respectively no
## cross-correlation, lies outside the bound.
## @item testable
## false (with @code{reason}) when the residual is constant or zero to
## rounding (below 1e-10 times the output's RMS), so that no correlation
## means anything; then @code{white} and @code{independent} are true. (A
## model whose output diverges is an error, residc:numericalFailure.)
## @end table
## Without outputs it plots both correlations with their bounds.
## Option @code{"maxlag"}: the largest lag m (default 25; N must exceed it).
## Option @code{"Levels"}: @qcode{"carried"} (default), yh is the model
## at the levels it carries (as @code{comparec} and @code{simc}: a model
## @code{srivc} estimated on a raw record, y - c = M (u - d); see
## @code{help idpoly}), or @qcode{"ignore"}, the model alone (give data
## with the offsets removed).
##
## @strong{Example}
## @example
## u = prbs (9, 8); Ts = 0.05; N = numel (u);
## y = simc (idctm (4, [1 2.4 4]), u, Ts) + 0.05 * randn (N, 1);
## R = residc (iddata (y, u, Ts), idctm (4, [1 2.4 4]));
## R.white, R.independent
## @end example
## @seealso{comparec, srivc}
## @end deftypefn

function varargout = residc (varargin)
  varargout = contsid_guard ("residc", @residc_body, nargout, varargin);
endfunction

function [R, varargout] = residc_body (varargin)
  contsid_nargchk ("residc", nargin, nargout, [0 Inf], 1);
  [d, yhat, rest] = contsid_model_output ("residc", varargin);
  if (columns (d.y) != 1)
    error ("residc:notSupported", "residc: one output only (%d given)",
           columns (d.y));
  endif
  if (! isempty (rest) && isnumeric (rest{1})
      && ! isnumeric (varargin{d.nconsumed + 1}))
    rest = [{"maxlag"}, rest];
  endif
  opts = contsid_options ("residc", struct ("maxlag", 25), rest);
  m = opts.maxlag;
  if (! isnumeric (m) || ! isreal (m) || ! isscalar (m) || m != fix (m)
      || m < 1)
    error ("residc:badInput", "residc: maxlag must be an integer >= 1");
  endif
  e = d.y - yhat;
  N = numel (e);
  if (N <= m + 1)
    error ("residc:badInput", ...
           "residc: %d samples are too few for maxlag = %d", N, m);
  endif
  out.e = e;
  out.lags = (0:m)';
  out.xlags = (-m:m)';
  out.bound = 2.576 / sqrt (N);
  nu = columns (d.u);
  ec = e - mean (e);
  if (all (ec == 0)
          || sqrt (mean (e .^ 2)) <= 1e-10 * sqrt (mean (d.y .^ 2)))
    out.autocorr = [1; zeros(m, 1)];
    out.xcorr = zeros (2 * m + 1, nu);
    out.white = true;
    out.independent = true;
    out.testable = false;
    out.reason = "the residual is constant or zero to rounding";
  else
    out.autocorr = zeros (m + 1, 1);
    for k = 0:m
      out.autocorr(k+1) = sum (ec(1+k:end) .* ec(1:end-k)) / sum (ec .^ 2);
    endfor
    out.xcorr = zeros (2 * m + 1, nu);
    for j = 1:nu
      uc = d.u(:, j) - mean (d.u(:, j));
      scale = sqrt (sum (ec .^ 2) * sum (uc .^ 2));
      for i = 1:numel (out.xlags)
        k = out.xlags(i);        # e(t) against u(t - k)
        if (k >= 0)
          c = sum (ec(1+k:end) .* uc(1:end-k));
        else
          c = sum (ec(1:end+k) .* uc(1-k:end));
        endif
        out.xcorr(i, j) = ifelse_zero (scale, c / scale);
      endfor
    endfor
    out.white = all (abs (out.autocorr(2:end)) <= out.bound);
    out.independent = all (abs (out.xcorr(:)) <= out.bound);
    out.testable = true;
    out.reason = "";
  endif
  if (nargout > 0)
    R = out;
    return;
  endif
  subplot (2, 1, 1);
  stem (out.lags, out.autocorr);
  hold on;
  plot (out.lags([1 end]), [1 1] * out.bound, "r--",
        out.lags([1 end]), -[1 1] * out.bound, "r--");
  hold off;
  title ("autocorrelation of the residual");
  subplot (2, 1, 2);
  plot (out.xlags, out.xcorr, "o-");
  hold on;
  plot (out.xlags([1 end]), [1 1] * out.bound, "r--",
        out.xlags([1 end]), -[1 1] * out.bound, "r--");
  hold off;
  title ("cross-correlation of the residual with the input");
  xlabel ("lag (samples)");
endfunction

function v = ifelse_zero (scale, v)
  if (scale == 0)
    v = 0;
  endif
endfunction

%!shared u, Ts, x, M, N
%! u = prbs (10, 4); Ts = 0.05; N = numel (u);
%! M = idctm (4, [1 2.4 4]);
%! x = simc (M, u, Ts);

%!test  # white noise and the true model: white and independent
%! randn ("state", 1);
%! R = residc (iddata (x + 0.1 * randn (N, 1), u, Ts), M);
%! assert (R.testable);
%! assert (R.autocorr(1), 1, 1e-12);
%! assert (mean (abs (R.autocorr(2:end)) > R.bound) <= 0.1);
%! assert (mean (abs (R.xcorr(:)) > R.bound) <= 0.1);

%!test  # a wrong model: residual correlated with the input
%! R = residc (iddata (x, u, Ts), idctm (3, [1 2.4 4]));
%! assert (! R.independent);
%! assert (! R.white);

%!test  # a delayed input: the cross-correlation peaks at lag 3
%! x3 = [zeros(3, 1); x(1:end-3)];
%! R = residc (iddata (x3, u, Ts), idctm (0.01, [1 1]), "maxlag", 10);
%! [~, i] = max (abs (R.xcorr));
%! assert (R.xlags(i) >= 3);

%!test  # a perfect model: cannot test, reported
%! R = residc (iddata (x, u, Ts), M);
%! assert (! R.testable);

%!test  # exact to rounding: cannot test either
%! R = residc (iddata (x, u, Ts), idctm (4 * (1 + 1e-14), [1 2.4 4]));
%! assert (! R.testable);

%!test  # SITB models; the CONTSID form with the lag as third argument
%! randn ("state", 2);
%! y = x + 0.1 * randn (N, 1);
%! R1 = residc (iddata (y, u, Ts), idpoly (1, 4, 1, 1, [1 2.4 4], "Ts", 0));
%! R2 = residc (iddata (y, u, Ts), idtf (4, [1 2.4 4]), 25);
%! assert (R2.e, R1.e, 1e-12);
%! assert (R2.autocorr, R1.autocorr, 1e-10);

%!test  # the model's levels: the residual of a raw record
%! v = prbs (8, 6); h = 0.05;
%! e = 0.1 * sin ((1:numel (v))');
%! yr = simc (idctm (4, [1 2.4 4]), v, h) + e;
%! M2 = idtf (4, [1 2.4 4]);
%! M2.Report.DataUsed.InputOffset = 2;
%! M2.Report.DataUsed.OutputOffset = 10;
%! R = residc (iddata (yr + 10, v + 2, h), M2);
%! assert (R.e, e, 1e-10);
%! R0 = residc (iddata (yr, v, h), M2, "Levels", "ignore");
%! assert (R0.e, e, 1e-10);
%!error id=residc:badOption residc (iddata (ones (40, 1), prbs (5, 2)(1:40), 0.1), idtf (1, [1 1]), "Levels", 1)
%!error id=residc:notSupported residc (iddata ([x x], u, Ts), idss (-1, 1, [1; 1], [0; 0]))
%!error id=residc:numericalFailure residc (iddata (x, u, Ts), idctm (4, [1 -30 4]))

%!error id=residc:badInput residc (iddata (x, u, Ts), M, "maxlag", 0)
%!error id=residc:badInput residc (iddata (x(1:10), u(1:10), Ts), M, "maxlag", 20)
%!error id=residc:badOption residc (iddata (x, u, Ts), M, "bogus", 1)
%!error id=residc:badInput residc (iddata (x, u, Ts), {1})

%!demo
%! u = prbs (9, 8); Ts = 0.05; N = numel (u);
%! y = simc (idctm (4, [1 2.4 4]), u, Ts) + 0.05 * randn (N, 1);
%! residc (iddata (y, u, Ts), idctm (4, [1 2 4]));
