// SPDX-License-Identifier: BSD-3-Clause
// Copyright (C) the ctid authors
// Discrete controllers for closed-loop simulation,
// u(t_k) = r1(t_k) + C(q^-1) (r2(t_k) - y(t_k)), thesis eq. (2.39).
//
// C(q^-1) = (c0 + c1 q^-1 + .. + cm q^-m) / (1 + d1 q^-1 + .. + dn q^-n).
#pragma once

#include <cmath>

#include "ctid/base/status.hpp"
#include "ctid/base/types.hpp"
#include "ctid/filters/discrete_filter.hpp"

namespace ctid {

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

}  // namespace ctid
