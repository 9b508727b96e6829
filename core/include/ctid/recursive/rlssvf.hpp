// SPDX-License-Identifier: BSD-3-Clause
// Copyright (C) the ctid authors
// Recursive least squares state-variable filter (RLSSVF): the filtered
// regression of eq. (1.53) updated with a forgetting factor, eq. (1.57)
// (RLSSVF-FF), or a Kalman filter with random-walk parameters, eq. (1.59)
// (RLSSVF-KF). Defaults as in the thesis: theta(t_0) = 0, P(t_0) = 1e4 I.
//
// The practical variants of Chapter 3 are options of the same estimator:
//   - the update in square-root form, PotterSVF (eq. 3.73, potter.hpp), or
//     regularised, LMR-RLSSVF (eq. 3.82, lmr.hpp);
//   - signal scaling with a diagonal M_s (eqs. 3.65-3.66, App. C;
//     scaling.hpp): the recursion runs on M_s phi_f and returns the
//     unscaled estimates;
//   - initial-condition regressors (eqs. 3.36-3.41): theta is extended by
//     c_1 .. c_na;
//   - a delayed start t_s,ls (Suggested procedure 3.7): the filters run from
//     the first sample, the estimates are updated from t_s,ls on;
//   - the covariance protection of the standard form (covariance_guard.hpp,
//     on by default; not part of the thesis): P is repaired when it has
//     lost positive definiteness and its variances are held below the
//     range of the precision; LMR's R the same way (lmr.hpp).
//
// RlsSvf is the online estimator (configure once, then update() per sample,
// no allocation per sample for uniformly sampled data); run_rlssvf() runs it
// over a record and writes the estimates, the simulated output of the
// frozen model at every sample (eq. 1.60) and, when asked, P at every
// sample.
#pragma once

#include <cstring>
#include <limits>
#include <string>
#include <type_traits>

#include "ctid/adaptation/adaptation.hpp"
#include "ctid/adaptation/lmr.hpp"
#include "ctid/adaptation/potter.hpp"
#include "ctid/base/record.hpp"
#include "ctid/filters/auxiliary_model.hpp"
#include "ctid/filters/frozen_model.hpp"
#include "ctid/filters/svf_regressor.hpp"
#include "ctid/recursive/scaling.hpp"

