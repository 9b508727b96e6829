## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn  {} {@var{y} =} simc (@var{M}, @var{data})
## @deftypefnx {} {@var{y} =} simc (@var{M}, @var{u}, @var{Ts})
## @deftypefnx {} {@var{y} =} simc (@var{THM}, @var{nn}, @var{data})
## @deftypefnx {} {@var{y} =} simc (@var{THM}, @var{nn}, @var{u}, @var{Ts})
## @deftypefnx {} {@var{y} =} simc (@dots{}, @var{SNR})
## @deftypefnx {} {@var{y} =} simc (@dots{}, @var{name}, @var{value})
## @deftypefnx {} {[@var{y}, @var{x}, @var{uc}] =} simc (@dots{})
## Simulate a continuous-time model, time-invariant or with time-varying
## parameters, on sampled input data, in open or closed loop.
##
## @strong{Model}
## @table @var
## @item M
## a continuous-time, time-invariant model: an @code{idpoly} (from
## @code{srivc}, @code{lssvf}, ..., or built, e.g.
## @code{idpoly (1, B, 1, 1, F, 0, 0, "InputDelay", [nk1 nk2] * Ts)}),
## @code{idtf}, @code{idproc}, @code{idss} or @code{idctm}; a struct with
## fields @code{B} (numerator coefficients in descending powers of p; a
## cell array of rows for several inputs), @code{F} (denominator,
## descending powers, normalised to be monic; one for all inputs or a cell
## with one per input) and optionally @code{nk} (input delays in samples);
## or a continuous-time @code{tf}/@code{ss} of the control package.
## Delays (InputDelay, IODelay, Td) are exact, also between samples
## (uniformly sampled data; the delayed ZOH or FOH input is integrated
## piece by piece).  Several outputs give one column each.  A model
## with one output and one denominator takes every option below; other
## models (several denominators or outputs, state space) take the noise
## options only.
## @item THM, nn
## a model with time-varying parameters: @var{nn} = [na nb nk] as in
## @code{rlssvf}, and @var{THM} an N-by-np matrix of the parameters
## [a1 .. a_na, b0 .. b_(nb-1)] at every sample (linear in between), or a
## single row (time-invariant). A true trajectory, or the output
## @var{thm} of a recursive estimator.
## @item M (idtraced)
## a model @code{residtrace} returned (@code{R.model},
## @code{R.final_model}): simulated as @code{residtrace} simulated it,
## levels and effects included, in the forms @code{simc (M, data)} and
## @code{simc (M, u, Ts)} without options (see @code{help idtraced/sim}
## for what the measured output in @var{data} is then used for).
## @end table
##
## @strong{Data}: an @code{iddata} object, input-only
## (@code{iddata ([], u, Ts, "InterSample", "zoh")}) or with outputs (its
## input, sampling and InterSample are used), or numeric @var{u}
## (N-by-nu) and @var{Ts} (scalar) or the N sampling instants. For
## irregularly sampled iddata without a given InterSample, the input's
## rule is chosen from its smoothness, as CONTSID's @code{simc} does:
## held (ZOH) when every change is followed by a sample without change,
## else linear between the instants (FOH).  The response is then exact for
## that input (not a Runge-Kutta approximation).
##
## @strong{Options}
## @table @code
## @item SNR
## add white Gaussian noise (@code{randn}) for this signal-to-noise ratio in
## dB, 10 log10 (P_x / P_e) with P the mean square (thesis eq. 1.64). Also
## accepted as a trailing positional number.
## @item noisevar
## add white Gaussian noise of this variance.
## @item noise
## add this N-by-1 noise sequence.
## @item InterSample
## @qcode{"zoh"} (default for numeric data) or @qcode{"foh"}: the input is
## held or linear between samples.
## @item x0
## initial state (na*nu values; the derivatives w, w', .. of each input's
## controllable canonical state), default at rest.
## @item substeps
## integration sub-steps per sample (default 1), for fast parameter changes.
## @item Levels
## @qcode{"carried"} (default): a model that carries levels (@code{srivc}
## on a raw record stores them in @code{M.Report.DataUsed.InputOffset}
## and @code{OutputOffset}; see @code{help idpoly}) is simulated as it
## was estimated, y = c + M (u - d) from rest at those levels: the input
## data are in the record's raw units and so is @var{y} (@var{x} too;
## @var{uc} is the raw input). @qcode{"ignore"}: the model alone, as
## MATLAB's @code{sim}; remove the offsets from the data yourself.
## SNR is measured on the response about the levels.
## @item controller, r2
## closed loop u = r1 + C(q^-1) (r2 - y) (thesis eq. 2.39): the controller
## as a struct with fields @code{num} and @code{den} (coefficients of
## q^0, q^-1, ..), or with fields @code{kp}, @code{ki}, @code{kd} for the
## backward-Euler PID kp + ki Ts/(1 - q^-1) + (kd/Ts)(1 - q^-1) (thesis
## eq. 2.55); and the N-by-1 reference r2; the input data are then r1.
## The measured y (with noise) is fed back.
## @end table
##
## @strong{Outputs}: @var{y} the simulated output with noise if asked,
## @var{x} the noise-free output, @var{uc} the input applied to the system
## (differs from the data in closed loop).
##
## Option @code{"InitialCondition"}: @qcode{"z"} (default, from rest) or
## @qcode{"e"}: with iddata input data that carry the measured output, the
## model's initial state is estimated on that output (least squares on the
## free responses, the refined-IV engine with every coefficient fixed) and
## its free response is added to the simulated output.
##
## @strong{Algorithm.} Each input's transfer function is realised in
## controllable canonical form (for nb = 1 the gain enters with the input, so
## x^(na) + a1(t) x^(na-1) + .. = b0(t) u is solved exactly); the input is
## appended to the state and each sampling interval is integrated by the
## fourth-order Magnus method, exact for time-invariant models. Its matrix
## exponential is taken of the balanced generator (a diagonal similarity,
## as MATLAB's and Octave's @code{expm}), so that high-order models with
## widely spread or lightly damped poles, whose canonical coefficients span
## many decades, are simulated accurately.
##
## @strong{Example}
## @example
## u = prbs (8, 4); Ts = 0.1;
## y = simc (struct ("B", 4, "F", [1 2.4 4]), u, Ts, "SNR", 20);
## @end example
## @seealso{rlssvf, prbs, iddata}
## @end deftypefn

