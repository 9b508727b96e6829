// SPDX-License-Identifier: BSD-3-Clause
// Copyright (C) the ctid authors
// Prediction-error minimisation for the output-error structure (thesis
// sec. 1.3.3, the criterion of eq. 1.16 with the noise model H = 1):
//
//   continuous time   y(t_k) = B(p)/F(p) u(t - td) |_(t = t_k) + e(t_k),
//   discrete time     y(k)   = B(q)/F(q) u(k) + e(k),
//
// theta = [f_1 .. f_nf, b_0 .. b_(nb-1) (, td)] (descending powers of p; in
// discrete time F = 1 + f_1 q^-1 + .., B = q^-nk (b_0 + b_1 q^-1 + ..)),
// minimising V(theta) = 1/N sum_k (y_k - y_hat_k(theta))^2 from rest.
// Several inputs (the SITB's multi-input OE/tfest structure): y_hat =
// sum_j B_j/F_j u_j, each input with its own denominator and delay, theta
// = [f of input 1, .., f of input m, b of input 1, .., b of input m]; the
// sensitivities below are then per input (those of x_j = B_j/F_j u_j),
// and one input is the m = 1 case of the same code.
//
// The continuous-time model is simulated exactly under the data's
// intersample rule (ZOH or FOH input, App. A.1; regular or irregular
// sampling; a delay that need not be a whole number of samples), by the
// exact filters of refined_iv.hpp. The residual Jacobian is exact too:
// the sensitivities
//   d y_hat / d b_k = p^(nb-1-k) u / F,
//   d y_hat / d f_i = -p^(nf-i) B u / F^2
// are filtered from u by the same exact rule (one filter 1/F and one
// 1/F^2 per iteration), so they are the derivatives of the sampled
// simulation, not approximations. With the delay td estimated,
//   d y_hat / d td = -p y_hat = -p B u(t - td) / F
// (strictly proper models: y_hat is then differentiable in t). In discrete time
// the sensitivities are 1/F applied to u and to y_hat, shifted.
//
// Minimiser: Levenberg-Marquardt (Marquardt's scaled damping) on the
// equilibrated Jacobian, each damped step solved by QR of [J; sqrt(mu) I],
// with F kept stable: a trial point with an unstable F (Routh test in
// continuous time, Jury/Schur test in discrete time) or a larger loss is
// refused and the damping raised, so the step is bounded by the damping
// and every iterate lies in the stable set. The continuous-time iteration
// runs in the time t' = sigma t (sigma = |f_nf|^(1/nf) of the start), as
// the refined-IV engine does, for conditioning.
//
// Start: SRIVC (refined_iv.hpp; one denominator group per input) in
// continuous time, least-squares ARX with unstable roots reflected in
// discrete time (several inputs: each input's ARX fitted to y minus the
// others' simulated outputs, a few backfitting sweeps), or a given stable
// theta.
//
// Covariance: s^2 (J^T J)^-1 with s^2 = sum e^2 / (N - np), the
// asymptotic covariance of the prediction-error estimate (thesis eq. 1.18
// with H = 1).
#pragma once

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <complex>
#include <limits>
#include <string>
#include <vector>

#include "ctid/base/stability.hpp"
#include "ctid/base/status.hpp"
#include "ctid/base/types.hpp"
#include "ctid/offline/refined_iv.hpp"

