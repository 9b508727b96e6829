## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn {} {@var{p} =} contsid_riv_args (@var{fname}, @var{routine}, @dots{})
## Argument preparation shared by rivsvf, rsrivc, clrivsvf and clrsrivc
## (@var{routine}) and by qnml: parses the data, @var{nn} and the options
## (messages start with @var{fname}), reorders from the public parameter
## order ([a b] for the SVF methods, [b f] for the SRIVC ones) to the core's
## [a b], and returns @var{p} with @code{data} = @{y, u, t@} and
## @code{opts}, the options struct of riv_mex (fields in
## mex/estimator_args.hpp), @code{perm}
## (thm_public = thm_core(:, perm)), @code{tsiv}, @code{d} and @code{orders}.
## @end deftypefn

function p = contsid_riv_args (fname, routine, varargin)
  srivc_form = any (strcmp (routine, {"rsrivc", "clrsrivc"}));
  closed = strncmp (routine, "cl", 2);
  if (srivc_form)
    method = "rsrivc";
    form = "f";
  else
    method = "rivsvf";
    form = "a";
  endif
  ## [] leaves an option to the core's default (recursive_options.hpp).
  defaults = struct ("lambda_svf", [], "adm", [], "adg", [], "th0", [],
                     "P0", [], "svf", [], "tsiv", [], "dtupdate", [],
                     "stability", [], "mtheta", [], "prefilter", [], "A", [],
                     "controller", [], "r1", [], "r2", [], "scaling", [],
                     "antiwindup", [], "antiwindup_lambda", [],
                     "precision", [], "covariance_guard", [],
                     "GapSettle", [], "InterSample", "");
  [d, orders, opts] = contsid_recursive_args (fname, form, defaults,
                                              varargin{:});
  ## The filters' rule for the input: the data's InterSample, or the
  ## option's (e.g. "trapezoid" for the thesis' Tustin filtering).
  d.intersample = contsid_filter_rule (fname, d, opts.InterSample);
  np = orders.np;
  na = orders.na;
  contsid_check_input (fname, d.u, orders.nb);
  ## Public order -> core order [a b].
  if (srivc_form)
    perm = [na+1:np, 1:na];         # thm_public = thm_core(:, perm)
  else
    perm = 1:np;
  endif
  iperm(perm) = 1:np;

  A = check_A (fname, opts.A, na, srivc_form);
  if (isempty (opts.lambda_svf) && ! isempty (A))
    ## The RLSSVF start needs a cut-off: the geometric mean of A's roots.
    opts.lambda_svf = A(end) ^ (1 / na);
  endif
  o = contsid_recursive_options (fname, opts, np, d);
  if (ischar (o.adm) && strcmp (o.adm, "lmr"))
    error ([fname ":badOption"], ...
           "%s: adm 'lmr' (LMR-RLSSVF) belongs to rlssvf", fname);
  endif
  if (isnumeric (opts.scaling) && ! isempty (opts.scaling)
      && numel (opts.scaling) == np)
    opts.scaling = opts.scaling(iperm);  # given in THM order
  endif
  o = contsid_ch3_options (fname, opts, orders, d, o);
  ## Qn, th0 and P0 are given in THM order: reordered when their size
  ## allows (the core checks the sizes).
  adg = o.adg;
  if (ischar (o.adm) && strcmp (o.adm, "kf") && isnumeric (adg)
      && isequal (size (adg), [np np]))
    adg = adg(iperm, iperm);
  endif
  th0 = o.th0;
  if (isnumeric (th0) && numel (th0) == np)
    th0 = th0(iperm);
  endif
  P0 = o.P0;
  if (isnumeric (P0) && isequal (size (P0), [np np]))
    P0 = P0(iperm, iperm);
  endif

  if (d.uniform)
    t = d.Ts;
    duration = (rows (d.y) - 1) * d.Ts;
  else
    t = d.t;
    duration = d.t(end) - d.t(1);
  endif
  tsiv = opts.tsiv;
  tsiv_detector = [];
  if (isempty (tsiv))
    tsiv = duration / 10;                # CONTSID default
  elseif ((ischar (tsiv) && strcmpi (tsiv, "auto")) || isstruct (tsiv))
    ## Detected convergence of the RLSSVF start (see help rlsconverge);
    ## a struct holds detector options. Scaling and precision do not
    ## change the RLSSVF estimates the detector examines, so they are not
    ## forwarded.
    det = {};
    if (isstruct (tsiv))
      det = tsiv;
    endif
    rls = struct ("lambda_svf", o.lambda_svf, "adm", o.adm, "adg", adg,
                  "th0", th0, "P0", P0, "svf", o.svf);
    nn_rls = [na, orders.nb, orders.nk];
    [tsiv, tsiv_detector] = contsid_converge (fname, d, nn_rls, rls, det,
                                              true);
  endif
  check_scalar (fname, tsiv, "tsiv");
  if (tsiv < 0 || tsiv > duration * (1 + 1e-12))
    error ([fname ":badInput"], ...
           "%s: tsiv = %g s lies outside the record [0, %g] s", fname, tsiv,
           duration);
  endif
  ## dtupdate below the sampling interval would name a refresh the data
  ## cannot give (the core checks it is finite and >= 0).
  dtupdate = opts.dtupdate;
  if (d.uniform && isnumeric (dtupdate) && isscalar (dtupdate)
      && dtupdate > 0 && dtupdate < d.Ts * (1 - 1e-9))
    error ([fname ":badInput"], ...
           ["%s: dtupdate (%g s) must not be below the sampling ", ...
            "interval (%g s)"],
           fname, dtupdate, d.Ts);
  endif
  [m_num, m_den] = check_mtheta (fname, opts.mtheta);

  c_num = []; c_den = []; r1 = []; r2 = [];
  if (closed)
    n = rows (d.y);
    [c_num, c_den] = check_controller (fname, opts.controller, d);
    if (isempty (opts.r1) && isempty (opts.r2))
      error ([fname ":badOption"], ...
             "%s: give the external signals r1 and/or r2 (the other is 0)",
             fname);
    endif
    if (isfield (d, "missing"))
      n = d.nfull;                       # r1, r2 cover the full record
    endif
    r1 = check_signal (fname, opts.r1, n, "r1");
    r2 = check_signal (fname, opts.r2, n, "r2");
    if (isfield (d, "missing"))
      r1 = r1(! d.missing);
      r2 = r2(! d.missing);
    endif
    if (orders.nb > 0 && columns (d.u) != 1)
      error ([fname ":badInput"], "%s: closed loop needs a single input",
             fname);
    endif
  else
    if (! isempty (opts.controller) || ! isempty (opts.r1)
        || ! isempty (opts.r2))
      error ([fname ":badOption"], ...
             "%s: controller, r1 and r2 belong to the closed-loop routines",
             fname);
    endif
  endif

  p = struct ("d", d, "orders", orders, "perm", perm, "tsiv", tsiv);
  p.tsiv_detector = tsiv_detector;
  p.data = {d.y, d.u, t};
  ## The gateway's options struct (mex/estimator_args.hpp), field by field.
  g.intersample = d.intersample;
  g.na = na;
  g.nb = orders.nb;
  g.nk = orders.nk;
  g.lambda_svf = o.lambda_svf;
  g.svf = o.svf;
  g.adm = o.adm;
  g.adg = adg;
  g.th0 = th0;
  g.P0 = P0;
  g.method = method;
  g.tsiv = tsiv;
  g.dtupdate = dtupdate;
  g.stability = lower_word (opts.stability);
  g.mtheta_num = m_num;
  g.mtheta_den = m_den;
  g.prefilter = lower_word (opts.prefilter);
  g.A = A;
  if (closed)
    g.controller_num = c_num;
    g.controller_den = c_den;
    g.r1 = r1;
    g.r2 = r2;
  endif
  g.scaling = o.scaling;
  g.antiwindup = o.antiwindup;
  g.antiwindup_lambda = o.antiwindup_lambda;
  g.precision = o.precision;
  g.covariance_guard = o.covariance_guard;
  [g.gap_interval, g.gap_settle] = gap_options (d, o);
  p.opts = g;
