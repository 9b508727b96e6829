## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn  {} {@var{Qn} =} qnml (@var{data}, @var{nn}, "lambda_svf", @var{lam}, @dots{})
## @deftypefnx {} {[@var{Qn}, @var{V}, @var{info}] =} qnml (@dots{})
## @deftypefnx {} {} qnml (@dots{})
## Maximum-likelihood estimate of the diagonal of the normalised covariance
## matrix Qn of a Kalman-filter based recursive estimator, from training
## data (thesis sec. 3.3, eq. 3.23, Suggested procedure 3.6).
##
## @var{data} and @var{nn} are those of the estimator chosen by
## @code{"method"} (@code{[nb nf nk]} for @code{rsrivc}, @code{[na nb nk]}
## for @code{rlssvf}); its options (@code{lambda_svf}, @code{tsiv},
## @code{th0}, @code{P0}, @code{svf}, @code{scaling}, @code{A},
## @code{controller}, @code{r1}, @code{r2}, ...) are passed through;
## @code{adm} and @code{adg} are set by qnml (adm "kf", adg = diag (q)).
##
## @strong{Options of the search}
## @table @code
## @item method
## @qcode{"rsrivc"} (default, as in the thesis), @qcode{"rlssvf"},
## @qcode{"rivsvf"}, @qcode{"clrsrivc"} or @qcode{"clrivsvf"}.
## @item q0
## start value: a scalar for every free element, or np values ordered like
## the estimator's THM (default 1e-5).
## @item lb, ub
## bounds, a scalar for every free element or np values (default 1e-8 and
## 1e-1); the lower bounds must be > 0 (the search is on log10 q).
## @item fixed
## np values, NaN for the elements to estimate and a number for those held
## (e.g. @code{[NaN 0]}: b0 known to be constant); default all free.
## @item maxeval, tol
## at most @code{maxeval} cost evaluations (default 200); stop when log10 q
## moves by less than @code{tol} (default 1e-3).
## @end table
##
## @strong{Outputs}: @var{Qn} the np-by-np diagonal ML estimate; @var{V} the
## cost (3.23) at it; @var{info} a struct with @code{q} (the diagonal),
## @code{free}, @code{sigma2} (the ML variance of the filtered noise),
## @code{evaluations}, @code{converged}, @code{message} (NLopt's stopping
## reason), @code{lb}, @code{ub}, @code{method} and @code{cost}, a function
## handle: @code{info.cost (Q)} evaluates V at the diagonals in the columns
## of @var{Q} (np-by-M). Without outputs, V is plotted against each free
## element around the optimum, the others held (thesis Fig. 3.4).
##
## @strong{Algorithm.} The estimator runs with Qn = diag (q) and gives at
## each update the prediction error epsilon and its normalised variance
## rho = 1 + phi_f^T P(t_k|t_(k-1)) phi_f (for the IV stage
## 1 + phi_f^T P zeta_f), eqs. (3.24)-(3.25). With r = sigma_e^2 rho the
## cost (3.23) is sum log r + sum epsilon^2 / r; the unknown sigma_e^2 (the
## variance of the filtered noise) is concentrated out, sigma_e^2 =
## mean (epsilon^2 / rho), leaving V = N log sigma_e^2 + sum log rho + N.
## NLopt's BOBYQA (COBYLA for a single free element) minimises V over log10
## of the free elements within the bounds. Reference: A. Padilla, PhD
## thesis, Universite de Lorraine, 2017, sec. 3.3.
##
## @strong{Example}
## @example
## Ts = 0.025; t = (0:Ts:250)'; u = prbs (13, 4)(1:numel (t));
## a1 = 2 + 0.8 * t / 250;                       # thesis example 3.3.3
## y = simc ([a1, 3 * ones(numel (t), 1)], [1 1 0], u, Ts) ...
##     + sqrt (3e-3) * randn (numel (t), 1);
## data = iddata (y, u, Ts, "InterSample", "zoh");
## Qn = qnml (data, [1 1 0], "lambda_svf", 3, "fixed", [0 NaN], ...
##            "q0", 1e-5, "lb", 1e-6, "ub", 1e-4);
## @end example
## @seealso{rsrivc, rlssvf}
## @end deftypefn

