## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn  {} {@var{M} =} ivsvf (@var{data}, [@var{na} @var{nb} @var{nk}], @var{lambda})
## @deftypefnx {} {@var{M} =} ivsvf (@var{data}, @var{nn}, "lambda_svf", @var{lambda}, @dots{})
## Instrumental-variable state-variable filter estimate (IVSVF) of a
## continuous-time transfer function (thesis eqs. 2.4-2.7): LSSVF first,
## then IV with instruments from the auxiliary model of the LSSVF estimate
## (its unstable roots reflected if any), all filtered by the same SVF.
##
## Arguments and output as for @code{lssvf}. The IV equations are solved
## through a QR factorisation of the instrument matrix.
##
## @strong{Example}
## @example
## u = prbs (10, 8); Ts = 0.05; N = numel (u);
## y = simc (idctm (4, [1 2.4 4]), u, Ts) + 0.2 * randn (N, 1);
## M = ivsvf (iddata (y, u, Ts), [2 1 0], 3)
## @end example
## @seealso{lssvf, srivc, rivsvf}
## @end deftypefn

function varargout = ivsvf (varargin)
  varargout = contsid_guard ("ivsvf", @ivsvf_body, nargout, varargin);
endfunction

function [M, varargout] = ivsvf_body (varargin)
  contsid_nargchk ("ivsvf", nargin, nargout, [0 Inf], 1);
  M = contsid_offline ("ivsvf", varargin);
endfunction

%!test  # noise-free: recovered
%! u = prbs (10, 8); Ts = 0.01;
%! x = simc (idctm (4, [1 2.4 4]), u, Ts);
%! M = ivsvf (iddata (x, u, Ts), [2 1 0], 3);
%! assert (M.theta, [2.4 4 4], 1e-3);

%!test  # noisy: much closer to the truth than LSSVF
%! randn ("state", 2);
%! u = prbs (11, 8); Ts = 0.05; N = numel (u);
%! y = simc (idctm (4, [1 2.4 4]), u, Ts) + 0.5 * randn (N, 1);
%! ls = lssvf (iddata (y, u, Ts), [2 1 0], 3);
%! iv = ivsvf (iddata (y, u, Ts), [2 1 0], 3);
%! assert (norm (iv.theta - [2.4 4 4]) < norm (ls.theta - [2.4 4 4]) / 2);

%!error id=ivsvf:badOption ivsvf (iddata ((1:10)', ones (10, 1), 1), [2 1 0])
%!error id=ivsvf:badInput ivsvf (iddata ((1:10)', ones (10, 1), 1), [2 1 0], NaN)

%!demo
%! u = prbs (10, 8); Ts = 0.05; N = numel (u);
%! y = simc (idctm (4, [1 2.4 4]), u, Ts) + 0.2 * randn (N, 1);
%! M = ivsvf (iddata (y, u, Ts), [2 1 0], 3)
