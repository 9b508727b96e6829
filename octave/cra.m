## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn  {} {@var{ir} =} cra (@var{data})
## @deftypefnx {} {@var{ir} =} cra (@var{data}, @var{M}, @var{na}, @var{plot})
## @deftypefnx {} {[@var{ir}, @var{R}, @var{cl}] =} cra (@dots{})
## Impulse response by correlation analysis, as the System Identification
## Toolbox's @code{cra}: the input is prewhitened by a least-squares AR
## model of order @var{na} (default 10), the output is filtered by the same
## filter, and the impulse response at lags 0..@var{M} (default 20) is the
## cross-covariance of the filtered output and the whitened input divided
## by the whitened input's variance.  @var{R} = [lags, R_yy, R_uu, R_yu]
## of the filtered signals, @var{cl} the 99 % confidence level of @var{ir}
## (2.58 sd under independence).  Without outputs (and @var{plot} >
## 0) the response is plotted.  Plain Octave: a presentation-level
## analysis (a few FFT-free sums), no iteration.
##
## @strong{Example}
## @example
## u = randn (1000, 1);
## y = filter ([0 1 0.5], [1 -0.5], u);
## ir = cra (iddata (y, u, 1));
## @end example
## @seealso{delayest, arx, spafdr}
## @end deftypefn

function varargout = cra (varargin)
  varargout = contsid_guard ("cra", @cra_body, nargout, varargin);
endfunction

function [ir, R, cl, varargout] = cra_body (varargin)
  contsid_nargchk ("cra", nargin, nargout, [1 7], 3);
  d = contsid_getdata ("cra", varargin{:});
  rest = varargin(d.nconsumed+1:end);
  if (size (d.u, 2) != 1)
    error ("cra:notSupported", "cra: one input only");
  endif
  if (! d.uniform)
    error ("cra:badInput", "cra: needs regularly sampled data");
  endif
  opts = {20, 10, 1};
  for i = 1:min (numel (rest), 3)
    if (! isempty (rest{i}))
      opts{i} = rest{i};
    endif
  endfor
  if (numel (rest) > 3)
    error ("cra:badInput", "cra: at most M, na and plot after the data");
  endif
  [M, na, plt] = opts{:};
  ok = @(v) isnumeric (v) && isreal (v) && isscalar (v) && isfinite (v) ...
            && v == fix (v) && v >= 0;
  n = rows (d.y);
  if (! ok (M) || ! ok (na) || ! ok (plt) || M < 1 || M + na + 2 >= n)
    error ("cra:badInput",
           "cra: M >= 1 and na >= 0 integers, M + na < N - 2");
  endif
  u = d.u - mean (d.u);
  y = d.y - mean (d.y);
  if (na > 0)
    k = (na+1:n)';
    Phi = zeros (numel (k), na);
    for i = 1:na
      Phi(:, i) = -u(k - i);
    endfor
    if (rank (Phi) < na)
      error ("cra:numericalFailure", ["cra: the input has too little ", ...
             "excitation for an AR(%d) prewhitening filter"], na);
    endif
    a = [1; Phi \ u(k)];
    uf = filter (a, 1, u)(na+1:end);
    yf = filter (a, 1, y)(na+1:end);
  else
    uf = u;
    yf = y;
  endif
  nf = numel (uf);
  lags = (-M:M)';
  ryu = zeros (2 * M + 1, 1);
  ruu = ryu;
  ryy = ryu;
  for i = 1:numel (lags)
    l = lags(i);
    if (l >= 0)
      ryu(i) = yf(l+1:end)' * uf(1:end-l) / nf;
      ruu(i) = uf(l+1:end)' * uf(1:end-l) / nf;
      ryy(i) = yf(l+1:end)' * yf(1:end-l) / nf;
    else
      ryu(i) = yf(1:end+l)' * uf(1-l:end) / nf;
      ruu(i) = uf(1:end+l)' * uf(1-l:end) / nf;
      ryy(i) = yf(1:end+l)' * yf(1-l:end) / nf;
    endif
  endfor
  lam = ruu(M+1);
  if (! (lam > 0))
    error ("cra:numericalFailure", "cra: the input is constant");
  endif
  ir = ryu(M+1:end) / lam;
  R = [lags, ryy, ruu, ryu];
  cl = 2.58 * sqrt (ryy(M+1) / lam / nf);
  if (nargout == 0 && plt > 0)
    stem (0:M, ir);
    hold on;
    plot ([0 M], [cl cl], "r--", [0 M], -[cl cl], "r--");
    hold off;
    xlabel ("lag (samples)");
    title ("Impulse response by correlation analysis");
  endif
endfunction

%!test  # white input: the response of an FIR system is recovered
%! randn ("state", 9);
%! u = randn (20000, 1);
%! y = filter ([0 1 0.5 0.25], 1, u);
%! ir = cra (iddata (y, u, 1), 5, 0);
%! assert (ir, [0 1 0.5 0.25 0 0]', 0.03);

%!test  # coloured input: prewhitening removes the bias
%! randn ("state", 10);
%! u = filter (1, [1 -0.8], randn (20000, 1));
%! y = filter ([0 1 0.5], 1, u);
%! [ir, R, cl] = cra (iddata (y, u, 1), 4, 4);
%! assert (ir, [0 1 0.5 0 0]', 0.03);
%! assert (size (R), [9 4]);
%! assert (cl > 0);

%!error id=cra:badInput cra (iddata ((1:10)', rand (10, 1), 1), 20)
%!error id=cra:badInput cra (iddata ((1:50)', rand (50, 1), 1), -1)
%!error id=cra:badInput cra (iddata ((1:50)', rand (50, 1), 1), 5, 2, 0, 1)
%!error id=cra:notSupported cra (iddata ((1:50)', rand (50, 2), 1))
%!error id=cra:numericalFailure cra (iddata ((1:50)', ones (50, 1), 1), 5, 0)

%!demo
%! u = randn (1000, 1);
%! y = filter ([0 1 0.5], [1 -0.5], u) + 0.1 * randn (1000, 1);
%! cra (iddata (y, u, 1));
