// SPDX-License-Identifier: BSD-3-Clause
// Copyright (C) the ctid authors
// Protection of the covariance P of the standard-form recursions (RLSSVF,
// eqs. 1.57/1.59, and the IV updates of RIVSVF/RSRIVC/CLRIVSVF/CLRSRIVC,
// eqs. 2.29/2.30) over long runs of poor excitation, as one step after
// each parameter update.
//
// Why. Under a constant input the regressor excites one direction only;
// with forgetting factor 1 the eigenvalue of P in that direction decays as
// 1/k while the round-off of each update does not, and the IV update
// P -= P zeta phi^T P / (offset + phi^T P zeta) has no symmetric form to
// hold it: after a few million samples the symmetric part
// Ps = (P + P^T) / 2 becomes indefinite and the estimates follow it away.
// With a forgetting factor < 1, P grows as lambda^-k in the directions
// the input does not excite (estimator windup, thesis sec. 3.6) until it
// overflows.
//
// What, scale-invariantly: nothing is measured against the trace or a
// norm of P, since P0 may span 1e4..1e20 on its diagonal (thesis sec.
// 4.1, parameters of very different sizes). P is left untouched, bit for
// bit, as long as Ps is positive definite at working precision in its
// correlation form C = D^-1 Ps D^-1, D = sqrt(diag Ps):
//   - every sample, the O(n^2) symptoms: a diagonal entry not > 0, or a
//     correlation |C_ij| >= 1 (Ps_ij^2 >= Ps_ii Ps_jj);
//   - every max(1, n / 6) samples (O(n^2) on average), an LDL^T
//     factorisation of Ps without pivoting, each pivot required to exceed
//     rho Ps_jj, rho = n eps: the pivots of C scaled back, so the test does
//     not depend on the units of the parameters.
// When a test fails, the eigenvalues of C below rho_r = 10 rho
// lambda_max(C) are raised to rho_r and only that correction,
// D V (Lambda' - Lambda) V^T D, is added to P: its antisymmetric part (the
// IV's own) and its positive directions are kept. rho_r above the
// detection level rho leaves a repaired P a margin before the next test.
// C with kappa_2 beyond 1 / (10 n eps) is meaningless in that precision
// anyway, whatever the scaling of P.
// Ceiling: a diagonal entry above sqrt(max) of the precision (1.3e154 in
// double, 1.8e19 in float; or above the largest diagonal entry of P0 if
// that is higher) scales its row and column down to it, P <- E P E with E
// diagonal: a congruence, so C and the definiteness are unchanged, the
// other parameters' variances too, and Ps_ii Ps_jj cannot overflow. This
// bounds the windup of a forgetting factor < 1 at the range of the
// precision, not at a size of P0.
//
// apply() returns what it did (kGuardRepair, kGuardCeiling, both, or
// kGuardNone) and allocates nothing; a non-finite P is left to the run's
// check of the estimates. apply_step<N>() is the same test written once for
// every size (step_size.hpp): the adaptation steps call it on their
// working copy of P, with N their compile-time size or Eigen::Dynamic.
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>

#include "ctid/adaptation/step_size.hpp"
#include "ctid/base/types.hpp"

namespace ctid {

enum CovarianceGuardAction : int {
  kGuardNone = 0,
  kGuardRepair = 1,   // Ps had lost definiteness and was repaired
  kGuardCeiling = 2,  // a variance reached the ceiling
};

template <typename S>
class CovarianceGuard {
 public:
  // n parameters; enabled false: apply() does nothing.
  void configure(Eigen::Index n, bool enabled) {
    enabled_ = enabled;
    n_ = n;
    rho_ = S(n > 0 ? n : 1) * std::numeric_limits<S>::epsilon();
    period_ = std::max<Eigen::Index>(1, n / 6);
    since_check_ = 0;
    work_ = Matrix<S>::Zero(n, n);
    pivots_ = Vector<S>::Zero(n);
    v_ = Vector<S>::Zero(n);
    d_ = Vector<S>::Zero(n);
    delta_ = Vector<S>::Zero(n);
    eigen_ = Eigen::SelfAdjointEigenSolver<Matrix<S>>(n);
    ceiling_ = range_ceiling();
    last_ = kGuardNone;
  }

