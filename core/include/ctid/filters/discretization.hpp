// SPDX-License-Identifier: BSD-3-Clause
// Copyright (C) the ctid authors
// Digital implementation of continuous-time filtering operations
// x' = F x + G s (thesis Appendix A), for the per-sample filters (svf.hpp)
// and the batch filters (batch_filters.hpp) alike. Every rule is written as
//
//   z(t_k) = Phi z(t_(k-1)) + Gamma0 s(t_(k-1)) + Gamma1 (s(t_k) - s(t_(k-1)))
//
// and named by Discretisation; the data's InterSample property maps to it
// once, in discretisation_of():
//
//   kExactZoh (App. A.1, eq. A.6): s held constant between samples,
//       [Phi Gamma0; 0 I] = expm([F G; 0 0] h), Gamma1 = 0.
//   kExactFoh: s linear between samples, exact: with the slope
//       (s_k - s_(k-1))/h as a further state,
//       expm([F G 0; 0 0 I/h; 0 0 0] h) = [Phi Gamma0 Gamma1; 0 I I; 0 0 I]
//       (the augmented matrix of App. A.1 for the input and its slope).
//   kTrapezoid (App. A.2): the bilinear (Tustin) map. The thesis writes it
//       in balanced coordinates (eq. A.7); here it is kept in the physical
//       state coordinates,
//           z(t_k) = Ad z(t_(k-1)) + Bd (s(t_(k-1)) + s(t_k)),
//           Ad = (I - h/2 F)^-1 (I + h/2 F),  Bd = (I - h/2 F)^-1 G h/2,
//       (Phi = Ad, Gamma0 = 2 Bd, Gamma1 = Bd in the form above), which has
//       the same input-output map and lets a time-varying filter carry its
//       state across a change of F (the tests check it against eq. A.7).
//       The thesis filters signals that are not piecewise constant this
//       way (Sec. 3.1.3, Suggested procedure 3.3); its frequency warping,
//       tan(w h/2)/(w h/2), shifts a lightly damped mode near Nyquist/3 by
//       percents, which the exact hold does not.
#pragma once

#include <unsupported/Eigen/MatrixFunctions>

#include "ctid/base/balanced_exponential.hpp"
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

// The filter rule of each intersample behaviour (the one mapping).
enum class Discretisation { kExactZoh, kExactFoh, kTrapezoid };

inline Discretisation discretisation_of(InterSample rule) {
  switch (rule) {
    case InterSample::kZoh:
      return Discretisation::kExactZoh;
    case InterSample::kFoh:
      return Discretisation::kExactFoh;
    case InterSample::kTrapezoid:
      return Discretisation::kTrapezoid;
  }
  return Discretisation::kExactZoh;
}

namespace detail {
// [F G 0; 0 0 I/h; 0 0 0] h and the blocks Phi, Gamma0, Gamma1 of its
// exponential e.
template <typename M, typename S>
M foh_augmented(const Matrix<S>& F, const Matrix<S>& G, S h) {
  const Eigen::Index n = F.rows();
  const Eigen::Index m = G.cols();
  M augmented = M::Zero(n + 2 * m, n + 2 * m);
  augmented.topLeftCorner(n, n) = F * h;
  augmented.block(0, n, n, m) = G * h;
  augmented.block(n, n + m, m, m).setIdentity();  // (I/h) h
  return augmented;
}
template <typename M, typename S>
void foh_blocks(const M& e, Eigen::Index n, Eigen::Index m, Matrix<S>& Phi,
                Matrix<S>& Gamma0, Matrix<S>& Gamma1) {
  Phi = e.topLeftCorner(n, n);
  Gamma0 = e.block(0, n, n, m);
  Gamma1 = e.block(0, n + m, n, m);
}
template <typename M, typename S>
void foh_exponential(const Matrix<S>& F, const Matrix<S>& G, S h,
                     Matrix<S>& Phi, Matrix<S>& Gamma0, Matrix<S>& Gamma1) {
  const M e = foh_augmented<M, S>(F, G, h).exp();
  foh_blocks<M, S>(e, F.rows(), G.cols(), Phi, Gamma0, Gamma1);
}
}  // namespace detail

// The exact first-order hold: Phi, Gamma0, Gamma1 of the form above.
template <typename S>
void foh_discretize(const Matrix<S>& F, const Matrix<S>& G, S h, Matrix<S>& Phi,
                    Matrix<S>& Gamma0, Matrix<S>& Gamma1) {
  constexpr int kMaxSmall = 12;
  if (F.rows() + 2 * G.cols() <= kMaxSmall) {
    using Small = Eigen::Matrix<S, Eigen::Dynamic, Eigen::Dynamic, 0, kMaxSmall,
                                kMaxSmall>;
    detail::foh_exponential<Small, S>(F, G, h, Phi, Gamma0, Gamma1);
  } else {
    detail::foh_exponential<Matrix<S>, S>(F, G, h, Phi, Gamma0, Gamma1);
  }
}

// The same exact first-order hold through the balanced exponential
// (balanced_exponential.hpp), for a state matrix F of arbitrary scaling (a
// user's state-space model rather than a filter of bounded order), as
// MATLAB's and Octave's expm compute it.
template <typename S>
void foh_discretize_balanced(const Matrix<S>& F, const Matrix<S>& G, S h,
                             Matrix<S>& Phi, Matrix<S>& Gamma0,
                             Matrix<S>& Gamma1) {
  const Matrix<S> e =
      balanced_exp<S>(detail::foh_augmented<Matrix<S>, S>(F, G, h));
  detail::foh_blocks<Matrix<S>, S>(e, F.rows(), G.cols(), Phi, Gamma0, Gamma1);
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

// Any rule in the common form z_k = Phi z_(k-1) + Gamma0 s_(k-1) +
// Gamma1 (s_k - s_(k-1)).
template <typename S>
void discretize(Discretisation rule, const Matrix<S>& F, const Matrix<S>& G,
                S h, Matrix<S>& Phi, Matrix<S>& Gamma0, Matrix<S>& Gamma1) {
  switch (rule) {
    case Discretisation::kExactZoh:
      // Phi and Gamma0 of the exact FOH are those of the exact ZOH (eq.
      // A.6 with the slope's block added): one exponential gives both, so
      // that ZOH and FOH channels filtered through discretize() share them
      // to the last bit.
      foh_discretize<S>(F, G, h, Phi, Gamma0, Gamma1);
      Gamma1.setZero(F.rows(), G.cols());
      return;
    case Discretisation::kExactFoh:
      foh_discretize<S>(F, G, h, Phi, Gamma0, Gamma1);
      return;
    case Discretisation::kTrapezoid:
      trapezoidal_discretize<S>(F, G, h, Phi, Gamma1);
      Gamma0 = 2 * Gamma1;
      return;
  }
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
