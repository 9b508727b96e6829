// SPDX-License-Identifier: BSD-3-Clause
// Copyright (C) the ctid authors
// Electronic throttle body (ETB) of thesis sec. 4.2: the plant, its closed
// loop, and the recursive estimation of the electrical submodel.
//
// Plant, eqs. (4.6)-(4.11) with the current dynamics neglected (4.11a):
//
//   i     = (u - Kv Gr omega) / R(t)                       (4.11a)
//   phi'  = omega                                          (4.11b)
//   J omega' = Kt Gr i - M_s(phi) - M_f(omega)             (4.11c)
//   phi_m(t_k) = phi(t_k) + e(t_k)                         (4.11d)
//
// with the piecewise-linear spring torque (4.7)-(4.8), the friction (4.9)
// M_f = Kb omega + Mc sign(omega), and no aerodynamic torque. Table 4.3
// gives the parameters (ThrottleParameters::table_4_3).
//
// Loop (Fig. 4.11): u(t_k) = C(q^-1) (F_phi(q^-1) phi_d(t_k) - phi_m(t_k)),
// F_phi the set-point filter (4.12) and C the PID (4.13)
//   C = kp + ki / (1 - q^-1) + kd (1 - q^-1),  kp = 2.85, ki = 6.06e-3,
//   kd = -36.96.
//
// What the thesis leaves open, and the reading taken here (the demo
// demos/demo_throttle.m and `help throttlesim` say the same):
//  - Angles in rad everywhere, also in the controller: with degrees the
//    loop of (4.13) is unstable at every sampling interval tried (1-10 ms);
//    with radians it is stable for R within (4.10).
//  - Ts = 1 ms. (4.12) is the Tustin discretisation of a/(p + a) with
//    a Ts = 0.02 (0.009901 = 0.01/1.01, 0.9802 = 0.99/1.01), i.e. a 20 rad/s
//    set-point filter at 1 kHz, of the closed loop's speed (its poles,
//    linearised at R = 1.4 Ohm: -2.5, -6.6 and -41 rad/s); the gains of
//    (4.13) are per sample, as printed.
//  - The loop starts at rest at the equilibrium of phi0 (default phi_d(t_1)):
//    F_phi acts on phi_d - phi_d(t_1) (its printed coefficients have static
//    gain 1.0001) and the PID's integrator holds the voltage that balances
//    the spring, R M_s(phi0) / (Kt Gr); both are exact for the linear
//    filters (a constant added to an integrator's output is an initial
//    state).
//  - The applied voltage is saturated at +-u_max (default 12 V, a car
//    battery); no anti-windup (the limit is rarely reached).
//  - sign(0) is set-valued (Filippov/Karnopp): at omega = 0 the plate
//    sticks while |Kt Gr u / R - M_s| <= Mc; at the pre-load jumps of
//    (4.7) M_s is set-valued too, and a plate bouncing on one is pinned
//    there (ThrottleBody).
//  - Outside [phi_min, phi_max] the end segments of (4.7) are extended
//    linearly (the estimator's auxiliary model may go there); the
//    simulator itself refuses a trajectory that leaves the range.
//
// Integration (ThrottleBody): the voltage is held over each sampling
// interval and R(t) is linear in between; each interval is split into
// `substeps` fourth-order Runge-Kutta steps of a smooth mode (sign of
// omega fixed, stuck or not). Events are located inside a step by
// bisection on the step length: omega reaching zero (then the plate sticks
// or reverses, by the torque balance above), and phi crossing a
// breakpoint of (4.7). While stuck, breakaway is where |Kt Gr u / R(t) -
// M_s| = Mc, solved exactly (R linear in t). Tests compare with a
// matrix-exponential solution of the piecewise-linear modes and with closed
// forms.
//
// Estimation of theta = [1/R, Kv Gr / R] (4.15) from the filtered
// regression (4.20)
//   i_f(t_k) = theta1 u_f(t_k) - theta2 (p phi)_f(t_k)
// with a second-order prefilter F(p):
//  - kClrsrivc: the mechanical prefilter (4.19), F = (Ks1/J) / (p^2 +
//    (Kb/J) p + Ks1/J), instruments [u_hat_f, -(p phi_hat)_f] from the
//    closed-loop auxiliary model of Fig. 4.12 / eq. (4.21): the plant with
//    the known mechanical parameters and torques and the latest accepted
//    electrical estimate, in the known loop, driven by phi_d. IV Kalman
//    filter (2.29) from t_s_iv on, the least-squares form before (the same
//    prefilter; sec. 3.2.1).
//  - kRlsSvf: the SVF (4.22), F = (lambda/(p + lambda))^2, least squares
//    with the Kalman filter (1.59).
//  - kRlsPrefilter: least squares with the prefilter (4.19), i.e. the start
//    of CLRSRIVC run to the end: it separates what the prefilter and what
//    the instruments contribute.
// u, i and u_hat are filtered with the exact ZOH rule (u is held, and i's
// dominant part theta1 u jumps with it); phi_m and phi_hat by default with
// the ZOH rule too: i's back-emf part is then held like phi, so both carry
// the same half-sample lag and the regression is consistent to O(Ts^2).
// Measured on noise-free data without friction, CLRSRIVC's relative error
// is 3.9e-6 / 1.2e-6 / 3.9e-7 at Ts = 2 / 1 / 0.5 ms with the ZOH rule for
// phi, 2.8e-4 / 1.6e-4 / 9.5e-5 with the trapezoidal rule (O(Ts)).
// The angles are filtered as deviations from phi_d(t_1): p kills the
// constant, and a loop that starts at rest at its set point then leaves no
// start-up transient in (p phi)_f, which the lightly damped (4.19) would
// otherwise carry for seconds (the initial-condition issue of sec. 3.4).
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "ctid/adaptation/adaptation.hpp"
#include "ctid/filters/svf.hpp"
#include "ctid/recursive/rlssvf.hpp"
#include "ctid/simulation/controller.hpp"

