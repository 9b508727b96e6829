// Adaptation mechanisms for the time-varying parameters, as
// interchangeable parts of every recursive estimator:
//
//   ForgettingFactorAdaptation: exponential forgetting, RLSSVF-FF
//     eq. (1.57) and its IV form eq. (2.30);
//   KalmanAdaptation: random-walk parameters with normalised covariance
//     Qn = Qw / sigma_e^2 (eq. 1.46), RLSSVF-KF eq. (1.59) and the IV-based
//     Kalman filter eq. (2.29).
//
// ParameterUpdate holds theta and P and applies one correction step
//   L   = P- zeta / (offset + phi^T P- zeta)
//   theta = theta + L (target - phi^T theta)
//   P   = scale (P- - L phi^T P-)
// with P- = P (+ Qn for the Kalman filter), offset = lambda or 1 and
// scale = 1/lambda or 1. zeta = phi gives the least-squares form; its
// covariance update is done as a symmetric rank-one update so that P stays
// exactly symmetric. No allocation happens in update().
#pragma once

#include <cmath>
#include <limits>
#include <string>
#include <type_traits>
#include <variant>

#include "ctid/status.hpp"
#include "ctid/types.hpp"

namespace ctid {

template <typename S>
class ForgettingFactorAdaptation {
 public:
  explicit ForgettingFactorAdaptation(S lambda = 1) : lambda_(lambda) {}
  void predict(Matrix<S>& /*P*/) const {}
  S gain_offset() const { return lambda_; }
  S covariance_scale() const { return S(1) / lambda_; }
  S lambda() const { return lambda_; }

 private:
  S lambda_;
};

template <typename S>
class KalmanAdaptation {
 public:
  KalmanAdaptation() = default;
  // Qn is symmetrised so that P stays exactly symmetric.
  explicit KalmanAdaptation(const Matrix<S>& qn)
      : qn_((qn + qn.transpose()) / 2) {}
  void predict(Matrix<S>& P) const { P += qn_; }
  S gain_offset() const { return 1; }
  S covariance_scale() const { return 1; }
  const Matrix<S>& qn() const { return qn_; }

 private:
  Matrix<S> qn_;
};

template <typename S>
using Adaptation =
    std::variant<ForgettingFactorAdaptation<S>, KalmanAdaptation<S>>;

// Forgetting factor in (0, 1].
template <typename S>
Status validate_forgetting_factor(S lambda) {
  if (!(lambda > 0 && lambda <= 1)) {
    return bad_input("the forgetting factor must lie in (0, 1], got " +
                     std::to_string(static_cast<double>(lambda)));
  }
  return Status::Ok();
}

// A symmetric positive semi-definite np-by-np matrix with finite entries
// (used for Qn and P0). `what` names the argument in the message.
template <typename S>
Status validate_covariance(const Matrix<S>& M, Eigen::Index np,
                           const std::string& what, bool require_definite) {
  if (M.rows() != np || M.cols() != np) {
    return dimension_mismatch(
        what + " must be " + std::to_string(np) + "-by-" + std::to_string(np) +
        " (one row and column per parameter), got " + std::to_string(M.rows()) +
        "-by-" + std::to_string(M.cols()));
  }
  if (!M.allFinite()) return bad_input(what + " must be finite");
  const S scale = M.cwiseAbs().maxCoeff();
  const S tolerance = 1000 * std::numeric_limits<S>::epsilon() * scale;
  if ((M - M.transpose()).cwiseAbs().maxCoeff() > tolerance) {
    return bad_input(what + " must be symmetric");
  }
  if (np == 0) return Status::Ok();
  if (require_definite) {
    // Cholesky decides: a P0 whose diagonal spans many decades (parameters
    // of very different sizes, thesis sec. 4.1) is positive definite even
    // when its smallest eigenvalue is below eps times its largest.
    const Eigen::LLT<Matrix<S>> llt((M + M.transpose()) / 2);
    if (llt.info() != Eigen::Success || !(M.diagonal().array() > 0).all()) {
      return bad_input(what + " must be positive definite");
    }
    return Status::Ok();
  }
  const Eigen::SelfAdjointEigenSolver<Matrix<S>> eig(M);
  if (eig.eigenvalues().minCoeff() < -tolerance) {
    return bad_input(what + " must be positive semi-definite");
  }
  return Status::Ok();
}

// Spectral condition number kappa_2(P) = lambda_max / lambda_min of a
// symmetric positive definite matrix (thesis eq. 3.68 compares it with that
// of a square root). Infinity when P is not positive definite.
template <typename S>
S condition_number(const Matrix<S>& P) {
  if (P.size() == 0) return S(1);
  const Eigen::SelfAdjointEigenSolver<Matrix<S>> eig(P, Eigen::EigenvaluesOnly);
  const S smallest = eig.eigenvalues()(0);
  const S largest = eig.eigenvalues()(P.rows() - 1);
  if (!(smallest > 0)) return std::numeric_limits<S>::infinity();
  return largest / smallest;
}

// kappa_2(P) as reported after each recursion: for a symmetric P (the
// least-squares updates) the eigenvalue ratio, infinite once P has lost
// positive definiteness; for the non-symmetric P of the IV updates the
// ratio of extreme singular values.
template <typename S>
S kappa_2(const Matrix<S>& P) {
  if (P == P.transpose()) return condition_number(P);
  const Eigen::JacobiSVD<Matrix<S>> svd(P);
  const auto& sv = svd.singularValues();
  if (!(sv(sv.size() - 1) > 0)) return std::numeric_limits<S>::infinity();
  return sv(0) / sv(sv.size() - 1);
}

// The same for the fixed-size kernels (formed on request, not per sample
// unless asked for).
template <typename S, int N, std::enable_if_t<N != Eigen::Dynamic, int> = 0>
S condition_number(const MatrixN<S, N>& P) {
  return condition_number<S>(Matrix<S>(P));
}
template <typename S, int N, std::enable_if_t<N != Eigen::Dynamic, int> = 0>
S kappa_2(const MatrixN<S, N>& P) {
  return kappa_2<S>(Matrix<S>(P));
}

// NP: the number of parameters when known at compile time (fixed_size.hpp),
// Eigen::Dynamic for the general path. The adaptation is read once, in
// configure(): per step only its offset, scale and Qn are used.
template <typename S, int NP = Eigen::Dynamic>
class ParameterUpdate {
 public:
  using Vec = VectorN<S, NP>;
  using Mat = MatrixN<S, NP>;

