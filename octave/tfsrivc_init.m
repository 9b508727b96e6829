## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn  {} {@var{M} =} tfsrivc_init (@var{data}, @var{np}, @var{nz})
## @deftypefnx {} {@var{M} =} tfsrivc_init (@dots{}, @var{name}, @var{value}, @dots{})
## Initial continuous-time transfer function with delay for
## @code{tfsrivc}: SRIVC (thesis eqs. 2.8-2.13, on the refined-IV engine)
## at each delay of a grid, and the model of the smallest simulation loss.
##
## @var{data}: an @code{iddata} (one output, one input, regular or
## irregular). @var{np}, @var{nz}: orders (0 <= nz <= np). Options:
## @code{TdMin}, @code{TdMax} (the delay range, default 0 and, as in
## @code{tfsrivc}, from the input-output cross-correlation),
## @code{NumTd} (grid size, default 50 as CONTSID), @code{Lambda} (SVF
## cut-off of the start), @code{Integration} ('on': a pole at s = 0, as
## in @code{tfsrivc}).
##
## @var{M}: an @code{idtf} with IODelay the best grid delay, its SRIVC
## coefficients and covariance (delay fixed), and
## @code{Report.Termination.DelayGrid} / @code{.DelayGridLoss} (the loss
## at each grid delay, Inf where SRIVC failed). Pass it to
## @code{tfsrivc (data, M)} to refine the delay. The grid must be fine
## enough for a grid point to lie in the basin of the best delay: with
## zeros (nz > 0) a right-half-plane zero can imitate part of a delay, and
## the loss has local minima there.
## @seealso{tfsrivc, procsrivc}
## @end deftypefn

function varargout = tfsrivc_init (varargin)
  varargout = contsid_guard ("tfsrivc_init", @tfsrivc_init_body, nargout,
                             varargin);
endfunction

function [M, varargout] = tfsrivc_init_body (varargin)
  contsid_nargchk ("tfsrivc_init", nargin, nargout, [0 Inf], 1);
  M = contsid_tf_front ("tfsrivc_init", varargin);
endfunction

%!shared data, Ts
%! Ts = 0.05;
%! u = prbs (10, 4);
%! M0 = idtf ([0.5 4], [1 1.2 4], "IODelay", 0.4);
%! y = simc (M0, iddata ([], u, Ts, "InterSample", "zoh"));
%! data = iddata (y, u, Ts, "InterSample", "zoh");

%!test
%! ## The grid contains the true delay: the init model is exact there.
%! M = tfsrivc_init (data, 2, 1, "NumTd", 11, "TdMax", 1);
%! assert (M.IODelay, 0.4, 1e-12);
%! assert (getpvec (M), [0.5; 4; 1.2; 4; 0.4], 1e-6);   # [b f IODelay]
%! L = M.Report.Termination.DelayGridLoss;
%! assert (numel (L), 11);
%! [~, i] = min (L);
%! assert (M.Report.Termination.DelayGrid(i), M.IODelay);
%! assert (all (L(L != min (L)) > 1e3 * max (min (L), eps)));

%!test
%! ## Off-grid delay (grid spacing 0.95 samples): tfsrivc refines the
%! ## init model to the truth.
%! Mi = tfsrivc_init (data, 2, 1, "NumTd", 22, "TdMax", 1);
%! assert (abs (Mi.IODelay - 0.4) < 0.03);
%! M = tfsrivc (data, Mi);
%! assert (M.IODelay, 0.4, 1e-6);
%! assert (getpvec (M)(1:4), [0.5; 4; 1.2; 4], 1e-5);

%!error id=tfsrivc_init:badInput tfsrivc_init (data, 2)
%!error id=tfsrivc_init:badInput tfsrivc_init (data, 2, 1, 0.3)
%!error id=tfsrivc_init:badOption tfsrivc_init (data, 2, 1, "FixTd", "on")
%!error id=tfsrivc_init:badOption tfsrivc_init (data, 2, 1, "NumTd", 0)
%!error id=tfsrivc_init:badInput tfsrivc_init (data, idtf (1, [1 1]))

%!demo
%! Ts = 0.05; u = prbs (10, 4);
%! M0 = idtf ([0.5 4], [1 1.2 4], "IODelay", 0.4);
%! y = simc (M0, iddata ([], u, Ts, "InterSample", "zoh"));
%! data = iddata (y + 0.05 * randn (size (y)), u, Ts, "InterSample", "zoh");
%! model_init = tfsrivc_init (data, 2, 1, "NumTd", 20)
%! M = tfsrivc (data, model_init)
