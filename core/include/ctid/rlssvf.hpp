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
//     the first sample, the estimates are updated from t_s,ls on.
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
#include <utility>

#include "ctid/adaptation.hpp"
#include "ctid/auxiliary_model.hpp"
#include "ctid/fixed_size.hpp"
#include "ctid/lmr.hpp"
#include "ctid/potter.hpp"
#include "ctid/record.hpp"
#include "ctid/scaling.hpp"
#include "ctid/svf_regressor.hpp"

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
  // run_rlssvf() in double: compile-time kernels for one input and
  // nb <= na <= 4 (fixed_size.hpp); false forces the general dynamic-size
  // path.
  bool fixed_size = true;
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
    status = validate_covariance<S>(gamma, n, "Gamma", false);
    if (!status.ok()) return status;
  } else if (gamma.size() != 0) {
    return bad_input("Gamma belongs to LMR-RLSSVF only");
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
  if (!(config.t_s_ls >= 0) || !std::isfinite(config.t_s_ls)) {
    return bad_input("tsls must be finite and >= 0");
  }
  return validate_initial_estimate(config.theta0, config.P0, n);
}

// The parameter update of the least-squares estimators in one of the three
// forms, with optional signal scaling: update() takes the unscaled phi_f,
// theta() and P() are unscaled, kappa() is kappa_2 of the matrix actually
// propagated (P_s, S_s S_s^T or R_s).
template <typename S, int NP = Eigen::Dynamic>
class LeastSquaresUpdate {
 public:
  using Vec = VectorN<S, NP>;
  using Mat = MatrixN<S, NP>;