namespace ctid {

// How P (or its square root, or its inverse) is propagated.
enum class UpdateForm {
  kStandard,            // P itself, eqs. (1.57)/(1.59)
  kPotter,              // S with P = S S^T, eq. (3.73)
  kLevenbergMarquardt,  // R = P^-1 with regularisation Gamma, eq. (3.82)
};

template <typename S>
struct RlsSvfConfig {
  ModelOrders orders;
  SvfSettings<S> svf;
  Adaptation<S> adaptation = ForgettingFactorAdaptation<S>(1);
  // theta0, P0, Qn (in `adaptation`), Gamma and the scaling cover every
  // estimated parameter: the np model parameters, then with
  // initial_conditions the na coefficients c_1 .. c_na.
  Vector<S> theta0;  // empty: zeros
  Matrix<S> P0;      // empty: 1e4 * I
  S ts = 0;          // sampling interval used by update(u, y)
  UpdateForm form = UpdateForm::kStandard;
  Matrix<S> lmr_gamma;  // Gamma of eq. (3.82); LMR only (needs adm 'ff')
  Vector<S> scaling;    // diagonal of M_s; empty: no scaling
  bool initial_conditions = false;
  S t_s_ls = 0;  // first update at the first sample with t - t_1 >= t_s_ls
  bool covariance_guard = true;  // covariance_guard.hpp (standard form),
                                 // lmr.hpp (R of LMR)
  // Gaps of missing samples (bridged by the caller: the record holds the
  // present samples on their instants). An interval h > gap_interval is a
  // gap (0: none); the filters run through it with the input held, but
  // the input during the gap is unknown, so their states are off for a
  // while after it: no update for gap_settle seconds after a gap.
  S gap_interval = 0;
  S gap_settle = 0;
};

// Parameters the estimator updates: np, plus na with initial conditions.
template <typename S>
Eigen::Index num_estimated(const RlsSvfConfig<S>& config) {
  return config.orders.num_parameters() +
         (config.initial_conditions ? config.orders.na : 0);
}

template <typename S>
Status validate_adaptation(const Adaptation<S>& adaptation, Eigen::Index np) {
  if (const auto* ff =
          std::get_if<ForgettingFactorAdaptation<S>>(&adaptation)) {
    return validate_forgetting_factor<S>(ff->lambda());
  }
  const auto& kf = std::get<KalmanAdaptation<S>>(adaptation);
  return validate_covariance<S>(kf.qn(), np, "Qn (adg)", false);
}

template <typename S>
Status validate_initial_estimate(const Vector<S>& theta0, const Matrix<S>& P0,
                                 Eigen::Index np) {
  if (theta0.size() != 0) {
    if (theta0.size() != np) {
      return dimension_mismatch("th0 must have " + std::to_string(np) +
                                " elements (one per parameter), got " +
                                std::to_string(theta0.size()));
    }
    if (!theta0.allFinite()) return bad_input("th0 must be finite");
  }
  if (P0.size() != 0) return validate_covariance<S>(P0, np, "P0", true);
  return Status::Ok();
}

// The update form, its adaptation and Gamma, and the scaling, for n
// estimated parameters.
template <typename S>
Status validate_update_form(UpdateForm form, const Adaptation<S>& adaptation,
                            const Matrix<S>& gamma, const Vector<S>& scaling,
                            Eigen::Index n) {
  Status status = validate_adaptation(adaptation, n);
  if (!status.ok()) return status;
  if (form == UpdateForm::kLevenbergMarquardt) {
    if (!std::holds_alternative<ForgettingFactorAdaptation<S>>(adaptation)) {
      return bad_input(
          "LMR-RLSSVF (eq. 3.82) takes a forgetting factor (adm 'ff'), "
          "not a Kalman filter");
    }
    if (gamma.size() == 0) {
      return Status(ErrorCode::kBadOption, "LMR-RLSSVF (eq. 3.82) needs Gamma");
    }
    status = validate_covariance<S>(gamma, n, "Gamma", false);
    if (!status.ok()) return status;
  } else if (gamma.size() != 0) {
    return Status(ErrorCode::kBadOption, "Gamma belongs to LMR-RLSSVF only");
  }
  return validate_scaling(scaling, n);
}

template <typename S>
Status validate(const RlsSvfConfig<S>& config) {
  Status status = validate_orders(config.orders);
  if (!status.ok()) return status;
  status = validate_svf_settings(config.svf);
  if (!status.ok()) return status;
  const Eigen::Index n = num_estimated(config);
  status = validate_update_form(config.form, config.adaptation,
                                config.lmr_gamma, config.scaling, n);
  if (!status.ok()) return status;
  if (!(config.gap_interval >= 0) || !std::isfinite(config.gap_interval) ||
      !(config.gap_settle >= 0) || !std::isfinite(config.gap_settle)) {
    return bad_input("gap_interval and gap_settle must be finite and >= 0");
  }
  if (!(config.t_s_ls >= 0) || !std::isfinite(config.t_s_ls)) {
    return bad_input("tsls must be finite and >= 0");
  }
  return validate_initial_estimate(config.theta0, config.P0, n);
}

// The parameter update of the least-squares estimators in one of the three
// forms, with optional signal scaling: update() takes the unscaled phi_f,
// theta() and P() are unscaled, kappa() is kappa_2 of the matrix actually
// propagated (P_s, S_s S_s^T or R_s). SquareRootForms = false (the
// recursive IV estimators, whose configuration has no update form) leaves
// the Potter and LMR steps out of update(), so that their code is not
// compiled where it cannot run; configure() then takes kStandard only.
template <typename S, bool SquareRootForms = true>
class LeastSquaresUpdate {
 public:
  void configure(Eigen::Index n, UpdateForm form,
                 const Adaptation<S>& adaptation, const Matrix<S>& gamma,
                 const Vector<S>& scaling, bool covariance_guard = true,
                 bool fixed_size = false) {
    form_ = SquareRootForms ? form : UpdateForm::kStandard;
    m_ = scaling;
    const bool scaled = m_.size() != 0;
    plain_ = form_ == UpdateForm::kStandard && !scaled;
    const Adaptation<S> a =
        scaled ? scaled_adaptation(adaptation, m_) : adaptation;
    switch (form_) {
      case UpdateForm::kStandard:
        standard_.configure(n, a, covariance_guard, fixed_size);
        break;
      case UpdateForm::kPotter:
        potter_.configure(n, a, fixed_size);
        break;
      case UpdateForm::kLevenbergMarquardt:
        lmr_.configure(
            n, std::get<ForgettingFactorAdaptation<S>>(a).lambda(),
            scaled ? Matrix<S>(m_.asDiagonal() * gamma * m_.asDiagonal())
                   : gamma,
            covariance_guard, fixed_size);
        break;
    }
    phi_s_ = Vector<S>::Zero(n);
    zeta_s_ = Vector<S>::Zero(n);
    theta_ = Vector<S>::Zero(n);
    P_ = Matrix<S>::Zero(n, n);
  }