function varargout = simc (varargin)
  varargout = contsid_guard ("simc", @simc_body, nargout, varargin);
endfunction

function varargout = simc_body (varargin)
  contsid_nargchk ("simc", nargin, nargout, [0 Inf], 3);
  fname = "simc";
  if (nargin < 2)
    error ("simc:badInput", "simc: expected a model and input data");
  endif
  if (isa (varargin{1}, "idtraced"))
    varargout = traced_sim (fname, varargin{1}, varargin(2:end));
    varargout(nargout+1:end) = [];
    return;
  endif
  [model, theta, orders, rest] = parse_model (fname, varargin);
  [u, t, intersample, rest] = parse_input (fname, rest);
  n = rows (u);
  if (! isempty (rest) && isnumeric (rest{1}) && isscalar (rest{1}))
    rest = [{"SNR"}, rest];
  endif
  if (! isempty (model))
    [theta, orders, model] = read_model (fname, model, u, t);
  endif
  defaults = struct ("SNR", [], "noisevar", [], "noise", [],
                     "InterSample", [], "x0", [], "substeps", 1,
                     "controller", [], "r2", [], "InitialCondition", "z",
                     "Levels", "carried");
  opts = contsid_options (fname, defaults, rest);
  ## The model's levels (doc/manual/levels.md), applied here once
  ## for every kind of model: y = c + M (u - d), from rest at them.
  ny = 1;
  if (isstruct (model))
    ny = model.ny;
  endif
  [c_lev, d_lev] = contsid_carried_levels (varargin{1}, columns (u), fname,
                                           opts.Levels, ny);
  u_raw = u;
  u -= d_lev;
  if (! isempty (opts.InterSample))
    intersample = check_intersample (fname, opts.InterSample);
  endif
  if (! isstruct (model) && rows (theta) != 1 && rows (theta) != n)
    error ("simc:dimensionMismatch", ...
           "simc: THM must have one row or one row per sample (%d), got %d",
           n, rows (theta));
  endif
  substeps = opts.substeps;
  if (! isnumeric (substeps) || ! isreal (substeps) || ! isscalar (substeps)
      || substeps != fix (substeps) || substeps < 1 || substeps > 1e4)
    error ("simc:badInput", "simc: substeps must be an integer in [1, 1e4]");
  endif
  x0 = real_matrix (fname, opts.x0, "x0");
  [c_num, c_den, r2] = parse_controller (fname, opts, n, t);
  if (isstruct (model))
    ## several outputs, a denominator per input or a state-space model
    if (! isempty (c_num) || ! isempty (x0))
      error ("simc:notSupported",
             ["simc: controller and x0 need a single-output model with ", ...
              "one denominator"]);
    endif
    x = simulate_model (model, u, t, intersample, substeps);
    e = noise (opts, x);
    x += c_lev;
    varargout = {x + e, x, u_raw};
    return;
  endif

  given = ! [isempty(opts.SNR), isempty(opts.noisevar), isempty(opts.noise)];
  if (sum (given) > 1)
    error ("simc:badOption", ...
           "simc: give at most one of SNR, noisevar and noise");
  endif
  e = [];
  if (given(3))
    e = real_matrix (fname, opts.noise, "noise");
    if (! isvector (e) || numel (e) != n)
      error ("simc:dimensionMismatch", ...
             "simc: noise must have one value per sample (%d)", n);
    endif
    e = e(:);
  elseif (given(2))
    v = real_matrix (fname, opts.noisevar, "noisevar");
    if (! isscalar (v) || v < 0)
      error ("simc:badInput", "simc: noisevar must be a scalar >= 0");
    endif
    e = sqrt (v) * randn (n, 1);
  elseif (given(1))
    snr = real_matrix (fname, opts.SNR, "SNR");
    if (! isscalar (snr))
      error ("simc:badInput", "simc: SNR must be a real scalar (dB)");
    endif
    ## P_x of the noise-free output (in closed loop: of the noise-free loop).
    xf = call_gateway (1, u, t, intersample, orders, theta, substeps, x0,
                       [], c_num, c_den, r2 - c_lev);
    e = randn (n, 1);
    e = e * sqrt (mean (xf .^ 2) / 10 ^ (snr / 10)) / sqrt (mean (e .^ 2));
  endif
  ## The gateway returns [x, y, uc]; simc returns [y, x, uc]. In closed
  ## loop u = r1 + C (r2 - y) with y = c + x reads u - d = (r1 - d) +
  ## C ((r2 - c) - (y - c)): the loop about the levels.
  outs = cell (1, max (2, nargout));
  [outs{:}] = call_gateway (numel (outs), u, t, intersample, orders, theta,
                            substeps, x0, e, c_num, c_den, r2 - c_lev);
  outs{1} += c_lev;
  outs{2} += c_lev;
  if (numel (outs) > 2)
    outs{3} += d_lev;
  endif
  varargout = outs([2 1 3:end]);
  ic = opts.InitialCondition;
  if (! ischar (ic) || ! any (strcmpi (ic, {"z", "e", "zero", "estimate"})))
    error ("simc:badOption",
           "simc: InitialCondition must be 'z' (zero) or 'e' (estimate)");
  endif
  if (any (strcmpi (ic, {"e", "estimate"})))
    ## The free response of the initial state, fitted to the measured
    ## output of the iddata given as input data (with the refined-IV
    ## engine, every model coefficient fixed).
    if (! isa (varargin{2}, "iddata") || isempty (get (varargin{2},
                                                       "OutputData"))
        || rows (theta) != 1 || ! isempty (c_num))
      error ("simc:badOption", ["simc: InitialCondition 'e' needs iddata ", ...
                                "with the measured output and a constant ", ...
                                "open-loop model"]);
    endif
    xe = contsid_initial_state (fname, varargin{1},
                                get (varargin{2}, "OutputData"), outs{1}, t);
    y0 = xe - outs{1};
    varargout{1} += y0;
    if (numel (varargout) > 1)
      varargout{2} += y0;
    endif
  endif