function varargout = qnml (varargin)
  varargout = contsid_guard ("qnml", @qnml_body, nargout, varargin);
endfunction

function [Qn, V, info, varargout] = qnml_body (varargin)
  contsid_nargchk ("qnml", nargin, nargout, [0 Inf], 3);
  fname = "qnml";
  if (nargin < 2)
    error ("qnml:badInput", "qnml: expected data, nn and options");
  endif
  [search, rest] = split_options (fname, varargin);
  method = search.method;
  if (! ischar (method)
      || ! any (strcmp (method, {"rsrivc", "rlssvf", "rivsvf", "clrsrivc", ...
                                  "clrivsvf"})))
    error ("qnml:badOption", ...
           ["qnml: method must be 'rsrivc', 'rlssvf', 'rivsvf', ", ...
            "'clrsrivc' or 'clrivsvf'"]);
  endif
  estimator_args = [rest, {"adm", "kf"}];
  if (strcmp (method, "rlssvf"))
    p = contsid_rlssvf_args (fname, estimator_args{:});
    perm = 1:p.orders.np;
    kind = "rlssvf";
    if (p.opts.ic)
      error ("qnml:badOption", ...
             "qnml: 'ic' is not supported in the Qn search");
    endif
    if (strcmp (p.opts.form, "lmr"))
      error ("qnml:badOption", "qnml: the Qn search needs a Kalman filter");
    endif
  else
    p = contsid_riv_args (fname, method, estimator_args{:});
    perm = p.perm;
    kind = "riv";
  endif
  np = p.orders.np;
  iperm(perm) = 1:np;

  q0 = per_element (fname, search.q0, np, "q0");
  lb = per_element (fname, search.lb, np, "lb");
  ub = per_element (fname, search.ub, np, "ub");
  fixed = search.fixed;
  if (isempty (fixed))
    fixed = NaN (np, 1);
  endif
  if (! isnumeric (fixed) || ! isreal (fixed) || ! isvector (fixed))
    error ("qnml:badInput", ...
           "qnml: fixed must be np values (NaN: free, a number: held)");
  endif
  if (numel (fixed) != np)
    error ("qnml:dimensionMismatch", ...
           "qnml: fixed must have %d elements (one per parameter), got %d",
           np, numel (fixed));
  endif
  fixed = double (fixed(:));
  free = isnan (fixed);
  if (any (! free & (! isfinite (fixed) | fixed < 0)))
    error ("qnml:badInput", "qnml: fixed values must be finite and >= 0");
  endif
  q0(! free) = fixed(! free);
  if (isscalar (search.lb))
    lb(! free) = -Inf;                   # scalar bounds apply to free ones
  endif
  if (isscalar (search.ub))
    ub(! free) = Inf;
  endif
  maxeval = search.maxeval;
  if (! isnumeric (maxeval) || ! isscalar (maxeval) || ! isreal (maxeval)
      || maxeval != fix (maxeval) || maxeval < 1)
    error ("qnml:badInput", "qnml: maxeval must be an integer >= 1");
  endif
  tol = search.tol;
  if (! isnumeric (tol) || ! isscalar (tol) || ! isreal (tol)
      || ! isfinite (tol) || tol <= 0)
    error ("qnml:badInput", "qnml: tol must be a finite scalar > 0");
  endif

  g = p.opts;
  g.estimator = kind;
  g.mode = "search";
  g.q0 = q0(iperm);
  g.lb = lb(iperm);
  g.ub = ub(iperm);
  g.free = double (free(iperm));
  g.maxeval = double (maxeval);
  g.xtol = double (tol);
  try
    [q, V, sigma2, evaluations, converged, message] = qnml_mex (fname,
                                                                p.data{:}, g);
  catch err
    contsid_rethrow (err);
  end_try_catch
  q = q(perm);
  Qn = diag (q);
  cost = @(Q) evaluate_cost (fname, kind, p, Q, iperm, np);
  info = struct ("q", q, "free", free, "sigma2", sigma2,
                 "evaluations", evaluations, "converged", converged,
                 "message", message, "lb", lb, "ub", ub, "method", method,
                 "cost", cost);
  if (! converged)
    warning ("qnml:notConverged", ...
             "qnml: the search stopped before its tolerance (%s)", message);
  endif
  if (nargout == 0)
    plot_profiles (q, V, free, lb, ub, cost);
    clear Qn;
  endif
