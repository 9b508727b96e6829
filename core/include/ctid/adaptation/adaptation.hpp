// SPDX-License-Identifier: BSD-3-Clause
// Copyright (C) the ctid authors
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
// exactly symmetric. After each step the covariance protection of
// covariance_guard.hpp checks P when asked (the estimators' default). No
// allocation happens in update().
//
// Fixed-size path: configured with fixed_size = true and
// np <= kMaxFixedParameters (the parameter counts orders 1-4 produce), each
// step runs on compile-time-size maps of the same storage
// (theta, P, Qn), with lambda and the adaptation kind read once at
// configure instead of through the variant every sample. The arithmetic is
// that of the dynamic step, in the same order; the guard is applied to the
// same P by the same object, so it acts exactly as on the dynamic path.
// The instrumental-variable step (2.29)/(2.30) has its fixed-size form
// too (update_fixed_iv), with the guard's unrolled test of a P that is not
// symmetric. The dynamic code stays for larger np and as the reference.
// The guard runs its tests with n = N at compile time.
#pragma once

#include <cmath>
#include <limits>
#include <string>
#include <type_traits>
#include <variant>

#include "ctid/adaptation/covariance_guard.hpp"
#include "ctid/base/status.hpp"
#include "ctid/base/types.hpp"

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

// Largest parameter count of the fixed-size least-squares step: na = 4,
// nb = 4.
constexpr int kMaxFixedParameters = 8;

template <typename S>
class ParameterUpdate {
 public:
  ParameterUpdate() = default;
  ParameterUpdate(Eigen::Index np, Adaptation<S> adaptation,
                  bool covariance_guard = false, bool fixed_size = false) {
    configure(np, std::move(adaptation), covariance_guard, fixed_size);
  }

  // covariance_guard: the protection of P (covariance_guard.hpp) after
  // each step. Off in the bare kernel, which keeps the exact identities
  // of eqs. (2.29)/(2.30) (an IV P whose symmetric part is indefinite
  // because the instruments are weakly correlated with the regressors is
  // legitimate, and the guard would change it); the estimators
  // (LeastSquaresUpdate: RLSSVF, RIVSVF, RSRIVC, CL*) turn it on by
  // default through their configs.
  // fixed_size: the compile-time-size least-squares and IV steps when
  // np <= kMaxFixedParameters (chosen here, once).
  void configure(Eigen::Index np, Adaptation<S> adaptation,
                 bool covariance_guard = false, bool fixed_size = false) {
    adaptation_ = std::move(adaptation);
    fixed_np_ = fixed_size && np <= kMaxFixedParameters ? int(np) : 0;
    kalman_ = std::holds_alternative<KalmanAdaptation<S>>(adaptation_);
    offset_ = offset();
    scale_ = std::visit([](const auto& a) { return a.covariance_scale(); },
                        adaptation_);
    guard_.configure(np, covariance_guard);
    theta_ = Vector<S>::Zero(np);
    P_ = Matrix<S>::Identity(np, np);
    p_zeta_ = Vector<S>::Zero(np);
    pt_phi_ = Vector<S>::Zero(np);
    gain_ = Vector<S>::Zero(np);
  }

  void reset(const Vector<S>& theta0, const Matrix<S>& P0) {
    theta_ = theta0;
    P_ = P0;
    guard_.reset(P_);
  }

  // Puts back an earlier estimate and leaves P as it is: a step whose
  // estimate failed a stability test is not accepted (thesis eq. 3.10,
  // "keep the last stable one").
  void set_theta(const Vector<S>& theta) { theta_ = theta; }

  // Least-squares step (zeta = phi). Returns the prediction error
  // target - phi^T theta(t_(k-1)), eq. (1.55).
  template <typename Derived>
  S update(const Eigen::MatrixBase<Derived>& phi, S target) {
    if constexpr (std::is_same_v<Derived, Vector<S>>) {
      switch (fixed_np_) {
        case 1:
          return update_fixed<1>(phi.derived().data(), target);
        case 2:
          return update_fixed<2>(phi.derived().data(), target);
        case 3:
          return update_fixed<3>(phi.derived().data(), target);
        case 4:
          return update_fixed<4>(phi.derived().data(), target);
        case 5:
          return update_fixed<5>(phi.derived().data(), target);
        case 6:
          return update_fixed<6>(phi.derived().data(), target);
        case 7:
          return update_fixed<7>(phi.derived().data(), target);
        case 8:
          return update_fixed<8>(phi.derived().data(), target);
        default:
          break;
      }
    }
    predict();
    const S error = target - phi.dot(theta_);
    p_zeta_.noalias() = P_ * phi;
    const S denominator = offset() + phi.dot(p_zeta_);
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
    guard_.apply(P_);
    return error;
  }

