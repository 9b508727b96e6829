## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

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
## e'e/N, FPE; Termination).
##
## @strong{Several inputs.}  With nu inputs, @var{nb}, @var{nf} and
## @var{nk} are row vectors of nu entries each (@code{[nb nf nk]} has
## 3 nu entries) and the model is y(t) = sum_j B_j(q)/F_j(q) u_j(t -
## nk_j) + e(t), each input with its own F_j (the System Identification
## Toolbox's multi-input OE structure); @code{M.B} and @code{M.F} are
## 1-by-nu cells, getpvec (M) = [B_1 .. B_nu (with their leading zeros),
## F_1(2:end) .. F_nu(2:end)].  The Jacobian is exact per input (1/F_j
## applied to u_j and to that input's simulated output x_j); the start
## fits each input's ARX model to y minus the other inputs' simulated
## outputs (a few backfitting sweeps).  On frequency data the orders are
## @code{[nb nf]} with nu entries each, for an @code{idfrd} with one
## output and nu inputs (its responses fitted together, the loss the sum
## over the inputs) or frequency-domain @code{iddata} with nu inputs
## (Y = sum_j B_j/F_j U_j); the SRIVC start then updates the inputs in
## turn, each fitted to Y minus the others' model outputs.
##
## @strong{Frequency data.}  On an @code{idfrd} (Ts = 0) or on
## continuous-time frequency-domain @code{iddata} (@code{datafreq = [Y U]}
## with @code{Y.Ts = U.Ts = 0}), @var{nn} = [@var{nb} @var{nf}] (or
## [@var{nb} @var{nf} 0]) gives the continuous-time model
## y = B(s)/F(s) u, B with @var{nb} coefficients, F monic of degree
## @var{nf}, fitted by frequency-domain output error: the weighted
## nonlinear least squares min sum_k |Y_k - B/F(j w_k) U_k|^2 (U = 1 for
## an @code{idfrd}; the output-error criterion of thesis eq. 1.16 with
## H = 1, by Parseval) by the Levenberg-Marquardt iteration of the
## time-domain fit (core @file{output_error.hpp}), started from SRIVC in
## the frequency domain (@code{srivc} on the same data, core
## @file{freq_srivc.hpp}; Pintelon and Schoukens, System Identification:
## A Frequency Domain Approach, 2012, ch. 9).  Focus [w1 w2] keeps the
## frequencies in the band.  Covariance s^2 (J'J)^-1 with J the Jacobian
## of the stacked real and imaginary parts and s^2 = sum |E|^2 / (2K - np);
## Report.Fit.LossFcn = sum |E|^2 / K.
##
## @strong{Example}
## @example
## u = sign (randn (500, 1));
## y = filter ([0 0.5], [1 -0.8], u) + 0.1 * randn (500, 1);
## M = oe (iddata (y, u, 1), [1 1 1])
## ## two inputs, each with its own denominator: nb = [1 2], nf = [1 1],
## ## nk = [1 2]
## u2 = randn (500, 1);
## y2 = y + filter ([0 0 1 0.5], [1 -0.3], u2);
## M2 = oe (iddata (y2, [u u2], 1), [1 2 1 1 1 2]);
## M2.F@{2@}                    # about [1 -0.3]
## @end example
## @seealso{oeOptions, arx, tfest, tfcoe}
## @end deftypefn

function varargout = oe (varargin)
  varargout = contsid_guard ("oe", @oe_body, nargout, varargin);
endfunction

function [M, info, varargout] = oe_body (varargin)
  contsid_nargchk ("oe", nargin, nargout, [2 Inf], 2);
  [M, info] = contsid_pem ("oe", varargin);
endfunction

%!shared u, x, N, w, B, F, G
%! N = 600; rand ("state", 1); u = sign (rand (N, 1) - 0.5);
%! x = filter ([0 0 0.5 0.3], [1 -1.5 0.7], u);
%! B = [2 5]; F = [1 0.8 4 2];               # resonance near 2 rad/s
%! w = logspace (-1, 1.3, 80).';
%! G = polyval (B, 1i * w) ./ polyval (F, 1i * w);

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

%!test  # idfrd, noise-free: exact; the control package's freqresp of the
%! # returned model reproduces the data
%! pkg load control
%! M = oe (idfrd (G, w, "Ts", 0), [2 3]);
%! assert (M.Ts, 0);
%! assert (M.B, B, 1e-9 * norm (B));
%! assert (M.F, F, 1e-9 * norm (F));
%! H = squeeze (freqresp (tf (M.B, M.F), w));
%! assert (H(:), G, 1e-9 * max (abs (G)));