namespace ctid {

// Physical parameters of Table 4.3 (SI units, angles in rad).
template <typename S>
struct ThrottleParameters {
  S Ks1, Ks2, Ks3;      // spring stiffness (N m / rad)
  S M_close, M_open;    // spring pre-loads (N m)
  S phi_min, phi_max;   // range of the plate (rad)
  S phi_LH, delta_phi;  // limp-home position and dead zone width (rad)
  S phi_12;             // start of the stiff spring segment (rad)
  S J;                  // moment of inertia (kg m^2)
  S Kb;                 // viscous friction (N m s / rad)
  S Mc;                 // Coulomb friction (N m)
  S R;                  // nominal armature resistance (Ohm)
  S L;                  // inductance (H), unused: current dynamics neglected
  S Kv;                 // velocity coefficient (V s / rad)
  S Kt;                 // torque coefficient (N m / A)
  S Gr;                 // gear ratio

  static ThrottleParameters table_4_3() {
    const S deg = S(3.14159265358979323846) / 180;
    ThrottleParameters p;
    p.Ks1 = S(1.83e-3) / deg;
    p.Ks2 = S(22.90e-3) / deg;
    p.Ks3 = S(47.15e-3) / deg;
    p.M_close = S(28.4162e-3);
    p.M_open = S(15.8202e-3);
    p.phi_min = 8 * deg;
    p.phi_max = 90 * deg;
    p.phi_LH = S(12.58) * deg;
    p.delta_phi = S(1.12) * deg;
    p.phi_12 = 85 * deg;
    p.J = S(1.56e-3);
    p.Kb = S(4.98e-3);
    p.Mc = S(8e-3);
    p.R = S(1.4);
    p.L = S(2.5e-3);
    p.Kv = S(0.02);
    p.Kt = S(10.8856e-3);
    p.Gr = S(22.56);
    return p;
  }