  // The ceiling never lies below P(t_0)'s largest variance.
  template <typename Derived>
  void reset(const Eigen::MatrixBase<Derived>& P0) {
    ceiling_ = range_ceiling();
    for (Eigen::Index i = 0; i < P0.rows(); ++i) {
      if (std::isfinite(P0(i, i))) ceiling_ = std::max(ceiling_, P0(i, i));
    }
    since_check_ = 0;
    last_ = kGuardNone;
  }

  // The guard on an n-by-n P with column-major storage.
  template <typename Derived>
  int apply(Eigen::PlainObjectBase<Derived>& P) {
    static_assert(!Derived::IsRowMajor, "P is column-major");
    const S* values = P.data();
    return apply_step<Eigen::Dynamic, false>(values, P.data());
  }

  // The guard on P (column-major, n-by-n, P[j * n + i] = P(i, j)) whose
  // entries the caller also holds in `values` (its Working copy, or P
  // itself): the tests read `values`, P is reached only to act on it.
  // Symmetric: P is known to be exactly symmetric (the least-squares steps
  // mirror their lower triangle), so the tests read s_ij = P(i, j) where
  // they otherwise form (P(i, j) + P(j, i)) / 2: the same number (the sum
  // of two equal numbers and the halving are exact) unless |P(i, j)| >
  // max / 2, where both fail the correlation test (s^2 overflows).
  // A variance that is not finite, not > 0 or above the ceiling sends the
  // step to the ceiling's scaling, after which the tests read P. The
  // correlation tests are all evaluated, without branches, instead of
  // stopping at the first failure: the same verdict.
  template <int N, bool Symmetric, typename Values>
  int apply_step(const Values& values, S* P) {
    last_ = kGuardNone;
    if (!enabled_ || n_ == 0) return last_;
    const int n = step_size<N>(n_);
    bool usual = true;
#pragma GCC unroll 8
    for (int i = 0; i < n; ++i) {
      const S pii = values[i * n + i];
      usual = usual & (pii > 0) & (pii <= ceiling_);
    }
    if (usual) return test_and_repair<N, Symmetric>(values, P, false);
    bool suspect = false;
    for (int i = 0; i < n; ++i) {
      const S pii = P[i * n + i];
      if (!std::isfinite(pii)) return last_;  // the run reports it
      suspect = suspect || !(pii > 0);
      if (pii > ceiling_) {
        const S e = std::sqrt(ceiling_ / pii);
        for (int j = 0; j < n; ++j) P[j * n + i] *= e;
        for (int j = 0; j < n; ++j) P[i * n + j] *= e;
        last_ |= kGuardCeiling;
      }
    }
    const S* scaled = P;
    return test_and_repair<N, Symmetric>(scaled, P, suspect);
  }

  int last_action() const { return last_; }
  bool enabled() const { return enabled_; }

 private:
  static S range_ceiling() { return std::sqrt(std::numeric_limits<S>::max()); }

  // s_ij of the tests, i > j.
  template <bool Symmetric, typename Values>
  static S symmetric_part(const Values& p, int n, int i, int j) {
    if constexpr (Symmetric) {
      return p[j * n + i];
    } else {
      return (p[j * n + i] + p[i * n + j]) / 2;
    }
  }

