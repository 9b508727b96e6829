// SPDX-License-Identifier: BSD-3-Clause
// Copyright (C) the ctid authors
// Stability test of the estimates that feed the auxiliary model and the
// adaptive prefilter, thesis eqs. (3.9)-(3.10): A(p) must have all roots in
// the open left half plane. The test is the Routh array (no eigenvalues,
// no allocation once the workspace exists); the "reflect" policy mirrors
// unstable roots into the left half plane. Its discrete-time counterpart,
// reflect_roots_into_unit_disc, mirrors roots into the unit disc.
#pragma once

#include <Eigen/Eigenvalues>
#include <complex>

#include "ctid/base/polynomial.hpp"
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

namespace stability_detail {

// x^n + a1 x^(n-1) + .. + an (a = [a1 .. an]) in ascending powers.
template <typename S>
Vector<S> monic_ascending(const Vector<S>& a) {
  const Eigen::Index n = a.size();
  Vector<S> c(n + 1);
  c(n) = 1;
  for (Eigen::Index i = 0; i < n; ++i) c(n - 1 - i) = a(i);
  return c;
}

// [a1 .. an] of a monic polynomial in descending powers, real parts.
template <typename S>
Vector<S> monic_tail(
    const Eigen::Matrix<std::complex<S>, Eigen::Dynamic, 1>& c) {
  return c.tail(c.size() - 1).real();
}

}  // namespace stability_detail

// Reflects the roots of p^n + a1 p^(n-1) + .. with positive (or zero) real
// part into the left half plane and returns the new coefficients. Roots on
// the imaginary axis are moved to -eps*scale so the result is Hurwitz.
template <typename S>
Vector<S> reflect_unstable_roots(const Vector<S>& a) {
  const Eigen::Index n = a.size();
  using C = std::complex<S>;
  Eigen::Matrix<C, Eigen::Dynamic, 1> roots =
      polynomial_roots<S>(stability_detail::monic_ascending(a));
  const S scale = std::max(S(1), a.cwiseAbs().maxCoeff());
  for (Eigen::Index k = 0; k < n; ++k) {
    C& root = roots(k);
    if (root.real() >= 0) {
      root = C(-std::max(root.real(),
                         std::sqrt(std::numeric_limits<S>::epsilon()) * scale),
               root.imag());
    }
  }
  return stability_detail::monic_tail(monic_from_roots<S>(roots));
}

// Reflects into the unit disc the roots of z^n + a1 z^(n-1) + .. + an
// (a = [a1 .. an]: the polynomial 1 + a1 q^-1 + .. + an q^-n of a
// discrete-time filter) and returns the new coefficients. A root z with
// |z| > 1 becomes 1/conj(z) (the magnitude response keeps its shape, up
// to a constant factor); a root then at |z| >= limit is moved along its ray
// to |z| = pull_to (pull_to < limit <= 1 keeps it off the unit circle).
// The coefficients are rebuilt from the roots, also when none moved;
// *moved (when given) tells whether one did.
template <typename S>
Vector<S> reflect_roots_into_unit_disc(const Vector<S>& a, S limit, S pull_to,
                                       bool* moved = nullptr) {
  if (moved != nullptr) *moved = false;
  const Eigen::Index n = a.size();
  if (n == 0) return a;
  Eigen::Matrix<std::complex<S>, Eigen::Dynamic, 1> roots =
      polynomial_roots<S>(stability_detail::monic_ascending(a));
  for (Eigen::Index k = 0; k < n; ++k) {
    std::complex<S>& root = roots(k);
    const S r = std::abs(root);
    if (r > 1) root /= r * r;  // 1 / conj(root)
    if (std::abs(root) >= limit) root *= pull_to / std::abs(root);
    if (moved != nullptr && (r > 1 || r >= limit)) *moved = true;
  }
  return stability_detail::monic_tail(monic_from_roots<S>(roots));
}

}  // namespace ctid
