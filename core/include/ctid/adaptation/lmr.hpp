// SPDX-License-Identifier: BSD-3-Clause
// Copyright (C) the ctid authors
// Levenberg-Marquardt regularised least squares, LMR-RLSSVF, thesis
// eq. (3.82) (sec. 3.6.3, [Waterschoot et al., 2008]): the minimiser of
//
//   V = sum_k lambda^(N'-k) [y_f^(na) - phi_f^T theta]^2
//       + [theta - theta(t_(N'-1))]^T Gamma [theta - theta(t_(N'-1))],  (3.81)
//
// propagated in information form,
//
//   R(t_k)     = lambda R(t_(k-1)) + phi_f phi_f^T + (1 - lambda) Gamma,
//   epsilon    = y_f^(na)(t_k) - phi_f^T theta(t_(k-1)),
//   theta(t_k) = theta(t_(k-1)) + R(t_k)^-1 phi_f epsilon,
//
// started from R(t_0) = P(t_0)^-1. The regularisation keeps R from
// decaying to a singular matrix under poor excitation (the windup of the
// forgetting factor, eq. 3.77), at the price of a bias toward the previous
// estimate. P = R^-1, so kappa_2(P) = kappa_2(R).
//
// Square-root information form (not in the thesis). R itself,
// summed in working precision, is lost under poor excitation: with a
// constant input phi_f stays in one direction, where R grows to
// |phi_f|^2 / (1 - lambda), while in the other directions R tends to Gamma.
// Each step adds a rounding error of about eps |R| to every entry, and
// the errors of the last 1 / (1 - lambda) steps are all still in R: in
// single precision, lambda = 0.998 and Gamma = 1e-3 I of the long-run
// scenario (tests/core/long_run_scenario.hpp), |phi_f|^2 / (1 - lambda)
// ~ 1e3 and eps |R| sqrt(500) ~ 1e-3, the size of Gamma itself, and the
// smallest eigenvalue of the summed R went negative after 5 880 samples of
// constant input (R's Cholesky failed). Here R = L L^T is propagated
// through its Cholesky factor L (lower triangular, positive diagonal):
// L <- sqrt(lambda) L, then one rank-one Cholesky update by phi_f and one
// per column g_i of a square root of (1 - lambda) Gamma (G G^T, from
// Gamma's eigenvalues, computed once). Every step re-triangularises a
// sum of squares: L L^T is positive definite by construction, its
// condition number is the square root of R's, and theta's gain is two
// triangular solves. O(n^2) per update, O(n^3) per step with Gamma.
//
// Guard on R (option covariance_guard, as for P in covariance_guard.hpp
// and reported the same way): after each step, row by row,
//   - ceiling: R_jj = |L_j,:|^2 above sqrt(max) of the precision (or
//     above the largest R_jj of R(t_0)) scales row j of L down to it:
//     R <- E R E, a congruence (the correlations of R are unchanged);
//   - floor, in correlation form as the P guard: the j-th pivot of R's
//     LDL^T, L_jj^2, must exceed rho R_jj (rho = n eps), and R_jj must be
//     at least 1 / ceiling (or the smallest R_jj of R(t_0)); otherwise
//     delta e_j e_j^T is added to R (one rank-one update of L) with
//     delta such that the pivot becomes 10 rho R_jj, or R_jj the floor:
//     information on parameter j alone, like Gamma. Without Gamma and
//     with lambda < 1 this bounds the windup (R decays as lambda^k) at the
//     range of the precision.
// The guard leaves L untouched, bit for bit, while neither applies.
// Nothing is allocated per step.
//
// The step is written once, as a template on the parameter count
// (step_size.hpp): at compile-time size np when configured with
// fixed_size = true and np <= kMaxFixedParameters, on a local copy of L
// written back once; otherwise at runtime size on L itself.
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>
#include <type_traits>

#include "ctid/adaptation/adaptation.hpp"
#include "ctid/adaptation/covariance_guard.hpp"
#include "ctid/adaptation/step_size.hpp"