  // The correlation tests every sample, the factorisation every period_
  // samples, the repair when either fails.
  template <int N, bool Symmetric, typename Values>
  int test_and_repair(const Values& p, S* P, bool suspect) {
    const int n = step_size<N>(n_);
#pragma GCC unroll 8
    for (int j = 0; j < n; ++j) {
#pragma GCC unroll 8
      for (int i = j + 1; i < n; ++i) {
        const S s = symmetric_part<Symmetric>(p, n, i, j);
        suspect = suspect | !(s * s < p[i * n + i] * p[j * n + j]);
      }
    }
    if (!suspect && ++since_check_ < period_) return last_;
    since_check_ = 0;
    if (!suspect && definite<N, Symmetric>(p)) return last_;
    repair(P);
    last_ |= kGuardRepair;
    return last_;
  }

  // LDL^T of Ps without pivoting, each pivot > rho Ps_jj; the factor's
  // lower triangle in l (l[k * n + i] = L(i, k)).
  template <int N, bool Symmetric, typename Values>
  bool definite(const Values& p) {
    const int n = step_size<N>(n_);
    Working<S, array_size(N, N)> l(work_.data(), false);
    Working<S, N> pivots(pivots_.data(), false), v(v_.data(), false);
#pragma GCC unroll 8
    for (int j = 0; j < n; ++j) {
      S dj = p[j * n + j];
#pragma GCC unroll 8
      for (int k = 0; k < j; ++k) {
        v[k] = l[k * n + j] * pivots[k];
        dj -= l[k * n + j] * v[k];
      }
      if (!(dj > rho_ * p[j * n + j])) return false;
      pivots[j] = dj;
#pragma GCC unroll 8
      for (int i = j + 1; i < n; ++i) {
        S lij = symmetric_part<Symmetric>(p, n, i, j);
#pragma GCC unroll 8
        for (int k = 0; k < j; ++k) lij -= l[k * n + i] * v[k];
        l[j * n + i] = lij / dj;
      }
    }
    return true;
  }

  // Raises the eigenvalues of C below rho_r to rho_r; adds only the
  // correction to P. Rare: written for the runtime size only.
  void repair(S* data) {
    Eigen::Map<Matrix<S>> P(data, n_, n_);
    S largest = 0;
    for (Eigen::Index i = 0; i < n_; ++i) {
      d_(i) = std::sqrt(std::abs(P(i, i)));
      largest = std::max(largest, d_(i));
    }
    for (Eigen::Index i = 0; i < n_; ++i) {
      if (!(d_(i) > 0)) d_(i) = largest > 0 ? largest : S(1);
    }
    for (Eigen::Index j = 0; j < n_; ++j) {
      for (Eigen::Index i = 0; i < n_; ++i) {
        work_(i, j) = (P(i, j) + P(j, i)) / (2 * d_(i) * d_(j));
      }
    }
    eigen_.compute(work_, Eigen::ComputeEigenvectors);
    const Vector<S>& lambda = eigen_.eigenvalues();
    const S floor =
        10 * rho_ * std::max(S(1), std::abs(lambda(lambda.size() - 1)));
    for (Eigen::Index k = 0; k < n_; ++k) {
      delta_(k) = lambda(k) < floor ? floor - lambda(k) : S(0);
    }
    const Matrix<S>& V = eigen_.eigenvectors();
    for (Eigen::Index k = 0; k < n_; ++k) {
      if (delta_(k) == 0) continue;
      for (Eigen::Index j = 0; j < n_; ++j) {
        const S vj = delta_(k) * V(j, k) * d_(j);
        for (Eigen::Index i = 0; i < n_; ++i) P(i, j) += V(i, k) * d_(i) * vj;
      }
    }
  }

  bool enabled_ = true;
  Eigen::Index n_ = 0;
  S rho_ = 0;
  S ceiling_ = 0;
  Eigen::Index period_ = 1, since_check_ = 0;
  Matrix<S> work_;
  Vector<S> pivots_, v_, d_, delta_;
  Eigen::SelfAdjointEigenSolver<Matrix<S>> eigen_;
  int last_ = kGuardNone;
};

}  // namespace ctid
