// SPDX-License-Identifier: BSD-3-Clause
// Copyright (C) the ctid authors
// State-variable filters: for a sampled signal s they produce the
// prefiltered time derivatives p^i F(p) s, i = 0..n, with
//
//   F(p) = g / D(p),  D(p) = p^n + d1 p^(n-1) + ... + dn,
//
// covering the normalised SVF (lambda/(p+lambda))^n (thesis eq. 3.1), the
// ordinary SVF 1/(p+lambda)^n (eq. 1.19), and a general, possibly
// time-varying denominator such as the adaptive prefilter of RSRIVC
// (eq. 2.19). Outputs follow eq. (1.21): outputs()(i) = p^i F(p) s(t_k).
//
// Realisation: D(p) w = s in controllable canonical form, z = [w .. w^(n-1)],
// so p^i F s = g z_i (i < n) and p^n F s = g (s - d^T z reversed). The state
// keeps its meaning when D changes, so a time-varying filter carries it
// across a change of coefficients. Discretisation per sample interval h_k
// (irregular sampling allowed) by the rule of the signal's InterSample
// (discretisation_of): exact ZOH, exact FOH or the trapezoidal rule, the
// matrices of discretization.hpp, which the batch filters
// (batch_filters.hpp) share. Signals that share a denominator and a rule
// share one FilterDiscretization (one matrix exponential per change) and
// keep their own FilterChannel state.
#pragma once

#include <cmath>
#include <limits>

#include "ctid/base/small_products.hpp"
#include "ctid/base/types.hpp"
#include "ctid/filters/companion_kernels.hpp"
#include "ctid/filters/discretization.hpp"

namespace ctid {

// Denominator and gain of the normalised (eq. 3.1) or ordinary (eq. 1.19)
// SVF of order n and cut-off lambda: D(p) = (p + lambda)^n.
template <typename S>
Vector<S> svf_denominator(int n, S lambda) {
  Vector<S> d(n);
  S binomial = 1;
  S power = 1;
  for (int i = 1; i <= n; ++i) {
    binomial = binomial * static_cast<S>(n - i + 1) / static_cast<S>(i);
    power *= lambda;
    d(i - 1) = binomial * power;
  }
  return d;
}

template <typename S>
S svf_gain(int n, S lambda, bool normalised) {
  return normalised ? std::pow(lambda, static_cast<S>(n)) : S(1);
}

// The discretised filter of one denominator D(p) and one intersample rule,
// shared by every signal filtered through it (y, u_j, the instrument x_hat):
// the matrices are recomputed only when h or D changes, so a uniformly
// sampled, fixed filter allocates nothing per sample.
template <typename S>
class FilterDiscretization {
 public:
  // The fixed-size kernels (companion_kernels.hpp) are chosen here, once,
  // for orders up to kMaxFixedOrder unless `kernels` asks for the
  // dynamic-size reference.
  void configure(int order, InterSample intersample,
                 FilterKernels kernels = FilterKernels::kFixedSize) {
    n_ = order;
    intersample_ = intersample;
    rule_ = discretisation_of(intersample);
    d_ = Vector<S>::Zero(n_);
    Phi_ = Matrix<S>::Identity(n_, n_);
    gamma_ = Vector<S>::Zero(n_);
    gamma1_ = Vector<S>::Zero(n_);
    const bool fixed = kernels == FilterKernels::kFixedSize;
    discretizer_ = fixed ? companion_discretizer<S>(n_, rule_) : nullptr;
    foh_discretizer_ = fixed && rule_ == Discretisation::kExactFoh
                           ? companion_foh_discretizer<S>(n_)
                           : nullptr;
    propagator_ = fixed ? companion_propagator<S>(n_) : nullptr;
    dirty_ = true;
  }

  // D(p) = p^n + d1 p^(n-1) + .. + dn, used from the next ensure() on.
  template <typename Derived>
  void set_denominator(const Eigen::MatrixBase<Derived>& d) {
    if (!(d == d_)) {
      d_ = d;
      dirty_ = true;
    }
  }

  // Makes Phi and Gamma those of the interval h. The work matrices are
  // members, so this allocates only on the first call.
  void ensure(S h) {
    const S tolerance = 64 * std::numeric_limits<S>::epsilon();
    if (!dirty_ && std::abs(h - h_) <= tolerance * h_) return;
    recompute(h);
  }

  int order() const { return n_; }
  InterSample intersample() const { return intersample_; }
  Discretisation rule() const { return rule_; }
  const Vector<S>& denominator() const { return d_; }
  // z_k = Phi z_(k-1) + Gamma v with v = s_(k-1) (exact ZOH and FOH) or
  // s_(k-1) + s_k (trapezoidal rule, Gamma = Bd), plus Gamma1 (s_k -
  // s_(k-1)) for the exact FOH (Gamma1 = 0 otherwise).
  const Matrix<S>& Phi() const { return Phi_; }
  const Vector<S>& Gamma() const { return gamma_; }
  const Vector<S>& Gamma1() const { return gamma1_; }
  // The fixed-size z <- Phi z + Gamma v of this order, or nullptr.
  CompanionPropagator<S> propagator() const { return propagator_; }

