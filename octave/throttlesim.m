## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn  {} {@var{sim} =} throttlesim ()
## @deftypefnx {} {@var{sim} =} throttlesim (@var{phi_d}, @var{Ts})
## @deftypefnx {} {@var{sim} =} throttlesim (@dots{}, @var{name}, @var{value})
## Simulate the electronic throttle body of thesis sec. 4.2 in its closed
## loop (Fig. 4.11): the plate driven by a DC motor against a
## piecewise-linear spring and friction, its angle measured with noise and
## fed back to a PID through a set-point filter.
##
## @strong{Model} (eqs. 4.6-4.13, Table 4.3 via @code{throttleparams}),
## current dynamics neglected as in eq. (4.11a):
## @example
## i = (u - Kv Gr omega) / R(t),   phi' = omega,
## J omega' = Kt Gr i - M_s(phi) - Kb omega - Mc sign(omega),
## phi_m(t_k) = phi(t_k) + e(t_k),
## u(t_k) = sat (C(q^-1) (F_phi(q^-1) phi_d(t_k) - phi_m(t_k)))
## @end example
## with the spring torque M_s of eqs. (4.7)-(4.8), the set-point filter
## F_phi of eq. (4.12) and the PID C = kp + ki/(1 - q^-1) + kd (1 - q^-1) of
## eq. (4.13).
##
## @strong{Inputs}
## @table @var
## @item phi_d
## the set point (rad), N-by-1. Without it: the default experiment, 100 s
## (option @code{duration}) of 1 s steps, 45 degrees, then levels 25 + 45
## frac(j 0.618..) degrees (a golden-ratio sequence: deterministic, steps of
## varied size, inside the linear spring region (4.16) with margin).
## @item Ts
## sampling interval (s); default @code{loop.Ts} = 1e-3.
## @end table
##
## @strong{Options}
## @table @code
## @item R
## the armature resistance R(t_k) (Ohm), scalar or N-by-1, linear between
## samples. Default: rising linearly from 0.5 R to 1.5 R over the record,
## R = 1.4 Ohm (eq. 4.10).
## @item noisevar
## variance of the white Gaussian noise e on the angle (@code{randn}),
## default 1e-3 rad^2.
## @item noise
## the N-by-1 noise sequence itself (replaces @code{noisevar}).
## @item params, loop
## structs whose fields override those of @code{throttleparams}, e.g.
## @code{struct ("Mc", 0)} to remove the Coulomb friction.
## @item substeps
## Runge-Kutta steps per sample (default 2).
## @item phi0
## initial angle (rad), default @var{phi_d}(1).
## @item duration
## length (s) of the default set point.
## @end table
##
## @strong{Output} @var{sim}: a struct with fields @code{Ts}, @code{t},
## @code{phi_d}, @code{r} (the filtered set point), @code{u} (the voltage,
## held over each interval), @code{i} (the current at t_k, with u(t_k)),
## @code{phi}, @code{phi_m}, @code{omega}, @code{e}, @code{R}, @code{theta}
## (the true [1/R, Kv Gr/R] of eq. 4.15 per sample), @code{params},
## @code{loop}, and @code{info} (@code{saturated}: samples at the voltage
## limit; @code{outside_linear}: samples with phi outside (4.16);
## @code{events}: located friction and spring events; @code{phi_range}).
## @var{sim} is the data argument of @code{throttleid}.
##
## @strong{What the thesis leaves open} (and is read here): angles in rad,
## also in the controller (with degrees the loop is unstable); Ts = 1 ms,
## since (4.12) is then the Tustin discretisation of 20/(p + 20) and the
## PID gains are per sample as printed; the loop starts at rest at the
## equilibrium of phi0 (the set-point filter acting on phi_d - phi_d(1),
## the integrator holding the voltage R M_s(phi0)/(Kt Gr)); the voltage is
## limited to +-12 V (rarely reached); at omega = 0 the plate sticks while
## the motor torque is within Mc of the spring's (sign(0) set-valued).
##
## @strong{Algorithm.} Per sample the voltage is held and R(t) is linear;
## each interval is integrated by @code{substeps} fourth-order Runge-Kutta
## steps of a smooth mode, with the events (omega reaching zero: stick or
## reverse; phi crossing a breakpoint of 4.7; breakaway) located by
## bisection. The core tests compare it with a matrix-exponential solution
## (agreement 1e-11 rad at 2 substeps) and with closed forms. Reference:
## A. Padilla, PhD thesis, Universite de Lorraine, 2017, sec. 4.2.
##
## @strong{Example}
## @example
## randn ("state", 1);
## sim = throttlesim ("duration", 20);
## plot (sim.t, sim.phi_m * 180 / pi, sim.t, sim.phi_d * 180 / pi);
## @end example
## @seealso{throttleid, throttleparams}
## @end deftypefn

