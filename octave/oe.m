## -*- texinfo -*-
## @deftypefn  {} {@var{M} =} oe (@var{data}, [@var{nb} @var{nf} @var{nk}])
## @deftypefnx {} {@var{M} =} oe (@dots{}, @var{name}, @var{value})
## @deftypefnx {} {@var{M} =} oe (@dots{}, @var{opt})
## @deftypefnx {} {[@var{M}, @var{info}] =} oe (@dots{})
## Discrete-time output-error model y(t) = B(q)/F(q) u(t - nk) + e(t) (as
## the System Identification Toolbox's @code{oe}): @var{nb} coefficients
## of B, @var{nf} of F (monic), @var{nk} samples of delay.  Minimises the
## simulation error by Levenberg-Marquardt with an exact Jacobian (1/F
## applied to u and to the simulated output), started from least-squares
## ARX with unstable roots reflected; every iterate has a stable F.
##
## Options (name-value, or an @code{oeOptions} set): @code{Focus}
## (@qcode{"simulation"} = @qcode{"prediction"} for OE, or a band [w1 w2]
## rad/s: y and u prefiltered by a 4th-order Butterworth band filter),
## @code{MaxIter} (@code{SearchOptions.MaxIterations}, default 100),
## @code{Tol} (default 1e-8).
##
## @var{M}: an @code{idpoly} (Ts of the data) with covariance s^2 (J'J)^-1
## (s^2 = e'e/(N - nb - nf)) and Report (Fit.FitPercent, LossFcn = MSE =
## e'e/N, FPE; Termination).  One input; frequency-domain data and
## @code{idfrd} give @code{oe:notSupported}.
##
## @strong{Example}
## @example
## u = sign (randn (500, 1));
## y = filter ([0 0.5], [1 -0.8], u) + 0.1 * randn (500, 1);
## M = oe (iddata (y, u, 1), [1 1 1])
## @end example
## @seealso{oeOptions, arx, tfest, tfcoe}
## @end deftypefn

function [M, info, varargout] = oe (varargin)
  contsid_nargchk ("oe", nargin, nargout, [2 Inf], 2);
  [M, info] = contsid_pem ("oe", varargin);
endfunction

%!shared u, x, N
%! N = 600; rand ("state", 1); u = sign (rand (N, 1) - 0.5);
%! x = filter ([0 0 0.5 0.3], [1 -1.5 0.7], u);

%!test  # noise-free: exact
%! M = oe (iddata (x, u, 1), [2 2 2]);
%! assert (M.F, [1 -1.5 0.7], 1e-10);
%! assert (M.B, [0 0 0.5 0.3], 1e-10);

%!test  # noisy: the loss equals a brute-force evaluation by filter and
%! # the optimum is a local minimum
%! randn ("state", 6);
%! y = x + 0.3 * randn (N, 1);
%! M = oe (iddata (y, u, 1), [2 2 2]);
%! loss = @(b, f) mean ((y - filter (b, f, u)) .^ 2);
%! assert (loss (M.B, M.F), M.Report.Fit.LossFcn, 1e-12);
%! for k = 2:3
%!   for s = [-1 1]
%!     f = M.F; f(k) += s * 1e-4;
%!     assert (loss (M.B, f) > M.Report.Fit.LossFcn);
%!   endfor
%! endfor
%! assert (numel (getpvec (M)), 6);    # B with its nk leading zeros

%!test  # Focus band: an oeOptions set and the name-value form agree
%! randn ("state", 7);
%! y = x + 0.3 * randn (N, 1);
%! M1 = oe (iddata (y, u, 1), [2 2 2], oeOptions ("Focus", [0 1]));
%! M2 = oe (iddata (y, u, 1), [2 2 2], "focus", [0 1]);
%! assert (M1.F, M2.F, 1e-12);

%!error id=oe:badInput oe (iddata (x, u, 1))
%!error id=oe:badInput oe (iddata (x, u, 1), [2 2])
%!error id=oe:badInput oe (iddata (x, u, 1), [0 2 1])
%!error id=oe:badInput oe (iddata (x, u, 1), [1.5 2 1])
%!error id=oe:badOption oe (iddata (x, u, 1), [2 2 2], "Lambda", 1)
%!error id=oe:badOption oe (iddata (x, u, 1), [2 2 2], "Focus", [2 1])
%!error id=oe:badOption oe (iddata (x, u, 1), [2 2 2], "Bogus", 1)
%!error id=oe:notSupported oe (iddata (x, [u u], 1), [2 2 2])
%!error id=oe:notSupported oe (idfrd (1, 1, 0), [2 2 2])
%!error id=oe:badInput oe (iddata (x, u, "SamplingInstants", cumsum (0.5 + rand (N, 1))), [2 2 2])

%!demo
%! u = sign (randn (500, 1));
%! y = filter ([0 0.5], [1 -0.8], u) + 0.1 * randn (500, 1);
%! M = oe (iddata (y, u, 1), [1 1 1]);
%! present (M)
