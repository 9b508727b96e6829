// SPDX-License-Identifier: BSD-3-Clause
// Copyright (C) the ctid authors
// Simulated output of a model whose parameters change from sample to
// sample: A(p, theta) x = sum_j B_j(p, theta) u_j, realised per input as
// A(p) w_j = u_j in controllable canonical form (the StateVariableFilter
// with D = A and unit gain) and x = sum_j B_j(p) w_j. The states are carried
// across parameter changes.
//
// It gives the auxiliary model of the IV methods, eq. (2.16), and the
// simulated output of the current frozen model, eq. (1.60), that the
// recursive routines return as YH.
#pragma once

#include <vector>

#include "ctid/base/delay_line.hpp"
#include "ctid/base/model.hpp"
#include "ctid/filters/svf.hpp"

namespace ctid {

template <typename S>
class AuxiliaryModel {
 public:
  AuxiliaryModel() = default;

  void configure(const ModelOrders& orders, InterSample u_intersample,
                 FilterKernels kernels = FilterKernels::kFixedSize) {
    orders_ = orders;
    disc_.configure(orders.na, u_intersample, kernels);
    channels_.resize(orders.num_inputs());
    delays_.resize(orders.num_inputs());
    for (int j = 0; j < orders.num_inputs(); ++j) {
      channels_[j].configure(orders.na);
      delays_[j].configure(orders.nk[j]);
    }
    theta_ = Vector<S>::Zero(orders.num_parameters());
  }

  void reset() {
    for (auto& c : channels_) c.reset();
    for (auto& d : delays_) d.reset();
  }

  // Parameters used from the next step on.
  template <typename Derived>
  void set_parameters(const Eigen::MatrixBase<Derived>& theta) {
    theta_ = theta;
    disc_.set_denominator(theta_.head(orders_.na));
  }

  // Feeds u(t_k); returns the model output x(t_k).
  S step(const S* u, S h) {
    S x = 0;
    disc_.ensure(h);
    for (int j = 0; j < orders_.num_inputs(); ++j) {
      channels_[j].step(disc_, S(1), delays_[j].push(u[j]));
      const Vector<S>& w = channels_[j].outputs();
      const int nb = orders_.nb[j];
      const int offset = orders_.numerator_offset(j);
      for (int l = 0; l < nb; ++l) x += theta_(offset + l) * w(nb - 1 - l);
    }
    return x;
  }

 private:
  ModelOrders orders_;
  FilterDiscretization<S> disc_;
  std::vector<FilterChannel<S>> channels_;
  std::vector<DelayLine<S>> delays_;
  Vector<S> theta_;
};

}  // namespace ctid
