## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn  {} {@var{thm} =} rarx (@var{z}, [@var{na} @var{nb} @var{nk}], @var{adm}, @var{adg})
## @deftypefnx {} {[@var{thm}, @var{yhat}, @var{P}] =} rarx (@var{z}, @var{nn}, @var{adm}, @var{adg}, @var{th0}, @var{P0})
## Recursive estimate of a discrete-time ARX model, in the System
## Identification Toolbox form.
##
## The model (thesis eq. 1.4) is
## @example
## y(k) + a1 y(k-1) + .. + a_na y(k-na)
##      = b1 u(k-nk) + .. + b_nb u(k-nk-nb+1) + e(k)
## @end example
## estimated sample by sample with the regressor of eq. 1.6.
##
## @var{z} is an @code{iddata} object with one input, or a numeric matrix
## [y u].  @var{adm} is the adaptation mechanism:
## @table @code
## @item "ff"
## forgetting factor (RLS-FF, eq. 1.41), @var{adg} = lambda in (0, 1];
## @item "kf"
## Kalman filter for random-walk parameters (eq. 1.45), @var{adg} = the
## normalised covariance Qn = R1/R2 of the parameter changes (a scalar
## means Qn*I, a vector its diagonal).
## @end table
## The gradient methods @qcode{"ng"} and @qcode{"ug"} of the SITB are not
## supported (error @code{rarx:notSupported}).  @var{th0} (default 0) and
## @var{P0} (default 1e4*I) start the recursion.
##
## @var{thm} is N-by-(na+nb), row k = [a1 .. a_na b1 .. b_nb] after sample
## k; @var{yhat} the one-step predictions phi(k)' theta(k-1); @var{P} the
## final covariance matrix (normalised by the noise variance).  For the
## continuous-time model of the same estimate (the indirect route of
## the thesis, sec. 1.3.4), see @code{rarxc}.
##
## @strong{Example}
## @example
## u = prbs (8, 5); N = numel (u);
## y = filter ([0 0.3 0.2], [1 -1.5 0.7], u) + 0.01 * randn (N, 1);
## thm = rarx ([y u], [2 2 1], "ff", 0.99);
## thm(end, :)     # close to [-1.5 0.7 0.3 0.2]
## @end example
## @seealso{rarxc, rlssvf}
## @end deftypefn

function varargout = rarx (varargin)
  varargout = contsid_guard ("rarx", @rarx_body, nargout, varargin);
endfunction

function [thm, yhat, P, varargout] = rarx_body (z, nn, adm, adg, th0, P0,
                                                varargin)
  contsid_nargchk ("rarx", nargin, nargout, [0 6], 3);
  if (nargin < 4)
    error ("rarx:badInput",
           "rarx: needs at least (z, nn, adm, adg), got %d arguments",
           nargin);
  endif
  if (isnumeric (z))
    if (! (isreal (z) && ndims (z) == 2 && columns (z) == 2 && rows (z) > 0))
      error ("rarx:badInput",
             "rarx: numeric data z must be an N-by-2 real matrix [y u]");
    endif
    d = contsid_getdata ("rarx", z(:, 1), z(:, 2), 1);
  else
    d = contsid_getdata ("rarx", z);
  endif
  contsid_check_output ("rarx", d.y);
  if (! (ischar (adm) && rows (adm) == 1))
    error ("rarx:badOption", "rarx: adm must be 'ff' or 'kf'");
  endif
  if (! (isnumeric (adg) && isreal (adg) && all (isfinite (adg(:)))))
    error ("rarx:badInput", "rarx: adg must be real and finite");
  endif
  o.adm = adm;
  o.adg = adg;
  o.th0 = [];
  o.P0 = [];
  if (nargin >= 5)
    o.th0 = check_numeric (th0, "th0");
  endif
  if (nargin >= 6)
    o.P0 = check_numeric (P0, "P0");
  endif
  o.lambda = 0;
  o.continuous = false;
  [thm, yhat, ~, ~, P] = contsid_rarx ("rarx", d, nn, o);
endfunction

function v = check_numeric (v, what)
  if (! (isnumeric (v) && isreal (v) && all (isfinite (v(:)))))
    error ("rarx:badInput", "rarx: %s must be real and finite", what);
  endif
endfunction

%!shared u, y, N
%! u = prbs (8, 5); N = numel (u);
%! y = filter ([0 0.3 0.2], [1 -1.5 0.7], u);

%!test  # noise-free: RLS converges to the true parameters
%! thm = rarx ([y u], [2 2 1], "ff", 1, zeros (4, 1), 1e12 * eye (4));
%! assert (thm(end, :), [-1.5 0.7 0.3 0.2], 1e-7);

%!test  # batch identity: RLS with lambda = 1 is least squares (+ prior)
%! randn ("state", 3);
%! yn = y + 0.05 * randn (N, 1);
%! [thm, yhat, P] = rarx (iddata (yn, u, 1), [2 2 1], "ff", 1, ...
%!                        zeros (4, 1), 1e10 * eye (4));
%! Phi = [-[0; yn(1:end-1)], -[0; 0; yn(1:end-2)], ...
%!        [0; u(1:end-1)], [0; 0; u(1:end-2)]];
%! th = (Phi' * Phi + 1e-10 * eye (4)) \ (Phi' * yn);
%! assert (thm(end, :)', th, 1e-8);
%! assert (P, inv (Phi' * Phi + 1e-10 * eye (4)), 1e-8 * norm (P));
%! assert (yhat(3), Phi(3, :) * thm(2, :)', 1e-12);

%!test  # Kalman filter with a scalar Qn equals the matrix form
%! a = rarx ([y u], [2 2 1], "kf", 1e-4);
%! b = rarx ([y u], [2 2 1], "kf", 1e-4 * eye (4));
%! assert (a, b, 0);

%!error id=rarx:badInput rarx ([y u], [2 2 1], "ff")
%!error id=rarx:notSupported rarx ([y u], [2 2 1], "ng", 0.1)
%!error id=rarx:badOption rarx ([y u], [2 2 1], "xx", 0.1)
%!error id=rarx:badInput rarx ([y u], [2 2], "ff", 1)
%!error id=rarx:badInput rarx ([y u], [0 2 1], "ff", 1)
%!error id=rarx:badInput rarx ([y u], [2 2 1], "ff", 1.5)
%!error id=rarx:dimensionMismatch rarx ([y u], [2 2 1], "kf", eye (3))
%!error id=rarx:dimensionMismatch rarx (iddata (y, [u u], 1), [2 2 1], "ff", 1)
%!error id=rarx:badInput rarx ([y u u], [2 2 1], "ff", 1)

%!demo
%! u = prbs (8, 5); N = numel (u);
%! y = filter ([0 0.3 0.2], [1 -1.5 0.7], u) + 0.02 * randn (N, 1);
%! thm = rarx ([y u], [2 2 1], "kf", 1e-5);
%! plot (thm); legend ("a1", "a2", "b1", "b2");
%! title ("rarx: recursive DT ARX estimates");
