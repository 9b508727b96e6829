// SPDX-License-Identifier: BSD-3-Clause
// Copyright (C) the ctid authors

// Matrix exponential of a badly scaled matrix, through a diagonal
// similarity that balances it first:
//
//   exp(A) = D exp(D^-1 A D) D^-1,
//
// D = diag(d) with powers of 2 (exact in floating point) chosen so that each
// row and column of D^-1 A D have about the same 1-norm off the diagonal
// (Parlett and Reinsch's balancing, LAPACK's dgebal scaling step, which
// MATLAB's and Octave's expm apply too; Eigen's exp() does not).
//
// Why: the scaling-and-squaring exponential is accurate relative to the
// norm of its argument. A companion (controllable canonical) matrix of a
// high-order model with widely spread poles has coefficients from 1 to
// 1e11 or more (a sixth-order model with modes at 20-240 rad/s: a_6 = 2.8e11)
// and its exponential, computed directly, errs by far more than its small
// entries: the propagator gets an eigenvalue above 1 and a stable model's
// simulation overflows. Balanced, the same matrix has entries of the size
// of its characteristic frequency, and each entry of the exponential keeps
// its relative accuracy through the exact diagonal scaling back.
#pragma once

#include <cmath>
#include <unsupported/Eigen/MatrixFunctions>

#include "ctid/base/types.hpp"

namespace ctid {

// In place: a <- D^-1 a D; returns d (the diagonal of D). Rows or columns
// that are zero off the diagonal keep d = 1.
template <typename S>
Vector<S> balance_diagonal(Matrix<S>& a) {
  const Eigen::Index n = a.rows();
  Vector<S> d = Vector<S>::Ones(n);
  const S radix = 2;
  const S radix2 = radix * radix;
  bool done = false;
  for (int sweep = 0; !done && sweep < 100; ++sweep) {
    done = true;
    for (Eigen::Index i = 0; i < n; ++i) {
      S c = 0;
      S r = 0;
      for (Eigen::Index j = 0; j < n; ++j) {
        if (j == i) continue;
        c += std::abs(a(j, i));
        r += std::abs(a(i, j));
      }
      if (c == 0 || r == 0) continue;
      const S s = c + r;
      S f = 1;
      S g = r / radix;
      while (c < g) {
        f *= radix;
        c *= radix2;
      }
      g = r * radix;
      while (c > g) {
        f /= radix;
        c /= radix2;
      }
      if ((c + r) / f < S(0.95) * s) {
        done = false;
        d(i) *= f;
        a.row(i) /= f;
        a.col(i) *= f;
      }
    }
  }
  return d;
}

// exp(a), computed on the balanced matrix and scaled back.
template <typename S>
Matrix<S> balanced_exp(const Matrix<S>& a) {
  Matrix<S> b = a;
  const Vector<S> d = balance_diagonal(b);
  Matrix<S> e = b.exp();
  // D e D^-1: entry (i, j) times d_i / d_j
  for (Eigen::Index j = 0; j < e.cols(); ++j) {
    for (Eigen::Index i = 0; i < e.rows(); ++i) e(i, j) *= d(i) / d(j);
  }
  return e;
}

}  // namespace ctid