namespace ctid {

template <typename S>
class LmrUpdate {
 public:
  // np parameters, forgetting factor lambda, Gamma (symmetric positive
  // semi-definite, see validate_covariance), the guard on R on or off;
  // fixed_size: the step at compile-time size np when np <=
  // kMaxFixedParameters (chosen here, once; step_size.hpp).
  void configure(Eigen::Index np, S lambda, const Matrix<S>& gamma,
                 bool guard = true, bool fixed_size = false) {
    fixed_np_ = fixed_step_size(np, fixed_size);
    step_ = select_size(np, fixed_size, [](auto size) {
      return &LmrUpdate::step<decltype(size)::value>;
    });
    lambda_ = lambda;
    sqrt_lambda_ = std::sqrt(lambda);
    guard_ = guard;
    rho_ = S(np > 0 ? np : 1) * std::numeric_limits<S>::epsilon();
    gamma_root_ = Matrix<S>::Zero(np, 0);
    if (np > 0 && lambda != S(1)) {
      const Matrix<S> sym = (gamma + gamma.transpose()) / 2;
      const Eigen::SelfAdjointEigenSolver<Matrix<S>> eig(sym);
      const Vector<S>& values = eig.eigenvalues();
      const S top = std::max(S(0), values(np - 1));
      Eigen::Index kept = 0;
      for (Eigen::Index k = 0; k < np; ++k) kept += values(k) > rho_ * top;
      gamma_root_.resize(np, kept);
      for (Eigen::Index k = np - kept, c = 0; k < np; ++k, ++c) {
        gamma_root_.col(c) =
            eig.eigenvectors().col(k) * std::sqrt((1 - lambda) * values(k));
      }
    }
    theta_ = Vector<S>::Zero(np);
    L_ = Matrix<S>::Identity(np, np);
    R_ = Matrix<S>::Identity(np, np);
    P_ = Matrix<S>::Identity(np, np);
    work_ = Vector<S>::Zero(np);
    x_ = Vector<S>::Zero(np);
    phi_copy_ = Vector<S>::Zero(np);
    ceiling_ = std::sqrt(std::numeric_limits<S>::max());
    floor_ = 1 / ceiling_;
  }

  // R(t_0) = P0^-1 (P0 positive definite, see validate_covariance).
  void reset(const Vector<S>& theta0, const Matrix<S>& P0) {
    theta_ = theta0;
    const Eigen::Index np = P0.rows();
    Matrix<S> R0 = Eigen::LLT<Matrix<S>>((P0 + P0.transpose()) / 2)
                       .solve(Matrix<S>::Identity(np, np));
    R0 = (R0 + R0.transpose()) / 2;
    const Eigen::LLT<Matrix<S>> llt(R0);
    L_ = llt.matrixL();
    failed_ = llt.info() != Eigen::Success || !L_.allFinite();
    ceiling_ = std::sqrt(std::numeric_limits<S>::max());
    floor_ = 1 / ceiling_;
    for (Eigen::Index j = 0; j < np; ++j) {
      const S rjj = L_.row(j).head(j + 1).squaredNorm();
      if (std::isfinite(rjj) && rjj > 0) {
        ceiling_ = std::max(ceiling_, rjj);
        floor_ = std::min(floor_, rjj);
      }
    }
    last_ = kGuardNone;
  }

  // One LMR-RLSSVF step (3.82). Returns the prediction error (3.82c). When
  // R's factor stops being finite (data beyond the range of the
  // precision), the estimate is kept and failed() turns true.
  template <typename Derived>
  S update(const Eigen::MatrixBase<Derived>& phi, S target) {
    return (this->*step_)(contiguous(phi, phi_copy_), target);
  }

  const Vector<S>& theta() const { return theta_; }
  // The Cholesky factor L of R = L L^T (lower triangular).
  const Matrix<S>& factor() const { return L_; }
  // R(t_k) = L L^T, formed on request.
  const Matrix<S>& information() const {
    R_.noalias() = L_ * L_.transpose();
    return R_;
  }
  // P(t_k) = R(t_k)^-1 = L^-T L^-1, formed on request.
  const Matrix<S>& P() const {
    const Eigen::Index np = L_.rows();
    inverse_ = Matrix<S>::Identity(np, np);
    L_.template triangularView<Eigen::Lower>().solveInPlace(inverse_);
    P_.noalias() = inverse_.transpose() * inverse_;
    return P_;
  }
  // kappa_2(R) = kappa_2(L)^2, from the singular values of L.
  S condition_number() const {
    if (L_.size() == 0) return S(1);
    if (failed_) return std::numeric_limits<S>::infinity();
    const Eigen::JacobiSVD<Matrix<S>> svd(L_);
    const auto& sv = svd.singularValues();
    if (!(sv(sv.size() - 1) > 0)) return std::numeric_limits<S>::infinity();
    const S ratio = sv(0) / sv(sv.size() - 1);
    return ratio * ratio;
  }
  bool failed() const { return failed_; }
  // What the guard did to R at the last update (CovarianceGuardAction:
  // kGuardRepair for a raised pivot or diagonal, kGuardCeiling).
  int covariance_guard() const { return last_; }
  // N of the compile-time-size step in use, 0 for the runtime-size one.
  int fixed_size() const { return fixed_np_; }

 private:
  using Step = S (LmrUpdate::*)(const S*, S);

