// SPDX-License-Identifier: BSD-3-Clause
// Copyright (C) the ctid authors
// Recursive instrumental-variable estimators of CT models with
// time-varying parameters (thesis Chapter 2 and sec. 3.2):
//
//   RIVSVF   fixed SVF F(p), instruments from the auxiliary model (2.16);
//   RSRIVC   adaptive prefilter 1/A(p, theta) (2.19) on y, u and x_hat;
//   CLRIVSVF, CLRSRIVC  the same with the closed-loop auxiliary model
//            (2.51)-(2.54): x_hat and u_hat from the estimated plant in a
//            loop with the known controller.
//
// Updates: IV Kalman filter (2.29) or forgetting factor (2.30), sharing the
// adaptation parts of RLSSVF. Start: RLSSVF until t_s_iv, then IV from the
// last RLSSVF estimate and P (sec. 3.2.1). The auxiliary model and the
// prefilters run from the first sample, driven by the latest accepted
// estimate, so their states are settled at t_s_iv (implementation notes,
// item 7). The estimate fed back is first smoothed by M_theta(q^-1)
// (sec. 3.2.3; default a one-sample delay), then checked for stability
// (eq. 3.10; keep the last stable one or reflect the unstable roots), and
// refreshed every `dtupdate` seconds.
//
// Chapter 3 options: signal scaling with a diagonal M_s (eq. 3.74; the
// RLSSVF start is scaled the same way, eq. 3.66), and conditional updating
// against estimator windup (sec. 3.6.2, eq. 3.79): an RLSSVF-FF runs in
// parallel on the same SVF regression; while kappa_2 of its P is >= gamma
// the estimates are held at theta(t_0), P(t_0), and when excitation
// returns the estimator restarts through RLSSVF (IV again t_s,iv later).
// The test is armed the first time kappa_2 < gamma holds at or after
// t_s,iv, the time by which RLSSVF on the same regression is taken to have
// converged (sec. 3.2.1): kappa_2(P(t_0)) = 1 for P(t_0) = p I, and the
// start-up of the parallel filter from it would otherwise count as poor
// excitation.
//
// Prefilter gain (RSRIVC): the thesis writes 1/A(p) (monic). Its output
// scales with A, so the regressors and with them the effective Qn change as
// A drifts; the default here is the unit-static-gain prefilter a_na/A(p),
// the analogue of the normalised SVF (eq. 3.1). See
// shared/implementation-notes.md, item 2, and demos/ for the measurement.
#pragma once

#include <vector>

#include "ctid/adaptation/adaptation.hpp"
#include "ctid/base/delay_line.hpp"
#include "ctid/base/record.hpp"
#include "ctid/base/stability.hpp"
#include "ctid/filters/svf_regressor.hpp"
#include "ctid/recursive/rlssvf.hpp"
#include "ctid/simulation/controller.hpp"

