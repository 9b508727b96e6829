// SPDX-License-Identifier: BSD-3-Clause
// Copyright (C) the ctid authors
// The refined-IV engine (see refined_iv.hpp for the model and the
// method): the parameter layout and time scaling, Engine (the problem in
// the scaled time with its filtered signals, through the batch filters of
// filters/batch_filters.hpp), the equilibrated IV solve, and Estimator
// (the SVF start, the SRIVC / CLSRIVC iterations, step control, covariance
// and the stopping tests). The start search over cut-offs that drives it
// is refined_iv_starts.hpp.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <complex>
#include <limits>
#include <numeric>
#include <string>
#include <vector>

#include "ctid/base/polynomial.hpp"
#include "ctid/filters/batch_filters.hpp"
#include "ctid/offline/offline_iv.hpp"
#include "ctid/offline/refined_iv_problem.hpp"
#include "ctid/offline/refined_iv_validation.hpp"

namespace ctid {
namespace riv_detail {

// The batch filters (filters/batch_filters.hpp) under the names the
// engine and the estimators built on it use.
using batch::Clock;
using batch::CompanionFilter;
using batch::filter_delayed_derivatives;
using batch::filter_derivatives;
using batch::free_responses;

// Number of trailing fixed zeros of group g's denominator (integrators).
template <typename S>
int integrators(const RivProblem<S>& problem, int offset, int n) {
  int r = 0;
  if (problem.fixed.empty()) return 0;
  while (r < n && problem.fixed[offset + n - 1 - r] &&
         problem.fixed_values(offset + n - 1 - r) == 0) {
    ++r;
  }
  return r;
}

// The parameter layout and the working state of one estimation.
template <typename S>
struct Layout {
  std::vector<int> f_offset;  // per group
  std::vector<int> b_offset;  // per channel
  std::vector<int> rank;      // integrators per group
  int offset_index = -1;
  int np = 0;
  std::vector<bool> fixed;
};

template <typename S>
Layout<S> make_layout(const RivProblem<S>& problem) {
  Layout<S> layout;
  int at = 0;
  for (int g = 0; g < problem.num_groups(); ++g) {
    layout.f_offset.push_back(at);
    at += problem.nf[g];
  }
  for (const RivChannel& c : problem.channels) {
    layout.b_offset.push_back(at);
    at += c.nb;
  }
  if (problem.output_offset) layout.offset_index = at++;
  layout.np = at;
  layout.fixed =
      problem.fixed.empty() ? std::vector<bool>(at, false) : problem.fixed;
  for (int g = 0; g < problem.num_groups(); ++g) {
    layout.rank.push_back(
        integrators(problem, layout.f_offset[g], problem.nf[g]));
  }
  return layout;
}

// d(i) with theta' = d .* theta for t' = sigma t.
template <typename S>
Vector<S> scale_factors(const RivProblem<S>& problem, const Layout<S>& layout,
                        S sigma) {
  Vector<S> d = Vector<S>::Ones(layout.np);
  for (int g = 0; g < problem.num_groups(); ++g) {
    for (int i = 1; i <= problem.nf[g]; ++i) {
      d(layout.f_offset[g] + i - 1) = std::pow(sigma, -S(i));
    }
  }
  for (std::size_t j = 0; j < problem.channels.size(); ++j) {
    const RivChannel& c = problem.channels[j];
    const int n = problem.nf[c.group];
    for (int l = 0; l < c.nb; ++l) {
      const int power = c.nb - 1 - l;
      d(layout.b_offset[j] + l) = std::pow(sigma, S(power - n));
    }
  }
  return d;
}

// The problem being solved, in the scaled time, with its signals.
template <typename S>
class Engine {
 public:
  Engine(const RivProblem<S>& problem, const RivData<S>& data)
      : p_(problem), layout_(make_layout(problem)) {
    n_ = data.num_samples;
    y_ = Eigen::Map<const Vector<S>>(data.y, n_);
    const int m = static_cast<int>(problem.channels.size());
    w_.resize(n_, m);
    for (int j = 0; j < m; ++j) {
      const int nk = problem.channels[j].nk;
      for (Eigen::Index k = 0; k < n_; ++k) {
        w_(k, j) = k >= nk ? data.w[j * n_ + k - nk] : S(0);
      }
    }
    data_ = data;
    clock_.ts = data.ts;
    clock_.instants = data.instants;
    clock_.n = n_;
    if (problem.continuous_loop()) {
      r_ = Eigen::Map<const Vector<S>>(problem.reference, n_);
      if (problem.r1 != nullptr) {
        r1_ = Eigen::Map<const Vector<S>>(problem.r1, n_);
      }
    }
  }

  const Layout<S>& layout() const { return layout_; }
  const Clock<S>& clock() const { return clock_; }
  Eigen::Index samples() const { return n_; }
  int free_parameters() const {
    int k = 0;
    for (bool f : layout_.fixed) k += f ? 0 : 1;
    return k;
  }

  // theta (original time) -> theta' at sigma, fixed values imposed.
  Vector<S> to_scaled(const Vector<S>& theta, S sigma) const {
    Vector<S> t = theta;
    for (int i = 0; i < layout_.np; ++i) {
      if (layout_.fixed[i]) t(i) = p_.fixed_values(i);
    }
    return scale_factors(p_, layout_, sigma).cwiseProduct(t);
  }
  Vector<S> from_scaled(const Vector<S>& theta, S sigma) const {
    return theta.cwiseQuotient(scale_factors(p_, layout_, sigma));
  }

  void set_scale(S sigma) { clock_.sigma = sigma; }
  S scale() const { return clock_.sigma; }

  Vector<S> denominator(const Vector<S>& theta, int g) const {
    return theta.segment(layout_.f_offset[g], p_.nf[g]);
  }
  // F_g without its integrators.
  Vector<S> stable_part(const Vector<S>& theta, int g) const {
    return theta.segment(layout_.f_offset[g], p_.nf[g] - layout_.rank[g]);
  }
  bool group_stable(const Vector<S>& theta, int g) const {
    const Vector<S> f1 = stable_part(theta, g);
    HurwitzTest<S> test(static_cast<int>(f1.size()));
    return test.is_stable(f1);
  }
  bool stable(const Vector<S>& theta) const {
    for (int g = 0; g < p_.num_groups(); ++g) {
      if (!group_stable(theta, g)) return false;
    }
    return true;
  }

  // The prefilter denominator of group g: F_g with its integrators
  // replaced by (p + integrator pole), in scaled time.
  Vector<S> prefilter(const Vector<S>& theta, int g, S pole) const {
    const Vector<S> f1 = stable_part(theta, g);
    Vector<S> poly(f1.size() + 1);
    poly(0) = 1;
    poly.tail(f1.size()) = f1;
    for (int i = 0; i < layout_.rank[g]; ++i) {
      Vector<S> next = Vector<S>::Zero(poly.size() + 1);
      next.head(poly.size()) = poly;
      next.tail(poly.size()) += pole * poly;
      poly = next;
    }
    return poly.tail(poly.size() - 1);
  }

  // p^i w_j / D, i = 0..n, with channel j's hold and delay.
  void channel_derivatives(std::size_t j, const Vector<S>& d, S gain,
                           Matrix<S>& out) const {
    const RivChannel& c = p_.channels[j];
    if (c.delay > 0) {
      filter_delayed_derivatives<S>(d, gain, c.rule, clock_, w_.col(j).data(),
                                    static_cast<S>(c.delay), out);
    } else {
      filter_derivatives<S>(d, gain, c.rule, clock_, w_.col(j).data(), out);
    }
  }