  // Lower and upper end of the linear spring region (4.16).
  S linear_region_low() const { return phi_LH + delta_phi / 2; }
  S linear_region_high() const { return phi_12; }
  // Constant term m_s1 of h_s1 (4.18): h_s1(phi) = Ks1 phi + m_s1.
  S m_s1() const { return -Ks1 * (phi_LH + delta_phi / 2) + M_open; }
  // theta of (4.15) for a resistance R and this Kv, Gr.
  S theta1(S r) const { return 1 / r; }
  S theta2(S r) const { return Kv * Gr / r; }
};

template <typename S>
Status validate(const ThrottleParameters<S>& p) {
  const S values[] = {p.Ks1,     p.Ks2,     p.Ks3,    p.M_close,   p.M_open,
                      p.phi_min, p.phi_max, p.phi_LH, p.delta_phi, p.phi_12,
                      p.J,       p.Kb,      p.Mc,     p.R,         p.L,
                      p.Kv,      p.Kt,      p.Gr};
  for (S v : values) {
    if (!std::isfinite(v)) return bad_input("the parameters must be finite");
  }
  if (!(p.J > 0) || !(p.Kt > 0) || !(p.Gr > 0) || !(p.R > 0)) {
    return bad_input("J, Kt, Gr and R must be > 0");
  }
  if (p.Ks1 < 0 || p.Ks2 < 0 || p.Ks3 < 0 || p.Kb < 0 || p.Mc < 0 || p.Kv < 0 ||
      p.L < 0) {
    return bad_input("Ks1, Ks2, Ks3, Kb, Mc, Kv and L must be >= 0");
  }
  if (!(p.delta_phi >= 0) ||
      !(p.phi_min < p.phi_LH - p.delta_phi / 2 &&
        p.phi_LH + p.delta_phi / 2 < p.phi_12 && p.phi_12 < p.phi_max)) {
    return bad_input(
        "the angles must satisfy phi_min < phi_LH - delta_phi/2 <= "
        "phi_LH + delta_phi/2 < phi_12 < phi_max");
  }
  if (!(p.Ks1 > 0)) {
    return bad_input("Ks1 must be > 0 (it sets the prefilter (4.19))");
  }
  return Status::Ok();
}

// Spring torque M_s = h_s(phi), eqs. (4.7)-(4.8); the end segments are
// extended linearly beyond [phi_min, phi_max].
template <typename S>
S spring_torque(const ThrottleParameters<S>& p, S phi) {
  const S low = p.phi_LH - p.delta_phi / 2;
  const S high = p.phi_LH + p.delta_phi / 2;
  if (phi < low) return -p.Ks3 * (low - phi) - p.M_close;  // h_s3
  if (phi <= high) return 0;
  if (phi < p.phi_12) return p.Ks1 * (phi - high) + p.M_open;  // h_s1
  return p.Ks2 * (phi - p.phi_12) + p.Ks1 * (p.phi_12 - high) +
         p.M_open;  // h_s2
}

// The PID (4.13), C = kp + ki / (1 - q^-1) + kd (1 - q^-1), as a
// DiscreteTransferFunction, gains per sample as printed.
template <typename S>
DiscreteTransferFunction<S> throttle_pid(S kp, S ki, S kd) {
  DiscreteTransferFunction<S> c;
  c.numerator.resize(3);
  c.numerator << kp + ki + kd, -kp - 2 * kd, kd;
  c.denominator.resize(2);
  c.denominator << 1, -1;
  return c;
}

// The set-point filter (4.12).
template <typename S>
DiscreteTransferFunction<S> throttle_setpoint_filter() {
  DiscreteTransferFunction<S> f;
  f.numerator.resize(2);
  f.numerator << S(0.009901), S(0.009901);
  f.denominator.resize(2);
  f.denominator << 1, S(-0.9802);
  return f;
}

// The known loop around the plant: PID, set-point filter, voltage limit.
template <typename S>
struct ThrottleController {
  DiscreteTransferFunction<S> pid =
      throttle_pid<S>(S(2.85), S(6.06e-3), S(-36.96));
  DiscreteTransferFunction<S> setpoint_filter = throttle_setpoint_filter<S>();
  S u_max = 12;  // V; infinity: no saturation
};

template <typename S>
Status validate(const ThrottleController<S>& c) {
  Status status = validate_controller(c.pid);
  if (!status.ok()) return bad_input("the PID: " + status.message());
  status = validate_controller(c.setpoint_filter);
  if (!status.ok()) {
    return bad_input("the set-point filter: " + status.message());
  }
  const S dc =
      c.setpoint_filter.numerator.sum() / c.setpoint_filter.denominator.sum();
  if (!std::isfinite(dc)) {
    return bad_input("the set-point filter must have a finite static gain");
  }
  if (!(c.u_max > 0)) return bad_input("umax must be > 0");
  return Status::Ok();
}

// The rigid plate of eq. (4.11b)-(4.11c) with i from (4.11a): state phi,
// omega and whether the plate sticks. See the header comment for the
// integration scheme.
//
// Sticking, with sign(0) set-valued: at omega = 0 the plate stays while the
// motor torque T_m = Kt Gr u / R(t) satisfies M_s - Mc <= T_m <= M_s + Mc.
// At the two pre-load jumps of (4.7) (the dead-zone edges) M_s is itself
// set-valued, [M_s(b-), M_s(b+)]: a plate that falls back and forth across
// the edge (a Zeno sequence of ever smaller bounces) is pinned there once
// its next excursion would be below 1e-12 rad, and stays pinned while
// M_s(b-) - Mc <= T_m <= M_s(b+) + Mc.
template <typename S>
class ThrottleBody {
 public:
  void configure(const ThrottleParameters<S>& p, int substeps) {
    p_ = p;
    substeps_ = std::max(1, substeps);
    breakpoints_[0] = p.phi_LH - p.delta_phi / 2;
    breakpoints_[1] = p.phi_LH + p.delta_phi / 2;
    breakpoints_[2] = p.phi_12;
    // M_s = slope phi + offset on each segment of (4.7): h_s3, dead zone,
    // h_s1, h_s2 (the end segments extended).
    const S points[4] = {breakpoints_[0] - 1, p.phi_LH,
                         breakpoints_[1] + S(1e-3), p.phi_12 + 1};
    for (int s = 0; s < 4; ++s) {
      slope_[s] = s == 0 ? p.Ks3 : (s == 1 ? S(0) : (s == 2 ? p.Ks1 : p.Ks2));
      offset_[s] = spring_torque(p, points[s]) - slope_[s] * points[s];
    }
    set_state(p.phi_LH, 0);
  }

  // At rest (omega = 0) the plate starts stuck; it breaks away as soon as
  // the torque balance allows.
  void set_state(S phi, S omega) {
    phi_ = phi;
    omega_ = omega;
    stuck_ = omega == 0;
    pinned_ = -1;
    direction_ = omega > 0 ? 1 : (omega < 0 ? -1 : 0);
    events_ = 0;
  }

  // Advances over [t_k, t_k + h] with the voltage u held, R(t) linear from
  // r_a to r_b, and the back-emf constant kv_gr = Kv Gr. Returns false if
  // the events pile up (more than kMaxEvents in one interval).
  bool advance(S u, S r_a, S r_b, S kv_gr, S h) {
    u_ = u;
    r_a_ = r_a;
    r_slope_ = (r_b - r_a) / h;
    kv_gr_ = kv_gr;
    const S dt = h / substeps_;
    S t = 0;
    int events = 0;
    for (int step = 1; step <= substeps_; ++step) {
      const S t_end = step == substeps_ ? h : step * dt;
      while (t < t_end) {
        if (++events > kMaxEvents) return false;
        t = stuck_ ? breakaway(t, t_end) : slip(t, t_end);
      }
    }
    return true;
  }

  S phi() const { return phi_; }
  S omega() const { return omega_; }
  bool stuck() const { return stuck_; }
  // Whether the plate is pinned at a pre-load jump of (4.7).
  bool pinned() const { return pinned_ >= 0; }
  // Stops, reversals, breakpoint crossings and breakaways located since
  // set_state.
  long events() const { return events_; }
  // Current (4.11a) at the start of an interval with voltage u and
  // resistance r.
  S current(S u, S r, S kv_gr) const { return (u - kv_gr * omega_) / r; }

 private:
  static constexpr int kMaxEvents = 10000;
  static constexpr int kBisections = 60;

