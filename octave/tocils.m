## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn  {} {@var{M} =} tocils (@var{data}, @var{nn}, @var{L})
## @deftypefnx {} {@var{M} =} tocils (@var{data}, @var{nn}, @var{L}, @var{maxiter}, @var{lambda}, @var{tol})
## @deftypefnx {} {[@var{M}, @var{nbIter}] =} tocils (@dots{}, @var{name}, @var{value})
## Third-order cumulant iterative least squares estimate of a
## continuous-time errors-in-variables model B(p)/F(p) (CONTSID's
## @code{tocils}; S. Thil, H. Garnier, M. Gilson, Automatica 44(3), 2008).
##
## Started by @code{tocls} (state-variable filter of cut-off
## @var{lambda}), it solves the same third-order cross-cumulant equations
## with the data filtered by the adaptive prefilter f_nf / F(p) of the
## current estimate, as SRIVC does (thesis eqs. 2.9-2.10), until the
## relative change of the parameters falls below @var{tol}.  The noises on
## the input and the output must have symmetric distributions and be
## independent of the noise-free input, which must be skewed (see
## @code{tocls}); they may be coloured and correlated with each other.
##
## Inputs as for @code{tocls}: @var{data} an @code{iddata} (one input, one
## output, regular sampling); @var{nn} = [nf nb nk] with nb the numerator
## @emph{degree}; @var{L} the number of cumulant lags; @var{maxiter}
## (default 20), @var{lambda} (the SVF cut-off of the start, default 3 rad/s)
## and @var{tol} (default 1e-4), also as name-value pairs
## @qcode{"MaxIter"}, @qcode{"lambda_svf"}, @qcode{"Tol"}, @qcode{"Lags"}.
## A run that stops at @var{maxiter} warns (@code{tocils:notConverged}).
##
## Outputs: @var{M} an @code{idpoly} (Ts = 0, no covariance; the levels
## removed before the fit in @code{M.Report.DataUsed}); @var{nbIter} the
## number of least-squares solutions computed (the start included).
##
## @strong{Example}
## @example
## Ts = 0.1; n = 5000;
## u0 = chisqr (n, 1, 2); u0 = (u0 - mean (u0)) / std (u0);
## M0 = idpoly (1, [1 -1], 1, 1, [1 2 1], "Ts", 0);
## y0 = simc (M0, iddata ([], u0, Ts, "InterSample", "zoh"));
## data = iddata (y0 + 0.1 * randn (n, 1), u0 + 0.3 * randn (n, 1), Ts);
## [M, nbIter] = tocils (data, [2 1 0], 50)
## @end example
## @seealso{tocls, srivc, chisqr}
## @end deftypefn

function varargout = tocils (varargin)
  varargout = contsid_guard ("tocils", @tocils_body, nargout, varargin);
endfunction

function [M, nbIter, varargout] = tocils_body (varargin)
  contsid_nargchk ("tocils", nargin, nargout, [0 Inf], 2);
  [M, nbIter] = contsid_eiv ("tocils", varargin);
endfunction

%!shared data0, Ts, n, u0, y0
%! Ts = 0.1; n = 5000;
%! randg ("state", 5); randn ("state", 6);
%! u0 = chisqr (n, 1, 2);
%! u0 = filter ([1 -0.2 0.3], 1, u0);
%! u0 = (u0 - mean (u0)) / std (u0);
%! y0 = simc (idpoly (1, [1 -1], 1, 1, [1 2 1], "Ts", 0),
%!            iddata ([], u0, Ts, "InterSample", "zoh"));
%! data0 = iddata (y0, u0, Ts, "InterSample", "zoh");

%!test
%! ## Noise-free: the true system.
%! [M, it] = tocils (data0, [2 1 0], 50, 50, 3, 1e-8);
%! assert (M.F, [1 2 1], 0.02);
%! assert (M.B, [1 -1], 0.02);
%! assert (it >= 2);

%!test
%! ## Levels: the means removed before the fit are the model's levels.
%! d = iddata (y0 + 7, u0 + 2, Ts, "InterSample", "zoh");
%! M = tocils (d, [2 1 0], 50);
%! assert (M.Report.DataUsed.InputOffset, mean (u0) + 2, 1e-12);
%! assert (M.Report.DataUsed.OutputOffset, mean (y0) + 7, 1e-12);
%! assert (M.F, [1 2 1], 0.02);

%!warning id=tocils:notConverged tocils (data0, [2 1 0], 50, 1, 3, 1e-12);
%!error id=tocils:badInput tocils (data0, [2 1 0], 50, 0)
%!error id=tocils:badInput tocils (data0, [2 1 0], 3000)
%!error id=tocils:badInput tocils (data0, [0 0 0], 50)

%!demo
%! Ts = 0.1; n = 5000;
%! u0 = chisqr (n, 1, 2); u0 = (u0 - mean (u0)) / std (u0);
%! M0 = idpoly (1, [1 -1], 1, 1, [1 2 1], "Ts", 0);
%! y0 = simc (M0, iddata ([], u0, Ts, "InterSample", "zoh"));
%! data = iddata (y0 + 0.1 * randn (n, 1), u0 + 0.3 * randn (n, 1), Ts);
%! [M, nbIter] = tocils (data, [2 1 0], 50)
