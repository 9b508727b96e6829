// SPDX-License-Identifier: BSD-3-Clause
// Copyright (C) the ctid authors
// Indirect recursive identification of a continuous-time model (thesis
// secs. 1.2.2 and 1.3.3, Fig. 1.3 left; the example of sec. 1.3.4 and
// Fig. 1.9a): a discrete-time ARX model is estimated recursively and
// converted to continuous time at every step.
//
//   DT ARX model, eqs. (1.4)-(1.7):
//     y(t_k) + alpha_1 y(t_(k-1)) + .. + alpha_na y(t_(k-na))
//        = beta_0 u(t_(k-nk)) + .. + beta_(nb-1) u(t_(k-nk-nb+1)) + e(t_k)
//   rho = [alpha_1 .. alpha_na, beta_0 .. beta_(nb-1)], regressor (1.6);
//   recursion: RLS-FF, eq. (1.41), or the normalised Kalman filter,
//   eq. (1.45), through the shared ParameterUpdate (adaptation.hpp).
//
// Optional prefilter (sec. 1.3.4): the SVF (lambda/(p+lambda))^na of the
// direct method, discretised with the bilinear (trapezoidal) rule, applied
// to y and u before the regressor is formed.
//
// ZOH conversion (sec. 1.3.4, "at every step, the conversion from DT to CT
// parameters is carried out using the appropriate zero-order hold
// assumption"): with the DT model in controllable canonical form (Ad, Bd,
// Cd), the ZOH map [Ad Bd; 0 1] = expm([A B; 0 0] Ts) (App. A.1, eq. A.6)
// is inverted with the principal matrix logarithm. The CT transfer function
// is B(p)/A(p) with A(p) = det(pI - A) and, for the strictly proper SISO
// case, B(p) = det(pI - A + B C) - det(pI - A). A DT pole at 0 or on the
// negative real axis has no real CT equivalent under ZOH: the conversion
// then reports a numerical failure and the batch run keeps the last CT
// estimate for that sample and flags it.
#pragma once

#include <complex>
#include <unsupported/Eigen/MatrixFunctions>
#include <vector>

#include "ctid/adaptation/adaptation.hpp"
#include "ctid/base/status.hpp"
#include "ctid/base/types.hpp"
#include "ctid/filters/svf.hpp"
#include "ctid/recursive/rlssvf.hpp"  // validate_adaptation, validate_initial_estimate