  S resistance(S t) const { return r_a_ + r_slope_ * t; }
  S motor_torque(S t) const { return p_.Kt * p_.Gr * u_ / resistance(t); }
  // The spring segment of (4.7) that phi lies in (0: h_s3, 1: dead zone,
  // 2: h_s1, 3: h_s2); breakpoint j separates segments j and j + 1.
  int segment(S phi) const {
    if (phi < breakpoints_[0]) return 0;
    if (phi <= breakpoints_[1]) return 1;
    if (phi < breakpoints_[2]) return 2;
    return 3;
  }
  S segment_torque(int s, S phi) const { return slope_[s] * phi + offset_[s]; }
  // The acceleration in the mode (direction_, segment_): smooth, so that
  // RK4 keeps its order up to the located events.
  S acceleration(S phi, S omega, S t) const {
    const S torque = p_.Kt * p_.Gr * (u_ - kv_gr_ * omega) / resistance(t) -
                     segment_torque(segment_, phi) - p_.Kb * omega -
                     p_.Mc * direction_;
    return torque / p_.J;
  }
  // One RK4 step of the slipping mode from (phi, omega) at t over tau.
  void rk4(S phi, S omega, S t, S tau, S& phi_out, S& omega_out) const {
    const S k1p = omega;
    const S k1w = acceleration(phi, omega, t);
    const S k2p = omega + tau / 2 * k1w;
    const S k2w =
        acceleration(phi + tau / 2 * k1p, omega + tau / 2 * k1w, t + tau / 2);
    const S k3p = omega + tau / 2 * k2w;
    const S k3w =
        acceleration(phi + tau / 2 * k2p, omega + tau / 2 * k2w, t + tau / 2);
    const S k4p = omega + tau * k3w;
    const S k4w = acceleration(phi + tau * k3p, omega + tau * k3w, t + tau);
    phi_out = phi + tau / 6 * (k1p + 2 * k2p + 2 * k3p + k4p);
    omega_out = omega + tau / 6 * (k1w + 2 * k2w + 2 * k3w + k4w);
  }
  // Whether a step of the mode ends past an event: omega stopped, or phi
  // in another spring segment.
  bool event_happened(S phi, S omega) const {
    return direction_ * omega <= 0 || segment(phi) != segment_;
  }

  // Slipping from t: a step to t_end, or to the first event before it.
  S slip(S t, S t_end) {
    segment_ = segment(phi_);
    S phi1, omega1;
    const S tau = t_end - t;
    rk4(phi_, omega_, t, tau, phi1, omega1);
    if (!event_happened(phi1, omega1)) {
      phi_ = phi1;
      omega_ = omega1;
      return t_end;
    }
    // Bisection on the step length: lo before the event, hi past it.
    S lo = 0, hi = tau;
    for (int it = 0; it < kBisections; ++it) {
      const S mid = (lo + hi) / 2;
      if (mid <= lo || mid >= hi) break;
      S phi_mid, omega_mid;
      rk4(phi_, omega_, t, mid, phi_mid, omega_mid);
      if (event_happened(phi_mid, omega_mid)) {
        hi = mid;
        phi1 = phi_mid;
        omega1 = omega_mid;
      } else {
        lo = mid;
      }
    }
    ++events_;
    const S t_event = t + hi;
    phi_ = phi1;
    if (direction_ * omega1 <= 0) {  // stop: stick or reverse
      omega_ = 0;
      const S torque = motor_torque(t_event) - spring_torque(p_, phi_);
      if (std::abs(torque) <= p_.Mc) {
        stuck_ = true;
        direction_ = 0;
      } else {
        direction_ = torque > 0 ? 1 : -1;
      }
      return t_event;
    }
    omega_ = omega1;
    const int entered = segment(phi_);
    pin_if_trapped(std::min(segment_, entered), entered, t_event);
    return t_event;
  }

  // Just past breakpoint j into segment `entered`: pins the plate at it if
  // the spring jump there traps it (stick condition above) and its next
  // excursion omega^2 J / (2 |net torque|) would be below 1e-12 rad.
  void pin_if_trapped(int j, int entered, S t) {
    const S b = breakpoints_[j];
    const S below = segment_torque(j, b), above = segment_torque(j + 1, b);
    if (!(above > below)) return;  // no pre-load jump (phi_12)
    const S motor = motor_torque(t);
    if (motor > above + p_.Mc || motor < below - p_.Mc) return;
    const S net = motor - segment_torque(entered, b) - p_.Mc * direction_;
    if (!(net * direction_ < 0)) return;
    if (omega_ * omega_ * p_.J / (2 * std::abs(net)) > S(1e-12)) return;
    phi_ = b;
    omega_ = 0;
    stuck_ = true;
    pinned_ = j;
    direction_ = 0;
  }

  // Stuck from t: stays stuck to t_end, or breaks away where the motor
  // torque leaves [M_s(below) - Mc, M_s(above) + Mc] (monotone in t: R is
  // linear).
  S breakaway(S t, S t_end) {
    S ms_below, ms_above;
    if (pinned_ >= 0) {
      ms_below = segment_torque(pinned_, phi_);
      ms_above = segment_torque(pinned_ + 1, phi_);
    } else {
      ms_below = ms_above = spring_torque(p_, phi_);
    }
    const S high = ms_above + p_.Mc, low = ms_below - p_.Mc;
    const S now = motor_torque(t);
    if (now > high || now < low) {
      release(now > high ? 1 : -1);
      return t;
    }
    const S end = motor_torque(t_end);
    if (end <= high && end >= low) return t_end;
    const int dir = end > high ? 1 : -1;
    // Kt Gr u / R(t_b) = threshold, R linear in t.
    const S threshold = dir > 0 ? high : low;
    S t_b = t_end;
    if (threshold != 0 && r_slope_ != 0) {
      const S r_b = p_.Kt * p_.Gr * u_ / threshold;
      t_b = std::clamp((r_b - r_a_) / r_slope_, t, t_end);
    }
    ++events_;
    release(dir);
    return t_b;
  }

