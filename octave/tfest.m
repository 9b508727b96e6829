## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn  {} {@var{M} =} tfest (@var{data}, @var{np})
## @deftypefnx {} {@var{M} =} tfest (@var{data}, @var{np}, @var{nz})
## @deftypefnx {} {@var{M} =} tfest (@var{data}, @var{np}, @var{nz}, @var{iodelay})
## @deftypefnx {} {@var{M} =} tfest (@dots{}, @var{opt})
## @deftypefnx {} {[@var{M}, @var{info}] =} tfest (@dots{})
## Continuous-time transfer function with @var{np} poles and @var{nz}
## zeros (default @var{nz} = @var{np} - 1) estimated from time-domain data
## by minimising the simulation (output) error, as the System
## Identification Toolbox's @code{tfest}: Levenberg-Marquardt from an
## SRIVC start, exact ZOH/FOH simulation and Jacobian (the core of
## @code{tfcoe}).  @var{iodelay} (seconds) is a fixed delay.
##
## @var{opt} is a @code{tfestOptions} set (Focus @qcode{"simulation"},
## @qcode{"prediction"} (the same for an output-error model) or a band
## [w1 w2] rad/s: the data are prefiltered by a 4th-order Butterworth band
## filter; SearchOptions.MaxIterations, SearchOptions.Tolerance), or
## name-value pairs with those names.
##
## @var{M}: an @code{idtf} with covariance and Report (Fit.FitPercent,
## LossFcn, MSE, FPE; Termination).
##
## @strong{Several inputs.}  With nu inputs, @var{np}, @var{nz} and
## @var{iodelay} are scalars (the same for every input) or row vectors of
## nu entries, and the model is y = sum_j B_j(s)/F_j(s) u_j(t - td_j),
## each input with its own denominator (as the System Identification
## Toolbox's @code{tfest}): @var{M} has one numerator and denominator per
## input (1-by-nu cells of @code{tfdata}), getpvec (M) = [num_1 ..
## num_nu, den_1(2:end) .. den_nu(2:end), IODelay].  The start is SRIVC
## with one denominator group per input (the refined-IV engine updates the
## inputs in turn); the Jacobian is exact per input.  The same on
## frequency data: an @code{idfrd} with one output and nu inputs, or
## frequency-domain @code{iddata} with nu inputs.
##
## @strong{Frequency data.}  On an @code{idfrd} (Ts = 0) or on
## continuous-time frequency-domain @code{iddata} (@code{[Y U]}, Ts = 0)
## the same model (@var{iodelay} fixed) is fitted by frequency-domain
## output error, min sum_k |Y_k - G(j w_k) U_k|^2 (U = 1 for an
## @code{idfrd}), by the Levenberg-Marquardt iteration of the time-domain
## fit from the frequency-domain SRIVC estimate (as @code{oe} on frequency
## data, which documents it); Focus [w1 w2] keeps the frequencies in the
## band.
##
## @strong{Example}
## @example
## u = prbs (10, 8); Ts = 0.05; N = numel (u);
## y = simc (idctm (4, [1 2.4 4]), u, Ts) + 0.1 * randn (N, 1);
## M = tfest (iddata (y, u, Ts), 2, 0)
## ## two inputs: 2 poles and no zero for u, 1 pole for u2, delayed 0.2 s
## u2 = u(randperm (N));
## y2 = y + simc (idctm (2, [1 0.8]), [zeros(4, 1); u2(1:end-4)], Ts);
## M2 = tfest (iddata (y2, [u u2], Ts), [2 1], 0, [0 0.2])
## @end example
## @seealso{tfestOptions, tfcoe, oe, srivc}
## @end deftypefn

function varargout = tfest (varargin)
  varargout = contsid_guard ("tfest", @tfest_body, nargout, varargin);
endfunction

function [M, info, varargout] = tfest_body (varargin)
  contsid_nargchk ("tfest", nargin, nargout, [2 Inf], 2);
  args = varargin;
  if (numel (args) == 2 || (numel (args) >= 3 && ! isnumeric (args{3})))
    if (isnumeric (args{2}) && ! isempty (args{2}) && isvector (args{2}))
      args = [args(1:2), {max(args{2} - 1, 0)}, args(3:end)];
    endif
  endif
  [M, info] = contsid_pem ("tfest", args);