  // Unscaled theta(t_0) and P(t_0).
  void reset(const Vector<S>& theta0, const Matrix<S>& P0) {
    if (m_.size() == 0) {
      reset_internal(theta0, P0);
    } else {
      reset_internal(theta0.cwiseQuotient(m_), unscale_both_sides<S>(P0, m_));
    }
    refresh_theta();
  }

  // Least-squares step on phi_f; returns the prediction error.
  template <typename Derived>
  S update(const Eigen::MatrixBase<Derived>& phi, S target) {
    // Standard form without scaling: phi and theta as they are, no copy
    // (the fixed-size step of ParameterUpdate takes phi's storage).
    if (plain_) {
      if constexpr (std::is_same_v<Derived, Vector<S>>) {
        return standard_.update(phi, target);
      } else {
        phi_s_ = phi;
        return standard_.update(phi_s_, target);
      }
    }
    const Vector<S>& p = scaled_regressor(phi, phi_s_);
    S error = 0;
    switch (form_) {
      case UpdateForm::kStandard:
        error = standard_.update(p, target);
        break;
      case UpdateForm::kPotter:
        if constexpr (SquareRootForms) error = potter_.update(p, target);
        break;
      case UpdateForm::kLevenbergMarquardt:
        if constexpr (SquareRootForms) error = lmr_.update(p, target);
        break;
    }
    refresh_theta();
    return error;
  }

  // Instrumental-variable step (standard form only), eqs. (2.29)/(2.30),
  // scaled as eq. (3.74).
  template <typename D1, typename D2>
  S update(const Eigen::MatrixBase<D1>& phi, const Eigen::MatrixBase<D2>& zeta,
           S target) {
    // Without scaling, phi and zeta as they are (the fixed-size IV step of
    // ParameterUpdate takes their storage); theta() is then standard_'s.
    if constexpr (std::is_same_v<D1, Vector<S>> &&
                  std::is_same_v<D2, Vector<S>>) {
      if (plain_) return standard_.update(phi, zeta, target);
    }
    const Vector<S>& p = scaled_regressor(phi, phi_s_);
    const Vector<S>& z = scaled_regressor(zeta, zeta_s_);
    const S error = standard_.update(p, z, target);
    refresh_theta();
    return error;
  }

