## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn  {} {@var{thm} =} throttleid (@var{data}, @var{method})
## @deftypefnx {} {@var{thm} =} throttleid (@dots{}, @var{name}, @var{value})
## @deftypefnx {} {[@var{thm}, @var{R}, @var{Kv}, @var{info}] =} @
##   throttleid (@dots{})
## Recursive estimation of the electrical submodel of the electronic
## throttle body (thesis sec. 4.2.3): theta = [1/R, Kv Gr/R] (eq. 4.15),
## tracking the armature resistance R(t), from closed-loop data.
##
## @strong{Inputs}
## @table @var
## @item data
## a struct with the N-by-1 fields @code{phi_d} (set point, rad), @code{u}
## (voltage, held between samples), @code{i} (current), @code{phi_m}
## (measured angle, rad) and the scalar @code{Ts}: the output of
## @code{throttlesim}, or measured data in the same form.
## @item method
## @table @asis
## @item "clrsrivc"
## closed-loop recursive IV with the mechanical prefilter (eq. 4.19), F(p)
## = (Ks1/J) / (p^2 + (Kb/J) p + Ks1/J), and instruments [u_hat_f,
## -(p phi_hat)_f] from the closed-loop auxiliary model of Fig. 4.12 (eq.
## 4.21): the plant with the known mechanical parameters and torques and
## the latest physical estimate (R > 0, Kv >= 0), in the known loop,
## driven by phi_d. IV Kalman filter (eq. 2.29) from @code{tsiv} on, its
## least-squares form before.
## @item "rlssvf"
## recursive least squares with the SVF (eq. 4.22), F(p) = (lambda_svf /
## (p + lambda_svf))^2, Kalman filter (eq. 1.59).
## @item "rlsprefilter"
## recursive least squares with the prefilter (4.19): the start of
## CLRSRIVC run to the end (not in the thesis; it separates what the
## prefilter and what the instruments do).
## @end table
## @end table
##
## All three use the filtered regression (eq. 4.20), i_f = theta1 u_f -
## theta2 (p phi)_f, with the mechanical parameters assumed known.
##
## @strong{Options}
## @table @code
## @item adg
## Qn, 2-by-2, default diag ([1e-6 5e-5]) (sec. 4.2.3).
## @item tsiv
## start of the IV stage (s after the first sample), default 5.
## @item lambda_svf
## cut-off of the SVF of RLSSVF, default 5 * 12.4 rad/s (12.4 rad/s is
## the bandwidth of eq. 4.19).
## @item th0, P0
## initial estimate and covariance, default 0 and 1e4 I.
## @item params, loop
## the known plant parameters and loop (structs overriding
## @code{throttleparams}); default those of @var{data} when it has them
## (as from @code{throttlesim}), else Table 4.3.
## @item substeps, phi0
## integration sub-steps and initial angle of the auxiliary model (default
## 2 and phi_d(1)).
## @item phirule
## @qcode{"zoh"} (default) or @qcode{"foh"}: the rule by which the angles
## are filtered. u and i are filtered as held (ZOH); with the ZOH rule for
## the angle too the back-emf part of i and the angle carry the same
## half-sample lag and the regression is consistent to O(Ts^2) (the
## trapezoidal rule: O(Ts)).
## @end table
##
## @strong{Outputs}: @var{thm} (N-by-2) the estimates of [1/R, Kv Gr/R] at
## every sample; @var{R} = 1 ./ thm(:, 1) and @var{Kv} = thm(:, 2) ./
## (Gr thm(:, 1)) the physical estimates (Fig. 4.15); @var{info} a struct
## with @code{pset} (2-by-2-by-N), @code{kappa} (kappa_2(P) per sample),
## @code{phi_hat} and @code{u_hat} (the auxiliary model's angle and
## voltage, CLRSRIVC) and @code{rejections} (estimates the auxiliary model
## refused as unphysical).
##
## The angles are filtered as deviations from phi_d(1), so that a loop
## starting at rest at its set point leaves no start-up transient in the
## lightly damped prefilter (thesis sec. 3.4).
##
## @strong{Example}
## @example
## randn ("state", 1);
## sim = throttlesim ("duration", 30);
## [thm, R] = throttleid (sim, "clrsrivc");
## plot (sim.t, sim.R, sim.t, R);
## @end example
## @seealso{throttlesim, throttleparams, clrsrivc, rlssvf}
## @end deftypefn

function varargout = throttleid (varargin)
  varargout = contsid_guard ("throttleid", @throttleid_body, nargout, varargin);
endfunction

