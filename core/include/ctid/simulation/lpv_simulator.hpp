// SPDX-License-Identifier: BSD-3-Clause
// Copyright (C) the ctid authors
// Simulation of a continuous-time linear parameter-varying (LPV)
// input/output model on sampled data (CONTSID's simulLPVCT).
//
// The model, with coefficients that multiply the derivatives,
//
//   a_0 y^(na) + a_1(rho) y^(na-1) + .. + a_na(rho) y
//       = b_1(rho) u^(nb-1) + .. + b_nb(rho) u,
//
// each coefficient a linear combination of scheduling-dependent basis
// functions known at the samples,
//
//   a_i(rho_k) = sum_j A(i, j) fA(j, i, k),  b_i(rho_k) = sum_j B(i, j) fB(j,
//   i, k)
//
// (Laurain, Toth, Gilson, Garnier, IET Control Theory Appl. 5(7), 2011).
// The basis values are CONTSID's dependency arrays DepA (n_dep x na x N) and
// DepB (n_dep x nb x N), column-major. The leading coefficient a_0 = A(0, 0)
// is constant.
//
// Derivatives of the sampled signals are backward (Euler) differences,
// D = (1 - q^-1) / Ts, so that D^m s_k = Ts^-m sum_l (-1)^l C(m, l) s_(k-l),
// with every signal at rest before the first sample (s_k = 0 for k < 0).
// The model then holds exactly as a recursion on the samples, solved for
// y_k at each k (the implicit, backward-Euler discretisation of the ODE:
// first order in Ts, so Ts must be small against the time constants). The
// estimator of lpv_refined_iv.hpp uses the same operator, so a model
// simulated here is recovered exactly from noise-free data.
#pragma once

#include <cmath>
#include <string>
#include <vector>

#include "ctid/base/status.hpp"
#include "ctid/base/types.hpp"

namespace ctid {

// Values of the basis functions of na (or nb) coefficients at N samples:
// value(j, i, k) is basis j of coefficient i at sample k (CONTSID's DepA).
template <typename S>
struct LpvBasis {
  const S* values = nullptr;
  Eigen::Index num_functions = 0;     // n_dep
  Eigen::Index num_coefficients = 0;  // na or nb
  Eigen::Index num_samples = 0;       // N

