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
// estimate. P = R^-1, so kappa_2(P) = kappa_2(R). R is refactorised by
// Cholesky every step (the matrix inversion the thesis mentions); nothing is
// allocated per step.
#pragma once

#include "ctid/adaptation/adaptation.hpp"

namespace ctid {

template <typename S>
class LmrUpdate {
 public:
  void configure(Eigen::Index np, S lambda, const Matrix<S>& gamma) {
    lambda_ = lambda;
    gamma_ = (gamma + gamma.transpose()) / 2;
    theta_ = Vector<S>::Zero(np);
    R_ = Matrix<S>::Identity(np, np);
    P_ = Matrix<S>::Identity(np, np);
    work_ = Vector<S>::Zero(np);
    llt_ = Eigen::LLT<Matrix<S>>(np);
  }

  // R(t_0) = P0^-1 (P0 positive definite, see validate_covariance).
  void reset(const Vector<S>& theta0, const Matrix<S>& P0) {
    theta_ = theta0;
    const Eigen::Index np = P0.rows();
    R_ = Eigen::LLT<Matrix<S>>(P0).solve(Matrix<S>::Identity(np, np));
    R_ = (R_ + R_.transpose()) / 2;
    failed_ = false;
  }

  // One LMR-RLSSVF step (3.82). Returns the prediction error (3.82c). When
  // R loses positive definiteness (rounding), the estimate is kept and
  // failed() turns true.
  template <typename Derived>
  S update(const Eigen::MatrixBase<Derived>& phi, S target) {
    const S error = target - phi.dot(theta_);
    R_ *= lambda_;
    R_.template selfadjointView<Eigen::Lower>().rankUpdate(phi, S(1));
    if (lambda_ != S(1)) R_.noalias() += (1 - lambda_) * gamma_;
    for (Eigen::Index j = 1; j < R_.cols(); ++j) {
      for (Eigen::Index i = 0; i < j; ++i) R_(i, j) = R_(j, i);
    }
    llt_.compute(R_);
    if (llt_.info() != Eigen::Success) {
      failed_ = true;
      return error;
    }
    work_ = phi;
    llt_.solveInPlace(work_);
    theta_ += work_ * error;
    return error;
  }

  const Vector<S>& theta() const { return theta_; }
  const Matrix<S>& information() const { return R_; }
  // P(t_k) = R(t_k)^-1, formed on request.
  const Matrix<S>& P() const {
    const Eigen::Index np = R_.rows();
    P_ = Eigen::LLT<Matrix<S>>(R_).solve(Matrix<S>::Identity(np, np));
    P_ = (P_ + P_.transpose()) / 2;
    return P_;
  }
  S condition_number() const { return ctid::condition_number<S>(R_); }
  bool failed() const { return failed_; }

 private:
  S lambda_ = 1;
  Matrix<S> gamma_;
  Vector<S> theta_;
  Matrix<S> R_;
  mutable Matrix<S> P_;
  Vector<S> work_;
  Eigen::LLT<Matrix<S>> llt_;
  bool failed_ = false;
};

}  // namespace ctid