  // Instrumental-variable step, eqs. (2.29) and (2.30).
  template <typename D1, typename D2>
  S update(const Eigen::MatrixBase<D1>& phi, const Eigen::MatrixBase<D2>& zeta,
           S target) {
    if constexpr (std::is_same_v<D1, Vector<S>> &&
                  std::is_same_v<D2, Vector<S>>) {
      const S* p = phi.derived().data();
      const S* z = zeta.derived().data();
      switch (fixed_np_) {
        case 1:
          return update_fixed_iv<1>(p, z, target);
        case 2:
          return update_fixed_iv<2>(p, z, target);
        case 3:
          return update_fixed_iv<3>(p, z, target);
        case 4:
          return update_fixed_iv<4>(p, z, target);
        case 5:
          return update_fixed_iv<5>(p, z, target);
        case 6:
          return update_fixed_iv<6>(p, z, target);
        case 7:
          return update_fixed_iv<7>(p, z, target);
        case 8:
          return update_fixed_iv<8>(p, z, target);
        default:
          break;
      }
    }
    predict();
    const S error = target - phi.dot(theta_);
    p_zeta_.noalias() = P_ * zeta;
    pt_phi_.noalias() = P_.transpose() * phi;
    const S denominator = offset() + phi.dot(p_zeta_);
    innovation_scale_ = denominator;
    gain_ = p_zeta_ / denominator;
    theta_ += gain_ * error;
    P_.noalias() -= gain_ * pt_phi_.transpose();
    scale_covariance();
    guard_.apply(P_);
    return error;
  }

  const Vector<S>& theta() const { return theta_; }
  // The gain denominator of the last step, lambda (or 1) + phi^T P^- zeta:
  // for the least-squares Kalman filter the variance of the prediction error
  // over sigma_e^2, r(t_k) / sigma_e^2 of eq. (3.18)/(3.25); for the IV
  // update the quantity RSRIVC computes in its place.
  S innovation_scale() const { return innovation_scale_; }
  // Gain L(t_k) of the last step.
  const Vector<S>& gain() const { return gain_; }
  const Matrix<S>& P() const { return P_; }
  const Adaptation<S>& adaptation() const { return adaptation_; }
  // What the covariance protection did to P at the last step (a
  // CovarianceGuardAction mask).
  int covariance_guard() const { return guard_.last_action(); }
  // N of the fixed-size step in use, 0 for the dynamic one.
  int fixed_size() const { return fixed_np_; }

 private:
  // The least-squares step above for np = N, unrolled scalar code on local
  // copies of phi, theta and P (P column-major as P_: p[j][i] = P(i, j)),
  // written back once: through the members' storage every store would make
  // the compiler reload the rest (all of it S*), and Eigen's packet copies
  // of these small objects reload, 16 bytes at a time, values just stored
  // 8 bytes at a time, which stalls store forwarding. The same operations
  // as the dynamic step, the sums in the order of its products; the guard
  // then tests the stored P with n = N fixed (covariance_guard.hpp).
  template <int N>
  S update_fixed(const S* phi_data, S target) {
    S phi[N], theta[N], p[N][N], pz[N], gain[N];
#pragma GCC unroll 8
    for (int i = 0; i < N; ++i) {
      phi[i] = phi_data[i];
      theta[i] = theta_.data()[i];
    }
    load_fixed<N>(p);
    S prediction = 0;
#pragma GCC unroll 8
    for (int i = 0; i < N; ++i) prediction += phi[i] * theta[i];
    const S error = target - prediction;
    // P- phi, column by column.
#pragma GCC unroll 8
    for (int i = 0; i < N; ++i) pz[i] = p[0][i] * phi[0];
#pragma GCC unroll 8
    for (int j = 1; j < N; ++j) {
#pragma GCC unroll 8
      for (int i = 0; i < N; ++i) pz[i] += p[j][i] * phi[j];
    }
    S phi_pz = 0;
#pragma GCC unroll 8
    for (int i = 0; i < N; ++i) phi_pz += phi[i] * pz[i];
    const S denominator = offset_ + phi_pz;
    innovation_scale_ = denominator;
    // One division instead of N + 1: the gain is pz times 1/den, within
    // one rounding of the dynamic step's pz / den; P's update below uses
    // the same -1/den as there, so P, all the guard sees, is unchanged.
    const S inverse = 1 / denominator;
#pragma GCC unroll 8
    for (int i = 0; i < N; ++i) {
      gain[i] = pz[i] * inverse;
      theta[i] += gain[i] * error;
    }
    // Lower triangle column by column as rankUpdate does, then mirrored.
    const S alpha = -inverse;
#pragma GCC unroll 8
    for (int j = 0; j < N; ++j) {
      const S a = alpha * pz[j];
#pragma GCC unroll 8
      for (int i = j; i < N; ++i) p[j][i] += a * pz[i];
    }
#pragma GCC unroll 8
    for (int j = 1; j < N; ++j) {
#pragma GCC unroll 8
      for (int i = 0; i < j; ++i) p[j][i] = p[i][j];
    }
    Eigen::Map<Eigen::Matrix<S, N, N>> P(store_fixed<N>(p, theta, gain));
    guard_.template apply_symmetric<N>(p, P);
    return error;
  }