  void release(int dir) {
    if (pinned_ >= 0) {  // leave the breakpoint on the side of the motion
      phi_ = std::nextafter(phi_, dir > 0 ? std::numeric_limits<S>::max()
                                          : std::numeric_limits<S>::lowest());
      pinned_ = -1;
    }
    stuck_ = false;
    direction_ = dir;
  }

  ThrottleParameters<S> p_ = ThrottleParameters<S>::table_4_3();
  int substeps_ = 1;
  S breakpoints_[3] = {0, 0, 0};
  S slope_[4] = {0, 0, 0, 0}, offset_[4] = {0, 0, 0, 0};
  int segment_ = 1;
  S phi_ = 0, omega_ = 0;
  bool stuck_ = true;
  int pinned_ = -1;
  int direction_ = 0;
  long events_ = 0;
  S u_ = 0, r_a_ = 1, r_slope_ = 0, kv_gr_ = 0;
};

// The plate in its loop (Fig. 4.11): set-point filter, PID, voltage limit.
// Used for the true system and for the auxiliary model of the estimator.
template <typename S>
class ThrottleLoop {
 public:
  void configure(const ThrottleParameters<S>& p, const ThrottleController<S>& c,
                 int substeps) {
    p_ = p;
    c_ = c;
    body_.configure(p, substeps);
    pid_.configure(c.pid);
    setpoint_.configure(c.setpoint_filter);
  }

  // At rest at phi0 (omega = 0), the set-point filter at rest around
  // phi_d0, the PID's integrator holding u_offset.
  void reset(S phi0, S phi_d0, S u_offset) {
    body_.set_state(phi0, 0);
    pid_.reset();
    setpoint_.reset();
    phi_d0_ = phi_d0;
    u_offset_ = u_offset;
    saturated_ = 0;
  }

  // The voltage that holds phi0 against the spring with resistance r.
  S holding_voltage(S phi0, S r) const {
    return r * spring_torque(p_, phi0) / (p_.Kt * p_.Gr);
  }

  // u(t_k) from the set point phi_d(t_k) and the fed-back angle y(t_k).
  S control(S phi_d, S y) {
    reference_ = phi_d0_ + setpoint_.step(phi_d - phi_d0_);
    const S v = u_offset_ + pid_.step(reference_ - y);
    const S u = std::clamp(v, -c_.u_max, c_.u_max);
    if (u != v) ++saturated_;
    return u;
  }

  bool advance(S u, S r_a, S r_b, S kv_gr, S h) {
    return body_.advance(u, r_a, r_b, kv_gr, h);
  }

  const ThrottleBody<S>& body() const { return body_; }
  S reference() const { return reference_; }
  long saturated() const { return saturated_; }

