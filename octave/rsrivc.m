## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn  {} {@var{thm} =} rsrivc (@var{data}, @var{nn}, "lambda_svf", @var{lam}, @dots{})
## @deftypefnx {} {@var{thm} =} rsrivc (@var{data}, @var{nn}, "A", @var{A}, @dots{})
## @deftypefnx {} {[@var{thm}, @var{yh}, @var{pset}, @var{info}] =} rsrivc (@dots{})
## Recursive simplified refined instrumental variable estimation of a
## continuous-time model with time-varying parameters (RSRIVC).
##
## @var{nn} = [nb nf nk]: nb numerator parameters, nf denominator
## parameters (the model order), nk the input delay in samples. @var{thm}
## is ordered [b0 .. b_(nb-1), f1 .. f_nf] (b before f, as CONTSID), for
## the model
## @example
## x = (b0 p^(nb-1) + .. ) / (p^nf + f1 p^(nf-1) + .. + f_nf) u
## @end example
## @code{adg} (Qn), @code{th0}, @code{P0} and @code{scaling} are ordered
## like @var{thm}. The other options are those of @code{rivsvf}
## (@code{lambda_svf}, @code{adm}, @code{adg}, @code{th0}, @code{P0},
## @code{tsiv} (also "auto"), @code{dtupdate}, @code{stability},
## @code{mtheta}, @code{svf}, @code{scaling}, @code{antiwindup},
## @code{antiwindup_lambda}, @code{precision}, @code{InterSample};
## @var{info} as there) plus:
## @table @code
## @item A
## a stable denominator [1 f1 .. f_nf] that starts the adaptive prefilter
## and the auxiliary model instead of (p + lambda_svf)^nf. Given alone, it
## also sets lambda_svf (for the RLSSVF start) to the geometric mean of its
## roots, f_nf^(1/nf).
## @item prefilter
## gain of the adaptive prefilter: @qcode{"unit"} (default) f_nf/A(p), unit
## static gain like the normalised SVF, or @qcode{"monic"} 1/A(p) as
## written in eq. (2.19). With "monic" the filtered signals, and so the
## effective Qn, rescale as A drifts; the unit gain keeps one Qn meaningful
## for RIVSVF and RSRIVC alike (see the README's results).
## @end table
##
## @strong{Algorithm.} RLSSVF until tsiv, then the IV update (2.29)/(2.30)
## where y, u and the auxiliary-model output x_hat are all filtered by the
## adaptive prefilter built from the latest accepted estimate (eqs.
## 2.18-2.20), after smoothing by M_theta and the stability test (3.10).
## Reference: A. Padilla, PhD thesis, Universite de Lorraine, 2017, sec.
## 2.2.3, 2.3.3 and 3.2.
##
## @strong{Example}
## @example
## Ts = 0.05; u = prbs (10, 8); N = numel (u);
## y = simc (struct ("B", 4, "F", [1 2.4 4]), u, Ts) + 0.1 * randn (N, 1);
## data = iddata (y, u, Ts, "InterSample", "zoh");
## thm = rsrivc (data, [1 2 0], "lambda_svf", 3, "adm", "kf", "adg", 1e-7);
## thm(end, :)   # [b0 f1 f2], close to [4 2.4 4]
## @end example
## @seealso{rivsvf, rlssvf, clrsrivc, srivc}
## @end deftypefn

function varargout = rsrivc (varargin)
  varargout = contsid_guard ("rsrivc", @rsrivc_body, nargout, varargin);
endfunction

function varargout = rsrivc_body (varargin)
  contsid_nargchk ("rsrivc", nargin, nargout, [0 Inf], 4);
  [varargout{1:max(1, nargout)}] = contsid_riv ("rsrivc", nargout, varargin{:});
endfunction

%!shared Ts, u, x, data, N
%! Ts = 0.05; u = prbs (10, 8); N = numel (u);
%! x = simc (struct ("B", 4, "F", [1 2.4 4]), u, Ts);
%! data = iddata (x, u, Ts, "InterSample", "zoh");

