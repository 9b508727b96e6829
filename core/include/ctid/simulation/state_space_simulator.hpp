// SPDX-License-Identifier: BSD-3-Clause
// Copyright (C) the ctid authors

// Output of the continuous-time state-space model
//
//   x'(t) = A x(t) + sum_j b_j u_j(t - tau_ij Ts)   (into output i),
//   y_i(t) = c_i x(t) + sum_j d_ij u_j(t - tau_ij Ts),
//
// from rest, at the sampling instants of the input, exact for an input held
// (ZOH) or linear (FOH) between samples. Each interval h is integrated with
// the exact hold of discretization.hpp (the exponential of the augmented
// matrix [A B 0; 0 0 I/h; 0 0 0] h, Van Loan; thesis App. A.1, eq. A.6 and
// its first-order-hold extension), taken through the balanced exponential
// because a user's A may be scaled arbitrarily:
//
//   x(t_k+1) = Phi x(t_k) + Gamma0 v(t_k) + Gamma1 (v(t_k+1) - v(t_k)).
//
// Delays tau_ij in samples. Integer delays shift the samples of the input
// (the outputs that share one row of delays are simulated together). A
// fractional delay m + phi (0 < phi < 1, uniform sampling only) moves the
// instant where the delayed input changes (ZOH) or bends (FOH) to phi Ts
// after each sample: every interval is integrated exactly in two pieces,
// phi Ts and (1 - phi) Ts, one input and one output at a time (the
// responses add up by linearity). The input is zero before the record.
#pragma once

#include <cmath>
#include <string>
#include <vector>

#include "ctid/base/record.hpp"
#include "ctid/base/status.hpp"
#include "ctid/base/types.hpp"
#include "ctid/filters/discretization.hpp"

namespace ctid {

template <typename S>
struct StateSpaceModel {
  Matrix<S> a;       // n-by-n
  Matrix<S> b;       // n-by-nu
  Matrix<S> c;       // ny-by-n
  Matrix<S> d;       // ny-by-nu
  Matrix<S> delays;  // ny-by-nu, in samples (>= 0); empty: no delays
};

template <typename S>
Status validate_state_space(const StateSpaceModel<S>& model) {
  const Eigen::Index n = model.a.rows();
  if (model.a.cols() != n) return dimension_mismatch("A must be square");
  const Eigen::Index nu = model.b.cols();
  const Eigen::Index ny = model.c.rows();
  if (model.b.rows() != n) {
    return dimension_mismatch("B must have as many rows as A (" +
                              std::to_string(n) + ")");
  }
  if (model.c.cols() != n) {
    return dimension_mismatch("C must have as many columns as A (" +
                              std::to_string(n) + ")");
  }
  if (model.d.rows() != ny || model.d.cols() != nu) {
    return dimension_mismatch("D must be " + std::to_string(ny) + "-by-" +
                              std::to_string(nu) +
                              " (rows of C by columns "
                              "of B)");
  }
  if (model.delays.size() != 0 &&
      (model.delays.rows() != ny || model.delays.cols() != nu)) {
    return dimension_mismatch("the delays must be " + std::to_string(ny) +
                              "-by-" + std::to_string(nu));
  }
  if (!model.a.allFinite() || !model.b.allFinite() || !model.c.allFinite() ||
      !model.d.allFinite()) {
    return bad_input("A, B, C and D must be finite");
  }
  for (Eigen::Index i = 0; i < model.delays.size(); ++i) {
    const S tau = model.delays.data()[i];
    if (!std::isfinite(tau) || tau < 0) {
      return bad_input("the delays must be finite and >= 0");
    }
  }
  return Status::Ok();
}

namespace detail {

// Exact hold propagator of one interval length, recomputed only when the
// length changes (irregular sampling).
template <typename S>
struct HoldPropagator {
  Matrix<S> phi, gamma0, gamma1;
  S h = S(-1);

