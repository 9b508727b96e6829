// SPDX-License-Identifier: BSD-3-Clause
// Copyright (C) the ctid authors
// Simulation of the continuous-time LTV system of eq. (1.49),
//
//   x^(na) + a1(t) x^(na-1) + .. + a_na(t) x = sum_j B_j(p, t) u_j(t - nk_j Ts)
//   y(t_k) = x(t_k) + e(t_k),
//
// in open loop, or in the closed loop u = r1 + C(q^-1)(r2 - y) of eq. (2.39)
// with a discrete controller.
//
// Realisation, per input, in controllable canonical form A(p,t) w_j = u_j,
// x = sum_j B_j(p,t) w_j. When nb_j = 1 the gain b_j,0(t) enters with the
// input instead (phase-variable form), which solves the differential
// equation x^(na) + .. = b0(t) u exactly; for nb_j > 1 the numerator acts on
// w_j (the usual frozen-coefficient reading for slowly varying systems).
//
// Integration: the input is held (ZOH) or linear (FOH) between samples and
// is appended to the state, so each interval is a homogeneous linear ODE
// xi' = M(t) xi, advanced with the fourth-order Magnus integrator with two
// Gauss points,
//   Omega = h/2 (M1 + M2) + sqrt(3)/12 h^2 [M2, M1],  xi <- expm(Omega) xi,
// on `substeps` equal sub-intervals. It is exact for time-invariant
// coefficients (one matrix exponential, reused while the coefficients stay
// the same) and has a local error O(h^5 |M'|) otherwise; the tests measure it
// against an analytic LTV solution. The exponential is taken of the
// balanced Omega (balanced_exponential.hpp): the canonical form of a
// high-order model with widely spread poles has coefficients over many
// decades, whose direct exponential makes a stable model's propagator
// unstable.
#pragma once

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <vector>

#include "ctid/base/balanced_exponential.hpp"
#include "ctid/base/delay_line.hpp"
#include "ctid/base/model.hpp"
#include "ctid/base/record.hpp"
#include "ctid/filters/discretization.hpp"
#include "ctid/simulation/controller.hpp"

namespace ctid {

// theta(t) in the layout of model.hpp, written into its second argument.
template <typename S>
using ParameterTrajectory = std::function<void(S, Vector<S>&)>;

// theta given at the sampling instants, linear in between (and constant
// outside the record).
template <typename S>
ParameterTrajectory<S> piecewise_linear_trajectory(const S* instants,
                                                   const S* thetas,
                                                   Eigen::Index n,
                                                   Eigen::Index np) {
  return [instants, thetas, n, np](S t, Vector<S>& theta) {
    theta.resize(np);
    auto value = [&](Eigen::Index k, Eigen::Index i) {
      return thetas[i * n + k];  // column-major N-by-np
    };
    if (n == 1 || t <= instants[0]) {
      for (Eigen::Index i = 0; i < np; ++i) theta(i) = value(0, i);
      return;
    }
    if (t >= instants[n - 1]) {
      for (Eigen::Index i = 0; i < np; ++i) theta(i) = value(n - 1, i);
      return;
    }
    const S* upper = std::upper_bound(instants, instants + n, t);
    const Eigen::Index k = (upper - instants) - 1;
    const S w = (t - instants[k]) / (instants[k + 1] - instants[k]);
    for (Eigen::Index i = 0; i < np; ++i) {
      theta(i) = (1 - w) * value(k, i) + w * value(k + 1, i);
    }
  };
}

// Standard deviation that gives unit-variance noise the signal-to-noise ratio
// SNR = 10 log10(P_x / P_e) of eq. (1.64), P_x the mean square of x.
template <typename S>
S noise_scale_for_snr(const S* x, Eigen::Index n, S snr_db) {
  S power = 0;
  for (Eigen::Index k = 0; k < n; ++k) power += x[k] * x[k];
  power /= static_cast<S>(n);
  return std::sqrt(power / std::pow(S(10), snr_db / 10));
}

template <typename S>
struct LtvSimulationConfig {
  ModelOrders orders;
  InterSample u_intersample = InterSample::kZoh;
  int substeps = 1;
  Vector<S> initial_state;  // na * num_inputs values; empty: at rest
  bool closed_loop = false;
  DiscreteTransferFunction<S> controller;
};

// Signals: in open loop `record.u` is the input u; in closed loop it is r1
// and `r2` is the second external signal. `noise` (optional) is e(t_k).
// Outputs (caller-owned, N each; u_applied N-by-nu, optional): the
// noise-free x, the measured y = x + e and the applied input.
template <typename S>
struct SimulationOutputs {
  S* x = nullptr;
  S* y = nullptr;
  S* u_applied = nullptr;
};

template <typename S>
class LtvSimulator {
 public:
  Status configure(const LtvSimulationConfig<S>& config) {
    Status status = validate_orders(config.orders);
    if (!status.ok()) return status;
    if (config.substeps < 1) {
      return bad_input("substeps must be an integer >= 1");
    }
    const int nu = config.orders.num_inputs();
    if (config.closed_loop) {
      if (nu != 1) {
        return bad_input("closed-loop simulation needs a single input");
      }
      if (config.u_intersample != InterSample::kZoh) {
        return bad_input(
            "closed-loop simulation needs a ZOH input "
            "(the controller output is held between samples)");
      }
      status = validate_controller(config.controller);
      if (!status.ok()) return status;
    }
    config_ = config;
    ns_ = config.orders.na * nu;
    nin_ = config.u_intersample == InterSample::kZoh ? nu : 2 * nu;
    if (config.initial_state.size() != 0 &&
        config.initial_state.size() != ns_) {
      return dimension_mismatch("the initial state must have na * nu = " +
                                std::to_string(ns_) + " elements");
    }
    if (config.initial_state.size() != 0 && !config.initial_state.allFinite()) {
      return bad_input("the initial state must be finite");
    }
    const Eigen::Index dim = ns_ + nin_;
    xi_ = Vector<S>::Zero(dim);
    m1_ = Matrix<S>::Zero(dim, dim);
    m2_ = Matrix<S>::Zero(dim, dim);
    m1_prev_ = Matrix<S>::Constant(dim, dim, S(NAN));
    m2_prev_ = m1_prev_;
    h_prev_ = -1;
    return Status::Ok();
  }