%!test  # noise-free LTI system recovered; THM is [b f]
%! thm = rsrivc (data, [1 2 0], "lambda_svf", 3);
%! assert (thm(end, :), [4 2.4 4], 2e-3 * 4);

%!test  # a gap of missing samples: RSRIVC keeps tracking after it
%! randn ("state", 3);
%! y = x + 0.02 * randn (N, 1);
%! yg = y; yg(3001:3200) = NaN;                    # 10 s of missing output
%! opts = {"lambda_svf", 3, "adm", "kf", "adg", 1e-7, "tsiv", 20};
%! [a, ~, ~, ia] = rsrivc (y, u, Ts, [1 2 0], opts{:});
%! [b, ~, ~, ib] = rsrivc (yg, u, Ts, [1 2 0], opts{:});
%! assert (nnz (ib.missing), 200);
%! assert (! isfield (ia, "missing"));
%! assert (b(3001:3200, :), repmat (b(3000, :), 200, 1));
%! late = 3201:N;                                  # after the gap
%! ## y is bridged linearly over the gap; its error passes through the
%! ## prefilter into a few updates, which the KF forgets slowly: the
%! ## estimates stay within 2 % of the run without the gap, 0.5 % at the end.
%! assert (all (max (abs (b(late, :) - a(late, :))) < 0.02 * abs (a(end, :))));
%! assert (b(end, :), a(end, :), 0.005 * 4);
%! assert (b(end, :), [4 2.4 4], 0.01 * 4);

%!test  # before tsiv: RLSSVF reordered
%! a = rsrivc (data, [1 2 0], "lambda_svf", 3, "tsiv", 100);
%! b = rlssvf (data, [2 1 0], "lambda_svf", 3);
%! k = round (100 / Ts);
%! assert (a(1:k, :), b(1:k, [3 1 2]), 0);

%!test  # th0, P0 and Qn are taken in THM order
%! Qn = diag ([1e-6 2e-6 3e-6]);
%! a = rsrivc (data, [1 2 0], "lambda_svf", 3, "adm", "kf", "adg", Qn, ...
%!             "th0", [4 2.4 4], "P0", 1e-8, "tsiv", 0);
%! assert (max (abs (a(end, :) - [4 2.4 4])) < 1e-3);

%!test  # the estimates start at 0 (unstable p^2): refused, then recovery
%! [thm, ~, ~, info] = rsrivc (data, [1 2 0], "lambda_svf", 3);
%! assert (info.stability_rejections > 0);
%! assert (thm(end, :), [4 2.4 4], 1e-2);
%! [thm, ~, ~, info] = rsrivc (data, [1 2 0], "lambda_svf", 3, ...
%!                             "stability", "reflect");
%! assert (info.stability_rejections > 0);
%! assert (thm(end, :), [4 2.4 4], 1e-2);

%!test  # A given instead of lambda_svf; monic prefilter
%! a = rsrivc (data, [1 2 0], "A", [1 4 4]);
%! assert (a(end, :), [4 2.4 4], 1e-2);
%! b = rsrivc (data, [1 2 0], "lambda_svf", 3, "prefilter", "monic");
%! assert (b(end, :), [4 2.4 4], 1e-2);

%!test  # scaling (eq. 3.74), given in THM order: same estimates
%! randn ("state", 5);
%! d = iddata (x + 0.1 * randn (N, 1), u, Ts, "InterSample", "zoh");
%! o = {"lambda_svf", 3, "adm", "kf", "adg", 1e-6, "tsiv", 10};
%! a = rsrivc (d, [1 2 0], o{:});
%! m = svfscaling (d, [1 2 0], "lambda_svf", 3, "order", "bf");
%! b = rsrivc (d, [1 2 0], o{:}, "scaling", m);
%! c = rsrivc (d, [1 2 0], o{:}, "scaling", "self");
%! assert (b, a, 1e-8 * max (abs (a(:))));
%! assert (c, b, 0);