 private:
  // The discretisation of the interval h (ensure() keeps the test of
  // whether it is needed small enough to be inlined in the per-sample
  // loops).
  void recompute(S h) {
    if (discretizer_ != nullptr) {
      discretizer_(d_.data(), h, Phi_.data(), gamma_.data());
      h_ = h;
      dirty_ = false;
      return;
    }
    if (foh_discretizer_ != nullptr) {
      foh_discretizer_(d_.data(), h, Phi_.data(), gamma_.data(),
                       gamma1_.data());
      h_ = h;
      dirty_ = false;
      return;
    }
    F_.setZero(n_, n_);
    for (int i = 0; i + 1 < n_; ++i) F_(i, i + 1) = 1;
    for (int j = 0; j < n_; ++j) F_(n_ - 1, j) = -d_(n_ - 1 - j);
    G_.setZero(n_, 1);
    G_(n_ - 1, 0) = 1;
    if (rule_ == Discretisation::kExactZoh) {
      zoh_discretize<S>(F_, G_, h, Phi_, Gamma_);
    } else if (rule_ == Discretisation::kExactFoh) {
      foh_discretize<S>(F_, G_, h, Phi_, Gamma_, Gamma1_);
      gamma1_ = Gamma1_.col(0);
    } else {
      // (I - h/2 F)^-1 (I + h/2 F) and (I - h/2 F)^-1 G h/2, see
      // discretization.hpp.
      work_ = -(h / 2) * F_;
      work_.diagonal().array() += 1;
      lu_.compute(work_);
      work_ = (h / 2) * F_;
      work_.diagonal().array() += 1;
      Phi_.noalias() = lu_.solve(work_);
      Gamma_.noalias() = lu_.solve(G_ * (h / 2));
    }
    gamma_ = Gamma_.col(0);
    h_ = h;
    dirty_ = false;
  }

  int n_ = 0;
  InterSample intersample_ = InterSample::kZoh;
  Discretisation rule_ = Discretisation::kExactZoh;
  Vector<S> d_;
  Matrix<S> Phi_;
  Vector<S> gamma_, gamma1_;
  Matrix<S> F_, G_, Gamma_, Gamma1_, work_;
  Eigen::PartialPivLU<Matrix<S>> lu_;
  CompanionDiscretizer<S> discretizer_ = nullptr;
  CompanionFohDiscretizer<S> foh_discretizer_ = nullptr;
  CompanionPropagator<S> propagator_ = nullptr;
  S h_ = 0;
  bool dirty_ = true;
};

// The state of one signal in a FilterDiscretization: outputs()(i) =
// p^i F(p) s(t_k), i = 0..n, with F = gain / D(p).
template <typename S>
class FilterChannel {
 public:
  void configure(int order) {
    n_ = order;
    z_ = Vector<S>::Zero(n_);
    z_next_ = Vector<S>::Zero(n_);
    out_ = Vector<S>::Zero(n_ + 1);
    reset();
  }

  // Zero state; the next sample is the first of a record. ZOH starts with
  // the state at rest at t_k; the trapezoidal rule and the exact FOH by
  // default as if s and the state were zero one interval earlier (a
  // discrete filter from rest; for the exact FOH a ramp from 0 to s(t_k)
  // over one interval); with rest_at_first_sample, at rest at t_k like ZOH
  // (the continuous filter started at the first sample, which is what the
  // initial-condition regressors of eqs. 3.36-3.41 describe, and what the
  // batch filters do).
  void set_rest_at_first_sample(bool rest) { rest_at_first_sample_ = rest; }
  void reset() {
    z_.setZero();
    first_ = true;
    s_prev_ = 0;
  }

  // Feeds s(t_k); `disc` must hold the matrices of t_k - t_(k-1).
  void step(const FilterDiscretization<S>& disc, S gain, S s) {
    const Discretisation rule = disc.rule();
    const bool trapezoid = rule == Discretisation::kTrapezoid;
    const bool foh = rule == Discretisation::kExactFoh;
    if (!first_ && disc.propagator() != nullptr) {
      disc.propagator()(disc.Phi().data(), disc.Gamma().data(), z_.data(),
                        trapezoid ? s_prev_ + s : s_prev_);
      if (foh) z_ += disc.Gamma1() * (s - s_prev_);
    } else if (!first_) {
      z_next_.noalias() = disc.Phi() * z_;
      z_next_ += disc.Gamma() * (trapezoid ? s_prev_ + s : s_prev_);
      if (foh) z_next_ += disc.Gamma1() * (s - s_prev_);
      z_.swap(z_next_);
    } else if (!rest_at_first_sample_ && trapezoid) {
      z_.noalias() = disc.Gamma() * s;
    } else if (!rest_at_first_sample_ && foh) {
      z_.noalias() = disc.Gamma1() * s;
    }
    first_ = false;
    s_prev_ = s;
    const Vector<S>& d = disc.denominator();
    S highest = s;
    for (int i = 0; i < n_; ++i) {
      out_(i) = gain * z_(i);
      highest -= d(i) * z_(n_ - 1 - i);
    }
    out_(n_) = gain * highest;
  }