namespace ctid {

enum class OeTime { kContinuous, kDiscrete };

// One input channel of the output-error structure: x_j = B_j/F_j u_j
// (delayed by nk_j samples and, in continuous time, delay_j time units),
// each with its own monic denominator F_j (the SITB's multi-input OE and
// tfest structures, y = sum_j B_j/F_j u_j).
struct OeChannel {
  int nf = 1;  // denominator order, >= 1 (continuous), >= 0 (discrete)
  int nb = 1;  // numerator coefficients, >= 1
  int nk = 0;  // input delay in samples, >= 0
  // Continuous time: an extra delay in time units (>= 0) on top of nk.
  double delay = 0;
  InterSample rule = InterSample::kZoh;  // of u_j (continuous time)
};

// The output-error structure. One input: the fields nf .. rule; several
// inputs: one OeChannel per column of u in `inputs` (then those fields are
// not read). theta = [f_1; ..; f_m; b_1; ..; b_m (; td)], the layout of
// the refined-IV engine (refined_iv.hpp) with one denominator group per
// input, which gives the start; one input is its m = 1 case.
struct OeStructure {
  OeTime time = OeTime::kContinuous;
  int nf = 1;  // denominator order, >= 1 (continuous), >= 0 (discrete)
  int nb = 1;  // numerator coefficients, >= 1
  int nk = 0;  // input delay in samples, >= 0
  // Continuous time: an extra delay in time units (>= 0) on top of nk.
  double delay = 0;
  InterSample rule = InterSample::kZoh;  // of u (continuous time)
  // Several inputs: one entry per column of u (empty: the one input above).
  std::vector<OeChannel> inputs;
  // Continuous time, one input: estimate the total delay td (time units)
  // as the last parameter, started from nk Ts + delay and kept in
  // [0, delay_max] (the bounds of the iteration); needs a strictly proper
  // model (nb <= nf).
  bool estimate_delay = false;
  double delay_max = 0;
  std::vector<OeChannel> channels() const {
    if (!inputs.empty()) return inputs;
    OeChannel c;
    c.nf = nf;
    c.nb = nb;
    c.nk = nk;
    c.delay = delay;
    c.rule = rule;
    return {c};
  }
  // (Orders are checked against the record before this sum is formed.)
  int num_parameters() const {
    int n = estimate_delay ? 1 : 0;
    for (const OeChannel& c : channels()) n += c.nf + c.nb;
    return n;
  }
};

template <typename S>
struct OeSettings {
  int max_iterations = 100;
  S tolerance = S(1e-8);            // relative step and relative loss decrease
  S gradient_tolerance = S(1e-10);  // on the scaled gradient, relative
  Vector<S> theta_init;             // empty: SRIVC / ARX start
  S srivc_cutoff = 0;  // SVF cut-off of SRIVC's start (rad/s); 0: a grid
  S initial_damping = S(1e-3);
  // Of the minimiser (levenberg_marquardt): damped steps tried per
  // iteration, the floor of the damping after a success, a stop once an
  // accepted step lowers the loss by less than this fraction (0: none),
  // and a floor on each column's scale relative to the largest column's
  // (0: a zero column gets the scale 1).
  int max_damping_attempts = 40;
  S min_damping = S(1e-12);
  S decrease_tolerance = 0;
  S relative_scale_floor = 0;
};

template <typename S>
struct OeResult {
  Vector<S> theta;
  Matrix<S> covariance;
  Vector<S> theta_start;
  std::string start;     // "srivc", "arx" or "given"
  S loss = 0;            // 1/N sum e^2 (the SITB's LossFcn/MSE)
  S noise_variance = 0;  // sum e^2 / (N - np)
  S gradient_norm = 0;   // ||J^T e|| / (N s^2) in the equilibrated scale
  S damping = 0;
  int iterations = 0;
  bool converged = false;
  std::string reason;
  Vector<S> simulated;
};

// The data: y (N samples) and u (N-by-num_inputs, column-major), Ts or N
// instants (continuous time only).
template <typename S>
struct OeData {
  const S* y = nullptr;
  const S* u = nullptr;
  int num_inputs = 1;
  Eigen::Index num_samples = 0;
  S ts = 0;
  const S* instants = nullptr;
};

namespace oe_detail {

// Schur-Cohn (Jury) test: all roots of 1 + a1 z^-1 + .. + an z^-n inside
// the unit circle.
template <typename S>
bool schur_stable(const Vector<S>& a) {
  const Eigen::Index n = a.size();
  if (n == 0) return true;
  if (!a.allFinite()) return false;
  Vector<S> c(n + 1);
  c(0) = 1;
  c.tail(n) = a;
  for (Eigen::Index m = n; m >= 1; --m) {
    const S k = c(m) / c(0);
    if (!(std::abs(k) < 1)) return false;
    Vector<S> next(m);
    for (Eigen::Index i = 0; i < m; ++i) next(i) = c(i) - k * c(m - i);
    c = next;
  }
  return true;
}

// Reflects the roots of 1 + a1 z^-1 + .. outside the unit circle to
// 1/conj(z), and moves those at |z| >= 0.999 to |z| = 0.99: a start whose
// F is well inside the stability region.
template <typename S>
Vector<S> reflect_outside_roots(const Vector<S>& a) {
  return reflect_roots_into_unit_disc<S>(a, S(0.999), S(0.99));
}

// y = 1/F(q) x, F = 1 + f1 q^-1 + .., from rest.
template <typename S>
void all_pole(const Vector<S>& f, const S* x, Eigen::Index n, S* y) {
  const Eigen::Index nf = f.size();
  for (Eigen::Index k = 0; k < n; ++k) {
    S v = x[k];
    for (Eigen::Index i = 1; i <= nf && i <= k; ++i) v -= f(i - 1) * y[k - i];
    y[k] = v;
  }
}

template <typename S>
Vector<S> polynomial_square(const Vector<S>& f) {
  // (p^n + f1 p^(n-1) + ..)^2 without the leading 1.
  const Eigen::Index n = f.size();
  Vector<S> full(n + 1);
  full(0) = 1;
  full.tail(n) = f;
  Vector<S> sq = Vector<S>::Zero(2 * n + 1);
  for (Eigen::Index i = 0; i <= n; ++i)
    for (Eigen::Index j = 0; j <= n; ++j) sq(i + j) += full(i) * full(j);
  return sq.tail(2 * n);
}

// The model: simulation and exact Jacobian of y_hat for a theta (scaled
// time in continuous time), y_hat = sum_j x_j over the input channels,
// each channel's sensitivities filtered from its own input by its own
// denominator (d y_hat / d theta_j = d x_j / d theta_j).
template <typename S>
class OeModel {
 public:
  OeModel(const OeStructure& s, const OeData<S>& d)
      : s_(s), d_(d), channels_(s.channels()) {
    clock_.ts = d.ts;
    clock_.instants = d.instants;
    clock_.n = d.num_samples;
    int at = 0;
    for (const OeChannel& c : channels_) {
      f_offset_.push_back(at);
      at += c.nf;
    }
    for (const OeChannel& c : channels_) {
      b_offset_.push_back(at);
      at += c.nb;
      hurwitz_.emplace_back(c.nf);
      double delay = c.delay;
      if (s.time == OeTime::kContinuous && c.nk > 0) {
        delay +=
            c.nk * (d.instants == nullptr ? d.ts : clock_.median_interval());
      }
      delay_.push_back(delay);
    }
  }
  // The total delay nk Ts + delay (time units, continuous time) of the
  // first input (the one whose delay can be estimated).
  double total_delay() const { return delay_[0]; }
  void set_scale(S sigma) { clock_.sigma = sigma; }
  S sigma() const { return clock_.sigma; }
  Eigen::Index samples() const { return d_.num_samples; }
  int num_channels() const { return static_cast<int>(channels_.size()); }
  const OeChannel& channel(int j) const { return channels_[j]; }
  int f_offset(int j) const { return f_offset_[j]; }