endfunction

## A model residtrace returned (idtraced): its one simulation
## (residtrace_model_sim), on the record's raw input; with an iddata that
## carries the measured output, what residtrace fits on such a record is
## fitted to it.
function out = traced_sim (fname, M, args)
  if (! isempty (args) && isa (args{1}, "iddata")
      && ! isempty (get (args{1}, "OutputData")))
    try
      [d, miss] = contsid_getdata (fname, args{1});
      d = residtrace_bridge (d, miss);
    catch err
      error (struct ("identifier", regexprep (err.identifier, '^[^:]*:',
                                              [fname ':']),
                     "message", regexprep (err.message, '^[^:]*:',
                                           [fname ':'])));
    end_try_catch
    rest = args(2:end);
  else
    [u, t, intersample, rest] = parse_input (fname, args);
    if (! isscalar (t))
      error ("simc:badInput",
             "simc: a residtrace model needs uniformly sampled data");
    endif
    d = struct ("y", [], "u", u, "Ts", t, "intersample", intersample,
                "missing", false (rows (u), 1));
  endif
  if (! isempty (rest))
    error ("simc:notSupported",
           ["simc: a residtrace model (idtraced) is simulated as ", ...
            "residtrace scored it: no options"]);
  endif
  y = residtrace_model_sim (fname, struct (M).model, d);
  out = {y, y, d.u};
endfunction

function varargout = call_gateway (nout, u, t, intersample, orders, theta,
                                    substeps, x0, e, c_num, c_den, r2)
  try
    g = struct ("intersample", intersample, "na", orders.na,
                "nb", orders.nb, "nk", orders.nk, "substeps", substeps,
                "x0", x0, "noise", e);
    if (! isempty (c_num))
      g.controller_num = c_num;
      g.controller_den = c_den;
      g.r2 = r2;
    endif
    [varargout{1:nout}] = simc_mex ("simc", u, t, theta, g);
  catch err
    contsid_rethrow (err);
  end_try_catch
endfunction