namespace ctid {

enum class IvMethod { kRivsvf, kRsrivc };
enum class PrefilterGain { kUnitStaticGain, kMonic };

template <typename S>
struct RecursiveIvConfig {
  ModelOrders orders;
  IvMethod method = IvMethod::kRsrivc;
  SvfSettings<S> svf;  // the SVF of RLSSVF and RIVSVF
  Adaptation<S> adaptation = ForgettingFactorAdaptation<S>(1);
  Vector<S> theta0;  // empty: zeros
  Matrix<S> P0;      // empty: 1e4 * I
  S ts = 0;          // sampling interval of update(u, y)
  S t_s_iv = 0;      // IV from the first sample with t - t_1 >= t_s_iv
  S dtupdate = 0;    // refresh period (s) of auxiliary model / prefilter;
                     // 0: every sample
  StabilityPolicy stability = StabilityPolicy::kKeepLast;
  // M_theta(q^-1); empty numerator: the default one-sample delay q^-1.
  DiscreteTransferFunction<S> m_theta;
  PrefilterGain prefilter_gain = PrefilterGain::kUnitStaticGain;
  // Denominator [a1 .. a_na] that starts the prefilter and the auxiliary
  // model; empty: (p + lambda_svf)^na.
  Vector<S> initial_denominator;
  bool closed_loop = false;
  DiscreteTransferFunction<S> controller;  // u = r1 + C (r2 - y)
  Vector<S> scaling;                       // diagonal of M_s; empty: no scaling
  S antiwindup_gamma = 0;  // gamma of eq. (3.79); 0: no conditional updating
  S antiwindup_lambda = S(0.998);  // forgetting factor of the parallel
                                   // RLSSVF-FF (thesis Table 3.2)
  bool covariance_guard = true;    // covariance_guard.hpp, on P and on the
                                   // parallel RLSSVF-FF's P
  S gap_interval = 0;  // gaps of missing samples, as in RlsSvfConfig: no
  S gap_settle = 0;    // update for gap_settle s after an interval above
                       // gap_interval (0: none)
};

template <typename S>
Status validate(const RecursiveIvConfig<S>& c) {
  RlsSvfConfig<S> ls;
  ls.orders = c.orders;
  ls.svf = c.svf;
  ls.adaptation = c.adaptation;
  ls.theta0 = c.theta0;
  ls.P0 = c.P0;
  ls.scaling = c.scaling;
  ls.gap_interval = c.gap_interval;
  ls.gap_settle = c.gap_settle;
  Status status = validate(ls);
  if (!status.ok()) return status;
  if (c.antiwindup_gamma != 0) {
    if (!(c.antiwindup_gamma > 1) || !std::isfinite(c.antiwindup_gamma)) {
      return bad_input(
          "the anti-windup threshold gamma must be finite and > 1 (kappa_2 "
          "of a matrix is >= 1), got " +
          std::to_string(static_cast<double>(c.antiwindup_gamma)));
    }
    status = validate_forgetting_factor<S>(c.antiwindup_lambda);
    if (!status.ok()) {
      return bad_input("anti-windup RLSSVF-FF: " + status.message());
    }
  }
  if (!(c.t_s_iv >= 0) || !std::isfinite(c.t_s_iv)) {
    return bad_input("tsiv must be finite and >= 0");
  }
  if (!(c.dtupdate >= 0) || !std::isfinite(c.dtupdate)) {
    return bad_input("dtupdate must be finite and >= 0");
  }
  if (c.m_theta.numerator.size() != 0) {
    status = validate_controller(c.m_theta);
    if (!status.ok()) {
      return bad_input("M_theta: " + status.message());
    }
    const S dc = c.m_theta.numerator.sum() / c.m_theta.denominator.sum();
    if (!(std::abs(dc - 1) < 1e-3)) {
      return bad_input(
          "M_theta must have unit static gain (it smooths the "
          "estimates), got " +
          std::to_string(static_cast<double>(dc)));
    }
  }
  if (c.initial_denominator.size() != 0) {
    if (c.initial_denominator.size() != c.orders.na) {
      return dimension_mismatch(
          "A must have na = " + std::to_string(c.orders.na) +
          " coefficients after the leading 1");
    }
    HurwitzTest<S> test(c.orders.na);
    if (!test.is_stable(c.initial_denominator)) {
      return bad_input("A must be a stable (Hurwitz) polynomial");
    }
  }
  if (c.closed_loop) {
    if (c.orders.num_inputs() != 1) {
      return bad_input("closed-loop estimation needs a single input");
    }
    if (c.svf.u_intersample != InterSample::kZoh) {
      return bad_input(
          "closed-loop estimation needs ZOH data (the "
          "controller output is held between samples)");
    }
    status = validate_controller(c.controller);
    if (!status.ok()) return bad_input("controller: " + status.message());
  }
  return Status::Ok();
}

template <typename S>
class RecursiveIv {
 public:
  Status configure(const RecursiveIvConfig<S>& config) {
    const Status status = validate(config);
    if (!status.ok()) return status;
    config_ = config;
    const ModelOrders& orders = config.orders;
    const int na = orders.na;
    const int nu = orders.num_inputs();
    const Eigen::Index np = orders.num_parameters();
    if (config_.theta0.size() == 0) config_.theta0 = Vector<S>::Zero(np);
    if (config_.P0.size() == 0)
      config_.P0 = S(1e4) * Matrix<S>::Identity(np, np);
    if (config_.initial_denominator.size() == 0) {
      config_.initial_denominator =
          svf_denominator<S>(na, config.svf.lambda_svf);
    }
    if (config_.m_theta.numerator.size() == 0) {
      config_.m_theta.numerator = Vector<S>::Zero(2);
      config_.m_theta.numerator(1) = 1;
      config_.m_theta.denominator = Vector<S>::Ones(1);
    }
    ls_regressor_.configure(orders, config.svf);
    // The adaptation steps (least squares, then IV) at compile-time size
    // with the fixed-size kernels as in RLSSVF (rlssvf.hpp), so that before
    // t_s,iv the estimates are RLSSVF's bit for bit.
    const bool fixed_ls = config.svf.kernels == FilterKernels::kFixedSize;
    update_.configure(np, UpdateForm::kStandard, config.adaptation, Matrix<S>(),
                      config.scaling, config.covariance_guard, fixed_ls);
    if (antiwindup()) {
      windup_monitor_.configure(
          np, UpdateForm::kStandard,
          ForgettingFactorAdaptation<S>(config.antiwindup_lambda), Matrix<S>(),
          config.scaling, config.covariance_guard, fixed_ls);
      eigen_ = Eigen::SelfAdjointEigenSolver<Matrix<S>>(np);
    }

    // Fixed SVF (RIVSVF) or adaptive prefilter (RSRIVC) on y, x_hat
    // (trapezoidal) and on u or u_hat (the input's rule).
    const InterSample u_rule = config.svf.u_intersample;
    const FilterKernels kernels = config.svf.kernels;
    signal_disc_.configure(na, config.svf.y_intersample, kernels);
    input_disc_.configure(na, u_rule, kernels);
    aux_disc_.configure(na, u_rule, kernels);
    y_channel_.configure(na);
    xhat_channel_.configure(na);
    uhat_channel_.configure(na);
    uhat_delay_.configure(config.closed_loop ? orders.nk[0] : 0);
    input_channels_.resize(nu);
    aux_channels_.resize(nu);
    delays_.resize(nu);
    aux_delays_.resize(nu);
    for (int j = 0; j < nu; ++j) {
      input_channels_[j].configure(na);
      aux_channels_[j].configure(na);
      delays_[j].configure(orders.nk[j]);
      aux_delays_[j].configure(orders.nk[j]);
    }
    m_filters_.assign(np, DiscreteFilter<S>());
    for (auto& f : m_filters_) f.configure(config_.m_theta);
    hurwitz_.configure(na);
    phi_ = Vector<S>::Zero(np);
    zeta_ = Vector<S>::Zero(np);
    theta_m_ = Vector<S>::Zero(np);
    theta_fb_ = Vector<S>::Zero(np);
    reset();
    return Status::Ok();
  }

