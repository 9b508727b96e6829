## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn  {} {@var{sys} =} tffcoe (@var{data}, @var{np}, @var{nz})
## @deftypefnx {} {@var{sys} =} tffcoe (@var{data}, @var{np}, @var{nz}, @var{IODelay})
## @deftypefnx {} {@var{sys} =} tffcoe (@var{data}, @var{Mi})
## @deftypefnx {} {@var{sys} =} tffcoe (@dots{}, @var{name}, @var{value})
## Continuous-time transfer function with a time delay,
## G(s) = B(s)/A(s) e^(-s td) (@var{np} poles, @var{nz} zeros), by output
## error in the frequency domain: Levenberg-Marquardt minimisation of
## sum_k |Y_k - G(j w_k) U_k|^2 over [a b td] (core @file{freq_srivc.hpp}),
## started from the frequency-domain SRIVC estimate of @code{tffsrivc}
## (whose delay search it shares). The data, options and outputs are those
## of @code{tffsrivc}. SRIVC's fixed point is itself a stationary point of
## this loss (at convergence its instruments are the loss's Jacobian and
## its equation error the output error, so the IV equations are the
## normal equations), and the delay search minimises the loss
## concentrated on td: from @code{tffsrivc}'s estimate the iteration
## usually stops at once, and the two models agree to the tolerance. It
## moves when SRIVC stopped at MaxIter or at a model it had to
## stabilise.
##
## See @code{tffsrivc} for @var{data} (relay-feedback iddata, idfrd or
## frequency-domain iddata), the delay search, the options (@code{TdMin},
## @code{TdMax}, @code{NumTd}, @code{FixTd}, @code{MaxIter}, @code{Tol},
## @code{IntSamp}, ...) and @var{sys} (an @code{idtf} with IODelay and the
## covariance s^2 (J'J)^-1 of the output-error fit): both are one back-end.
## @seealso{tffsrivc, relay, tfsrivc, srivc}
## @end deftypefn

function varargout = tffcoe (varargin)
  varargout = contsid_guard ("tffcoe", @tffcoe_body, nargout, varargin);
endfunction

function [sys, varargout] = tffcoe_body (varargin)
  contsid_nargchk ("tffcoe", nargin, nargout, [2 Inf], 1);
  sys = contsid_freq ("tffcoe", varargin);
endfunction

%!shared G, w
%! w = logspace (-1, 1.5, 50);
%! s = 1i * w;
%! G = idfrd ((0.5 * s + 4) ./ (s.^2 + 1.2 * s + 4) .* exp (-0.37 * s), w, "Ts", 0);

%!test  # exact frequency response: the model and the delay exactly
%! ## (the output-error minimum is the SRIVC fixed point here)
%! M = tffcoe (G, 2, 1);
%! [num, den] = tfdata (M, "v");
%! assert (den, [1 1.2 4], 1e-8);
%! assert (num(end-1:end), [0.5 4], 1e-8);
%! assert (get (M, "IODelay"), 0.37, 1e-8);

%!test  # fixed delay
%! M = tffcoe (G, 2, 1, 0.37, "FixTd", "on");
%! [~, den] = tfdata (M, "v");
%! assert (den, [1 1.2 4], 1e-8);

%!test  # relay data: close to the plant (aliasing of the harmonics neglected)
%! d = relay (1, [1 2 1], 0.005, "IODelay", 0.5, "NumCycle", 10);
%! M = tffcoe (d, 2, 0);
%! [num, den] = tfdata (M, "v");
%! assert (den, [1 2 1], 0.05);
%! assert (get (M, "IODelay"), 0.5, 0.02);

%!test  # a coarse grid (NumTd 10, TdMax 2: 0.37 s between grid points
%! ## 0.22 and 0.44, the loss with a second minimum at 0.196 s in the same
%! ## grid step): both sides of the grid minimum are searched, exact delay
%! M = tffcoe (G, 2, 1, "NumTd", 10, "TdMax", 2);
%! assert (get (M, "IODelay"), 0.37, 1e-7);

%!test  # noisy frequency response: tffcoe = tffsrivc, because SRIVC's
%! ## fixed point is a stationary point of the output-error loss (its
%! ## instruments are the loss's Jacobian); an independent minimiser
%! ## (fminsearch on sum |Y - G U|^2 over [b f td]) started beside it
%! ## returns to it and finds no lower loss
%! randn ("state", 4);
%! s = 1i * w(:);
%! G0 = (0.5 * s + 4) ./ (s.^2 + 1.2 * s + 4) .* exp (-0.37 * s);
%! Gn = G0 + 0.05 * (randn (50, 1) + 1i * randn (50, 1)) / sqrt (2);
%! d = idfrd (Gn, w, "Ts", 0);
%! Mc = tffcoe (d, 2, 1);
%! Ms = tffsrivc (d, 2, 1);
%! p = getpvec (Mc);                          # [b1 b0 f1 f2 td]
%! assert (p, getpvec (Ms), 1e-7 * norm (p));
%! V = @(q) sum (abs (Gn - polyval (q(1:2), s) ./ polyval ([1; q(3:4)], s)
%!                     .* exp (-s * q(5))) .^ 2);
%! q = fminsearch (V, p .* (1 + 0.01 * [1; -1; 1; -1; 1]),
%!                 optimset ("TolX", 1e-12, "TolFun", 1e-14,
%!                           "MaxFunEvals", 2e4, "MaxIter", 2e4));
%! assert (V (q) >= V (p) * (1 - 1e-9));
%! assert (q, p, 1e-4 * norm (p));

## The delay search against an exhaustive scan of fixed delays (one copy
## for tffsrivc and tffcoe): tests/octave/test_freq_delay_scan.m.

%!error id=tffcoe:badInput tffcoe (G)
%!error id=tffcoe:badInput tffcoe (G, 2)
%!error id=tffcoe:badInput tffcoe (G, 2, 3)
%!error id=tffcoe:badInput tffcoe (G, 2, 1, -1)
%!error id=tffcoe:badInput tffcoe (G, 2, 1, "FixTd", "on")
%!error id=tffcoe:badOption tffcoe (G, 2, 1, "FixTd", "maybe")
%!error id=tffcoe:badOption tffcoe (G, 2, 1, "TdMax", -1)
%!error id=tffcoe:badOption tffcoe (G, 2, 1, "NumTd", 1)
%!error id=tffcoe:badOption tffcoe (G, 2, 1, "MaxIter", 0)
%!error id=tffcoe:badOption tffcoe (G, 2, 1, "bogus", 1)
%!error id=tffcoe:badInput tffcoe (idfrd (ones (1, 2), 1:2, "Ts", 0), 2, 1)
%!error id=tffcoe:badInput tffcoe (iddata (randn (50, 1), randn (50, 1), 1), 2, 1)
%!error id=tffcoe:badInput tffcoe (42, 2, 1)

%!demo
%! data = relay (1, [1 2 1], 0.01, "IODelay", 0.5, "SNR", 20);
%! M = tffcoe (data, 2, 0)
%! present (M)
