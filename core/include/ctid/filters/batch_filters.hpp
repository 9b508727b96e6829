// SPDX-License-Identifier: BSD-3-Clause
// Copyright (C) the ctid authors
// Batch filters: a whole record through a continuous-time filter 1/D(p),
// the derivatives p^i s / D(p), i = 0..n, as the columns of a matrix (the
// refined instrumental-variable engine, refined_iv_engine.hpp, and the
// estimators built on it: refined_iv_bj.hpp, hammerstein.hpp,
// output_error.hpp). The discretisation of each interval is that of the
// per-sample filters (svf.hpp): discretize() of discretization.hpp, by the
// rule discretisation_of() gives for the signal's InterSample (the
// per-sample filters of orders 1-4 compute the same matrices with the
// fixed-size kernels of companion_kernels.hpp, equal to a few roundoffs),
// so that the same record filtered sample by sample and in one batch
// agrees to rounding (tests/core/batch_filters_test.cpp).
//
// The filter starts at rest at the first sample (FilterChannel's
// rest_at_first_sample). Irregular sampling: the intervals of the time
// base (Clock), each discretised; a continuous input delay is handled by
// stepping between the breakpoints of the delayed signal.
#pragma once

#include <algorithm>
#include <cmath>
#include <vector>

#include "ctid/base/types.hpp"
#include "ctid/filters/discretization.hpp"
#include "ctid/filters/svf.hpp"

namespace ctid {
namespace batch {

// Sampling intervals in the scaled time t' = sigma t.
template <typename S>
struct Clock {
  S ts = 0;
  const S* instants = nullptr;
  Eigen::Index n = 0;
  S sigma = 1;
  S interval(Eigen::Index k) const {
    if (instants == nullptr) return sigma * ts;
    if (k == 0) return sigma * (instants[1] - instants[0]);
    return sigma * (instants[k] - instants[k - 1]);
  }
  S duration() const {
    if (instants == nullptr) return ts * static_cast<S>(n - 1);
    return instants[n - 1] - instants[0];
  }
  S median_interval() const {
    if (instants == nullptr) return ts;
    std::vector<S> d(static_cast<std::size_t>(n - 1));
    for (Eigen::Index k = 1; k < n; ++k)
      d[k - 1] = instants[k] - instants[k - 1];
    std::nth_element(d.begin(), d.begin() + d.size() / 2, d.end());
    return d[d.size() / 2];
  }
};

// The discretised filter 1/D(p) in controllable canonical form, state
// z = [w .. w^(n-1)] for D(p) w = s, by the rule of the signal's
// InterSample (discretisation_of, discretization.hpp): z_k = Phi z_(k-1) +
// G0 s_(k-1) + G1 (s_k - s_(k-1)), the matrices of discretize(), which the
// per-sample filters (svf.hpp) share: exact ZOH (App. A.1, G1 = 0), exact
// FOH (s linear between samples) or the trapezoidal rule (App. A.2).
template <typename S>
class CompanionFilter {
 public:
  CompanionFilter(const Vector<S>& d, InterSample rule)
      : d_(d), rule_(discretisation_of(rule)) {
    n_ = static_cast<int>(d.size());
    A_ = companion_matrix<S>(d);
    G_ = Matrix<S>::Zero(n_, 1);
    G_(n_ - 1, 0) = 1;
    z_ = Vector<S>::Zero(n_);
    next_ = z_;
  }
  // Two discretisations are kept (the last two step lengths, equal within
  // a relative 1e-12): a continuously delayed input alternates between two
  // sub-step lengths (filter_delayed_derivatives).
  void ensure(S h) {
    if (same_length(h, h_)) return;
    if (same_length(h, h2_)) {
      std::swap(h_, h2_);
      Phi_.swap(Phi2_);
      g0_.swap(g02_);
      g1_.swap(g12_);
      return;
    }
    std::swap(h_, h2_);
    Phi_.swap(Phi2_);
    g0_.swap(g02_);
    g1_.swap(g12_);
    discretize<S>(rule_, A_, G_, h, Phi_, gamma0_, gamma1_);
    g0_ = gamma0_.col(0);
    g1_ = gamma1_.col(0);
    h_ = h;
  }
  // Advances from t_(k-1) (input s_prev) to t_k (input s). Hand-written
  // loops: for the small orders here a library matrix-vector product costs
  // more in call overhead than in arithmetic.
  void step(S s_prev, S s) {
    const S du = rule_ == Discretisation::kExactZoh ? S(0) : s - s_prev;
    const S* phi = Phi_.data();
    const S* g0 = g0_.data();
    const S* g1 = g1_.data();
    const S* z = z_.data();
    S* next = next_.data();
    for (int i = 0; i < n_; ++i) next[i] = g0[i] * s_prev + g1[i] * du;
    for (int j = 0; j < n_; ++j) {
      const S zj = z[j];
      const S* column = phi + static_cast<Eigen::Index>(j) * n_;
      for (int i = 0; i < n_; ++i) next[i] += column[i] * zj;
    }
    z_.swap(next_);
  }
  // The discretisation of the current step length (ensure() first).
  const Matrix<S>& Phi() const { return Phi_; }
  const Vector<S>& g0() const { return g0_; }
  const Vector<S>& g1() const { return g1_; }
  // p^i s / D, i = 0..n, at the current sample (input s).
  template <typename Row>
  void outputs(S gain, S s, Row&& row) const {
    S highest = s;
    for (int i = 0; i < n_; ++i) {
      row(i) = gain * z_(i);
      highest -= d_(i) * z_(n_ - 1 - i);
    }
    row(n_) = gain * highest;
  }