  Status simulate(const ParameterTrajectory<S>& trajectory,
                  const RecordView<S>& record, const S* r2, const S* noise,
                  const SimulationOutputs<S>& out) {
    const ModelOrders& orders = config_.orders;
    const int nu = orders.num_inputs();
    const Eigen::Index n = record.num_samples;
    if (record.num_inputs != nu) {
      return dimension_mismatch(
          "the input has " + std::to_string(record.num_inputs) +
          " column(s) but the model has " + std::to_string(nu) + " input(s)");
    }
    if (n < 1) return bad_input("the record is empty");
    if (config_.closed_loop && r2 == nullptr) {
      return bad_input("closed-loop simulation needs r2");
    }
    const Eigen::Index np = orders.num_parameters();
    std::vector<DelayLine<S>> delays(nu);
    for (int j = 0; j < nu; ++j) delays[j].configure(orders.nk[j]);
    DiscreteFilter<S> controller;
    if (config_.closed_loop) controller.configure(config_.controller);

    // Delayed plant input at every sample: known in advance in open loop,
    // filled as the loop runs in closed loop.
    Matrix<S> u_in(n, nu);
    if (!config_.closed_loop) {
      for (int j = 0; j < nu; ++j) {
        for (Eigen::Index k = 0; k < n; ++k) {
          u_in(k, j) = delays[j].push(record.u_at(k, j));
        }
      }
    }
    xi_.setZero();
    if (config_.initial_state.size() != 0) {
      xi_.head(ns_) = config_.initial_state;
    }
    Vector<S> theta(np);
    for (Eigen::Index k = 0; k < n; ++k) {
      const S t = record.instants ? record.instants[k] : k * record.ts;
      trajectory(t, theta);
      if (theta.size() != np || !theta.allFinite()) {
        return bad_input("the parameter trajectory must give " +
                         std::to_string(np) + " finite values (at t = " +
                         std::to_string(static_cast<double>(t)) + ")");
      }
      const S e = noise ? noise[k] : S(0);
      const S x_free = free_output(theta);
      S x = 0;
      if (!config_.closed_loop) {
        x = x_free;
        for (int j = 0; j < nu; ++j) x += feedthrough(theta, j) * u_in(k, j);
        if (out.u_applied) {
          for (int j = 0; j < nu; ++j)
            out.u_applied[j * n + k] = record.u_at(k, j);
        }
      } else {
        const S d = feedthrough(theta, 0);
        S u = 0;
        if (orders.nk[0] == 0) {
          // u = r1 + c0 (r2 - x - e) + v_past with x = x_free + d u.
          const S c0 = controller.feedthrough();
          const S loop = 1 + c0 * d;
          if (std::abs(loop) < 1e3 * std::numeric_limits<S>::epsilon()) {
            return numerical_failure(
                "the closed loop has a singular "
                "algebraic loop (1 + c0 * b0 = 0)");
          }
          u = (record.u_at(k, 0) + c0 * (r2[k] - e - x_free) +
               controller.free_response()) /
              loop;
          x = x_free + d * u;
          controller.step(r2[k] - x - e);
          u_in(k, 0) = u;
        } else {
          // The plant sees u(t_(k-nk)), already known.
          u_in(k, 0) = delays[0].oldest();
          x = x_free + d * u_in(k, 0);
          u = record.u_at(k, 0) + controller.step(r2[k] - x - e);
          delays[0].push(u);
        }
        if (out.u_applied) out.u_applied[k] = u;
      }
      if (out.x) out.x[k] = x;
      if (out.y) out.y[k] = x + e;
      if (!std::isfinite(x)) {
        return numerical_failure("the simulated output is not finite at t = " +
                                 std::to_string(static_cast<double>(t)) +
                                 " (unstable system or closed loop?)");
      }
      if (k + 1 < n) {
        const S t_next =
            record.instants ? record.instants[k + 1] : (k + 1) * record.ts;
        advance(trajectory, t, t_next, u_in, k, n);
      }
    }
    return Status::Ok();
  }

