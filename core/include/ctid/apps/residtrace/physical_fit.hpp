// SPDX-License-Identifier: BSD-3-Clause
// Copyright (C) the ctid authors
// residtrace's physical candidates (simulation/physical_realisations.hpp:
// an end stop, "stop", and two first-order sections with an overflowing
// inner state, "cascade") fitted by their simulation error. Their
// nonlinearity acts on a state that is not measured, so they have no
// regression form: the parameters minimise the output error
//   V(theta) = sum_k e_k^2,  e = y - y_sim(theta)  (thesis eq. 1.16, H = 1)
// by the Levenberg-Marquardt iteration of offline/output_error.hpp with a
// forward-difference Jacobian (the simulators are not differentiable at
// the levels), a share kept in [0, 1] by projecting each step onto it,
// and the Gauss-Newton covariance s^2 (J^T J)^+ (thesis eq. 1.18 with
// H = 1; a pseudo-inverse, so a parameter without effect, a level never
// reached, gets a zero variance instead of spoiling the others).
//
// Parameters theta: for "stop", the free coefficients of the monic F,
// every channel's numerator, the output offset (when a parameter) and the
// finite levels; for "cascade", every channel's gain, the constant inflow
// d, log alpha, log gamma, the output level c (square-root nodes), the
// inner level (when finite), the outer level yhi, the share spill and the
// initial levels h0 and z0 (each when present).
//
// With a declared initial state the free response of the model's
// (linearised) F, a basis of its initial-condition responses
// (responses.hpp), is fitted on the error by least squares at each
// evaluation and removed; a cascade with an initial level h0 has its
// initial state as parameters instead (z0 then one too, started at rest
// with h0).
//
// Budget: at most max_iterations iterations, and at most max(8, 48000 /
// n) on the n = min(N, 6000) first samples fitted (a budget of samples
// times iterations, for speed, that grows as n falls); the residual
// variance, BIC and errors returned are those of the whole record.
#pragma once

#include <Eigen/Dense>
#include <Eigen/SVD>
#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "ctid/apps/residtrace/responses.hpp"
#include "ctid/base/polynomial.hpp"
#include "ctid/base/status.hpp"
#include "ctid/base/types.hpp"
#include "ctid/offline/output_error.hpp"
#include "ctid/simulation/physical_realisations.hpp"