  // The same, remembered: the filterings of the inputs repeat (the
  // simulation of x_g at theta filters w_j by 1/F_g, and the next refined
  // step's prefilter is that same 1/F_g; the LSSVF and IVSVF steps of a
  // start share 1/D), so the last few are kept, keyed by channel, time
  // scale, gain and the exact coefficients of D. The reference stays valid
  // until the next call.
  const Matrix<S>& channel_derivatives(std::size_t j, const Vector<S>& d,
                                       S gain) const {
    ++tick_;
    for (CacheEntry& e : cache_) {
      if (e.used > 0 && e.channel == j && e.sigma == clock_.sigma &&
          e.gain == gain && e.d.size() == d.size() && e.d == d) {
        e.used = tick_;
        return e.out;
      }
    }
    // Large records with high orders: no copies kept beyond a budget.
    const double size =
        static_cast<double>(n_) * static_cast<double>(d.size() + 1);
    if (size * static_cast<double>(cache_.size()) > kCacheBudget) {
      channel_derivatives(j, d, gain, uncached_);
      return uncached_;
    }
    CacheEntry* slot = &cache_[0];
    for (CacheEntry& e : cache_) {
      if (e.used < slot->used) slot = &e;
    }
    slot->used = 0;  // invalid while it is being filled
    channel_derivatives(j, d, gain, slot->out);
    slot->channel = j;
    slot->sigma = clock_.sigma;
    slot->gain = gain;
    slot->d = d;
    slot->used = tick_;
    return slot->out;
  }

  // x_g = sum_(j in g) B_j / F_g w_j (scaled time): `source` = w or, in
  // closed loop, the reference (then the closed-loop x_hat and u_hat).
  void simulate_group(const Vector<S>& theta, int g, Vector<S>& x) const {
    x = Vector<S>::Zero(n_);
    const Vector<S> f = denominator(theta, g);
    for (std::size_t j = 0; j < p_.channels.size(); ++j) {
      const RivChannel& c = p_.channels[j];
      if (c.group != g || c.nb == 0) continue;
      const Matrix<S>& D = channel_derivatives(j, f, S(1));
      for (int l = 0; l < c.nb; ++l) {
        x += theta(layout_.b_offset[j] + l) * D.col(c.nb - 1 - l);
      }
    }
  }

  // Closed loop, u = r1 + C(p)(r - y), plant B/F: x_hat = B (Nc r + Dc
  // r1) / Acl and u_hat = F (Nc r + Dc r1) / Acl with Acl = F Dc + B Nc
  // (eqs. 2.48-2.49b with a continuous-time controller). Scaled time:
  // C(p) = C(sigma p'). A zero signal is not filtered.
  Status simulate_closed_loop(const Vector<S>& theta, Vector<S>& x,
                              Vector<S>& u) const {
    if (p_.discrete_controller != nullptr) {
      return simulate_discrete_loop(theta, x, u);
    }
    const int n = p_.nf[0];
    const RivChannel& c = p_.channels[0];
    Vector<S> F(n + 1), B = Vector<S>::Zero(n + 1);
    F(0) = 1;
    F.tail(n) = theta.head(n);
    for (int l = 0; l < c.nb; ++l) {
      B(n + 1 - c.nb + l) = theta(layout_.b_offset[0] + l);
    }
    const Vector<S> nc = scaled_poly(p_.controller_num);
    const Vector<S> dc = scaled_poly(p_.controller_den);
    const Vector<S> acl =
        add(convolve<S>(F, dc), convolve<S>(B, pad(nc, dc.size())));
    const Vector<S> bx = convolve<S>(B, nc), fu = convolve<S>(F, nc);
    const S lead = acl(0);
    if (!(std::abs(lead) > 0)) {
      return numerical_failure("the closed loop is improper");
    }
    const int ncl = static_cast<int>(acl.size()) - 1;
    const Vector<S> d = acl.tail(ncl) / lead;
    HurwitzTest<S> test(ncl);
    if (!test.is_stable(d)) {
      return numerical_failure(
          "the model in the loop with the controller is unstable");
    }
    x = Vector<S>::Zero(n_);
    u = Vector<S>::Zero(n_);
    Matrix<S> D;
    if (!r_.isZero(0)) {
      filter_derivatives<S>(d, S(1) / lead, p_.channels[0].rule, clock_,
                            r_.data(), D);
      x += combine(D, bx);
      u += combine(D, fu);
    }
    if (r1_.size() > 0 && !r1_.isZero(0)) {
      filter_derivatives<S>(d, S(1) / lead, p_.channels[0].rule, clock_,
                            r1_.data(), D);
      x += combine(D, convolve<S>(B, dc));
      u += combine(D, convolve<S>(F, dc));
    }
    return Status::Ok();
  }

  // The regression of group g at the prefilter 1/D (gain `gain`): target
  // (fixed terms moved to it), regressors and instruments of the free
  // parameters of g. `instrument` empty: Z = Phi (least squares).
  void regression(const Vector<S>& theta, int g, const Vector<S>& d, S gain,
                  const Vector<S>& target_signal, const Vector<S>* instrument,
                  const Vector<S>* instrument_u, Matrix<S>& Phi, Matrix<S>& Z,
                  Vector<S>& target, std::vector<int>& index) const {
    const int n = p_.nf[g];
    Matrix<S>& Y = scratch_y_;
    Matrix<S>& X = scratch_x_;
    if (instrument != nullptr && !p_.closed_loop()) {
      // Model-based interpolation of y between samples: the auxiliary
      // model x_hat = sum B_j/F_g w_j is filtered exactly (each channel by
      // its own hold, through B_j / (F_g D)), and only the residual
      // y - x_hat is interpolated (by y's rule). Filtering y itself would
      // interpolate the whole output linearly, an error of order
      // (w h)^2 that biases lightly damped modes and models of relative
      // degree 1 with ZOH inputs; here it vanishes where the model fits.
      exact_model_derivatives(theta, g, d, gain, X);
      scratch_residual_ = target_signal - *instrument;
      filter_derivatives<S>(d, gain, p_.y_rule, clock_,
                            scratch_residual_.data(), Y);
      Y += X;
    } else {
      filter_derivatives<S>(d, gain, p_.y_rule, clock_, target_signal.data(),
                            Y);
      if (instrument != nullptr) {
        filter_derivatives<S>(d, gain, p_.y_rule, clock_, instrument->data(),
                              X);
      }
    }
    // The free parameters of g, in theta's order: Phi and Z are sized once
    // and filled column by column (no copies of N-long columns).
    index.clear();
    for (int i = 1; i <= n; ++i) {
      const int at = layout_.f_offset[g] + i - 1;
      if (!layout_.fixed[at]) index.push_back(at);
    }
    for (std::size_t j = 0; j < p_.channels.size(); ++j) {
      const RivChannel& c = p_.channels[j];
      if (c.group != g || c.nb == 0) continue;
      for (int l = 0; l < c.nb; ++l) {
        const int at = layout_.b_offset[j] + l;
        if (!layout_.fixed[at]) index.push_back(at);
      }
    }
    Phi.resize(n_, static_cast<Eigen::Index>(index.size()));
    Z.resize(n_, static_cast<Eigen::Index>(index.size()));
    Eigen::Index col = 0;
    target = Y.col(n);
    for (int i = 1; i <= n; ++i) {
      const int at = layout_.f_offset[g] + i - 1;
      if (layout_.fixed[at]) {
        target += theta(at) * Y.col(n - i);
        continue;
      }
      Phi.col(col) = -Y.col(n - i);
      if (instrument != nullptr) {
        Z.col(col) = -X.col(n - i);
      } else {
        Z.col(col) = -Y.col(n - i);
      }
      ++col;
    }
    for (std::size_t j = 0; j < p_.channels.size(); ++j) {
      const RivChannel& c = p_.channels[j];
      if (c.group != g || c.nb == 0) continue;
      const Matrix<S>& W = channel_derivatives(j, d, gain);
      Matrix<S>& U = scratch_u_;
      if (instrument_u != nullptr) {
        filter_derivatives<S>(d, gain, c.rule, clock_, instrument_u->data(), U);
      }
      for (int l = 0; l < c.nb; ++l) {
        const int at = layout_.b_offset[j] + l;
        const int power = c.nb - 1 - l;
        if (layout_.fixed[at]) {
          target -= theta(at) * W.col(power);
          continue;
        }
        Phi.col(col) = W.col(power);
        if (instrument_u != nullptr) {
          Z.col(col) = U.col(power);
        } else {
          Z.col(col) = W.col(power);
        }
        ++col;
      }
    }
  }

