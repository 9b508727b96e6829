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
// Fixed-size path: configured with fixed_size = true and
// np <= kMaxFixedParameters, the step runs as update_fixed<np>, unrolled
// scalar code on a local copy of L written back once (as
// ParameterUpdate::update_fixed in adaptation.hpp): the same rotations,
// guard and triangular solves in the same order as the dynamic step. The
// dynamic code stays for larger np and as the reference.
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>
#include <type_traits>

#include "ctid/adaptation/adaptation.hpp"
#include "ctid/adaptation/covariance_guard.hpp"

namespace ctid {

template <typename S>
class LmrUpdate {
 public:
  // np parameters, forgetting factor lambda, Gamma (symmetric positive
  // semi-definite, see validate_covariance), the guard on R on or off;
  // fixed_size: the compile-time-size step when np <= kMaxFixedParameters
  // (chosen here, once).
  void configure(Eigen::Index np, S lambda, const Matrix<S>& gamma,
                 bool guard = true, bool fixed_size = false) {
    fixed_np_ = fixed_size && np <= kMaxFixedParameters ? int(np) : 0;
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
    if constexpr (std::is_same_v<Derived, Vector<S>>) {
      const S* p = phi.derived().data();
      switch (fixed_np_) {
        case 1:
          return update_fixed<1>(p, target);
        case 2:
          return update_fixed<2>(p, target);
        case 3:
          return update_fixed<3>(p, target);
        case 4:
          return update_fixed<4>(p, target);
        case 5:
          return update_fixed<5>(p, target);
        case 6:
          return update_fixed<6>(p, target);
        case 7:
          return update_fixed<7>(p, target);
        case 8:
          return update_fixed<8>(p, target);
        default:
          break;
      }
    }
    const S error = target - phi.dot(theta_);
    last_ = kGuardNone;
    if (failed_) return error;
    if (lambda_ != S(1)) L_ *= sqrt_lambda_;
    x_ = phi;
    rank_one_update(0);
    for (Eigen::Index c = 0; c < gamma_root_.cols(); ++c) {
      x_ = gamma_root_.col(c);
      rank_one_update(0);
    }
    if (!L_.allFinite()) {
      failed_ = true;
      return error;
    }
    if (guard_) last_ = guard();
    work_ = phi;
    L_.template triangularView<Eigen::Lower>().solveInPlace(work_);
    L_.transpose().template triangularView<Eigen::Upper>().solveInPlace(work_);
    theta_ += work_ * error;
    return error;
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
  // N of the fixed-size step in use, 0 for the dynamic one.
  int fixed_size() const { return fixed_np_; }

 private:
  // The step above for np = N on l[k][i] = L(i, k) (column-major as L_),
  // written back once.
  template <int N>
  S update_fixed(const S* phi_data, S target) {
    S phi[N], theta[N], l[N][N], x[N], w[N];
#pragma GCC unroll 8
    for (int i = 0; i < N; ++i) {
      phi[i] = phi_data[i];
      theta[i] = theta_.data()[i];
    }
    S prediction = 0;
#pragma GCC unroll 8
    for (int i = 0; i < N; ++i) prediction += phi[i] * theta[i];
    const S error = target - prediction;
    last_ = kGuardNone;
    if (failed_) return error;
    const S* L_in = L_.data();
#pragma GCC unroll 8
    for (int k = 0; k < N; ++k) {
#pragma GCC unroll 8
      for (int i = 0; i < N; ++i) l[k][i] = L_in[k * N + i];
    }
    if (lambda_ != S(1)) {
      const S sqrt_lambda = sqrt_lambda_;
#pragma GCC unroll 8
      for (int k = 0; k < N; ++k) {
#pragma GCC unroll 8
        for (int i = 0; i < N; ++i) l[k][i] *= sqrt_lambda;
      }
    }
#pragma GCC unroll 8
    for (int i = 0; i < N; ++i) x[i] = phi[i];
    rank_one_update_fixed<N>(l, x, 0);
    const S* g = gamma_root_.data();
    for (Eigen::Index c = 0; c < gamma_root_.cols(); ++c) {
#pragma GCC unroll 8
      for (int i = 0; i < N; ++i) x[i] = g[c * N + i];
      rank_one_update_fixed<N>(l, x, 0);
    }
    bool finite = true;
#pragma GCC unroll 8
    for (int k = 0; k < N; ++k) {
#pragma GCC unroll 8
      for (int i = 0; i < N; ++i) finite = finite & std::isfinite(l[k][i]);
    }
    S* L_out = L_.data();
#pragma GCC unroll 8
    for (int k = 0; k < N; ++k) {
#pragma GCC unroll 8
      for (int i = 0; i < N; ++i) L_out[k * N + i] = l[k][i];
    }
    if (!finite) {
      failed_ = true;
      return error;
    }
    if (guard_) {
      last_ = guard_fixed<N>(l, x);
      if (last_ != kGuardNone) {
#pragma GCC unroll 8
        for (int k = 0; k < N; ++k) {
#pragma GCC unroll 8
          for (int i = 0; i < N; ++i) L_out[k * N + i] = l[k][i];
        }
      }
    }
    // R^-1 phi: L w = phi forward, then L^T w = w backward.
#pragma GCC unroll 8
    for (int i = 0; i < N; ++i) w[i] = phi[i];
#pragma GCC unroll 8
    for (int k = 0; k < N; ++k) {
      w[k] /= l[k][k];
#pragma GCC unroll 8
      for (int i = k + 1; i < N; ++i) w[i] -= w[k] * l[k][i];
    }
#pragma GCC unroll 8
    for (int k = N - 1; k >= 0; --k) {
      S sum = w[k];
#pragma GCC unroll 8
      for (int i = k + 1; i < N; ++i) sum -= l[k][i] * w[i];
      w[k] = sum / l[k][k];
    }
    S* theta_data = theta_.data();
#pragma GCC unroll 8
    for (int i = 0; i < N; ++i) theta_data[i] = theta[i] + w[i] * error;
    return error;
  }

  // rank_one_update() on l and x.
  template <int N>
  static void rank_one_update_fixed(S (&l)[N][N], S (&x)[N], int first) {
#pragma GCC unroll 8
    for (int k = first; k < N; ++k) {
      const S xk = x[k];
      if (xk == 0) continue;
      const S lkk = l[k][k];
      const S r = std::sqrt(lkk * lkk + xk * xk);
      const S c = lkk / r, s = xk / r;
      l[k][k] = r;
#pragma GCC unroll 8
      for (int i = k + 1; i < N; ++i) {
        const S lik = l[k][i];
        l[k][i] = c * lik + s * x[i];
        x[i] = c * x[i] - s * lik;
      }
    }
  }

  // guard() on l, x as workspace.
  template <int N>
  int guard_fixed(S (&l)[N][N], S (&x)[N]) const {
    int action = kGuardNone;
#pragma GCC unroll 8
    for (int j = 0; j < N; ++j) {
      S rjj = 0;
#pragma GCC unroll 8
      for (int k = 0; k <= j; ++k) rjj += l[k][j] * l[k][j];
      if (rjj > ceiling_) {
        const S e = std::sqrt(ceiling_ / rjj);
        for (int k = 0; k <= j; ++k) l[k][j] *= e;
        rjj = 0;
        for (int k = 0; k <= j; ++k) rjj += l[k][j] * l[k][j];
        action |= kGuardCeiling;
      }
      const S pivot = l[j][j] * l[j][j];
      S delta = 0;
      if (!(pivot > rho_ * rjj)) {
        delta = (10 * rho_ * rjj - pivot) / (1 - 10 * rho_);
      }
      if (rjj < floor_) delta = std::max(delta, floor_ - rjj);
      if (!(delta > 0)) continue;
      for (int i = 0; i < N; ++i) x[i] = 0;
      x[j] = std::sqrt(delta);
      rank_one_update_fixed<N>(l, x, j);
      action |= kGuardRepair;
    }
    return action;
  }

  // L L^T + x x^T, x_ (zero above `first`) consumed: Givens rotations of
  // column k of L against x that zero x_k (LINPACK's dchud), |c|, |s| <= 1
  // whatever the size of x_k against L_kk.
  void rank_one_update(Eigen::Index first) {
    const Eigen::Index n = L_.rows();
    for (Eigen::Index k = first; k < n; ++k) {
      const S xk = x_(k);
      if (xk == 0) continue;
      const S lkk = L_(k, k);
      const S r = std::sqrt(lkk * lkk + xk * xk);
      const S c = lkk / r, s = xk / r;
      L_(k, k) = r;
      for (Eigen::Index i = k + 1; i < n; ++i) {
        const S lik = L_(i, k);
        L_(i, k) = c * lik + s * x_(i);
        x_(i) = c * x_(i) - s * lik;
      }
    }
  }

  int guard() {
    int action = kGuardNone;
    const Eigen::Index n = L_.rows();
    for (Eigen::Index j = 0; j < n; ++j) {
      S rjj = L_.row(j).head(j + 1).squaredNorm();
      if (rjj > ceiling_) {
        L_.row(j).head(j + 1) *= std::sqrt(ceiling_ / rjj);
        rjj = L_.row(j).head(j + 1).squaredNorm();
        action |= kGuardCeiling;
      }
      const S pivot = L_(j, j) * L_(j, j);
      S delta = 0;
      if (!(pivot > rho_ * rjj)) {
        delta = (10 * rho_ * rjj - pivot) / (1 - 10 * rho_);
      }
      if (rjj < floor_) delta = std::max(delta, floor_ - rjj);
      if (!(delta > 0)) continue;
      x_.setZero();
      x_(j) = std::sqrt(delta);
      rank_one_update(j);
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
  bool failed_ = false;
  int last_ = kGuardNone;
  int fixed_np_ = 0;  // N of the fixed-size step, 0: dynamic
};

}  // namespace ctid
