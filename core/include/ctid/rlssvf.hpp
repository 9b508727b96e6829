// Recursive least squares state-variable filter (RLSSVF): the filtered
// regression of eq. (1.53) updated with a forgetting factor, eq. (1.57)
// (RLSSVF-FF), or a Kalman filter with random-walk parameters, eq. (1.59)
// (RLSSVF-KF). Defaults as in the thesis: theta(t_0) = 0, P(t_0) = 1e4 I.
//
// RlsSvf is the online estimator (configure once, then update() per sample,
// no allocation per sample for uniformly sampled data); run_rlssvf() runs it
// over a record and writes the estimates, the simulated output of the
// frozen model at every sample (eq. 1.60) and, when asked, P at every
// sample.
#pragma once

#include <cstring>
#include <string>

#include "ctid/adaptation.hpp"
#include "ctid/auxiliary_model.hpp"
#include "ctid/record.hpp"
#include "ctid/svf_regressor.hpp"

namespace ctid {

template <typename S>
struct RlsSvfConfig {
  ModelOrders orders;
  SvfSettings<S> svf;
  Adaptation<S> adaptation = ForgettingFactorAdaptation<S>(1);
  Vector<S> theta0;  // empty: zeros
  Matrix<S> P0;      // empty: 1e4 * I
  S ts = 0;          // sampling interval used by update(u, y)
};

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

template <typename S>
Status validate(const RlsSvfConfig<S>& config) {
  Status status = validate_orders(config.orders);
  if (!status.ok()) return status;
  status = validate_svf_settings(config.svf);
  if (!status.ok()) return status;
  const Eigen::Index np = config.orders.num_parameters();
  status = validate_adaptation(config.adaptation, np);
  if (!status.ok()) return status;
  return validate_initial_estimate(config.theta0, config.P0, np);
}

template <typename S>
class RlsSvf {
 public:
  RlsSvf() = default;

  // Validates the configuration, allocates, and resets the estimator.
  Status configure(const RlsSvfConfig<S>& config) {
    const Status status = validate(config);
    if (!status.ok()) return status;
    config_ = config;
    const Eigen::Index np = config.orders.num_parameters();
    if (config_.theta0.size() == 0) config_.theta0 = Vector<S>::Zero(np);
    if (config_.P0.size() == 0) {
      config_.P0 = S(1e4) * Matrix<S>::Identity(np, np);
    }
    regressor_.configure(config.orders, config.svf);
    update_.configure(np, config.adaptation);
    reset();
    return Status::Ok();
  }

  void reset() {
    regressor_.reset();
    update_.reset(config_.theta0, config_.P0);
  }

  // One recursion with u(t_k) (one value per input) and y(t_k), where
  // h = t_k - t_(k-1). Returns theta(t_k).
  const Vector<S>& update(const S* u, S y, S h) {
    regressor_.step(u, y, h);
    prediction_error_ = update_.update(regressor_.phi(), regressor_.target());
    return update_.theta();
  }
  const Vector<S>& update(S u, S y) { return update(&u, y, config_.ts); }

  const Vector<S>& theta() const { return update_.theta(); }
  const Matrix<S>& P() const { return update_.P(); }
  S prediction_error() const { return prediction_error_; }
  const SvfRegressor<S>& regressor() const { return regressor_; }
  const RlsSvfConfig<S>& config() const { return config_; }

 private:
  RlsSvfConfig<S> config_;
  SvfRegressor<S> regressor_;
  ParameterUpdate<S> update_;
  S prediction_error_ = 0;
};

// Where run_* writes its results (column-major, caller-owned): thm is
// N-by-np; yh (N), pset (np*np*N) and kappa (N) are optional (null: not
// computed).
template <typename S>
struct RecursiveOutputs {
  S* thm = nullptr;
  S* yh = nullptr;
  S* pset = nullptr;
  S* kappa = nullptr;  // kappa_2(P) after each recursion (thesis sec. 3.5)
};

// Runs a recursive estimator over a record: `update(u_k, y_k, h, k)`
// performs one recursion and returns theta(t_k), `covariance()` gives P
// after it. Writes THM, and when asked YH (the frozen model of each sample
// simulated along the record, eq. 1.60) and PSET; fails if an estimate is
// not finite, with `hint` saying what to check.
template <typename S, typename Update, typename Covariance>
Status record_recursive_run(const ModelOrders& orders, InterSample u_rule,
                            const RecordView<S>& record,
                            const RecursiveOutputs<S>& out, Update&& update,
                            Covariance&& covariance, const char* hint) {
  const Eigen::Index n = record.num_samples;
  const Eigen::Index np = orders.num_parameters();
  const Eigen::Index nu = record.num_inputs;
  AuxiliaryModel<S> frozen_model;
  if (out.yh != nullptr) frozen_model.configure(orders, u_rule);
  Vector<S> u_k(nu);
  for (Eigen::Index k = 0; k < n; ++k) {
    for (Eigen::Index j = 0; j < nu; ++j) u_k(j) = record.u_at(k, j);
    const S h = record.interval(k);
    const Vector<S>& theta = update(u_k.data(), record.y[k], h, k);
    for (Eigen::Index i = 0; i < np; ++i) out.thm[i * n + k] = theta(i);
    if (out.yh != nullptr) {
      frozen_model.set_parameters(theta);
      out.yh[k] = frozen_model.step(u_k.data(), h);
    }
    if (out.pset != nullptr) {
      std::memcpy(out.pset + k * np * np, covariance().data(),
                  sizeof(S) * np * np);
    }
    if (out.kappa != nullptr) out.kappa[k] = kappa_2(covariance());
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
  return record_recursive_run(
      config.orders, config.svf.u_intersample, record, out,
      [&](const S* u, S y, S h, Eigen::Index) -> const Vector<S>& {
        return estimator.update(u, y, h);
      },
      [&]() -> const Matrix<S>& { return estimator.P(); },
      "the scaling of the data and lambda_svf");
}

}  // namespace ctid