function [model, theta, orders, rest] = parse_model (fname, args)
  M = args{1};
  model = [];
  theta = [];
  orders = [];
  if (isobject (M) || isstruct (M))
    model = M;
    rest = args(2:end);
  elseif (isnumeric (M) && numel (args) >= 3)
    theta = real_matrix (fname, M, "THM");
    nn = real_matrix (fname, args{2}, "nn");
    if (isempty (nn) || ! isvector (nn) || any (nn != fix (nn)))
      error ("simc:badInput",
             "simc: nn must be a vector of integers [na nb nk]");
    endif
    if (numel (nn) == 2)
      nn(3) = 0;
    endif
    if (numel (nn) != 3)
      error ("simc:badInput", "simc: nn must be [na nb nk] (single input)");
    endif
    orders = struct ("na", nn(1), "nb", nn(2), "nk", nn(3));
    if (nn(1) < 1 || nn(2) < 1 || nn(2) > nn(1) + 1 || nn(3) < 0)
      error ("simc:badInput", ...
             "simc: nn needs na >= 1, 1 <= nb <= na + 1 and nk >= 0");
    endif
    if (columns (theta) != nn(1) + nn(2))
      error ("simc:dimensionMismatch", ...
             "simc: THM must have na + nb = %d columns, got %d",
             nn(1) + nn(2), columns (theta));
    endif
    rest = args(3:end);
  else
    error ("simc:badInput", ...
           ["simc: the model must be an idpoly, idtf, idproc, idss (or ", ...
            "idctm), a struct with B and F, a tf/ss, or THM with nn"]);
  endif
endfunction

## A time-invariant model: read once (contsid_model).  A single-output
## model with one denominator becomes theta and orders for the gateway
## (all options apply); anything else stays a model struct for
## simulate_model.
function [theta, orders, m] = read_model (fname, M, u, t)
  Ts = NaN;
  if (isscalar (t))
    Ts = t;
  endif
  m = contsid_model (fname, M, Ts, ! isnan (Ts));
  theta = [];
  orders = [];
  if (m.Ts > 0)
    error ("simc:notSupported",
           ["simc: simulates continuous-time models; this one is ", ...
            "discrete-time (Ts = %g): use sim"], m.Ts);
  endif
  if (columns (u) != m.nu)
    error ("simc:dimensionMismatch",
           "simc: the model has %d input(s), the data %d", m.nu, columns (u));
  endif
  if (strcmp (m.kind, "ss") || m.ny > 1 || ! m.common
      || any (m.nk(:) != fix (m.nk(:))))
    if (strcmp (m.kind, "tf"))
      check_orders (m);
    endif
    return;
  endif
  check_orders (m);
  F = m.F{1};
  a = F(2:end);
  b = [];
  nb = zeros (1, m.nu);
  for j = 1:m.nu
    nb(j) = numel (trim (m.B{j}));
    b = [b, trim(m.B{j})];
  endfor
  theta = [a, b];
  orders = struct ("na", numel (a), "nb", nb, "nk", m.nk(1, :));
  m = [];
endfunction

function check_orders (m)
  for k = 1:numel (m.F)
    if (numel (m.F{k}) < 2)
      error ("simc:badInput", ...
             "simc: F must be [1 a1 .. a_na] with na >= 1");
    endif
    if (numel (trim (m.B{k})) > numel (m.F{k}))
      error ("simc:badInput", ...
             ["simc: the model is improper (numerator degree above ", ...
              "the denominator's)"]);
    endif
  endfor
endfunction

function b = trim (b)
  first = find (b != 0, 1);
  if (isempty (first))
    b = 0;
  else
    b = b(first:end);
  endif
endfunction

## Noise-free output of a model struct: a state-space model exactly
## (the gateway's state-space method), a transfer-function model input by
## input through the gateway (the responses add up).
function x = simulate_model (m, u, t, intersample, substeps)
  n = rows (u);
  if (strcmp (m.kind, "ss"))
    x = simulate_ss (m.a, m.b, m.c, m.d, u, t, intersample, m.nk);
    return;
  endif
  x = zeros (n, m.ny);
  for i = 1:m.ny
    for j = 1:m.nu
      b = trim (m.B{i, j});
      if (all (b == 0))
        continue;
      endif
      if (m.nk(i, j) != fix (m.nk(i, j)))
        ## a delay between samples: exact in state space
        [a, bb, c, d] = canonical (b, m.F{i, j});
        x(:, i) += simulate_ss (a, bb, c, d, u(:, j), t, intersample,
                                m.nk(i, j));
        continue;
      endif
      orders = struct ("na", numel (m.F{i, j}) - 1, "nb", numel (b),
                       "nk", m.nk(i, j));
      x(:, i) += call_gateway (1, u(:, j), t, intersample, orders,
                               [m.F{i, j}(2:end), b], substeps, [], [], [],
                               [], []);
    endfor
  endfor
endfunction

## x' = a x + b u, y = c x + d u from rest, exact for a ZOH or FOH input,
## nk: ny-by-nu delays in samples, fractional with a sampling interval.
function y = simulate_ss (a, b, c, d, u, t, intersample, nk)
  try
    y = simc_mex ("simc", "state_space", u, t,
                  struct ("a", a, "b", b, "c", c, "d", d, "nk", nk,
                          "intersample", intersample));
  catch err
    contsid_rethrow (err);
  end_try_catch
endfunction