 private:
  // Output for zero current input: the part of x(t_k) set by the state.
  S free_output(const Vector<S>& theta) const {
    const ModelOrders& orders = config_.orders;
    const int na = orders.na;
    S x = 0;
    for (int j = 0; j < orders.num_inputs(); ++j) {
      const Eigen::Index r = static_cast<Eigen::Index>(j) * na;
      const int nb = orders.nb[j];
      if (nb == 1) {
        x += xi_(r);
        continue;
      }
      const int offset = orders.numerator_offset(j);
      for (int l = 0; l < nb; ++l) {
        const int derivative = nb - 1 - l;
        S w = 0;
        if (derivative < na) {
          w = xi_(r + derivative);
        } else {  // w^(na) = u - sum a_i w^(na-i); the u part is feedthrough
          for (int i = 1; i <= na; ++i) w -= theta(i - 1) * xi_(r + na - i);
        }
        x += theta(offset + l) * w;
      }
    }
    return x;
  }

  // d x(t_k) / d u_j(t_k): b_j,0 when nb_j = na + 1, else 0.
  S feedthrough(const Vector<S>& theta, int j) const {
    const ModelOrders& orders = config_.orders;
    if (orders.nb[j] != orders.na + 1 || orders.nb[j] == 1) return 0;
    return theta(orders.numerator_offset(j));
  }

  void build_generator(const Vector<S>& theta, Matrix<S>& m) const {
    const ModelOrders& orders = config_.orders;
    const int na = orders.na;
    const int nu = orders.num_inputs();
    m.setZero();
    for (int j = 0; j < nu; ++j) {
      const Eigen::Index r = static_cast<Eigen::Index>(j) * na;
      for (int i = 0; i + 1 < na; ++i) m(r + i, r + i + 1) = 1;
      for (int c = 0; c < na; ++c) m(r + na - 1, r + c) = -theta(na - 1 - c);
      m(r + na - 1, ns_ + j) =
          orders.nb[j] == 1 ? theta(orders.numerator_offset(j)) : S(1);
      if (nin_ == 2 * nu) m(ns_ + j, ns_ + nu + j) = 1;
    }
  }

  void advance(const ParameterTrajectory<S>& trajectory, S t0, S t1,
               const Matrix<S>& u_in, Eigen::Index k, Eigen::Index n) {
    const int nu = config_.orders.num_inputs();
    const S h = t1 - t0;
    for (int j = 0; j < nu; ++j) {
      xi_(ns_ + j) = u_in(k, j);
      if (nin_ == 2 * nu) {
        const S next = k + 1 < n ? u_in(k + 1, j) : u_in(k, j);
        xi_(ns_ + nu + j) = (next - u_in(k, j)) / h;
      }
    }
    const int m = config_.substeps;
    const S hs = h / m;
    const S c1 = S(0.5) - std::sqrt(S(3)) / 6;
    const S c2 = S(0.5) + std::sqrt(S(3)) / 6;
    Vector<S> theta;
    for (int s = 0; s < m; ++s) {
      const S tau = t0 + s * hs;
      trajectory(tau + c1 * hs, theta);
      build_generator(theta, m1_);
      trajectory(tau + c2 * hs, theta);
      build_generator(theta, m2_);
      const S tolerance = 64 * std::numeric_limits<S>::epsilon();
      if (!(m1_ == m1_prev_ && m2_ == m2_prev_ &&
            std::abs(hs - h_prev_) <= tolerance * hs)) {
        const Matrix<S> omega =
            (hs / 2) * (m1_ + m2_) +
            (std::sqrt(S(3)) / 12) * hs * hs * (m2_ * m1_ - m1_ * m2_);
        propagator_ = balanced_exp<S>(omega);
        m1_prev_ = m1_;
        m2_prev_ = m2_;
        h_prev_ = hs;
      }
      xi_ = propagator_ * xi_;
    }
  }

  LtvSimulationConfig<S> config_;
  Eigen::Index ns_ = 0;
  Eigen::Index nin_ = 0;
  Vector<S> xi_;
  Matrix<S> m1_, m2_, m1_prev_, m2_prev_, propagator_;
  S h_prev_ = -1;
};

}  // namespace ctid