  void prepare(const Matrix<S>& a, const Matrix<S>& b, S length) {
    if (length == h) return;
    foh_discretize_balanced<S>(a, b, length, phi, gamma0, gamma1);
    h = length;
  }
};

// The outputs `rows` of the model driven by the input v (N-by-nu, already
// delayed), integer delays only; written into the same rows of y (N-by-ny).
template <typename S>
void simulate_shifted(const StateSpaceModel<S>& model,
                      const std::vector<Eigen::Index>& rows, const Matrix<S>& v,
                      bool foh, const RecordView<S>& record, Matrix<S>& y) {
  const Eigen::Index n = model.a.rows();
  const Eigen::Index num = v.rows();
  HoldPropagator<S> hold;
  Vector<S> x = Vector<S>::Zero(n);
  Vector<S> next(n);
  for (Eigen::Index k = 0; k < num; ++k) {
    for (Eigen::Index r : rows) {
      y(k, r) = model.c.row(r).dot(x) + model.d.row(r).dot(v.row(k));
    }
    if (k + 1 == num) break;
    hold.prepare(model.a, model.b, record.interval(k + 1));
    next.noalias() = hold.phi * x;
    next.noalias() += hold.gamma0 * v.row(k).transpose();
    if (foh) {
      next.noalias() += hold.gamma1 * (v.row(k + 1) - v.row(k)).transpose();
    }
    x = next;
  }
}

// Output i driven by input j through a delay of m + phi samples, 0 < phi <
// 1, added into y (N values). On [t_k, t_k + phi Ts) the delayed input is
// the piece that starts at sample k - m - 1, on [t_k + phi Ts, t_k+1) the
// piece that starts at sample k - m.
template <typename S>
void add_fractional(const StateSpaceModel<S>& model, Eigen::Index i,
                    Eigen::Index j, S delay, bool foh,
                    const RecordView<S>& record, S* y) {
  const Eigen::Index num = record.num_samples;
  const Eigen::Index n = model.a.rows();
  const Eigen::Index m = static_cast<Eigen::Index>(std::floor(delay));
  const S phi = delay - static_cast<S>(m);
  const S ts = record.ts;
  const Matrix<S> b = model.b.col(j);
  HoldPropagator<S> first;
  HoldPropagator<S> second;
  first.prepare(model.a, b, phi * ts);
  second.prepare(model.a, b, (1 - phi) * ts);
  auto sample = [&](Eigen::Index k) {
    return k >= 0 && k < num ? record.u_at(k, j) : S(0);
  };
  const S d = model.d(i, j);
  Vector<S> x = Vector<S>::Zero(n);
  Vector<S> next(n);
  for (Eigen::Index k = 0; k < num; ++k) {
    const Eigen::Index p = k - m - 1;  // the piece in force at t_k
    const S step1 = foh ? sample(p + 1) - sample(p) : S(0);
    const S v0 = sample(p) + (1 - phi) * step1;  // delayed input at t_k
    y[k] += model.c.row(i).dot(x) + d * v0;
    if (k + 1 == num) break;
    next.noalias() = first.phi * x;
    next += first.gamma0.col(0) * v0 + first.gamma1.col(0) * (phi * step1);
    const S step2 = foh ? sample(p + 2) - sample(p + 1) : S(0);
    x.noalias() = second.phi * next;
    x += second.gamma0.col(0) * sample(p + 1) +
         second.gamma1.col(0) * ((1 - phi) * step2);
  }
}

}  // namespace detail

// y (N-by-ny) of the model driven by record.u (N-by-nu) from rest.
// record.y is not read. Fractional delays need a constant sampling
// interval (record.instants null).
template <typename S>
Status simulate_state_space(const StateSpaceModel<S>& model, InterSample rule,
                            const RecordView<S>& record, Matrix<S>& y) {
  Status status = validate_state_space(model);
  if (!status.ok()) return status;
  if (rule == InterSample::kTrapezoid) {
    return bad_input(
        "the exact simulation needs a ZOH or FOH input, not the trapezoidal "
        "rule");
  }
  const Eigen::Index nu = model.b.cols();
  const Eigen::Index ny = model.c.rows();
  const Eigen::Index num = record.num_samples;
  if (record.num_inputs != nu) {
    return dimension_mismatch("u has " + std::to_string(record.num_inputs) +
                              " column(s) but the model has " +
                              std::to_string(nu) + " input(s)");
  }
  if (num < 1) return bad_input("the record is empty");
  for (Eigen::Index i = 0; i < num * nu; ++i) {
    if (!std::isfinite(record.u[i])) return bad_input("u must be finite");
  }
  if (record.instants == nullptr &&
      (!(record.ts > 0) || !std::isfinite(record.ts))) {
    return bad_input("the sampling interval Ts must be finite and > 0");
  }
  Matrix<S> delays = model.delays;
  if (delays.size() == 0) delays = Matrix<S>::Zero(ny, nu);
  const bool foh = rule == InterSample::kFoh;
  bool any_fractional = false;
  for (Eigen::Index i = 0; i < delays.size(); ++i) {
    const S tau = delays.data()[i];
    any_fractional = any_fractional || tau != std::floor(tau);
  }
  if (any_fractional && record.instants != nullptr) {
    return not_supported("fractional delays need uniformly sampled data");
  }
  y = Matrix<S>::Zero(num, ny);

  // The pairs with an integer delay: the outputs that share a row of delays
  // together, each input shifted by its delay.
  std::vector<bool> done(ny, false);
  Matrix<S> v(num, nu);
  for (Eigen::Index i = 0; i < ny; ++i) {
    if (done[i]) continue;
    std::vector<Eigen::Index> rows{i};
    done[i] = true;
    for (Eigen::Index r = i + 1; r < ny; ++r) {
      if (!done[r] && delays.row(r) == delays.row(i)) {
        rows.push_back(r);
        done[r] = true;
      }
    }
    for (Eigen::Index j = 0; j < nu; ++j) {
      const S tau = delays(i, j);
      // a fractional delay's input is left out here (added below)
      const Eigen::Index shift = tau == std::floor(tau) && tau < S(num)
                                     ? static_cast<Eigen::Index>(tau)
                                     : num;
      for (Eigen::Index k = 0; k < num; ++k) {
        v(k, j) = k >= shift ? record.u_at(k - shift, j) : S(0);
      }
    }
    detail::simulate_shifted(model, rows, v, foh, record, y);
  }
  for (Eigen::Index i = 0; i < ny; ++i) {
    for (Eigen::Index j = 0; j < nu; ++j) {
      const S tau = delays(i, j);
      if (tau == std::floor(tau) || tau >= S(num)) continue;
      detail::add_fractional(model, i, j, tau, foh, record, y.col(i).data());
    }
  }
  for (Eigen::Index i = 0; i < y.size(); ++i) {
    if (!std::isfinite(y.data()[i])) {
      return numerical_failure(
          "the simulated output is not finite (an unstable model or a "
          "record too long for it)");
    }
  }
  return Status::Ok();
}

}  // namespace ctid
