## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn  {} {@var{M} =} tocls (@var{data}, @var{nn}, @var{L})
## @deftypefnx {} {@var{M} =} tocls (@var{data}, @var{nn}, @var{L}, @var{lambda})
## @deftypefnx {} {@var{M} =} tocls (@var{data}, @var{nn}, @var{L}, @var{lambda}, @var{tol})
## @deftypefnx {} {@var{M} =} tocls (@dots{}, @var{name}, @var{value})
## Third-order cumulant least squares estimate of a continuous-time
## errors-in-variables model B(p)/F(p), where both the input and the output
## are measured with noise (CONTSID's @code{tocls}; S. Thil, H. Garnier,
## M. Gilson, Automatica 44(3), 2008).
##
## The data are filtered by the state-variable filter
## (lambda/(p + lambda))^nf (thesis eq. 1.27) and, instead of the
## regression itself, its third-order cross-cumulants with the measured
## input, cum (x(t), u(t - tau), u(t - tau)) for the lags tau = 0 ..
## @var{L}-1, are fitted by least squares.  Noises independent of the
## noise-free input with symmetric distributions (Gaussian, uniform, any
## colour, correlated with each other) have no third-order cumulants, so
## the estimate is consistent where @code{lssvf}, @code{ivsvf} and
## @code{srivc} are biased by the input noise.  The noise-free input must
## have a skewed distribution (e.g. @code{chisqr}); an input whose sample
## skewness is not distinguishable from zero is refused
## (@code{tocls:badInput}).  The signals' means are removed first and kept
## as the model's levels (@code{M.Report.DataUsed.InputOffset} and
## @code{OutputOffset}).
##
## Inputs:
## @table @var
## @item data
## an @code{iddata} object with one output and one input, regularly
## sampled (InterSample @qcode{"zoh"} or @qcode{"foh"}).
## @item nn
## [nf nb nk]: the denominator order nf, the numerator @emph{degree} nb
## (nb + 1 coefficients, nb <= nf) and the input delay nk in samples.
## This is how CONTSID's errors-in-variables demo calls it,
## @code{nn = [length(A)-1 length(B)-1 0]}.
## @item L
## the number of cumulant lags (50 to 150 is usual); at least the number
## of parameters and at most half the record.
## @item lambda
## the SVF cut-off in rad/s (default 3, CONTSID's).
## @item tol
## accepted for CONTSID compatibility; the estimate is not iterative.
## @end table
## The same values may be given as name-value pairs @qcode{"Lags"},
## @qcode{"lambda_svf"}, @qcode{"Tol"}.
##
## @var{M} is an @code{idpoly} (Ts = 0) without covariance: no simple
## formula gives the spread of this estimate.  @code{tocils} iterates the
## same equations with the optimal prefilter and is more accurate.
##
## @strong{Example}
## @example
## Ts = 0.1; n = 5000;
## u0 = chisqr (n, 1, 2); u0 = (u0 - mean (u0)) / std (u0);
## M0 = idpoly (1, [1 -1], 1, 1, [1 2 1], "Ts", 0);
## y0 = simc (M0, iddata ([], u0, Ts, "InterSample", "zoh"));
## data = iddata (y0 + 0.1 * randn (n, 1), u0 + 0.3 * randn (n, 1), Ts);
## M = tocls (data, [2 1 0], 50, 3)
## @end example
## @seealso{tocils, lssvf, ivsvf, srivc, chisqr}
## @end deftypefn

function varargout = tocls (varargin)
  varargout = contsid_guard ("tocls", @tocls_body, nargout, varargin);
endfunction

function [M, varargout] = tocls_body (varargin)
  contsid_nargchk ("tocls", nargin, nargout, [0 Inf], 1);
  M = contsid_eiv ("tocls", varargin);
endfunction

%!shared data, Ts, n
%! Ts = 0.1; n = 5000;
%! randg ("state", 3); randn ("state", 4);
%! u0 = chisqr (n, 1, 2);
%! u0 = filter ([1 -0.2 0.3], 1, u0);
%! u0 = (u0 - mean (u0)) / std (u0);
%! y0 = simc (idpoly (1, [1 -1], 1, 1, [1 2 1], "Ts", 0),
%!            iddata ([], u0, Ts, "InterSample", "zoh"));
%! data = iddata (y0, u0, Ts, "InterSample", "zoh");

%!test
%! ## Noise-free: the true system up to the SVF's O(Ts^2) discretisation
%! ## error of the output channel.
%! M = tocls (data, [2 1 0], 50, 3);
%! assert (isa (M, "idpoly"));
%! assert (M.F, [1 2 1], 0.05);
%! assert (M.B, [1 -1], 0.05);

%!test
%! ## Name-value form, and CONTSID's positional tol accepted.
%! M1 = tocls (data, [2 1 0], "Lags", 50, "lambda_svf", 3);
%! M2 = tocls (data, [2 1 0], 50, 3, 1e-4);
%! assert (M1.F, M2.F, 1e-12);

%!error <M is required> tocls (data, [2 1 0])
%!error id=tocls:badInput tocls (data, [2 3 0], 50)
%!error id=tocls:badInput tocls (data, [2 1 0], 2)
%!error id=tocls:badInput tocls (data, [2 1 0], 50, -1)
%!error id=tocls:badInput tocls ([1 2 3], [2 1 0], 50)
%!error id=tocls:badInput
%! u = repmat ([1; 1; -1; -1], 500, 1);
%! tocls (iddata (filter (1, [1 -0.9], u), u, 0.1), [2 1 0], 50);

%!demo
%! Ts = 0.1; n = 5000;
%! u0 = chisqr (n, 1, 2); u0 = (u0 - mean (u0)) / std (u0);
%! M0 = idpoly (1, [1 -1], 1, 1, [1 2 1], "Ts", 0);
%! y0 = simc (M0, iddata ([], u0, Ts, "InterSample", "zoh"));
%! data = iddata (y0 + 0.1 * randn (n, 1), u0 + 0.3 * randn (n, 1), Ts);
%! M = tocls (data, [2 1 0], 50, 3)
