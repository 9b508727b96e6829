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
// Each step is written once, as a template on the parameter count
// (step_size.hpp): configured with fixed_size = true and np <=
// kMaxFixedParameters (the parameter counts orders 1-4 produce) it runs at
// compile-time size np, on local copies of theta and P written back once,
// with lambda and the adaptation kind read once at configure; otherwise at
// runtime size on the storage itself. The choice is made once, in
// configure().
#pragma once

#include <cmath>
#include <limits>
#include <string>
#include <type_traits>
#include <variant>

#include "ctid/adaptation/covariance_guard.hpp"
#include "ctid/adaptation/step_size.hpp"
#include "ctid/base/small_products.hpp"
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
  // fixed_size: the steps at compile-time size np when np <=
  // kMaxFixedParameters (chosen here, once; step_size.hpp).
  void configure(Eigen::Index np, Adaptation<S> adaptation,
                 bool covariance_guard = false, bool fixed_size = false) {
    adaptation_ = std::move(adaptation);
    fixed_np_ = fixed_step_size(np, fixed_size);
    least_squares_step_ = select_size(np, fixed_size, [](auto size) {
      return &ParameterUpdate::least_squares_step<decltype(size)::value>;
    });
    iv_step_ = select_size(np, fixed_size, [](auto size) {
      return &ParameterUpdate::iv_step<decltype(size)::value>;
    });
    kalman_ = std::holds_alternative<KalmanAdaptation<S>>(adaptation_);
    offset_ =
        std::visit([](const auto& a) { return a.gain_offset(); }, adaptation_);
    scale_ = std::visit([](const auto& a) { return a.covariance_scale(); },
                        adaptation_);
    guard_.configure(np, covariance_guard);
    theta_ = Vector<S>::Zero(np);
    P_ = Matrix<S>::Identity(np, np);
    p_zeta_ = Vector<S>::Zero(np);
    pt_phi_ = Vector<S>::Zero(np);
    gain_ = Vector<S>::Zero(np);
    phi_copy_ = Vector<S>::Zero(np);
    zeta_copy_ = Vector<S>::Zero(np);
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
    return (this->*least_squares_step_)(contiguous(phi, phi_copy_), target);
  }

  // Instrumental-variable step, eqs. (2.29) and (2.30).
  template <typename D1, typename D2>
  S update(const Eigen::MatrixBase<D1>& phi, const Eigen::MatrixBase<D2>& zeta,
           S target) {
    return (this->*iv_step_)(contiguous(phi, phi_copy_),
                             contiguous(zeta, zeta_copy_), target);
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
  // N of the compile-time-size steps in use, 0 for the runtime-size ones.
  int fixed_size() const { return fixed_np_; }

 private:
  using Step = S (ParameterUpdate::*)(const S*, S);
  using IvStep = S (ParameterUpdate::*)(const S*, const S*, S);

  // The least-squares step for np = N (step_size.hpp), P column-major
  // (p[j * n + i] = P(i, j)). P's update is a symmetric rank-one update
  // of the lower triangle, mirrored, so that P stays exactly symmetric,
  // and the guard tests it as such.
  template <int N>
  S least_squares_step(const S* phi, S target) {
    const int n = step_size<N>(theta_.size());
    Working<S, N> theta(theta_.data(), true);
    Working<S, N> pz(p_zeta_.data(), false), gain(gain_.data(), false);
    Working<S, array_size(N, N)> p(P_.data(), true);
    predict<N>(p);
    const S error = target - dot<N>(phi, theta);
    multiply(n, p, phi, pz);  // P- phi
    const S denominator = offset_ + dot<N>(phi, pz);
    // One division: the gain is pz times 1/den, the same -1/den as P's
    // update.
    const S inverse = 1 / denominator;
#pragma GCC unroll 8
    for (int i = 0; i < n; ++i) {
      gain[i] = pz[i] * inverse;
      theta[i] += gain[i] * error;
    }
    // P- - (P- phi)(P- phi)^T / den: the lower triangle column by column,
    // then mirrored.
    const S alpha = -inverse;
#pragma GCC unroll 8
    for (int j = 0; j < n; ++j) {
      const S a = alpha * pz[j];
#pragma GCC unroll 8
      for (int i = j; i < n; ++i) p[j * n + i] += a * pz[i];
    }
#pragma GCC unroll 8
    for (int j = 1; j < n; ++j) {
#pragma GCC unroll 8
      for (int i = 0; i < j; ++i) p[j * n + i] = p[i * n + j];
    }
    finish<N, true>(p, theta, gain, denominator);
    return error;
  }

  // The instrumental-variable step for np = N, eqs. (2.29)/(2.30):
  // L = P- zeta / (offset + phi^T P- zeta), P = scale (P- - L (P-^T phi)^T).
  // P is not symmetric: the guard tests its symmetric part.
  template <int N>
  S iv_step(const S* phi, const S* zeta, S target) {
    const int n = step_size<N>(theta_.size());
    Working<S, N> theta(theta_.data(), true);
    Working<S, N> pz(p_zeta_.data(), false), ptphi(pt_phi_.data(), false),
        gain(gain_.data(), false);
    Working<S, array_size(N, N)> p(P_.data(), true);
    predict<N>(p);
    const S error = target - dot<N>(phi, theta);
    multiply(n, p, zeta, pz);               // P- zeta
    multiply_transposed(n, p, phi, ptphi);  // P-^T phi
    const S denominator = offset_ + dot<N>(phi, pz);
#pragma GCC unroll 8
    for (int i = 0; i < n; ++i) {
      gain[i] = pz[i] / denominator;
      theta[i] += gain[i] * error;
    }
    // P- - L (P-^T phi)^T, eq. (2.29c)/(2.30c).
#pragma GCC unroll 8
    for (int j = 0; j < n; ++j) {
#pragma GCC unroll 8
      for (int i = 0; i < n; ++i) p[j * n + i] -= gain[i] * ptphi[j];
    }
    finish<N, false>(p, theta, gain, denominator);
    return error;
  }

  template <int N, typename A, typename B>
  S dot(const A& a, const B& b) const {
    const int n = step_size<N>(theta_.size());
    S sum = 0;
#pragma GCC unroll 8
    for (int i = 0; i < n; ++i) sum += a[i] * b[i];
    return sum;
  }

  // P- = P + Qn for the Kalman filter, eq. (1.59).
  template <int N, typename Square>
  void predict(Square& p) const {
    if (!kalman_) return;
    const int n = step_size<N>(theta_.size());
    const S* qn = std::get_if<KalmanAdaptation<S>>(&adaptation_)->qn().data();
#pragma GCC unroll 64
    for (int i = 0; i < n * n; ++i) p[i] += qn[i];
  }

  // P scaled by 1/lambda for the forgetting factor, eq. (1.57); theta, P
  // and the gain written back; the guard on P.
  template <int N, bool Symmetric, typename Square, typename Vec>
  void finish(Square& p, Vec& theta, Vec& gain, S denominator) {
    const int n = step_size<N>(theta_.size());
    const S scale = scale_;
    if (scale != S(1)) {
#pragma GCC unroll 64
      for (int i = 0; i < n * n; ++i) p[i] *= scale;
    }
    p.write_back();
    theta.write_back();
    gain.write_back();
    innovation_scale_ = denominator;
    guard_.template apply_step<N, Symmetric>(p, P_.data());
  }

  Adaptation<S> adaptation_;
  Vector<S> theta_;
  Matrix<S> P_;
  Vector<S> p_zeta_;
  Vector<S> pt_phi_;
  Vector<S> gain_;
  Vector<S> phi_copy_, zeta_copy_;  // phi, zeta when not contiguous
  S innovation_scale_ = 1;
  CovarianceGuard<S> guard_;
  Step least_squares_step_ = nullptr;
  IvStep iv_step_ = nullptr;
  int fixed_np_ = 0;
  bool kalman_ = false;
  S offset_ = 1;
  S scale_ = 1;
};

}  // namespace ctid
