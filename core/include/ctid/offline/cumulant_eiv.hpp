// SPDX-License-Identifier: BSD-3-Clause
// Copyright (C) the ctid authors

// Errors-in-variables estimation of continuous-time models from third-order
// cumulants (S. Thil, H. Garnier, M. Gilson, "Third-order cumulants based
// methods for continuous-time errors-in-variables model identification",
// Automatica 44(3), 2008):
//
//   TOCLS   least squares on the third-order cross-cumulants of the
//           SVF-filtered regression (1.27) with the input;
//   TOCILS  the same equations with the adaptive prefilter a_na / A(p) of
//           SRIVC (2.9)-(2.10) in place of the SVF, A(p) re-estimated at
//           each iteration, started by TOCLS.
//
// Both the input and the output are measured with noise, u = u0 + u~ and
// y = y0 + y~, where the noises are independent of u0 and have symmetric
// distributions (their third-order cumulants vanish), while u0 is skewed.
// The filtered regression y_f^(na) = phi_f^T theta + v holds for the
// noise-free parts, and every term that carries a noise has a zero
// third-order cross-cumulant with the measured input:
//
//   cum(x(t), u(t - tau), u(t - tau)) = E[x(t) (u(t - tau)^2 - E u^2)]
//
// for a zero-mean u. Stacking these cross-cumulants of the target and of
// each regressor for the lags tau = 0 .. M-1 gives M equations
// c_y(tau) = c_phi(tau)^T theta, free of the noises, solved by least
// squares (QR, no normal equations). LS and IV on the same data are biased
// by the input noise, which enters the regressors and, through the
// auxiliary model, the instruments.
//
// The signals' means are removed first (A(0) y = B(0) u holds for the
// means, so the model is unchanged). No covariance is computed: the
// estimate's spread is not given by a simple formula here.
#pragma once

#include <cmath>
#include <string>
#include <vector>

#include "ctid/base/record.hpp"
#include "ctid/base/stability.hpp"
#include "ctid/offline/least_squares.hpp"
#include "ctid/offline/offline_iv.hpp"

namespace ctid {

template <typename S>
struct CumulantEivSettings {
  int lags = 50;            // M, the number of cross-cumulant lags
  int max_iterations = 20;  // TOCILS only
  S tolerance = S(1e-4);  // TOCILS: on ||theta_i - theta_(i-1)|| / ||theta_i||
};

template <typename S>
struct CumulantEivEstimate {
  Vector<S> theta;  // [a1 .. a_na, b0 .. b_nb-1] as in model.hpp
  int iterations = 0;
  bool converged = true;
};

namespace cumulant_eiv_detail {

template <typename S>
Status validate(const ModelOrders& orders, const RecordView<S>& record,
                const CumulantEivSettings<S>& settings,
                const CumulantEivEstimate<S>* estimate) {
  if (estimate == nullptr) return bad_input("the estimate output is null");
  Status status = validate_orders(orders);
  if (!status.ok()) return status;
  if (orders.num_inputs() != 1) {
    return bad_input("the cumulant estimators take a single input");
  }
  if (record.y == nullptr || record.u == nullptr) {
    return bad_input("the record needs y and u");
  }
  if (record.instants != nullptr) {
    return bad_input("the cumulant estimators need regularly sampled data");
  }
  status = validate_record(record, orders);
  if (!status.ok()) return status;
  const int np = orders.num_parameters();
  if (settings.lags < np) {
    return bad_input(
        "the number of lags M must be at least the number of "
        "parameters (" +
        std::to_string(np) + "), got " + std::to_string(settings.lags));
  }
  if (settings.lags > record.num_samples / 2) {
    return bad_input(
        "the number of lags M must be at most half the number "
        "of samples (" +
        std::to_string(record.num_samples / 2) + "), got " +
        std::to_string(settings.lags));
  }
  if (settings.max_iterations < 1) {
    return bad_input("the maximum number of iterations must be >= 1");
  }
  if (!(settings.tolerance > 0) || !std::isfinite(settings.tolerance)) {
    return bad_input("the tolerance must be finite and > 0");
  }
  return Status::Ok();
}

// Mean-removed copies of y and u, and the record that views them.
template <typename S>
struct CentredRecord {
  Vector<S> y, u;
  RecordView<S> view;

