// SPDX-License-Identifier: BSD-3-Clause
// Copyright (C) the ctid authors
// Discrete controllers for closed-loop simulation,
// u(t_k) = r1(t_k) + C(q^-1) (r2(t_k) - y(t_k)), thesis eq. (2.39).
//
// C(q^-1) = (c0 + c1 q^-1 + .. + cm q^-m) / (1 + d1 q^-1 + .. + dn q^-n).
#pragma once

#include <cmath>
#include <vector>

#include "ctid/base/status.hpp"
#include "ctid/base/types.hpp"

namespace ctid {

template <typename S>
struct DiscreteTransferFunction {
  Vector<S> numerator;    // c0 .. cm
  Vector<S> denominator;  // 1, d1 .. dn (normalised so that d0 = 1)
};

template <typename S>
Status validate_controller(const DiscreteTransferFunction<S>& c) {
  if (c.numerator.size() == 0 || c.denominator.size() == 0) {
    return bad_input("the controller needs a numerator and a denominator");
  }
  if (!c.numerator.allFinite() || !c.denominator.allFinite()) {
    return bad_input("the controller coefficients must be finite");
  }
  if (c.denominator(0) == S(0)) {
    return bad_input(
        "the controller denominator must have a non-zero "
        "leading coefficient (a causal controller)");
  }
  return Status::Ok();
}

// Backward-Euler discretisation of the continuous PID
//   C = kp + ki Ts / (1 - q^-1) + (kd / Ts) (1 - q^-1),
// the reading of thesis eq. (2.55) that keeps example 2.4.6 stable
// (shared/implementation-notes.md, note 3).
template <typename S>
DiscreteTransferFunction<S> pid_backward_euler(S kp, S ki, S kd, S ts) {
  DiscreteTransferFunction<S> c;
  c.numerator.resize(3);
  c.numerator << kp + ki * ts + kd / ts, -kp - 2 * kd / ts, kd / ts;
  c.denominator.resize(2);
  c.denominator << 1, -1;
  return c;
}

// Runs C(q^-1) sample by sample; the direct-feedthrough term c0 is exposed
// so that a loop with feedthrough in the plant can be solved exactly.
template <typename S>
class DiscreteFilter {
 public:
  void configure(const DiscreteTransferFunction<S>& c) {
    const S d0 = c.denominator(0);
    b_ = c.numerator / d0;
    a_ = c.denominator / d0;
    in_.assign(b_.size(), S(0));
    out_.assign(a_.size(), S(0));
  }
  void reset() {
    std::fill(in_.begin(), in_.end(), S(0));
    std::fill(out_.begin(), out_.end(), S(0));
  }
  S feedthrough() const { return b_(0); }
  // Output for input e(t_k) = 0, i.e. the part due to past samples.
  S free_response() const {
    S v = 0;
    for (Eigen::Index i = 1; i < b_.size(); ++i) v += b_(i) * in_[i - 1];
    for (Eigen::Index i = 1; i < a_.size(); ++i) v -= a_(i) * out_[i - 1];
    return v;
  }
  // Commits e(t_k) and returns v(t_k).
  S step(S e) {
    const S v = feedthrough() * e + free_response();
    shift(in_, e);
    shift(out_, v);
    return v;
  }

 private:
  static void shift(std::vector<S>& history, S value) {
    if (history.empty()) return;
    for (std::size_t i = history.size() - 1; i > 0; --i) {
      history[i] = history[i - 1];
    }
    history[0] = value;
  }
  Vector<S> b_;
  Vector<S> a_;
  std::vector<S> in_;   // e(t_(k-1)), e(t_(k-2)), ..
  std::vector<S> out_;  // v(t_(k-1)), ..
};

}  // namespace ctid