  void reset() {
    ls_regressor_.reset();
    update_.reset(config_.theta0, config_.P0);
    if (antiwindup()) windup_monitor_.reset(config_.theta0, config_.P0);
    monitor_kappa_ = 1;
    armed_ = false;
    excited_ = true;
    stage_start_ = 0;
    resets_ = 0;
    y_channel_.reset();
    xhat_channel_.reset();
    uhat_channel_.reset();
    uhat_delay_.reset();
    for (auto& c : input_channels_) c.reset();
    for (auto& c : aux_channels_) c.reset();
    for (auto& d : delays_) d.reset();
    for (auto& d : aux_delays_) d.reset();
    for (auto& f : m_filters_) f.reset();
    if (config_.closed_loop) controller_.configure(config_.controller);
    theta_fb_.setZero();
    theta_fb_.head(config_.orders.na) = config_.initial_denominator;
    apply_feedback_parameters();
    elapsed_ = 0;
    since_gap_ = std::numeric_limits<S>::infinity();
    gap_hold_ = false;
    since_refresh_ = 0;
    first_ = true;
    iv_active_ = false;
    rejections_ = 0;
    last_xhat_ = 0;
  }

  // One recursion: u(t_k) (one value per input), y(t_k), h = t_k - t_(k-1),
  // and in closed loop the external signals r1(t_k), r2(t_k).
  const Vector<S>& update(const S* u, S y, S h, S r1 = 0, S r2 = 0) {
    if (!first_) {
      elapsed_ += h;
      since_refresh_ += h;
      since_gap_ = config_.gap_interval > 0 && h > config_.gap_interval
                       ? S(0)
                       : since_gap_ + h;
    }
    gap_hold_ = since_gap_ < config_.gap_settle * (1 - 1e-12);
    first_ = false;
    const ModelOrders& orders = config_.orders;
    const int na = orders.na;
    const int nu = orders.num_inputs();
    aux_disc_.ensure(h);
    signal_disc_.ensure(h);
    if (config_.method == IvMethod::kRivsvf) input_disc_.ensure(h);

    // RLSSVF regression, always run so that its filters stay settled.
    ls_regressor_.step(u, y, h);
    if (antiwindup()) monitor_excitation();

    // Method filters (fixed SVF or adaptive prefilter): y and x_hat by the
    // trapezoidal rule, u (and u_hat) by the input's rule.
    const S xhat = config_.closed_loop ? closed_loop_auxiliary(r1, r2)
                                       : open_loop_auxiliary(u);
    y_channel_.step(signal_disc_, gain_, y);
    xhat_channel_.step(signal_disc_, gain_, xhat);
    const Vector<S>& yf = y_channel_.outputs();
    const Vector<S>& xf = xhat_channel_.outputs();
    for (int i = 0; i < na; ++i) {
      phi_(i) = -yf(na - 1 - i);
      zeta_(i) = -xf(na - 1 - i);
    }
    int offset = na;
    for (int j = 0; j < nu; ++j) {
      input_channels_[j].step(input_filter(), gain_, delays_[j].push(u[j]));
      const Vector<S>& uf = input_channels_[j].outputs();
      const int nb = orders.nb[j];
      for (int l = 0; l < nb; ++l) phi_(offset + l) = uf(nb - 1 - l);
      offset += nb;
    }
    const Eigen::Index nnum = phi_.size() - na;
    if (config_.closed_loop) {  // instruments from u_hat, eq. (2.51)
      const Vector<S>& uhf = uhat_channel_.outputs();
      const int nb = orders.nb[0];
      for (int l = 0; l < nb; ++l) zeta_(na + l) = uhf(nb - 1 - l);
    } else {  // eq. (2.17): the input part of zeta is u_f itself
      zeta_.tail(nnum) = phi_.tail(nnum);
    }

    iv_active_ = elapsed_ - stage_start_ >= config_.t_s_iv * (1 - 1e-12);
    if (!excited_) {  // conditional updating: hold theta(t_0), P(t_0)
      iv_active_ = false;
      update_.reset(config_.theta0, config_.P0);
      prediction_error_ =
          ls_regressor_.target() - ls_regressor_.phi().dot(update_.theta());
    } else if (gap_hold_) {  // filters settling after a gap: no update
      prediction_error_ = iv_active_
                              ? yf(na) - phi_.dot(update_.theta())
                              : ls_regressor_.target() -
                                    ls_regressor_.phi().dot(update_.theta());
    } else if (!iv_active_) {
      prediction_error_ =
          update_.update(ls_regressor_.phi(), ls_regressor_.target());
    } else {
      prediction_error_ = update_.update(phi_, zeta_, yf(na));
    }
    feed_back(update_.theta());
    return update_.theta();
  }
  const Vector<S>& update(S u, S y) { return update(&u, y, config_.ts); }