endfunction

function [search, rest] = split_options (fname, args)
  search = struct ("method", "rsrivc", "q0", 1e-5, "lb", 1e-8, "ub", 1e-1,
                   "fixed", [], "maxeval", 200, "tol", 1e-3);
  names = fieldnames (search);
  rest = {};
  k = 1;
  while (k <= numel (args))
    a = args{k};
    if (ischar (a) && rows (a) == 1 && k < numel (args))
      idx = find (strcmpi (a, names));
      if (! isempty (idx))
        search.(names{idx}) = args{k+1};
        k += 2;
        continue;
      endif
      if (any (strcmpi (a, {"adm", "adg"})))
        error ([fname ":badOption"], ...
               "%s: adm and adg are set by the search (adm 'kf', adg = Qn)",
               fname);
      endif
      rest(end+1:end+2) = args(k:k+1);
      k += 2;
      continue;
    endif
    rest{end+1} = a;
    k += 1;
  endwhile
endfunction

function v = per_element (fname, v, np, what)
  if (! isnumeric (v) || ! isreal (v) || ! isvector (v) || any (isnan (v)))
    error ([fname ":badInput"], "%s: %s must be a real scalar or vector",
           fname, what);
  endif
  if (isscalar (v))
    v = v * ones (np, 1);
  elseif (numel (v) != np)
    error ([fname ":dimensionMismatch"], ...
           "%s: %s must be a scalar or have %d elements, got %d", fname,
           what, np, numel (v));
  endif
  v = double (v(:));
endfunction

function V = evaluate_cost (fname, kind, p, Q, iperm, np)
  if (isvector (Q) && numel (Q) == np)
    Q = Q(:);
  endif
  if (! isnumeric (Q) || ! isreal (Q) || rows (Q) != np)
    error ([fname ":dimensionMismatch"], ...
           "%s: the diagonals to evaluate must be %d-by-M", fname, np);
  endif
  try
    g = p.opts;
    g.estimator = kind;
    g.mode = "evaluate";
    g.Q = double (Q(iperm, :));
    V = qnml_mex (fname, p.data{:}, g);
  catch err
    contsid_rethrow (err);
  end_try_catch
endfunction

function plot_profiles (q, V, free, lb, ub, cost)
  idx = find (free);
  for j = 1:numel (idx)
    i = idx(j);
    values = logspace (log10 (lb(i)), log10 (ub(i)), 25);
    Q = repmat (q(:), 1, numel (values));
    Q(i, :) = values;
    subplot (numel (idx), 1, j);
    semilogx (values, cost (Q), "b.-", q(i), V, "ro");
    xlabel (sprintf ("q_{n,%d}", i));
    ylabel ("V");
    grid on;
  endfor
endfunction

%!shared data, N
%! Ts = 0.025; t = (0:Ts:100)'; N = numel (t);
%! u = prbs (12, 4); u = u(1:N);
%! a1 = 2 + 0.8 * t / 100;
%! randn ("state", 1);
%! y = simc ([a1, 3 * ones(N, 1)], [1 1 0], u, Ts) + sqrt (3e-3) * randn (N, 1);
%! data = iddata (y, u, Ts, "InterSample", "zoh");

%!test  # the optimum is no worse than any grid point, and inside the bounds
%! [Qn, V, info] = qnml (data, [1 1 0], "lambda_svf", 3, "tsiv", 10, ...
%!                       "fixed", [0 NaN], "q0", 1e-5, "lb", 1e-7, "ub", 1e-3);
%! assert (Qn(1, 1), 0);
%! assert (Qn(2, 2) >= 1e-7 && Qn(2, 2) <= 1e-3);
%! qs = logspace (-7, -3, 9);
%! Vg = info.cost ([zeros(1, 9); qs]);
%! assert (V <= min (Vg) + 1e-6 * abs (V));
%! assert (info.cost ([0; Qn(2, 2)]), V, 1e-9 * abs (V));