## Controllable canonical realisation of b(p) / f(p), f monic, deg b <=
## deg f.
function [a, b, c, d] = canonical (num, den)
  n = numel (den) - 1;
  num = [zeros(1, n + 1 - numel (num)), num];
  d = num(1);
  r = num(2:end) - d * den(2:end);     # strictly proper remainder
  a = [-den(2:end); eye(n - 1, n)];
  b = [1; zeros(n - 1, 1)];
  c = r;
endfunction

## Additive output noise of the SNR / noisevar / noise options, one
## column per output.
function e = noise (opts, x)
  [n, ny] = size (x);
  e = zeros (n, ny);
  given = ! [isempty(opts.SNR), isempty(opts.noisevar), isempty(opts.noise)];
  if (sum (given) > 1)
    error ("simc:badOption", ...
           "simc: give at most one of SNR, noisevar and noise");
  endif
  if (given(3))
    e = real_matrix ("simc", opts.noise, "noise");
    if (rows (e) != n && numel (e) == n)
      e = e(:);
    endif
    if (! isequal (size (e), [n ny]))
      error ("simc:dimensionMismatch",
             "simc: noise must be %d-by-%d", n, ny);
    endif
  elseif (given(2))
    v = real_matrix ("simc", opts.noisevar, "noisevar");
    if (! isscalar (v) || v < 0)
      error ("simc:badInput", "simc: noisevar must be a scalar >= 0");
    endif
    e = sqrt (v) * randn (n, ny);
  elseif (given(1))
    snr = real_matrix ("simc", opts.SNR, "SNR");
    if (! isscalar (snr))
      error ("simc:badInput", "simc: SNR must be a real scalar (dB)");
    endif
    e = randn (n, ny);
    e = e .* sqrt (mean (x .^ 2) / 10 ^ (snr / 10)) ./ sqrt (mean (e .^ 2));
  endif
endfunction

function [u, t, intersample, rest] = parse_input (fname, args)
  if (isempty (args))
    error ("simc:badInput", "simc: the input data are missing");
  endif
  if (isa (args{1}, "iddata"))
    [u, t, intersample] = input_data (fname, args{1});
    rest = args(2:end);
    return;
  endif
  if (numel (args) < 2)
    error ("simc:badInput", "simc: give the input u and Ts (or the instants)");
  endif
  u = real_matrix (fname, args{1}, "u");
  if (isrow (u))
    u = u(:);
  endif
  if (isempty (u) || any (! isfinite (u(:))))
    error ("simc:badInput", "simc: u must be non-empty and finite");
  endif
  t = real_matrix (fname, args{2}, "Ts");
  if (isscalar (t))
    if (! (t > 0) || ! isfinite (t))
      error ("simc:badInput", "simc: Ts must be finite and > 0");
    endif
  else
    t = t(:);
    if (numel (t) != rows (u))
      error ("simc:dimensionMismatch", ...
             "simc: the sampling instants must have one entry per sample");
    endif
  endif
  intersample = "zoh";
  rest = args(3:end);
endfunction

## The input signals and sampling of an iddata set, with or without
## outputs (iddata ([], u, Ts) as CONTSID builds them).
function [u, t, intersample] = input_data (fname, data)
  [~, ny, nu, ne] = size (data);
  if (ne != 1)
    error ("simc:badInput", "simc: the data must hold one experiment");
  endif
  if (nu == 0)
    error ("simc:badInput", "simc: the data have no input");
  endif
  if (ny > 0)
    d = contsid_getdata (fname, data);
    u = d.u;
    t = merge (d.uniform, d.Ts, d.t);
    intersample = d.intersample;
    return;
  endif
  info = samplinginfo (data);
  u = get (data, "InputData");
  if (iscell (u))
    u = u{1};
  endif
  u = real_matrix (fname, u, "u");
  if (isempty (u) || any (! isfinite (u(:))))
    error ("simc:badInput", "simc: u must be non-empty and finite");
  endif
  if (info.Uniform && info.Ts > 0)
    t = info.Ts;
  elseif (! info.Uniform)
    t = info.SamplingInstants(:);
  else
    error ("simc:badInput", "simc: the data have no sampling interval");
  endif
  intersample = contsid_intersample (u, info);
endfunction

function [c_num, c_den, r2] = parse_controller (fname, opts, n, Ts)
  c_num = [];
  c_den = [];
  r2 = [];
  C = opts.controller;
  if (isempty (C))
    if (! isempty (opts.r2))
      error ("simc:badOption", "simc: r2 needs a controller");
    endif
    return;
  endif
  [c_num, c_den] = contsid_controller (fname, C, Ts);
  r2 = opts.r2;
  if (isempty (r2))
    r2 = zeros (n, 1);
  endif
  r2 = real_matrix (fname, r2, "r2");
  if (! isvector (r2) || numel (r2) != n)
    error ("simc:dimensionMismatch", "simc: r2 must have one value per sample");
  endif
  r2 = r2(:);
endfunction

