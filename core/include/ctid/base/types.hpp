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

// How the signal behaves between samples (the data's InterSample property)
// and so how a filter of it is discretised (filters/discretization.hpp,
// discretisation_of()):
//   kZoh: piecewise constant, held from one sample to the next: the exact
//         zero-order-hold discretisation (thesis App. A.1, eq. A.6);
//   kFoh: piecewise linear between samples: the exact first-order-hold
//         discretisation (App. A.1 with the input's slope as a state);
//   kTrapezoid: treated as piecewise linear but filtered with the
//         trapezoidal (Tustin, bilinear) rule (App. A.2), the choice of the
//         thesis for the recursive methods (Sec. 3.1.3, Suggested
//         procedure 3.3): named so that a thesis reproduction asks for it.
enum class InterSample { kZoh, kFoh, kTrapezoid };

}  // namespace ctid