 private:
  ThrottleParameters<S> p_;
  ThrottleController<S> c_;
  ThrottleBody<S> body_;
  DiscreteFilter<S> pid_, setpoint_;
  S phi_d0_ = 0, u_offset_ = 0, reference_ = 0;
  long saturated_ = 0;
};

// ---------------------------------------------------------------------------
// Simulation of the closed loop.

template <typename S>
struct ThrottleSimulationConfig {
  ThrottleParameters<S> plant = ThrottleParameters<S>::table_4_3();
  ThrottleController<S> controller;
  S ts = S(1e-3);
  int substeps = 2;
  S phi0 = std::numeric_limits<S>::quiet_NaN();  // NaN: phi_d(t_1)
};

// Inputs, N samples each: the set point, R(t_k) (linear in between) and
// the measurement noise e(t_k) (null: none).
template <typename S>
struct ThrottleSimulationInputs {
  const S* phi_d = nullptr;
  const S* resistance = nullptr;
  const S* noise = nullptr;
  Eigen::Index num_samples = 0;
};

// Outputs, N samples each, caller-owned; null entries are not written.
template <typename S>
struct ThrottleSimulationOutputs {
  S* u = nullptr;          // applied voltage, held over [t_k, t_(k+1))
  S* i = nullptr;          // current (4.11a) at t_k (with u(t_k))
  S* phi = nullptr;        // true angle
  S* phi_m = nullptr;      // measured angle (4.11d)
  S* omega = nullptr;      // angular velocity
  S* reference = nullptr;  // filtered set point F_phi phi_d
};

template <typename S>
struct ThrottleSimulationInfo {
  long saturated = 0;           // samples with |u| at u_max
  long outside_linear = 0;      // samples with phi outside (4.16)
  long events = 0;              // located stops, reversals, crossings
  S phi_low = 0, phi_high = 0;  // range of the true angle
};

template <typename S>
Status validate(const ThrottleSimulationConfig<S>& c) {
  Status status = validate(c.plant);
  if (!status.ok()) return status;
  status = validate(c.controller);
  if (!status.ok()) return status;
  if (!(c.ts > 0) || !std::isfinite(c.ts)) {
    return bad_input("Ts must be finite and > 0");
  }
  if (c.substeps < 1 || c.substeps > 10000) {
    return bad_input("substeps must be an integer in [1, 10000]");
  }
  if (!std::isnan(c.phi0) &&
      !(c.phi0 >= c.plant.phi_min && c.phi0 <= c.plant.phi_max)) {
    return bad_input("phi0 must lie in [phi_min, phi_max]");
  }
  return Status::Ok();
}

template <typename S>
Status simulate_throttle(const ThrottleSimulationConfig<S>& config,
                         const ThrottleSimulationInputs<S>& in,
                         const ThrottleSimulationOutputs<S>& out,
                         ThrottleSimulationInfo<S>* info = nullptr) {
  Status status = validate(config);
  if (!status.ok()) return status;
  const Eigen::Index n = in.num_samples;
  if (n < 1 || in.phi_d == nullptr || in.resistance == nullptr) {
    return bad_input("the set point and R(t) must have at least one sample");
  }
  for (Eigen::Index k = 0; k < n; ++k) {
    if (!std::isfinite(in.phi_d[k])) {
      return bad_input("phi_d must be finite");
    }
    if (!(in.resistance[k] > 0) || !std::isfinite(in.resistance[k])) {
      return bad_input("R(t) must be finite and > 0");
    }
    if (in.noise != nullptr && !std::isfinite(in.noise[k])) {
      return bad_input("the noise must be finite");
    }
  }
  const ThrottleParameters<S>& p = config.plant;
  const S phi0 = std::isnan(config.phi0) ? in.phi_d[0] : config.phi0;
  if (!(phi0 >= p.phi_min && phi0 <= p.phi_max)) {
    return bad_input(
        "the initial angle phi_d(t_1) must lie in [phi_min, "
        "phi_max]");
  }
  ThrottleLoop<S> loop;
  loop.configure(p, config.controller, config.substeps);
  loop.reset(phi0, in.phi_d[0], loop.holding_voltage(phi0, in.resistance[0]));
  const S kv_gr = p.Kv * p.Gr;
  ThrottleSimulationInfo<S> summary;
  summary.phi_low = summary.phi_high = phi0;
  for (Eigen::Index k = 0; k < n; ++k) {
    const S phi = loop.body().phi();
    const S omega = loop.body().omega();
    if (!(phi >= p.phi_min && phi <= p.phi_max)) {
      return bad_input(
          "the angle left [phi_min, phi_max] at t = " +
          std::to_string(static_cast<double>(k * config.ts)) +
          " s, where the spring model (4.7) is not defined: keep the set "
          "point inside (4.16)");
    }
    summary.phi_low = std::min(summary.phi_low, phi);
    summary.phi_high = std::max(summary.phi_high, phi);
    if (!(phi > p.linear_region_low() && phi < p.linear_region_high())) {
      ++summary.outside_linear;
    }
    const S phi_m = phi + (in.noise ? in.noise[k] : S(0));
    const S u = loop.control(in.phi_d[k], phi_m);
    const S r = in.resistance[k];
    if (out.u) out.u[k] = u;
    if (out.i) out.i[k] = loop.body().current(u, r, kv_gr);
    if (out.phi) out.phi[k] = phi;
    if (out.phi_m) out.phi_m[k] = phi_m;
    if (out.omega) out.omega[k] = omega;
    if (out.reference) out.reference[k] = loop.reference();
    if (k + 1 < n &&
        !loop.advance(u, r, in.resistance[k + 1], kv_gr, config.ts)) {
      return numerical_failure(
          "the friction events pile up at t = " +
          std::to_string(static_cast<double>(k * config.ts)) +
          " s; raise substeps");
    }
  }
  summary.saturated = loop.saturated();
  summary.events = loop.body().events();
  if (info != nullptr) *info = summary;
  return Status::Ok();
}

// ---------------------------------------------------------------------------
// Recursive estimation of the electrical submodel, eqs. (4.14)-(4.22).

enum class ThrottleIdMethod { kRlsSvf, kClrsrivc, kRlsPrefilter };

template <typename S>
struct ThrottleIdConfig {
  ThrottleIdMethod method = ThrottleIdMethod::kClrsrivc;
  // Known mechanical parameters (prefilter (4.19), auxiliary model); R and
  // Kv give the auxiliary model's electrical part until the first
  // acceptable estimate.
  ThrottleParameters<S> plant = ThrottleParameters<S>::table_4_3();
  ThrottleController<S> controller;  // the known loop (auxiliary model)
  S lambda_svf = S(5 * 12.4);        // SVF (4.22) of RLSSVF, rad/s
  Adaptation<S> adaptation = KalmanAdaptation<S>(
      (Matrix<S>(2, 2) << S(1e-6), 0, 0, S(5e-5)).finished());
  Vector<S> theta0;  // empty: zeros
  Matrix<S> P0;      // empty: 1e4 I
  S ts = S(1e-3);
  S t_s_iv = 5;      // CLRSRIVC: IV from t - t_1 >= t_s_iv
  int substeps = 2;  // auxiliary model integration
  InterSample phi_intersample = InterSample::kZoh;
  S phi0 = std::numeric_limits<S>::quiet_NaN();  // aux start; NaN: phi_d(t_1)
};

template <typename S>
Status validate(const ThrottleIdConfig<S>& c) {
  Status status = validate(c.plant);
  if (!status.ok()) return status;
  status = validate(c.controller);
  if (!status.ok()) return status;
  if (!(c.lambda_svf > 0) || !std::isfinite(c.lambda_svf)) {
    return bad_input("lambda_svf must be finite and > 0");
  }
  status = validate_adaptation(c.adaptation, 2);
  if (!status.ok()) return status;
  status = validate_initial_estimate(c.theta0, c.P0, 2);
  if (!status.ok()) return status;
  if (!(c.ts > 0) || !std::isfinite(c.ts)) {
    return bad_input("Ts must be finite and > 0");
  }
  if (!(c.t_s_iv >= 0) || !std::isfinite(c.t_s_iv)) {
    return bad_input("tsiv must be finite and >= 0");
  }
  if (c.substeps < 1 || c.substeps > 10000) {
    return bad_input("substeps must be an integer in [1, 10000]");
  }
  return Status::Ok();
}

// Denominator [d1 d2] and gain of the prefilter: (4.19) or (4.22).
template <typename S>
void throttle_prefilter(const ThrottleIdConfig<S>& c, Vector<S>& d, S& gain) {
  d.resize(2);
  if (c.method != ThrottleIdMethod::kRlsSvf) {
    d << c.plant.Kb / c.plant.J, c.plant.Ks1 / c.plant.J;
    gain = c.plant.Ks1 / c.plant.J;
  } else {
    d = svf_denominator<S>(2, c.lambda_svf);
    gain = c.lambda_svf * c.lambda_svf;
  }
}

template <typename S>
class ThrottleEstimator {
 public:
  Status configure(const ThrottleIdConfig<S>& config) {
    const Status status = validate(config);
    if (!status.ok()) return status;
    config_ = config;
    if (config_.theta0.size() == 0) config_.theta0 = Vector<S>::Zero(2);
    if (config_.P0.size() == 0) config_.P0 = S(1e4) * Matrix<S>::Identity(2, 2);
    Vector<S> d;
    throttle_prefilter(config_, d, gain_);
    zoh_disc_.configure(2, InterSample::kZoh);
    zoh_disc_.set_denominator(d);
    phi_disc_.configure(2, config.phi_intersample);
    phi_disc_.set_denominator(d);
    for (FilterChannel<S>* c : {&u_f_, &i_f_, &phi_f_, &uhat_f_, &phihat_f_}) {
      c->configure(2);
    }
    update_.configure(2, config.adaptation);
    aux_.configure(config.plant, config.controller, config.substeps);
    regressor_ = Vector<S>::Zero(2);
    instrument_ = Vector<S>::Zero(2);
    reset();
    return Status::Ok();
  }

