// SPDX-License-Identifier: BSD-3-Clause
// Copyright (C) the ctid authors

// Products of a small square matrix with a vector, written once for the
// fixed-size kernels (the adaptation steps of adaptation/, the per-sample
// filters of filters/svf.hpp). The matrix is an n-by-n array stored column
// by column, m[j * n + i] = M(i, j); the arguments are anything indexable
// (pointers, local arrays, the Working copies of step_size.hpp). The loops
// are plain, so that for a compile-time n the compiler unrolls them and
// keeps every value in a register once the function is inlined; the sums
// run in a fixed order (the same result for every size).
#pragma once

namespace ctid {

// out = M x, summed column by column (out = m_0 x_0 + m_1 x_1 + ...).
template <typename Mat, typename In, typename Out>
inline void multiply(int n, const Mat& m, const In& x, Out& out) {
#pragma GCC unroll 8
  for (int i = 0; i < n; ++i) out[i] = m[i] * x[0];
#pragma GCC unroll 8
  for (int j = 1; j < n; ++j) {
#pragma GCC unroll 8
    for (int i = 0; i < n; ++i) out[i] += m[j * n + i] * x[j];
  }
}

// out = M^T x: out[j] = (column j of M) . x.
template <typename Mat, typename In, typename Out>
inline void multiply_transposed(int n, const Mat& m, const In& x, Out& out) {
#pragma GCC unroll 8
  for (int j = 0; j < n; ++j) {
    auto sum = m[j * n] * x[0];
#pragma GCC unroll 8
    for (int i = 1; i < n; ++i) sum += m[j * n + i] * x[i];
    out[j] = sum;
  }
}

}  // namespace ctid