  const Vector<S>& theta() const { return plain_ ? standard_.theta() : theta_; }
  // Unscaled P(t_k) (M_s P_s M_s), formed on request.
  const Matrix<S>& P() const {
    const Matrix<S>& working = working_P();
    if (m_.size() == 0) return working;
    P_.noalias() = m_.asDiagonal() * working * m_.asDiagonal();
    return P_;
  }
  S kappa() const {
    switch (form_) {
      case UpdateForm::kPotter:
        return potter_.condition_number();
      case UpdateForm::kLevenbergMarquardt:
        return lmr_.condition_number();
      default:
        return kappa_2(standard_.P());
    }
  }
  // lambda (or 1) + phi^T P^- phi of the last step (eq. 3.25 over
  // sigma_e^2); scaling leaves it unchanged. Not defined for LMR (NaN).
  S innovation_scale() const {
    switch (form_) {
      case UpdateForm::kPotter:
        return potter_.innovation_scale();
      case UpdateForm::kLevenbergMarquardt:
        return std::numeric_limits<S>::quiet_NaN();
      default:
        return standard_.innovation_scale();
    }
  }
  // The covariance the recursion propagates: P_s with scaling (formed from
  // S_s or R_s for the Potter and LMR forms).
  const Matrix<S>& working_P() const {
    switch (form_) {
      case UpdateForm::kPotter:
        return potter_.P();
      case UpdateForm::kLevenbergMarquardt:
        return lmr_.P();
      default:
        return standard_.P();
    }
  }
  UpdateForm form() const { return form_; }
  // What the covariance protection did at the last step: to P (standard
  // form) or to R = P^-1 (LMR, lmr.hpp); the Potter form keeps P positive
  // definite by construction.
  int covariance_guard() const {
    switch (form_) {
      case UpdateForm::kStandard:
        return standard_.covariance_guard();
      case UpdateForm::kLevenbergMarquardt:
        return lmr_.covariance_guard();
      default:
        return kGuardNone;
    }
  }
  bool failed() const {
    return form_ == UpdateForm::kLevenbergMarquardt && lmr_.failed();
  }
  // N of the fixed-size step of the form in use, 0 for the dynamic one.
  int fixed_size() const {
    switch (form_) {
      case UpdateForm::kPotter:
        return potter_.fixed_size();
      case UpdateForm::kLevenbergMarquardt:
        return lmr_.fixed_size();
      default:
        return standard_.fixed_size();
    }
  }

 private:
  void reset_internal(const Vector<S>& theta0, const Matrix<S>& P0) {
    switch (form_) {
      case UpdateForm::kStandard:
        standard_.reset(theta0, P0);
        break;
      case UpdateForm::kPotter:
        potter_.reset(theta0, P0);
        break;
      case UpdateForm::kLevenbergMarquardt:
        lmr_.reset(theta0, P0);
        break;
    }
  }

  template <typename Derived>
  const Vector<S>& scaled_regressor(const Eigen::MatrixBase<Derived>& v,
                                    Vector<S>& work) {
    if (m_.size() == 0) {
      work = v;
    } else {
      work = v.cwiseProduct(m_);
    }
    return work;
  }

  const Vector<S>& internal_theta() const {
    switch (form_) {
      case UpdateForm::kPotter:
        return potter_.theta();
      case UpdateForm::kLevenbergMarquardt:
        return lmr_.theta();
      default:
        return standard_.theta();
    }
  }
  void refresh_theta() {
    if (m_.size() == 0) {
      theta_ = internal_theta();
    } else {
      theta_ = internal_theta().cwiseProduct(m_);
    }
  }

  UpdateForm form_ = UpdateForm::kStandard;
  bool plain_ = true;  // standard form, no scaling: theta is standard_'s
  ParameterUpdate<S> standard_;
  PotterUpdate<S> potter_;
  LmrUpdate<S> lmr_;
  Vector<S> m_;
  Vector<S> phi_s_, zeta_s_, theta_;
  mutable Matrix<S> P_;
};

template <typename S>
class RlsSvf {
 public:
  RlsSvf() = default;

  // Validates the configuration, allocates, and resets the estimator.
  Status configure(const RlsSvfConfig<S>& config) {
    const Status status = validate(config);
    if (!status.ok()) return status;
    config_ = config;
    const Eigen::Index n = num_estimated(config);
    if (config_.theta0.size() == 0) config_.theta0 = Vector<S>::Zero(n);
    if (config_.P0.size() == 0) {
      config_.P0 = S(1e4) * Matrix<S>::Identity(n, n);
    }
    SvfSettings<S> svf = config.svf;
    if (config.initial_conditions) {
      svf.rest_at_first_sample = true;
      ic_regressor_.configure(config.orders.na, svf.lambda_svf, svf.normalised);
    }
    regressor_.configure(config.orders, svf);
    // The adaptation step at compile-time size goes with the fixed-size
    // filter kernels (svf.kernels, chosen once here; step_size.hpp).
    update_.configure(n, config.form, config.adaptation, config.lmr_gamma,
                      config.scaling, config.covariance_guard,
                      svf.kernels == FilterKernels::kFixedSize);
    phi_ = Vector<S>::Zero(n);
    reset();
    return Status::Ok();
  }