  const Vector<S>& theta() const { return update_.theta(); }
  const Matrix<S>& P() const { return update_.P(); }
  S kappa() const { return update_.kappa(); }
  // What the covariance protection did to P at the last update (a
  // CovarianceGuardAction mask; kGuardNone while held).
  int covariance_guard() const {
    return excited_ && !gap_hold_ ? update_.covariance_guard()
                                  : int(kGuardNone);
  }
  // r(t_k)/sigma_e^2 of the last update: 1 + phi^T P^- phi (RLSSVF stage)
  // or 1 + phi^T P^- zeta (IV stage), eq. (3.25); NaN while held.
  S innovation_scale() const {
    return excited_ && !gap_hold_ ? update_.innovation_scale()
                                  : std::numeric_limits<S>::quiet_NaN();
  }
  // Conditional updating (eq. 3.79): kappa_2(P) of the parallel RLSSVF-FF,
  // whether the estimates are updated, and how many times they were reset.
  S monitor_kappa() const { return monitor_kappa_; }
  bool updating() const { return excited_; }
  long resets() const { return resets_; }
  // The estimate that currently drives the auxiliary model and prefilter.
  const Vector<S>& feedback_parameters() const { return theta_fb_; }
  bool iv_active() const { return iv_active_; }
  long stability_rejections() const { return rejections_; }
  S prediction_error() const { return prediction_error_; }
  S last_xhat() const { return last_xhat_; }

