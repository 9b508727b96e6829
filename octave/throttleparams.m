## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn  {} {@var{p} =} throttleparams ()
## @deftypefnx {} {[@var{p}, @var{loop}] =} throttleparams ()
## Parameters of the electronic throttle body of thesis sec. 4.2 (Table
## 4.3) and of its control loop (eqs. 4.12, 4.13), as used by
## @code{throttlesim} and @code{throttleid}.
##
## @var{p} has the fields of Table 4.3 in SI units with angles in rad:
## @code{Ks1}, @code{Ks2}, @code{Ks3} (spring stiffness, N m/rad),
## @code{M_close}, @code{M_open} (spring pre-loads, N m), @code{phi_min},
## @code{phi_max}, @code{phi_LH}, @code{delta_phi}, @code{phi_12} (rad),
## @code{J} (kg m^2), @code{Kb} (N m s/rad), @code{Mc} (Coulomb friction,
## N m), @code{R} (nominal armature resistance, Ohm), @code{L} (H, unused:
## the current dynamics are neglected, eq. 4.11a), @code{Kv} (V s/rad),
## @code{Kt} (N m/A), @code{Gr} (gear ratio).
##
## @var{loop} describes u = C(q^-1) (F_phi(q^-1) phi_d - phi_m): @code{Ts}
## (1e-3 s), the PID gains @code{kp} = 2.85, @code{ki} = 6.06e-3,
## @code{kd} = -36.96 of eq. (4.13), C = kp + ki/(1 - q^-1) + kd (1 -
## q^-1), per sample as printed; @code{setpoint_filter}, the struct
## (@code{num}, @code{den}) of eq. (4.12) in powers of q^-1; @code{umax} =
## 12 V, the voltage limit.
##
## The thesis states neither Ts nor the angle unit of the controller:
## (4.12) is the Tustin discretisation of 20/(p + 20) at Ts = 1 ms (a Ts =
## 0.02), and the loop of (4.13) is stable with angles in rad (unstable
## with degrees). The voltage limit (a car battery) is an assumption; it is
## rarely reached. See @code{help throttlesim}.
##
## Change a field and pass the struct as the @code{params} or @code{loop}
## option of @code{throttlesim} / @code{throttleid}, e.g. @code{p.Mc = 0}
## for a plant without Coulomb friction.
##
## @strong{Example}
## @example
## p = throttleparams ();
## p.Ks1 / p.J        # 67.2 (rad/s)^2: the mechanical prefilter (4.19)
## @end example
## @seealso{throttlesim, throttleid}
## @end deftypefn

function varargout = throttleparams (varargin)
  varargout = contsid_guard ("throttleparams", @throttleparams_body, nargout,
                             varargin);
endfunction

function [p, loop, varargout] = throttleparams_body (varargin)
  contsid_nargchk ("throttleparams", nargin, nargout, [0 0], 2);
  deg = pi / 180;
  p = struct ("Ks1", 1.83e-3 / deg, "Ks2", 22.90e-3 / deg,
              "Ks3", 47.15e-3 / deg, "M_close", 28.4162e-3,
              "M_open", 15.8202e-3, "phi_min", 8 * deg, "phi_max", 90 * deg,
              "phi_LH", 12.58 * deg, "delta_phi", 1.12 * deg,
              "phi_12", 85 * deg, "J", 1.56e-3, "Kb", 4.98e-3, "Mc", 8e-3,
              "R", 1.4, "L", 2.5e-3, "Kv", 0.02, "Kt", 10.8856e-3,
              "Gr", 22.56);
  loop = struct ("Ts", 1e-3, "kp", 2.85, "ki", 6.06e-3, "kd", -36.96,
                 "setpoint_filter",
                 struct ("num", [0.009901 0.009901], "den", [1 -0.9802]),
                 "umax", 12);
endfunction

%!test  # Table 4.3 in SI units; (4.16) is ]13.14, 85[ degrees
%! [p, loop] = throttleparams ();
%! assert (p.Ks1, 1.83e-3 * 180 / pi, eps);
%! assert ((p.phi_LH + p.delta_phi / 2) * 180 / pi, 13.14, 1e-12);
%! assert (p.phi_12 * 180 / pi, 85, 1e-12);
%! assert (numel (fieldnames (p)), 18);
%! assert (loop.Ts, 1e-3);
%! assert ([loop.kp loop.ki loop.kd], [2.85 6.06e-3 -36.96]);

%!test  # (4.12) is the Tustin map of 20/(p + 20) at Ts = 1 ms
%! [~, loop] = throttleparams ();
%! a = 20 * loop.Ts / 2;
%! f = loop.setpoint_filter;
%! assert (f.num, [1 1] * a / (1 + a), 5e-7);
%! assert (f.den, [1, -(1 - a) / (1 + a)], 5e-5);

%!demo
%! p = throttleparams ();
%! deg = pi / 180;
%! phi = linspace (p.phi_min, p.phi_max, 500);
%! low = p.phi_LH - p.delta_phi / 2; high = p.phi_LH + p.delta_phi / 2;
%! Ms = zeros (size (phi));
%! k = phi < low;
%! Ms(k) = -p.Ks3 * (low - phi(k)) - p.M_close;
%! k = phi > high & phi < p.phi_12;
%! Ms(k) = p.Ks1 * (phi(k) - high) + p.M_open;
%! k = phi >= p.phi_12;
%! Ms(k) = p.Ks2 * (phi(k) - p.phi_12) + p.Ks1 * (p.phi_12 - high) + p.M_open;
%! plot (phi / deg, Ms);
%! xlabel ("phi (deg)"); ylabel ("M_s (N m)");
%! title ("Spring torque, thesis eqs. 4.7-4.8 (cf. Fig. 4.10)");