  // p^i x_g / D, i = 0..n, computed exactly: each channel through
  // gain B_j(p) / (F_g(p) D(p)) with its own hold.
  void exact_model_derivatives(const Vector<S>& theta, int g,
                               const Vector<S>& d, S gain, Matrix<S>& X) const {
    const int n = p_.nf[g];
    const Vector<S> f = denominator(theta, g);
    // F_g D, monic, order 2n (ascending index = descending powers).
    Vector<S> fd = Vector<S>::Zero(2 * n);
    Vector<S> fa(n + 1), da(n + 1);
    fa(0) = 1;
    fa.tail(n) = f;
    da(0) = 1;
    da.tail(n) = d;
    for (int i = 0; i <= n; ++i) {
      for (int j = 0; j <= n; ++j) {
        if (i + j > 0) fd(i + j - 1) += fa(i) * da(j);
      }
    }
    X.setZero(n_, n + 1);
    Matrix<S>& D = scratch_model_;
    for (std::size_t j = 0; j < p_.channels.size(); ++j) {
      const RivChannel& c = p_.channels[j];
      if (c.group != g || c.nb == 0) continue;
      channel_derivatives(j, fd, gain, D);
      for (int l = 0; l < c.nb; ++l) {
        const S b = theta(layout_.b_offset[j] + l);
        const int power = c.nb - 1 - l;
        for (int i = 0; i <= n; ++i) X.col(i) += b * D.col(power + i);
      }
    }
  }

  // Least-squares y0 and c on r = y - sum x_g (scaled time), if asked.
  void fit_free_terms(const Vector<S>& theta, const Vector<S>& residual,
                      Vector<S>& x0, S& c, Vector<S>& y0) const {
    int cols = p_.output_offset ? 1 : 0;
    std::vector<Matrix<S>> bases;
    if (p_.initial_state) {
      for (int g = 0; g < p_.num_groups(); ++g) {
        Matrix<S> H;
        free_responses<S>(denominator(theta, g), clock_, H);
        cols += static_cast<int>(H.cols());
        bases.push_back(H);
      }
    }
    y0 = Vector<S>::Zero(n_);
    c = 0;
    x0.resize(0);
    if (cols == 0) return;
    Matrix<S> A(n_, cols);
    int at = 0;
    for (const Matrix<S>& H : bases) {
      A.middleCols(at, H.cols()) = H;
      at += static_cast<int>(H.cols());
    }
    if (p_.output_offset) A.col(at) = Vector<S>::Ones(n_);
    Vector<S> norms = A.colwise().norm().transpose();
    for (int i = 0; i < cols; ++i) norms(i) = norms(i) > 0 ? norms(i) : S(1);
    const Matrix<S> As = A * norms.cwiseInverse().asDiagonal();
    const Eigen::CompleteOrthogonalDecomposition<Matrix<S>> cod(As);
    const Vector<S> coef = cod.solve(residual).cwiseQuotient(norms);
    y0 = A * coef;
    x0 = coef.head(p_.initial_state ? at : 0);
    if (p_.output_offset) {
      c = coef(at);
      y0 -= Vector<S>::Constant(n_, c);
    }
  }

  const Vector<S>& y() const { return y_; }

 private:
  // x_hat and u_hat of eqs. (2.45), (2.49) with the discrete controller:
  // offline_iv.hpp's closed-loop auxiliary model, in the original time.
  Status simulate_discrete_loop(const Vector<S>& theta, Vector<S>& x,
                                Vector<S>& u) const {
    ModelOrders orders =
        siso_orders(p_.nf[0], p_.channels[0].nb, p_.channels[0].nk);
    const Vector<S> original =
        theta.cwiseQuotient(scale_factors(p_, layout_, clock_.sigma));
    RecordView<S> record;
    record.y = data_.y;
    record.u = data_.w;
    record.num_samples = n_;
    record.num_inputs = 1;
    record.ts = data_.ts;
    record.instants = data_.instants;
    offline_iv_detail::Loop<S> loop;
    loop.r1 = p_.r1;
    loop.r2 = p_.r2;
    loop.controller = p_.discrete_controller;
    Vector<S> uhat;
    const Status status = offline_iv_detail::simulate_auxiliary(
        orders, InterSample::kZoh, original, record, loop, x, uhat);
    if (!status.ok()) return status;
    // The regression's channels are delayed by nk; so is u_hat.
    const int nk = p_.channels[0].nk;
    u = Vector<S>::Zero(n_);
    for (Eigen::Index k = nk; k < n_; ++k) u(k) = uhat(k - nk);
    return Status::Ok();
  }

  Vector<S> scaled_poly(const Vector<S>& q) const {
    // q(sigma p'): coefficient of p'^k scaled by sigma^k, descending.
    Vector<S> out = q;
    const int deg = static_cast<int>(q.size()) - 1;
    for (int i = 0; i <= deg; ++i) {
      out(i) = q(i) * std::pow(clock_.sigma, S(deg - i));
    }
    return out;
  }
  static Vector<S> pad(const Vector<S>& a, Eigen::Index size) {
    Vector<S> out = Vector<S>::Zero(std::max(size, a.size()));
    out.tail(a.size()) = a;
    return out;
  }
  static Vector<S> add(const Vector<S>& a, const Vector<S>& b) {
    const Eigen::Index size = std::max(a.size(), b.size());
    return pad(a, size) + pad(b, size);
  }
  // sum_k num_k p^k r / Acl for num in descending powers (deg <= ncl).
  static Vector<S> combine(const Matrix<S>& D, const Vector<S>& num) {
    Vector<S> out = Vector<S>::Zero(D.rows());
    const int deg = static_cast<int>(num.size()) - 1;
    for (int i = 0; i <= deg; ++i) {
      const int power = deg - i;
      if (power < D.cols() && num(i) != 0) out += num(i) * D.col(power);
    }
    return out;
  }

