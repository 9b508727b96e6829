// SPDX-License-Identifier: BSD-3-Clause
// Copyright (C) the ctid authors
// The filtered linear regression of the SVF methods, eqs. (1.24)-(1.27):
//
//   y_f^(na)(t_k) = phi_f^T(t_k) theta + v_f(t_k)
//   phi_f = [-y_f^(na-1) .. -y_f, u_1f^(nb_1-1) .. u_1f, u_2f^(nb_2-1) ..]
//
// built sample by sample from the filter channels of each signal. The input
// is filtered with the data's InterSample rule; the output, never piecewise
// constant, with the trapezoidal rule by default (Suggested procedure 3.3;
// see shared/implementation-notes.md, note 1).
#pragma once

#include <vector>

#include "ctid/base/delay_line.hpp"
#include "ctid/base/model.hpp"
#include "ctid/filters/discretization.hpp"
#include "ctid/filters/svf.hpp"

namespace ctid {

template <typename S>
struct SvfSettings {
  S lambda_svf = 1;
  bool normalised = true;  // (lambda/(p+lambda))^na, eq. (3.1)
  InterSample u_intersample = InterSample::kZoh;
  InterSample y_intersample = InterSample::kTrapezoid;
  // Trapezoidal and FOH channels start at rest at the first sample instead
  // of as a discrete filter from rest (see FilterChannel::reset).
  bool rest_at_first_sample = false;
  // Fixed-size filter kernels for orders 1-4 (companion_kernels.hpp), or the
  // dynamic-size reference.
  FilterKernels kernels = FilterKernels::kFixedSize;
};

template <typename S>
Status validate_svf_settings(const SvfSettings<S>& svf) {
  if (!(svf.lambda_svf > 0) || !std::isfinite(svf.lambda_svf)) {
    return bad_input("lambda_svf must be finite and > 0");
  }
  return Status::Ok();
}

template <typename S>
class SvfRegressor {
 public:
  SvfRegressor() = default;

  void configure(const ModelOrders& orders, const SvfSettings<S>& svf) {
    orders_ = orders;
    const int na = orders.na;
    const Vector<S> d = svf_denominator<S>(na, svf.lambda_svf);
    gain_ = svf_gain<S>(na, svf.lambda_svf, svf.normalised);
    y_disc_.configure(na, svf.y_intersample, svf.kernels);
    y_disc_.set_denominator(d);
    u_disc_.configure(na, svf.u_intersample, svf.kernels);
    u_disc_.set_denominator(d);
    y_channel_.configure(na);
    y_channel_.set_rest_at_first_sample(svf.rest_at_first_sample);
    u_channels_.resize(orders.num_inputs());
    delays_.resize(orders.num_inputs());
    for (int j = 0; j < orders.num_inputs(); ++j) {
      u_channels_[j].configure(na);
      u_channels_[j].set_rest_at_first_sample(svf.rest_at_first_sample);
      delays_[j].configure(orders.nk[j]);
    }
    phi_ = Vector<S>::Zero(orders.num_parameters());
    target_ = 0;
    // The fixed-size kernels of both discretisations (set by configure
    // above for these orders) allow the fixed-order step.
    fixed_order_ =
        y_disc_.propagator() != nullptr && u_disc_.propagator() != nullptr ? na
                                                                           : 0;
  }

  void reset() {
    y_channel_.reset();
    for (auto& c : u_channels_) c.reset();
    for (auto& d : delays_) d.reset();
  }

  // Feeds u(t_k) (num_inputs values) and y(t_k); h = t_k - t_(k-1).
  void step(const S* u, S y, S h) {
    switch (fixed_order_) {
      case 1:
        return step_order<1>(u, y, h);
      case 2:
        return step_order<2>(u, y, h);
      case 3:
        return step_order<3>(u, y, h);
      case 4:
        return step_order<4>(u, y, h);
      default:
        return step_order<Eigen::Dynamic>(u, y, h);
    }
  }

  const Vector<S>& phi() const { return phi_; }
  S target() const { return target_; }
  const ModelOrders& orders() const { return orders_; }