endfunction

function A = check_A (fname, A, na, allowed)
  if (isempty (A))
    A = [];
    return;
  endif
  if (! allowed)
    error ([fname ":badOption"], "%s: the option A belongs to rsrivc", fname);
  endif
  if (! isnumeric (A) || ! isreal (A) || ! isvector (A)
      || any (! isfinite (A)))
    error ([fname ":badInput"], "%s: A must be a finite real vector", fname);
  endif
  A = double (A(:).');
  if (numel (A) == na + 1)
    A = A(2:end) / A(1);
  elseif (numel (A) != na)
    error ([fname ":dimensionMismatch"], ...
           "%s: A must be [1 a1 .. a_nf] (%d coefficients)", fname, na + 1);
  endif
  if (any (real (roots ([1 A])) >= 0))
    error ([fname ":badInput"], "%s: A must be a stable polynomial", fname);
  endif
endfunction

function w = lower_word (w)
  if (ischar (w))
    w = lower (w);
  endif
endfunction

function [num, den] = check_mtheta (fname, m)
  num = []; den = [];
  if (isempty (m) || (ischar (m) && strcmpi (m, "delay")))
    return;                              # default q^-1 in the core
  endif
  if (ischar (m) && strcmpi (m, "none"))
    num = 1; den = 1;
    return;
  endif
  if (isnumeric (m))
    m = struct ("num", m, "den", 1);     # FIR
  endif
  if (! isstruct (m) || ! isscalar (m) || ! all (isfield (m, {"num", "den"})))
    error ([fname ":badInput"], ...
           ["%s: mtheta must be 'delay', 'none', FIR taps or a struct ", ...
            "with num and den"],
           fname);
  endif
  num = m.num; den = m.den;
  if (! isnumeric (num) || ! isnumeric (den) || ! isreal (num)
      || ! isreal (den) || isempty (num) || isempty (den)
      || ! isvector (num) || ! isvector (den))
    error ([fname ":badInput"], "%s: mtheta.num and .den must be real vectors",
           fname);
  endif
  num = double (num(:).'); den = double (den(:).');
endfunction

function [num, den] = check_controller (fname, C, d)
  if (isempty (C))
    error ([fname ":badOption"], "%s: the controller is required", fname);
  endif
  Ts = NaN;
  if (d.uniform)
    Ts = d.Ts;
  endif
  [num, den] = contsid_controller (fname, C, Ts);
endfunction

function r = check_signal (fname, r, n, what)
  if (isempty (r))
    r = zeros (n, 1);
    return;
  endif
  if (! isnumeric (r) || ! isreal (r) || ! isvector (r) || issparse (r)
      || any (! isfinite (r)))
    error ([fname ":badInput"], "%s: %s must be a finite real vector", fname,
           what);
  endif
  if (numel (r) != n)
    error ([fname ":dimensionMismatch"], ...
           "%s: %s must have one value per sample (%d), got %d", fname, what,
           n, numel (r));
  endif
  r = double (r(:));
endfunction

function check_scalar (fname, v, what)
  if (! isnumeric (v) || ! isreal (v) || ! isscalar (v) || ! isfinite (v))
    error ([fname ":badInput"], "%s: %s must be a finite real scalar", fname,
           what);
  endif
endfunction

## Gaps of missing samples (contsid_recursive_args bridged them): no update
## for GapSettle seconds after each (default 20 / lambda_svf).
function [interval, settle] = gap_options (d, o)
  interval = 0;
  settle = o.GapSettle;                  # [] unless given or gaps bridged
  if (isfield (d, "gap_interval"))
    interval = d.gap_interval;
  endif
endfunction
