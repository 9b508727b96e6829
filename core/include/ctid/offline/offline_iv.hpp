// SPDX-License-Identifier: BSD-3-Clause
// Copyright (C) the ctid authors
// Off-line (batch) estimators of continuous-time LTI models:
//
//   LSSVF    least squares on the SVF regression, thesis eq. (1.32);
//   IVSVF    LSSVF, then IV with instruments from the auxiliary model of the
//            LSSVF estimate, filtered by the same SVF, eqs. (2.4)-(2.7);
//   SRIVC    iterated IV with the adaptive prefilter 1/A(p, theta^(i-1)) and
//            the auxiliary model of theta^(i-1), eqs. (2.8)-(2.13);
//   CLSRIVC  SRIVC with the closed-loop auxiliary model (x_hat, u_hat of the
//            estimated plant in a loop with the known controller),
//            eqs. (2.47)-(2.50), started by CLIVSVF, eqs. (2.44)-(2.46).
//
// IV solution: with Z the filtered instruments, Phi the filtered regressors
// and Y the target, Z P = Q R (column-pivoting QR, thin Q) turns
// Z^T Phi theta = Z^T Y into the square system (Q^T Phi) theta = Q^T Y
// (R^T cancels), solved with a rank-revealing QR; the normal equations are
// never formed. LSSVF is the case Z = Phi.
//
// Filters: y and x_hat by the trapezoidal rule (svf.y_intersample), u and
// u_hat by the data's rule (svf.u_intersample), as in SvfRegressor. The
// SRIVC prefilter has unit static gain, a_na / A(p): the IV solution does
// not depend on a common gain, and the unit gain keeps the filtered signals
// at the scale of the normalised SVF (eq. 3.1; shared/implementation-notes.md
// item 2). The covariance is reported for the monic prefilter 1/A(p) of the
// thesis, for which the filtered equation error is the white noise e itself.
//
// The refined methods (SRIVC, CLSRIVC) are run by the engine of
// refined_iv.hpp, which uses the pieces of this header (the QR solution,
// the closed-loop auxiliary model); srivc() and clsrivc() live there.
#pragma once

#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "ctid/base/delay_line.hpp"
#include "ctid/base/record.hpp"
#include "ctid/base/stability.hpp"
#include "ctid/filters/svf.hpp"
#include "ctid/filters/svf_regressor.hpp"
#include "ctid/offline/least_squares.hpp"
#include "ctid/simulation/controller.hpp"
#include "ctid/simulation/ltv_simulator.hpp"