  void reset() {
    for (FilterChannel<S>* c : {&u_f_, &i_f_, &phi_f_, &uhat_f_, &phihat_f_}) {
      c->reset();
    }
    update_.reset(config_.theta0, config_.P0);
    aux_r_ = config_.plant.R;
    aux_kv_gr_ = config_.plant.Kv * config_.plant.Gr;
    first_ = true;
    elapsed_ = 0;
    iv_active_ = false;
    rejections_ = 0;
    aux_failed_ = false;
    uhat_ = phihat_ = 0;
  }

  // One recursion with phi_d(t_k), u(t_k), i(t_k), phi_m(t_k); h = t_k -
  // t_(k-1) (ignored for the first sample). Returns theta(t_k).
  const Vector<S>& update(S phi_d, S u, S i, S phi_m, S h) {
    if (first_) {
      h = config_.ts;
      phi_offset_ = phi_d;
      if (config_.method == ThrottleIdMethod::kClrsrivc) {
        const S phi0 = std::isnan(config_.phi0) ? phi_d : config_.phi0;
        aux_.reset(phi0, phi_d, aux_.holding_voltage(phi0, aux_r_));
      }
    } else {
      elapsed_ += h;
    }
    zoh_disc_.ensure(h);
    phi_disc_.ensure(h);
    u_f_.step(zoh_disc_, gain_, u);
    i_f_.step(zoh_disc_, gain_, i);
    phi_f_.step(phi_disc_, gain_, phi_m - phi_offset_);
    regressor_(0) = u_f_.outputs()(0);
    regressor_(1) = -phi_f_.outputs()(1);
    const S target = i_f_.outputs()(0);
    if (config_.method != ThrottleIdMethod::kClrsrivc) {
      prediction_error_ = update_.update(regressor_, target);
      first_ = false;
      return update_.theta();
    }
    // Closed-loop auxiliary model (4.21), Fig. 4.12.
    if (!first_ && !aux_failed_) {
      aux_failed_ = !aux_.advance(uhat_, aux_r_, aux_r_, aux_kv_gr_, h);
    }
    first_ = false;
    phihat_ = aux_.body().phi();
    uhat_ = aux_.control(phi_d, phihat_);
    uhat_f_.step(zoh_disc_, gain_, uhat_);
    phihat_f_.step(phi_disc_, gain_, phihat_ - phi_offset_);
    instrument_(0) = uhat_f_.outputs()(0);
    instrument_(1) = -phihat_f_.outputs()(1);
    iv_active_ = elapsed_ >= config_.t_s_iv * (1 - 1e-12);
    prediction_error_ = iv_active_
                            ? update_.update(regressor_, instrument_, target)
                            : update_.update(regressor_, target);
    feed_back(update_.theta());
    return update_.theta();
  }

