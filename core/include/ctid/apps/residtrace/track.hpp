// SPDX-License-Identifier: BSD-3-Clause
// Copyright (C) the ctid authors
// Tracking of residtrace's dynamic parameters along a record (the
// parameter-drift candidate and the tracked validation figure of
// octave/residtrace.m): the IV Kalman-filter update of thesis eq. (2.29)
// on a regression that the caller has filtered once, at a frozen model
// (octave/private/residtrace_track.m builds it: the SRIVC regression of
// eqs. 2.8-2.13, regressors phi and instruments zeta, target p^n y_f).
//
// The recursion is ParameterUpdate's IV step (adaptation.hpp) with
// KalmanAdaptation(Qn). residtrace adds the random walk after the
// correction (P(t_k) = P - K phi^T P + Qn), the update of eq. (2.29)
// shifted by one sample: started from P(t_0) - Qn, ParameterUpdate's
// predicted P equals residtrace's P at every sample, and residtrace's
// final P is ParameterUpdate's plus Qn.
//
// An update that makes the model's denominator F unstable (apart from
// its r integrators, F = p^r F1: the Routh test of F1, HurwitzTest of
// stability.hpp) is not accepted: the previous estimate is kept, P keeps
// its update (the stability test of thesis eq. 3.10 with "keep").
//
// Row k of theta is the estimate before sample k (one sample behind, so
// that sample k is never explained by itself); before the first tracked
// sample it is theta0. V is the negative log-likelihood of the
// innovations (prediction-error decomposition, the noise variance
// concentrated out; thesis sec. 3.3) over the samples after a start-up of
// max(10, round(count / 50)) updates.
#pragma once

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "ctid/adaptation/adaptation.hpp"
#include "ctid/base/stability.hpp"
#include "ctid/base/status.hpp"
#include "ctid/base/types.hpp"

namespace ctid::residtrace {

template <typename S>
struct TrackConfig {
  Vector<S> f;            // [f1 .. fn] of the model's monic F
  std::vector<int> free;  // indices into f (0-based) of the tracked
                          // coefficients: theta's first free.size() entries
  int integrators = 0;    // r: the last r coefficients of f are fixed at 0
  Matrix<S> Qn;           // random-walk covariance over sigma_e^2
  Vector<S> theta0;
  Matrix<S> P0;
  Eigen::Index first = 0;  // first tracked sample (0-based)
};

template <typename S>
struct TrackResult {
  Matrix<S> theta;  // N-by-np
  S V = 0;
  Matrix<S> P;
};

template <typename S>
Status validate(const TrackConfig<S>& c, Eigen::Index N, Eigen::Index np) {
  const Eigen::Index n = c.f.size();
  if (c.theta0.size() != np) {
    return dimension_mismatch("theta0 must have " + std::to_string(np) +
                              " entries (one per regressor)");
  }
  if (c.P0.rows() != np || c.P0.cols() != np || c.Qn.rows() != np ||
      c.Qn.cols() != np) {
    return dimension_mismatch("P0 and Qn must be " + std::to_string(np) +
                              "-by-" + std::to_string(np));
  }
  if (static_cast<Eigen::Index>(c.free.size()) > np) {
    return dimension_mismatch("more free coefficients than parameters");
  }
  for (const int i : c.free) {
    if (i < 0 || i >= n) {
      return bad_input("a free coefficient index is outside 1.." +
                       std::to_string(n));
    }
  }
  if (c.integrators < 0 || c.integrators > n) {
    return bad_input("the number of integrators must lie in 0.." +
                     std::to_string(n));
  }
  if (c.first < 0 || c.first > N) {
    return bad_input("the first tracked sample must lie in 1.." +
                     std::to_string(N + 1));
  }
  if (N < 1) return bad_input("the record must not be empty");
  return Status::Ok();
}

template <typename S>
Status track(const TrackConfig<S>& c, const Eigen::Ref<const Vector<S>>& target,
             const Eigen::Ref<const Matrix<S>>& Phi,
             const Eigen::Ref<const Matrix<S>>& Z, TrackResult<S>* out) {
  const Eigen::Index N = Phi.rows();
  const Eigen::Index np = Phi.cols();
  if (target.size() != N || Z.rows() != N || Z.cols() != np) {
    return dimension_mismatch(
        "the target, the regressors and the instruments need one row per "
        "sample and the same columns");
  }
  Status status = validate(c, N, np);
  if (!status.ok()) return status;

  ParameterUpdate<S> update(np, KalmanAdaptation<S>(c.Qn));
  update.reset(c.theta0, c.P0 - c.Qn);
  const int n1 = static_cast<int>(c.f.size()) - c.integrators;
  HurwitzTest<S> hurwitz(n1);
  Vector<S> f = c.f;
  Vector<S> theta = c.theta0;
  Vector<S> phi(np), zeta(np);
  std::vector<S> e2(static_cast<std::size_t>(N), S(0));
  std::vector<S> h(static_cast<std::size_t>(N), S(1));
  out->theta.resize(N, np);
  for (Eigen::Index k = 0; k < c.first; ++k) {
    out->theta.row(k) = c.theta0.transpose();
  }
  for (Eigen::Index k = c.first; k < N; ++k) {
    out->theta.row(k) = theta.transpose();
    phi = Phi.row(k).transpose();
    zeta = Z.row(k).transpose();
    const S e = update.update(phi, zeta, target(k));
    for (std::size_t i = 0; i < c.free.size(); ++i) {
      f(c.free[i]) = update.theta()(static_cast<Eigen::Index>(i));
    }
    if (hurwitz.is_stable(f.head(n1))) {
      theta = update.theta();
    } else {
      update.set_theta(theta);
    }
    e2[k] = e * e;
    h[k] = std::abs(update.innovation_scale());
  }
  const Eigen::Index count = N - c.first;
  const Eigen::Index startup = std::max<Eigen::Index>(
      10, static_cast<Eigen::Index>(std::round(static_cast<S>(count) / S(50))));
  const Eigen::Index skip = std::min(N - 1, c.first + startup);
  S ratio = 0;
  S log_h = 0;
  for (Eigen::Index k = skip; k < N; ++k) {
    ratio += e2[k] / h[k];
    log_h += std::log(h[k]);
  }
  const S used = static_cast<S>(N - skip);
  out->V = used * std::log(ratio / used) + log_h;
  out->P = update.P() + c.Qn;
  return Status::Ok();
}

}  // namespace ctid::residtrace