  const RivProblem<S>& p_;
  Layout<S> layout_;
  RivData<S> data_;
  Eigen::Index n_ = 0;
  Vector<S> y_, r_, r1_;
  Matrix<S> w_;
  Clock<S> clock_;
  // Work arrays reused from call to call (N rows: allocating them anew at
  // every step costs page faults comparable to the filtering itself).
  mutable Matrix<S> scratch_y_, scratch_x_, scratch_u_, scratch_model_;
  mutable Matrix<S> uncached_;
  mutable Vector<S> scratch_residual_;
  struct CacheEntry {
    std::size_t channel = 0;
    S sigma = 0, gain = 0;
    Vector<S> d;
    Matrix<S> out;
    unsigned long used = 0;  // 0: empty
  };
  static constexpr double kCacheBudget = 3.2e7;  // doubles, all entries
  mutable std::array<CacheEntry, 3> cache_;
  mutable unsigned long tick_ = 0;
};

// Z^T Phi theta = Z^T Y with the columns of Phi and Z equilibrated by the
// norms of Phi's: solve_iv of offline_iv.hpp on the scaled problem, mapped
// back. Also the condition number of Q^T Phi.
template <typename S>
Status solve_equilibrated(const Matrix<S>& Z, const Matrix<S>& Phi,
                          const Vector<S>& target, const char* instruments,
                          offline_iv_detail::IvSolution<S>& solution,
                          S& condition) {
  if (!Phi.allFinite() || !Z.allFinite() || !target.allFinite()) {
    return numerical_failure(
        "the filtered signals are not finite (the model's time scale is far "
        "from the data's)");
  }
  Vector<S> norms = Phi.colwise().norm().transpose();
  for (Eigen::Index i = 0; i < norms.size(); ++i) {
    if (!(norms(i) > 0)) {
      return numerical_failure(
          "a regressor is identically zero: the input is not persistently "
          "exciting for this model structure");
    }
  }
  const Vector<S> inv = norms.cwiseInverse();
  Vector<S> z_norms = Z.colwise().norm().transpose();
  for (Eigen::Index i = 0; i < z_norms.size(); ++i) {
    if (!(z_norms(i) > 0)) z_norms(i) = 1;
  }
  const Matrix<S> phi_s = Phi * inv.asDiagonal();
  const Matrix<S> z_s = Z * z_norms.cwiseInverse().asDiagonal();
  const Status status =
      offline_iv_detail::solve_iv(z_s, phi_s, target, instruments, solution);
  if (!status.ok()) return status;
  solution.theta = solution.theta.cwiseProduct(inv);
  const Vector<S> zi = z_norms.cwiseInverse();
  solution.inverse_gram =
      zi.asDiagonal() * solution.inverse_gram * zi.asDiagonal();
  solution.sandwich = inv.asDiagonal() * solution.sandwich * inv.asDiagonal();
  const Matrix<S> m = z_s.transpose() * phi_s;
  const Eigen::JacobiSVD<Matrix<S>> svd(m);
  const auto& sv = svd.singularValues();
  condition = sv(sv.size() - 1) > 0 ? sv(0) / sv(sv.size() - 1)
                                    : std::numeric_limits<S>::infinity();
  return Status::Ok();
}

// One estimation run in a fixed time scale; theta in scaled time.
template <typename S>
struct Run {
  Vector<S> theta;
  Matrix<S> covariance;  // scaled time
  Vector<S> x0;
  S offset = 0;
  Vector<S> simulated, free_response;
  S cost = std::numeric_limits<S>::infinity();  // simulation error variance
  int iterations = 0;
  bool converged = false;
  bool stable = false;
  bool clipped = false;  // the last iterate had to be stabilised
  int clipped_iterations = 0;
  bool determined = true;
  std::vector<int> integrator_suspected;  // per group, see RivResult
  std::vector<S> losses;                  // loss after each iteration
  S condition = 0;
  std::string reason;
};

template <typename S>
class Estimator {
 public:
  Estimator(Engine<S>& engine, const RivProblem<S>& problem,
            const RivSettings<S>& settings)
      : e_(engine), p_(problem), s_(settings) {
    pole_ = settings.integrator_pole;
  }

  // sum_g x_g and the free terms at theta (scaled), and the cost.
  void evaluate(Run<S>& run) const {
    const int groups = p_.num_groups();
    xs_.assign(groups, Vector<S>());
    for (int g = 0; g < groups; ++g) e_.simulate_group(run.theta, g, xs_[g]);
    finish(run);
  }

  // y0, c, the simulated output and the loss at the current x_g.
  void finish(Run<S>& run) const {
    Vector<S> sum = Vector<S>::Zero(e_.samples());
    for (const Vector<S>& x : xs_) sum += x;
    e_.fit_free_terms(run.theta, e_.y() - sum, run.x0, run.offset,
                      run.free_response);
    run.simulated =
        sum + run.free_response + Vector<S>::Constant(e_.samples(), run.offset);
    const Vector<S> r = e_.y() - run.simulated;
    const S dof = static_cast<S>(
        std::max<Eigen::Index>(e_.samples() - e_.free_parameters(), 1));
    run.cost = r.allFinite() ? r.squaredNorm() / dof
                             : std::numeric_limits<S>::infinity();
    if (!e_.stable(run.theta)) run.cost = std::numeric_limits<S>::infinity();
  }

  // The prefilter pole replacing integrators, scaled time.
  S integrator_pole() const {
    const S pole = pole_ > 0 ? pole_ : S(10) / e_.clock().duration();
    return pole * e_.scale();
  }

