// SPDX-License-Identifier: BSD-3-Clause
// Copyright (C) the ctid authors
// Simulation of an LTI model with effect terms fed by its own output, the
// model structures of residtrace:
//
//   F(p) x(t) = sum_j B_j(p) w_j(t - nk_j Ts),   y = x + output terms,
//
// where a channel w_j is either an exogenous signal (an input, a constant,
// a clipped or powered input, computed by the caller) or a function of the
// model's own state, re-evaluated at every sub-step:
//   - sign(v), v = dx/dt the simulated velocity (Coulomb friction, thesis
//     eq. 4.17; for a first-order model v = x, the output read as a
//     velocity), or sign(x + y_off) (Coulomb on an output that is a
//     velocity);
//   - (x + y_off)^p, a fractional p keeping the sign (sign(y)|y|^p: the
//     sqrt outflow of a tank; an integer p a hardening spring).
// In closed loop the first input is u1 = r1 + C(q^-1)(r2 - y_k), the
// discrete controller acting on the sampled output y_k = x + y_off +
// c2 x^2 + c3 x^3 + s_k (s: known additive output terms); the channels
// that are the first input, its powers or its clipped value are then
// recomputed from u1.
//
// The model is stepped in observable canonical form (x1 = x, x1' = -f1 x1
// + x2 + b_(1) w, ...) through each sampling interval in `substeps` equal
// sub-steps, each exact for inputs held over the sub-step: [Phi Gamma] =
// expm([A B; 0 0] h) (thesis App. A.1, eq. A.6). Exogenous channels are
// held over the sampling interval (ZOH). With per-sample coefficients
// (f_t, b_t) the sub-step map of each interval uses the coefficients of
// its first sample, recomputed only when they change.
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "ctid/base/status.hpp"
#include "ctid/base/types.hpp"
#include "ctid/filters/discretization.hpp"

