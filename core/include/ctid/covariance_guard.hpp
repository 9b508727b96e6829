// Protection of the covariance P of the recursive estimators over long
// runs of poor excitation (thesis sec. 3.6: estimator windup), applied as
// a separate step after each parameter update of the standard form
// (RLSSVF, eqs. 1.57/1.59, and the IV updates, eqs. 2.29/2.30).
//
// Two bounds, on the symmetric part Ps = (P + P^T) / 2:
//
//   floor: the smallest eigenvalue of Ps stays >= rho * trace(Ps), with
//     rho = np * eps of the precision. The IV update P -= P zeta phi^T P /
//     (offset + phi^T P zeta) makes P non-symmetric; under a constant input
//     the smallest eigenvalue of Ps decays as 1/k while the round-off of
//     the update does not, and after a few million samples Ps becomes
//     indefinite. When the Cholesky factorisation of Ps - floor I fails, P
//     is replaced by Ps with its eigenvalues raised to the floor: P gives up
//     its antisymmetric part (the IV's own) at that sample, and its norm
//     does not grow (a shift of P by a multiple of I instead feeds back
//     through the next IV updates and grows P exponentially once the
//     estimates have wound up).
//     rho is a numerical floor, not a regularisation: kappa_2(Ps) above
//     1 / rho is meaningless in that precision anyway.
//   ceiling: with a forgetting factor lambda < 1, P grows as lambda^-k in
//     the directions the input does not excite, until it overflows
//     (sec. 3.6). trace(Ps) is held at trace(P(t_0)) at most: P is scaled
//     down when it exceeds it, so P never claims more uncertainty than the
//     start did. The Kalman filter's P grows only linearly (k Qn, its
//     random-walk model) and gets no ceiling.
//
// apply() reports what it did (kFloor, kCeiling, both, or none), which the
// estimators pass on per sample (info.covariance_guard of the
// front-ends). No allocation in apply() after configure().
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>

#include "ctid/types.hpp"

namespace ctid {

enum CovarianceGuardAction : int { kGuardNone = 0, kGuardFloor = 1,
                                   kGuardCeiling = 2 };

template <typename S>
class CovarianceGuard {
 public:
  // ceiling_trace: the largest trace(Ps) allowed; 0 for no ceiling.
  void configure(Eigen::Index np, S ceiling_trace) {
    ceiling_ = ceiling_trace;
    rho_ = S(np > 0 ? np : 1) * std::numeric_limits<S>::epsilon();
    sym_ = Matrix<S>::Zero(np, np);
    clipped_ = Vector<S>::Zero(np);
    llt_ = Eigen::LLT<Matrix<S>>(np);
    eigen_ = Eigen::SelfAdjointEigenSolver<Matrix<S>>(np);
    last_ = kGuardNone;
  }

  int apply(Matrix<S>& P) {
    last_ = kGuardNone;
    if (P.size() == 0 || !P.allFinite()) return last_;  // the run reports
    sym_ = P;
    sym_ += P.transpose();
    sym_ *= S(0.5);
    S trace = sym_.trace();
    if (ceiling_ > 0 && trace > ceiling_) {
      const S c = ceiling_ / trace;
      P *= c;
      sym_ *= c;
      trace = ceiling_;
      last_ |= kGuardCeiling;
    }
    const S floor = rho_ * std::abs(trace);
    sym_.diagonal().array() -= floor;
    llt_.compute(sym_);
    if (llt_.info() != Eigen::Success) {
      sym_.diagonal().array() += floor;
      eigen_.compute(sym_, Eigen::ComputeEigenvectors);
      const auto& lambda = eigen_.eigenvalues();
      const S top = std::max(std::abs(lambda(0)),
                             std::abs(lambda(lambda.size() - 1)));
      const S target = std::max(floor, rho_ * top);
      clipped_ = lambda.cwiseMax(target);
      const Matrix<S>& V = eigen_.eigenvectors();
      P.noalias() = V * clipped_.asDiagonal() * V.transpose();
      last_ |= kGuardFloor;
    }
    return last_;
  }

  int last_action() const { return last_; }

 private:
  S ceiling_ = 0;
  S rho_ = 0;
  Matrix<S> sym_;
  Vector<S> clipped_;
  Eigen::LLT<Matrix<S>> llt_;
  Eigen::SelfAdjointEigenSolver<Matrix<S>> eigen_;
  int last_ = kGuardNone;
};

}  // namespace ctid
