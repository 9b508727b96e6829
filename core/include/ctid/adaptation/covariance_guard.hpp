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
// check of the estimates. Templated on the size (N fixed or
// Eigen::Dynamic) so that fixed-size kernels can hold one; apply_symmetric()
// is apply() unrolled for the fixed-size least-squares step,
// apply_unrolled() for the fixed-size IV step (a P that is not symmetric).
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>

#include "ctid/base/types.hpp"

namespace ctid {

enum CovarianceGuardAction : int {
  kGuardNone = 0,
  kGuardRepair = 1,   // Ps had lost definiteness and was repaired
  kGuardCeiling = 2,  // a variance reached the ceiling
};

template <typename S, int N = Eigen::Dynamic>
class CovarianceGuard {
 public:
  using Mat = Eigen::Matrix<S, N, N>;
  using Vec = Eigen::Matrix<S, N, 1>;

  // n parameters; enabled false: apply() does nothing.
  void configure(Eigen::Index n, bool enabled) {
    enabled_ = enabled;
    n_ = n;
    rho_ = S(n > 0 ? n : 1) * std::numeric_limits<S>::epsilon();
    period_ = std::max<Eigen::Index>(1, n / 6);
    since_check_ = 0;
    work_ = Mat::Zero(n, n);
    pivots_ = Vec::Zero(n);
    v_ = Vec::Zero(n);
    d_ = Vec::Zero(n);
    delta_ = Vec::Zero(n);
    eigen_ = Eigen::SelfAdjointEigenSolver<Mat>(n);
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

  template <typename Derived>
  int apply(Eigen::MatrixBase<Derived>& P) {
    last_ = kGuardNone;
    if (!enabled_ || n_ == 0) return last_;
    bool suspect = false;
    for (Eigen::Index i = 0; i < n_; ++i) {
      const S pii = P(i, i);
      if (!std::isfinite(pii)) return last_;  // the run reports it
      suspect = suspect || !(pii > 0);
      if (pii > ceiling_) {
        const S e = std::sqrt(ceiling_ / pii);
        P.row(i) *= e;
        P.col(i) *= e;
        last_ |= kGuardCeiling;
      }
    }
    for (Eigen::Index j = 0; j < n_ && !suspect; ++j) {
      for (Eigen::Index i = j + 1; i < n_; ++i) {
        const S s = (P(i, j) + P(j, i)) / 2;
        if (!(s * s < P(i, i) * P(j, j))) {
          suspect = true;
          break;
        }
      }
    }
    if (!suspect && ++since_check_ < period_) return last_;
    since_check_ = 0;
    if (!suspect && definite(P)) return last_;
    repair(P);
    last_ |= kGuardRepair;
    return last_;
  }

  // apply() for n = K known at compile time and a P known to be exactly
  // symmetric (the fixed-size least-squares step of adaptation.hpp, which
  // mirrors its lower triangle), whose entries the caller also holds in p
  // (column-major, p[j][i] = P(i, j)): the tests run on p, unrolled, with
  // the factor in local arrays, and reach P only to act on it. The same
  // decisions, counters and repairs as apply(), bit for bit:
  //   - a variance that is not finite, not > 0 or above the ceiling hands
  //     the step to apply() (which returns or acts);
  //   - otherwise the tests read s_ij = P(i, j) where apply() forms
  //     (P(i, j) + P(j, i)) / 2: the same number for a symmetric P (the
  //     sum of two equal numbers and the halving are exact) unless
  //     |P(i, j)| > max / 2, where both fail the correlation test (s^2
  //     overflows) and never reach the factorisation;
  //   - the correlation tests are all evaluated, without branches,
  //     instead of stopping at the first failure: the same verdict.
  template <int K, typename Derived>
  int apply_symmetric(const S (&p)[K][K], Eigen::MatrixBase<Derived>& P) {
    return apply_fixed<K, true>(p, P);
  }

  // apply_symmetric() for any P, symmetric or not (the fixed-size IV step
  // of adaptation.hpp, eqs. 2.29/2.30): the tests read the symmetric part
  // s_ij = (P(i, j) + P(j, i)) / 2 as apply() forms it, the same number
  // by the same operations, so the decisions, counters and repairs are
  // apply()'s, bit for bit.
  template <int K, typename Derived>
  int apply_unrolled(const S (&p)[K][K], Eigen::MatrixBase<Derived>& P) {
    return apply_fixed<K, false>(p, P);
  }

  int last_action() const { return last_; }
  bool enabled() const { return enabled_; }

 private:
  static S range_ceiling() { return std::sqrt(std::numeric_limits<S>::max()); }

  // s_ij of the tests from p (p[j][i] = P(i, j)), i > j: P(i, j) itself
  // when P is known to be symmetric, else (P(i, j) + P(j, i)) / 2.
  template <bool Symmetric, int K>
  static S symmetric_part(const S (&p)[K][K], int i, int j) {
    if constexpr (Symmetric) {
      return p[j][i];
    } else {
      return (p[j][i] + p[i][j]) / 2;
    }
  }

  template <int K, bool Symmetric, typename Derived>
  int apply_fixed(const S (&p)[K][K], Eigen::MatrixBase<Derived>& P) {
    if (!enabled_ || n_ == 0) {
      last_ = kGuardNone;
      return last_;
    }
    bool usual = true;
#pragma GCC unroll 8
    for (int i = 0; i < K; ++i) {
      usual = usual & (p[i][i] > 0) & (p[i][i] <= ceiling_);
    }
    if (!usual) return apply(P);
    last_ = kGuardNone;
    bool suspect = false;
#pragma GCC unroll 8
    for (int j = 0; j < K; ++j) {
#pragma GCC unroll 8
      for (int i = j + 1; i < K; ++i) {
        const S s = symmetric_part<Symmetric>(p, i, j);
        suspect = suspect | !(s * s < p[i][i] * p[j][j]);
      }
    }
    if (!suspect && ++since_check_ < period_) return last_;
    since_check_ = 0;
    if (!suspect && definite_fixed<K, Symmetric>(p)) return last_;
    repair(P);
    last_ |= kGuardRepair;
    return last_;
  }

  // LDL^T of Ps in the lower triangle of work_, each pivot > rho Ps_jj.
  template <typename Derived>
  bool definite(const Eigen::MatrixBase<Derived>& P) {
    for (Eigen::Index j = 0; j < n_; ++j) {
      S dj = P(j, j);
      for (Eigen::Index k = 0; k < j; ++k) {
        v_(k) = work_(j, k) * pivots_(k);
        dj -= work_(j, k) * v_(k);
      }
      if (!(dj > rho_ * P(j, j))) return false;
      pivots_(j) = dj;
      for (Eigen::Index i = j + 1; i < n_; ++i) {
        S lij = (P(i, j) + P(j, i)) / 2;
        for (Eigen::Index k = 0; k < j; ++k) lij -= work_(i, k) * v_(k);
        work_(i, j) = lij / dj;
      }
    }
    return true;
  }

  // definite() on the p of apply_fixed(), the factor in local arrays: the
  // same operations in the same order.
  template <int K, bool Symmetric>
  bool definite_fixed(const S (&p)[K][K]) const {
    S L[K][K], pivots[K], v[K];
#pragma GCC unroll 8
    for (int j = 0; j < K; ++j) {
      S dj = p[j][j];
#pragma GCC unroll 8
      for (int k = 0; k < j; ++k) {
        v[k] = L[j][k] * pivots[k];
        dj -= L[j][k] * v[k];
      }
      if (!(dj > rho_ * p[j][j])) return false;
      pivots[j] = dj;
#pragma GCC unroll 8
      for (int i = j + 1; i < K; ++i) {
        S lij = symmetric_part<Symmetric>(p, i, j);
#pragma GCC unroll 8
        for (int k = 0; k < j; ++k) lij -= L[i][k] * v[k];
        L[i][j] = lij / dj;
      }
    }
    return true;
  }

  // Raises the eigenvalues of C below rho_r to rho_r; adds only the
  // correction to P.
  template <typename Derived>
  void repair(Eigen::MatrixBase<Derived>& P) {
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
    const Vec& lambda = eigen_.eigenvalues();
    const S floor =
        10 * rho_ * std::max(S(1), std::abs(lambda(lambda.size() - 1)));
    for (Eigen::Index k = 0; k < n_; ++k) {
      delta_(k) = lambda(k) < floor ? floor - lambda(k) : S(0);
    }
    const Mat& V = eigen_.eigenvectors();
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
  Mat work_;
  Vec pivots_, v_, d_, delta_;
  Eigen::SelfAdjointEigenSolver<Mat> eigen_;
  int last_ = kGuardNone;
};

}  // namespace ctid