  // Scale factors: theta = theta_scaled .* factors (continuous time).
  Vector<S> factors(S sigma) const {
    Vector<S> d = Vector<S>::Ones(s_.num_parameters());
    if (s_.time == OeTime::kDiscrete) return d;
    for (int j = 0; j < num_channels(); ++j) {
      const OeChannel& c = channels_[j];
      for (int i = 0; i < c.nf; ++i)
        d(f_offset_[j] + i) = std::pow(sigma, S(i + 1));
      for (int k = 0; k < c.nb; ++k)
        d(b_offset_[j] + k) = std::pow(sigma, S(c.nf - (c.nb - 1 - k)));
    }
    return d;  // td stays in time units
  }

  bool stable(const Vector<S>& theta) {
    for (int j = 0; j < num_channels(); ++j) {
      const Vector<S> f = theta.segment(f_offset_[j], channels_[j].nf);
      if (!f.allFinite()) return false;
      const bool ok = s_.time == OeTime::kContinuous ? hurwitz_[j].is_stable(f)
                                                     : schur_stable<S>(f);
      if (!ok) return false;
    }
    return true;
  }

  // y_hat and (with J non-null) d y_hat / d theta.
  void evaluate(const Vector<S>& theta, Vector<S>& yhat, Matrix<S>* J) {
    yhat = Vector<S>::Zero(d_.num_samples);
    if (J != nullptr) J->setZero(d_.num_samples, s_.num_parameters());
    for (int j = 0; j < num_channels(); ++j) {
      if (s_.time == OeTime::kContinuous) {
        continuous(j, theta, yhat, J);
      } else {
        discrete(j, theta, yhat, J);
      }
    }
  }

 private:
  const S* input(int j) const { return d_.u + j * d_.num_samples; }

  void filter(int j, const Vector<S>& d, Matrix<S>& out) {
    const InterSample rule = channels_[j].rule;
    if (delay_[j] > 0) {
      riv_detail::filter_delayed_derivatives<S>(d, S(1), rule, clock_, input(j),
                                                static_cast<S>(delay_[j]), out);
    } else {
      riv_detail::filter_derivatives<S>(d, S(1), rule, clock_, input(j), out);
    }
  }

  // Channel j's x_j added to y_hat and its columns of J.
  void continuous(int j, const Vector<S>& theta, Vector<S>& yhat,
                  Matrix<S>* J) {
    const int nf = channels_[j].nf, nb = channels_[j].nb;
    const int fo = f_offset_[j], bo = b_offset_[j];
    const int td_index = s_.num_parameters() - 1;
    const Vector<S> f = theta.segment(fo, nf);
    const Vector<S> b = theta.segment(bo, nb);
    if (s_.estimate_delay) delay_[j] = static_cast<double>(theta(td_index));
    filter(j, f, X_);  // columns p^i u_j / F_j, i = 0..nf
    for (int k = 0; k < nb; ++k) yhat += b(k) * X_.col(nb - 1 - k);
    if (J == nullptr) return;
    for (int k = 0; k < nb; ++k) J->col(bo + k) = X_.col(nb - 1 - k);
    if (s_.estimate_delay) {
      // -p y_hat in original time: p = sigma p'.
      auto col = J->col(td_index);
      for (int k = 0; k < nb; ++k) col -= clock_.sigma * b(k) * X_.col(nb - k);
    }
    filter(j, polynomial_square<S>(f), X2_);  // p^i u_j / F_j^2, i <= 2 nf
    for (int i = 1; i <= nf; ++i) {
      auto col = J->col(fo + i - 1);
      for (int k = 0; k < nb; ++k) col -= b(k) * X2_.col(nf - i + nb - 1 - k);
    }
  }

  void discrete(int j, const Vector<S>& theta, Vector<S>& yhat, Matrix<S>* J) {
    const int nf = channels_[j].nf, nb = channels_[j].nb, nk = channels_[j].nk;
    const int fo = f_offset_[j], bo = b_offset_[j];
    const Eigen::Index n = d_.num_samples;
    const Vector<S> f = theta.segment(fo, nf);
    const Vector<S> b = theta.segment(bo, nb);
    v_.resize(n);
    all_pole<S>(f, input(j), n, v_.data());  // u_j / F_j
    x_ = Vector<S>::Zero(n);
    for (int k = 0; k < nb; ++k) {
      const Eigen::Index shift = nk + k;
      if (shift < n) x_.tail(n - shift) += b(k) * v_.head(n - shift);
    }
    yhat += x_;
    if (J == nullptr) return;
    for (int k = 0; k < nb; ++k) {
      const Eigen::Index shift = nk + k;
      if (shift < n) J->col(bo + k).tail(n - shift) = v_.head(n - shift);
    }
    w_.resize(n);
    all_pole<S>(f, x_.data(), n, w_.data());  // x_j / F_j
    for (int i = 1; i <= nf; ++i) {
      if (i < n) J->col(fo + i - 1).tail(n - i) = -w_.head(n - i);
    }
  }