namespace ctid {

// Monic characteristic polynomial det(pI - M) = p^n + c1 p^(n-1) + .. + cn,
// returned as [c1 .. cn], from the eigenvalues (M is small).
template <typename S>
Vector<S> characteristic_polynomial(const Matrix<S>& M) {
  const Eigen::Index n = M.rows();
  const Eigen::ComplexEigenSolver<Matrix<S>> eig(M, false);
  std::vector<std::complex<S>> c(n + 1, std::complex<S>(0));
  c[0] = 1;
  for (Eigen::Index i = 0; i < n; ++i) {
    const std::complex<S> root = eig.eigenvalues()(i);
    for (Eigen::Index j = i + 1; j >= 1; --j) c[j] -= root * c[j - 1];
  }
  Vector<S> out(n);
  for (Eigen::Index j = 0; j < n; ++j) out(j) = c[j + 1].real();
  return out;
}

// The CT transfer function B(p)/A(p) whose ZOH sampling with period ts is
// the DT transfer function Bz(z)/Az(z):
//   Az(z) = z^n + alpha_1 z^(n-1) + .. + alpha_n   (alpha: n entries),
//   Bz(z) = beta_z(0) z^(n-1) + .. + beta_z(n-1)    (n entries),
// giving a = [a1 .. an] (A(p) = p^n + a1 p^(n-1) + ..) and
// b = [b_0 .. b_(n-1)] (B(p) = b_0 p^(n-1) + .. + b_(n-1)).
template <typename S>
Status zoh_to_continuous(const Vector<S>& alpha, const Vector<S>& beta_z, S ts,
                         Vector<S>* a, Vector<S>* b) {
  const Eigen::Index n = alpha.size();
  if (n < 1 || beta_z.size() != n) {
    return bad_input("the DT model needs na >= 1 and na numerator entries");
  }
  if (!(ts > 0) || !alpha.allFinite() || !beta_z.allFinite()) {
    return bad_input("the DT model and Ts must be finite, Ts > 0");
  }
  Matrix<S> Ad = Matrix<S>::Zero(n, n);
  for (Eigen::Index i = 0; i + 1 < n; ++i) Ad(i, i + 1) = 1;
  for (Eigen::Index j = 0; j < n; ++j) Ad(n - 1, j) = -alpha(n - 1 - j);
  const Eigen::ComplexEigenSolver<Matrix<S>> eig(Ad, false);
  const S tiny = std::sqrt(std::numeric_limits<S>::epsilon());
  for (Eigen::Index i = 0; i < n; ++i) {
    const std::complex<S> z = eig.eigenvalues()(i);
    if (std::abs(z) <= tiny ||
        (z.real() < 0 && std::abs(z.imag()) <= tiny * std::abs(z))) {
      return numerical_failure(
          "the DT model has a pole at 0 or on the negative real axis: no "
          "continuous-time equivalent under ZOH");
    }
  }
  Matrix<S> M = Matrix<S>::Zero(n + 1, n + 1);
  M.topLeftCorner(n, n) = Ad;
  M(n - 1, n) = 1;
  M(n, n) = 1;
  const Matrix<S> L = M.log() / ts;
  if (!L.allFinite()) {
    return numerical_failure("the matrix logarithm of the ZOH map failed");
  }
  const Matrix<S> A = L.topLeftCorner(n, n);
  const Vector<S> B = L.topRightCorner(n, 1);
  Vector<S> C(n);  // y = Bz(z) w with state [w_k .. w_(k+n-1)]
  for (Eigen::Index j = 0; j < n; ++j) C(j) = beta_z(n - 1 - j);
  *a = characteristic_polynomial<S>(A);
  const Matrix<S> closed = A - B * C.transpose();
  *b = characteristic_polynomial<S>(closed) - *a;
  return Status::Ok();
}

template <typename S>
struct RecursiveArxConfig {
  int na = 2;  // alpha_1 .. alpha_na
  int nb = 2;  // beta_0 .. beta_(nb-1)
  int nk = 1;  // delay of beta_0 in samples
  S ts = 0;    // sampling interval (uniform sampling)
  Adaptation<S> adaptation = ForgettingFactorAdaptation<S>(S(1));
  Vector<S> theta0;        // empty: zeros
  Matrix<S> P0;            // empty: 1e4 I
  S lambda_prefilter = 0;  // 0: no prefilter
  // Convert to CT at every step; needs nk >= 1 and nk + nb - 1 <= na (a
  // strictly proper DT model of order na, the ZOH image of a CT model).
  bool to_continuous = true;
  int num_parameters() const { return na + nb; }
};

template <typename S>
Status validate(const RecursiveArxConfig<S>& c) {
  if (c.na < 1 || c.nb < 1 || c.nk < 0) {
    return bad_input("orders must satisfy na >= 1, nb >= 1, nk >= 0");
  }
  if (!(c.ts > 0) || !std::isfinite(c.ts)) {
    return bad_input("Ts must be a positive finite sampling interval");
  }
  if (!(c.lambda_prefilter >= 0) || !std::isfinite(c.lambda_prefilter)) {
    return bad_input("the prefilter cut-off must be finite and >= 0");
  }
  if (c.to_continuous && (c.nk < 1 || c.nk + c.nb - 1 > c.na)) {
    return bad_input(
        "the ZOH conversion to continuous time needs nk >= 1 and "
        "nk + nb - 1 <= na (a strictly proper DT model of order na)");
  }
  const Eigen::Index np = c.num_parameters();
  Status status = validate_initial_estimate<S>(c.theta0, c.P0, np);
  if (!status.ok()) return status;
  return validate_adaptation<S>(c.adaptation, np);
}

// The recursive estimator object (reset / update, no allocation per
// sample once configured).
template <typename S>
class RecursiveArx {
 public:
  Status configure(const RecursiveArxConfig<S>& config) {
    Status status = validate(config);
    if (!status.ok()) return status;
    config_ = config;
    const Eigen::Index np = config.num_parameters();
    update_.configure(np, config.adaptation);
    phi_ = Vector<S>::Zero(np);
    y_past_.assign(config.na, S(0));
    u_past_.assign(config.nk + config.nb, S(0));
    if (config.lambda_prefilter > 0) {
      for (StateVariableFilter<S>* f : {&filter_y_, &filter_u_}) {
        f->configure(config.na, InterSample::kTrapezoid);
        f->set_denominator(
            svf_denominator<S>(config.na, config.lambda_prefilter),
            svf_gain<S>(config.na, config.lambda_prefilter, true));
      }
    }
    a_ct_ = Vector<S>::Zero(config.na);
    b_ct_ = Vector<S>::Zero(config.na);
    reset();
    return Status::Ok();
  }