function [thm, R, Kv, info, varargout] = throttleid_body (data, method,
                                                         varargin)
  contsid_nargchk ("throttleid", nargin, nargout, [2 Inf], 4);
  fname = "throttleid";
  if (nargin < 2)
    error ("throttleid:badInput", "throttleid: expected data and a method");
  endif
  if (! (ischar (method) && rows (method) == 1))
    error ("throttleid:badOption", ["throttleid: the method must be ", ...
                                    "'clrsrivc', 'rlssvf' or 'rlsprefilter'"]);
  endif
  method = lower (method);
  if (! any (strcmp (method, {"clrsrivc", "rlssvf", "rlsprefilter"})))
    error ("throttleid:badOption",
           "throttleid: unknown method '%s' (clrsrivc, rlssvf, rlsprefilter)",
           method);
  endif
  if (! (isstruct (data) && isscalar (data)))
    error ("throttleid:badInput",
           "throttleid: data must be a struct (e.g. from throttlesim)");
  endif
  need = {"phi_d", "u", "i", "phi_m", "Ts"};
  missing = need(! isfield (data, need));
  if (! isempty (missing))
    error ("throttleid:badInput", "throttleid: data lacks the field(s) %s",
           strjoin (missing, ", "));
  endif
  n = numel (data.phi_d);
  for f = need(1:4)
    v = data.(f{1});
    if (! (isnumeric (v) && isreal (v) && isvector (v)))
      error ("throttleid:badInput", "throttleid: data.%s must be a real vector",
             f{1});
    endif
    if (numel (v) != n)
      error ("throttleid:dimensionMismatch",
             "throttleid: data.%s has %d samples, data.phi_d %d", f{1},
             numel (v), n);
    endif
  endfor
  Ts = data.Ts;
  if (! (isnumeric (Ts) && isreal (Ts) && isscalar (Ts) && Ts > 0))
    error ("throttleid:badInput", "throttleid: data.Ts must be a scalar > 0");
  endif

  defaults = struct ("adg", diag ([1e-6 5e-5]), "tsiv", 5,
                     "lambda_svf", 5 * 12.4, "th0", [], "P0", [],
                     "params", [], "loop", [], "substeps", 2, "phi0", [],
                     "phirule", "zoh");
  opts = contsid_options (fname, defaults, varargin);
  params = opts.params;
  if (isempty (params) && isfield (data, "params"))
    params = data.params;
  endif
  loop = opts.loop;
  if (isempty (loop) && isfield (data, "loop"))
    loop = data.loop;
  endif
  [gw, p] = throttle_args (fname, params, loop);

  Qn = opts.adg;
  if (! (isnumeric (Qn) && isreal (Qn)))
    error ("throttleid:badInput", "throttleid: adg (Qn) must be a real matrix");
  endif
  if (! isequal (size (Qn), [2 2]))
    error ("throttleid:dimensionMismatch",
           "throttleid: adg (Qn) must be 2-by-2, got %s",
           mat2str (size (Qn)));
  endif
  tsiv = opts.tsiv;
  if (! (isnumeric (tsiv) && isreal (tsiv) && isscalar (tsiv)))
    error ("throttleid:badInput", "throttleid: tsiv must be a real scalar");
  endif
  if (strcmp (method, "clrsrivc") && (tsiv < 0 || tsiv > (n - 1) * Ts))
    error ("throttleid:badInput",
           "throttleid: tsiv = %g s lies outside the record [0, %g] s", tsiv,
           (n - 1) * Ts);
  endif
  if (! any (strcmpi (opts.phirule, {"zoh", "foh"})))
    error ("throttleid:badOption",
           "throttleid: phirule must be 'zoh' or 'foh'");
  endif
  s = opts.substeps;
  if (! (isnumeric (s) && isreal (s) && isscalar (s) && s == fix (s)
         && s >= 1 && s <= 1e4))
    error ("throttleid:badInput",
           "throttleid: substeps must be an integer in [1, 1e4]");
  endif
  num = @(v) double (v(:));
  gw.method = method;
  gw.Ts = double (Ts);
  gw.substeps = double (s);
  gw.phi0 = double (opts.phi0);
  gw.lambda_svf = double (opts.lambda_svf);
  gw.adg = double (Qn);
  gw.th0 = double (opts.th0);
  gw.P0 = double (opts.P0);
  gw.tsiv = double (tsiv);
  gw.phirule = lower (opts.phirule);
  args = {"throttleid", num(data.phi_d), num(data.u), num(data.i), ...
          num(data.phi_m), gw};
  try
    if (nargout >= 4)
      [thm, pset, kappa, phi_hat, u_hat, rej] = throttle_mex (args{:});
      info = struct ("pset", pset, "kappa", kappa, "phi_hat", phi_hat,
                     "u_hat", u_hat, "rejections", rej);
    else
      thm = throttle_mex (args{:});
    endif
  catch err
    contsid_rethrow (err);
  end_try_catch
  R = 1 ./ thm(:, 1);
  Kv = thm(:, 2) ./ (p.Gr * thm(:, 1));
