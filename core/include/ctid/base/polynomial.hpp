// SPDX-License-Identifier: BSD-3-Clause
// Copyright (C) the ctid authors

// Polynomial helpers shared by the core: product, value, derivative and
// roots of real polynomials stored as coefficient vectors.
#pragma once

#include <algorithm>
#include <cmath>
#include <complex>
#include <limits>
#include <vector>

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

// The roots of c (descending powers), as Octave's roots finds them: the
// eigenvalues of the companion matrix of c without its leading zeros, then
// one zero root for each trailing zero (appended last); none for an empty,
// all-zero or constant c; not-a-number ones when c holds a value that is
// not finite.
template <typename S>
std::vector<std::complex<S>> roots_descending(const Vector<S>& c) {
  std::vector<std::complex<S>> r;
  if (c.size() > 1 && !c.allFinite()) {
    r.assign(static_cast<std::size_t>(c.size() - 1),
             std::complex<S>(std::numeric_limits<S>::quiet_NaN()));
    return r;
  }
  S cmax = 0;
  for (Eigen::Index i = 0; i < c.size(); ++i) {
    cmax = std::max(cmax, std::abs(c(i)));
  }
  if (c.size() == 0 || cmax == 0) return r;
  Eigen::Index first = 0, last = c.size() - 1;
  while (c(first) / cmax == 0) ++first;
  while (c(last) / cmax == 0) --last;
  if (last > first) {
    Vector<S> ascending(last - first + 1);
    for (Eigen::Index i = first; i <= last; ++i) ascending(last - i) = c(i);
    const auto z = polynomial_roots<S>(ascending);
    for (Eigen::Index i = 0; i < z.size(); ++i) r.push_back(z(i));
  }
  for (Eigen::Index i = last + 1; i < c.size(); ++i) r.emplace_back(S(0));
  return r;
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

// The real coefficients (descending powers, monic) of prod_k (x - r_k)
// from roots in conjugate pairs, given as a list.
template <typename S>
Vector<S> real_monic_from_roots(const std::vector<std::complex<S>>& r) {
  const Eigen::Map<const Eigen::Matrix<std::complex<S>, Eigen::Dynamic, 1>> v(
      r.data(), static_cast<Eigen::Index>(r.size()));
  return monic_from_roots<S>(v).real();
}

}  // namespace ctid