function s = check_intersample (fname, s)
  if (! ischar (s) || ! any (strcmpi (s, {"zoh", "foh"})))
    error ("simc:badOption", "simc: InterSample must be 'zoh' or 'foh'");
  endif
  s = lower (s);
endfunction

function x = real_matrix (fname, x, what)
  if (! isnumeric (x) || ! isreal (x) || ndims (x) > 2)
    error ([fname ":badInput"], "%s: %s must be a real numeric matrix",
           fname, what);
  endif
  x = double (x);
endfunction

%!test  # LTI step response of a second-order system (exact)
%! Ts = 0.1; u = ones (100, 1); t = (0:99)' * Ts;
%! y = simc (struct ("B", 4, "F", [1 2.4 4]), u, Ts);
%! wd = 2 * sqrt (1 - 0.36);
%! exact = 1 - exp (-1.2 * t) .* (cos (wd * t) + 1.2 / wd * sin (wd * t));
%! assert (y, exact, 1e-12);

%!test  # the same model as THM with nn, and as a control tf
%! u = prbs (6, 3); Ts = 0.1;
%! a = simc (struct ("B", 4, "F", [1 2.4 4]), u, Ts);
%! b = simc ([2.4 4 4], [2 1 0], u, Ts);
%! assert (a, b, 0);
%! pkg load control
%! c = simc (tf (4, [1 2.4 4]), u, Ts);
%! assert (a, c, 1e-14);

%!test  # time-varying gain: (p + 1) x = b0(t) u, b0 = 1 + t, u = 1
%! Ts = 0.01; n = 301; t = (0:n-1)' * Ts;
%! y = simc ([ones(n, 1), 1 + t], [1 1 0], ones (n, 1), Ts);
%! assert (y, t, 1e-9);   # x = t solves x' + x = 1 + t, x(0) = 0

%!test  # SNR of the added noise
%! randn ("seed", 1);
%! u = prbs (10, 4); Ts = 0.1;
%! [y, x] = simc (struct ("B", 4, "F", [1 2.4 4]), u, Ts, "SNR", 10);
%! assert (10 * log10 (mean (x .^ 2) / mean ((y - x) .^ 2)), 10, 1e-10);
%! [y2, x2] = simc (struct ("B", 4, "F", [1 2.4 4]), u, Ts, 10);
%! assert (x2, x, 0);

%!test  # iddata input, delay, closed loop with a PI controller
%! u = prbs (7, 5); Ts = 0.05; n = numel (u);
%! d = iddata (zeros (n, 1), u, Ts, "InterSample", "zoh");
%! a = simc (struct ("B", 2, "F", [1 1.5], "nk", 3), d);
%! b = simc (struct ("B", 2, "F", [1 1.5]), u, Ts);
%! assert (a(4:end), b(1:end-3), 1e-12);
%! C = struct ("num", [0.8 + 1.2 * Ts, -0.8], "den", [1 -1]);
%! [y, x, uc] = simc (struct ("B", 2, "F", [1 1.5]), zeros (n, 1), Ts, ...
%!                    "controller", C, "r2", ones (n, 1));
%! assert (y(end), 1, 1e-3);   # the integral action removes the error
%! y2 = simc (struct ("B", 2, "F", [1 1.5]), zeros (n, 1), Ts, ...
%!            "controller", struct ("kp", 0.8, "ki", 1.2, "kd", 0), ...
%!            "r2", ones (n, 1));
%! assert (y2, y, 1e-12);      # the same PI given by its gains

%!test  # SITB models on input-only data: MISO idpoly, delays per input
%! Ts = 0.05; u = [prbs(7, 3), prbs(7, 5)(1:381)]; n = rows (u);
%! M = idpoly (1, {2, [1 3]}, 1, 1, {[1 1.5], [1 2 5]}, 0, 0,
%!             "InputDelay", [2 5] * Ts);
%! y = simc (M, iddata (zeros (n, 0), u, Ts, "InterSample", "zoh"));
%! y1 = simc (struct ("B", 2, "F", [1 1.5]), u(:, 1), Ts);
%! y2 = simc (struct ("B", [1 3], "F", [1 2 5]), u(:, 2), Ts);
%! assert (y, [zeros(2, 1); y1(1:end-2)] + [zeros(5, 1); y2(1:end-5)],
%!         1e-12);

%!test  # idss and idtf against the control package's exact ZOH model
%! pkg load control
%! Ts = 0.1; u = prbs (6, 4); n = numel (u); t = (0:n-1)' * Ts;
%! A = [-1 2; -2 -1]; B = [0; 1]; C = [1 0]; D = 0.5;
%! y = simc (idss (A, B, C, D), u, Ts);
%! yc = lsim (c2d (ss (A, B, C, D), Ts, "zoh"), u, t);
%! assert (y, yc, 1e-10);
%! G = idtf (2, [1 3 2], "IODelay", 3 * Ts);
%! yg = simc (G, u, Ts);
%! yc = lsim (c2d (tf (2, [1 3 2]), Ts, "zoh"), u, t);
%! assert (yg, [0; 0; 0; yc(1:end-3)], 1e-10);

