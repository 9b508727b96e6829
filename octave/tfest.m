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
## @end example
## @seealso{tfestOptions, tfcoe, oe, srivc}
## @end deftypefn

function [M, info, varargout] = tfest (varargin)
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