  void configure(Eigen::Index n, UpdateForm form,
                 const Adaptation<S>& adaptation, const Matrix<S>& gamma,
                 const Vector<S>& scaling) {
    form_ = form;
    m_ = scaling;
    const bool scaled = m_.size() != 0;
    const Adaptation<S> a =
        scaled ? scaled_adaptation(adaptation, m_) : adaptation;
    switch (form_) {
      case UpdateForm::kStandard:
        standard_.configure(n, a);
        break;
      case UpdateForm::kPotter:
        potter_.configure(n, a);
        break;
      case UpdateForm::kLevenbergMarquardt:
        lmr_.configure(
            n, std::get<ForgettingFactorAdaptation<S>>(a).lambda(),
            scaled ? Matrix<S>(m_.asDiagonal() * gamma * m_.asDiagonal())
                   : gamma);
        break;
    }
    phi_s_ = Vec::Zero(n);
    zeta_s_ = Vec::Zero(n);
    theta_ = Vec::Zero(n);
    P_ = Mat::Zero(n, n);
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
    const Vec& p = scaled_regressor(phi, phi_s_);
    S error = 0;
    switch (form_) {
      case UpdateForm::kStandard:
        error = standard_.update(p, target);
        break;
      case UpdateForm::kPotter:
        error = potter_.update(p, target);
        break;
      case UpdateForm::kLevenbergMarquardt:
        error = lmr_.update(p, target);
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
    const Vec& p = scaled_regressor(phi, phi_s_);
    const Vec& z = scaled_regressor(zeta, zeta_s_);
    const S error = standard_.update(p, z, target);
    refresh_theta();
    return error;
  }

  const Vec& theta() const { return theta_; }
  // Unscaled P(t_k) (M_s P_s M_s), formed on request.
  const Mat& P() const {
    const Mat& working = working_P();
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
  const Mat& working_P() const {
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
  bool failed() const {
    return form_ == UpdateForm::kLevenbergMarquardt && lmr_.failed();
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
  const Vec& scaled_regressor(const Eigen::MatrixBase<Derived>& v, Vec& work) {
    if (m_.size() == 0) {
      work = v;
    } else {
      work = v.cwiseProduct(m_);
    }
    return work;
  }

  const Vec& internal_theta() const {
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
  ParameterUpdate<S, NP> standard_;
  PotterUpdate<S, NP> potter_;
  LmrUpdate<S, NP> lmr_;
  Vector<S> m_;
  Vec phi_s_, zeta_s_, theta_;
  mutable Mat P_;
};

// NA, NP: na and np when known at compile time (fixed_size.hpp; one input,
// no initial-condition regressors), Eigen::Dynamic for the general path.
template <typename S, int NA = Eigen::Dynamic, int NP = Eigen::Dynamic>
class RlsSvf {
 public:
  using Theta = VectorN<S, NP>;
  using Covariance = MatrixN<S, NP>;

  RlsSvf() = default;

  // Validates the configuration, allocates, and resets the estimator.
  Status configure(const RlsSvfConfig<S>& config) {
    const Status status = validate(config);
    if (!status.ok()) return status;
    if (!sizes_match<NA, NP>(config.orders,
                             config.initial_conditions ? config.orders.na : 0)) {
      return bad_input(
          "the orders (or the initial-condition regressors) do not fit the "
          "compile-time sizes of this RlsSvf; use the dynamic-size one");
    }
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
    update_.configure(n, config.form, config.adaptation, config.lmr_gamma,
                      config.scaling);
    phi_ = Theta::Zero(n);
    reset();
    return Status::Ok();
  }

  void reset() {
    regressor_.reset();
    ic_regressor_.reset();
    update_.reset(config_.theta0, config_.P0);
    elapsed_ = 0;
    first_ = true;
    updating_ = false;
    prediction_error_ = 0;
  }

  // One recursion with u(t_k) (one value per input) and y(t_k), where
  // h = t_k - t_(k-1). Returns theta(t_k) (with the c_i last when initial
  // conditions are estimated).
  const Theta& update(const S* u, S y, S h) {
    if (!first_) elapsed_ += h;
    first_ = false;
    regressor_.step(u, y, h);
    const Eigen::Index np = config_.orders.num_parameters();
    phi_.head(np) = regressor_.phi();
    if (config_.initial_conditions) {
      ic_regressor_.step(h);
      phi_.tail(config_.orders.na) = ic_regressor_.phi();
    }
    updating_ = elapsed_ >= config_.t_s_ls * (1 - 1e-12);
    if (updating_) {
      prediction_error_ = update_.update(phi_, regressor_.target());
    } else {
      prediction_error_ = regressor_.target() - phi_.dot(update_.theta());
    }
    return update_.theta();
  }
  const Theta& update(S u, S y) { return update(&u, y, config_.ts); }

  const Theta& theta() const { return update_.theta(); }
  const Covariance& P() const { return update_.P(); }
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
  const SvfRegressor<S, NA, NP>& regressor() const { return regressor_; }
  const RlsSvfConfig<S>& config() const { return config_; }

 private:
  RlsSvfConfig<S> config_;
  SvfRegressor<S, NA, NP> regressor_;
  InitialConditionRegressor<S> ic_regressor_;
  LeastSquaresUpdate<S, NP> update_;
  Theta phi_;
  S elapsed_ = 0;
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
};

// Runs a recursive estimator over a record. `estimator` provides
// update(u_k, y_k, h, k) -> theta(t_k) (np model parameters first),
// covariance() (P after it), kappa(), prediction_error() and
// innovation_scale(). Writes THM, and when asked YH (the frozen model of
// each sample simulated along the record, eq. 1.60), PSET and the rest;
// fails if an estimate is not finite, with `hint` saying what to check.
// NA, NP: the compile-time sizes of the estimator (fixed_size.hpp), which the
// frozen model of YH shares.
template <int NA, int NP, typename S, typename Estimator>
Status record_recursive_run_sized(const ModelOrders& orders,
                                  InterSample u_rule,
                                  const RecordView<S>& record,
                                  const RecursiveOutputs<S>& out,
                                  Estimator&& estimator, const char* hint) {
  const Eigen::Index n = record.num_samples;
  const Eigen::Index np = orders.num_parameters();
  const Eigen::Index nu = record.num_inputs;
  AuxiliaryModel<S, NA, NP> frozen_model;
  if (out.yh != nullptr) frozen_model.configure(orders, u_rule);
  Vector<S> u_k(nu);
  for (Eigen::Index k = 0; k < n; ++k) {
    for (Eigen::Index j = 0; j < nu; ++j) u_k(j) = record.u_at(k, j);
    const S h = record.interval(k);
    const auto& theta = estimator.update(u_k.data(), record.y[k], h, k);
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
      const auto& P = estimator.covariance();
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
  }
  for (Eigen::Index i = 0; i < n * np; ++i) {
    if (!std::isfinite(out.thm[i])) {
      return numerical_failure(
          std::string("the estimates became non-finite; check ") + hint);
    }
  }
  return Status::Ok();
}

template <typename S, typename Estimator>
Status record_recursive_run(const ModelOrders& orders, InterSample u_rule,
                            const RecordView<S>& record,
                            const RecursiveOutputs<S>& out,
                            Estimator&& estimator, const char* hint) {
  return record_recursive_run_sized<Eigen::Dynamic, Eigen::Dynamic>(
      orders, u_rule, record, out, std::forward<Estimator>(estimator), hint);
}

// run_rlssvf() with the sizes chosen (fixed_size.hpp).
template <typename S, int NA, int NP>
Status run_rlssvf_sized(const RlsSvfConfig<S>& config,
                        const RecordView<S>& record,
                        const RecursiveOutputs<S>& out) {
  RlsSvfConfig<S> adjusted = config;
  adjusted.ts = record.ts;
  RlsSvf<S, NA, NP> estimator;
  Status status = estimator.configure(adjusted);
  if (!status.ok()) return status;
  struct Adapter {
    RlsSvf<S, NA, NP>& e;
    const auto& update(const S* u, S y, S h, Eigen::Index) {
      return e.update(u, y, h);
    }
    const auto& covariance() const { return e.P(); }
    S kappa() const { return e.kappa(); }
    S prediction_error() const { return e.prediction_error(); }
    S innovation_scale() const { return e.innovation_scale(); }
  };
  status = record_recursive_run_sized<NA, NP>(
      config.orders, config.svf.u_intersample, record, out, Adapter{estimator},
      "the scaling of the data and lambda_svf");
  if (status.ok() && estimator.failed()) {
    return numerical_failure(
        "R of LMR-RLSSVF lost positive definiteness; check Gamma and the "
        "scaling of the data");
  }
  return status;
}

template <typename S>
Status run_rlssvf(const RlsSvfConfig<S>& config, const RecordView<S>& record,
                  const RecursiveOutputs<S>& out) {
  const Status status = validate_record(record, config.orders);
  if (!status.ok()) return status;
  const bool fixed = config.fixed_size && !config.initial_conditions;
  return with_fixed_sizes<S>(config.orders, fixed, [&](auto na, auto np) {
    return run_rlssvf_sized<S, decltype(na)::value, decltype(np)::value>(
        config, record, out);
  });
}

}  // namespace ctid
