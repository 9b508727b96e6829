// SPDX-License-Identifier: BSD-3-Clause
// Copyright (C) the ctid authors
// Eigen aliases shared by the core. Every numerical class is a template on
// the scalar type so that the same code runs in double and in float.
#pragma once

#include <Eigen/Dense>

namespace ctid {

template <typename S>
using Vector = Eigen::Matrix<S, Eigen::Dynamic, 1>;
template <typename S>
using Matrix = Eigen::Matrix<S, Eigen::Dynamic, Eigen::Dynamic>;

// How the signal behaves between samples (the data's InterSample property).
//   kZoh: piecewise constant, held from one sample to the next (exact
//         discretisation through the matrix exponential, thesis App. A.1);
//   kFoh: treated as piecewise linear, discretised with the trapezoidal
//         (Tustin) rule (thesis App. A.2).
enum class InterSample { kZoh, kFoh };

}  // namespace ctid