  ParameterUpdate() = default;
  ParameterUpdate(Eigen::Index np, Adaptation<S> adaptation) {
    configure(np, std::move(adaptation));
  }

  void configure(Eigen::Index np, Adaptation<S> adaptation) {
    adaptation_ = std::move(adaptation);
    theta_ = Vec::Zero(np);
    P_ = Mat::Identity(np, np);
    p_zeta_ = Vec::Zero(np);
    pt_phi_ = Vec::Zero(np);
    gain_ = Vec::Zero(np);
    offset_ = std::visit([](const auto& a) { return a.gain_offset(); },
                         adaptation_);
    scale_ = std::visit([](const auto& a) { return a.covariance_scale(); },
                        adaptation_);
    const auto* kf = std::get_if<KalmanAdaptation<S>>(&adaptation_);
    has_qn_ = kf != nullptr && kf->qn().size() != 0;
    qn_ = has_qn_ ? Mat(kf->qn()) : Mat::Zero(np, np);
  }

  template <typename D1, typename D2>
  void reset(const Eigen::MatrixBase<D1>& theta0,
             const Eigen::MatrixBase<D2>& P0) {
    theta_ = theta0;
    P_ = P0;
  }

  // Least-squares step (zeta = phi). Returns the prediction error
  // target - phi^T theta(t_(k-1)), eq. (1.55).
  template <typename Derived>
  S update(const Eigen::MatrixBase<Derived>& phi, S target) {
    predict();
    const S error = target - phi.dot(theta_);
    p_zeta_.noalias() = P_ * phi;
    const S denominator = offset_ + phi.dot(p_zeta_);
    innovation_scale_ = denominator;
    gain_ = p_zeta_ / denominator;
    theta_ += gain_ * error;
    // P -= (P phi)(P phi)^T / den on the lower triangle, mirrored: P stays
    // exactly symmetric.
    P_.template selfadjointView<Eigen::Lower>().rankUpdate(p_zeta_,
                                                           -1 / denominator);
    for (Eigen::Index j = 1; j < P_.cols(); ++j) {
      for (Eigen::Index i = 0; i < j; ++i) P_(i, j) = P_(j, i);
    }
    scale_covariance();
    return error;
  }

  // Instrumental-variable step, eqs. (2.29) and (2.30).
  template <typename D1, typename D2>
  S update(const Eigen::MatrixBase<D1>& phi, const Eigen::MatrixBase<D2>& zeta,
           S target) {
    predict();
    const S error = target - phi.dot(theta_);
    p_zeta_.noalias() = P_ * zeta;
    pt_phi_.noalias() = P_.transpose() * phi;
    const S denominator = offset_ + phi.dot(p_zeta_);
    innovation_scale_ = denominator;
    gain_ = p_zeta_ / denominator;
    theta_ += gain_ * error;
    P_.noalias() -= gain_ * pt_phi_.transpose();
    scale_covariance();
    return error;
  }

  const Vec& theta() const { return theta_; }
  // The gain denominator of the last step, lambda (or 1) + phi^T P^- zeta:
  // for the least-squares Kalman filter the variance of the prediction error
  // over sigma_e^2, r(t_k) / sigma_e^2 of eq. (3.18)/(3.25); for the IV
  // update the quantity RSRIVC computes in its place.
  S innovation_scale() const { return innovation_scale_; }
  // Gain L(t_k) of the last step.
  const Vec& gain() const { return gain_; }
  const Mat& P() const { return P_; }
  const Adaptation<S>& adaptation() const { return adaptation_; }

 private:
  void predict() {
    if (has_qn_) P_ += qn_;
  }
  void scale_covariance() {
    if (scale_ != S(1)) P_ *= scale_;
  }

  Adaptation<S> adaptation_;
  S offset_ = 1;  // lambda (forgetting factor) or 1
  S scale_ = 1;   // 1 / lambda or 1
  bool has_qn_ = false;
  Mat qn_;
  Vec theta_;
  Mat P_;
  Vec p_zeta_;
  Vec pt_phi_;
  Vec gain_;
  S innovation_scale_ = 1;
};

}  // namespace ctid