namespace ctid::residtrace {

enum class PhysicalKind { kStop, kCascade };

template <typename S>
struct PhysicalModel {
  PhysicalKind kind = PhysicalKind::kStop;
  int substeps = 1;
  S yscale = 1;  // the output's scale (the smallest finite-difference step)
  // "stop": F = [F0 f1 .. fn] (n >= 2), which f_i are fixed (n flags),
  // channel j's numerator B[j] (descending powers, nb_j <= n - 1 values),
  // the output offset (a parameter when has_offset) plus the fixed ones,
  // the levels lo < hi of the output (+-inf: none).
  Vector<S> F;
  std::vector<bool> fixed;
  std::vector<Vector<S>> B;
  bool has_offset = false;
  S offset = 0;
  S offset_fixed = 0;
  S lo = -std::numeric_limits<S>::infinity();
  // "stop": the upper level of the output; "cascade": of the inner state.
  S hi = std::numeric_limits<S>::infinity();
  // "cascade": the channels' gains b, the constant inflow d, alpha, gamma,
  // the output level c, the outer level yhi (of the output), the share
  // spill, the initial levels h0 (of the output minus c) and z0, each
  // when present, and the mean channel signals wbar (the linearisation).
  bool sqrt_nodes = true;
  Vector<S> b;
  S d = 0, alpha = 1, gamma = 1, c = 0;
  bool has_yhi = false, has_spill = false, has_h0 = false, has_z0 = false;
  S yhi = 0, spill = 0, h0 = 0, z0 = 0;
  Vector<S> wbar;
  // the parameters of its last fit (pack_physical) and their covariance
  // (fit_physical_model, physical_model.hpp); empty before a fit
  Vector<S> theta;
  Matrix<S> cov;
};

// The denominator of a cascade linearised at its steady state for the
// inflow q = wbar' b + d: poles alpha g'(z) and gamma g'(h), for
// square-root nodes alpha^2 / (2 q) and alpha gamma^2 / (2 q). [1 f1 f2].
template <typename S>
Vector<S> cascade_linearisation(const PhysicalModel<S>& m) {
  S p1 = m.alpha, p2 = m.gamma;
  if (m.sqrt_nodes) {
    S q = m.d;
    for (Eigen::Index j = 0; j < m.b.size() && j < m.wbar.size(); ++j) {
      q += m.wbar(j) * m.b(j);
    }
    q = std::max(q, S(1e-9) * (std::abs(m.d) + 1));
    p1 = m.alpha * m.alpha / (2 * q);
    p2 = m.alpha * m.gamma * m.gamma / (2 * q);
  }
  Vector<S> F(3);
  F << 1, p1 + p2, p1 * p2;
  return F;
}

// The cascade whose linearisation (cascade_linearisation) at its steady
// state for the mean channel signals wbar has the poles p1 (upstream) and
// p2, the static gains K of the channels and the output level hbar above
// c: for square-root nodes sqrt(z) = s = 2 p2 hbar at that state, alpha =
// 2 p1 s, gamma = 2 p2 sqrt(hbar), b = 2 K s p1 p2; for linear ones alpha
// = p1, gamma = p2, b = K p1 p2; d makes up the inflow of that state
// (alpha s, or alpha gamma hbar). The start of a cascade from a linear
// model. Sets b, d, alpha, gamma, wbar and F of *m.
template <typename S>
void cascade_from_linear(S p1, S p2, const Vector<S>& K, const Vector<S>& wbar,
                         S hbar, PhysicalModel<S>* m) {
  S q;
  if (m->sqrt_nodes) {
    const S s = 2 * p2 * hbar;
    m->alpha = 2 * p1 * s;
    m->gamma = 2 * p2 * std::sqrt(hbar);
    m->b = 2 * K * s * p1 * p2;
    q = m->alpha * s;
  } else {
    m->alpha = p1;
    m->gamma = p2;
    m->b = K * p1 * p2;
    q = m->alpha * m->gamma * hbar;
  }
  m->d = q - wbar.dot(m->b);
  m->wbar = wbar;
  m->F = cascade_linearisation(*m);
}

// The initial levels of a cascade: h0 kept below the outer level, z0 as
// given or at rest with h0 (g(z0) = gamma g(h0)) below the inner level;
// both NaN without h0 (the cascade then starts at rest for the first
// sample's inflow).
template <typename S>
void cascade_levels(const PhysicalModel<S>& m, S* z0, S* h0) {
  *z0 = *h0 = std::numeric_limits<S>::quiet_NaN();
  if (!m.has_h0) return;
  *h0 = m.h0;
  if (m.has_yhi) *h0 = std::min(*h0, m.yhi - m.c);
  if (m.has_z0) {
    *z0 = m.z0;
  } else if (m.sqrt_nodes) {
    *z0 = std::min(m.gamma * m.gamma * std::max(*h0, S(0)), m.hi);
  } else {
    *z0 = std::min(m.gamma * *h0, m.hi);
  }
}

// Outputs (N-by-K, one column per model) and inner states (the position
// for "stop") of models of one kind and structure on the channel signals
// W (N-by-nc, column-major, already delayed), held over each interval.
template <typename S>
Status simulate_physical(const std::vector<PhysicalModel<S>>& models,
                         const S* W, Eigen::Index N, Eigen::Index nc, S ts,
                         Matrix<S>* y, Matrix<S>* z) {
  const Eigen::Index K = static_cast<Eigen::Index>(models.size());
  if (K < 1) return bad_input("no model to simulate");
  y->resize(N, K);
  z->resize(N, K);
  if (models[0].kind == PhysicalKind::kStop) {
    for (Eigen::Index i = 0; i < K; ++i) {
      const PhysicalModel<S>& m = models[i];
      const Eigen::Index n = m.F.size() - 1;
      if (n < 2) return bad_input("an end stop needs a model of order >= 2");
      if (static_cast<Eigen::Index>(m.B.size()) != nc) {
        return dimension_mismatch("one numerator per channel");
      }
      EndStopConfig<S> c;
      c.f = m.F.tail(n) / m.F(0);
      c.b = Matrix<S>::Zero(n, nc);
      for (Eigen::Index j = 0; j < nc; ++j) {
        const Eigen::Index nb = m.B[j].size();
        if (nb > n) return bad_input("a numerator longer than F");
        c.b.col(j).tail(nb) = m.B[j] / m.F(0);
      }
      const S off = m.offset_fixed + (m.has_offset ? m.offset : S(0));
      c.ts = ts;
      c.substeps = m.substeps;
      c.lo = std::isfinite(m.lo) ? m.lo - off : -INFINITY;
      c.hi = std::isfinite(m.hi) ? m.hi - off : INFINITY;
      Status status = simulate_end_stop<S>(c, W, N, z->col(i).data());
      if (!status.ok()) return status;
      z->col(i).array() += off;
      y->col(i) = z->col(i);
    }
    return Status::Ok();
  }
  // cascades: the simulator takes initial levels for all sets or none, so
  // the sets with and without them are simulated in separate passes
  std::vector<S> z0(K), h0(K);
  for (Eigen::Index i = 0; i < K; ++i)
    cascade_levels(models[i], &z0[i], &h0[i]);
  for (const bool given : {true, false}) {
    std::vector<Eigen::Index> set;
    for (Eigen::Index i = 0; i < K; ++i) {
      if (std::isfinite(z0[i]) == given) set.push_back(i);
    }
    if (set.empty()) continue;
    const Eigen::Index k = static_cast<Eigen::Index>(set.size());
    CascadeConfig<S> c;
    c.sqrt_nodes = models[set[0]].sqrt_nodes;
    c.ts = ts;
    c.b.resize(nc, k);
    c.d.resize(k);
    c.alpha.resize(k);
    c.gamma.resize(k);
    c.hi.resize(k);
    c.ho.resize(k);
    c.spill.resize(k);
    c.c.resize(k);
    if (given) {
      c.z0.resize(k);
      c.h0.resize(k);
    }
    for (Eigen::Index s = 0; s < k; ++s) {
      const PhysicalModel<S>& m = models[set[s]];
      if (m.b.size() != nc) return dimension_mismatch("one gain per channel");
      c.b.col(s) = m.b;
      c.d(s) = m.d;
      c.alpha(s) = m.alpha;
      c.gamma(s) = m.gamma;
      c.c(s) = m.c;
      // a level that is not finite is none (NaN: min ignores it)
      c.hi(s) = std::isfinite(m.hi) ? m.hi : INFINITY;
      const S ho = m.has_yhi ? m.yhi - m.c : INFINITY;
      c.ho(s) = std::isfinite(ho) ? ho : INFINITY;
      c.spill(s) = m.has_spill && std::isfinite(m.spill) ? m.spill : S(0);
      c.substeps = std::max(c.substeps, m.substeps);
      if (given) {
        c.z0(s) = z0[set[s]];
        c.h0(s) = h0[set[s]];
      }
    }
    Matrix<S> ys(N, k), zs(N, k);
    Status status = simulate_cascade<S>(c, W, N, ys.data(), zs.data());
    if (!status.ok()) return status;
    for (Eigen::Index s = 0; s < k; ++s) {
      y->col(set[s]) = ys.col(s);
      z->col(set[s]) = zs.col(s);
    }
  }
  return Status::Ok();
}

// The parameter vector theta of a model and a scale per parameter (the
// smallest step of its finite difference).
template <typename S>
Vector<S> pack_physical(const PhysicalModel<S>& m, Vector<S>* scale) {
  const S ys = std::max(m.yscale, std::numeric_limits<S>::epsilon());
  std::vector<S> th, sc;
  auto put = [&](S v, S s) {
    th.push_back(v);
    sc.push_back(s);
  };
  if (m.kind == PhysicalKind::kStop) {
    for (Eigen::Index i = 1; i < m.F.size(); ++i) {
      if (!m.fixed[i - 1]) {
        const S f = m.F(i) / m.F(0);
        put(f, std::abs(f) + S(1e-3));
      }
    }
    for (const Vector<S>& bj : m.B) {
      for (Eigen::Index k = 0; k < bj.size(); ++k) {
        const S v = bj(k) / m.F(0);
        put(v, std::abs(v) + S(1e-3));
      }
    }
    if (m.has_offset) put(m.offset, ys);
    if (std::isfinite(m.lo)) put(m.lo, ys);
    if (std::isfinite(m.hi)) put(m.hi, ys);
  } else {
    for (Eigen::Index j = 0; j < m.b.size(); ++j) {
      put(m.b(j), std::abs(m.b(j)) + S(1e-6));
    }
    put(m.d, std::abs(m.d) + S(1e-6));
    put(std::log(m.alpha), 1);
    put(std::log(m.gamma), 1);
    if (m.sqrt_nodes) put(m.c, ys);
    if (std::isfinite(m.hi)) put(m.hi, std::max(std::abs(m.hi), S(1e-6)));
    if (m.has_yhi) put(m.yhi, ys);
    if (m.has_spill) put(m.spill, 1);
    if (m.has_h0) put(m.h0, ys);
    if (m.has_z0) put(m.z0, std::max(std::abs(m.z0), S(1e-6)));
  }
  if (scale != nullptr) {
    *scale = Eigen::Map<const Vector<S>>(sc.data(), sc.size());
  }
  return Eigen::Map<const Vector<S>>(th.data(), th.size());
}

// The model of parameters theta (the layout of pack_physical); a stop's F
// becomes monic, a cascade's F its linearisation.
template <typename S>
PhysicalModel<S> unpack_physical(const PhysicalModel<S>& tmpl,
                                 const Vector<S>& th) {
  PhysicalModel<S> m = tmpl;
  Eigen::Index k = 0;
  if (m.kind == PhysicalKind::kStop) {
    m.F = tmpl.F / tmpl.F(0);
    for (Eigen::Index i = 1; i < m.F.size(); ++i) {
      if (!m.fixed[i - 1]) m.F(i) = th(k++);
    }
    for (Vector<S>& bj : m.B) {
      for (Eigen::Index i = 0; i < bj.size(); ++i) bj(i) = th(k++);
    }
    if (m.has_offset) m.offset = th(k++);
    if (std::isfinite(tmpl.lo)) m.lo = th(k++);
    if (std::isfinite(tmpl.hi)) m.hi = th(k++);
    return m;
  }
  for (Eigen::Index j = 0; j < m.b.size(); ++j) m.b(j) = th(k++);
  m.d = th(k++);
  m.alpha = std::exp(th(k++));
  m.gamma = std::exp(th(k++));
  if (m.sqrt_nodes) m.c = th(k++);
  if (std::isfinite(tmpl.hi)) m.hi = th(k++);
  if (m.has_yhi) m.yhi = th(k++);
  if (m.has_spill) m.spill = th(k++);
  if (m.has_h0) m.h0 = th(k++);
  if (m.has_z0) m.z0 = th(k++);
  m.F = cascade_linearisation(m);
  return m;
}

// The index of the share spill in theta (-1: none), the one bounded
// parameter.
template <typename S>
Eigen::Index spill_index(const PhysicalModel<S>& m) {
  if (m.kind != PhysicalKind::kCascade || !m.has_spill) return -1;
  Eigen::Index k = m.b.size() + 3 + (m.sqrt_nodes ? 1 : 0) +
                   (std::isfinite(m.hi) ? 1 : 0) + (m.has_yhi ? 1 : 0);
  return k;
}

// The admissible parameters: finite; a stop's F without roots in the
// right half-plane (beyond 1e-9 of the largest modulus: integrators pass)
// and lo < hi; a cascade's alpha, gamma below 1e8 and spill in [0, 1].
template <typename S>
bool admissible_physical(const PhysicalModel<S>& tmpl, const Vector<S>& th) {
  if (!th.allFinite()) return false;
  const PhysicalModel<S> m = unpack_physical(tmpl, th);
  if (m.kind == PhysicalKind::kStop) {
    const Vector<S> asc = m.F.reverse();
    const auto r = polynomial_roots<S>(asc);
    S largest = 0;
    for (Eigen::Index i = 0; i < r.size(); ++i) {
      largest = std::max(largest, std::abs(r(i)));
    }
    for (Eigen::Index i = 0; i < r.size(); ++i) {
      if (!(r(i).real() <= S(1e-9) * largest)) return false;
    }
    return m.lo < m.hi;
  }
  bool ok = m.alpha < S(1e8) && m.gamma < S(1e8);
  if (m.has_spill) ok = ok && m.spill >= 0 && m.spill <= 1;
  return ok;
}

namespace physical_detail {

// The simulation errors e = y - y_sim of the models, one column each; with
// a declared initial state, minus their least-squares fit by the free
// responses of each model's F. A simulation that fails, or an error that
// is not finite, gives Inf.
template <typename S>
void errors(const std::vector<PhysicalModel<S>>& models, const S* W,
            Eigen::Index nc, const Vector<S>& y, S ts, bool initial_state,
            Matrix<S>* E) {
  const Eigen::Index N = y.size();
  const Eigen::Index K = static_cast<Eigen::Index>(models.size());
  Matrix<S> Y, Z;
  const Status status = simulate_physical<S>(models, W, N, nc, ts, &Y, &Z);
  *E = Matrix<S>::Constant(N, K, std::numeric_limits<S>::infinity());
  if (!status.ok()) return;
  for (Eigen::Index i = 0; i < K; ++i) {
    E->col(i) = y - Y.col(i);
    if (initial_state && E->col(i).allFinite()) {
      const Vector<S>& F = models[i].F;
      const Vector<S> f = F.tail(F.size() - 1) / F(0);
      Matrix<S> X;
      if (free_responses<S>(f, ts, N, X).ok()) {
        const Eigen::ColPivHouseholderQR<Matrix<S>> qr(X);
        const Vector<S> coef = qr.solve(Vector<S>(E->col(i)));
        if (coef.allFinite()) E->col(i) -= X * coef;
      }
    }
    for (Eigen::Index k = 0; k < N; ++k) {
      if (!std::isfinite((*E)(k, i))) (*E)(k, i) = INFINITY;
    }
  }
}

// The model the minimiser sees: y_hat = -e(theta) against the target 0,
// J = d y_hat / d theta by forward differences (backward at a bound,
// never past it; the perturbed models simulated side by side).
template <typename S>
class FitProblem {
 public:
  FitProblem(const PhysicalModel<S>& tmpl, const S* W, Eigen::Index nc,
             const Vector<S>& y, S ts, bool initial_state)
      : tmpl_(tmpl),
        W_(W),
        nc_(nc),
        y_(y),
        ts_(ts),
        initial_state_(initial_state),
        bound_(spill_index(tmpl)) {
    pack_physical(tmpl, &scale_);
  }