 private:
  static bool same_length(S a, S b) {
    return a == b || std::abs(a - b) <= S(1e-12) * std::abs(a);
  }

  Vector<S> d_;
  Discretisation rule_;
  int n_ = 0;
  Matrix<S> A_, G_, Phi_, Phi2_, gamma0_, gamma1_;
  Vector<S> g0_, g1_, g02_, g12_, z_, next_;
  S h_ = -1, h2_ = -1;
};

// p^i s / D(p), i = 0..n (columns), for D = p^n + d1 p^(n-1) + .. + dn,
// the filter at rest at the first sample.
// The per-sample kernel of filter_derivatives on a regular grid (one
// discretisation for every step, App. A.1): z_k = Phi z_(k-1) + g0 s_(k-1)
// (+ g1 (s_k - s_(k-1)) for FOH and the trapezoid), outputs gain z_k(i) and
// gain (s_k - d^T z_k reversed) written straight into the columns of `out`. N >
// 0 fixes the order at compile time (registers, unrolled loops); N = 0 takes it
// from d (any order). No allocation per sample.
template <typename S, int N>
void filter_regular_kernel(const Vector<S>& d, S gain, bool slope,
                           const Matrix<S>& Phi, const Vector<S>& g0v,
                           const Vector<S>& g1v, const S* s, Eigen::Index count,
                           Matrix<S>& out) {
  // The previous sample is carried in a register, not read again from s,
  // and (N > 0) the filter and its state are local arrays whose address is
  // never taken, so that the compiler keeps them in registers: otherwise
  // every store into `out` may alias them, they are reloaded at every
  // sample, and a reload right after a store to an address with the same
  // low 12 bits stalls, which made some orders several times slower than
  // others depending on where the allocations fell.
  S* const o = out.data();
  const Eigen::Index ld = out.rows();
  S s0 = count > 0 ? s[0] : S(0);
  if constexpr (N > 0) {
    S P[N * N], a[N], b[N], dd[N], z[N] = {}, next[N];
#pragma GCC unroll 8
    for (int i = 0; i < N; ++i) {
#pragma GCC unroll 8
      for (int j = 0; j < N; ++j) P[i * N + j] = Phi(i, j);  // row-major
    }
#pragma GCC unroll 8
    for (int i = 0; i < N; ++i) {
      a[i] = g0v(i);
      b[i] = slope ? g1v(i) : S(0);
      dd[i] = d(i);
    }
    for (Eigen::Index k = 0; k < count; ++k) {
      const S sk = s[k];
      if (k > 0) {
        const S du = sk - s0;
#pragma GCC unroll 8
        for (int i = 0; i < N; ++i) {
          S sum = a[i] * s0 + b[i] * du;
#pragma GCC unroll 8
          for (int j = 0; j < N; ++j) sum += P[i * N + j] * z[j];
          next[i] = sum;
        }
#pragma GCC unroll 8
        for (int i = 0; i < N; ++i) z[i] = next[i];
      }
      S highest = sk;
#pragma GCC unroll 8
      for (int i = 0; i < N; ++i) {
        o[i * ld + k] = gain * z[i];
        highest -= dd[i] * z[N - 1 - i];
      }
      o[N * ld + k] = gain * highest;
      s0 = sk;
    }
  } else {
    const int n = static_cast<int>(d.size());
    std::vector<S> work(static_cast<std::size_t>(n * n + 5 * n), S(0));
    S* phi = work.data();
    S* g0 = phi + n * n;
    S* g1 = g0 + n;
    S* dd = g1 + n;
    S* z = dd + n;
    S* next = z + n;
    for (int i = 0; i < n * n; ++i) phi[i] = Phi.data()[i];
    for (int i = 0; i < n; ++i) {
      g0[i] = g0v(i);
      g1[i] = slope ? g1v(i) : S(0);
      dd[i] = d(i);
    }
    for (Eigen::Index k = 0; k < count; ++k) {
      const S sk = s[k];
      if (k > 0) {
        const S du = sk - s0;
        for (int i = 0; i < n; ++i) next[i] = g0[i] * s0 + g1[i] * du;
        for (int j = 0; j < n; ++j) {
          const S zj = z[j];
          const S* column = phi + j * n;
          for (int i = 0; i < n; ++i) next[i] += column[i] * zj;
        }
        for (int i = 0; i < n; ++i) z[i] = next[i];
      }
      S highest = sk;
      for (int i = 0; i < n; ++i) {
        o[i * ld + k] = gain * z[i];
        highest -= dd[i] * z[n - 1 - i];
      }
      o[n * ld + k] = gain * highest;
      s0 = sk;
    }
  }
}

template <typename S>
void filter_derivatives(const Vector<S>& d, S gain, InterSample rule,
                        const Clock<S>& clock, const S* s, Matrix<S>& out) {
  const int n = static_cast<int>(d.size());
  CompanionFilter<S> filter(d, rule);
  out.resize(clock.n, n + 1);
  if (clock.instants == nullptr && clock.n > 1) {
    // Regular sampling: one discretisation, the fast kernel.
    filter.ensure(clock.interval(1));
    const bool slope = rule != InterSample::kZoh;
    const Matrix<S>& P = filter.Phi();
    const Vector<S>& a = filter.g0();
    const Vector<S>& b = filter.g1();
    switch (n) {
      case 1:
        return filter_regular_kernel<S, 1>(d, gain, slope, P, a, b, s, clock.n,
                                           out);
      case 2:
        return filter_regular_kernel<S, 2>(d, gain, slope, P, a, b, s, clock.n,
                                           out);
      case 3:
        return filter_regular_kernel<S, 3>(d, gain, slope, P, a, b, s, clock.n,
                                           out);
      case 4:
        return filter_regular_kernel<S, 4>(d, gain, slope, P, a, b, s, clock.n,
                                           out);
      case 5:
        return filter_regular_kernel<S, 5>(d, gain, slope, P, a, b, s, clock.n,
                                           out);
      case 6:
        return filter_regular_kernel<S, 6>(d, gain, slope, P, a, b, s, clock.n,
                                           out);
      case 8:
        return filter_regular_kernel<S, 8>(d, gain, slope, P, a, b, s, clock.n,
                                           out);
      default:
        return filter_regular_kernel<S, 0>(d, gain, slope, P, a, b, s, clock.n,
                                           out);
    }
  }
  for (Eigen::Index k = 0; k < clock.n; ++k) {
    if (k > 0) {
      filter.ensure(clock.interval(k));
      filter.step(s[k - 1], s[k]);
    }
    filter.outputs(gain, s[k], out.row(k));
  }
}

// p^i s(t - delay) / D(p), i = 0..n: the signal delayed by a continuous
// delay >= 0 (original time units), the filter at rest at the first
// sample. Before its first sample the signal is 0 (ZOH) or a ramp from 0
// over one sampling interval (FOH, trapezoid), as a delay of whole samples
// (nk) gives, so a delay of nk Ts equals the nk shift. The delayed signal
// changes its piece at t_j + delay, between the sampling instants: the
// filter is stepped (by the signal's rule) from piece to piece.
template <typename S>
void filter_delayed_derivatives(const Vector<S>& d, S gain, InterSample rule,
                                const Clock<S>& clock, const S* s, S delay,
                                Matrix<S>& out) {
  const int n = static_cast<int>(d.size());
  const Eigen::Index count = clock.n;
  CompanionFilter<S> filter(d, rule);
  out.resize(count, n + 1);
  std::vector<S> t(static_cast<std::size_t>(count));
  for (Eigen::Index k = 0; k < count; ++k) {
    t[k] = clock.instants == nullptr ? clock.ts * static_cast<S>(k)
                                     : clock.instants[k] - clock.instants[0];
  }
  const S h0 = t[1] - t[0];
  const S snap = S(1e-9) * clock.median_interval();
  // The undelayed signal at time tau (relative to t_0); ZOH right-
  // continuous, evaluated just after tau so that rounding of t_j + delay
  // does not pick the previous sample.
  auto value = [&](S tau) -> S {
    if (rule == InterSample::kZoh) {
      if (tau + snap < 0) return 0;
      const auto it = std::upper_bound(t.begin(), t.end(), tau + snap);
      return s[(it - t.begin()) - 1];
    }
    if (tau <= -h0) return 0;
    if (tau < 0) return s[0] * (1 + tau / h0);
    const auto it = std::upper_bound(t.begin(), t.end(), tau);
    const Eigen::Index j = (it - t.begin()) - 1;
    if (j >= count - 1) return s[count - 1];
    return s[j] + (s[j + 1] - s[j]) * (tau - t[j]) / (t[j + 1] - t[j]);
  };
  // Breakpoints of the undelayed signal: its samples, and the start of the
  // FOH ramp.
  std::vector<S> breaks;
  if (rule != InterSample::kZoh) breaks.push_back(-h0);
  breaks.insert(breaks.end(), t.begin(), t.end());
  for (Eigen::Index k = 0; k < count; ++k) {
    if (k > 0) {
      S a = t[k - 1] - delay;
      const S b = t[k] - delay;
      auto it = std::upper_bound(breaks.begin(), breaks.end(), a + snap);
      for (;; ++it) {
        const bool last = it == breaks.end() || *it >= b - snap;
        const S c = last ? b : *it;
        filter.ensure(clock.sigma * (c - a));
        if (rule == InterSample::kZoh) {
          filter.step(value(S(0.5) * (a + c)), 0);
        } else {
          filter.step(value(a), value(c));
        }
        a = c;
        if (last) break;
      }
    }
    filter.outputs(gain, value(t[k] - delay), out.row(k));
  }
}

// Free responses of F(p) h = 0: column i has h^(l)(t_0) = delta_il.
template <typename S>
void free_responses(const Vector<S>& f, const Clock<S>& clock, Matrix<S>& H) {
  const int n = static_cast<int>(f.size());
  FilterDiscretization<S> disc;
  disc.configure(n, InterSample::kZoh);
  disc.set_denominator(f);
  H.resize(clock.n, n);
  Matrix<S> z = Matrix<S>::Identity(n, n);
  for (Eigen::Index k = 0; k < clock.n; ++k) {
    if (k > 0) {
      disc.ensure(clock.interval(k));
      z = disc.Phi() * z;
    }
    H.row(k) = z.row(0);
  }
}

}  // namespace batch
}  // namespace ctid
