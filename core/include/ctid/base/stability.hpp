// SPDX-License-Identifier: BSD-3-Clause
// Copyright (C) the ctid authors
// Stability test of the estimates that feed the auxiliary model and the
// adaptive prefilter, thesis eqs. (3.9)-(3.10): A(p) must have all roots in
// the open left half plane. The test is the Routh array (no eigenvalues,
// no allocation once the workspace exists); the "reflect" policy mirrors
// unstable roots into the left half plane.
#pragma once

#include <Eigen/Eigenvalues>
#include <complex>

#include "ctid/base/types.hpp"

namespace ctid {

enum class StabilityPolicy { kKeepLast, kReflect };

// Routh-Hurwitz test of p^n + a1 p^(n-1) + .. + an (a = [a1 .. an]).
template <typename S>
class HurwitzTest {
 public:
  explicit HurwitzTest(int n = 0) { configure(n); }
  void configure(int n) {
    n_ = n;
    table_ = Matrix<S>::Zero(n + 1, n / 2 + 2);
  }

  template <typename Derived>
  bool is_stable(const Eigen::MatrixBase<Derived>& a) {
    const int n = n_;
    if (n == 0) return true;
    for (int i = 0; i < n; ++i) {
      if (!(a(i) > 0)) return false;  // necessary; also rejects NaN
    }
    const int width = static_cast<int>(table_.cols());
    table_.setZero();
    // Row 0: 1, a2, a4, ..; row 1: a1, a3, ..
    for (int j = 0; 2 * j <= n; ++j)
      table_(0, j) = 2 * j == 0 ? S(1) : a(2 * j - 1);
    for (int j = 0; 2 * j + 1 <= n; ++j) table_(1, j) = a(2 * j);
    for (int r = 2; r <= n; ++r) {
      const S pivot = table_(r - 1, 0);
      if (!(pivot > 0)) return false;
      for (int j = 0; j + 1 < width; ++j) {
        table_(r, j) = (pivot * table_(r - 2, j + 1) -
                        table_(r - 2, 0) * table_(r - 1, j + 1)) /
                       pivot;
      }
    }
    return table_(n, 0) > 0;
  }

 private:
  int n_ = 0;
  Matrix<S> table_;
};

// Reflects the roots of p^n + a1 p^(n-1) + .. with positive (or zero) real
// part into the left half plane and returns the new coefficients. Roots on
// the imaginary axis are moved to -eps*scale so the result is Hurwitz.
template <typename S>
Vector<S> reflect_unstable_roots(const Vector<S>& a) {
  const Eigen::Index n = a.size();
  Matrix<S> companion = Matrix<S>::Zero(n, n);
  for (Eigen::Index i = 0; i + 1 < n; ++i) companion(i + 1, i) = 1;
  for (Eigen::Index i = 0; i < n; ++i) companion(0, i) = -a(i);
  const Eigen::EigenSolver<Matrix<S>> eig(companion, false);
  using C = std::complex<S>;
  Eigen::Matrix<C, Eigen::Dynamic, 1> poly(n + 1);  // descending powers
  poly.setZero();
  poly(0) = 1;
  const S scale = std::max(S(1), a.cwiseAbs().maxCoeff());
  for (Eigen::Index k = 0; k < n; ++k) {
    C root = eig.eigenvalues()(k);
    if (root.real() >= 0) {
      root = C(-std::max(root.real(),
                         std::sqrt(std::numeric_limits<S>::epsilon()) * scale),
               root.imag());
    }
    for (Eigen::Index i = k + 1; i > 0; --i) poly(i) -= root * poly(i - 1);
  }
  Vector<S> out(n);
  for (Eigen::Index i = 0; i < n; ++i) out(i) = poly(i + 1).real();
  return out;
}

}  // namespace ctid