  bool stable(const Vector<S>& th) const {
    return admissible_physical(tmpl_, th);
  }

  Vector<S> project(Vector<S> th) const {
    if (bound_ >= 0) th(bound_) = std::clamp(th(bound_), S(0), S(1));
    return th;
  }

  Vector<S> errors_at(const Vector<S>& th) {
    if (cached_.size() == th.size() && cached_ == th) return cached_e_;
    Matrix<S> E;
    errors<S>({unpack_physical(tmpl_, th)}, W_, nc_, y_, ts_, initial_state_,
              &E);
    cached_ = th;
    cached_e_ = E.col(0);
    return cached_e_;
  }

  void evaluate(const Vector<S>& th, Vector<S>& yhat, Matrix<S>* J) {
    const Vector<S> r = errors_at(th);
    yhat = -r;
    if (J == nullptr) return;
    const Eigen::Index np = th.size();
    const Eigen::Index N = y_.size();
    Vector<S> h(np);
    std::vector<PhysicalModel<S>> perturbed;
    for (Eigen::Index i = 0; i < np; ++i) {
      h(i) = S(1e-5) * std::max(std::abs(th(i)), scale_(i));
      Vector<S> t = th;
      t(i) += h(i);
      if (!stable(t)) {
        t(i) = th(i) - h(i);
        if (stable(t)) h(i) = -h(i);
      }
      t = th;
      t(i) += h(i);
      h(i) = project(t)(i) - th(i);  // 0: no step, a zero column
      t(i) = th(i) + h(i);
      perturbed.push_back(unpack_physical(tmpl_, t));
    }
    Matrix<S> E;
    if (tmpl_.kind == PhysicalKind::kCascade) {
      errors<S>(perturbed, W_, nc_, y_, ts_, initial_state_, &E);
    } else {
      E.resize(N, np);
      for (Eigen::Index i = 0; i < np; ++i) {
        if (h(i) == 0) continue;
        Matrix<S> Ei;
        errors<S>({perturbed[i]}, W_, nc_, y_, ts_, initial_state_, &Ei);
        E.col(i) = Ei.col(0);
      }
    }
    J->resize(N, np);
    for (Eigen::Index i = 0; i < np; ++i) {
      if (h(i) == 0) {
        J->col(i).setZero();
      } else {
        J->col(i) = -(E.col(i) - r) / h(i);
      }
    }
  }