  OeStructure s_;
  OeData<S> d_;
  std::vector<OeChannel> channels_;
  std::vector<int> f_offset_, b_offset_;
  riv_detail::Clock<S> clock_;
  std::vector<HurwitzTest<S>> hurwitz_;
  std::vector<double> delay_;
  Matrix<S> X_, X2_;
  Vector<S> v_, w_, x_;
};

}  // namespace oe_detail

// Least-squares ARX, A(q) y = sum_j B_j(q) u_j + e with A = 1 + a1 q^-1 ..
// + a_na q^-na, B_j = q^-nk_j (b_j0 + .. b_j(nb_j-1) q^-(nb_j-1)) (thesis
// eq. 1.7 in discrete time), the regression over the samples whose
// regressor lies inside the record (k > max(na, nk_j + nb_j - 1)). theta
// = [a; b_1; ..; b_m], covariance s^2 (Phi^T Phi)^-1 with s^2 = ||e||^2 /
// (rows - np); u is N-by-m column-major.
template <typename S>
struct ArxResult {
  Vector<S> theta;
  Matrix<S> covariance;
  S loss = 0;  // mean square equation error over the regression rows
  S noise_variance = 0;
  Eigen::Index rows = 0;
  // y(k) - y_hat(k|k-1) at every sample, the regressor's values before
  // the record taken as 0 (the SITB's prediction fit of an ARX model)
  Vector<S> prediction_error;
};

template <typename S>
Status arx_least_squares(const S* y, const S* u, Eigen::Index n, int m, int na,
                         const std::vector<int>& nb, const std::vector<int>& nk,
                         ArxResult<S>* out) {
  if (out == nullptr) return bad_input("arx: no result given");
  if (na < 0 || static_cast<int>(nb.size()) != m ||
      static_cast<int>(nk.size()) != m) {
    return Status(ErrorCode::kDimensionMismatch,
                  "nb and nk need one entry per input");
  }
  if (na > n) return bad_input("na must be smaller than the record");
  int np = na, start = na;
  for (int j = 0; j < m; ++j) {
    if (nb[j] < 0 || nk[j] < 0) return bad_input("nb and nk must be >= 0");
    // Each order against the record before the sums (int overflow).
    if (nb[j] > n || nk[j] > n)
      return bad_input("nb and nk must be smaller than the record");
    np += nb[j];
    if (nb[j] > 0) start = std::max(start, nk[j] + nb[j] - 1);
  }
  if (np < 1) return bad_input("the model has no parameter");
  const Eigen::Index rows = n - start;
  if (rows <= np) {
    return bad_input("too few samples (" + std::to_string(n) + ") for " +
                     std::to_string(np) + " parameters");
  }
  Matrix<S> Phi(rows, np);
  Vector<S> Y(rows);
  for (Eigen::Index r = 0; r < rows; ++r) {
    const Eigen::Index k = start + r;
    Y(r) = y[k];
    int c = 0;
    for (int i = 1; i <= na; ++i) Phi(r, c++) = -y[k - i];
    for (int j = 0; j < m; ++j) {
      for (int i = 0; i < nb[j]; ++i) Phi(r, c++) = u[j * n + k - nk[j] - i];
    }
  }
  if (!Phi.allFinite() || !Y.allFinite()) return bad_input("non-finite data");
  const Vector<S> scale = Phi.colwise().norm().transpose();
  for (int c = 0; c < np; ++c) {
    if (!(scale(c) > 0)) {
      return numerical_failure("the regressor column " + std::to_string(c + 1) +
                               " is zero (no excitation)");
    }
  }
  const Matrix<S> Pn = Phi * scale.cwiseInverse().asDiagonal();
  const Eigen::ColPivHouseholderQR<Matrix<S>> qr(Pn);
  if (qr.rank() < np) {
    return numerical_failure(
        "the regressor is rank deficient (rank " + std::to_string(qr.rank()) +
        " < " + std::to_string(np) + "): too little excitation for the orders");
  }
  const Vector<S> thn = qr.solve(Y);
  out->theta = thn.cwiseQuotient(scale);
  const Vector<S> e = Y - Phi * out->theta;
  out->rows = rows;
  out->loss = e.squaredNorm() / static_cast<S>(rows);
  out->noise_variance = e.squaredNorm() / static_cast<S>(rows - np);
  const Matrix<S> Rinv = qr.matrixR()
                             .topLeftCorner(np, np)
                             .template triangularView<Eigen::Upper>()
                             .solve(Matrix<S>::Identity(np, np));
  Matrix<S> Cn = qr.colsPermutation() * (Rinv * Rinv.transpose()) *
                 qr.colsPermutation().transpose();
  out->covariance = out->noise_variance * scale.cwiseInverse().asDiagonal() *
                    Cn * scale.cwiseInverse().asDiagonal();
  out->prediction_error.resize(n);
  for (Eigen::Index k = 0; k < n; ++k) {
    S yhat = 0;
    int c = 0;
    for (int i = 1; i <= na; ++i, ++c) {
      if (k - i >= 0) yhat -= out->theta(c) * y[k - i];
    }
    for (int j = 0; j < m; ++j) {
      for (int i = 0; i < nb[j]; ++i, ++c) {
        const Eigen::Index at = k - nk[j] - i;
        if (at >= 0) yhat += out->theta(c) * u[j * n + at];
      }
    }
    out->prediction_error(k) = y[k] - yhat;
  }
  return Status::Ok();
}

namespace oe_detail {

template <typename S>
Status validate(const OeStructure& s, const OeSettings<S>& settings,
                const OeData<S>& d, OeResult<S>* result) {
  if (result == nullptr) return bad_input("no result given");
  if (d.y == nullptr || d.u == nullptr) return bad_input("no data given");
  const std::vector<OeChannel> channels = s.channels();
  const int m = static_cast<int>(channels.size());
  if (d.num_inputs != m) {
    return Status(ErrorCode::kDimensionMismatch,
                  "the structure has " + std::to_string(m) +
                      " input(s), the data " + std::to_string(d.num_inputs));
  }
  if (m > 1 && s.estimate_delay)
    return bad_input("the delay is estimated for one input only");
  for (int j = 0; j < m; ++j) {
    const OeChannel& c = channels[j];
    const std::string of =
        m > 1 ? " (input " + std::to_string(j + 1) + ")" : std::string();
    if (c.nb < 1) return bad_input("nb must be >= 1" + of);
    if (c.nk < 0) return bad_input("nk must be >= 0" + of);
    // Each order against the record before any sum of them (which would
    // overflow int for orders near INT_MAX).
    if (c.nf > d.num_samples || c.nb > d.num_samples || c.nk > d.num_samples)
      return bad_input("orders and delay must be smaller than the record" + of);
    if (s.time == OeTime::kContinuous) {
      if (c.nf < 1) return bad_input("nf must be >= 1 in continuous time" + of);
      if (c.nb > c.nf + 1)
        return bad_input("the model must be proper (nb <= nf + 1)" + of);
      if (!(c.delay >= 0) || !std::isfinite(c.delay))
        return bad_input("the delay must be finite and >= 0" + of);
    } else if (c.nf < 0) {
      return bad_input("nf must be >= 0" + of);
    }
  }
  if (s.time == OeTime::kContinuous) {
    if (s.estimate_delay && channels[0].nb > channels[0].nf)
      return bad_input("estimating the delay needs a strictly proper model");
    if (s.estimate_delay && !(s.delay_max >= 0 && std::isfinite(s.delay_max)))
      return bad_input("the delay bound must be finite and >= 0");
    if (d.instants == nullptr && !(d.ts > 0))
      return bad_input("Ts must be > 0");
  } else {
    if (s.estimate_delay)
      return bad_input("a discrete-time delay is nk, not estimated here");
    if (d.instants != nullptr)
      return bad_input("a discrete-time model needs regular sampling");
  }
  if (m > d.num_samples) return bad_input("more inputs than samples");
  const int np = s.num_parameters();
  if (d.num_samples < 2 * static_cast<Eigen::Index>(np) + 2) {
    return bad_input("too few samples (" + std::to_string(d.num_samples) +
                     ") for " + std::to_string(np) + " parameters");
  }
  for (Eigen::Index k = 0; k < d.num_samples; ++k) {
    if (!std::isfinite(d.y[k])) return bad_input("y and u must be finite");
    for (int j = 0; j < m; ++j) {
      if (!std::isfinite(d.u[j * d.num_samples + k]))
        return bad_input("y and u must be finite");
    }
  }
  if (settings.max_iterations < 0)
    return Status(ErrorCode::kBadOption, "MaxIter must be >= 0");
  if (!(settings.tolerance > 0) || !std::isfinite(settings.tolerance))
    return Status(ErrorCode::kBadOption, "the tolerance must be > 0");
  if (!(settings.srivc_cutoff >= 0) || !std::isfinite(settings.srivc_cutoff))
    return Status(ErrorCode::kBadOption,
                  "the SRIVC start's cut-off must be finite and >= 0");
  if (settings.theta_init.size() != 0 && settings.theta_init.size() != np) {
    return Status(
        ErrorCode::kDimensionMismatch,
        "the initial parameters need " + std::to_string(np) + " entries");
  }
  return Status::Ok();
}

// Discrete-time start: least-squares ARX of each input's channel with
// unstable roots reflected. With several inputs each channel is fitted to
// y minus the simulated outputs of the others (backfitting, a few sweeps:
// the other channels act as an equation error on the first ones); with
// one input this is the ARX fit itself.
template <typename S>
Status arx_start(const std::vector<OeChannel>& channels, const OeData<S>& d,
                 Vector<S>* theta) {
  const int m = static_cast<int>(channels.size());
  const Eigen::Index n = d.num_samples;
  int np = 0;
  for (const OeChannel& c : channels) np += c.nf + c.nb;
  Vector<S> th(np);
  Matrix<S> x = Matrix<S>::Zero(n, m);  // simulated channel outputs
  const Eigen::Map<const Vector<S>> y(d.y, n);
  const int sweeps = m > 1 ? 8 : 1;
  for (int sweep = 0; sweep < sweeps; ++sweep) {
    int fo = 0, bo = 0;
    for (const OeChannel& c : channels) bo += c.nf;
    for (int j = 0; j < m; ++j) {
      const OeChannel& c = channels[j];
      Vector<S> target = y;
      for (int i = 0; i < m; ++i)
        if (i != j) target -= x.col(i);
      ArxResult<S> arx;
      const Status st = arx_least_squares<S>(target.data(), d.u + j * n, n, 1,
                                             c.nf, {c.nb}, {c.nk}, &arx);
      if (!st.ok()) {
        const std::string of =
            m > 1 ? " (input " + std::to_string(j + 1) + ")" : std::string();
        return Status(st.code(), "ARX start: " + st.message() + of);
      }
      const Vector<S> f = reflect_outside_roots<S>(arx.theta.head(c.nf));
      th.segment(fo, c.nf) = f;
      th.segment(bo, c.nb) = arx.theta.tail(c.nb);
      if (m > 1) {
        Vector<S> v(n);
        all_pole<S>(f, d.u + j * n, n, v.data());
        x.col(j).setZero();
        for (int k = 0; k < c.nb; ++k) {
          const Eigen::Index shift = c.nk + k;
          if (shift < n)
            x.col(j).tail(n - shift) += arx.theta(c.nf + k) * v.head(n - shift);
        }
      }
      fo += c.nf;
      bo += c.nb;
    }
  }
  *theta = th;
  return Status::Ok();
}

template <typename S>
Status start_estimate(const OeStructure& s, const OeData<S>& d, S cutoff,
                      double start_delay, Vector<S>* theta, std::string* how) {
  const std::vector<OeChannel> channels = s.channels();
  if (s.time == OeTime::kContinuous) {
    // SRIVC with one denominator group per input (refined_iv.hpp).
    RivProblem<S> problem;
    for (int j = 0; j < static_cast<int>(channels.size()); ++j) {
      const OeChannel& in = channels[j];
      problem.nf.push_back(in.nf);
      RivChannel c;
      c.group = j;
      c.nb = in.nb;
      c.nk = in.nk;
      c.rule = in.rule;
      c.delay = in.delay;
      if (s.estimate_delay) {
        c.nk = 0;
        c.delay = start_delay;
      }
      problem.channels.push_back(c);
    }
    RivSettings<S> settings;
    if (cutoff > 0) settings.cutoffs = {cutoff};
    Vector<S> fit;
    const Status st = refined_iv_start<S>(
        problem, settings, {d.y, d.u, d.num_samples, d.ts, d.instants},
        "SRIVC start", &fit);
    if (!st.ok()) return st;
    const int nfb = static_cast<int>(fit.size());
    *theta = Vector<S>(s.num_parameters());
    theta->head(nfb) = fit;
    if (s.estimate_delay) (*theta)(nfb) = static_cast<S>(start_delay);
    *how = "srivc";
    return Status::Ok();
  }
  const Status st = arx_start<S>(channels, d, theta);
  if (!st.ok()) return st;
  *how = "arx";
  return Status::Ok();
}

}  // namespace oe_detail

// A box bound on one parameter (the delay), kept by projection.
template <typename S>
struct LmBound {
  int index = -1;  // -1: no bound
  S lower = 0, upper = 0;
};

template <typename S>
struct LmOutcome {
  S cost = 0;  // ||y - y_hat||^2 at the result
  int iterations = 0;
  bool converged = false;
  std::string reason;
  S damping = 0;
  S gradient_norm = 0;  // ||Jn^T e|| / ||e|| (equilibrated Jacobian)
  Vector<S> yhat;
  // (J^T J)^-1 in the model's parameters (NaN when J is rank deficient).
  Matrix<S> inverse_information;
  Matrix<S> jacobian;  // J at the result
};

// Levenberg-Marquardt minimisation of ||y - y_hat(theta)||^2, shared by the
// time-domain output-error fit above and the frequency-domain one
// (freq_srivc.hpp): Marquardt's scaled damping on the equilibrated
// Jacobian, each damped step solved by QR of [J; sqrt(mu) I]; a trial
// point that Model::stable refuses, or with a larger loss, raises the
// damping (bounded steps, every iterate stable); an optional bound kept by
// projection. Model provides bool stable(theta) and
// evaluate(theta, y_hat, Matrix* J) (J = d y_hat / d theta, or null).
// Stops when the scaled gradient vanishes, the residual is at rounding
// level, the relative step and loss decrease fall below the tolerance (or
// the loss decrease alone below settings.decrease_tolerance), no damped
// step lowers the loss (converged when the predicted decrease is
// negligible) or J is not finite; MaxIter reached: not converged, the
// last iterate kept.
template <typename S, typename Model>
Status levenberg_marquardt(Model& model, const Eigen::Ref<const Vector<S>>& y,
                           const OeSettings<S>& settings,
                           const LmBound<S>& bound, Vector<S>* theta_io,
                           LmOutcome<S>* out) {
  Vector<S>& theta = *theta_io;
  const Eigen::Index np = theta.size();
  const int td_index = bound.index;
  Vector<S> yhat, trial_yhat;
  Matrix<S> J;
  model.evaluate(theta, yhat, &J);
  Vector<S> e = y - yhat;
  S cost = e.squaredNorm();
  if (!std::isfinite(cost))
    return numerical_failure("the start model's output is not finite");
  // The residual of an exact model is rounding: ||e|| <= 1e-12 ||y||
  // (the simulation's relative accuracy is ~1e-14 per sample) ends the
  // iteration, as no step can lower it reliably.
  const S exact_floor = S(1e-24) * y.squaredNorm();
  S mu = settings.initial_damping;
  int iter = 0;
  bool converged = false;
  std::string reason;
  Vector<S> scale(np), gn(np);
  auto equilibrate = [&]() {
    scale = J.colwise().norm().transpose();
    const S floor = settings.relative_scale_floor * scale.maxCoeff();
    for (Eigen::Index i = 0; i < np; ++i) {
      scale(i) = std::max(scale(i), floor);
      if (!(scale(i) > 0)) scale(i) = 1;
    }
  };
  for (;;) {
    if (!J.allFinite()) {
      reason = "the Jacobian is not finite";
      gn.setConstant(std::numeric_limits<S>::quiet_NaN());
      break;
    }
    equilibrate();
    const Matrix<S> Jn = J * scale.cwiseInverse().asDiagonal();
    gn = Jn.transpose() * e;
    const S yscale = std::max(cost, std::numeric_limits<S>::min());
    if (gn.norm() <= settings.gradient_tolerance * std::sqrt(yscale) +
                         std::numeric_limits<S>::min()) {
      converged = true;
      reason = "the gradient vanished";
      break;
    }
    if (cost <= exact_floor) {
      converged = true;
      reason = "exact fit (the residual is at rounding level)";
      break;
    }
    if (iter >= settings.max_iterations) {
      reason =
          "MaxIter (" + std::to_string(settings.max_iterations) + ") reached";
      break;
    }
    ++iter;
    // R of the equilibrated Jacobian and Q^T e, then damped steps.
    const Eigen::HouseholderQR<Matrix<S>> qr(Jn);
    const Matrix<S> R =
        qr.matrixQR().topRows(np).template triangularView<Eigen::Upper>();
    // Q^T e = R^-T Jn^T e (cheaper than applying Q to e; equal while R is
    // regular, else Q is applied).
    Vector<S> qte =
        R.transpose().template triangularView<Eigen::Lower>().solve(gn);
    if (!qte.allFinite()) {
      qte = (qr.householderQ().transpose() * e).head(np);
    }
    bool accepted = false;
    S new_cost = cost;
    Vector<S> step, trial;
    for (int attempt = 0; attempt < settings.max_damping_attempts; ++attempt) {
      Matrix<S> A(2 * np, np);
      A.topRows(np) = R;
      A.bottomRows(np) = std::sqrt(mu) * Matrix<S>::Identity(np, np);
      Vector<S> rhs = Vector<S>::Zero(2 * np);
      rhs.head(np) = qte;
      const Vector<S> dn = A.householderQr().solve(rhs);
      step = dn.cwiseQuotient(scale);
      trial = theta + step;
      if (td_index >= 0) {
        trial(td_index) = std::clamp(trial(td_index), bound.lower, bound.upper);
        step(td_index) = trial(td_index) - theta(td_index);
      }
      if (model.stable(trial)) {
        model.evaluate(trial, trial_yhat, nullptr);
        new_cost = (y - trial_yhat).squaredNorm();
        if (std::isfinite(new_cost) && new_cost < cost) {
          accepted = true;
          break;
        }
      }
      mu *= 10;
      if (mu > S(1e16)) break;
    }
    if (!accepted) {
      // No damped step lowers the loss: a (local) minimum to the working
      // precision when the predicted decrease is negligible.
      const S predicted = qte.squaredNorm();
      if (predicted <= settings.tolerance * cost || cost <= 4 * exact_floor) {
        converged = true;
        reason = "no further decrease (a local minimum)";
      } else {
        reason = "no step lowers the loss while keeping F stable";
      }
      break;
    }
    const S rel_step = step.cwiseProduct(scale).norm() /
                       (theta.cwiseProduct(scale).norm() + S(1e-300));
    const S rel_decrease = (cost - new_cost) / cost;
    theta = trial;
    cost = new_cost;
    mu = std::max(mu / 10, settings.min_damping);
    model.evaluate(theta, yhat, &J);
    e = y - yhat;
    if (rel_decrease < settings.decrease_tolerance) {
      converged = true;
      reason = "the relative loss decrease fell below the tolerance";
      break;
    }
    if (rel_step <= settings.tolerance && rel_decrease <= settings.tolerance) {
      converged = true;
      reason = "the relative step and loss decrease fell below the tolerance";
      equilibrate();
      gn = (J * scale.cwiseInverse().asDiagonal()).transpose() * e;
      break;
    }
  }
  out->cost = cost;
  out->iterations = iter;
  out->converged = converged;
  out->damping = mu;
  out->gradient_norm = gn.norm() / std::sqrt(std::max(cost, S(1e-300)));
  out->yhat = yhat;
  out->jacobian = J;
  if (!J.allFinite()) {
    out->inverse_information =
        Matrix<S>::Constant(np, np, std::numeric_limits<S>::quiet_NaN());
    out->reason = reason;
    return Status::Ok();
  }
  // (J^T J)^-1 from the column-pivoted QR of the equilibrated Jacobian.
  const Matrix<S> Jn = J * scale.cwiseInverse().asDiagonal();
  const Eigen::ColPivHouseholderQR<Matrix<S>> qr(Jn);
  out->inverse_information =
      Matrix<S>::Constant(np, np, std::numeric_limits<S>::quiet_NaN());
  if (qr.rank() == np) {
    const Matrix<S> Rinv = qr.matrixR()
                               .topLeftCorner(np, np)
                               .template triangularView<Eigen::Upper>()
                               .solve(Matrix<S>::Identity(np, np));
    const Matrix<S> Cn = qr.colsPermutation() * (Rinv * Rinv.transpose()) *
                         qr.colsPermutation().transpose();
    out->inverse_information = scale.cwiseInverse().asDiagonal() * Cn *
                               scale.cwiseInverse().asDiagonal();
  } else {
    reason += "; the Jacobian is rank deficient (no covariance)";
  }
  out->reason = reason;
  return Status::Ok();
}

// The output-error estimate by Levenberg-Marquardt from the SRIVC/ARX (or
// given) start. Returns kNotConverged with the last (stable) iterate when
// MaxIter is reached or no step lowers the loss before convergence.
template <typename S>
Status output_error(const OeStructure& s, const OeSettings<S>& settings,
                    const OeData<S>& data, OeResult<S>* result) {
  using namespace oe_detail;
  Status status = validate(s, settings, data, result);
  if (!status.ok()) return status;
  const int np = s.num_parameters();
  const Eigen::Index n = data.num_samples;
  OeModel<S> model(s, data);

  Vector<S> theta0;
  if (settings.theta_init.size() == np) {
    theta0 = settings.theta_init;
    result->start = "given";
  } else {
    status = start_estimate(s, data, settings.srivc_cutoff, model.total_delay(),
                            &theta0, &result->start);
    if (!status.ok()) return status;
  }
  const int td_index = s.estimate_delay ? np - 1 : -1;
  if (td_index >= 0) {
    if (!(theta0(td_index) >= 0 && theta0(td_index) <= s.delay_max)) {
      return bad_input("the start delay lies outside [0, delay_max]");
    }
  }
  result->theta_start = theta0;
  if (!model.stable(theta0)) {
    if (result->start == "given")
      return bad_input("the initial model must have a stable F");
    for (int j = 0; j < model.num_channels(); ++j) {
      auto f = theta0.segment(model.f_offset(j), model.channel(j).nf);
      if (s.time == OeTime::kContinuous) {
        f = reflect_unstable_roots<S>(f.eval());
      } else {
        f = reflect_outside_roots<S>(f.eval());
      }
    }
    if (!model.stable(theta0))
      return numerical_failure("no stable start model");
  }

  // Time scale (continuous time): |f_nf|^(1/nf) of the start, the
  // geometric mean of the inputs' ones with several inputs.
  S sigma = 1;
  if (s.time == OeTime::kContinuous) {
    const int m = model.num_channels();
    for (int j = 0; j < m; ++j) {
      const int nf = model.channel(j).nf;
      const S fn = std::abs(theta0(model.f_offset(j) + nf - 1));
      if (fn > 0) sigma *= std::pow(fn, S(1) / S(nf * m));
    }
    if (!std::isfinite(sigma) || !(sigma > 0)) sigma = 1;
  }
  model.set_scale(sigma);
  const Vector<S> factors = model.factors(sigma);
  Vector<S> theta = theta0.cwiseQuotient(factors);

  const Eigen::Map<const Vector<S>> y(data.y, n);
  LmBound<S> bound;
  if (td_index >= 0) {
    bound.index = td_index;
    bound.lower = 0;
    bound.upper = static_cast<S>(s.delay_max);
  }
  LmOutcome<S> lm;
  status = levenberg_marquardt<S>(model, y, settings, bound, &theta, &lm);
  if (!status.ok()) return status;
  result->theta = theta.cwiseProduct(factors);
  result->loss = lm.cost / static_cast<S>(n);
  result->noise_variance = n > np ? lm.cost / static_cast<S>(n - np)
                                  : std::numeric_limits<S>::quiet_NaN();
  result->iterations = lm.iterations;
  result->converged = lm.converged;
  result->reason = lm.reason;
  result->damping = lm.damping;
  result->gradient_norm = lm.gradient_norm;
  result->simulated = lm.yhat;
  // Covariance s^2 (J^T J)^-1, mapped from the scaled to the original time.
  result->covariance = result->noise_variance * factors.asDiagonal() *
                       lm.inverse_information * factors.asDiagonal();
  if (!lm.converged) return Status(ErrorCode::kNotConverged, result->reason);
  return Status::Ok();
}

}  // namespace ctid
