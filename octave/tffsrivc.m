## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn  {} {@var{sys} =} tffsrivc (@var{data}, @var{np}, @var{nz})
## @deftypefnx {} {@var{sys} =} tffsrivc (@var{data}, @var{np}, @var{nz}, @var{IODelay})
## @deftypefnx {} {@var{sys} =} tffsrivc (@var{data}, @var{Mi})
## @deftypefnx {} {@var{sys} =} tffsrivc (@dots{}, @var{name}, @var{value})
## Continuous-time transfer function with a time delay,
## G(s) = B(s)/A(s) e^(-s td) (@var{np} poles, @var{nz} zeros), by SRIVC
## in the frequency domain (core @file{freq_srivc.hpp}): the prefilter
## 1/A(jw) and the auxiliary model B/A of thesis eqs. 2.8-2.13 applied to
## frequency data, iterated to a fixed point.
##
## @var{data}: regular time-domain @code{iddata} of a relay-feedback test
## (see @code{relay}; its whole limit cycles are transformed: the DFT at
## the harmonics of the cycle with at least 1 % of the largest input
## harmonic, below a quarter of the sampling frequency, the input corrected
## for its zero-order hold and, with @code{IntSamp} @qcode{"on"} (default),
## the output for integrated sampling; the aliases of higher harmonics are
## neglected), an @code{idfrd} (Ts = 0) or frequency-domain @code{iddata}
## [Y U] (Ts = 0).
##
## The delay: without @var{IODelay}, the SRIVC loss is minimised over
## td: a grid of @code{NumTd} (50) values in [@code{TdMin}, @code{TdMax}]
## (0 and half the limit-cycle period, or pi over the median frequency)
## refined by golden section (separable estimation, Chen et al., Automatica
## 2018); with @var{IODelay}, from there; with @code{FixTd} @qcode{"on"},
## td = @var{IODelay} is kept. @var{Mi}: an @code{idtf} whose orders,
## coefficients (start) and IODelay are used. Other options: @code{MaxIter}
## (50), @code{Tol} or @code{TolPar} (1e-8); @code{TolFun},
## @code{StepMax}, @code{StepReduction} and @code{Lambda} are accepted
## and not used (golden section replaces CONTSID's step rule; the start
## is least squares with the prefilter 1/(s + sigma)^np, sigma the centre
## of the band).
##
## @var{sys}: an @code{idtf} with IODelay, covariance of [b; a]
## (s^2 (J'J)^-1, J the Jacobian of the model's frequency response),
## @code{Report.Fit} (on the frequency data), @code{Report.Parameters.IODelaySD},
## @code{Report.DataUsed.Harmonics}.
## @seealso{tffcoe, relay, tfsrivc, srivc}
## @end deftypefn

function varargout = tffsrivc (varargin)
  varargout = contsid_guard ("tffsrivc", @tffsrivc_body, nargout, varargin);
endfunction

function [sys, varargout] = tffsrivc_body (varargin)
  contsid_nargchk ("tffsrivc", nargin, nargout, [2 Inf], 1);
  sys = contsid_freq ("tffsrivc", varargin);
endfunction

%!shared G, w
%! w = logspace (-1, 1.5, 50);
%! s = 1i * w;
%! G = idfrd ((0.5 * s + 4) ./ (s.^2 + 1.2 * s + 4) .* exp (-0.37 * s), w, "Ts", 0);

%!test  # exact frequency response: the model and the delay exactly
%! M = tffsrivc (G, 2, 1);
%! [num, den] = tfdata (M, "v");
%! assert (den, [1 1.2 4], 1e-8);
%! assert (num(end-1:end), [0.5 4], 1e-8);
%! assert (get (M, "IODelay"), 0.37, 1e-8);

%!test  # fixed delay
%! M = tffsrivc (G, 2, 1, 0.37, "FixTd", "on");
%! [~, den] = tfdata (M, "v");
%! assert (den, [1 1.2 4], 1e-8);

%!test  # relay data: close to the plant (aliasing of the harmonics neglected)
%! d = relay (1, [1 2 1], 0.005, "IODelay", 0.5, "NumCycle", 10);
%! M = tffsrivc (d, 2, 0);
%! [num, den] = tfdata (M, "v");
%! assert (den, [1 2 1], 0.05);
%! assert (get (M, "IODelay"), 0.5, 0.02);

%!test  # a coarse grid (NumTd 10, TdMax 2: 0.37 s between grid points
%! ## 0.22 and 0.44, the loss with a second minimum at 0.196 s in the same
%! ## grid step): both sides of the grid minimum are searched, exact delay
%! M = tffsrivc (G, 2, 1, "NumTd", 10, "TdMax", 2);
%! assert (get (M, "IODelay"), 0.37, 1e-7);

## The delay search against an exhaustive scan of fixed delays (one copy
## for tffsrivc and tffcoe): tests/octave/test_freq_delay_scan.m.

%!error id=tffsrivc:badInput tffsrivc (G)
%!error id=tffsrivc:badInput tffsrivc (G, 2)
%!error id=tffsrivc:badInput tffsrivc (G, 2, 3)
%!error id=tffsrivc:badInput tffsrivc (G, 2, 1, -1)
%!error id=tffsrivc:badInput tffsrivc (G, 2, 1, "FixTd", "on")
%!error id=tffsrivc:badOption tffsrivc (G, 2, 1, "FixTd", "maybe")
%!error id=tffsrivc:badOption tffsrivc (G, 2, 1, "TdMax", -1)
%!error id=tffsrivc:badOption tffsrivc (G, 2, 1, "NumTd", 1)
%!error id=tffsrivc:badOption tffsrivc (G, 2, 1, "MaxIter", 0)
%!error id=tffsrivc:badOption tffsrivc (G, 2, 1, "bogus", 1)
%!error id=tffsrivc:badInput tffsrivc (idfrd (ones (1, 2), 1:2, "Ts", 0), 2, 1)
%!error id=tffsrivc:badInput tffsrivc (iddata (randn (50, 1), randn (50, 1), 1), 2, 1)
%!error id=tffsrivc:badInput tffsrivc (42, 2, 1)

%!demo
%! data = relay (1, [1 2 1], 0.01, "IODelay", 0.5, "SNR", 20);
%! M = tffsrivc (data, 2, 0)
%! present (M)
