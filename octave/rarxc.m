## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn  {} {@var{THM} =} rarxc (@var{data}, [@var{na} @var{nb} @var{nk}], @var{name}, @var{value}, @dots{})
## @deftypefnx {} {[@var{THM}, @var{YH}, @var{info}] =} rarxc (@dots{})
## Indirect recursive identification of a continuous-time model: a
## discrete-time ARX model estimated recursively and converted to
## continuous time at every step under the zero-order-hold assumption
## (thesis secs. 1.2.2 and 1.3.4, Fig. 1.9a).
##
## This is the route MATLAB users take with @code{recursiveARX}/@code{rarx}
## plus @code{d2c}; the direct route of this toolbox is @code{rlssvf}.
## The DT model is that of @code{rarx}, @var{nn} = [na nb nk]; the ZOH
## conversion needs nk >= 1 and nk + nb - 1 <= na (a strictly proper DT
## model of order na, the image of a CT model of order na).  The data
## must be uniformly sampled with a zero-order-hold input.
##
## Options (name-value pairs or a struct):
## @table @code
## @item adm, adg
## @qcode{"ff"} with the forgetting factor (default 1), or @qcode{"kf"}
## with the normalised covariance Qn of the DT parameter changes (a scalar
## means Qn*I, a vector its diagonal), ordered [a1..a_na b1..b_nb].
## @item lambda_svf
## cut-off (rad/s) of the prefilter: the SVF (lambda/(p+lambda))^na
## discretised by the bilinear rule, applied to y and u (sec. 1.3.4);
## 0 (default) for none.
## @item th0, P0
## start of the DT recursion (default 0 and 1e4*I).
## @end table
##
## @var{THM} is N-by-2na, row k = [a1 .. a_na, b0 .. b_(na-1)] of the CT
## model B(p)/A(p) with A(p) = p^na + a1 p^(na-1) + .. and
## B(p) = b0 p^(na-1) + .. + b_(na-1), the ordering of @code{rlssvf}.  At
## a sample whose DT estimate has a pole at 0 or on the negative real
## axis there is no CT equivalent: the row repeats the last CT model and
## @code{info.conversion_failed} marks it.  @var{YH} is the one-step
## prediction of the (prefiltered) output.  @var{info} has
## @code{theta_dt} (the DT estimates, as @code{rarx} returns them),
## @code{conversion_failed} (N-by-1 logical), @code{failures} (their
## count) and @code{P} (the final DT covariance).
##
## @strong{Example}
## @example
## Ts = 0.1; u = prbs (9, 10); N = numel (u);
## y = simc (struct ("B", 4, "F", [1 2.4 4]), u, Ts);
## THM = rarxc (iddata (y, u, Ts), [2 2 1]);
## THM(end, :)     # close to [2.4 4 0 4]
## @end example
## @seealso{rarx, rlssvf}
## @end deftypefn

function varargout = rarxc (varargin)
  varargout = contsid_guard ("rarxc", @rarxc_body, nargout, varargin);
endfunction

function [THM, YH, info, varargout] = rarxc_body (varargin)
  contsid_nargchk ("rarxc", nargin, nargout, [0 Inf], 3);
  d = contsid_getdata ("rarxc", varargin{:});
  contsid_check_output ("rarxc", d.y);
  rest = varargin(d.nconsumed + 1:end);
  if (isempty (rest))
    error ("rarxc:badInput", "rarxc: nn = [na nb nk] is missing");
  endif
  nn = rest{1};
  if (! strcmp (d.intersample, "zoh"))
    error ("rarxc:notSupported",
           "rarxc: the ZOH conversion needs a zero-order-hold input, got '%s'",
           d.intersample);
  endif
  defaults = struct ("adm", "ff", "adg", 1, "lambda_svf", 0, "th0", [],
                     "P0", []);
  o = contsid_options ("rarxc", defaults, rest(2:end));
  if (! (isnumeric (o.lambda_svf) && isreal (o.lambda_svf)
         && isscalar (o.lambda_svf) && isfinite (o.lambda_svf)
         && o.lambda_svf >= 0))
    error ("rarxc:badInput",
           "rarxc: lambda_svf must be a finite scalar >= 0");
  endif
  for name = {"adg", "th0", "P0"}
    v = o.(name{1});
    if (! (isnumeric (v) && isreal (v) && all (isfinite (v(:)))))
      error ("rarxc:badInput", "rarxc: %s must be real and finite", name{1});
    endif
  endfor
  if (! ischar (o.adm))
    error ("rarxc:badOption", "rarxc: adm must be 'ff' or 'kf'");
  endif
  o.lambda = o.lambda_svf;
  o.continuous = true;
  [thm, YH, THM, failed, P] = contsid_rarx ("rarxc", d, nn, o);
  info = struct ("theta_dt", thm, "conversion_failed", logical (failed),
                 "failures", sum (failed), "P", P);