  // One group update with prefilter 1/d (gain) and instruments from x_g
  // (or least squares). Returns the raw solution in `theta` (group g's
  // free entries replaced) and the group's covariance block.
  Status update_group(Run<S>& run, int g, const Vector<S>& d, S gain, bool iv,
                      bool refined, Matrix<S>& cov_block,
                      std::vector<int>& index, S& condition) const {
    Vector<S> others = Vector<S>::Zero(e_.samples());
    for (int h = 0; h < p_.num_groups(); ++h) {
      if (h != g) others += xs_[h];
    }
    const Vector<S> target_signal =
        e_.y() - others - run.free_response -
        Vector<S>::Constant(e_.samples(), run.offset);
    Matrix<S> Phi, Z;
    Vector<S> target, xcl, ucl;
    const Vector<S>* instrument = nullptr;
    const Vector<S>* instrument_u = nullptr;
    if (iv) {
      if (p_.closed_loop()) {
        Status status = e_.simulate_closed_loop(run.theta, xcl, ucl);
        if (!status.ok()) return status;
        instrument = &xcl;
        instrument_u = &ucl;
      } else {
        instrument = &xs_[g];
      }
    }
    e_.regression(run.theta, g, d, gain, target_signal, instrument,
                  instrument_u, Phi, Z, target, index);
    if (index.empty()) return Status::Ok();
    offline_iv_detail::IvSolution<S> solution;
    const Eigen::Index k = static_cast<Eigen::Index>(index.size());
    bool joint = false;
    if (refined && s_.offset_in_regression && p_.output_offset &&
        !p_.closed_loop()) {
      // The output offset c joins the refined-IV regression instead of
      // being refitted only between steps (refined_iv()'s second attempt).
      // The regression is linear in the filtered signal, so A_hat(p) F(p)
      // 1(t), c's column linearised at the current iterate, is the
      // equation error of the signal minus that of the signal minus 1; the
      // column is its own instrument. c itself is refitted by finish().
      Matrix<S> Phi1, Z1;
      Vector<S> target1;
      std::vector<int> index1;
      e_.regression(run.theta, g, d, gain,
                    Vector<S>(target_signal - Vector<S>::Ones(e_.samples())),
                    instrument, instrument_u, Phi1, Z1, target1, index1);
      Vector<S> current(k);
      for (Eigen::Index i = 0; i < k; ++i) {
        current(i) = run.theta(index[static_cast<std::size_t>(i)]);
      }
      const Vector<S> column =
          (target - Phi * current) - (target1 - Phi1 * current);
      Matrix<S> Phi_c(Phi.rows(), k + 1), Z_c(Z.rows(), k + 1);
      Phi_c << Phi, column;
      Z_c << Z, column;
      joint = index1 == index && column.allFinite() &&
              solve_equilibrated(Z_c, Phi_c, target,
                                 iv ? "instrument" : "regressor", solution,
                                 condition)
                  .ok();
    }
    if (!joint) {
      Status status = solve_equilibrated(
          Z, Phi, target, iv ? "instrument" : "regressor", solution, condition);
      if (!status.ok()) return status;
    }
    for (std::size_t i = 0; i < index.size(); ++i) {
      run.theta(index[i]) = solution.theta(static_cast<Eigen::Index>(i));
    }
    if (joint) {  // theta's block: its covariance with c estimated jointly
      solution.inverse_gram =
          Matrix<S>(solution.inverse_gram.topLeftCorner(k, k));
      solution.sandwich = Matrix<S>(solution.sandwich.topLeftCorner(k, k));
    }
    // Refined IV: (sum zeta_f zeta_f^T)^-1, scaled by sigma^2 later
    // (eq. 2.13); one-step methods: the IV/LS formula for white equation
    // error (nominal, the SVF-filtered equation error is coloured). In
    // closed loop the sandwich (Z^T Phi)^-1 Z^T Z (Phi^T Z)^-1: it equals
    // (Z^T Z)^-1 for the optimal instruments (Z the noise-free part of
    // Phi, eq. 2.48) and stays right for instruments built from another
    // loop than the data's (a controller or an external signal given
    // wrong), where (Z^T Z)^-1 is off by the instruments' scale.
    if (refined && p_.closed_loop()) {
      cov_block = gain * gain * solution.sandwich;
    } else if (refined) {
      cov_block = gain * gain * solution.inverse_gram;
    } else {
      cov_block = solution.equation_error_variance * solution.sandwich;
    }
    return Status::Ok();
  }

  // Keeps group g stable: step halving from `previous` toward the new
  // value, reflection as a last resort. Returns true if it had to act.
  bool stabilise(Run<S>& run, const Vector<S>& previous, int g) const {
    if (e_.group_stable(run.theta, g)) return false;
    const int at = e_.layout().f_offset[g];
    const int n = p_.nf[g];
    const Vector<S> target = run.theta;
    if (e_.group_stable(previous, g)) {
      S alpha = 0.5;
      for (int k = 0; k < 12; ++k, alpha /= 2) {
        run.theta = previous + alpha * (target - previous);
        if (e_.group_stable(run.theta, g)) return true;
      }
    }
    run.theta = target;
    const int m = n - e_.layout().rank[g];
    run.theta.segment(at, m) =
        reflect_unstable_roots<S>(Vector<S>(target.segment(at, m)));
    return true;
  }

  // The SVF start at cut-off 1 (scaled time): LSSVF (eq. 1.32), then with
  // `iv` the IVSVF step (eqs. 2.4-2.7), group by group (two sweeps when
  // there are several groups).
  Status svf_start(Run<S>& run, bool iv) const {
    const int groups = p_.num_groups();
    // Several groups, or free terms (offset, initial state) that the
    // first sweep cannot see: more sweeps, the free terms refitted between.
    const bool free_terms = p_.output_offset || p_.initial_state;
    const int sweeps = groups > 1 || free_terms ? (free_terms ? 3 : 2) : 1;
    evaluate_partial(run);
    Matrix<S> cov;
    std::vector<int> index;
    run.covariance = Matrix<S>::Zero(run.theta.size(), run.theta.size());
    for (int sweep = 0; sweep < sweeps; ++sweep) {
      if (sweep > 0 && free_terms) {
        Run<S> fitted = run;
        for (int g = 0; g < groups; ++g) {
          stabilise(fitted, fitted.theta, g);
        }
        evaluate(fitted);
        run.offset = fitted.offset;
        run.free_response = fitted.free_response;
        for (int g = 0; g < groups; ++g) {
          e_.simulate_group(run.theta, g, xs_[g]);
        }
      }
      for (int g = 0; g < groups; ++g) {
        const int n = p_.nf[g];
        const Vector<S> d = svf_denominator<S>(n, S(1));
        Status status = update_group(run, g, d, S(1), false, false, cov, index,
                                     run.condition);
        if (!status.ok()) return status;
        store(run, cov, index);
        if (iv) {
          Vector<S> previous = run.theta;
          Run<S> driven = run;
          stabilise(driven, previous, g);
          if (!e_.group_stable(driven.theta, g)) {
            return numerical_failure(
                "the LSSVF estimate cannot be "
                "stabilised");
          }
          run.theta = driven.theta;
          e_.simulate_group(run.theta, g, xs_[g]);
          status = update_group(run, g, d, S(1), true, false, cov, index,
                                run.condition);
          if (!status.ok()) return status;
          store(run, cov, index);
        }
        e_.simulate_group(run.theta, g, xs_[g]);
      }
    }
    evaluate(run);
    run.iterations = 1;
    run.converged = true;
    run.stable = e_.stable(run.theta);
    return Status::Ok();
  }

