// SPDX-License-Identifier: BSD-3-Clause
// Copyright (C) the ctid authors
// CONTSID's LPV example system for the tests of lpv_simulator.hpp and
// lpv_refined_iv.hpp: the coefficient matrices and the dependency arrays
// of a scheduling signal.
#pragma once

#include <Eigen/Dense>
#include <cmath>
#include <vector>

#include "ctid/simulation/lpv_simulator.hpp"

namespace ctid::test {

// The system of CONTSID's LPV example:
//   y'' + a1(p) y' + a2(p) y = b1(p) u' + b0(p) u,
//   a1 = 2 - 1.5p + 2p^2, a2 = 5 + 3p, b1 = 3 + 2cos(p), b0 = 5 - 3 sin(2p).
struct Example {
  Eigen::MatrixXd a{{1, 0, 0}, {2, -1.5, 2}, {5, 3, 0}};
  Eigen::MatrixXd b{{3, 2}, {5, -3}};
  std::vector<double> dep_a, dep_b;
  LpvBasis<double> basis_a, basis_b;

  explicit Example(const std::vector<double>& p) {
    const Eigen::Index n = static_cast<Eigen::Index>(p.size());
    dep_a.resize(3 * 2 * n);
    dep_b.resize(2 * 2 * n);
    for (Eigen::Index k = 0; k < n; ++k) {
      const double r = p[k];
      const double fa[6] = {1, r, r * r, 1, r, 0};
      for (int q = 0; q < 6; ++q) dep_a[6 * k + q] = fa[q];
      const double fb[4] = {1, std::cos(r), 1, std::sin(2 * r)};
      for (int q = 0; q < 4; ++q) dep_b[4 * k + q] = fb[q];
    }
    basis_a = {dep_a.data(), 3, 2, n};
    basis_b = {dep_b.data(), 2, 2, n};
  }
};

}  // namespace ctid::test