  // The step for np = N (step_size.hpp) on l[k * n + i] = L(i, k).
  template <int N>
  S step(const S* phi, S target) {
    const int n = step_size<N>(theta_.size());
    Working<S, N> theta(theta_.data(), true);
    S prediction = 0;
#pragma GCC unroll 8
    for (int i = 0; i < n; ++i) prediction += phi[i] * theta[i];
    const S error = target - prediction;
    last_ = kGuardNone;
    if (failed_) return error;
    Working<S, array_size(N, N)> l(L_.data(), true);
    Working<S, N> x(x_.data(), false), w(work_.data(), false);
    // R <- lambda R + phi phi^T + (1 - lambda) Gamma, eq. (3.82a).
    if (lambda_ != S(1)) {
      const S sqrt_lambda = sqrt_lambda_;
#pragma GCC unroll 64
      for (int i = 0; i < n * n; ++i) l[i] *= sqrt_lambda;
    }
#pragma GCC unroll 8
    for (int i = 0; i < n; ++i) x[i] = phi[i];
    rank_one_update<N>(l, x, 0);
    const S* g = gamma_root_.data();
    for (Eigen::Index c = 0; c < gamma_root_.cols(); ++c) {
#pragma GCC unroll 8
      for (int i = 0; i < n; ++i) x[i] = g[c * n + i];
      rank_one_update<N>(l, x, 0);
    }
    bool finite = true;
#pragma GCC unroll 64
    for (int i = 0; i < n * n; ++i) finite = finite & std::isfinite(l[i]);
    l.write_back();
    if (!finite) {
      failed_ = true;
      return error;
    }
    if (guard_) {
      last_ = guard<N>(l, x);
      if (last_ != kGuardNone) l.write_back();
    }
    // theta += R^-1 phi epsilon (3.82c): L w = phi forward, then L^T w = w
    // backward.
#pragma GCC unroll 8
    for (int i = 0; i < n; ++i) w[i] = phi[i];
#pragma GCC unroll 8
    for (int k = 0; k < n; ++k) {
      w[k] /= l[k * n + k];
#pragma GCC unroll 8
      for (int i = k + 1; i < n; ++i) w[i] -= w[k] * l[k * n + i];
    }
#pragma GCC unroll 8
    for (int k = n - 1; k >= 0; --k) {
      S sum = w[k];
#pragma GCC unroll 8
      for (int i = k + 1; i < n; ++i) sum -= l[k * n + i] * w[i];
      w[k] = sum / l[k * n + k];
    }
#pragma GCC unroll 8
    for (int i = 0; i < n; ++i) theta[i] += w[i] * error;
    theta.write_back();
    return error;
  }

  // L L^T + x x^T, x (zero above `first`) consumed: Givens rotations of
  // column k of L against x that zero x_k (LINPACK's dchud), |c|, |s| <= 1
  // whatever the size of x_k against L_kk.
  template <int N, typename Square, typename Column>
  void rank_one_update(Square& l, Column& x, int first) const {
    const int n = step_size<N>(theta_.size());
#pragma GCC unroll 8
    for (int k = first; k < n; ++k) {
      const S xk = x[k];
      if (xk == 0) continue;
      const S lkk = l[k * n + k];
      const S r = std::sqrt(lkk * lkk + xk * xk);
      const S c = lkk / r, s = xk / r;
      l[k * n + k] = r;
#pragma GCC unroll 8
      for (int i = k + 1; i < n; ++i) {
        const S lik = l[k * n + i];
        l[k * n + i] = c * lik + s * x[i];
        x[i] = c * x[i] - s * lik;
      }
    }
  }

  // The guard on R = L L^T, row by row (see above); x as workspace.
  template <int N, typename Square, typename Column>
  int guard(Square& l, Column& x) const {
    const int n = step_size<N>(theta_.size());
    int action = kGuardNone;
#pragma GCC unroll 8
    for (int j = 0; j < n; ++j) {
      S rjj = 0;
#pragma GCC unroll 8
      for (int k = 0; k <= j; ++k) rjj += l[k * n + j] * l[k * n + j];
      if (rjj > ceiling_) {
        const S e = std::sqrt(ceiling_ / rjj);
        for (int k = 0; k <= j; ++k) l[k * n + j] *= e;
        rjj = 0;
        for (int k = 0; k <= j; ++k) rjj += l[k * n + j] * l[k * n + j];
        action |= kGuardCeiling;
      }
      const S pivot = l[j * n + j] * l[j * n + j];
      S delta = 0;
      if (!(pivot > rho_ * rjj)) {
        delta = (10 * rho_ * rjj - pivot) / (1 - 10 * rho_);
      }
      if (rjj < floor_) delta = std::max(delta, floor_ - rjj);
      if (!(delta > 0)) continue;
      for (int i = 0; i < n; ++i) x[i] = 0;
      x[j] = std::sqrt(delta);
      rank_one_update<N>(l, x, j);
      action |= kGuardRepair;
    }
    return action;
  }

  S lambda_ = 1, sqrt_lambda_ = 1;
  bool guard_ = true;
  S rho_ = 0, ceiling_ = 0, floor_ = 0;
  Matrix<S> gamma_root_;  // G with G G^T = (1 - lambda) Gamma
  Vector<S> theta_;
  Matrix<S> L_;
  mutable Matrix<S> R_, P_, inverse_;  // formed on request
  Vector<S> work_, x_;
  Vector<S> phi_copy_;  // phi when not contiguous
  Step step_ = nullptr;
  bool failed_ = false;
  int last_ = kGuardNone;
  int fixed_np_ = 0;
};

}  // namespace ctid