  const Vector<S>& theta() const { return update_.theta(); }
  const Matrix<S>& P() const { return update_.P(); }
  bool iv_active() const { return iv_active_; }
  // Estimates refused for the auxiliary model (theta1 <= 0, theta2 < 0).
  long rejections() const { return rejections_; }
  bool auxiliary_failed() const { return aux_failed_; }
  S auxiliary_angle() const { return phihat_; }
  S auxiliary_voltage() const { return uhat_; }
  S prediction_error() const { return prediction_error_; }

 private:
  // The auxiliary model takes the estimate when it is physical: R > 0 and
  // Kv >= 0 (the loop with the known PID is stable over (4.10)).
  void feed_back(const Vector<S>& theta) {
    if (theta.allFinite() && theta(0) > 0 && theta(1) >= 0) {
      aux_r_ = 1 / theta(0);
      aux_kv_gr_ = theta(1) / theta(0);
    } else {
      ++rejections_;
    }
  }

  ThrottleIdConfig<S> config_;
  FilterDiscretization<S> zoh_disc_, phi_disc_;
  FilterChannel<S> u_f_, i_f_, phi_f_, uhat_f_, phihat_f_;
  S gain_ = 1;
  ParameterUpdate<S> update_;
  ThrottleLoop<S> aux_;
  Vector<S> regressor_, instrument_;
  S aux_r_ = 1, aux_kv_gr_ = 0;
  S uhat_ = 0, phihat_ = 0, phi_offset_ = 0;
  bool first_ = true, iv_active_ = false, aux_failed_ = false;
  S elapsed_ = 0;
  long rejections_ = 0;
  S prediction_error_ = 0;
};

// A throttle record, N samples each, uniformly sampled.
template <typename S>
struct ThrottleRecord {
  const S* phi_d = nullptr;
  const S* u = nullptr;
  const S* i = nullptr;
  const S* phi_m = nullptr;
  Eigen::Index num_samples = 0;
  S ts = 0;
};

// Outputs of run_throttle_id (caller-owned, column-major): thm N-by-2;
// optional pset (2*2*N), kappa (N), and the auxiliary model's angle and
// voltage (N each, CLRSRIVC only).
template <typename S>
struct ThrottleIdOutputs {
  S* thm = nullptr;
  S* pset = nullptr;
  S* kappa = nullptr;
  S* phi_hat = nullptr;
  S* u_hat = nullptr;
};

template <typename S>
struct ThrottleIdInfo {
  long rejections = 0;
  bool auxiliary_failed = false;
};

template <typename S>
Status validate(const ThrottleRecord<S>& r) {
  if (r.num_samples < 2) return bad_input("the record needs >= 2 samples");
  if (!(r.ts > 0) || !std::isfinite(r.ts)) {
    return bad_input("Ts must be finite and > 0");
  }
  const S* signals[] = {r.phi_d, r.u, r.i, r.phi_m};
  const char* names[] = {"phi_d", "u", "i", "phi_m"};
  for (int s = 0; s < 4; ++s) {
    if (signals[s] == nullptr)
      return bad_input(std::string(names[s]) + " is missing");
    for (Eigen::Index k = 0; k < r.num_samples; ++k) {
      if (!std::isfinite(signals[s][k])) {
        return bad_input(std::string(names[s]) + " must be finite (sample " +
                         std::to_string(k + 1) + " is not)");
      }
    }
  }
  return Status::Ok();
}

// Runs a ThrottleEstimator over a record (the pattern of
// record_recursive_run in rlssvf.hpp).
template <typename S>
Status run_throttle_id(const ThrottleIdConfig<S>& config,
                       const ThrottleRecord<S>& record,
                       const ThrottleIdOutputs<S>& out,
                       ThrottleIdInfo<S>* info = nullptr) {
  Status status = validate(record);
  if (!status.ok()) return status;
  const Eigen::Index n = record.num_samples;
  if (config.method == ThrottleIdMethod::kClrsrivc &&
      config.t_s_iv > (n - 1) * record.ts * (1 + 1e-12)) {
    return bad_input(
        "tsiv = " + std::to_string(static_cast<double>(config.t_s_iv)) +
        " s lies outside the record (length " +
        std::to_string(static_cast<double>((n - 1) * record.ts)) + " s)");
  }
  ThrottleIdConfig<S> adjusted = config;
  adjusted.ts = record.ts;
  ThrottleEstimator<S> estimator;
  status = estimator.configure(adjusted);
  if (!status.ok()) return status;
  for (Eigen::Index k = 0; k < n; ++k) {
    const Vector<S>& theta = estimator.update(
        record.phi_d[k], record.u[k], record.i[k], record.phi_m[k], record.ts);
    out.thm[k] = theta(0);
    out.thm[n + k] = theta(1);
    if (out.pset) {
      std::copy(estimator.P().data(), estimator.P().data() + 4,
                out.pset + 4 * k);
    }
    if (out.kappa) out.kappa[k] = kappa_2(estimator.P());
    if (out.phi_hat) out.phi_hat[k] = estimator.auxiliary_angle();
    if (out.u_hat) out.u_hat[k] = estimator.auxiliary_voltage();
  }
  if (info != nullptr) {
    info->rejections = estimator.rejections();
    info->auxiliary_failed = estimator.auxiliary_failed();
  }
  for (Eigen::Index k = 0; k < 2 * n; ++k) {
    if (!std::isfinite(out.thm[k])) {
      return numerical_failure(
          "the estimates became non-finite; check the scaling of the data");
    }
  }
  if (estimator.auxiliary_failed()) {
    return numerical_failure(
        "the auxiliary model's friction events piled up; raise substeps");
  }
  return Status::Ok();
}

}  // namespace ctid