 private:
  bool antiwindup() const { return config_.antiwindup_gamma != 0; }

  // Eq. (3.79) on the parallel RLSSVF-FF: armed once kappa_2 < gamma at or
  // after t_s,iv; a drop of excitation resets the estimates, its return
  // restarts the RLSSVF stage.
  void monitor_excitation() {
    windup_monitor_.update(ls_regressor_.phi(), ls_regressor_.target());
    eigen_.compute(windup_monitor_.working_P(), Eigen::EigenvaluesOnly);
    const auto& lambda = eigen_.eigenvalues();
    const S smallest = lambda(0);
    monitor_kappa_ = smallest > 0 ? lambda(lambda.size() - 1) / smallest
                                  : std::numeric_limits<S>::infinity();
    const bool rich = monitor_kappa_ < config_.antiwindup_gamma;
    armed_ = armed_ || (rich && elapsed_ >= config_.t_s_iv * (1 - 1e-12));
    const bool excited = !armed_ || rich;
    if (excited && !excited_) stage_start_ = elapsed_;
    if (!excited && excited_) ++resets_;
    excited_ = excited;
  }

  // x_hat(t_k) of the auxiliary model (2.16) with theta_fb.
  S open_loop_auxiliary(const S* u) {
    S x = 0;
    for (int j = 0; j < config_.orders.num_inputs(); ++j) {
      aux_channels_[j].step(aux_disc_, S(1), aux_delays_[j].push(u[j]));
      x += numerator_output(j, aux_channels_[j].outputs());
    }
    last_xhat_ = x;
    return x;
  }

  // Closed-loop auxiliary model (2.52): x_hat from the estimated plant
  // driven by u_hat = r1 + C (r2 - x_hat). With nk = 0 and a biproper
  // model the loop has a direct feedthrough b0, solved exactly (the input
  // is ZOH, so only the highest derivative depends on u_hat(t_k)).
  S closed_loop_auxiliary(S r1, S r2) {
    const ModelOrders& orders = config_.orders;
    const int nk = orders.nk[0];
    const S plant_input = nk > 0 ? aux_delays_[0].oldest() : S(0);
    aux_channels_[0].step(aux_disc_, S(1), plant_input);
    S x = numerator_output(0, aux_channels_[0].outputs());
    S uhat = 0;
    if (nk > 0) {
      uhat = r1 + controller_.step(r2 - x);
      aux_delays_[0].push(uhat);
    } else {
      const bool biproper = orders.nb[0] == orders.na + 1;
      const S d = biproper ? theta_fb_(orders.na) : S(0);
      const S c0 = controller_.feedthrough();
      const S loop = 1 + c0 * d;
      uhat = r1 + c0 * (r2 - x) + controller_.free_response();
      if (std::abs(loop) > 1e3 * std::numeric_limits<S>::epsilon()) {
        uhat /= loop;
      }
      x += d * uhat;
      aux_channels_[0].replace_last_input(S(1), uhat);
      controller_.step(r2 - x);
    }
    uhat_channel_.step(input_filter(), gain_, uhat_delay_.push(uhat));
    last_xhat_ = x;
    return x;
  }

