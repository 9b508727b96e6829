// SPDX-License-Identifier: BSD-3-Clause
// Copyright (C) the ctid authors

// A residtrace model (model.hpp) with a physical realisation
// (physical_fit.hpp): its fit and the start of a tank cascade from a
// linear model.
//
//   fit_physical_model: the realisation fitted by its simulation error
//     (fit_physical) on the estimation record, the result written back
//     into the model: F, the numerators (a cascade's channels: their
//     gains), the output offset, the realisation's fitted fields with its
//     parameters theta and their covariance; the estimate holds np =
//     numel (theta), s2, BIC and the errors, and as theta the linear
//     part's parameters (an end stop: the free f's and the numerators, a
//     head of the realisation's theta with its covariance; a cascade: the
//     free coefficients of its linearisation F and the gains over F(0),
//     without covariance).
//
//   cascade_template: two first-order sections in series, the inner state
//     z' = b'w + d - alpha g(z), the output y = c + x with x' = g(z) -
//     gamma g(x), g a square root (Torricelli) or linear, whose
//     linearisation matches the linear model's two slowest poles (a
//     complex pair: a critically damped cascade at its modulus; a single
//     pole p: a faster upstream section at 4 p) and its static gains at
//     the record's mean channel signals and output level
//     (cascade_from_linear). Inputs, their powers and clips only, a level
//     at most as output term, stable poles, open loop. For square-root
//     nodes the output level c starts 10 % of the output's range below its
//     minimum (and at most 0). With an inner level (clip) it starts at the
//     quantile (0.7 .. 0.99) of the unclipped inner state whose clip
//     simulates the record best, nothing of the overflow kept (spill 0).
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "ctid/apps/residtrace/model.hpp"
#include "ctid/apps/residtrace/model_fit.hpp"
#include "ctid/apps/residtrace/physical_fit.hpp"
#include "ctid/apps/residtrace/simulate.hpp"
#include "ctid/base/status.hpp"