 private:
  // The step with na = N known at compile time (the fixed-size kernels:
  // the channels' propagation inlined, FilterChannel::step_fixed) or read
  // at run time (Eigen::Dynamic).
  template <int N>
  void step_order(const S* u, S y, S h) {
    const int na = N == Eigen::Dynamic ? orders_.na : N;
    y_disc_.ensure(h);
    u_disc_.ensure(h);
    channel_step<N>(y_channel_, y_disc_, y);
    const S* yf = y_channel_.outputs().data();
    S* phi = phi_.data();
    for (int i = 0; i < na; ++i) phi[i] = -yf[na - 1 - i];
    target_ = yf[na];
    int offset = na;
    for (int j = 0; j < orders_.num_inputs(); ++j) {
      channel_step<N>(u_channels_[j], u_disc_, delays_[j].push(u[j]));
      const S* uf = u_channels_[j].outputs().data();
      const int nb = orders_.nb[j];
      for (int l = 0; l < nb; ++l) phi[offset + l] = uf[nb - 1 - l];
      offset += nb;
    }
  }

  template <int N>
  void channel_step(FilterChannel<S>& channel,
                    const FilterDiscretization<S>& disc, S s) const {
    if constexpr (N == Eigen::Dynamic) {
      channel.step(disc, gain_, s);
    } else {
      channel.template step_fixed<N>(disc, gain_, s);
    }
  }

  ModelOrders orders_;
  FilterDiscretization<S> y_disc_;
  FilterDiscretization<S> u_disc_;
  FilterChannel<S> y_channel_;
  std::vector<FilterChannel<S>> u_channels_;
  S gain_ = 1;
  std::vector<DelayLine<S>> delays_;
  Vector<S> phi_;
  S target_ = 0;
  int fixed_order_ = 0;  // na of the fixed-order step, 0: dynamic
};

// Initial-condition regressors of RLSSVF, eqs. (3.36)-(3.41):
//
//   phi_ic(t_k) = [f_(na-1)(t_k) .. f_0(t_k)],
//
// f_i the impulse response of F_i(p) = g p^i / D(p) (D = (p + lambda)^na,
// g = lambda^na for the normalised SVF, 1 for the ordinary one), so that
// c_1 f_(na-1) + .. + c_na f_0 is the filtered effect of the unknown initial
// conditions, F(p) C(p) in eq. (3.34); for na = 1, c_1 = y(0). With
// z(t) = exp(F t) e_na (the canonical state after a unit impulse at the
// first sample), f_i(t) = g z_i(t); z is advanced by the exact matrix
// exponential of each interval.
template <typename S>
class InitialConditionRegressor {
 public:
  void configure(int na, S lambda_svf, bool normalised) {
    na_ = na;
    gain_ = svf_gain<S>(na, lambda_svf, normalised);
    F_ = companion_matrix<S>(svf_denominator<S>(na, lambda_svf));
    G_ = Matrix<S>::Zero(na, 1);
    Phi_ = Matrix<S>::Identity(na, na);
    Gamma_ = Matrix<S>::Zero(na, 1);
    z_ = Vector<S>::Zero(na);
    z_next_ = Vector<S>::Zero(na);
    phi_ = Vector<S>::Zero(na);
    h_ = 0;
    reset();
  }

  void reset() { first_ = true; }

  // Advances to the next sample; h = t_k - t_(k-1).
  void step(S h) {
    if (first_) {
      z_.setZero();
      z_(na_ - 1) = 1;
      first_ = false;
    } else {
      if (h != h_) {
        zoh_discretize<S>(F_, G_, h, Phi_, Gamma_);
        h_ = h;
      }
      z_next_.noalias() = Phi_ * z_;
      z_.swap(z_next_);
    }
    for (int j = 0; j < na_; ++j) phi_(j) = gain_ * z_(na_ - 1 - j);
  }

  const Vector<S>& phi() const { return phi_; }

 private:
  int na_ = 0;
  S gain_ = 1;
  Matrix<S> F_, G_, Phi_, Gamma_;
  Vector<S> z_, z_next_, phi_;
  S h_ = 0;
  bool first_ = true;
};

}  // namespace ctid