  // The input's filter: RSRIVC's prefilter has the auxiliary model's
  // denominator and rule, so the two share one discretisation.
  const FilterDiscretization<S>& input_filter() const {
    return config_.method == IvMethod::kRsrivc ? aux_disc_ : input_disc_;
  }

  S numerator_output(int j, const Vector<S>& w) const {
    const int nb = config_.orders.nb[j];
    const int offset = config_.orders.numerator_offset(j);
    S x = 0;
    for (int l = 0; l < nb; ++l) x += theta_fb_(offset + l) * w(nb - 1 - l);
    return x;
  }

  // M_theta, stability test, refresh of auxiliary model and prefilter.
  void feed_back(const Vector<S>& theta) {
    const Eigen::Index np = theta.size();
    for (Eigen::Index i = 0; i < np; ++i)
      theta_m_(i) = m_filters_[i].step(theta(i));
    if (config_.dtupdate > 0 &&
        since_refresh_ < config_.dtupdate * (1 - 1e-9)) {
      return;
    }
    since_refresh_ = 0;
    const int na = config_.orders.na;
    if (!theta_m_.allFinite()) {
      ++rejections_;
      return;
    }
    if (hurwitz_.is_stable(theta_m_.head(na))) {
      theta_fb_ = theta_m_;
    } else {
      ++rejections_;
      if (config_.stability == StabilityPolicy::kReflect) {
        theta_fb_ = theta_m_;
        theta_fb_.head(na) = reflect_unstable_roots<S>(theta_m_.head(na));
        if (!hurwitz_.is_stable(theta_fb_.head(na))) return;
      } else {
        return;  // keep the last stable estimate
      }
    }
    apply_feedback_parameters();
  }

  void apply_feedback_parameters() {
    const int na = config_.orders.na;
    aux_disc_.set_denominator(theta_fb_.head(na));
    if (config_.method == IvMethod::kRsrivc) {
      signal_disc_.set_denominator(theta_fb_.head(na));
      gain_ = config_.prefilter_gain == PrefilterGain::kUnitStaticGain
                  ? theta_fb_(na - 1)
                  : S(1);
    } else if (!svf_set_) {
      const Vector<S> d = svf_denominator<S>(na, config_.svf.lambda_svf);
      signal_disc_.set_denominator(d);
      input_disc_.set_denominator(d);
      gain_ = svf_gain<S>(na, config_.svf.lambda_svf, config_.svf.normalised);
      svf_set_ = true;
    }
  }

  RecursiveIvConfig<S> config_;
  SvfRegressor<S> ls_regressor_;
  // Standard form only (eqs. 2.29/2.30 and the RLSSVF start, 1.57/1.59).
  LeastSquaresUpdate<S, false> update_;
  LeastSquaresUpdate<S, false> windup_monitor_;
  Eigen::SelfAdjointEigenSolver<Matrix<S>> eigen_;
  S monitor_kappa_ = 1;
  bool armed_ = false, excited_ = true;
  S stage_start_ = 0;
  long resets_ = 0;
  FilterDiscretization<S> signal_disc_, input_disc_, aux_disc_;
  FilterChannel<S> y_channel_, xhat_channel_, uhat_channel_;
  std::vector<FilterChannel<S>> input_channels_, aux_channels_;
  std::vector<DelayLine<S>> delays_, aux_delays_;
  std::vector<DiscreteFilter<S>> m_filters_;
  DiscreteFilter<S> controller_;
  HurwitzTest<S> hurwitz_;
  Vector<S> phi_, zeta_, theta_m_, theta_fb_;
  S gain_ = 1;
  bool svf_set_ = false;
  S elapsed_ = 0, since_refresh_ = 0;
  S since_gap_ = std::numeric_limits<S>::infinity();
  bool gap_hold_ = false;
  bool first_ = true, iv_active_ = false;
  long rejections_ = 0;
  S prediction_error_ = 0, last_xhat_ = 0;
  DelayLine<S> uhat_delay_;
};

}  // namespace ctid