endfunction

%!shared u, Ts, x, N
%! u = prbs (10, 8); Ts = 0.05; N = numel (u);
%! x = simc (idctm ([1.5 4], [1 2.4 4]), u, Ts);

%!test  # noise-free: exact, nz defaults to np - 1
%! M = tfest (iddata (x, u, Ts), 2);
%! [num, den] = tfdata (M, "vector");
%! assert (den, [1 2.4 4], 1e-8);
%! assert (num(end-1:end), [1.5 4], 1e-8);

%!function y = zoh_sim (n, d, u, Ts)  # control's c2d (ZOH) and filter
%!  [b, a] = tfdata (c2d (tf (n, d), Ts, "zoh"), "vector");
%!  b = [zeros(1, numel (a) - numel (b)), b];   # powers of z -> of q^-1
%!  y = filter (b, a, u);
%!endfunction

%!test  # the loss at the optimum: a brute-force evaluation by control's
%! # c2d (ZOH) and filter gives the same MSE, and it is a local minimum
%! randn ("state", 4);
%! y = x + 0.2 * randn (N, 1);
%! M = tfest (iddata (y, u, Ts), 2, 1);
%! [num, den] = tfdata (M, "vector");
%! loss = @(n, d) mean ((y - zoh_sim (n, d, u, Ts)) .^ 2);
%! assert (loss (num, den), M.Report.Fit.MSE, 1e-9 * M.Report.Fit.MSE);
%! for k = [2 3]
%!   for s = [-1 1]
%!     d2 = den; d2(k) += s * 1e-3 * abs (d2(k));
%!     assert (loss (num, d2) > M.Report.Fit.MSE);
%!   endfor
%! endfor

%!test  # options set and name-value forms agree
%! randn ("state", 5);
%! y = x + 0.2 * randn (N, 1);
%! M1 = tfest (iddata (y, u, Ts), 2, 1, tfestOptions ("Focus", [0 20]));
%! M2 = tfest (iddata (y, u, Ts), 2, 1, "Focus", [0 20]);
%! assert (getpvec (M1), getpvec (M2), 1e-12);