endfunction

%!shared u, Ts, x, N
%! Ts = 0.1; u = prbs (9, 10); N = numel (u);
%! x = simc (struct ("B", 4, "F", [1 2.4 4]), u, Ts);

%!test  # noise-free ZOH record: the CT model is recovered
%! [THM, YH, info] = rarxc (iddata (x, u, Ts), [2 2 1], "P0", 1e12 * eye (4));
%! assert (THM(end, :), [2.4 4 0 4], 1e-5);
%! ## theta0 = 0 puts both DT poles at z = 0 (no CT equivalent) until the
%! ## first samples have moved them: only the start-up may be flagged.
%! assert (all (find (info.conversion_failed) <= 4));
%! assert (size (info.theta_dt), [N 4]);

%!test  # the DT estimates are those of rarx; the CT rows their ZOH inverse
%! randn ("state", 1);
%! y = x + 0.05 * randn (N, 1);
%! [THM, ~, info] = rarxc (iddata (y, u, Ts), [2 2 1], "adm", "kf", ...
%!                         "adg", 1e-4);
%! assert (info.theta_dt, rarx (iddata (y, u, Ts), [2 2 1], "kf", 1e-4), 0);
%! k = N;  # independent conversion: c2d of the CT row gives the DT row
%! a = THM(k, 1:2); b = THM(k, 3:4);
%! F = [0 1; -a(2) -a(1)]; G = [0; 1];
%! E = expm ([F G; 0 0 0] * Ts); Ad = E(1:2, 1:2); Bd = E(1:2, 3);
%! alpha = poly (Ad); C = [b(2) b(1)];
%! beta = poly (Ad - Bd * C) - alpha;
%! assert ([alpha(2:3) beta(2:3)], info.theta_dt(k, :), 1e-9);

%!test  # the bilinear SVF prefilter keeps noise-free recovery exact
%! THM = rarxc (iddata (x, u, Ts), [2 2 1], "lambda_svf", 3.2, ...
%!              "P0", 1e12 * eye (4));
%! assert (THM(end, :), [2.4 4 0 4], 1e-4);

%!error id=rarxc:badInput rarxc (iddata (x, u, Ts), [2 2 0])
%!error id=rarxc:badInput rarxc (iddata (x, zeros (N, 1), Ts), [2 1 1])
%!error id=rarxc:badInput rarxc (iddata (x, u, Ts), [2 3 1])
%!error id=rarxc:badInput rarxc (iddata (x, u, Ts))
%!error id=rarxc:badInput rarxc (iddata (x, u, Ts), [2 2 1], "lambda_svf", -1)
%!error id=rarxc:badOption rarxc (iddata (x, u, Ts), [2 2 1], "bogus", 1)
%!error id=rarxc:notSupported rarxc (iddata (x, u, Ts, "InterSample", "foh"), [2 2 1])
%!error id=rarxc:dimensionMismatch rarxc (iddata (x, [u u], Ts), [2 2 1])

%!demo
%! Ts = 0.1; u = prbs (9, 10); N = numel (u);
%! y = simc (struct ("B", 4, "F", [1 2.4 4]), u, Ts) + 0.1 * randn (N, 1);
%! THM = rarxc (iddata (y, u, Ts), [2 2 1], "adm", "kf", "adg", 1e-5, ...
%!              "lambda_svf", 3);
%! plot ((0:N-1) * Ts, THM(:, [1 2 4]));
%! legend ("a1", "a2", "b (p^0)"); title ("rarxc: indirect CT estimates");
