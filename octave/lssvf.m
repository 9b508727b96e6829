## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn  {} {@var{M} =} lssvf (@var{data}, [@var{na} @var{nb} @var{nk}], @var{lambda})
## @deftypefnx {} {@var{M} =} lssvf (@var{data}, @var{nn}, "lambda_svf", @var{lambda}, @dots{})
## Least-squares state-variable filter estimate (LSSVF) of a
## continuous-time transfer function B(p)/A(p) from sampled data (thesis
## eq. 1.32).
##
## @var{data}: an iddata object or numeric y, u, Ts (see @code{rlssvf});
## @var{nn} = [na nb nk] as in @code{rlssvf}; @var{lambda}: the SVF cut-off
## (rad/s), a little above the system's bandwidth. Option @code{"svf"}:
## @qcode{"normalised"} (default) or @qcode{"ordinary"}.  Missing samples
## (NaN in y or u) are bridged as in @code{rlssvf}: the SVF runs over the
## present samples at their own instants; @code{"Missing", "error"}
## refuses them.
##
## Returns an @code{idctm} model (fields B, F, nk, covariance,
## noise_variance, ...), accepted by @code{simc}, @code{comparec},
## @code{residc}; @code{tf (M)} converts it to a control-package tf.
## LSSVF is biased when the output is noisy; see @code{ivsvf} and
## @code{srivc}. The regression is solved by a QR factorisation.
##
## @strong{Example}
## @example
## u = prbs (10, 8); Ts = 0.05;
## y = simc (idctm (4, [1 2.4 4]), u, Ts);
## M = lssvf (iddata (y, u, Ts, "InterSample", "zoh"), [2 1 0], 3)
## @end example
## @seealso{ivsvf, srivc, rlssvf, idctm}
## @end deftypefn

function varargout = lssvf (varargin)
  varargout = contsid_guard ("lssvf", @lssvf_body, nargout, varargin);
endfunction

function [M, varargout] = lssvf_body (varargin)
  contsid_nargchk ("lssvf", nargin, nargout, [0 Inf], 1);
  M = contsid_offline ("lssvf", varargin);
endfunction

%!shared u, Ts, x, data
%! u = prbs (10, 8); Ts = 0.01;
%! x = simc (idctm (4, [1 2.4 4]), u, Ts);
%! data = iddata (x, u, Ts, "InterSample", "zoh");

%!test  # noise-free: recovered up to the O(Ts^2) Tustin error on y
%! M = lssvf (data, [2 1 0], 3);
%! assert (M.F, [1 2.4 4], 1e-3);
%! assert (M.B, 4, 1e-3);
%! assert (M.method, "lssvf");
%! assert (size (M.covariance), [3 3]);

%!test  # 7.2-style name-value cut-off gives the same model
%! a = lssvf (data, [2 1 0], 3);
%! b = lssvf (data, [2 1 0], "lambda_svf", 3);
%! assert (a.theta, b.theta, 0);

%!error id=lssvf:badOption lssvf (data, [2 1 0])
%!error id=lssvf:badInput lssvf (data, [2 1 0], -3)
%!error id=lssvf:badInput lssvf (data, [2 5 0], 3)
%!error id=lssvf:badOption lssvf (data, [2 1 0], 3, "Tol", 1)
%!error id=lssvf:badInput lssvf (iddata (zeros (100, 1), zeros (100, 1), 0.1), [2 1 0], 3)
%!error <constant> lssvf (iddata (ones (100, 1), (1:100)', 0.1), [2 1 0], 3)
%!error <3 \(present\) samples> lssvf (iddata ([1; 2; 4], [1; 0; 1], 0.1), [2 1 0], 3)
%!error id=lssvf:badInput [a, b] = lssvf (iddata ((1:9)', ones (9, 1), 1), [2 1 0], 3)

%!demo
%! u = prbs (10, 8); Ts = 0.05; N = numel (u);
%! y = simc (idctm (4, [1 2.4 4]), u, Ts) + 0.2 * randn (N, 1);
%! M = lssvf (iddata (y, u, Ts), [2 1 0], 3)   # biased by the noise