%!test  # conditional updating: held at th0 while the input is constant
%! uc = [u; ones(3000, 1); u];
%! xc = simc (struct ("B", 4, "F", [1 2.4 4]), uc, Ts);
%! [thm, ~, ~, info] = rsrivc (iddata (xc, uc, Ts, "InterSample", "zoh"), ...
%!     [1 2 0], "lambda_svf", 3, "tsiv", 10, "adm", "kf", "adg", 1e-8, ...
%!     "antiwindup", 300, "antiwindup_lambda", 0.99);
%! n = numel (u);
%! assert (info.updating(n), 1);
%! held = ! info.updating;
%! assert (nnz (held(n+1:n+3000)) > 2000);
%! assert (all (all (thm(held, :) == 0)));
%! assert (all (info.kappa_ff(held) >= 300));
%! assert (info.resets >= 1);
%! assert (thm(end, :), [4 2.4 4], 1e-2);

%!error id=rsrivc:badInput rsrivc (data, [1 2 0], "A", [1 -1 4])
%!error id=rsrivc:badInput
%! rsrivc (iddata (x, zeros (N, 1), Ts), [1 2 0], "lambda_svf", 3);
%!warning id=rsrivc:cutoffAboveNyquist
%! thm = rsrivc (data, [1 2 0], "lambda_svf", 1e9, "tsiv", 5);
%!error id=rsrivc:badInput rsrivc (data, [1 2 0], "lambda_svf", 3, "antiwindup", 1)
%!error id=rsrivc:badInput rsrivc (data, [1 2 0], "lambda_svf", 3, "antiwindup", "on")
%!error id=rsrivc:badInput rsrivc (data, [1 2 0], "lambda_svf", 3, "antiwindup", 300, "antiwindup_lambda", 1.5)
%!error id=rsrivc:badOption rsrivc (data, [1 2 0], "lambda_svf", 3, "adm", "lmr")
%!error id=rsrivc:badOption rsrivc (data, [1 2 0], "lambda_svf", 3, "potter", true)
%!error id=rsrivc:badOption rsrivc (data, [1 2 0], "lambda_svf", 3, "precision", "x")
%!error id=rsrivc:dimensionMismatch rsrivc (data, [1 2 0], "lambda_svf", 3, "scaling", [1 2])
%!error id=rsrivc:dimensionMismatch rsrivc (data, [1 2 0], "A", [1 2 3 4])
%!error id=rsrivc:badInput rsrivc (data, [1 2 0], "A", "x")
%!error id=rsrivc:badOption rsrivc (data, [1 2 0], "lambda_svf", 3, "prefilter", "x")
%!error id=rsrivc:badInput rsrivc (data, [1 2 0], "lambda_svf", 3, "tsiv", 1e9)
%!error id=rsrivc:badInput rsrivc (data, [4 2 0], "lambda_svf", 3)
%!error id=rsrivc:badInput rsrivc (data, [1 0 0], "lambda_svf", 3)
%!error id=rsrivc:dimensionMismatch rsrivc (data, [1 2 0], "lambda_svf", 3, "th0", [1 2])
%!error id=rsrivc:badOption rsrivc (data, [1 2 0], "lambda_svf", 3, "controller", struct ("num", 1, "den", 1))

%!demo
%! ## RSRIVC tracking a drifting resonance.
%! Ts = 0.02; u = prbs (12, 10); N = numel (u); t = (0:N-1)' * Ts;
%! wn = 3 * (1 + 0.3 * sin (2 * pi * t / t(end)));
%! theta = [wn .^ 2, 1.2 * wn, wn .^ 2];       # [b0 f1 f2]
%! y = simc (theta(:, [2 3 1]), [2 1 0], u, Ts) + 0.1 * randn (N, 1);
%! data = iddata (y, u, Ts, "InterSample", "zoh");
%! thm = rsrivc (data, [1 2 0], "lambda_svf", 5, "adm", "kf", ...
%!               "adg", 1e-6 * eye (3), "tsiv", 20);
%! plot (t, theta(:, 3), "k", t, thm(:, 3), "r");
%! legend ("true f_2", "RSRIVC"); xlabel ("t (s)");