  // The IV step above for np = N, in the manner of update_fixed(): local
  // copies written back once, the products in the order of the dynamic
  // step's (P zeta and P^T phi column by column, the outer product entry
  // by entry), the gain by division as there, so that P, theta and what
  // the guard sees differ from the dynamic step's by the rounding of the
  // sums only. P is not symmetric: the guard's unrolled test forms its
  // symmetric part as apply() does (covariance_guard.hpp).
  template <int N>
  S update_fixed_iv(const S* phi_data, const S* zeta_data, S target) {
    S phi[N], zeta[N], theta[N], p[N][N], pz[N], ptphi[N], gain[N];
#pragma GCC unroll 8
    for (int i = 0; i < N; ++i) {
      phi[i] = phi_data[i];
      zeta[i] = zeta_data[i];
      theta[i] = theta_.data()[i];
    }
    load_fixed<N>(p);
    S prediction = 0;
#pragma GCC unroll 8
    for (int i = 0; i < N; ++i) prediction += phi[i] * theta[i];
    const S error = target - prediction;
    // P- zeta, column by column; P-^T phi, a dot product per column.
#pragma GCC unroll 8
    for (int i = 0; i < N; ++i) pz[i] = p[0][i] * zeta[0];
#pragma GCC unroll 8
    for (int j = 1; j < N; ++j) {
#pragma GCC unroll 8
      for (int i = 0; i < N; ++i) pz[i] += p[j][i] * zeta[j];
    }
#pragma GCC unroll 8
    for (int j = 0; j < N; ++j) {
      S sum = 0;
#pragma GCC unroll 8
      for (int i = 0; i < N; ++i) sum += p[j][i] * phi[i];
      ptphi[j] = sum;
    }
    S phi_pz = 0;
#pragma GCC unroll 8
    for (int i = 0; i < N; ++i) phi_pz += phi[i] * pz[i];
    const S denominator = offset_ + phi_pz;
    innovation_scale_ = denominator;
#pragma GCC unroll 8
    for (int i = 0; i < N; ++i) {
      gain[i] = pz[i] / denominator;
      theta[i] += gain[i] * error;
    }
    // P- - L (P-^T phi)^T, eq. (2.29c)/(2.30c).
#pragma GCC unroll 8
    for (int j = 0; j < N; ++j) {
#pragma GCC unroll 8
      for (int i = 0; i < N; ++i) p[j][i] -= gain[i] * ptphi[j];
    }
    Eigen::Map<Eigen::Matrix<S, N, N>> P(store_fixed<N>(p, theta, gain));
    guard_.template apply_unrolled<N>(p, P);
    return error;
  }

  // The fixed-size steps' local copies: P (plus Qn for the Kalman filter,
  // P- = P + Qn) read once, and P scaled (the forgetting factor), theta and
  // the gain written back once; returns P's storage for the guard.
  template <int N>
  void load_fixed(S (&p)[N][N]) const {
    const S* P_in = P_.data();
#pragma GCC unroll 8
    for (int j = 0; j < N; ++j) {
#pragma GCC unroll 8
      for (int i = 0; i < N; ++i) p[j][i] = P_in[j * N + i];
    }
    if (kalman_) {  // P- = P + Qn
      const S* qn = std::get_if<KalmanAdaptation<S>>(&adaptation_)->qn().data();
#pragma GCC unroll 8
      for (int j = 0; j < N; ++j) {
#pragma GCC unroll 8
        for (int i = 0; i < N; ++i) p[j][i] += qn[j * N + i];
      }
    }
  }
  template <int N>
  S* store_fixed(S (&p)[N][N], const S (&theta)[N], const S (&gain)[N]) {
    const S scale = scale_;  // read once: the stores below may alias it
    if (scale != S(1)) {
#pragma GCC unroll 8
      for (int j = 0; j < N; ++j) {
#pragma GCC unroll 8
        for (int i = 0; i < N; ++i) p[j][i] *= scale;
      }
    }
    S* P_data = P_.data();
#pragma GCC unroll 8
    for (int j = 0; j < N; ++j) {
#pragma GCC unroll 8
      for (int i = 0; i < N; ++i) P_data[j * N + i] = p[j][i];
    }
    S* theta_data = theta_.data();
    S* gain_data = gain_.data();
#pragma GCC unroll 8
    for (int i = 0; i < N; ++i) {
      theta_data[i] = theta[i];
      gain_data[i] = gain[i];
    }
    return P_data;
  }

  void predict() {
    std::visit([this](const auto& a) { a.predict(P_); }, adaptation_);
  }
  S offset() const {
    return std::visit([](const auto& a) { return a.gain_offset(); },
                      adaptation_);
  }
  void scale_covariance() {
    const S scale = std::visit(
        [](const auto& a) { return a.covariance_scale(); }, adaptation_);
    if (scale != S(1)) P_ *= scale;
  }

  Adaptation<S> adaptation_;
  Vector<S> theta_;
  Matrix<S> P_;
  Vector<S> p_zeta_;
  Vector<S> pt_phi_;
  Vector<S> gain_;
  S innovation_scale_ = 1;
  CovarianceGuard<S> guard_;
  int fixed_np_ = 0;  // N of the fixed-size step, 0: dynamic
  bool kalman_ = false;
  S offset_ = 1;
  S scale_ = 1;
};

}  // namespace ctid