namespace ctid::residtrace {

namespace physical_model_detail {

// sum of x(k), in the order of the samples
template <typename S>
S plain_sum(const Vector<S>& x) {
  S s = 0;
  for (Eigen::Index k = 0; k < x.size(); ++k) s += x(k);
  return s;
}

// The sample standard deviation (N - 1).
template <typename S>
S sample_std(const Vector<S>& x) {
  const Eigen::Index n = x.size();
  if (n < 2) return 0;
  const S m = plain_sum(x) / static_cast<S>(n);
  S s = 0;
  for (Eigen::Index k = 0; k < n; ++k) s += (x(k) - m) * (x(k) - m);
  return std::sqrt(s / static_cast<S>(n - 1));
}

}  // namespace physical_model_detail

// The quantile q of x by linear interpolation between the sorted samples
// at (k - 1/2) / n (Hazen's rule, Octave's default); not-a-number samples
// ignored.
template <typename S>
S sample_quantile(const Vector<S>& x, S q) {
  std::vector<S> v;
  for (Eigen::Index k = 0; k < x.size(); ++k) {
    if (!std::isnan(x(k))) v.push_back(x(k));
  }
  const Eigen::Index m = static_cast<Eigen::Index>(v.size());
  if (m == 0) return std::numeric_limits<S>::quiet_NaN();
  std::sort(v.begin(), v.end());
  if (m == 1) return v[0];
  const S p = q * static_cast<S>(m) + S(0.5);
  const Eigen::Index i = std::max<Eigen::Index>(
      std::min<Eigen::Index>(static_cast<Eigen::Index>(std::floor(p)), m - 1),
      1);
  const S r = std::max(std::min(p - static_cast<S>(i), S(1)), S(0));
  return (1 - r) * v[i - 1] + r * v[i];
}

// fit_physical_model (head of this file): tmpl has a realisation; *out is
// tmpl with estimate.ok false when the simulation error is not finite.
template <typename S>
Status fit_physical_model(const ResidtraceModel<S>& tmpl, const FitRecord<S>& D,
                          int max_iterations, ResidtraceModel<S>* out) {
  if (out == nullptr) return bad_input("no result");
  if (!tmpl.has_phys) return bad_input("the model has no realisation");
  ResidtraceModel<S> model = tmpl;
  model.estimate.ok = false;
  Matrix<S> W;
  Status status = delayed_channel_signals(tmpl.channels, D.u, &W);
  if (!status.ok()) return status;
  PhysicalFit<S> fit;
  status = fit_physical<S>(physical_realisation(tmpl), W.data(), W.cols(), D.y,
                           D.ts, D.initial_state, max_iterations, &fit);
  if (!status.ok()) return status;
  if (!fit.ok) {
    *out = model;
    return Status::Ok();
  }
  const PhysicalModel<S>& q = fit.model;
  PhysicalModel<S> P = tmpl.phys;
  const bool stop = P.kind == PhysicalKind::kStop;
  model.F = q.F;
  if (stop) {
    for (std::size_t j = 0; j < model.channels.size(); ++j) {
      model.channels[j].B = q.B[j];
    }
    for (OutputTerm<S>& t : model.out) {
      if (t.kind != OutputTermKind::kOffset) continue;
      t.c = Vector<S>::Constant(1, q.offset);
      break;
    }
    P.lo = q.lo;
    P.hi = q.hi;
  } else {
    for (std::size_t j = 0; j < model.channels.size(); ++j) {
      model.channels[j].B =
          Vector<S>::Constant(1, q.b(static_cast<Eigen::Index>(j)));
    }
    P.d = q.d;
    P.alpha = q.alpha;
    P.gamma = q.gamma;
    P.c = q.c;
    P.hi = q.hi;
    P.has_yhi = q.has_yhi;
    P.yhi = q.yhi;
    P.has_spill = q.has_spill;
    P.spill = q.spill;
    P.has_h0 = q.has_h0;
    P.h0 = q.h0;
    P.has_z0 = q.has_z0;
    P.z0 = q.z0;
  }
  P.theta = fit.theta;
  P.cov = fit.cov;
  model.phys = P;
  ModelEstimate<S>& e = model.estimate;
  e.np = static_cast<int>(fit.theta.size());
  e.s2 = fit.s2;
  e.bic = fit.bic;
  e.e = fit.e;
  Eigen::Index nl = 0;
  for (bool f : model.fixed) nl += f ? 0 : 1;
  for (const StructureChannel<S>& c : model.channels) nl += c.nb;
  if (stop) {
    e.theta = fit.theta.head(nl);
    e.cov = fit.cov.topLeftCorner(nl, nl);
  } else {
    std::vector<S> th;
    const S F0 = model.F(0);
    for (std::size_t i = 0; i < model.fixed.size(); ++i) {
      if (!model.fixed[i]) {
        th.push_back(model.F(static_cast<Eigen::Index>(i) + 1) / F0);
      }
    }
    for (const StructureChannel<S>& c : model.channels) {
      for (Eigen::Index k = 0; k < c.B.size(); ++k) th.push_back(c.B(k) / F0);
    }
    e.theta = Eigen::Map<const Vector<S>>(th.data(), th.size());
    e.cov = Matrix<S>::Constant(nl, nl, std::numeric_limits<S>::quiet_NaN());
  }
  e.ok = true;
  e.set = true;
  *out = model;
  return Status::Ok();
}

// cascade_template (head of this file): *made false with the reason *why
// when the model has no cascade realisation.
template <typename S>
Status cascade_template(const ResidtraceModel<S>& cur, const FitRecord<S>& D,
                        bool sqrt_nodes, bool clip, ResidtraceModel<S>* t,
                        bool* made, std::string* why) {
  using namespace physical_model_detail;
  if (t == nullptr || made == nullptr || why == nullptr) {
    return bad_input("no result");
  }
  *made = false;
  why->clear();
  if (D.closed) {
    *why = "a cascade realisation in open loop only";
    return Status::Ok();
  }
  std::vector<StructureChannel<S>> chans;
  for (const StructureChannel<S>& c : cur.channels) {
    const bool keep = c.kind == ChannelKind::kInput ||
                      c.kind == ChannelKind::kPower ||
                      c.kind == ChannelKind::kClip;
    if (keep) {
      chans.push_back(c);
    } else if (c.kind != ChannelKind::kConstant) {
      chans.clear();
      break;
    }
  }
  if (chans.empty()) {
    *why = "channels other than inputs";
    return Status::Ok();
  }
  for (const OutputTerm<S>& o : cur.out) {
    if (o.kind != OutputTermKind::kOffset) {
      *why = "output terms other than a level";
      return Status::Ok();
    }
  }
  if (cur.F.size() < 2 || cur.F(0) == 0 || !cur.F.allFinite()) {
    *why = "integrators or unstable poles";
    return Status::Ok();
  }
  const std::vector<std::complex<S>> roots = roots_descending<S>(cur.F);
  const Eigen::Map<const Eigen::Matrix<std::complex<S>, Eigen::Dynamic, 1>> r0(
      roots.data(), static_cast<Eigen::Index>(roots.size()));
  for (Eigen::Index i = 0; i < r0.size(); ++i) {
    if (std::abs(r0(i)) * D.ts < S(1e-9) || r0(i).real() >= 0) {
      *why = "integrators or unstable poles";
      return Status::Ok();
    }
  }
  std::vector<Eigen::Index> order(static_cast<std::size_t>(r0.size()));
  for (Eigen::Index i = 0; i < r0.size(); ++i) order[i] = i;
  std::stable_sort(order.begin(), order.end(),
                   [&](Eigen::Index a, Eigen::Index b) {
                     return std::abs(r0(a)) < std::abs(r0(b));
                   });
  S p1, p2;
  if (r0.size() == 1) {
    p1 = 4 * std::abs(r0(0));
    p2 = std::abs(r0(0));
  } else if (r0(order[0]).imag() != 0) {
    p1 = p2 = std::abs(r0(order[0]));  // a pair: critically damped
  } else {
    p1 = std::abs(r0(order[1]));
    p2 = std::abs(r0(order[0]));
  }
  const Eigen::Index N = D.y.size();
  const Eigen::Index nc = static_cast<Eigen::Index>(chans.size());
  Matrix<S> W;
  Status status = simulate_detail::channel_signals_at_rest(chans, D.u, &W);
  if (!status.ok()) return status;
  Vector<S> wbar(nc), K(nc);
  const S Fn = cur.F(cur.F.size() - 1);
  for (Eigen::Index j = 0; j < nc; ++j) {
    wbar(j) = plain_sum<S>(W.col(j)) / static_cast<S>(N);
    const Vector<S>& B = chans[j].B;
    K(j) = (B.size() ? B(B.size() - 1) : S(0)) / Fn * cur.F(0);
  }
  const Vector<S>& y = D.y;
  S c0 = 0;
  if (sqrt_nodes) {
    c0 = std::min(S(0), y.minCoeff() - S(0.1) * (y.maxCoeff() - y.minCoeff()));
  }
  const S hbar = plain_sum(y) / static_cast<S>(N) - c0;
  if (!(hbar > 0)) {
    *why = "no positive level";
    return Status::Ok();
  }
  PhysicalModel<S> P;
  P.kind = PhysicalKind::kCascade;
  P.sqrt_nodes = sqrt_nodes;
  cascade_from_linear<S>(p1, p2, K, wbar, hbar, &P);
  ResidtraceModel<S> m = cur;
  for (Eigen::Index j = 0; j < nc; ++j) {
    chans[j].nb = 1;
    chans[j].B = Vector<S>::Constant(1, P.b(j));
  }
  m.channels = chans;
  m.out.clear();
  m.fixed.assign(2, false);
  P.c = c0;
  P.hi = std::numeric_limits<S>::infinity();
  P.substeps = static_cast<int>(std::min(
      S(20), std::max(S(1), std::ceil(D.ts * std::max(p1, p2) / S(0.1)))));
  P.yscale = sample_std(y);
  P.has_h0 = true;
  P.h0 = y(0) - c0;
  m.F = P.F;
  m.has_phys = true;
  m.phys = P;
  if (clip) {
    m.phys.has_spill = true;  // the share of the overflow kept
    m.phys.spill = 0;
    Vector<S> ys, z;
    status = simulate_physical_model<S>(m, D.u, D.ts, &ys, &z);
    if (!status.ok()) return status;
    S best = std::numeric_limits<S>::infinity(), hi = best;
    for (const S q : {S(0.7), S(0.8), S(0.9), S(0.95), S(0.99)}) {
      ResidtraceModel<S> mq = m;
      mq.phys.hi = sample_quantile<S>(z, q);
      Vector<S> yq, zq;
      status = simulate_physical_model<S>(mq, D.u, D.ts, &yq, &zq);
      if (!status.ok()) return status;
      const Vector<S> e = y - yq;
      const S sse = e.dot(e);
      if (sse < best) {
        best = sse;
        hi = mq.phys.hi;
      }
    }
    if (!std::isfinite(best)) {
      *why = "no inner level to try";
      return Status::Ok();
    }
    m.phys.hi = hi;
  }
  *t = m;
  *made = true;
  return Status::Ok();
}

}  // namespace ctid::residtrace