  void reset() {
    const Eigen::Index np = config_.num_parameters();
    const Vector<S> theta0 = config_.theta0.size() == np
                                 ? config_.theta0
                                 : Vector<S>(Vector<S>::Zero(np));
    const Matrix<S> P0 = config_.P0.size() == np * np
                             ? config_.P0
                             : Matrix<S>(S(1e4) * Matrix<S>::Identity(np, np));
    update_.reset(theta0, P0);
    std::fill(y_past_.begin(), y_past_.end(), S(0));
    std::fill(u_past_.begin(), u_past_.end(), S(0));
    if (config_.lambda_prefilter > 0) {
      filter_y_.reset();
      filter_u_.reset();
    }
  }

  // One sample; returns the prediction error y_f - phi^T rho(t_(k-1)) and
  // sets the one-step prediction (eq. 1.36) and, when asked for, the CT
  // conversion status of the new estimate.
  S update(S y, S u) {
    S yf = y;
    S uf = u;
    if (config_.lambda_prefilter > 0) {
      filter_y_.step(y, config_.ts);
      filter_u_.step(u, config_.ts);
      yf = filter_y_.outputs()(0);
      uf = filter_u_.outputs()(0);
    }
    // u_past_[i] = u_f(t_(k-i)), i = 0 .. nk + nb - 1.
    std::rotate(u_past_.rbegin(), u_past_.rbegin() + 1, u_past_.rend());
    u_past_[0] = uf;
    const int na = config_.na;
    for (int i = 0; i < na; ++i) phi_(i) = -y_past_[i];
    for (int j = 0; j < config_.nb; ++j) phi_(na + j) = u_past_[config_.nk + j];
    prediction_ = phi_.dot(update_.theta());
    const S error = update_.update(phi_, yf);
    std::rotate(y_past_.rbegin(), y_past_.rbegin() + 1, y_past_.rend());
    if (na > 0) y_past_[0] = yf;
    if (config_.to_continuous) convert();
    return error;
  }

  const Vector<S>& theta() const { return update_.theta(); }
  const Matrix<S>& P() const { return update_.P(); }
  S prediction() const { return prediction_; }
  // The CT model of the latest estimate that had one: [a1..ana], [b0..].
  const Vector<S>& a_continuous() const { return a_ct_; }
  const Vector<S>& b_continuous() const { return b_ct_; }
  bool last_conversion_ok() const { return conversion_ok_; }

