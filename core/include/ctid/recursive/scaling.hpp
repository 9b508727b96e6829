// SPDX-License-Identifier: BSD-3-Clause
// Copyright (C) the ctid authors
// Signal scaling of the recursive estimators, thesis sec. 3.5.2-3.5.5.
//
// The estimators propagate theta_s = M_s^-1 theta and P_s = M_s^-1 P M_s^-1
// (eq. 3.65) with a diagonal M_s = diag(m_1 .. m_np). Since
// phi^T theta = (M_s phi)^T theta_s, the scaled recursions (3.66) (RLSSVF),
// (3.74) (RSRIVC) and (C.9) (PotterSVF) are the plain recursions run on the
// scaled regressor phi_s = M_s phi, instruments zeta_s = M_s zeta, with
// theta_s(t_0) = M_s^-1 theta(t_0), P_s(t_0) = M_s^-1 P(t_0) M_s^-1 and
// Q_n,s = M_s^-1 Q_n M_s^-1: in exact arithmetic the estimates are those of
// the unscaled recursion; only the conditioning of P_s changes. M_s comes
// from training data, m_i = 1 / ||Phi_i|| (eq. 3.54), the columns of the
// regressor matrix of the filtered regression (3.55).
#pragma once

#include <cmath>
#include <string>

#include "ctid/adaptation/adaptation.hpp"
#include "ctid/offline/least_squares.hpp"

namespace ctid {

// m: the diagonal of M_s, np finite entries > 0 (empty: no scaling).
template <typename S>
Status validate_scaling(const Vector<S>& m, Eigen::Index np) {
  if (m.size() == 0) return Status::Ok();
  if (m.size() != np) {
    return dimension_mismatch("the scaling M_s must have " +
                              std::to_string(np) +
                              " diagonal entries (one per parameter), got " +
                              std::to_string(m.size()));
  }
  for (Eigen::Index i = 0; i < np; ++i) {
    if (!std::isfinite(m(i)) || !(m(i) > 0)) {
      return bad_input(
          "the scaling M_s must have finite diagonal entries > 0 (entry " +
          std::to_string(i + 1) + " is " +
          std::to_string(static_cast<double>(m(i))) + ")");
    }
  }
  return Status::Ok();
}

// m_i = 1 / ||Phi_i|| (eq. 3.54). Fails when a column is zero (a regressor
// never excited in the training data) or not finite.
template <typename S>
Status scaling_from_regressors(const Matrix<S>& Phi, Vector<S>& m) {
  m.resize(Phi.cols());
  for (Eigen::Index i = 0; i < Phi.cols(); ++i) {
    const S norm = Phi.col(i).norm();
    if (!std::isfinite(norm) || !(norm > 0)) {
      return bad_input("regressor " + std::to_string(i + 1) +
                       " is zero (or not finite) over the training data: "
                       "no scaling M_s can be formed from it");
    }
    m(i) = S(1) / norm;
  }
  return Status::Ok();
}

// M_s of eq. (3.54) from a training record, with the SVF regression of
// RLSSVF (eqs. 1.24-1.27). The thesis computes it once, offline, and uses
// the same M_s for RLSSVF, RSRIVC and PotterSVF (sec. 4.1.3).
template <typename S>
Status svf_scaling(const ModelOrders& orders, const SvfSettings<S>& svf,
                   const RecordView<S>& training, Vector<S>& m) {
  Matrix<S> Phi;
  Vector<S> target;
  const Status status =
      build_svf_regression(orders, svf, training, Phi, target);
  if (!status.ok()) return status;
  return scaling_from_regressors(Phi, m);
}

// M^-1 A M^-1 for a diagonal M = diag(m).
template <typename S>
Matrix<S> unscale_both_sides(const Matrix<S>& A, const Vector<S>& m) {
  const Vector<S> inverse = m.cwiseInverse();
  return inverse.asDiagonal() * A * inverse.asDiagonal();
}

// The adaptation of the scaled recursion: the forgetting factor is
// unchanged, Qn becomes Q_n,s = M_s^-1 Q_n M_s^-1.
template <typename S>
Adaptation<S> scaled_adaptation(const Adaptation<S>& adaptation,
                                const Vector<S>& m) {
  if (const auto* kf = std::get_if<KalmanAdaptation<S>>(&adaptation)) {
    return KalmanAdaptation<S>(unscale_both_sides<S>(kf->qn(), m));
  }
  return adaptation;
}

}  // namespace ctid