%!test  # the cost is the concentrated likelihood of the run's innovations
%! q = [0; 2e-5];
%! [thm, ~, ~, r] = rsrivc (data, [1 1 0], "lambda_svf", 3, "tsiv", 10, ...
%!                          "adm", "kf", "adg", diag (q));
%! [~, ~, info] = qnml (data, [1 1 0], "lambda_svf", 3, "tsiv", 10, ...
%!                      "fixed", [0 NaN], "maxeval", 3);
%! k = ! isnan (r.innovation);
%! n = nnz (k);
%! s2 = mean (r.error(k) .^ 2 ./ r.innovation(k));
%! assert (info.cost (q), n * log (s2) + sum (log (r.innovation(k))) + n, ...
%!         1e-9 * n);

%!test  # rlssvf as the estimator; parameters in THM order
%! [Qn, V] = qnml (data, [1 1 0], "method", "rlssvf", "lambda_svf", 3, ...
%!                 "fixed", [NaN 0], "lb", 1e-7, "ub", 1e-3);
%! assert (Qn(2, 2), 0);
%! assert (Qn(1, 1) > 0 && isfinite (V));

%!error id=qnml:badInput qnml (data)
%!error id=qnml:badOption qnml (data, [1 1 0], "lambda_svf", 3, "method", "x")
%!error id=qnml:badOption qnml (data, [1 1 0], "lambda_svf", 3, "adm", "ff")
%!error id=qnml:badInput qnml (data, [1 1 0], "lambda_svf", 3, "lb", 1e-3, "ub", 1e-5)
%!error id=qnml:badInput qnml (data, [1 1 0], "lambda_svf", 3, "lb", 0)
%!error id=qnml:badInput qnml (data, [1 1 0], "lambda_svf", 3, "q0", 1, "ub", 1e-2)
%!error id=qnml:badInput qnml (data, [1 1 0], "lambda_svf", 3, "lb", [1e-6 1e-6], "ub", [1e-4 1e-4], "fixed", [NaN 1])
%!error id=qnml:badInput qnml (data, [1 1 0], "lambda_svf", 3, "fixed", [0 0])
%!error id=qnml:dimensionMismatch qnml (data, [1 1 0], "lambda_svf", 3, "fixed", [0 0 0])
%!error id=qnml:badInput qnml (data, [1 1 0], "lambda_svf", 3, "fixed", [-1 NaN])
%!error id=qnml:badInput qnml (data, [1 1 0], "lambda_svf", 3, "maxeval", 0)
%!error id=qnml:badInput qnml (data, [1 1 0], "lambda_svf", 3, "tol", -1)
%!error id=qnml:dimensionMismatch qnml (data, [1 1 0], "lambda_svf", 3, "q0", [1 2 3])
%!error id=qnml:badOption qnml (data, [1 1 0], "lambda_svf", 3, "method", "rlssvf", "adm", "lmr")
%!error id=qnml:badOption qnml (data, [1 1 0], "lambda_svf", 3, "nonsense", 1)
%!error id=qnml:notSupported qnml (data, [1 1 0], 3, "precision", "single")

%!demo
%! ## Thesis example 3.3.3: a1 drifts, b0 is known to be constant.
%! Ts = 0.025; t = (0:Ts:250)'; N = numel (t);
%! u = prbs (13, 4); u = u(1:N);
%! y = simc ([2 + 0.8 * t / 250, 3 * ones(N, 1)], [1 1 0], u, Ts) ...
%!     + sqrt (3e-3) * randn (N, 1);
%! data = iddata (y, u, Ts, "InterSample", "zoh");
%! qnml (data, [1 1 0], "lambda_svf", 3, "fixed", [0 NaN], ...
%!       "q0", 1e-5, "lb", 1e-6, "ub", 1e-4);      # plots V (Fig. 3.4)