%!test  # a two-output idtf: one column per output
%! u = prbs (6, 3); Ts = 0.1;
%! y = simc (idtf ({1; 2}, {[1 1]; [1 2]}), u, Ts);
%! assert (y, [simc(idtf (1, [1 1]), u, Ts), simc(idtf (2, [1 2]), u, Ts)],
%!         1e-14);

%!test  # a delay between samples: the same as on a grid twice as fine
%! ## (the input starts at rest, so that the FOH ramp before the first
%! ## sample, one sampling interval long, is the same on both grids)
%! Ts = 0.1; u = [zeros(3, 1); prbs(6, 3)]; n = numel (u);
%! G = idtf ([1 4], [1 2.4 4], "IODelay", 0.25);
%! for is = {"zoh", "foh"}
%!   y = simc (G, u, Ts, "InterSample", is{1});
%!   u2 = kron (u, [1; 1]);
%!   if (strcmp (is{1}, "foh"))       # the piecewise-linear input, finer
%!     u2 = interp1 ((0:n-1)', u, (0:2*n-1)' / 2, "linear", "extrap");
%!     u2(end) = u(end);
%!   endif
%!   y2 = simc (idtf ([1 4], [1 2.4 4], "IODelay", 0.25), u2, Ts / 2,
%!              "InterSample", is{1});
%!   ## 0.25 s = 5 fine samples: integer there, fractional on Ts
%!   assert (y, y2(1:2:end), 1e-10);
%! endfor

%!test  # whole and fractional delays together, with feedthrough: the sum
%! ## of the single-input responses (the whole delay's feedthrough reads
%! ## the input at the sample itself)
%! Ts = 0.1; k = (0:99)'; u = [sign(sin(k / 5)), sign(cos(k / 7))];
%! A = [-1 2; -2 -1]; B = [0 1; 1 0.5]; C = [1 0.3]; D = [0.5 -0.2];
%! for is = {"zoh", "foh"}
%!   y = simc (idss (A, B, C, D, "InputDelay", [0; 0.25]), u, Ts,
%!             "InterSample", is{1});
%!   y1 = simc (idss (A, B(:, 1), C, D(1)), u(:, 1), Ts, "InterSample", is{1});
%!   y2 = simc (idss (A, B(:, 2), C, D(2), "InputDelay", 0.25), u(:, 2), Ts,
%!              "InterSample", is{1});
%!   assert (y, y1 + y2, 1e-13);
%! endfor

%!test  # FOH on a ramp is exact: 1/(s+1) driven by u = t
%! Ts = 0.2; t = (0:50)' * Ts;
%! y = simc (idss (-1, 1, 1, 0), iddata (zeros (51, 0), t, Ts,
%!                                       "InterSample", "foh"));
%! assert (y, t - 1 + exp (-t), 1e-12);
%! y2 = simc (idproc ("P1", "Kp", 1, "Tp1", 1), t, Ts, "InterSample", "foh");
%! assert (y2, t - 1 + exp (-t), 1e-12);

%!test  # the levels a model carries: y = c + M (u - d), from rest at them
%! u = 5 + prbs (6, 3); Ts = 0.1;
%! M = idtf (2, [1 1.2 1]);
%! y0 = simc (M, u - 5, Ts);
%! M.Report.DataUsed.InputOffset = 5;
%! M.Report.DataUsed.OutputOffset = 20;
%! [y, x, uc] = simc (M, u, Ts);
%! assert (y, 20 + y0, 1e-12);
%! assert (x, y, 0);
%! assert (uc, u, 0);
%! assert (simc (M, u - 5, Ts, "Levels", "ignore"), y0, 0);
%! ## several outputs (state space): one output level each
%! S = idss ([-1 0; 0 -2], [1; 1], eye (2), [0; 0]);
%! S.Report.DataUsed.InputOffset = 5;
%! S.Report.DataUsed.OutputOffset = [1 2];
%! assert (simc (S, u, Ts), simc (S, u - 5, Ts, "Levels", "ignore") + [1 2],
%!         1e-12);

