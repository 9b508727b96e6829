// SPDX-License-Identifier: BSD-3-Clause
// Copyright (C) the ctid authors

// A discrete-time filter C(q^-1) = (c0 + c1 q^-1 + .. + cm q^-m) /
// (d0 + d1 q^-1 + .. + dn q^-n), d0 != 0, run sample by sample: the
// controllers of closed-loop simulation (simulation/controller.hpp) and the
// Focus prefilter (focus_filter.hpp).
#pragma once

#include <algorithm>
#include <vector>

#include "ctid/base/types.hpp"

namespace ctid {

template <typename S>
struct DiscreteTransferFunction {
  Vector<S> numerator;    // c0 .. cm
  Vector<S> denominator;  // d0 .. dn (DiscreteFilter divides by d0)
};

// Runs C(q^-1) sample by sample, at rest before the first sample; the
// direct-feedthrough term c0 is exposed so that a loop with feedthrough in
// the plant can be solved exactly.
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