  void reset() {
    regressor_.reset();
    ic_regressor_.reset();
    update_.reset(config_.theta0, config_.P0);
    elapsed_ = 0;
    since_gap_ = std::numeric_limits<S>::infinity();
    first_ = true;
    updating_ = false;
    prediction_error_ = 0;
  }

  // One recursion with u(t_k) (one value per input) and y(t_k), where
  // h = t_k - t_(k-1). Returns theta(t_k) (with the c_i last when initial
  // conditions are estimated).
  const Vector<S>& update(const S* u, S y, S h) {
    if (!first_) {
      elapsed_ += h;
      since_gap_ = config_.gap_interval > 0 && h > config_.gap_interval
                       ? S(0)
                       : since_gap_ + h;
    }
    first_ = false;
    regressor_.step(u, y, h);
    // phi_f itself, or extended by the initial-condition regressors.
    const Vector<S>* phi = &regressor_.phi();
    if (config_.initial_conditions) {
      phi_.head(config_.orders.num_parameters()) = regressor_.phi();
      ic_regressor_.step(h);
      phi_.tail(config_.orders.na) = ic_regressor_.phi();
      phi = &phi_;
    }
    updating_ = elapsed_ >= config_.t_s_ls * (1 - 1e-12) &&
                since_gap_ >= config_.gap_settle * (1 - 1e-12);
    if (updating_) {
      prediction_error_ = update_.update(*phi, regressor_.target());
    } else {
      prediction_error_ = regressor_.target() - phi->dot(update_.theta());
    }
    return update_.theta();
  }
  const Vector<S>& update(S u, S y) { return update(&u, y, config_.ts); }

  const Vector<S>& theta() const { return update_.theta(); }
  const Matrix<S>& P() const { return update_.P(); }
  S kappa() const { return update_.kappa(); }
  S prediction_error() const { return prediction_error_; }
  // r(t_k)/sigma_e^2 of the last update (eq. 3.25); NaN before t_s,ls.
  S innovation_scale() const {
    return updating_ ? update_.innovation_scale()
                     : std::numeric_limits<S>::quiet_NaN();
  }
  // False before t_s,ls.
  bool updating() const { return updating_; }
  bool failed() const { return update_.failed(); }
  // What the covariance protection did at the last update (a
  // CovarianceGuardAction mask; kGuardNone before t_s,ls).
  int covariance_guard() const {
    return updating_ ? update_.covariance_guard() : int(kGuardNone);
  }
  const SvfRegressor<S>& regressor() const { return regressor_; }
  const RlsSvfConfig<S>& config() const { return config_; }

