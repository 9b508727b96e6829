// SPDX-License-Identifier: BSD-3-Clause
// Copyright (C) the ctid authors
// Shared assertions for the core tests: matrix comparison with a relative
// tolerance that reports the first failing entry.
#pragma once

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <cstdio>
#include <random>
#include <sstream>
#include <string>
#include <unsupported/Eigen/MatrixFunctions>
#include <vector>

namespace ctid::test {

// num(p)/den(p) (descending powers, proper) driven by v held over each
// step h, output at every sample (the system at rest at t = 0): the exact
// ZOH response through the matrix exponential of the controllable form.
inline std::vector<double> simulate_zoh(const Eigen::VectorXd& num,
                                        const Eigen::VectorXd& den,
                                        const std::vector<double>& v,
                                        double h) {
  const int n = static_cast<int>(den.size()) - 1;
  const double lead = den(0);
  Eigen::VectorXd a = den / lead;
  Eigen::VectorXd b = Eigen::VectorXd::Zero(n + 1);
  b.tail(num.size()) = num / lead;
  // x' = A x + B v, x = [w .. w^(n-1)], y = sum c_i w^(i) + d v.
  Eigen::MatrixXd A = Eigen::MatrixXd::Zero(n, n);
  for (int i = 0; i + 1 < n; ++i) A(i, i + 1) = 1;
  for (int j = 0; j < n; ++j) A(n - 1, j) = -a(n - j);
  const double d = b(0);
  Eigen::RowVectorXd c(n);
  for (int i = 0; i < n; ++i) c(i) = b(n - i) - d * a(n - i);
  Eigen::MatrixXd big = Eigen::MatrixXd::Zero(n + 1, n + 1);
  big.topLeftCorner(n, n) = A * h;
  big(n - 1, n) = h;
  const Eigen::MatrixXd e = big.exp();
  const Eigen::MatrixXd Phi = e.topLeftCorner(n, n);
  const Eigen::VectorXd G = e.topRightCorner(n, 1);
  Eigen::VectorXd x = Eigen::VectorXd::Zero(n);
  std::vector<double> y(v.size());
  for (std::size_t k = 0; k < v.size(); ++k) {
    y[k] = c * x + d * v[k];
    x = Phi * x + G * v[k];
  }
  return y;
}

// |a - b| <= tol * max(1, max|b|) entry by entry.
template <typename A, typename B>
::testing::AssertionResult MatrixNear(const Eigen::MatrixBase<A>& a,
                                      const Eigen::MatrixBase<B>& b,
                                      double tol) {
  if (a.rows() != b.rows() || a.cols() != b.cols()) {
    return ::testing::AssertionFailure()
           << "size " << a.rows() << "x" << a.cols() << " vs " << b.rows()
           << "x" << b.cols();
  }
  const double scale =
      std::max(1.0, static_cast<double>(b.cwiseAbs().maxCoeff()));
  for (Eigen::Index j = 0; j < a.cols(); ++j) {
    for (Eigen::Index i = 0; i < a.rows(); ++i) {
      const double diff =
          std::abs(static_cast<double>(a(i, j)) - static_cast<double>(b(i, j)));
      if (!(diff <= tol * scale)) {
        return ::testing::AssertionFailure()
               << "entry (" << i << "," << j << "): " << a(i, j) << " vs "
               << b(i, j) << ", |diff| = " << diff
               << " > tol*scale = " << tol * scale << " (tol " << tol << ")";
      }
    }
  }
  return ::testing::AssertionSuccess();
}

inline std::string scientific(double value) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.3e", value);
  return buffer;
}

inline double relative_error(const Eigen::VectorXd& a,
                             const Eigen::VectorXd& b) {
  return (a - b).norm() / b.norm();
}

// Random binary input (levels +-1) held for `hold` samples, from the raw
// mt19937 stream (the same on every platform).
inline std::vector<double> binary_input(int n, int hold, unsigned seed) {
  std::mt19937 rng(seed);
  std::vector<double> u(n);
  double level = 1;
  for (int k = 0; k < n; ++k) {
    if (k % hold == 0) level = (rng() & 1) ? 1.0 : -1.0;
    u[k] = level;
  }
  return u;
}

}  // namespace ctid::test