namespace ctid {

// r1 and r2 (N samples each) for the closed-loop methods; null otherwise.
template <typename S>
struct ClosedLoopSignals {
  const S* r1 = nullptr;
  const S* r2 = nullptr;
};

// Runs a RecursiveIv over a record (see run_rlssvf for the outputs).
// `rejections` (optional) receives the number of estimates refused by the
// stability test.
// Conditional-updating results of run_recursive_iv (optional, N values
// each): kappa_2(P) of the parallel RLSSVF-FF and 1/0 whether the
// estimates were updated at each sample.
template <typename S>
struct AntiWindupOutputs {
  S* monitor_kappa = nullptr;
  S* updating = nullptr;
  long resets = 0;
};

// Runs a RecursiveIv over a record (see run_rlssvf for the outputs).
// `rejections` (optional) receives the number of estimates refused by the
// stability test.
template <typename S>
Status run_recursive_iv(const RecursiveIvConfig<S>& config,
                        const RecordView<S>& record,
                        const ClosedLoopSignals<S>& loop,
                        const RecursiveOutputs<S>& out,
                        long* rejections = nullptr,
                        AntiWindupOutputs<S>* windup = nullptr) {
  Status status = validate_record(record, config.orders);
  if (!status.ok()) return status;
  const Eigen::Index n = record.num_samples;
  const S t_first = record.instants ? record.instants[0] : S(0);
  const S t_last =
      record.instants ? record.instants[n - 1] : (n - 1) * record.ts;
  if (config.t_s_iv > (t_last - t_first) * (1 + 1e-12)) {
    return bad_input(
        "tsiv = " + std::to_string(static_cast<double>(config.t_s_iv)) +
        " s lies outside the record (length " +
        std::to_string(static_cast<double>(t_last - t_first)) + " s)");
  }
  const S interval = record.interval(1 < n ? 1 : 0);
  if (config.dtupdate > 0 && config.dtupdate < interval * (1 - 1e-9)) {
    return bad_input("dtupdate must not be below the sampling interval (" +
                     std::to_string(static_cast<double>(interval)) + " s)");
  }
  if (config.closed_loop && (loop.r1 == nullptr || loop.r2 == nullptr)) {
    return bad_input("closed-loop estimation needs r1 and r2");
  }
  if (loop.r1 != nullptr) {
    for (Eigen::Index k = 0; k < n; ++k) {
      if (!std::isfinite(loop.r1[k]) || !std::isfinite(loop.r2[k])) {
        return bad_input("r1 and r2 must be finite");
      }
    }
  }
  RecursiveIvConfig<S> adjusted = config;
  adjusted.ts = record.ts;
  RecursiveIv<S> estimator;
  status = estimator.configure(adjusted);
  if (!status.ok()) return status;
  struct Adapter {
    RecursiveIv<S>& e;
    const ClosedLoopSignals<S>& loop;
    AntiWindupOutputs<S>* windup;
    const Vector<S>& update(const S* u, S y, S h, Eigen::Index k) {
      const S r1 = loop.r1 ? loop.r1[k] : S(0);
      const S r2 = loop.r2 ? loop.r2[k] : S(0);
      const Vector<S>& theta = e.update(u, y, h, r1, r2);
      if (windup != nullptr) {
        if (windup->monitor_kappa) windup->monitor_kappa[k] = e.monitor_kappa();
        if (windup->updating) windup->updating[k] = e.updating() ? 1 : 0;
      }
      return theta;
    }
    const Matrix<S>& covariance() const { return e.P(); }
    S kappa() const { return e.kappa(); }
    S prediction_error() const { return e.prediction_error(); }
    S innovation_scale() const { return e.innovation_scale(); }
    int covariance_guard() const { return e.covariance_guard(); }
  };
  const Status run = record_recursive_run(
      config.orders, config.svf.u_intersample, record, out,
      Adapter{estimator, loop, windup},
      "the scaling of the data, lambda_svf and tsiv", config.svf.kernels);
  if (rejections != nullptr) *rejections = estimator.stability_rejections();
  if (windup != nullptr) windup->resets = estimator.resets();
  return run;
}

}  // namespace ctid