 private:
  RlsSvfConfig<S> config_;
  SvfRegressor<S> regressor_;
  InitialConditionRegressor<S> ic_regressor_;
  LeastSquaresUpdate<S> update_;
  Vector<S> phi_;
  S elapsed_ = 0;
  S since_gap_ = std::numeric_limits<S>::infinity();
  bool first_ = true;
  bool updating_ = false;
  S prediction_error_ = 0;
};

// Where run_* writes its results (column-major, caller-owned): thm is
// N-by-np; the others are optional (null: not computed).
template <typename S>
struct RecursiveOutputs {
  S* thm = nullptr;
  S* yh = nullptr;
  S* pset = nullptr;   // np*np*N: the model block of P after each recursion
  S* kappa = nullptr;  // N: kappa_2(P) after each recursion (sec. 3.5)
  S* extra = nullptr;  // N-by-(n - np): further estimated parameters (the
                       // initial-condition coefficients c_i)
  S* error = nullptr;  // N: prediction error of each recursion
  S* innovation = nullptr;  // N: r(t_k)/sigma_e^2 of each recursion
  S* guard = nullptr;       // N: what the covariance protection did to P
                            // (covariance_guard.hpp: 0, 1 repair, 2 ceiling, 3)
};

// Runs a recursive estimator over a record. `estimator` provides
// update(u_k, y_k, h, k) -> theta(t_k) (np model parameters first),
// covariance() (P after it), kappa(), prediction_error(),
// innovation_scale() and covariance_guard(). Writes THM, and when asked YH (the
// frozen model of each sample simulated along the record, eq. 1.60), PSET and
// the rest; fails if an estimate is not finite, with `hint` saying what to
// check.
template <typename S, typename Estimator>
Status record_recursive_run(const ModelOrders& orders, InterSample u_rule,
                            const RecordView<S>& record,
                            const RecursiveOutputs<S>& out,
                            Estimator&& estimator, const char* hint,
                            FilterKernels kernels = FilterKernels::kFixedSize) {
  const Eigen::Index n = record.num_samples;
  const Eigen::Index np = orders.num_parameters();
  const Eigen::Index nu = record.num_inputs;
  FrozenModel<S> frozen_model;
  if (out.yh != nullptr) frozen_model.configure(orders, u_rule, kernels);
  Vector<S> u_k(nu);
  for (Eigen::Index k = 0; k < n; ++k) {
    for (Eigen::Index j = 0; j < nu; ++j) u_k(j) = record.u_at(k, j);
    const S h = record.interval(k);
    const Vector<S>& theta = estimator.update(u_k.data(), record.y[k], h, k);
    for (Eigen::Index i = 0; i < np; ++i) out.thm[i * n + k] = theta(i);
    if (out.extra != nullptr) {
      for (Eigen::Index i = np; i < theta.size(); ++i) {
        out.extra[(i - np) * n + k] = theta(i);
      }
    }
    if (out.yh != nullptr) {
      frozen_model.set_parameters(theta.head(np));
      out.yh[k] = frozen_model.step(u_k.data(), h);
    }
    if (out.pset != nullptr) {
      const Matrix<S>& P = estimator.covariance();
      for (Eigen::Index j = 0; j < np; ++j) {
        for (Eigen::Index i = 0; i < np; ++i) {
          out.pset[k * np * np + j * np + i] = P(i, j);
        }
      }
    }
    if (out.kappa != nullptr) out.kappa[k] = estimator.kappa();
    if (out.error != nullptr) out.error[k] = estimator.prediction_error();
    if (out.innovation != nullptr) {
      out.innovation[k] = estimator.innovation_scale();
    }
    if (out.guard != nullptr) out.guard[k] = S(estimator.covariance_guard());
  }
  for (Eigen::Index i = 0; i < n * np; ++i) {
    if (!std::isfinite(out.thm[i])) {
      return numerical_failure(
          std::string("the estimates became non-finite; check ") + hint);
    }
  }
  return Status::Ok();
}

template <typename S>
Status run_rlssvf(const RlsSvfConfig<S>& config, const RecordView<S>& record,
                  const RecursiveOutputs<S>& out) {
  Status status = validate_record(record, config.orders);
  if (!status.ok()) return status;
  RlsSvfConfig<S> adjusted = config;
  adjusted.ts = record.ts;
  RlsSvf<S> estimator;
  status = estimator.configure(adjusted);
  if (!status.ok()) return status;
  struct Adapter {
    RlsSvf<S>& e;
    const Vector<S>& update(const S* u, S y, S h, Eigen::Index) {
      return e.update(u, y, h);
    }
    const Matrix<S>& covariance() const { return e.P(); }
    S kappa() const { return e.kappa(); }
    S prediction_error() const { return e.prediction_error(); }
    S innovation_scale() const { return e.innovation_scale(); }
    int covariance_guard() const { return e.covariance_guard(); }
  };
  status = record_recursive_run(
      config.orders, config.svf.u_intersample, record, out, Adapter{estimator},
      "the scaling of the data and lambda_svf", config.svf.kernels);
  if (status.ok() && estimator.failed()) {
    return numerical_failure(
        "the factor of R of LMR-RLSSVF is no longer finite; check Gamma "
        "and the scaling of the data");
  }
  return status;
}

}  // namespace ctid