  explicit CentredRecord(const RecordView<S>& record) {
    const Eigen::Index n = record.num_samples;
    y = Eigen::Map<const Vector<S>>(record.y, n);
    u = Eigen::Map<const Vector<S>>(record.u, n);
    y.array() -= y.mean();
    u.array() -= u.mean();
    view = record;
    view.y = y.data();
    view.u = u.data();
  }
};

// The method needs a skewed input: its third-order cumulants are what the
// equations are made of. The sample skewness of a symmetric signal has a
// standard error of about sqrt(6 / N) (Gaussian white noise); an input
// whose skewness is within 3 such errors of zero is refused.
template <typename S>
Status check_skewness(const Vector<S>& u_centred) {
  const S n = static_cast<S>(u_centred.size());
  const S variance = u_centred.squaredNorm() / n;
  if (!(variance > 0)) {
    return bad_input("the input is constant: nothing can be estimated");
  }
  const S skewness =
      u_centred.array().cube().sum() / n / std::pow(variance, S(1.5));
  const S bound = 3 * std::sqrt(S(6) / n);
  if (!(std::abs(skewness) > bound)) {
    return bad_input(
        "the input is not skewed (sample skewness " + std::to_string(skewness) +
        ", within 3 standard errors " + std::to_string(bound) +
        " of zero): its third-order cumulants vanish, so the cumulant "
        "equations carry no information; use an input with an asymmetric "
        "distribution");
  }
  return Status::Ok();
}

// Rows tau = 0 .. M-1: the cross-cumulants of each column of Phi (and of
// the target) with u(t - tau)^2, over the samples t = M-1 .. N-1 common to
// every lag, then theta by least squares.
template <typename S>
Status solve_cumulant_equations(const Matrix<S>& Phi, const Vector<S>& target,
                                const Vector<S>& u, int lags,
                                Vector<S>& theta) {
  const Eigen::Index n = Phi.rows();
  const Eigen::Index np = Phi.cols();
  const Eigen::Index first = lags - 1;
  const Eigen::Index count = n - first;
  Matrix<S> C(lags, np);
  Vector<S> c(lags);
  Vector<S> weight(count);
  for (int tau = 0; tau < lags; ++tau) {
    weight = u.segment(first - tau, count).array().square().matrix();
    weight.array() -= weight.mean();
    C.row(tau) =
        (weight.transpose() * Phi.bottomRows(count)) / static_cast<S>(count);
    c(tau) = weight.dot(target.tail(count)) / static_cast<S>(count);
  }
  if (!C.allFinite() || !c.allFinite()) {
    return numerical_failure("the cross-cumulants are not finite");
  }
  const S scale = C.cwiseAbs().maxCoeff();
  if (!(scale > 0)) {
    return bad_input(
        "the cross-cumulants with the input vanish: the input is not skewed "
        "(its third-order cumulants are zero), so the cumulant equations "
        "carry no information");
  }
  return solve_least_squares(C, c, theta);
}

}  // namespace cumulant_eiv_detail

// TOCLS: the cumulant equations of the SVF-filtered regression.
template <typename S>
Status tocls(const ModelOrders& orders, const SvfSettings<S>& svf,
             const RecordView<S>& record,
             const CumulantEivSettings<S>& settings,
             CumulantEivEstimate<S>* estimate) {
  using namespace cumulant_eiv_detail;
  Status status = validate(orders, record, settings, estimate);
  if (!status.ok()) return status;
  const CentredRecord<S> centred(record);
  status = check_skewness(centred.u);
  if (!status.ok()) return status;
  Matrix<S> Phi;
  Vector<S> target;
  status = build_svf_regression(orders, svf, centred.view, Phi, target);
  if (!status.ok()) return status;
  status = solve_cumulant_equations(Phi, target, centred.u, settings.lags,
                                    estimate->theta);
  if (!status.ok()) return status;
  estimate->iterations = 1;
  estimate->converged = true;
  return Status::Ok();
}

// TOCILS: TOCLS, then the cumulant equations of the regression filtered by
// a_na / A(p, theta_(i-1)) until the relative change of theta falls below
// the tolerance. An iterate with an unstable A(p) drives the next
// prefilter with its roots reflected (as SRIVC's start does).
template <typename S>
Status tocils(const ModelOrders& orders, const SvfSettings<S>& svf,
              const RecordView<S>& record,
              const CumulantEivSettings<S>& settings,
              CumulantEivEstimate<S>* estimate) {
  using namespace cumulant_eiv_detail;
  Status status = tocls(orders, svf, record, settings, estimate);
  if (!status.ok()) return status;
  const CentredRecord<S> centred(record);
  const int na = orders.na;
  Matrix<S> Phi;
  Vector<S> target, drive, theta;
  estimate->converged = false;
  for (int i = 0; i < settings.max_iterations; ++i) {
    status = offline_iv_detail::stabilised(orders, estimate->theta, drive);
    if (!status.ok()) return status;
    const Vector<S> d = drive.head(na);  // A(p) = p^na + d1 p^(na-1) + ..
    offline_iv_detail::build_prefiltered_regression(
        orders, d, d(na - 1), svf.y_intersample, svf.u_intersample,
        centred.view, Phi, target);
    status =
        solve_cumulant_equations(Phi, target, centred.u, settings.lags, theta);
    if (!status.ok()) return status;
    const S change = (theta - estimate->theta).norm() / theta.norm();
    estimate->theta = theta;
    estimate->iterations = i + 2;
    if (change < settings.tolerance) {
      estimate->converged = true;
      break;
    }
  }
  return Status::Ok();
}

}  // namespace ctid