endfunction

%!shared sim0, sim, truth
%! sim0 = throttlesim ("duration", 30, "noisevar", 0, "R", 1.4);
%! randn ("state", 2);
%! sim = throttlesim ("duration", 30, "R", 1.4);
%! truth = sim.theta(end, :);

%!test  # noise-free, constant R, Qn = 0: both recover theta (disc. error)
%! thm = throttleid (sim0, "clrsrivc", "adg", zeros (2));
%! assert (thm(end, :), truth, 2.6e-5 * truth);   # 2 (w_b Ts)^2 / 12
%! thm = throttleid (sim0, "rlssvf", "adg", zeros (2));
%! assert (thm(end, :), truth, 6.5e-4 * truth);   # 2 (lambda_svf Ts)^2 / 12

%!test  # noise in the loop: RLSSVF biased, CLRSRIVC not (measured:
%! ## theta2 -16 % against -0.3 %)
%! ls = throttleid (sim, "rlssvf", "adg", zeros (2));
%! [iv, R, Kv, info] = throttleid (sim, "clrsrivc", "adg", zeros (2));
%! assert (ls(end, 2) < 0.9 * truth(2));
%! assert (iv(end, :), truth, 0.02 * truth);
%! assert (R(end), 1.4, 0.03);
%! assert (Kv(end), 0.02, 0.001);
%! assert (size (info.pset), [2 2 numel(sim.t)]);
%! assert (info.phi_hat(1), sim.phi_d(1));
%! assert (std (info.phi_hat - sim.phi) < 0.2);   # the aux model follows

%!test  # the least-squares start of CLRSRIVC equals rlsprefilter until tsiv
%! a = throttleid (sim, "clrsrivc", "tsiv", 5);
%! b = throttleid (sim, "rlsprefilter");
%! k = 1:5000;
%! assert (a(k, :), b(k, :), 0);
%! assert (any (a(end, :) != b(end, :)));

%!error id=throttleid:badInput throttleid (sim)
%!error id=throttleid:badOption throttleid (sim, 3)
%!error id=throttleid:badOption throttleid (sim, "ivsvf")
%!error id=throttleid:badInput throttleid ([1 2 3], "rlssvf")
%!error id=throttleid:badInput throttleid (rmfield (sim, "phi_m"), "rlssvf")
%!error id=throttleid:badInput throttleid (setfield (sim, "u", {1}), "rlssvf")
%!error id=throttleid:dimensionMismatch throttleid (setfield (sim, "u", [1; 2]), "rlssvf")
%!error id=throttleid:badInput throttleid (setfield (sim, "Ts", -1), "rlssvf")
%!error id=throttleid:badInput throttleid (sim, "rlssvf", "adg", "x")
%!error id=throttleid:dimensionMismatch throttleid (sim, "rlssvf", "adg", eye (3))
%!error id=throttleid:badInput throttleid (sim, "rlssvf", "adg", -eye (2))
%!error id=throttleid:badInput throttleid (sim, "clrsrivc", "tsiv", 100)
%!error id=throttleid:badInput throttleid (sim, "clrsrivc", "tsiv", [1 2])
%!error id=throttleid:badOption throttleid (sim, "rlssvf", "phirule", "cubic")
%!error id=throttleid:badInput throttleid (sim, "rlssvf", "substeps", 0)
%!error id=throttleid:badInput throttleid (sim, "rlssvf", "lambda_svf", -1)
%!error id=throttleid:dimensionMismatch throttleid (sim, "rlssvf", "th0", [1 2 3])
%!error id=throttleid:badInput throttleid (sim, "rlssvf", "P0", -eye (2))
%!error id=throttleid:badOption throttleid (sim, "rlssvf", "params", struct ("X", 1))
%!error id=throttleid:badOption throttleid (sim, "rlssvf", "speed", 1)
%!error id=throttleid:badInput throttleid (setfield (sim, "i", [NaN; sim.i(2:end)]), "rlssvf")

%!demo
%! randn ("state", 1);
%! sim = throttlesim ();
%! [~, R_ls] = throttleid (sim, "rlssvf");
%! [~, R_iv] = throttleid (sim, "clrsrivc");
%! plot (sim.t, sim.R, "k", sim.t, R_ls, "r", sim.t, R_iv, "b");
%! ylim ([0 3]); xlabel ("t (s)"); ylabel ("R (Ohm)");
%! legend ("true", "RLSSVF", "CLRSRIVC");