  S value(Eigen::Index j, Eigen::Index i, Eigen::Index k) const {
    return values[j + num_functions * (i + num_coefficients * k)];
  }
  // Basis j of coefficient i is used (not identically zero).
  bool active(Eigen::Index j, Eigen::Index i) const {
    for (Eigen::Index k = 0; k < num_samples; ++k) {
      if (value(j, i, k) != S(0)) return true;
    }
    return false;
  }
  // Basis j of coefficient i has one nonzero value at every sample.
  bool constant(Eigen::Index j, Eigen::Index i) const {
    const S first = num_samples > 0 ? value(j, i, 0) : S(0);
    if (first == S(0)) return false;
    for (Eigen::Index k = 1; k < num_samples; ++k) {
      if (value(j, i, k) != first) return false;
    }
    return true;
  }
};

namespace lpv_detail {

// Weights w[m][l] = (-1)^l C(m, l) Ts^-m of D^m s_k = sum_l w[m][l] s_(k-l),
// m = 0..order.
template <typename S>
std::vector<std::vector<S>> difference_weights(int order, S ts) {
  std::vector<std::vector<S>> w(static_cast<std::size_t>(order) + 1);
  for (int m = 0; m <= order; ++m) {
    w[m].assign(static_cast<std::size_t>(m) + 1, S(0));
    S binomial = 1;
    const S scale = std::pow(ts, -S(m));
    for (int l = 0; l <= m; ++l) {
      w[m][l] = ((l % 2) ? -binomial : binomial) * scale;
      binomial = binomial * S(m - l) / S(l + 1);
    }
  }
  return w;
}

// out_k = D^m s_k (backward differences, at rest before the first sample).
template <typename S>
void backward_difference(const S* s, Eigen::Index n,
                         const std::vector<S>& weights, S* out) {
  const Eigen::Index m = static_cast<Eigen::Index>(weights.size()) - 1;
  for (Eigen::Index k = 0; k < n; ++k) {
    S acc = 0;
    const Eigen::Index last = std::min(m, k);
    for (Eigen::Index l = 0; l <= last; ++l) acc += weights[l] * s[k - l];
    out[k] = acc;
  }
}

// Coefficient values c_i(rho_k) = sum_j coef(i + row0, j) f(j, i, k):
// an N-by-(num_coefficients) matrix.
template <typename S>
Matrix<S> coefficient_trajectories(const Matrix<S>& coef, Eigen::Index row0,
                                   const LpvBasis<S>& basis) {
  const Eigen::Index n = basis.num_samples;
  Matrix<S> c = Matrix<S>::Zero(n, basis.num_coefficients);
  for (Eigen::Index k = 0; k < n; ++k) {
    for (Eigen::Index i = 0; i < basis.num_coefficients; ++i) {
      S acc = 0;
      for (Eigen::Index j = 0; j < basis.num_functions; ++j) {
        acc += coef(i + row0, j) * basis.value(j, i, k);
      }
      c(k, i) = acc;
    }
  }
  return c;
}

}  // namespace lpv_detail

// Checks the sizes of the coefficient matrices A ((na+1) x n_dep_a, first
// row [a_0 0 .. 0]) and B (nb x n_dep_b) against their bases.
template <typename S>
Status check_lpv_model(const Matrix<S>& a, const LpvBasis<S>& dep_a,
                       const Matrix<S>& b, const LpvBasis<S>& dep_b) {
  if (dep_a.num_samples != dep_b.num_samples) {
    return dimension_mismatch(
        "DepA and DepB must have the same number of samples (third "
        "dimension)");
  }
  if (a.rows() != dep_a.num_coefficients + 1 ||
      a.cols() != dep_a.num_functions) {
    return dimension_mismatch(
        "A must be (na+1)-by-n_dep = " +
        std::to_string(dep_a.num_coefficients + 1) + "-by-" +
        std::to_string(dep_a.num_functions) + " for this DepA, got " +
        std::to_string(a.rows()) + "-by-" + std::to_string(a.cols()));
  }
  if (b.rows() != dep_b.num_coefficients || b.cols() != dep_b.num_functions) {
    return dimension_mismatch(
        "B must be nb-by-n_dep = " + std::to_string(dep_b.num_coefficients) +
        "-by-" + std::to_string(dep_b.num_functions) + " for this DepB, got " +
        std::to_string(b.rows()) + "-by-" + std::to_string(b.cols()));
  }
  if (dep_b.num_coefficients < 1) {
    return bad_input("the model needs at least one B coefficient (nb >= 1)");
  }
  if (!a.allFinite() || !b.allFinite()) {
    return bad_input("A and B must be finite");
  }
  if (!(a(0, 0) != S(0)) ||
      (a.cols() > 1 && (a.row(0).tail(a.cols() - 1).array() != S(0)).any())) {
    return bad_input(
        "the first row of A is the constant leading coefficient "
        "[a0 0 .. 0] with a0 nonzero");
  }
  return Status::Ok();
}

// Noise-free output of the LPV model for the input u (N samples), written
// to y. Fails (numericalFailure) when the recursion is singular at a sample
// or the output is not finite (an unstable model).
template <typename S>
Status simulate_lpv(const S* u, Eigen::Index n, S ts, const Matrix<S>& a,
                    const LpvBasis<S>& dep_a, const Matrix<S>& b,
                    const LpvBasis<S>& dep_b, S* y) {
  const Status sizes = check_lpv_model(a, dep_a, b, dep_b);
  if (!sizes.ok()) return sizes;
  if (dep_a.num_samples != n) {
    return dimension_mismatch("the dependency arrays have " +
                              std::to_string(dep_a.num_samples) +
                              " samples but u has " + std::to_string(n));
  }
  if (!(ts > 0) || !std::isfinite(ts)) return bad_input("Ts must be > 0");
  using namespace lpv_detail;
  const int na = static_cast<int>(dep_a.num_coefficients);
  const int nb = static_cast<int>(dep_b.num_coefficients);
  const auto wa = difference_weights<S>(na, ts);
  const auto wb = difference_weights<S>(nb - 1, ts);
  const Matrix<S> alpha = coefficient_trajectories<S>(a, 1, dep_a);
  const Matrix<S> beta = coefficient_trajectories<S>(b, 0, dep_b);
  const S a0 = a(0, 0);
  // D^m u for m = 0..nb-1.
  Matrix<S> du(n, nb);
  for (int m = 0; m < nb; ++m)
    backward_difference(u, n, wb[m], du.col(m).data());
  for (Eigen::Index k = 0; k < n; ++k) {
    // sum_i alpha_i D^(na-i) y_k = r_k, with y_k alone on the left.
    S r = 0;
    for (int i = 0; i < nb; ++i) r += beta(k, i) * du(k, nb - 1 - i);
    S lead = a0 * wa[na][0];
    for (Eigen::Index l = 1; l <= std::min<Eigen::Index>(na, k); ++l) {
      r -= a0 * wa[na][l] * y[k - l];
    }
    for (int i = 1; i <= na; ++i) {
      const int m = na - i;
      const S c = alpha(k, i - 1);
      lead += c * wa[m][0];
      for (Eigen::Index l = 1; l <= std::min<Eigen::Index>(m, k); ++l) {
        r -= c * wa[m][l] * y[k - l];
      }
    }
    if (!(lead != S(0)) || !std::isfinite(lead)) {
      return numerical_failure("the LPV recursion is singular at sample " +
                               std::to_string(k + 1) +
                               " (a0 Ts^-na + .. + a_na(rho) = 0)");
    }
    y[k] = r / lead;
    if (!std::isfinite(y[k])) {
      return numerical_failure(
          "the simulated output is not finite from sample " +
          std::to_string(k + 1) + " on (unstable model)");
    }
  }
  return Status::Ok();
}

}  // namespace ctid