function varargout = throttlesim (varargin)
  varargout = contsid_guard ("throttlesim", @throttlesim_body, nargout,
                             varargin);
endfunction

function [sim, varargout] = throttlesim_body (varargin)
  contsid_nargchk ("throttlesim", nargin, nargout, [0 Inf], 1);
  fname = "throttlesim";
  args = varargin;
  phi_d = [];
  Ts = [];
  if (! isempty (args) && ! ischar (args{1}) && ! isstruct (args{1}))
    if (numel (args) < 2)
      error ("throttlesim:badInput",
             "throttlesim: expected the set point phi_d and Ts");
    endif
    phi_d = args{1};
    Ts = args{2};
    args = args(3:end);
    if (! (isnumeric (phi_d) && isreal (phi_d) && isvector (phi_d)
           && numel (phi_d) >= 1))
      error ("throttlesim:badInput",
             "throttlesim: phi_d must be a real vector (rad)");
    endif
    if (! (isnumeric (Ts) && isreal (Ts) && isscalar (Ts) && Ts > 0
           && isfinite (Ts)))
      error ("throttlesim:badInput",
             "throttlesim: Ts must be a real scalar > 0");
    endif
    phi_d = double (phi_d(:));
  endif
  defaults = struct ("R", [], "noisevar", 1e-3, "noise", [], "params", [],
                     "loop", [], "substeps", 2, "phi0", [], "duration", 100);
  opts = contsid_options (fname, defaults, args);
  [gw, p, loop] = throttle_args (fname, opts.params, opts.loop);
  if (isempty (Ts))
    Ts = loop.Ts;
  else
    loop.Ts = Ts;
  endif
  if (isempty (phi_d))
    d = opts.duration;
    if (! (isnumeric (d) && isreal (d) && isscalar (d) && d >= Ts
           && isfinite (d)))
      error ("throttlesim:badInput",
             "throttlesim: duration must be a real scalar >= Ts");
    endif
    phi_d = default_setpoint (round (d / Ts) + 1, Ts);
  elseif (any (strcmp (opts.given_, "duration")))
    error ("throttlesim:badOption",
           "throttlesim: duration belongs to the default set point");
  endif
  n = numel (phi_d);

  R = opts.R;
  if (isempty (R))
    R = p.R * (0.5 + (0:n-1)' / max (n - 1, 1));
  elseif (! (isnumeric (R) && isreal (R) && isvector (R)))
    error ("throttlesim:badInput", "throttlesim: R must be a real vector");
  elseif (isscalar (R))
    R = repmat (double (R), n, 1);
  elseif (numel (R) != n)
    error ("throttlesim:dimensionMismatch",
           "throttlesim: R must be a scalar or have %d values, got %d", n,
           numel (R));
  else
    R = double (R(:));
  endif

  if (! isempty (opts.noise))
    e = opts.noise;
    if (! (isnumeric (e) && isreal (e) && isvector (e)))
      error ("throttlesim:badInput",
             "throttlesim: noise must be a real vector");
    endif
    if (numel (e) != n)
      error ("throttlesim:dimensionMismatch",
             "throttlesim: noise must have %d values, got %d", n, numel (e));
    endif
    if (any (strcmp (opts.given_, "noisevar")))
      error ("throttlesim:badOption",
             "throttlesim: give noise or noisevar, not both");
    endif
    e = double (e(:));
  else
    v = opts.noisevar;
    if (! (isnumeric (v) && isreal (v) && isscalar (v) && v >= 0
           && isfinite (v)))
      error ("throttlesim:badInput",
             "throttlesim: noisevar must be a real scalar >= 0");
    endif
    e = sqrt (v) * randn (n, 1);
  endif

  s = opts.substeps;
  if (! (isnumeric (s) && isreal (s) && isscalar (s) && s == fix (s)
         && s >= 1 && s <= 1e4))
    error ("throttlesim:badInput",
           "throttlesim: substeps must be an integer in [1, 1e4]");
  endif
  phi0 = opts.phi0;
  if (! isempty (phi0) && ! (isnumeric (phi0) && isreal (phi0)
                             && isscalar (phi0)))
    error ("throttlesim:badInput", "throttlesim: phi0 must be a real scalar");
  endif

  gw.Ts = Ts;
  gw.noise = e;
  gw.substeps = double (s);
  gw.phi0 = double (phi0);
  try
    [u, i, phi, phi_m, omega, r, info] = ...
      throttle_mex ("throttlesim", phi_d, R, gw);
  catch err
    contsid_rethrow (err);
  end_try_catch
  t = (0:n-1)' * Ts;
  sim = struct ("Ts", Ts, "t", t, "phi_d", phi_d, "r", r, "u", u, "i", i,
                "phi", phi, "phi_m", phi_m, "omega", omega, "e", e, "R", R,
                "theta", [1 ./ R, p.Kv * p.Gr ./ R], "params", p,
                "loop", loop);
  sim.info = struct ("saturated", info(1), "outside_linear", info(2),
                     "events", info(3), "phi_range", info(4:5));
endfunction

function phi_d = default_setpoint (n, Ts)
  ## 1 s levels: 45 degrees, then 25 + 45 frac(j g) degrees, g the golden
  ## ratio's fractional part.
  g = (sqrt (5) - 1) / 2;
  j = floor ((0:n-1)' * Ts + 1e-9);
  level = 25 + 45 * (j * g - floor (j * g));
  level(j == 0) = 45;
  phi_d = level * pi / 180;
endfunction

%!shared p
%! p = throttleparams ();

%!test  # the outputs satisfy eqs. (4.11a) and (4.11d); inside (4.16)
%! randn ("state", 3);
%! sim = throttlesim ("duration", 20);
%! n = 20001;
%! assert (size (sim.u), [n 1]);
%! assert (sim.t(end), 20, 1e-12);
%! assert (sim.i, (sim.u - p.Kv * p.Gr * sim.omega) ./ sim.R, 1e-12);
%! assert (sim.phi_m, sim.phi + sim.e, 0);
%! assert (sim.R([1 end]), [0.7; 2.1], 1e-12);
%! assert (sim.theta, [1 ./ sim.R, p.Kv * p.Gr ./ sim.R], 1e-15);
%! assert (sim.info.outside_linear, 0);
%! assert (std (sim.e), sqrt (1e-3), 2e-3);
%! low = (p.phi_LH + p.delta_phi / 2); high = p.phi_12;
%! assert (all (sim.phi > low & sim.phi < high));

%!test  # at rest at the equilibrium of a constant set point, noise-free
%! sim = throttlesim (0.7 * ones (500, 1), 1e-3, "noisevar", 0, "R", 1.2);
%! assert (sim.phi, 0.7 * ones (500, 1), 0);
%! Ms = p.Ks1 * (0.7 - p.phi_LH - p.delta_phi / 2) + p.M_open;
%! assert (sim.u, 1.2 * Ms / (p.Kt * p.Gr) * ones (500, 1), 1e-14);

%!test  # a set-point step: the plate follows the filtered set point
%! phi_d = [0.5 * ones(1000, 1); 0.9 * ones(7000, 1)];
%! sim = throttlesim (phi_d, 1e-3, "noisevar", 0, "R", 1.4);
%! assert (max (abs (sim.phi(6000:end) - sim.r(6000:end))) < 1e-3);
%! assert (max (sim.phi) < 0.95);

%!test  # params reach the plant: without Coulomb friction the motion differs
%! a = throttlesim ("duration", 5, "noisevar", 0);
%! b = throttlesim ("duration", 5, "noisevar", 0, "params", struct ("Mc", 0));
%! assert (b.params.Mc, 0);
%! assert (max (abs (a.phi - b.phi)) > 1e-3);
%! assert (a.u(1), b.u(1), 0);   # the same equilibrium at the start

%!error id=throttlesim:badInput throttlesim ([0.5; 0.6])
%!error id=throttlesim:badInput throttlesim ({1}, 1e-3)
%!error id=throttlesim:badInput throttlesim ([0.5; 0.6], -1)
%!error id=throttlesim:badOption throttlesim ("colour", 1)
%!error id=throttlesim:badOption throttlesim ([0.5; 0.6], 1e-3, "duration", 3)
%!error id=throttlesim:badInput throttlesim ("duration", -1)
%!error id=throttlesim:dimensionMismatch throttlesim ([0.5; 0.6], 1e-3, "R", [1 2 3])
%!error id=throttlesim:badInput throttlesim ([0.5; 0.6], 1e-3, "R", "x")
%!error id=throttlesim:badInput throttlesim ([0.5; 0.6], 1e-3, "R", [1; -1])
%!error id=throttlesim:dimensionMismatch throttlesim ([0.5; 0.6], 1e-3, "noise", [1 2 3])
%!error id=throttlesim:badInput throttlesim ([0.5; 0.6], 1e-3, "noise", {1})
%!error id=throttlesim:badOption throttlesim ([0.5; 0.6], 1e-3, "noise", [0 0], "noisevar", 1)
%!error id=throttlesim:badInput throttlesim ([0.5; 0.6], 1e-3, "noisevar", -1)
%!error id=throttlesim:badInput throttlesim ([0.5; 0.6], 1e-3, "substeps", 0.5)
%!error id=throttlesim:badInput throttlesim ([0.5; 0.6], 1e-3, "phi0", [1 2])
%!error id=throttlesim:badInput throttlesim ([0.5; 0.6], 1e-3, "phi0", 3)
%!error id=throttlesim:badOption throttlesim ([0.5; 0.6], 1e-3, "params", struct ("Jay", 1))
%!error id=throttlesim:badOption throttlesim ([0.5; 0.6], 1e-3, "params", 3)
%!error id=throttlesim:badInput throttlesim ([0.5; 0.6], 1e-3, "params", struct ("J", NaN))
%!error id=throttlesim:badInput throttlesim ([0.5; 0.6], 1e-3, "params", struct ("J", -1))
%!error id=throttlesim:badInput throttlesim ([0.5; 0.6], 1e-3, "loop", struct ("umax", 0))
%!error id=throttlesim:badInput throttlesim ([0.5; 0.6], 1e-3, "loop", struct ("setpoint_filter", 1))
%!error id=throttlesim:badInput throttlesim ([0.5; 0.6], 1e-3, "loop", struct ("setpoint_filter", struct ("num", 1, "den", [1 -1])))
%!error id=throttlesim:badOption throttlesim ([0.5; 0.6], 1e-3, "loop", struct ("kq", 1))
%!error <left \[phi_min, phi_max\]> throttlesim ([0.5 * ones(100, 1); 2 * ones(3000, 1)], 1e-3, "noisevar", 0)

%!demo
%! randn ("state", 1);
%! sim = throttlesim ("duration", 30);
%! deg = 180 / pi;
%! subplot (3, 1, 1);
%! plot (sim.t, sim.phi_m * deg, sim.t, sim.phi_d * deg);
%! ylabel ("angle (deg)"); legend ("phi_m", "phi_d");
%! subplot (3, 1, 2); plot (sim.t, sim.u); ylabel ("u (V)");
%! subplot (3, 1, 3); plot (sim.t, sim.i); ylabel ("i (A)"); xlabel ("t (s)");
