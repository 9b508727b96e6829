// SPDX-License-Identifier: BSD-3-Clause
// Copyright (C) the ctid authors
// Digital implementation of continuous-time filtering operations
// x' = F x + G s (thesis Appendix A).
//
//   ZOH (App. A.1, eq. A.6): [Phi Gamma; 0 I] = expm([F G; 0 0] h), exact
//   when s is held constant between samples:
//       z(t_k) = Phi z(t_(k-1)) + Gamma s(t_(k-1)).
//   Trapezoidal rule (App. A.2): the bilinear (Tustin) map. The thesis writes
//   it in balanced coordinates (eq. A.7); here it is kept in the physical
//   state coordinates,
//       z(t_k) = Ad z(t_(k-1)) + Bd (s(t_(k-1)) + s(t_k)),
//       Ad = (I - h/2 F)^-1 (I + h/2 F),  Bd = (I - h/2 F)^-1 G h/2,
//   which has the same input-output map and lets a time-varying filter carry
//   its state across a change of F (the tests check it against eq. A.7).
#pragma once

#include <unsupported/Eigen/MatrixFunctions>

#include "ctid/base/types.hpp"

namespace ctid {

namespace detail {
template <typename M, typename S>
void zoh_exponential(const Matrix<S>& F, const Matrix<S>& G, S h,
                     Matrix<S>& Phi, Matrix<S>& Gamma) {
  const Eigen::Index n = F.rows();
  const Eigen::Index m = G.cols();
  M augmented = M::Zero(n + m, n + m);
  augmented.topLeftCorner(n, n) = F * h;
  augmented.topRightCorner(n, m) = G * h;
  const M e = augmented.exp();
  Phi = e.topLeftCorner(n, n);
  Gamma = e.topRightCorner(n, m);
}
}  // namespace detail

// Small systems (the usual case: a filter of order <= 11) use matrices of
// bounded size on the stack, so a rediscretisation allocates only when
// Phi/Gamma change size.
template <typename S>
void zoh_discretize(const Matrix<S>& F, const Matrix<S>& G, S h, Matrix<S>& Phi,
                    Matrix<S>& Gamma) {
  constexpr int kMaxSmall = 12;
  if (F.rows() + G.cols() <= kMaxSmall) {
    using Small = Eigen::Matrix<S, Eigen::Dynamic, Eigen::Dynamic, 0, kMaxSmall,
                                kMaxSmall>;
    detail::zoh_exponential<Small, S>(F, G, h, Phi, Gamma);
  } else {
    detail::zoh_exponential<Matrix<S>, S>(F, G, h, Phi, Gamma);
  }
}

template <typename S>
void trapezoidal_discretize(const Matrix<S>& F, const Matrix<S>& G, S h,
                            Matrix<S>& Ad, Matrix<S>& Bd) {
  const Eigen::Index n = F.rows();
  const Matrix<S> identity = Matrix<S>::Identity(n, n);
  const Eigen::PartialPivLU<Matrix<S>> lu(identity - (h / 2) * F);
  Ad = lu.solve(identity + (h / 2) * F);
  Bd = lu.solve(G * (h / 2));
}

// Companion (controllable canonical) matrix of the monic polynomial
// D(p) = p^n + d1 p^(n-1) + ... + dn, with state z = [w, w', .., w^(n-1)]
// for D(p) w = s.
template <typename S>
Matrix<S> companion_matrix(const Vector<S>& d) {
  const Eigen::Index n = d.size();
  Matrix<S> F = Matrix<S>::Zero(n, n);
  for (Eigen::Index i = 0; i + 1 < n; ++i) F(i, i + 1) = 1;
  for (Eigen::Index j = 0; j < n; ++j) F(n - 1, j) = -d(n - 1 - j);
  return F;
}

}  // namespace ctid