  // SRIVC / CLSRIVC iterations from run.theta (stable, scaled time).
  // The SRIVC iteration as a damped fixed-point method: the refined IV
  // step theta_IV (eqs. 2.9-2.13) is taken in full when it does not
  // increase the simulation loss, else halved (up to 5 times) until it
  // does (if none does, a Gauss-Newton step on the simulation loss,
  // halved until it lowers the loss; if none does either, the full IV
  // step is taken). Stops on a fixed point
  // (relative change of the full step below the tolerance) or on a
  // stationary loss (relative decrease of a damped step below the
  // tolerance, confirmed by a score statistic below the number of fitted
  // sensitivities; else a Gauss-Newton step is taken from there and the
  // iteration goes on); on measured records, where the model is an
  // approximation,
  // the undamped iteration often cycles. A further stop for approximate
  // models, after the last iteration: a score statistic below 1 at the
  // lowest-loss iterate (a Gauss-Newton step could not gain a
  // log-likelihood unit, N ln V; that iterate is returned). A
  // run that still does not converge while its slowest pole creeps to
  // p = 0 flags integrator_suspected (the caller may refit with the pole
  // declared). When no step lowers the loss (stalled), the previous
  // iterate is returned as converged if its score statistic is below the
  // number of sensitivities (a stationary point), or as not converged with
  // integrator_suspected if the full Gauss-Newton step, which would lower
  // the loss, leaves the stable region by moving a real slowest pole
  // through p = 0 (the minimum is on the stability boundary); only
  // otherwise is the full IV step taken.
  Status refine(Run<S>& run) const {
    const int groups = p_.num_groups();
    evaluate(run);
    Matrix<S> cov;
    std::vector<int> index;
    run.covariance = Matrix<S>::Zero(run.theta.size(), run.theta.size());
    run.converged = false;
    run.clipped = false;
    run.clipped_iterations = 0;
    run.determined = true;
    run.integrator_suspected.assign(groups, 0);
    run.losses.clear();
    // Per group, the rate of the slowest pole after each iteration (NaN
    // when it is not real).
    std::vector<std::vector<S>> slowest(groups);
    // The lowest-loss unclipped iterate (where stationarity is tested when
    // the iteration does not converge by itself).
    Run<S> lowest;
    lowest.cost = std::numeric_limits<S>::infinity();
    S lowest_worst = std::numeric_limits<S>::infinity();
    std::string how;
    // The simulation losses of the last iterations (a loss that stays put
    // while the parameters move: flat directions).
    std::vector<S> losses;
    constexpr int kLossWindow = 5;
    bool boundary = false;  // stopped at the stability boundary (below)
    for (int it = 1; it <= s_.max_iterations; ++it) {
      const Run<S> previous = run;
      bool clipped = false;
      for (int g = 0; g < groups; ++g) {
        const Vector<S> d = e_.prefilter(run.theta, g, integrator_pole());
        Status status = update_group(run, g, d, S(1), true, true, cov, index,
                                     run.condition);
        if (!status.ok()) return status;
        clipped = stabilise(run, previous.theta, g) || clipped;
        store(run, cov, index);
        e_.simulate_group(run.theta, g, xs_[g]);
      }
      finish(run);
      run.iterations = it;
      run.clipped = clipped;
      const Vector<S> step = run.theta - previous.theta;
      const S change = step.norm() / std::max(run.theta.norm(), S(1e-300));
      bool stalled = false;
      bool damped = false;
      bool newton = false;  // a Gauss-Newton step was taken instead
      // Score statistic at the previous iterate, when a Gauss-Newton step
      // from it was computed (infinite otherwise).
      S previous_score = std::numeric_limits<S>::infinity();
      int score_columns = 0;
      bool newton_unstable = false;  // the full Gauss-Newton step was
      std::vector<int> toward_origin(groups, 0);
      if (!(run.cost <= previous.cost)) {
        damped = true;
        const Vector<S> full = run.theta;
        bool accepted = halved_step(run, previous, step, S(0.5), 5);
        if (!accepted && !p_.closed_loop()) {
          // No decrease along the IV step (an approximate model: the IV
          // fixed point is not the loss minimum): a Gauss-Newton step on
          // the simulation loss from the previous iterate, halved until
          // it lowers the loss with a stable model.
          Run<S> from = previous;
          Vector<S> eps, fitted, delta;
          int columns = 0;
          if (gauss_newton(from, eps, fitted, delta, &columns)) {
            previous_score = score_of(eps, fitted);
            score_columns = columns;
            S smallest = 1;
            accepted = halved_step(run, previous, delta, S(1), 6,
                                   &newton_unstable, &smallest);
            if (accepted) {
              clipped = false;  // not the pulled-back IV step
              newton = true;
            } else if (newton_unstable) {
              // Does the Gauss-Newton direction take a real slowest pole
              // toward p = 0 (the smallest step tried)?
              const Vector<S> toward = previous.theta + smallest * delta;
              for (int g = 0; g < groups; ++g) {
                const S now = slowest_real_pole(previous.theta, g);
                const S next = slowest_real_pole(toward, g);
                if (std::isfinite(now) && now > 0 && std::isfinite(next) &&
                    next < now) {
                  toward_origin[g] = 1;
                }
              }
            }
          }
        }
        if (!accepted && newton_unstable &&
            std::any_of(toward_origin.begin(), toward_origin.end(),
                        [](int v) { return v != 0; })) {
          // The loss falls toward the stability boundary: neither a damped
          // IV step nor a Gauss-Newton step that stays stable lowers it,
          // and the full Gauss-Newton step, which would, leaves the stable
          // region by moving the slowest (real) pole through p = 0. The
          // loss minimum of the structure lies on or beyond the boundary
          // (an integrator the structure does not declare). The previous
          // iterate is returned, not converged, with the pole flagged, instead
          // of the full IV step (on a raw EMPS position record that step
          // raised the loss 500-fold and the iterates cycled).
          return_previous(run, previous, it);
          boundary = true;
          run.integrator_suspected = toward_origin;
          break;
        }
        if (!accepted && score_below(previous_score, score_columns) &&
            std::isfinite(previous.cost)) {
          // Neither the damped IV step nor a Gauss-Newton step lowers the
          // loss, and the score statistic at the previous iterate is below
          // the number of fitted sensitivities (the plateau test below):
          // that iterate is a stationary point of the simulation loss. It
          // is returned instead of the full IV step, which on measured
          // records can raise the loss a hundredfold (raw EMPS [2 2 0]
          // with input offsets: 0.0059 -> 1.62 var(y)) and start a cycle.
          return_previous(run, previous, it);
          run.converged = true;
          how =
              "stationary simulation loss: neither the refined-IV step "
              "nor a Gauss-Newton step lowers it " +
              score_words(previous_score, score_columns);
          break;
        }
        if (!accepted) {
          // No decrease along the step and no evidence of a stationary
          // point: the plain SRIVC step is taken (the IV fixed point need
          // not minimise the loss, e.g. with coloured noise).
          run.theta = full;
          evaluate(run);
          stalled = true;
        }
      }
      run.clipped = clipped;
      run.losses.push_back(run.cost);
      if (clipped) ++run.clipped_iterations;
      for (int g = 0; g < groups; ++g) {
        slowest[g].push_back(slowest_real_pole(run.theta, g));
      }
      if (change < s_.tolerance && !clipped) {
        run.converged = true;
        how = "fixed point";
        break;
      }
      // Statistically converged: no parameter moves by more than
      // min(1 %, 1e4 Tol) of its standard error sigma_i = (cost (sum
      // zeta_f zeta_f^T)^-1)_ii^1/2 (flat directions of over-parameterised
      // structures drift slowly below the relative tolerance otherwise).
      S worst = std::numeric_limits<S>::infinity();
      if (!clipped && std::isfinite(run.cost)) {
        worst = 0;
        for (Eigen::Index i = 0; i < step.size(); ++i) {
          const S variance = run.cost * run.covariance(i, i);
          if (variance > 0) {
            worst = std::max(worst, std::abs(step(i)) / std::sqrt(variance));
          }
        }
      }
      if (!clipped && std::isfinite(run.cost) && run.cost < lowest.cost) {
        lowest = run;
        lowest_worst = worst;
      }
      if (!clipped && !stalled && std::isfinite(run.cost)) {
        if (worst < std::min(S(0.01), S(1e4) * s_.tolerance)) {
          run.converged = true;
          how = "changes below 1 % of the standard errors";
          break;
        }
      }
      // Converged on the simulation error: over the last kLossWindow
      // iterations the loss changed by less than max(10 Tol, 1e-5) of
      // itself (relative spread). The parameters may still move in
      // directions that do not change the simulated output; the result
      // says so (determined = false) when they move by more than their
      // standard errors.
      if (!clipped && std::isfinite(run.cost)) {
        losses.push_back(run.cost);
        if (static_cast<int>(losses.size()) >= kLossWindow) {
          const auto first = losses.end() - kLossWindow;
          const S hi = *std::max_element(first, losses.end());
          const S lo = *std::min_element(first, losses.end());
          if (hi - lo <= std::max(S(10) * s_.tolerance, S(1e-5)) * lo) {
            run.converged = true;
            run.determined = !(worst > S(1));
            how = "simulation loss stationary over " +
                  std::to_string(kLossWindow) + " iterations";
            if (!run.determined) {
              how += "; parameters still move by up to " +
                     std::to_string(static_cast<int>(std::ceil(worst))) +
                     " standard error(s) per iteration in directions the "
                     "data do not determine (over-parameterised structure?)";
            }
            break;
          }
        }
      } else {
        losses.clear();
      }
      // A plateau of the loss reached by damped steps: the IV fixed point
      // is not approached monotonically (the model is an approximation).
      // A small damped decrease alone does not show that the loss is
      // stationary (the damped IV direction may be nearly orthogonal to
      // the gradient while the loss still falls along a valley): the
      // plateau counts as converged only if the score statistic
      // N eps' P_psi eps / eps' eps at this iterate is below the number
      // n_psi of fitted sensitivities (the mean of its chi^2(n_psi) law
      // when the iterate is a draw of the estimator around the loss
      // minimiser: the minimiser is then within the estimate's own
      // standard errors); else that Gauss-Newton step, halved until it
      // lowers the loss, is taken and the iteration goes on.
      if (damped && !stalled && !clipped && !newton &&
          previous.cost - run.cost <= s_.tolerance * previous.cost) {
        if (p_.closed_loop()) {
          run.converged = true;
          how = "stationary simulation loss";
          break;
        }
        Vector<S> eps, fitted, delta;
        Run<S> at = run;
        int columns = 0;
        if (gauss_newton(at, eps, fitted, delta, &columns)) {
          const S score = score_of(eps, fitted);
          if (score_below(score, columns)) {
            run.converged = true;
            how = "stationary simulation loss after a damped step " +
                  score_words(score, columns);
            break;
          }
          const Run<S> here = run;
          if (!halved_step(run, here, delta, S(1), 6)) {
            run = here;
          } else {
            run.losses.back() = run.cost;
            if (lowest.cost > run.cost) {
              lowest = run;
              lowest_worst = worst;
            }
          }
        }
      }
    }
    // No convergence by the rules above (a limit cycle of the IV step, a
    // slow drift): the simulation loss is stationary at the lowest-loss
    // iterate if its score statistic is below the number of fitted
    // sensitivities, the threshold of the plateau test above (a threshold
    // of 1, one log-likelihood unit, rejects true minima; the two tests
    // agree).
    if (!run.converged && !boundary && std::isfinite(lowest.cost) &&
        !p_.closed_loop()) {
      int columns = 0;
      const S score = score_statistic(lowest, &columns);
      if (score_below(score, columns)) {
        const int its = run.iterations;
        const std::vector<S> history = run.losses;
        const int clips = run.clipped_iterations;
        run = lowest;
        run.iterations = its;
        run.losses = history;
        run.clipped_iterations = clips;
        run.clipped = false;
        run.converged = true;
        run.determined = !(lowest_worst > S(1));
        how = "stationary simulation loss at the lowest-loss iterate " +
              score_words(score, columns);
      }
    }
    if (!run.converged && !boundary) {
      for (int g = 0; g < groups; ++g) {
        run.integrator_suspected[g] =
            creeps_to_origin(slowest[g], run.losses) ? 1 : 0;
      }
    }
    evaluate(run);
    run.stable = e_.stable(run.theta);
    if (run.converged) {
      run.reason = "converged in " + std::to_string(run.iterations) +
                   " iteration(s) (" + how + ")";
    } else if (boundary) {
      run.reason =
          "stopped after " + std::to_string(run.iterations) +
          " iteration(s): the simulation loss falls toward the stability "
          "boundary (the Gauss-Newton step that lowers it moves the slowest "
          "real pole through p = 0)";
    } else if (run.clipped) {
      run.reason =
          "the unconstrained estimate is unstable: the returned model is the "
          "last iterate pulled back into the stable region";
    } else {
      run.reason = "no convergence within " +
                   std::to_string(s_.max_iterations) + " iteration(s)";
    }
    // sigma^2 (sum zeta_f zeta_f^T)^-1, eq. (2.13) covariance.
    run.covariance *= run.cost;
    return Status::Ok();
  }