%!test  # two inputs, noise-free ZOH data: exact, one numerator and
%! # denominator per input (np, nz per input; nz defaults to np - 1)
%! rand ("state", 2);
%! u2 = u(randperm (N));
%! x2 = x + zoh_sim (2, [1 0.8], u2, Ts);
%! M = tfest (iddata (x2, [u u2], Ts), [2 1], [1 0]);
%! [num, den] = tfdata (M);
%! assert (size (M), [1 2]);
%! assert (den{1}, [1 2.4 4], 1e-8);
%! assert (num{1}(end-1:end), [1.5 4], 1e-8);
%! assert (den{2}, [1 0.8], 1e-8);
%! assert (num{2}(end), 2, 1e-8);
%! M = tfest (iddata (x2, [u u2], Ts), [2 1]);
%! assert (getpvec (M), [1.5 4 2 2.4 4 0.8 0 0].', 1e-8);

%!test  # two inputs with a fixed delay each, noisy: the MSE equals a
%! # brute-force evaluation (control's c2d (ZOH) and filter per input,
%! # summed), and the estimate is a local minimum in every denominator
%! # coefficient
%! rand ("state", 2); randn ("state", 3);
%! u2 = u(randperm (N));
%! y = zoh_sim ([1.5 4], [1 2.4 4], [zeros(2, 1); u(1:end-2)], Ts) ...
%!     + zoh_sim (2, [1 0.8], [zeros(5, 1); u2(1:end-5)], Ts) ...
%!     + 0.2 * randn (N, 1);
%! M = tfest (iddata (y, [u u2], Ts), [2 1], [1 0], [2 5] * Ts);
%! assert (M.IODelay, [2 5] * Ts);
%! [num, den] = tfdata (M);
%! yh = @(d) zoh_sim (num{1}, d{1}, [zeros(2, 1); u(1:end-2)], Ts) ...
%!           + zoh_sim (num{2}, d{2}, [zeros(5, 1); u2(1:end-5)], Ts);
%! loss = @(d) mean ((y - yh (d)) .^ 2);
%! assert (loss (den), M.Report.Fit.MSE, 1e-9 * M.Report.Fit.MSE);
%! for j = 1:2
%!   for k = 2:numel (den{j})
%!     for s = [-1 1]
%!       d2 = den; d2{j}(k) += s * 1e-3 * abs (d2{j}(k));
%!       assert (loss (d2) > M.Report.Fit.MSE);
%!     endfor
%!   endfor
%! endfor
%! [p, sd] = getpvec (M);
%! assert (numel (p), 8);              # [num_1 num_2 den_1 den_2 IODelay]
%! assert (sd(end-1:end), [0; 0]);
%! assert (all (abs (p(1:6) - [1.5 4 2 2.4 4 0.8].') < 5 * sd(1:6)));

%!test  # idfrd, one output and two inputs with a delay each, noise-free:
%! # exact; the control package's freqresp reproduces each response
%! pkg load control
%! w = logspace (-1, 1.5, 60).';
%! G1 = polyval ([1.5 4], 1i * w) ./ polyval ([1 2.4 4], 1i * w) ...
%!      .* exp (-0.3i * w);
%! G2 = 2 ./ (1i * w + 0.8) .* exp (-0.1i * w);
%! R = zeros (1, 2, numel (w)); R(1, 1, :) = G1; R(1, 2, :) = G2;
%! M = tfest (idfrd (R, w, "Ts", 0), [2 1], [1 0], [0.3 0.1]);
%! [num, den] = tfdata (M);
%! assert (den{1}, [1 2.4 4], 1e-9);
%! assert (num{1}(end-1:end), [1.5 4], 1e-9);
%! assert (den{2}, [1 0.8], 1e-9);
%! assert (num{2}(end), 2, 1e-9);
%! H1 = squeeze (freqresp (tf (num{1}, den{1}), w)) .* exp (-0.3i * w);
%! H2 = squeeze (freqresp (tf (num{2}, den{2}), w)) .* exp (-0.1i * w);
%! assert ([H1(:); H2(:)], [G1; G2], 1e-9 * max (abs ([G1; G2])));

%!test  # two-input frequency-domain iddata, noisy: tfest and oe reach the
%! # same minimum, and its loss equals sum |Y - G_1 U_1 - G_2 U_2|^2 / K
%! # evaluated independently (polyval)
%! randn ("state", 8);
%! rand ("state", 5); ui = sign (rand (400, 2) - 0.5);  # independent inputs
%! U = fft (iddata ([], ui, 0.05, "InterSample", "bl"));
%! U.Ts = 0;
%! Y = sim (idpoly (1, {[1.5 4], 2}, 1, 1, {[1 2.4 4], [1 0.8]}, "Ts", 0), U);
%! Y.y = Y.y + 0.05 * (randn (size (Y.y)) + 1i * randn (size (Y.y)));
%! Mt = tfest ([Y U], [2 1], [1 0]);
%! Mo = oe ([Y U], [2 1 2 1]);
%! assert (getpvec (Mt)(1:6), getpvec (Mo), 1e-8);
%! [num, den] = tfdata (Mt);
%! wu = get (U, "Frequency"); Ud = get (U, "InputData");
%! G = @(j) polyval (num{j}, 1i * wu) ./ polyval (den{j}, 1i * wu);
%! E = Y.y - G (1) .* Ud(:, 1) - G (2) .* Ud(:, 2);
%! assert (mean (abs (E) .^ 2), Mt.Report.Fit.LossFcn, ...
%!         1e-10 * Mt.Report.Fit.LossFcn);

%!error id=tfest:dimensionMismatch tfest (iddata (x, [u u], Ts), [2 2 2], 1)
%!error id=tfest:dimensionMismatch tfest (iddata (x, [u u], Ts), 2, [1 1 1])
%!error id=tfest:dimensionMismatch tfest (iddata (x, [u u], Ts), 2, 1, [0 0 0])
%!error id=tfest:badInput tfest (iddata (x, [u u], Ts), [2 -1], 1)
%!error id=tfest:badInput tfest (iddata (x, [u u], Ts), [2 1], [1 2])
%!error id=tfest:badInput tfest (iddata (x, [u u], Ts), 2, 1, [0 -1])
%!error id=tfest:dimensionMismatch
%! tfest (idfrd (zeros (1, 2, 3), [1 2 3], 0), [2 2 2], 1)
%!error id=tfest:badInput tfest (iddata (x, u, Ts))
%!error id=tfest:badInput tfest (iddata (x, u, Ts), 0, 0)
%!error id=tfest:badInput tfest (iddata (x, u, Ts), 2, 1, -1)
%!error id=tfest:badOption tfest (iddata (x, u, Ts), 2, 1, "Lambda", 2)
%!error id=tfest:badOption tfest (iddata (x, u, Ts), 2, 1, "Focus", "bogus")
%!error id=tfest:badOption tfest (iddata (x, u, Ts), 2, 1, struct ("a", 1))
%!error id=tfest:badInput tfest (idfrd (1, 1, 0), 2, 1)
%!error id=tfest:badInput tfest (idfrd ([1; 2; 3], [1; 2; 3], 0), 2, 3)
%!error id=tfest:badOption tfest (idfrd ([1; 2; 3], [1; 2; 3], 0), 1, 0, "Focus", [5 6])

%!test  # idfrd with a fixed delay, noise-free: exact; the control
%! # package's freqresp of the returned model reproduces the data
%! pkg load control
%! w = logspace (-1, 1.5, 60).';
%! G = polyval ([1.5 4], 1i * w) ./ polyval ([1 2.4 4], 1i * w) ...
%!     .* exp (-0.3i * w);
%! M = tfest (idfrd (G, w, "Ts", 0), 2, 1, 0.3);
%! [num, den] = tfdata (M, "vector");
%! assert (den, [1 2.4 4], 1e-9);
%! assert (num(end-1:end), [1.5 4], 1e-9);
%! assert (M.IODelay, 0.3);
%! H = squeeze (freqresp (tf (num, den), w)) .* exp (-0.3i * w);
%! assert (H(:), G, 1e-9 * max (abs (G)));
%! assert (getpvec (M)(end), 0.3);     # [b1 b0 f1 f2 IODelay]

%!test  # frequency-domain iddata: tfest and oe reach the same minimum, and
%! # the tfestOptions Focus form equals the fit on the band's frequencies
%! randn ("state", 8);
%! ui = idinput (400, "sine", [0 0.5]);
%! U = fft (iddata ([], ui, 0.05, "InterSample", "bl"));
%! U.Ts = 0;
%! Y = sim (idpoly (1, [1.5 4], 1, 1, [1 2.4 4], "Ts", 0), U);
%! Y.y = Y.y + 0.05 * (randn (size (Y.y)) + 1i * randn (size (Y.y)));
%! Mt = tfest ([Y U], 2, 1);
%! Mo = oe ([Y U], [2 2]);
%! assert (getpvec (Mt)(1:4), getpvec (Mo), 1e-8);
%! M1 = tfest ([Y U], 2, 1, tfestOptions ("Focus", [0 10]));
%! M2 = tfest ([Y U], 2, 1, "Focus", [0 10]);
%! assert (getpvec (M1), getpvec (M2), 1e-12);

%!demo
%! u = prbs (10, 8); Ts = 0.05; N = numel (u);
%! y = simc (idctm (4, [1 2.4 4]), u, Ts) + 0.1 * randn (N, 1);
%! M = tfest (iddata (y, u, Ts), 2, 0, tfestOptions ("Focus", [0 10]))

%!demo
%! ## two inputs, each with its own denominator and delay
%! u = prbs (10, 8); Ts = 0.05; N = numel (u); u2 = u(randperm (N));
%! y = simc (idctm (4, [1 2.4 4]), u, Ts) ...
%!     + simc (idctm (2, [1 0.8]), [zeros(4, 1); u2(1:end-4)], Ts);
%! M = tfest (iddata (y + 0.1 * randn (N, 1), [u u2], Ts), [2 1], 0, [0 0.2])
%! [num, den] = tfdata (M)