  // step() for a discretisation of compile-time order N with the
  // fixed-size kernels (disc.propagator() set): z <- Phi z + Gamma v and
  // the outputs as unrolled scalar code, the sums in the order of the
  // propagator's product (column by column, then Gamma v). Scalar loads
  // and stores only: a packet load of values just stored one by one (or
  // the converse) stalls store forwarding.
  template <int N>
  void step_fixed(const FilterDiscretization<S>& disc, S gain, S s) {
    const S* Phi = disc.Phi().data();
    const S* Gamma = disc.Gamma().data();
    const S* d = disc.denominator().data();
    const Discretisation rule = disc.rule();
    const bool trapezoid = rule == Discretisation::kTrapezoid;
    const bool foh = rule == Discretisation::kExactFoh;
    S* z = z_.data();
    S next[N];
    if (!first_) {
      const S v = trapezoid ? s_prev_ + s : s_prev_;
      S state[N];
#pragma GCC unroll 4
      for (int i = 0; i < N; ++i) state[i] = z[i];
      multiply(N, Phi, state, next);
#pragma GCC unroll 4
      for (int i = 0; i < N; ++i) next[i] += Gamma[i] * v;
      if (foh) {
        const S* Gamma1 = disc.Gamma1().data();
        const S du = s - s_prev_;
#pragma GCC unroll 4
        for (int i = 0; i < N; ++i) next[i] += Gamma1[i] * du;
      }
    } else if (!rest_at_first_sample_ && (trapezoid || foh)) {
      const S* first = trapezoid ? Gamma : disc.Gamma1().data();
#pragma GCC unroll 4
      for (int i = 0; i < N; ++i) next[i] = first[i] * s;
    } else {
#pragma GCC unroll 4
      for (int i = 0; i < N; ++i) next[i] = z[i];
    }
    first_ = false;
    s_prev_ = s;
    S* out = out_.data();
    S highest = s;
#pragma GCC unroll 4
    for (int i = 0; i < N; ++i) {
      z[i] = next[i];
      out[i] = gain * next[i];
      highest -= d[i] * next[N - 1 - i];
    }
    out[N] = gain * highest;
  }

  // Replaces s(t_k) of the last step by `s` (ZOH only, where the state at
  // t_k does not depend on s(t_k)): used to close an algebraic loop.
  void replace_last_input(S gain, S s) {
    out_(n_) += gain * (s - s_prev_);
    s_prev_ = s;
  }

  const Vector<S>& outputs() const { return out_; }
  const Vector<S>& state() const { return z_; }

 private:
  int n_ = 0;
  Vector<S> z_;
  Vector<S> z_next_;
  Vector<S> out_;
  S s_prev_ = 0;
  bool first_ = true;
  bool rest_at_first_sample_ = false;
};

// One signal through its own filter: a FilterDiscretization with a single
// FilterChannel.
template <typename S>
class StateVariableFilter {
 public:
  StateVariableFilter() = default;
  StateVariableFilter(int order, InterSample intersample) {
    configure(order, intersample);
  }

  // Allocates the filter of order n >= 1; denominator p^n, gain 1 until set.
  void configure(int order, InterSample intersample) {
    disc_.configure(order, intersample);
    channel_.configure(order);
    gain_ = 1;
  }

  // Sets D(p) = p^n + d1 p^(n-1) + .. + dn and the gain g. The new filter
  // governs the intervals advanced from the next step on.
  template <typename Derived>
  void set_denominator(const Eigen::MatrixBase<Derived>& d, S gain) {
    disc_.set_denominator(d);
    gain_ = gain;
  }

  void reset() { channel_.reset(); }

  // Feeds s(t_k), where h = t_k - t_(k-1) (for the first sample of a record
  // the nominal interval).
  void step(S s, S h) {
    disc_.ensure(h);
    channel_.step(disc_, gain_, s);
  }

  // p^i F(p) s(t_k), i = 0..n, after the last step.
  const Vector<S>& outputs() const { return channel_.outputs(); }
  int order() const { return disc_.order(); }
  const Vector<S>& state() const { return channel_.state(); }

 private:
  FilterDiscretization<S> disc_;
  FilterChannel<S> channel_;
  S gain_ = 1;
};

}  // namespace ctid