 private:
  // The simulation error eps at run.theta and the least-squares fit
  // Psi delta of it by the sensitivities Psi of the simulated output to
  // the free parameters: for the output-error model the refined
  // instruments p^i x_g / F_g and p^k w_j / F_g of eq. (2.12), and a
  // constant for c. delta (np, zero for fixed entries and c) is the
  // Gauss-Newton step on the simulation loss. False if not finite.
  bool gauss_newton(Run<S>& run, Vector<S>& eps, Vector<S>& fitted,
                    Vector<S>& delta, int* columns = nullptr) const {
    evaluate(run);
    eps = e_.y() - run.simulated;
    std::vector<Vector<S>> cols;
    std::vector<int> at;
    Matrix<S> Phi, Z;
    Vector<S> target;
    std::vector<int> index;
    for (int g = 0; g < p_.num_groups(); ++g) {
      const Vector<S> d = e_.prefilter(run.theta, g, integrator_pole());
      e_.regression(run.theta, g, d, S(1), e_.y(), &xs_[g], nullptr, Phi, Z,
                    target, index);
      for (Eigen::Index i = 0; i < Z.cols(); ++i) {
        cols.push_back(Z.col(i));
        at.push_back(index[static_cast<std::size_t>(i)]);
      }
    }
    if (p_.output_offset) {
      cols.push_back(Vector<S>::Ones(e_.samples()));
      at.push_back(-1);
    }
    delta = Vector<S>::Zero(run.theta.size());
    fitted = Vector<S>::Zero(e_.samples());
    if (columns != nullptr) *columns = static_cast<int>(cols.size());
    if (cols.empty()) return true;
    Matrix<S> psi(e_.samples(), static_cast<Eigen::Index>(cols.size()));
    Vector<S> norms(static_cast<Eigen::Index>(cols.size()));
    for (std::size_t i = 0; i < cols.size(); ++i) {
      const S norm = cols[i].norm();
      norms(i) = norm > 0 ? norm : S(1);
      psi.col(i) = cols[i] / norms(i);
    }
    if (!psi.allFinite() || !eps.allFinite()) return false;
    const Eigen::CompleteOrthogonalDecomposition<Matrix<S>> cod(psi);
    const Vector<S> coef = cod.solve(eps);
    fitted = psi * coef;
    for (std::size_t i = 0; i < at.size(); ++i) {
      if (at[i] >= 0) delta(at[i]) = coef(i) / norms(i);
    }
    return fitted.allFinite() && delta.allFinite();
  }