  Eigen::Index bound() const { return bound_; }

 private:
  const PhysicalModel<S>& tmpl_;
  const S* W_;
  Eigen::Index nc_;
  const Vector<S>& y_;
  S ts_;
  bool initial_state_;
  Eigen::Index bound_;
  Vector<S> scale_;
  Vector<S> cached_, cached_e_;
};

// The pseudo-inverse of a symmetric matrix by its SVD, the singular
// values below n sigma_max eps dropped.
template <typename S>
Matrix<S> pseudo_inverse(const Matrix<S>& A) {
  const Eigen::JacobiSVD<Matrix<S>> svd(
      A, Eigen::ComputeThinU | Eigen::ComputeThinV);
  const Vector<S>& sv = svd.singularValues();
  const S tol = static_cast<S>(std::max(A.rows(), A.cols())) *
                (sv.size() ? sv(0) : S(0)) * std::numeric_limits<S>::epsilon();
  Vector<S> inv(sv.size());
  for (Eigen::Index i = 0; i < sv.size(); ++i) {
    inv(i) = sv(i) > tol ? S(1) / sv(i) : S(0);
  }
  return svd.matrixV() * inv.asDiagonal() * svd.matrixU().transpose();
}

}  // namespace physical_detail

template <typename S>
struct PhysicalFit {
  bool ok = false;  // false: no finite simulation error at the start or end
  PhysicalModel<S> model;
  Vector<S> theta;  // the parameters (pack_physical)
  Matrix<S> cov;    // their Gauss-Newton covariance
  Vector<S> e;      // the errors on the whole record
  S s2 = 0;         // e'e / max(N - np, 1)
  S bic = 0;        // N log s2 + np log N
  S sse = 0;        // the criterion on the samples fitted
  int iterations = 0;
};

// Fits tmpl on the channel signals W (N-by-nc, column-major, delayed) and
// the output y (N samples) at the interval ts.
template <typename S>
Status fit_physical(const PhysicalModel<S>& tmpl, const S* W, Eigen::Index nc,
                    const Vector<S>& y, S ts, bool initial_state,
                    int max_iterations, PhysicalFit<S>* out) {
  using namespace physical_detail;
  const Eigen::Index N = y.size();
  if (N < 1) return bad_input("the record is empty");
  if (!(ts > 0)) return bad_input("the sampling interval must be > 0");
  if (tmpl.kind == PhysicalKind::kStop) {
    if (tmpl.F.size() < 3 || !(tmpl.F(0) != 0)) {
      return bad_input("an end stop needs a model of order >= 2");
    }
    if (static_cast<Eigen::Index>(tmpl.fixed.size()) != tmpl.F.size() - 1) {
      return dimension_mismatch("one fixed flag per coefficient of F");
    }
  }
  PhysicalModel<S> start = tmpl;
  bool x0 = initial_state;
  if (x0 && start.kind == PhysicalKind::kCascade && start.has_h0) {
    // the cascade's initial state, both levels, are parameters: no free
    // response on top; the inner one starts at rest with h0
    S z0, h0;
    cascade_levels(start, &z0, &h0);
    start.has_z0 = true;
    start.z0 = z0;
    x0 = false;
  }
  out->ok = false;
  out->model = start;
  const Eigen::Index nfit = std::min<Eigen::Index>(N, 6000);
  const Vector<S> yfit = y.head(nfit);
  // the channel signals of the first nfit samples
  Matrix<S> Wfit(nfit, nc);
  for (Eigen::Index j = 0; j < nc; ++j) {
    Wfit.col(j) = Eigen::Map<const Vector<S>>(W + j * N, nfit);
  }
  FitProblem<S> fit(start, Wfit.data(), nc, yfit, ts, x0);
  Vector<S> th = pack_physical<S>(start, nullptr);
  const Eigen::Index np = th.size();
  const Vector<S> r0 = fit.errors_at(th);
  if (!std::isfinite(r0.squaredNorm())) return Status::Ok();
  OeSettings<S> settings;
  settings.max_iterations =
      std::min(std::max(max_iterations, 1),
               std::max(8, static_cast<int>(std::floor(48000.0 / nfit))));
  settings.tolerance = 0;
  settings.gradient_tolerance = 0;
  settings.initial_damping = S(1e-3);
  settings.max_damping_attempts = 6;
  settings.min_damping = S(1e-9);
  settings.decrease_tolerance = S(1e-7);
  settings.relative_scale_floor = S(1e-3);  // 1e-6 on J^T J's diagonal
  LmBound<S> bound;
  if (fit.bound() >= 0) {
    bound.index = static_cast<int>(fit.bound());
    bound.lower = 0;
    bound.upper = 1;
  }
  LmOutcome<S> lm;
  const Vector<S> zero = Vector<S>::Zero(nfit);
  Status status = levenberg_marquardt<S>(fit, zero, settings, bound, &th, &lm);
  if (!status.ok()) return Status::Ok();
  out->model = unpack_physical(start, th);
  Matrix<S> E;
  errors<S>({out->model}, W, nc, y, ts, x0, &E);
  if (!E.allFinite()) return Status::Ok();
  out->e = E.col(0);
  out->theta = th;
  out->sse = lm.cost;
  out->iterations = lm.iterations;
  const S n = static_cast<S>(N);
  out->s2 = out->e.squaredNorm() / std::max<S>(n - np, 1);
  out->bic = n * std::log(out->s2) + np * std::log(n);
  const S s2f = lm.cost / std::max<S>(static_cast<S>(nfit - np), 1);
  const Matrix<S>& J = lm.jacobian;
  if (J.allFinite()) {
    out->cov = s2f * pseudo_inverse<S>(J.transpose() * J);
  } else {
    out->cov = Matrix<S>::Constant(np, np, std::numeric_limits<S>::quiet_NaN());
  }
  out->ok = true;
  return Status::Ok();
}

}  // namespace ctid::residtrace