%!test  # noisy idfrd: the loss is sum |G - B/F|^2 / K evaluated
%! # independently (polyval), and the estimate is a local minimum of it
%! randn ("state", 3);
%! Gn = G + 0.05 * (randn (size (G)) + 1i * randn (size (G)));
%! M = oe (idfrd (Gn, w, "Ts", 0), [2 3]);
%! H = @(b, f) polyval (b, 1i * w) ./ polyval (f, 1i * w);
%! loss = @(b, f) mean (abs (Gn - H (b, f)) .^ 2);
%! assert (loss (M.B, M.F), M.Report.Fit.LossFcn, 1e-10 * M.Report.Fit.LossFcn);
%! for k = 2:4
%!   for s = [-1 1]
%!     f = M.F; f(k) += s * 1e-4 * abs (f(k));
%!     assert (loss (M.B, f) > M.Report.Fit.LossFcn);
%!   endfor
%! endfor
%! [p, sd] = getpvec (M);
%! assert (numel (p), 5);
%! assert (all (abs (p - [B F(2:end)].') < 5 * sd));

%!test  # Focus [0 wc] is the fit on the frequencies below wc; the
%! # oeOptions form and the name-value form agree
%! randn ("state", 4);
%! Gn = G + 0.05 * (randn (size (G)) + 1i * randn (size (G)));
%! M1 = oe (idfrd (Gn, w, "Ts", 0), [2 3], "Focus", [0 5]);
%! M2 = oe (idfrd (Gn, w, "Ts", 0), [2 3], oeOptions ("Focus", [0 5]));
%! k = w <= 5;
%! M3 = oe (idfrd (Gn(k), w(k), "Ts", 0), [2 3]);
%! assert (getpvec (M1), getpvec (M2), 1e-12);
%! assert (getpvec (M1), getpvec (M3), 1e-12);
%! assert (M1.Report.DataUsed.Length, sum (k));

%!test  # frequency-domain iddata (tutorial3's construction), noise-free
%! ui = idinput (400, "sine", [0 0.5]);
%! U = fft (iddata ([], ui, 0.05, "InterSample", "bl"));
%! U.Ts = 0;
%! Y = sim (idpoly (1, B, 1, 1, F, "Ts", 0), U);
%! M = oe ([Y U], [2 3]);
%! assert (getpvec (M), [B F(2:end)].', 1e-8);

%!test  # two inputs, noise-free: exact, each input with its own F; B
%! # and F are cells (as the SITB's multi-input idpoly)
%! u2 = filter (1, [1 -0.5], sign (rand (N, 1) - 0.5));
%! x2 = x + filter ([0 0 1.2 -0.4], [1 -0.6], u2);
%! M = oe (iddata (x2, [u u2], 1), [2 2 2 1 2 2]);
%! assert (iscell (M.B) && iscell (M.F));
%! assert (M.F{1}, [1 -1.5 0.7], 1e-8);
%! assert (M.B{1}, [0 0 0.5 0.3], 1e-8);
%! assert (M.F{2}, [1 -0.6], 1e-8);
%! assert (M.B{2}, [0 0 1.2 -0.4], 1e-8);

%!test  # two inputs, noisy: the loss equals an independent evaluation (each
%! # input filtered by its B_j/F_j, summed), the optimum is a local minimum
%! # in every F coefficient, and the covariance is in getpvec's layout
%! randn ("state", 9); rand ("state", 10);
%! u2 = filter (1, [1 -0.5], sign (rand (N, 1) - 0.5));
%! y = x + filter ([0 0 1.2 -0.4], [1 -0.6], u2) + 0.3 * randn (N, 1);
%! M = oe (iddata (y, [u u2], 1), [2 2 2 1 2 2]);
%! yh = @(B, F) filter (B{1}, F{1}, u) + filter (B{2}, F{2}, u2);
%! loss = @(B, F) mean ((y - yh (B, F)) .^ 2);
%! assert (loss (M.B, M.F), M.Report.Fit.LossFcn, 1e-12);
%! for j = 1:2
%!   for k = 2:numel (M.F{j})
%!     for s = [-1 1]
%!       Fp = M.F; Fp{j}(k) += s * 1e-4;
%!       assert (loss (M.B, Fp) > M.Report.Fit.LossFcn);
%!     endfor
%!   endfor
%! endfor
%! [p, sd] = getpvec (M);
%! assert (numel (p), 4 + 4 + 2 + 1);  # B_1, B_2 with their zeros, F_1, F_2
%! assert (sd([1 2 5 6]), zeros (4, 1));         # the nk leading zeros
%! assert (all (sd([3 4 7 8 9 10 11]) > 0));
%! assert (all (abs (p - [0 0 0.5 0.3 0 0 1.2 -0.4 -1.5 0.7 -0.6].') ...
%!              < 5 * sd + 1e-12));

%!test  # idfrd with one output and two inputs, noise-free: exact; the
%! # control package's freqresp of each returned B_j/F_j reproduces G_j
%! pkg load control
%! B2 = [1 3]; F2 = [1 2 6];
%! G2 = polyval (B2, 1i * w) ./ polyval (F2, 1i * w);
%! R = zeros (1, 2, numel (w)); R(1, 1, :) = G; R(1, 2, :) = G2;
%! M = oe (idfrd (R, w, "Ts", 0), [2 2 3 2]);
%! assert (M.B{1}, B, 1e-9 * norm (B));
%! assert (M.F{1}, F, 1e-9 * norm (F));
%! assert (M.B{2}, B2, 1e-9 * norm (B2));
%! assert (M.F{2}, F2, 1e-9 * norm (F2));
%! H1 = squeeze (freqresp (tf (M.B{1}, M.F{1}), w));
%! H2 = squeeze (freqresp (tf (M.B{2}, M.F{2}), w));
%! assert (H1(:), G, 1e-9 * max (abs (G)));
%! assert (H2(:), G2, 1e-9 * max (abs (G2)));

%!test  # two-input frequency-domain iddata, noise-free: exact (Y formed
%! # independently as G_1 U_1 + G_2 U_2 by polyval)
%! rand ("state", 5); ui = sign (rand (400, 2) - 0.5);  # independent inputs
%! U = fft (iddata ([], ui, 0.05, "InterSample", "bl"));
%! U.Ts = 0;
%! wu = get (U, "Frequency"); Ud = get (U, "InputData");
%! Yd = polyval (B, 1i * wu) ./ polyval (F, 1i * wu) .* Ud(:, 1) ...
%!      + 3 ./ (1i * wu + 0.8) .* Ud(:, 2);
%! Y = sim (idpoly (1, {B, 3}, 1, 1, {F, [1 0.8]}, "Ts", 0), U);
%! Y.y = Yd;
%! M = oe ([Y U], [2 1 3 1]);
%! assert (getpvec (M), [B 3 F(2:end) 0.8].', 1e-8);

%!error id=oe:dimensionMismatch oe (iddata (x, [u u], 1), [2 2 2])
%!error id=oe:badInput oe (iddata (x, [u u], 1), [2 2 2 2 1])
%!error id=oe:badInput oe (iddata (x, [u u], 1), [2 2 -1 2 1 1])
%!error id=oe:badInput oe (iddata (x, [u u], 1), [2 0 2 2 1 1])
%!error id=oe:badInput oe (idfrd (zeros (1, 2, 3), [1 2 3], 0), [2 2])
%!error id=oe:badInput oe (idfrd (G, w, "Ts", 0), 2)
%!error id=oe:badInput oe (idfrd (G, w, "Ts", 0), [2 0])
%!error id=oe:notSupported oe (idfrd (G, w, "Ts", 0), [2 3 1])
%!error id=oe:badOption oe (idfrd (G, w, "Ts", 0), [2 3], "Focus", [50 60])
%!error id=oe:badOption oe (idfrd (G, w, "Ts", 0), [2 3], "Lambda", 2)
%!error id=oe:badInput oe (iddata (x, u, 1))
%!error id=oe:badInput oe (iddata (x, u, 1), [2 2])
%!error id=oe:badInput oe (iddata (x, u, 1), [0 2 1])
%!error id=oe:badInput oe (iddata (x, u, 1), [1.5 2 1])
%!error id=oe:badOption oe (iddata (x, u, 1), [2 2 2], "Lambda", 1)
%!error id=oe:badOption oe (iddata (x, u, 1), [2 2 2], "Focus", [2 1])
%!error id=oe:badOption oe (iddata (x, u, 1), [2 2 2], "Bogus", 1)
%!error id=oe:notSupported oe (idfrd (1, 1, 0), [2 2 2])
%!error id=oe:badInput oe (iddata (x, u, "SamplingInstants", cumsum (0.5 + rand (N, 1))), [2 2 2])

%!demo
%! ## frequency-response data (advantages53): oe with and without Focus
%! w = logspace (-1, 2, 250).';
%! G = freqs ([-6400 1600], [1 5 408 416 1600], w);
%! G = G + 1.5 * (randn (size (G)) + 1i * randn (size (G)));
%! Moe = oe (idfrd (G, w, "Ts", 0), [2 4])
%! Moefocus = oe (idfrd (G, w, "Ts", 0), [2 4], "Focus", [0 25]);

%!demo
%! u = sign (randn (500, 1));
%! y = filter ([0 0.5], [1 -0.8], u) + 0.1 * randn (500, 1);
%! M = oe (iddata (y, u, 1), [1 1 1]);
%! present (M)

%!demo
%! ## two inputs, each with its own denominator: [nb nf nk] with two
%! ## entries each; M.B and M.F are cells
%! N = 1000; u1 = sign (randn (N, 1)); u2 = randn (N, 1);
%! y = filter ([0 0.5], [1 -0.8], u1) + filter ([0 0 1 0.5], [1 -0.3], u2);
%! M = oe (iddata (y + 0.1 * randn (N, 1), [u1 u2], 1), [1 2 1 1 1 2])
%! celldisp (M.F)