  // Steps from `from` along `direction` by the lengths first, first / 2,
  // .. (at most `tries` of them), skipping those that leave the stable
  // region, until one lowers the simulation loss below from.cost. True
  // when one does (run holds it, evaluated); false when none does (run's
  // theta is the last step tried). *first_unstable is set when the full
  // length `first` leaves the stable region; *smallest is the last length
  // tried.
  bool halved_step(Run<S>& run, const Run<S>& from, const Vector<S>& direction,
                   S first, int tries, bool* first_unstable = nullptr,
                   S* smallest = nullptr) const {
    bool lowered = false;
    S length = first;
    for (int k = 0; k < tries && !lowered; ++k, length /= 2) {
      if (smallest != nullptr) *smallest = length;
      run.theta = from.theta + length * direction;
      if (!e_.stable(run.theta)) {
        if (k == 0 && first_unstable != nullptr) *first_unstable = true;
        continue;
      }
      evaluate(run);
      lowered = run.cost < from.cost;
    }
    return lowered;
  }

  // `previous` returned in place of this iteration's iterate (the
  // covariance at itself, see covariance_at), the iteration count and the
  // number of clipped iterations kept.
  void return_previous(Run<S>& run, const Run<S>& previous, int it) const {
    const int clips = run.clipped_iterations;
    run = previous;
    covariance_at(run);
    run.iterations = it;
    run.clipped = false;
    run.clipped_iterations = clips;
  }

  // N times the relative loss decrease of the Gauss-Newton fit `fitted`
  // of the simulation error eps (the score statistic).
  S score_of(const Vector<S>& eps, const Vector<S>& fitted) const {
    const S mean_square = eps.squaredNorm() / static_cast<S>(e_.samples());
    if (!(mean_square > 0)) return 0;
    return fitted.squaredNorm() / mean_square;
  }

  // The score test of a stationary simulation loss: the score statistic
  // below the number of fitted sensitivities (at least 1), the mean of its
  // chi^2 law at the loss minimiser.
  static bool score_below(S score, int columns) {
    return score < std::max(S(1), static_cast<S>(columns));
  }

  // "(score statistic .. below ..)" of that test, for the stop reason.
  static std::string score_words(S score, int columns) {
    return "(score statistic " + std::to_string(score) + " below " +
           std::to_string(std::max(1, columns)) + ")";
  }

  // The score statistic at run.theta: eps^T Psi (Psi^T Psi)^+ Psi^T eps /
  // (eps^T eps / N), N times the relative loss decrease of a full
  // Gauss-Newton step.
  S score_statistic(Run<S>& run, int* columns = nullptr) const {
    Vector<S> eps, fitted, delta;
    if (!gauss_newton(run, eps, fitted, delta, columns)) {
      return std::numeric_limits<S>::infinity();
    }
    return score_of(eps, fitted);
  }

  // -p of the root of F_g's stable part nearest to p = 0 if that root is
  // real, else NaN.
  S slowest_real_pole(const Vector<S>& theta, int g) const {
    const Vector<S> f1 = e_.stable_part(theta, g);
    const Eigen::Index n = f1.size();
    if (n == 0) return std::numeric_limits<S>::quiet_NaN();
    Matrix<S> companion = Matrix<S>::Zero(n, n);
    for (Eigen::Index i = 0; i + 1 < n; ++i) companion(i + 1, i) = 1;
    for (Eigen::Index i = 0; i < n; ++i) companion(0, i) = -f1(i);
    const Eigen::EigenSolver<Matrix<S>> eig(companion, false);
    Eigen::Index k = 0;
    for (Eigen::Index i = 1; i < n; ++i) {
      if (std::abs(eig.eigenvalues()(i)) < std::abs(eig.eigenvalues()(k))) {
        k = i;
      }
    }
    const std::complex<S> root = eig.eigenvalues()(k);
    if (std::abs(root.imag()) > S(1e-9) * std::abs(root)) {
      return std::numeric_limits<S>::quiet_NaN();
    }
    return -root.real();
  }

  // A pole creeping to the origin: over the last kCreepWindow iterations
  // the slowest pole stayed real, its rate fell at every iteration and by
  // at least 10 % in all, while the loss did not rise. The loss minimum
  // of the structure then lies at (or beyond) p = 0: on the stability
  // boundary, where the iteration cannot arrive in finitely many steps.
  static bool creeps_to_origin(const std::vector<S>& rate,
                               const std::vector<S>& losses) {
    constexpr int kCreepWindow = 5;
    const int n = static_cast<int>(rate.size());
    if (n < kCreepWindow || static_cast<int>(losses.size()) != n) return false;
    for (int i = n - kCreepWindow; i < n; ++i) {
      if (!std::isfinite(rate[i]) || !(rate[i] > 0)) return false;
      if (!std::isfinite(losses[i])) return false;
      if (i > n - kCreepWindow) {
        if (!(rate[i] < rate[i - 1])) return false;
        if (losses[i] > losses[i - 1]) return false;
      }
    }
    return rate[n - 1] <= S(0.9) * rate[n - kCreepWindow];
  }

  // The refined-IV covariance (eq. 2.13, before the sigma^2 scaling) at
  // run.theta itself: prefilters and instruments from that iterate. For
  // an iterate returned without an update of its own (the previous one,
  // when no step from it lowers the loss), whose stored covariance is that
  // of the step before it, or zero when it is the start (a record with
  // its initial state estimated, stationary at the first iteration, would
  // report standard deviations of exactly 0).
  void covariance_at(Run<S>& run) const {
    evaluate(run);
    Matrix<S> cov;
    std::vector<int> index;
    S condition = run.condition;
    for (int g = 0; g < p_.num_groups(); ++g) {
      Run<S> probe = run;
      const Vector<S> d = e_.prefilter(run.theta, g, integrator_pole());
      if (!update_group(probe, g, d, S(1), true, true, cov, index, condition)
               .ok()) {
        run.covariance.setConstant(std::numeric_limits<S>::quiet_NaN());
        return;
      }
      store(run, cov, index);
    }
  }

  void store(Run<S>& run, const Matrix<S>& cov,
             const std::vector<int>& index) const {
    for (std::size_t a = 0; a < index.size(); ++a) {
      for (std::size_t b = 0; b < index.size(); ++b) {
        run.covariance(index[a], index[b]) = cov(a, b);
      }
    }
  }
  // x_g at theta without the free terms (they start at zero).
  void evaluate_partial(Run<S>& run) const {
    xs_.assign(p_.num_groups(), Vector<S>::Zero(e_.samples()));
    run.free_response = Vector<S>::Zero(e_.samples());
    run.offset = 0;
  }

  Engine<S>& e_;
  const RivProblem<S>& p_;
  const RivSettings<S>& s_;
  S pole_ = 0;
  mutable std::vector<Vector<S>> xs_;
};

// |F(0)|^(1/n) of the part without integrators: the scale of the model.
template <typename S>
S characteristic_frequency(const Engine<S>& engine,
                           const RivProblem<S>& problem,
                           const Vector<S>& theta_scaled) {
  S log_sum = 0;
  int count = 0;
  for (int g = 0; g < problem.num_groups(); ++g) {
    const Vector<S> f1 = engine.stable_part(theta_scaled, g);
    const int m = static_cast<int>(f1.size());
    if (m == 0 || !(std::abs(f1(m - 1)) > 0)) continue;
    log_sum += std::log(std::abs(f1(m - 1)));
    count += m;
  }
  if (count == 0) return engine.scale();
  return engine.scale() * std::exp(log_sum / static_cast<S>(count));
}

}  // namespace riv_detail
}  // namespace ctid