%!error id=simc:badOption simc (idtf (1, [1 1]), ones (5, 1), 0.1, "Levels", "raw")
%!error <Report.DataUsed.InputOffset>
%! M = idtf (1, [1 1]); M.Report.DataUsed.InputOffset = [1 2];
%! simc (M, ones (5, 1), 0.1);
%!error id=simc:notSupported simc (idpoly (1, [0 1], 1, 1, [1 -0.5], 1, 0.1), ones (5, 1), 0.1)
%!error id=simc:notSupported simc (idtf (1, [1 1], "IODelay", 0.15), ones (5, 1), [0 0.1 0.2 0.4 0.5])
%!error id=simc:dimensionMismatch simc (idtf (1, [1 1]), ones (5, 2), 0.1)
%!error id=simc:badInput simc (idproc ("P1"), ones (5, 1), 0.1)
%!error id=simc:notSupported simc (idfrd (1, 1), ones (5, 1), 0.1)
%!error id=simc:notSupported simc (idss (-1, [1 1], 1, [0 0]), ones (5, 2), 0.1, "x0", [1 2])
%!error id=simc:badInput simc ()
%!error id=simc:badInput simc (struct ("B", 1), ones (5, 1), 0.1)
%!error id=simc:badInput simc (struct ("B", 1, "F", 1), ones (5, 1), 0.1)
%!error id=simc:badInput simc (struct ("B", [1 2 3], "F", [1 1]), ones (5, 1), 0.1)
%!error id=simc:badInput simc (struct ("B", 1, "F", [1 1], "nk", -1), ones (5, 1), 0.1)
%!error id=simc:badInput simc ("model", ones (5, 1), 0.1)
%!error id=simc:badInput simc ([1 1], [1 1 0], ones (5, 1), 0)
%!error id=simc:badInput simc ([1 1], [1 1 0], [1; NaN; 1], 0.1)
%!error id=simc:badInput simc ([1 1], [1 1.5 0], ones (5, 1), 0.1)
%!error id=simc:badInput simc ([1 1], [1 3 0], ones (5, 1), 0.1)
%!error id=simc:dimensionMismatch simc ([1 1 1], [1 1 0], ones (5, 1), 0.1)
%!error id=simc:dimensionMismatch simc (ones (3, 2), [1 1 0], ones (5, 1), 0.1)
%!error id=simc:dimensionMismatch simc ([1 1], [1 1 0], ones (5, 1), (0:3)')
%!error id=simc:badInput simc ([1 1], [1 1 0], ones (5, 1), [0 1 1 2 3]')
%!error id=simc:badInput simc ([1 1], [1 1 0], ones (5, 1), 0.1, "substeps", 0)
%!error id=simc:badOption simc ([1 1], [1 1 0], ones (5, 1), 0.1, "SNR", 1, "noisevar", 1)
%!error id=simc:badOption simc ([1 1], [1 1 0], ones (5, 1), 0.1, "bogus", 1)
%!error id=simc:badOption simc ([1 1], [1 1 0], ones (5, 1), 0.1, "InterSample", "x")
%!error id=simc:badOption simc ([1 1], [1 1 0], ones (5, 1), 0.1, "r2", ones (5, 1))
%!error id=simc:badInput simc ([1 1], [1 1 0], ones (5, 1), 0.1, "controller", 3)
%!error id=simc:badInput simc ([1 1], [1 1 0], ones (5, 1), 0.1, "controller", struct ("num", 1, "den", 0))
%!error id=simc:badInput simc ([1 1], [1 1 0], ones (5, 1), 0.1, "controller", struct ("kp", 1, "ki", "a", "kd", 0))
%!error id=simc:dimensionMismatch simc ([1 1], [1 1 0], ones (5, 1), 0.1, "noise", ones (3, 1))
%!error id=simc:badInput simc ([1 1], [1 1 0], ones (5, 1), 0.1, "noisevar", -1)
%!error id=simc:badInput simc ([1 1], [1 1 0], ones (5, 1), 0.1, "SNR", "high")
%!error id=simc:badInput simc ([1 1], [1 1 0], ones (5, 1), 0.1, "x0", {1})
%!error id=simc:dimensionMismatch simc ([1 1], [1 1 0], ones (5, 1), 0.1, "x0", [1 2])
%!error id=simc:numericalFailure simc ([-800 1], [1 1 0], ones (2000, 1), 0.1)

%!demo
%! ## Step responses of a second-order system whose natural frequency drifts.
%! Ts = 0.05; n = 2000; t = (0:n-1)' * Ts;
%! wn = 2 * (1 + 0.3 * cos (2 * pi * t / t(end)));
%! theta = [1.2 * wn, wn .^ 2, wn .^ 2];
%! y = simc (theta, [2 1 0], double (mod (t, 10) < 5), Ts);
%! plot (t, y); xlabel ("t (s)"); ylabel ("y");

%!test  # InitialCondition 'e': the free response fitted to the measured y
%! pkg load control
%! u = prbs (8, 6); Ts = 0.05; N = numel (u); t = (0:N-1)' * Ts;
%! M = idctm (4, [1 2.4 4]);
%! [a, b, c] = ssdata (ss (tf (4, [1 2.4 4])));
%! yfree = arrayfun (@(tk) c * expm (a * tk) * [1; -2], t);
%! y = simc (M, u, Ts) + yfree;
%! ye = simc (M, iddata (y, u, Ts), "InitialCondition", "e");
%! assert (ye, y, 1e-8);

%!error id=simc:badOption simc (idctm (4, [1 2.4 4]), ones (20, 1), 0.1, "InitialCondition", "e")
%!error id=simc:badOption simc (idctm (4, [1 2.4 4]), ones (20, 1), 0.1, "InitialCondition", "q")
