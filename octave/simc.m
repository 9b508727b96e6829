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
## a time-invariant model: an @code{idctm} (from @code{srivc}, @code{lssvf},
## ...), or a struct with fields @code{B} (numerator
## coefficients in descending powers of p; a cell array of rows for several
## inputs), @code{F} (denominator, descending powers, normalised to be monic)
## and optionally @code{nk} (input delay in samples); or a continuous-time
## @code{tf} of the control package.
## @item THM, nn
## a model with time-varying parameters: @var{nn} = [na nb nk] as in
## @code{rlssvf}, and @var{THM} an N-by-np matrix of the parameters
## [a1 .. a_na, b0 .. b_(nb-1)] at every sample (linear in between), or a
## single row (time-invariant). A true trajectory, or the output
## @var{thm} of a recursive estimator.
## @end table
##
## @strong{Data}: an @code{iddata} object (its input, sampling and
## InterSample are used) or numeric @var{u} (N-by-nu) and @var{Ts} (scalar)
## or the N sampling instants.
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
## @strong{Algorithm.} Each input's transfer function is realised in
## controllable canonical form (for nb = 1 the gain enters with the input, so
## x^(na) + a1(t) x^(na-1) + .. = b0(t) u is solved exactly); the input is
## appended to the state and each sampling interval is integrated by the
## fourth-order Magnus method, exact for time-invariant models.
##
## @strong{Example}
## @example
## u = prbs (8, 4); Ts = 0.1;
## y = simc (struct ("B", 4, "F", [1 2.4 4]), u, Ts, "SNR", 20);
## @end example
## @seealso{rlssvf, prbs, iddata}
## @end deftypefn

function varargout = simc (varargin)
  contsid_nargchk ("simc", nargin, nargout, [0 Inf], 3);
  fname = "simc";
  if (nargin < 2)
    error ("simc:badInput", "simc: expected a model and input data");
  endif
  [theta, orders, rest] = parse_model (fname, varargin);
  [u, t, intersample, rest] = parse_input (fname, rest);
  n = rows (u);
  if (! isempty (rest) && isnumeric (rest{1}) && isscalar (rest{1}))
    rest = [{"SNR"}, rest];
  endif
  defaults = struct ("SNR", [], "noisevar", [], "noise", [],
                     "InterSample", [], "x0", [], "substeps", 1,
                     "controller", [], "r2", []);
  opts = contsid_options (fname, defaults, rest);
  if (! isempty (opts.InterSample))
    intersample = check_intersample (fname, opts.InterSample);
  endif
  if (rows (theta) != 1 && rows (theta) != n)
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
                       [], c_num, c_den, r2);
    e = randn (n, 1);
    e = e * sqrt (mean (xf .^ 2) / 10 ^ (snr / 10)) / sqrt (mean (e .^ 2));
  endif
  ## The gateway returns [x, y, uc]; simc returns [y, x, uc].
  outs = cell (1, max (2, nargout));
  [outs{:}] = call_gateway (numel (outs), u, t, intersample, orders, theta,
                            substeps, x0, e, c_num, c_den, r2);
  varargout = outs([2 1 3:end]);
endfunction

function varargout = call_gateway (nout, u, t, intersample, orders, theta,
                                    substeps, x0, e, c_num, c_den, r2)
  try
    [varargout{1:nout}] = simc_mex ("simc", u, t, intersample, orders.na,
                                    orders.nb, orders.nk, theta, substeps,
                                    x0, e, c_num, c_den, r2);
  catch err
    contsid_rethrow (err);
  end_try_catch
endfunction

function [theta, orders, rest] = parse_model (fname, args)
  M = args{1};
  if (isa (M, "idctm"))
    M = struct (M);
  endif
  if (isstruct (M) || isa (M, "tf"))
    if (isa (M, "tf"))
      if (! isct (M))
        error ("simc:badInput", "simc: M must be a continuous-time tf");
      endif
      [num, den] = tfdata (M, "vector");
      B = {num};
      F = den;
      nk = 0;
    else
      if (! isscalar (M) || ! all (isfield (M, {"B", "F"})))
        error ("simc:badInput", "simc: the model struct needs fields B and F");
      endif
      B = M.B;
      F = M.F;
      nk = [];
      if (isfield (M, "nk"))
        nk = M.nk;
      endif
      if (! iscell (B))
        B = {B};
      endif
    endif
    F = real_matrix (fname, F, "F");
    if (! isvector (F) || numel (F) < 2 || F(1) == 0)
      error ("simc:badInput", ...
             "simc: F must be [1 a1 .. a_na] with na >= 1");
    endif
    a = F(2:end) / F(1);
    na = numel (a);
    nu = numel (B);
    nb = zeros (1, nu);
    b = [];
    for j = 1:nu
      bj = real_matrix (fname, B{j}, "B");
      if (! isempty (bj) && ! isvector (bj))
        error ("simc:badInput", "simc: B must be a row of coefficients");
      endif
      first = find (bj != 0, 1);
      if (isempty (first))
        bj = 0;
      else
        bj = bj(first:end);
      endif
      nb(j) = numel (bj);
      b = [b, bj(:).' / F(1)];
    endfor
    if (isempty (nk))
      nk = zeros (1, nu);
    endif
    nk = real_matrix (fname, nk, "nk");
    if (numel (nk) != nu || any (nk != fix (nk)) || any (nk < 0))
      error ("simc:badInput", "simc: nk must be one integer >= 0 per input");
    endif
    if (any (nb > na + 1))
      error ("simc:badInput", ...
             ["simc: the model is improper (numerator degree above ", ...
              "the denominator's)"]);
    endif
    theta = [a(:).', b];
    orders = struct ("na", na, "nb", nb, "nk", nk(:).');
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
           ["simc: the model must be an idctm, a struct with B and F, ", ...
            "a tf, or THM with nn"]);
  endif
endfunction

function [u, t, intersample, rest] = parse_input (fname, args)
  if (isempty (args))
    error ("simc:badInput", "simc: the input data are missing");
  endif
  if (isa (args{1}, "iddata"))
    d = contsid_getdata (fname, args{1});
    u = d.u;
    if (d.uniform)
      t = d.Ts;
    else
      t = d.t;
    endif
    intersample = d.intersample;
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
