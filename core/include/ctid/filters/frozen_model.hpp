// SPDX-License-Identifier: BSD-3-Clause
// Copyright (C) the ctid authors
// Simulated output of the frozen model, eq. (1.60): at every sample t_k the
// current estimate theta(t_k) = [a_1 .. a_na, b's] is taken as the model
// A(p) x = sum_j B_j(p) u_j over the interval (t_(k-1), t_k], the states
// carried across the changes of parameters; the recursive routines return
// x(t_k) as YH.
//
// The same output as AuxiliaryModel (auxiliary_model.hpp: per input, A(p)
// w_j = u_j in controllable canonical form, x = sum_j B_j(p) w_j), but
// the denominator changes at every sample and its Phi would be applied to a
// single state per input: for ZOH inputs and orders 1-4 with the fixed-size
// kernels, each state is advanced by CompanionZohAdvance
// (companion_kernels.hpp), the action of the augmented matrix exponential on
// the state, O(n) per Taylor term, instead of forming Phi and Gamma (a
// matrix exponential) and multiplying. Where that series does not apply
// (prepare() false: non-finite or extreme coefficients, very fast poles
// relative to h) the sample takes the matrix kernels, as before; other
// rules, orders or FilterKernels::kDynamic (the reference) are an
// AuxiliaryModel. No allocation per sample.
#pragma once

#include <vector>

#include "ctid/base/delay_line.hpp"
#include "ctid/base/model.hpp"
#include "ctid/filters/auxiliary_model.hpp"
#include "ctid/filters/companion_kernels.hpp"
#include "ctid/filters/svf.hpp"

namespace ctid {

template <typename S>
class FrozenModel {
 public:
  void configure(const ModelOrders& orders, InterSample u_intersample,
                 FilterKernels kernels = FilterKernels::kFixedSize) {
    orders_ = orders;
    n_ = orders.na;
    series_ = u_intersample == InterSample::kZoh &&
              kernels == FilterKernels::kFixedSize && n_ >= 1 &&
              n_ <= kMaxFixedOrder;
    theta_ = Vector<S>::Zero(orders.num_parameters());
    if (!series_) {
      general_.configure(orders, u_intersample, kernels);
      return;
    }
    const int nu = orders.num_inputs();
    disc_.configure(n_, u_intersample, kernels);
    states_ = Matrix<S>::Zero(n_, nu);
    s_prev_.assign(nu, S(0));
    offsets_.resize(nu);
    delays_.resize(nu);
    for (int j = 0; j < nu; ++j) {
      offsets_[j] = orders.numerator_offset(j);
      delays_[j].configure(orders.nk[j]);
    }
    first_ = true;
  }

  void reset() {
    if (!series_) {
      general_.reset();
      return;
    }
    states_.setZero();
    for (auto& d : delays_) d.reset();
    first_ = true;
  }

  // Parameters used from the next step on.
  template <typename Derived>
  void set_parameters(const Eigen::MatrixBase<Derived>& theta) {
    if (!series_) {
      general_.set_parameters(theta);
      return;
    }
    theta_ = theta;
  }

  // Feeds u(t_k), t_k - t_(k-1) = h; returns the model output x(t_k).
  S step(const S* u, S h) {
    if (!series_) return general_.step(u, h);
    switch (n_) {
      case 1:
        return step_fixed<1>(u, h);
      case 2:
        return step_fixed<2>(u, h);
      case 3:
        return step_fixed<3>(u, h);
      default:
        return step_fixed<4>(u, h);
    }
  }

 private:
  // AuxiliaryModel::step with the states advanced by the series: the same
  // ZOH (input held at s(t_(k-1))), the first sample at rest, the outputs
  // w_i = z_i (i < n) and w_n = s - sum_i d_i z_(n-1-i) in the same order.
  template <int N>
  S step_fixed(const S* u, S h) {
    const S* d = theta_.data();
    CompanionZohAdvance<N, S>& series = series_kernel<N>();
    const bool use_series = !first_ && series.prepare(d, h);
    if (!first_ && !use_series) {
      disc_.set_denominator(theta_.head(N));
      disc_.ensure(h);
    }
    S x = 0;
    for (int j = 0; j < int(offsets_.size()); ++j) {
      const S s = delays_[j].push(u[j]);
      S* z = states_.data() + j * N;
      if (first_) {
        // at rest at t_1 (ZOH)
      } else if (use_series) {
        series.advance(z, s_prev_[j]);
      } else {
        disc_.propagator()(disc_.Phi().data(), disc_.Gamma().data(), z,
                           s_prev_[j]);
      }
      s_prev_[j] = s;
      S highest = s;
#pragma GCC unroll 4
      for (int i = 0; i < N; ++i) highest -= d[i] * z[N - 1 - i];
      const int nb = orders_.nb[j];
      for (int l = 0; l < nb; ++l) {
        const int derivative = nb - 1 - l;
        x += theta_(offsets_[j] + l) *
             (derivative < N ? z[derivative] : highest);
      }
    }
    first_ = false;
    return x;
  }

  template <int N>
  CompanionZohAdvance<N, S>& series_kernel() {
    if constexpr (N == 1) {
      return series1_;
    } else if constexpr (N == 2) {
      return series2_;
    } else if constexpr (N == 3) {
      return series3_;
    } else {
      return series4_;
    }
  }

  ModelOrders orders_;
  int n_ = 0;
  bool series_ = false;
  bool first_ = true;
  Vector<S> theta_;
  Matrix<S> states_;  // n-by-nu, column j the state of input j
  std::vector<S> s_prev_;
  std::vector<int> offsets_;
  std::vector<DelayLine<S>> delays_;
  FilterDiscretization<S> disc_;  // the samples the series does not take
  AuxiliaryModel<S> general_;     // other rules, orders, kDynamic
  // The series of each order (they keep the terms of the last interval).
  CompanionZohAdvance<1, S> series1_;
  CompanionZohAdvance<2, S> series2_;
  CompanionZohAdvance<3, S> series3_;
  CompanionZohAdvance<4, S> series4_;
};

}  // namespace ctid
