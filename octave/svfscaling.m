## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn  {} {@var{m} =} svfscaling (@var{data}, @var{nn}, "lambda_svf", @var{lam})
## @deftypefnx {} {@var{m} =} svfscaling (@dots{}, "svf", @var{form}, "order", @var{order})
## Diagonal of the scaling matrix M_s of the filtered SVF regression, from
## training data (thesis eq. 3.54): m_i = 1 / ||Phi_i||, Phi_i the i-th
## column of the regressor matrix of eq. (3.55).
##
## @var{data}: an iddata (or numeric y, u, Ts) training record; @var{nn} =
## [na nb nk] as in @code{rlssvf}; @code{lambda_svf} the cut-off (rad/s,
## required); @code{svf} @qcode{"normalised"} (default) or
## @qcode{"ordinary"}. @var{m} is ordered like rlssvf's THM
## [a1 .. a_na, b0 ..]; with @code{"order", "bf"} like rsrivc's
## [b0 .. , f1 .. f_nf] (then @var{nn} = [nb nf nk]).
##
## The recursive estimators take @var{m} as their @code{scaling} option
## (or the training record itself): they then propagate theta_s =
## M_s^-1 theta and P_s = M_s^-1 P M_s^-1 (eqs. 3.65, 3.66, 3.74, C.9),
## which gives the same estimates with a better conditioned P_s. The
## function fails (rlssvf:badInput-like id @code{svfscaling:badInput}) when a
## regressor is identically zero in the training data.
##
## @strong{Example}
## @example
## Ts = 1e-3; u = prbs (10, 2); N = numel (u);
## y = simc (struct ("B", [2e3 0], "F", [1 2e3 1e6]), u, Ts);
## m = svfscaling (iddata (y, u, Ts), [2 2 0], "lambda_svf", 3e3)
## @end example
## @seealso{rlssvf, rsrivc}
## @end deftypefn

function varargout = svfscaling (varargin)
  varargout = contsid_guard ("svfscaling", @svfscaling_body, nargout, varargin);
endfunction

function [m, varargout] = svfscaling_body (varargin)
  contsid_nargchk ("svfscaling", nargin, nargout, [0 Inf], 1);
  fname = "svfscaling";
  if (nargin < 2)
    error ("svfscaling:badInput", "svfscaling: expected data and nn");
  endif
  defaults = struct ("lambda_svf", [], "svf", "normalised", "order", "ab");
  [d, ~, opts] = contsid_recursive_args (fname, "a", defaults, varargin{:});
  if (! ischar (opts.order) || ! any (strcmp (opts.order, {"ab", "bf"})))
    error ("svfscaling:badOption", "svfscaling: order must be 'ab' or 'bf'");
  endif
  form = "a";
  if (strcmp (opts.order, "bf"))
    form = "f";
  endif
  [~, orders] = contsid_recursive_args (fname, form, defaults, varargin{:});
  opts.adm = "ff"; opts.adg = []; opts.th0 = []; opts.P0 = [];
  o = contsid_recursive_options (fname, opts, orders.np, d);
  o = contsid_ch3_options (fname, struct ("scaling", "self",
                                          "precision", "double",
                                          "antiwindup", 0,
                                          "antiwindup_lambda", 1),
                           orders, d, o);
  m = o.scaling;
  if (strcmp (opts.order, "bf"))
    na = orders.na;
    m = m([na+1:orders.np, 1:na]);
  endif
endfunction

%!shared data
%! Ts = 1e-3; u = prbs (10, 2); N = numel (u);
%! y = simc (struct ("B", [2e3 0], "F", [1 2e3 1e6]), u, Ts);
%! data = iddata (y, u, Ts, "InterSample", "zoh");

%!test  # eq. 3.54: one over the norms of the regressor columns
%! lam = 3e3;
%! m = svfscaling (data, [2 2 0], "lambda_svf", lam);
%! ## the columns through an independent filter: normalised SVF in Octave
%! ## (trapezoidal rule for y, exact ZOH for u, as the core)
%! y = get (data, "OutputData"); u = get (data, "InputData"); Ts = 1e-3;
%! F = [0 1; -lam^2 -2*lam]; G = [0; 1];
%! Ad = (eye (2) - Ts/2*F) \ (eye (2) + Ts/2*F);
%! Bd = (eye (2) - Ts/2*F) \ (G * Ts/2);
%! E = expm ([F G; 0 0 0] * Ts); Az = E(1:2, 1:2); Bz = E(1:2, 3);
%! zy = Bd * y(1); zu = [0; 0]; N = numel (y);
%! Zy = zeros (N, 2); Zu = zeros (N, 2); Zy(1, :) = zy.';
%! for k = 2:N
%!   zy = Ad * zy + Bd * (y(k-1) + y(k));  zu = Az * zu + Bz * u(k-1);
%!   Zy(k, :) = zy.';  Zu(k, :) = zu.';
%! endfor
%! Phi = lam^2 * [-Zy(:, 2), -Zy(:, 1), Zu(:, 2), Zu(:, 1)];
%! assert (m, 1 ./ sqrt (sum (Phi .^ 2)).', 1e-8 * max (m));

%!test  # the 'bf' order is rsrivc's
%! a = svfscaling (data, [2 2 0], "lambda_svf", 3e3);
%! b = svfscaling (data, [2 2 0], "lambda_svf", 3e3, "order", "bf");
%! assert (b, a([3 4 1 2]), 0);

%!error id=svfscaling:badInput svfscaling (data)
%!error id=svfscaling:badOption svfscaling (data, [2 2 0])
%!error id=svfscaling:badOption svfscaling (data, [2 2 0], "lambda_svf", 3, "order", "x")
%!error id=svfscaling:badInput svfscaling (iddata (zeros (100, 1), ones (100, 1), 0.1), [1 1 0], "lambda_svf", 3)

%!demo
%! ## The regressors of a fast band-pass filter span many decades.
%! Ts = 1e-3; u = prbs (10, 2); N = numel (u);
%! y = simc (struct ("B", [2e3 0], "F", [1 2e3 1e6]), u, Ts);
%! m = svfscaling (iddata (y, u, Ts), [2 2 0], "lambda_svf", 3e3)