namespace ctid {

enum class EffectChannelKind {
  kExogenous,        // column j of the channel signals W, delayed by nk_j
  kSignVelocity,     // sign(dx/dt) (sign(x) for a first-order model)
  kSignOutput,       // sign(x + y_off)
  kOutputPower,      // (x + y_off)^p
  kControlledInput,  // closed loop: u1 (delayed by nk_j)
  kControlledPower,  // closed loop: u1^p
  kControlledClip,   // closed loop: min(max(u1, -c), c)
};

template <typename S>
struct EffectSimulationConfig {
  Vector<S> f;  // f1..fn of the monic F (n >= 1)
  Matrix<S> b;  // n-by-m: column j holds B_j right-aligned (b_(n) last)
  std::vector<EffectChannelKind> kinds;  // m entries
  std::vector<int> delays;               // m entries, samples (>= 0)
  std::vector<S> params;                 // m entries: p or c (else unused)
  S ts = 1;                              // sampling interval (s)
  S y_off = 0;                           // output offset seen by the channels
  int substeps = 1;
  // Closed loop (controller_den empty: open loop).
  Vector<S> controller_num;
  Vector<S> controller_den;
  S poly2 = 0;  // c2, c3 of the sampled output y = x + y_off + c2 x^2 + c3 x^3
  S poly3 = 0;
  // Time-varying coefficients (empty: constant): N-by-n and N-by-(n m),
  // column block j of b_t holding the n rows of channel j.
  Matrix<S> f_t;
  Matrix<S> b_t;
};

// Channel signals W (N-by-m, exogenous columns; others ignored), r1 (N,
// closed loop: the external part of u1), r2 (N, the reference) and s (N,
// additive sampled output terms) as column-major arrays; r1/r2/s may be
// null in open loop. Writes x (N) and, when u_applied != nullptr, u1 (N).
template <typename S>
Status simulate_effect_model(const EffectSimulationConfig<S>& c, const S* W,
                             Eigen::Index num_samples, const S* r1, const S* r2,
                             const S* s, S* x, S* u_applied) {
  const Eigen::Index n = c.f.size();
  const Eigen::Index m = c.b.cols();
  const Eigen::Index N = num_samples;
  if (n < 1) return bad_input("the model needs an order n >= 1");
  if (c.b.rows() != n) {
    return dimension_mismatch("b must have n = " + std::to_string(n) + " rows");
  }
  if (static_cast<Eigen::Index>(c.kinds.size()) != m ||
      static_cast<Eigen::Index>(c.delays.size()) != m ||
      static_cast<Eigen::Index>(c.params.size()) != m) {
    return dimension_mismatch(
        "kinds, delays and params need one entry per "
        "channel");
  }
  if (c.substeps < 1) return bad_input("substeps must be >= 1");
  if (!(c.ts > 0)) return bad_input("ts must be > 0");
  const bool closed = c.controller_den.size() > 0;
  if (closed && (c.controller_num.size() == 0 || c.controller_den[0] == 0 ||
                 r1 == nullptr || r2 == nullptr)) {
    return bad_input(
        "the closed loop needs a controller with den(1) != 0, "
        "r1 and r2");
  }
  const bool varying = c.f_t.size() > 0;
  if (varying && (c.f_t.rows() != N || c.f_t.cols() != n || c.b_t.rows() != N ||
                  c.b_t.cols() != n * m)) {
    return dimension_mismatch("f_t must be N-by-n and b_t N-by-(n m)");
  }
  for (Eigen::Index j = 0; j < m; ++j) {
    const EffectChannelKind k = c.kinds[j];
    if (c.delays[j] < 0) return bad_input("delays must be >= 0");
    const bool controlled = k == EffectChannelKind::kControlledInput ||
                            k == EffectChannelKind::kControlledPower ||
                            k == EffectChannelKind::kControlledClip;
    if (controlled && !closed) {
      return bad_input("a controlled-input channel needs the closed loop");
    }
  }

  Matrix<S> A = Matrix<S>::Zero(n, n);
  A.col(0) = -c.f;
  if (n > 1) A.topRightCorner(n, n - 1).setIdentity();
  Matrix<S> Bc = c.b;
  const S h = c.ts / c.substeps;
  Matrix<S> Phi, Gamma;
  zoh_discretize<S>(A, Bc, h, Phi, Gamma);

  Vector<S> state = Vector<S>::Zero(n);
  Vector<S> w = Vector<S>::Zero(m);
  std::vector<S> u1;
  if (closed) u1.assign(static_cast<std::size_t>(N), S(0));
  const Eigen::Index ncn = c.controller_num.size();
  const Eigen::Index ncd = c.controller_den.size();
  Vector<S> ebuf = Vector<S>::Zero(ncn);
  Vector<S> ubuf = Vector<S>::Zero(ncd);
  const bool first_order = (n == 1);

  auto power = [](S y, S p) {
    if (p == std::floor(p)) return std::pow(y, p);
    const S a = std::pow(std::abs(y), p);
    return y > 0 ? a : (y < 0 ? -a : S(0));
  };
  auto sign = [](S v) { return v > 0 ? S(1) : (v < 0 ? S(-1) : S(0)); };

  for (Eigen::Index k = 0; k < N; ++k) {
    if (varying && (k == 0 || c.f_t.row(k) != c.f_t.row(k - 1) ||
                    c.b_t.row(k) != c.b_t.row(k - 1))) {
      A.col(0) = -c.f_t.row(k).transpose();
      for (Eigen::Index j = 0; j < m; ++j) {
        Bc.col(j) = c.b_t.row(k).segment(j * n, n).transpose();
      }
      zoh_discretize<S>(A, Bc, h, Phi, Gamma);
    }
    const S xk = state[0];
    x[k] = xk;
    if (closed) {
      const S yk = xk + c.y_off + c.poly2 * xk * xk + c.poly3 * xk * xk * xk +
                   (s != nullptr ? s[k] : S(0));
      for (Eigen::Index i = ncn - 1; i > 0; --i) ebuf[i] = ebuf[i - 1];
      ebuf[0] = r2[k] - yk;
      S acc = c.controller_num.dot(ebuf);
      for (Eigen::Index i = 1; i < ncd; ++i)
        acc -= c.controller_den[i] * ubuf[i - 1];
      const S uc = acc / c.controller_den[0];
      for (Eigen::Index i = ncd - 1; i > 0; --i) ubuf[i] = ubuf[i - 1];
      if (ncd > 0) ubuf[0] = uc;
      u1[static_cast<std::size_t>(k)] = r1[k] + uc;
      if (u_applied != nullptr) u_applied[k] = u1[static_cast<std::size_t>(k)];
    }
    for (Eigen::Index j = 0; j < m; ++j) {
      const Eigen::Index kk = k - c.delays[j];
      switch (c.kinds[j]) {
        case EffectChannelKind::kExogenous:
          w[j] = kk >= 0 ? W[j * N + kk] : S(0);
          break;
        case EffectChannelKind::kControlledInput:
          w[j] = kk >= 0 ? u1[static_cast<std::size_t>(kk)] : S(0);
          break;
        case EffectChannelKind::kControlledPower:
          w[j] = kk >= 0
                     ? std::pow(u1[static_cast<std::size_t>(kk)], c.params[j])
                     : S(0);
          break;
        case EffectChannelKind::kControlledClip:
          w[j] = kk >= 0 ? std::min(std::max(u1[static_cast<std::size_t>(kk)],
                                             -c.params[j]),
                                    c.params[j])
                         : S(0);
          break;
        default:
          break;
      }
    }
    for (int sub = 0; sub < c.substeps; ++sub) {
      S v = 0;
      bool have_v = false;
      for (Eigen::Index j = 0; j < m; ++j) {
        switch (c.kinds[j]) {
          case EffectChannelKind::kSignVelocity:
            if (!have_v) {
              if (first_order) {
                v = state[0];
              } else {
                // x1' = -f1 x1 + x2 + the direct terms of the exogenous
                // and controlled channels (those not fed by the state)
                v = A.row(0).dot(state);
                for (Eigen::Index i = 0; i < m; ++i) {
                  const EffectChannelKind ki = c.kinds[i];
                  if (ki != EffectChannelKind::kSignVelocity &&
                      ki != EffectChannelKind::kSignOutput &&
                      ki != EffectChannelKind::kOutputPower) {
                    v += Bc(0, i) * w[i];
                  }
                }
              }
              have_v = true;
            }
            w[j] = sign(v);
            break;
          case EffectChannelKind::kSignOutput:
            w[j] = sign(state[0] + c.y_off);
            break;
          case EffectChannelKind::kOutputPower:
            w[j] = power(state[0] + c.y_off, c.params[j]);
            break;
          default:
            break;
        }
      }
      state = Phi * state + Gamma * w;
    }
    if (!state.allFinite()) {
      for (Eigen::Index i = k + 1; i < N; ++i) {
        x[i] = std::numeric_limits<S>::quiet_NaN();
      }
      return Status::Ok();  // a diverging model: NaN from here on
    }
  }
  return Status::Ok();
}

}  // namespace ctid
