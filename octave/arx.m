## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn  {} {@var{M} =} arx (@var{data}, [@var{na} @var{nb} @var{nk}])
## @deftypefnx {} {@var{M} =} arx (@var{data}, [@var{na} @var{nb1} @dots{} @var{nbm} @var{nk1} @dots{} @var{nkm}])
## @deftypefnx {} {[@var{M}, @var{info}] =} arx (@dots{})
## @deftypefnx {} {[@var{sys}, @var{x0}] =} arx (@var{dat}, @var{n}, @dots{})
## Least-squares ARX model A(q) y(t) = sum_j B_j(q) u_j(t - nk_j) + e(t)
## in the System Identification Toolbox's [na nb nk] form (thesis eq. 1.7
## in discrete time): A monic of order @var{na}, @var{nb} coefficients and
## @var{nk} samples of delay per input.  The regression uses the samples
## whose regressors lie inside the record; solved by column-pivoted QR in
## the core (no normal equations).
##
## @var{M}: an @code{idpoly} (Ts of the data) with covariance s^2
## (Phi'Phi)^-1, s^2 = e'e/(rows - np), NoiseVariance s^2 and Report
## (Fit.FitPercent, LossFcn = MSE of the one-step prediction error,
## FPE).  Too little excitation gives @code{arx:numericalFailure}.
##
## The control package's forms (a scalar order @var{n}, the keys
## @qcode{'na'}, @qcode{'nb'}, or an options struct) are passed on to the
## control package's @code{arx} unchanged (its errors are raised again
## as @code{arx:badInput}).
##
## @strong{Example}
## @example
## u = sign (randn (500, 1));
## y = filter ([0 0.5], [1 -0.8], u + 0.1 * randn (500, 1));
## M = arx (iddata (y, u, 1), [1 1 1])
## @end example
## @seealso{oe, delayest}
## @end deftypefn

function varargout = arx (varargin)
  varargout = contsid_guard ("arx", @arx_body, nargout, varargin);
endfunction

function [M, info, varargout] = arx_body (varargin)
  contsid_nargchk ("arx", nargin, nargout, [2 Inf], 2);
  if (! sitb_form (varargin))
    [M, info] = control_arx (varargin, nargout);
    return;
  endif
  [M, info] = contsid_pem ("arx", varargin);
endfunction

## [na nb nk] (a numeric vector of at least 3 entries) with no further
## argument: the SITB form; everything else is the control package's.
function tf = sitb_form (args)
  tf = numel (args) == 2 && isnumeric (args{2}) && numel (args{2}) >= 3;
endfunction

function [a, b] = control_arx (args, nout)
  b = [];
  list = pkg ("list", "control");
  if (isempty (list))
    error ("arx:notSupported", ["arx: this form needs the control ", ...
           "package; the toolbox's form is arx (data, [na nb nk])"]);
  endif
  ## The control package's errors carry no identifier: they are raised
  ## again as arx:badInput with its message (its results are untouched).
  try
    if (nout < 2)
      a = contsid_call_shadowed (list{1}.dir, "arx", 1, args);
    else
      [a, b] = contsid_call_shadowed (list{1}.dir, "arx", 2, args);
    endif
  catch err
    msg = regexprep (err.message, '^arx: ', '');
    error ("arx:badInput", "arx: %s (the control package's arx)", msg);
  end_try_catch
endfunction

%!shared u, y, N
%! N = 400; rand ("state", 2); randn ("state", 2);
%! u = sign (rand (N, 1) - 0.5);
%! y = filter ([0 0.4 0.2], [1 -0.9 0.2], u) + filter (1, [1 -0.9 0.2], 0.3 * randn (N, 1));

%!test  # equals the normal equations solved here
%! M = arx (iddata (y, u, 1), [2 2 1]);
%! k = (3:N)';
%! Phi = [-y(k-1), -y(k-2), u(k-1), u(k-2)];
%! th = (Phi' * Phi) \ (Phi' * y(k));
%! assert (M.A, [1 th(1:2)'], 1e-10);
%! assert (M.B, [0 th(3:4)'], 1e-10);
%! e = y(k) - Phi * th;
%! s2 = (e' * e) / (numel (k) - 4);
%! C = getcov (M);                  # B's leading zero is fixed
%! assert (C([1 2 4 5], [1 2 4 5]), s2 * inv (Phi' * Phi), 1e-10);
%! assert (M.NoiseVariance, s2, 1e-12);
%! ## Report.Fit: of the one-step prediction error over the whole record
%! ## (the regressor's values before the record 0)
%! ep = y - filter ([0 -th(1:2)'], 1, y) - filter ([0 th(3:4)'], 1, u);
%! assert (M.Report.Fit.MSE, mean (ep .^ 2), 1e-12);
%! assert (M.Report.Fit.FitPercent,
%!         100 * (1 - norm (ep) / norm (y - mean (y))), 1e-9);

%!test  # two inputs
%! u2 = sign (randn (N, 1));
%! M = arx (iddata (y + 0.5 * filter ([0 1], [1 -0.9 0.2], u2), [u u2], 1), [2 2 1 1 1]);
%! assert (M.B, {[0 0.3975 0.2107], [0 0.5172]}, 1e-4);

%!test  # the control package's form is passed on
%! if (! isempty (pkg ("list", "control")))
%!   sys = arx (iddata (y, u, 1), 2);
%!   assert (isa (sys, "lti"));
%! endif

%!error id=arx:badInput arx (iddata (y, u, 1))
%!error id=arx:badInput arx (iddata (y, u, 1), [2 -1 1])
%!error id=arx:dimensionMismatch arx (iddata (y, u, 1), [2 2 1 1])
%!error id=arx:numericalFailure arx (iddata (y, zeros (N, 1), 1), [2 2 1])
%!error id=arx:badInput arx (iddata (y(1:4), u(1:4), 1), [2 2 1])
%!error id=arx:badInput arx (1, 2)

%!demo
%! u = sign (randn (500, 1));
%! y = filter ([0 0.5], [1 -0.8], u + 0.1 * randn (500, 1));
%! M = arx (iddata (y, u, 1), [1 1 1]);
%! present (M)