namespace ctid {

template <typename S>
struct OfflineEstimate {
  Vector<S> theta;       // [a1..a_na, b...] as in model.hpp
  Matrix<S> covariance;  // np x np estimated parameter covariance
  // Variance of the simulation residual y - x_hat(theta), x_hat simulated
  // from the measured input u (also in closed loop, where u already carries
  // the feedback, so that the residual is e itself); +inf when A(theta) is
  // unstable.
  S noise_variance = 0;
  int iterations = 0;     // SRIVC iterations done (1 for lssvf/ivsvf)
  bool converged = true;  // false: SRIVC stopped at max_iterations
};

template <typename S>
struct SrivcSettings {
  S tolerance = S(1e-6);  // on ||theta_i - theta_(i-1)|| / ||theta_i||
  int max_iterations = 20;
  // Initial estimate; it must have a stable A. Empty: IVSVF (CLIVSVF in
  // closed loop) with the SVF of init_svf.
  Vector<S> theta_init;
};

namespace offline_iv_detail {

// The loop of the closed-loop methods, u = r1 + C(q^-1)(r2 - y); a null
// controller means open loop.
template <typename S>
struct Loop {
  const S* r1 = nullptr;
  const S* r2 = nullptr;
  const DiscreteTransferFunction<S>* controller = nullptr;
  bool closed() const { return controller != nullptr; }
};

template <typename S>
Status validate_problem(const ModelOrders& orders, const SvfSettings<S>& svf,
                        const RecordView<S>& record, const Loop<S>& loop,
                        const OfflineEstimate<S>* estimate) {
  if (estimate == nullptr) return bad_input("the estimate output is null");
  Status status = validate_orders(orders);
  if (!status.ok()) return status;
  status = validate_svf_settings(svf);
  if (!status.ok()) return status;
  if (record.y == nullptr || record.u == nullptr) {
    return bad_input("the record needs y and u");
  }
  status = validate_record(record, orders);
  if (!status.ok()) return status;
  if (!loop.closed()) return Status::Ok();
  if (orders.num_inputs() != 1) {
    return bad_input("closed-loop estimation needs a single input");
  }
  if (svf.u_intersample != InterSample::kZoh) {
    return bad_input(
        "closed-loop estimation needs ZOH data (the controller output is held "
        "between samples)");
  }
  status = validate_controller(*loop.controller);
  if (!status.ok()) return bad_input("controller: " + status.message());
  if (loop.r1 == nullptr || loop.r2 == nullptr) {
    return bad_input("closed-loop estimation needs r1 and r2");
  }
  for (Eigen::Index k = 0; k < record.num_samples; ++k) {
    if (!std::isfinite(loop.r1[k]) || !std::isfinite(loop.r2[k])) {
      return bad_input("r1 and r2 must be finite (sample " +
                       std::to_string(k + 1) + " is not)");
    }
  }
  return Status::Ok();
}

template <typename S>
Status validate_srivc_settings(const ModelOrders& orders,
                               const SrivcSettings<S>& settings) {
  if (!(settings.tolerance > 0) || !std::isfinite(settings.tolerance)) {
    return bad_input("the tolerance must be finite and > 0");
  }
  if (settings.max_iterations < 1) {
    return bad_input("the maximum number of iterations must be >= 1, got " +
                     std::to_string(settings.max_iterations));
  }
  const Vector<S>& theta = settings.theta_init;
  if (theta.size() == 0) return Status::Ok();
  if (theta.size() != orders.num_parameters()) {
    return dimension_mismatch("the initial estimate must have " +
                              std::to_string(orders.num_parameters()) +
                              " parameters, got " +
                              std::to_string(theta.size()));
  }
  if (!theta.allFinite()) {
    return bad_input("the initial estimate must be finite");
  }
  HurwitzTest<S> hurwitz(orders.na);
  if (!hurwitz.is_stable(theta.head(orders.na))) {
    return bad_input(
        "the initial estimate must have a stable (Hurwitz) denominator A(p)");
  }
  return Status::Ok();
}

// The regression (1.24) filtered by gain / D(p) for any fixed D: the
// SvfRegressor layout (eq. 1.27) with the adaptive prefilter (2.9)-(2.10)
// in place of the SVF. Rows: phi_f^T(t_k); target: y_f^(na)(t_k).
template <typename S>
void build_prefiltered_regression(const ModelOrders& orders, const Vector<S>& d,
                                  S gain, InterSample y_rule,
                                  InterSample u_rule,
                                  const RecordView<S>& record, Matrix<S>& Phi,
                                  Vector<S>& target) {
  const int na = orders.na;
  const int nu = orders.num_inputs();
  const Eigen::Index n = record.num_samples;
  FilterDiscretization<S> y_disc, u_disc;
  y_disc.configure(na, y_rule);
  y_disc.set_denominator(d);
  u_disc.configure(na, u_rule);
  u_disc.set_denominator(d);
  FilterChannel<S> y_channel;
  y_channel.configure(na);
  std::vector<FilterChannel<S>> u_channels(nu);
  std::vector<DelayLine<S>> delays(nu);
  for (int j = 0; j < nu; ++j) {
    u_channels[j].configure(na);
    delays[j].configure(orders.nk[j]);
  }
  Phi.resize(n, orders.num_parameters());
  target.resize(n);
  for (Eigen::Index k = 0; k < n; ++k) {
    const S h = record.interval(k);
    y_disc.ensure(h);
    u_disc.ensure(h);
    y_channel.step(y_disc, gain, record.y[k]);
    const Vector<S>& yf = y_channel.outputs();
    for (int i = 0; i < na; ++i) Phi(k, i) = -yf(na - 1 - i);
    target(k) = yf(na);
    int offset = na;
    for (int j = 0; j < nu; ++j) {
      u_channels[j].step(u_disc, gain, delays[j].push(record.u_at(k, j)));
      const Vector<S>& uf = u_channels[j].outputs();
      const int nb = orders.nb[j];
      for (int l = 0; l < nb; ++l) Phi(k, offset + l) = uf(nb - 1 - l);
      offset += nb;
    }
  }
}

template <typename S>
struct IvSolution {
  Vector<S> theta;
  Matrix<S> inverse_gram;  // (Z^T Z)^-1
  // (Z^T Phi)^-1 (Z^T Z) (Phi^T Z)^-1 = M^-1 M^-T, M = Q^T Phi: the IV
  // covariance for unit-variance white equation error ((Phi^T Phi)^-1 for
  // LS).
  Matrix<S> sandwich;
  S equation_error_variance = 0;  // ||Y - Phi theta||^2 / (N - np)
};

// theta solving Z^T Phi theta = Z^T Y through Z P = Q R, see the header
// comment. `instruments` names Z in the rank-deficiency message.
template <typename S>
Status solve_iv(const Matrix<S>& Z, const Matrix<S>& Phi,
                const Vector<S>& target, const char* instruments,
                IvSolution<S>& solution) {
  const Eigen::Index np = Phi.cols();
  const Eigen::ColPivHouseholderQR<Matrix<S>> z_qr(Z);
  if (z_qr.rank() < np) {
    return numerical_failure(
        std::string("the ") + instruments + " matrix is rank deficient (rank " +
        std::to_string(z_qr.rank()) + " < " + std::to_string(np) +
        "): the input is not persistently exciting for this model order");
  }
  Matrix<S> qt_phi = Phi;
  qt_phi.applyOnTheLeft(z_qr.householderQ().adjoint());
  Vector<S> qt_target = target;
  qt_target.applyOnTheLeft(z_qr.householderQ().adjoint());
  const Matrix<S> m = qt_phi.topRows(np);
  const Eigen::ColPivHouseholderQR<Matrix<S>> m_qr(m);
  if (m_qr.rank() < np) {
    return numerical_failure(
        "the instrument-regressor matrix Q^T Phi_f is rank deficient (rank " +
        std::to_string(m_qr.rank()) + " < " + std::to_string(np) +
        "): the input is not persistently exciting for this model order");
  }
  solution.theta = m_qr.solve(qt_target.head(np));
  if (!solution.theta.allFinite()) {
    return numerical_failure(
        "the IV solution is not finite; check the scaling of the data and "
        "lambda_svf");
  }
  const Matrix<S> identity = Matrix<S>::Identity(np, np);
  const Matrix<S> r_inverse = z_qr.matrixR()
                                  .topLeftCorner(np, np)
                                  .template triangularView<Eigen::Upper>()
                                  .solve(identity);
  const auto& perm = z_qr.colsPermutation();
  solution.inverse_gram =
      perm * (r_inverse * r_inverse.transpose()) * perm.transpose();
  const Matrix<S> m_inverse = m_qr.solve(identity);
  solution.sandwich = m_inverse * m_inverse.transpose();
  const Eigen::Index dof = Phi.rows() > np ? Phi.rows() - np : Phi.rows();
  solution.equation_error_variance =
      (target - Phi * solution.theta).squaredNorm() / static_cast<S>(dof);
  return Status::Ok();
}

// theta with A(p) made Hurwitz (roots reflected) when it is not: the model
// that drives the prefilter and the auxiliary model.
template <typename S>
Status stabilised(const ModelOrders& orders, const Vector<S>& theta,
                  Vector<S>& out) {
  const int na = orders.na;
  HurwitzTest<S> hurwitz(na);
  out = theta;
  if (hurwitz.is_stable(theta.head(na))) return Status::Ok();
  out.head(na) = reflect_unstable_roots<S>(theta.head(na));
  if (!hurwitz.is_stable(out.head(na))) {
    return numerical_failure(
        "the estimate has an unstable A(p) whose roots could not be reflected "
        "into a stable one");
  }
  return Status::Ok();
}

// The auxiliary model with constant theta (A(theta) stable): x_hat =
// B/A u in open loop (2.6), (2.12); in closed loop x_hat and u_hat of
// (2.45), (2.49), driven by r1 and r2.
template <typename S>
Status simulate_auxiliary(const ModelOrders& orders, InterSample u_rule,
                          const Vector<S>& theta, const RecordView<S>& record,
                          const Loop<S>& loop, Vector<S>& xhat,
                          Vector<S>& uhat) {
  LtvSimulationConfig<S> config;
  config.orders = orders;
  config.u_intersample = u_rule;
  if (loop.closed()) {
    config.closed_loop = true;
    config.controller = *loop.controller;
  }
  LtvSimulator<S> simulator;
  Status status = simulator.configure(config);
  if (!status.ok()) return status;
  RecordView<S> drive = record;
  if (loop.closed()) drive.u = loop.r1;
  xhat.resize(record.num_samples);
  SimulationOutputs<S> out;
  out.x = xhat.data();
  if (loop.closed()) {
    uhat.resize(record.num_samples);
    out.u_applied = uhat.data();
  }
  const ParameterTrajectory<S> constant = [&theta](S, Vector<S>& value) {
    value = theta;
  };
  return simulator.simulate(constant, drive, loop.r2, nullptr, out);
}

// ||y - x_hat(theta)||^2 / (N - np), x_hat = B/A u from the measured u.
template <typename S>
Status simulation_noise_variance(const ModelOrders& orders, InterSample u_rule,
                                 const Vector<S>& theta,
                                 const RecordView<S>& record, S& variance) {
  HurwitzTest<S> hurwitz(orders.na);
  if (!hurwitz.is_stable(theta.head(orders.na))) {
    variance = std::numeric_limits<S>::infinity();
    return Status::Ok();
  }
  Vector<S> xhat, unused;
  const Status status = simulate_auxiliary(orders, u_rule, theta, record,
                                           Loop<S>(), xhat, unused);
  if (!status.ok()) return status;
  const Eigen::Index n = record.num_samples;
  const Eigen::Index np = orders.num_parameters();
  const Eigen::Index dof = n > np ? n - np : n;
  S sum = 0;
  for (Eigen::Index k = 0; k < n; ++k) {
    const S r = record.y[k] - xhat(k);
    sum += r * r;
  }
  variance = sum / static_cast<S>(dof);
  return Status::Ok();
}

// The record of the auxiliary model: x_hat as the output, u (open loop) or
// u_hat (closed loop) as the input, on the data's time base.
template <typename S>
RecordView<S> auxiliary_record(const RecordView<S>& record, const Loop<S>& loop,
                               const Vector<S>& xhat, const Vector<S>& uhat) {
  RecordView<S> aux = record;
  aux.y = xhat.data();
  if (loop.closed()) aux.u = uhat.data();
  return aux;
}

// The estimate of a one-step method (LSSVF, IVSVF): theta, its covariance
// from the IV solution, and the variance of the simulation residual.
template <typename S>
Status fill_single_step_estimate(const ModelOrders& orders, InterSample u_rule,
                                 const RecordView<S>& record,
                                 const IvSolution<S>& solution,
                                 OfflineEstimate<S>* estimate) {
  S noise_variance = 0;
  const Status status = simulation_noise_variance(
      orders, u_rule, solution.theta, record, noise_variance);
  if (!status.ok()) return status;
  estimate->theta = solution.theta;
  estimate->covariance = solution.equation_error_variance * solution.sandwich;
  estimate->noise_variance = noise_variance;
  estimate->iterations = 1;
  estimate->converged = true;
  return Status::Ok();
}

}  // namespace offline_iv_detail

// LSSVF, eq. (1.32). Covariance sigma^2 (Phi^T Phi)^-1 with sigma^2 the
// residual variance of the filtered regression (nominal: LSSVF is biased on
// noisy data).
template <typename S>
Status lssvf(const ModelOrders& orders, const SvfSettings<S>& svf,
             const RecordView<S>& record, OfflineEstimate<S>* estimate) {
  using namespace offline_iv_detail;
  Status status = validate_problem(orders, svf, record, Loop<S>(), estimate);
  if (!status.ok()) return status;
  Matrix<S> Phi;
  Vector<S> target;
  status = build_svf_regression(orders, svf, record, Phi, target);
  if (!status.ok()) return status;
  IvSolution<S> solution;
  status = solve_iv(Phi, Phi, target, "regressor", solution);
  if (!status.ok()) return status;
  return offline_iv_detail::fill_single_step_estimate(
      orders, svf.u_intersample, record, solution, estimate);
}

namespace offline_iv_detail {

// IVSVF (open loop) or CLIVSVF (closed loop): the instruments come from the
// auxiliary model of the LSSVF estimate and the SVF of `svf`. Covariance:
// the IV formula for white equation error (nominal: the SVF-filtered
// equation error F(p) A(p) e is coloured).
template <typename S>
Status svf_iv(const ModelOrders& orders, const SvfSettings<S>& svf,
              const RecordView<S>& record, const Loop<S>& loop,
              OfflineEstimate<S>* estimate) {
  Status status = validate_problem(orders, svf, record, loop, estimate);
  if (!status.ok()) return status;
  // First step, LSSVF on the same regression (built once for both steps).
  Matrix<S> Phi, Z;
  Vector<S> target, unused;
  status = build_svf_regression(orders, svf, record, Phi, target);
  if (!status.ok()) return status;
  IvSolution<S> ls;
  status = solve_iv(Phi, Phi, target, "regressor", ls);
  if (!status.ok()) return status;
  Vector<S> drive;
  status = stabilised(orders, ls.theta, drive);
  if (!status.ok()) return status;
  Vector<S> xhat, uhat;
  status = simulate_auxiliary(orders, svf.u_intersample, drive, record, loop,
                              xhat, uhat);
  if (!status.ok()) return status;
  status = build_svf_regression(
      orders, svf, auxiliary_record(record, loop, xhat, uhat), Z, unused);
  if (!status.ok()) return status;
  IvSolution<S> solution;
  status = solve_iv(Z, Phi, target, "instrument", solution);
  if (!status.ok()) return status;
  return fill_single_step_estimate(orders, svf.u_intersample, record, solution,
                                   estimate);
}

}  // namespace offline_iv_detail

// IVSVF, eqs. (2.4)-(2.7).
template <typename S>
Status ivsvf(const ModelOrders& orders, const SvfSettings<S>& svf,
             const RecordView<S>& record, OfflineEstimate<S>* estimate) {
  return offline_iv_detail::svf_iv(orders, svf, record,
                                   offline_iv_detail::Loop<S>(), estimate);
}

}  // namespace ctid
