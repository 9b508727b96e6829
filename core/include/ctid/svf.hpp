// State-variable filter bank: for a sampled signal s it produces the
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
// (irregular sampling allowed): exact ZOH or the trapezoidal rule, see
// discretization.hpp. The matrices are recomputed only when h or D changes,
// so a uniformly sampled, fixed filter allocates nothing per sample.
#pragma once

#include <cmath>
#include <limits>

#include "ctid/discretization.hpp"
#include "ctid/types.hpp"

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

template <typename S>
class StateVariableFilter {
 public:
  StateVariableFilter() = default;
  StateVariableFilter(int order, InterSample intersample) {
    configure(order, intersample);
  }

  // Allocates the filter of order n >= 1; denominator p^n, gain 1 until set.
  void configure(int order, InterSample intersample) {
    n_ = order;
    intersample_ = intersample;
    d_ = Vector<S>::Zero(n_);
    gain_ = 1;
    z_ = Vector<S>::Zero(n_);
    z_next_ = Vector<S>::Zero(n_);
    out_ = Vector<S>::Zero(n_ + 1);
    Phi_ = Matrix<S>::Identity(n_, n_);
    Gamma_ = Matrix<S>::Zero(n_, 1);
    dirty_ = true;
    reset();
  }

  // Sets D(p) = p^n + d1 p^(n-1) + .. + dn and the gain g. The new filter
  // governs the intervals advanced from the next step on.
  template <typename Derived>
  void set_denominator(const Eigen::MatrixBase<Derived>& d, S gain) {
    if (!(d == d_)) {
      d_ = d;
      dirty_ = true;
    }
    gain_ = gain;
  }

  // Zero state; the next sample is the first of a record.
  void reset() {
    z_.setZero();
    first_ = true;
    s_prev_ = 0;
  }

  // Feeds s(t_k), where h = t_k - t_(k-1). For the first sample of a record
  // h is the nominal interval: ZOH starts with the state at rest at t_k,
  // the trapezoidal rule as if s and the state were zero one interval
  // earlier.
  void step(S s, S h) {
    if (!first_) {
      ensure_discretised(h);
      if (intersample_ == InterSample::kZoh) {
        z_next_.noalias() = Phi_ * z_;
        z_next_ += Gamma_.col(0) * s_prev_;
      } else {
        z_next_.noalias() = Phi_ * z_;
        z_next_ += Gamma_.col(0) * (s_prev_ + s);
      }
      z_.swap(z_next_);
    } else if (intersample_ == InterSample::kFoh) {
      // Trapezoidal rule from rest: s(t_(-1)) = 0 and z(t_(-1)) = 0, the
      // convention of a discrete filter with zero initial conditions.
      ensure_discretised(h);
      z_.noalias() = Gamma_.col(0) * s;
    }
    first_ = false;
    s_prev_ = s;
    S highest = s;
    for (int i = 0; i < n_; ++i) {
      out_(i) = gain_ * z_(i);
      highest -= d_(i) * z_(n_ - 1 - i);
    }
    out_(n_) = gain_ * highest;
  }

  // p^i F(p) s(t_k), i = 0..n, after the last step.
  const Vector<S>& outputs() const { return out_; }
  int order() const { return n_; }
  const Vector<S>& state() const { return z_; }

 private:
  void ensure_discretised(S h) {
    const S tolerance = 64 * std::numeric_limits<S>::epsilon();
    if (!dirty_ && std::abs(h - h_) <= tolerance * h_) return;
    const Matrix<S> F = companion_matrix<S>(d_);
    Matrix<S> G = Matrix<S>::Zero(n_, 1);
    G(n_ - 1, 0) = 1;
    if (intersample_ == InterSample::kZoh) {
      zoh_discretize<S>(F, G, h, Phi_, Gamma_);
    } else {
      trapezoidal_discretize<S>(F, G, h, Phi_, Gamma_);
    }
    h_ = h;
    dirty_ = false;
  }

  int n_ = 0;
  InterSample intersample_ = InterSample::kZoh;
  Vector<S> d_;
  S gain_ = 1;
  Vector<S> z_;
  Vector<S> z_next_;
  Vector<S> out_;
  Matrix<S> Phi_;
  Matrix<S> Gamma_;
  S h_ = 0;
  S s_prev_ = 0;
  bool dirty_ = true;
  bool first_ = true;
};

}  // namespace ctid
