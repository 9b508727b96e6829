// SPDX-License-Identifier: BSD-3-Clause
// Copyright (C) the ctid authors

// Polynomial helpers shared by the core: product, value, derivative and
// roots of real polynomials stored as coefficient vectors.
#pragma once

#include <complex>

#include "ctid/base/types.hpp"

namespace ctid {

// Polynomial product: the coefficients of x * y in the order of x and y
// (ascending or descending powers alike; q^0, q^-1, .. for filters).
template <typename S>
Vector<S> convolve(const Vector<S>& x, const Vector<S>& y) {
  Vector<S> z = Vector<S>::Zero(x.size() + y.size() - 1);
  for (Eigen::Index i = 0; i < x.size(); ++i) {
    for (Eigen::Index j = 0; j < y.size(); ++j) z(i + j) += x(i) * y(j);
  }
  return z;
}

// c_0 + c_1 x + .. + c_n x^n (ascending powers), by Horner's rule.
template <typename S>
S polynomial_value(const Vector<S>& c, S x) {
  S value = 0;
  for (Eigen::Index i = c.size() - 1; i >= 0; --i) value = value * x + c(i);
  return value;
}

// The derivative of c (ascending powers, c.size() >= 1).
template <typename S>
Vector<S> polynomial_derivative(const Vector<S>& c) {
  Vector<S> d(c.size() - 1);
  for (Eigen::Index i = 1; i < c.size(); ++i) d(i - 1) = S(i) * c(i);
  return d;
}

// Roots of c (ascending powers, c_n != 0, n >= 1): the eigenvalues of the
// companion matrix.
template <typename S>
Eigen::Matrix<std::complex<S>, Eigen::Dynamic, 1> polynomial_roots(
    const Vector<S>& c) {
  const Eigen::Index n = c.size() - 1;
  Matrix<S> companion = Matrix<S>::Zero(n, n);
  for (Eigen::Index j = 0; j < n; ++j) companion(0, j) = -c(n - 1 - j) / c(n);
  for (Eigen::Index i = 1; i < n; ++i) companion(i, i - 1) = 1;
  return Eigen::EigenSolver<Matrix<S>>(companion, false).eigenvalues();
}

// Coefficients of prod_k (x - r_k), descending powers of x, from complex
// roots (conjugate pairs give real coefficients up to rounding).
template <typename S>
Eigen::Matrix<std::complex<S>, Eigen::Dynamic, 1> monic_from_roots(
    const Eigen::Matrix<std::complex<S>, Eigen::Dynamic, 1>& r) {
  Eigen::Matrix<std::complex<S>, Eigen::Dynamic, 1> c =
      Eigen::Matrix<std::complex<S>, Eigen::Dynamic, 1>::Zero(r.size() + 1);
  c(0) = 1;
  for (Eigen::Index k = 0; k < r.size(); ++k) {
    for (Eigen::Index i = k + 1; i > 0; --i) c(i) -= r(k) * c(i - 1);
  }
  return c;
}

}  // namespace ctid