 private:
  void convert() {
    const int na = config_.na;
    const Vector<S>& rho = update_.theta();
    Vector<S> alpha = rho.head(na);
    // Bz(z) = z^na B(z^-1): beta_j multiplies z^(na - nk - j).
    Vector<S> beta_z = Vector<S>::Zero(na);
    for (int j = 0; j < config_.nb; ++j) {
      beta_z(config_.nk + j - 1) = rho(na + j);
    }
    Vector<S> a, b;
    const Status s = zoh_to_continuous<S>(alpha, beta_z, config_.ts, &a, &b);
    conversion_ok_ = s.ok() && a.allFinite() && b.allFinite();
    if (conversion_ok_) {
      a_ct_ = a;
      b_ct_ = b;
    }
  }

  RecursiveArxConfig<S> config_;
  ParameterUpdate<S> update_;
  Vector<S> phi_;
  std::vector<S> y_past_;
  std::vector<S> u_past_;
  StateVariableFilter<S> filter_y_;
  StateVariableFilter<S> filter_u_;
  Vector<S> a_ct_;
  Vector<S> b_ct_;
  S prediction_ = 0;
  bool conversion_ok_ = true;
};

// Outputs of the batch run; each pointer may be null (not wanted).
template <typename S>
struct RecursiveArxOutputs {
  S* theta = nullptr;       // N x (na + nb), column-major: DT estimates rho
  S* theta_ct = nullptr;    // N x 2 na: [a1..ana, b0..b(na-1)] per sample
  S* prediction = nullptr;  // N: one-step prediction of (filtered) y
  S* conversion_failed = nullptr;  // N: 1 where the CT conversion failed
  S* final_P = nullptr;            // (na + nb)^2: P after the last sample
};

// Runs the estimator over a record (y, u of n samples).
template <typename S>
Status run_recursive_arx(const RecursiveArxConfig<S>& config, const S* y,
                         const S* u, Eigen::Index n,
                         const RecursiveArxOutputs<S>& out,
                         long* failed_conversions) {
  if (y == nullptr || u == nullptr || n < 1) {
    return bad_input("the record needs y and u with at least one sample");
  }
  for (Eigen::Index k = 0; k < n; ++k) {
    if (!std::isfinite(y[k]) || !std::isfinite(u[k])) {
      return bad_input("y and u must be finite (sample " +
                       std::to_string(k + 1) + " is not)");
    }
  }
  RecursiveArx<S> estimator;
  Status status = estimator.configure(config);
  if (!status.ok()) return status;
  const Eigen::Index np = config.num_parameters();
  const int na = config.na;
  long failures = 0;
  for (Eigen::Index k = 0; k < n; ++k) {
    estimator.update(y[k], u[k]);
    const Vector<S>& rho = estimator.theta();
    if (!rho.allFinite()) {
      return numerical_failure("the estimates became non-finite at sample " +
                               std::to_string(k + 1));
    }
    if (out.theta != nullptr) {
      for (Eigen::Index j = 0; j < np; ++j) out.theta[k + j * n] = rho(j);
    }
    if (out.prediction != nullptr) out.prediction[k] = estimator.prediction();
    if (config.to_continuous) {
      if (!estimator.last_conversion_ok()) ++failures;
      if (out.theta_ct != nullptr) {
        for (int j = 0; j < na; ++j) {
          out.theta_ct[k + j * n] = estimator.a_continuous()(j);
          out.theta_ct[k + (na + j) * n] = estimator.b_continuous()(j);
        }
      }
      if (out.conversion_failed != nullptr) {
        out.conversion_failed[k] = estimator.last_conversion_ok() ? 0 : 1;
      }
    }
  }
  if (out.final_P != nullptr) {
    Eigen::Map<Matrix<S>>(out.final_P, np, np) = estimator.P();
  }
  if (failed_conversions != nullptr) *failed_conversions = failures;
  return Status::Ok();
}

}  // namespace ctid
