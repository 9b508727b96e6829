// SPDX-License-Identifier: BSD-3-Clause
// Copyright (C) the ctid authors

// The standard-form updates as the thesis writes them, evaluated with
// Eigen expressions at runtime size: an independent computation for the
// tests of ParameterUpdate (adaptation.hpp), whose steps are loops over a
// compile-time or runtime size. Least squares, eqs. (1.57)/(1.59):
//   P- = P (+ Qn),  L = P- phi / (offset + phi^T P- phi),
//   theta += L (y - phi^T theta),  P = scale (P- - P- phi phi^T P- / den);
// instrumental variables, eqs. (2.29)/(2.30):
//   L = P- zeta / (offset + phi^T P- zeta),  P = scale (P- - L phi^T P-),
// then the covariance guard (covariance_guard.hpp, tested on its own) on P.
#pragma once

#include <variant>

#include "ctid/adaptation/adaptation.hpp"

namespace ctid {
namespace test {

template <typename S>
class TextbookUpdate {
 public:
  TextbookUpdate(Eigen::Index np, const Adaptation<S>& adaptation) {
    if (const auto* kf = std::get_if<KalmanAdaptation<S>>(&adaptation)) {
      qn_ = kf->qn();
    } else {
      const S lambda =
          std::get<ForgettingFactorAdaptation<S>>(adaptation).lambda();
      qn_ = Matrix<S>::Zero(np, np);
      offset_ = lambda;
      scale_ = 1 / lambda;
    }
    guard_.configure(np, true);
  }

  void reset(const Vector<S>& theta0, const Matrix<S>& P0) {
    theta_ = theta0;
    P_ = P0;
    guard_.reset(P_);
  }

  S update(const Vector<S>& phi, S target) { return step(phi, phi, target); }
  S update(const Vector<S>& phi, const Vector<S>& zeta, S target) {
    return step(phi, zeta, target);
  }

  const Vector<S>& theta() const { return theta_; }
  const Matrix<S>& P() const { return P_; }
  const Vector<S>& gain() const { return gain_; }
  S innovation_scale() const { return denominator_; }
  int covariance_guard() const { return guard_.last_action(); }

 private:
  S step(const Vector<S>& phi, const Vector<S>& zeta, S target) {
    const Matrix<S> P_minus = P_ + qn_;
    const S error = target - phi.dot(theta_);
    denominator_ = offset_ + phi.dot(P_minus * zeta);
    gain_ = P_minus * zeta / denominator_;
    theta_ += gain_ * error;
    P_ = scale_ * (P_minus - gain_ * (phi.transpose() * P_minus));
    guard_.apply(P_);
    return error;
  }

  Matrix<S> qn_;
  S offset_ = 1, scale_ = 1;
  Vector<S> theta_, gain_;
  Matrix<S> P_;
  S denominator_ = 1;
  CovarianceGuard<S> guard_;
};

}  // namespace test
}  // namespace ctid
