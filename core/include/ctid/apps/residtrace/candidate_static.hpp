// SPDX-License-Identifier: BSD-3-Clause
// Copyright (C) the ctid authors
// The static-nonlinearity candidate of residtrace
// (octave/private/residtrace_cand_static.m). Variants:
//   - on an input (Hammerstein): extra channels u^2, u^3 or both, or the
//     input clipped to +-c (with the input's own channel a saturation or a
//     dead zone; c at the 30, 50, 70, 85 and 95 % quantiles of |u|), each
//     with as many numerator coefficients as the input's own; the best
//     level is then refined between its grid neighbours by a
//     golden-section search of the BIC, each level screened with a few
//     SRIVC iterations from the fitted model, the best one iterated to
//     convergence and kept if its BIC is smaller. Not with an input of two
//     levels only, through which every static map is affine.
//   - The polynomial u + a2 u^2 + a3 u^3 of a model that is only
//     B(p)/F(p) u (one input, nb >= 2, no fixed coefficient, output term,
//     initial state or drift, open loop) is a Hammerstein model, B_k =
//     a_k B: it is estimated by HSRIVC (offline/hammerstein.hpp: the
//     products separated with their covariance, thesis eqs. 2.8-2.13),
//     which uses 2 nb - 2 fewer parameters than the unconstrained
//     channels; its theta is the free f's and the products [b, a2 b,
//     a3 b], their covariance J C J^T with J the Jacobian of the products
//     in [f, b, a2, a3]. With nb = 1 the two structures coincide and the
//     channels are fitted as such.
//   - on the output (Wiener): y = x + c2 x^2 + c3 x^3 with x the model
//     output, by alternation with SRIVC (fit_model).
// select_variant keeps the variant of smallest BIC on the estimation data.
// Evidence: the fitted coefficients with their standard deviations (a2,
// a3 of the Hammerstein model; c2, c3 of the output polynomial; the
// numerators of the added channels otherwise).
#pragma once

#include <algorithm>
#include <cmath>
#include <complex>
#include <limits>
#include <string>
#include <vector>

#include "ctid/apps/residtrace/candidate.hpp"
#include "ctid/apps/residtrace/candidate_state.hpp"
#include "ctid/apps/residtrace/simulate.hpp"
#include "ctid/offline/hammerstein.hpp"

namespace ctid::residtrace {

// The input nonlinearity u + a2 u^2 + a3 u^3 of a Hammerstein fit: alpha
// = [1 a2 a3] and the standard deviations [0 sd2 sd3].
template <typename S>
struct HammersteinPart {
  bool present = false;
  Vector<S> alpha, sd;
};

namespace static_detail {

// x(max(1, min(N, round(p N)))) of the sorted x (1-based): the quantile
// of the level grid.
template <typename S>
S grid_quantile(std::vector<S> x, S p) {
  std::sort(x.begin(), x.end());
  const long n = static_cast<long>(x.size());
  const long i = std::max(1L, std::min(n, std::lround(p * static_cast<S>(n))));
  return x[static_cast<std::size_t>(i - 1)];
}

template <typename S>
std::vector<S> absolute(const Matrix<S>& u, int col) {
  std::vector<S> a(static_cast<std::size_t>(u.rows()));
  for (Eigen::Index k = 0; k < u.rows(); ++k) {
    a[static_cast<std::size_t>(k)] = std::abs(u(k, col));
  }
  return a;
}

// Does the input take two levels only (to a part in 1e9 of its range)?
template <typename S>
bool two_levels(const Matrix<S>& u, int col) {
  S mx = 0;
  for (Eigen::Index k = 0; k < u.rows(); ++k) {
    mx = std::max(mx, std::abs(u(k, col)));
  }
  const S q = mx * S(1e-9) + std::numeric_limits<S>::epsilon();
  std::vector<S> r;
  for (Eigen::Index k = 0; k < u.rows(); ++k) {
    const S v = std::round(u(k, col) / q);
    if (std::find(r.begin(), r.end(), v) == r.end()) {
      r.push_back(v);
      if (r.size() > 2) return false;
    }
  }
  return true;
}

// Can the polynomial of the input be fitted as a Hammerstein model by
// HSRIVC (head of this file)?
template <typename S>
bool hammerstein_plain(const ResidtraceModel<S>& cur,
                       const CandidateContext<S>& ctx) {
  if (cur.channels.size() != 1) return false;
  const StructureChannel<S>& ch = cur.channels[0];
  bool fixed = false;
  for (bool f : cur.fixed) fixed = fixed || f;
  return ch.kind == ChannelKind::kInput && ch.nb >= 2 && !fixed &&
         cur.out.empty() && !cur.x0 && !ctx.D.closed && !cur.drifting &&
         !ctx.D.initial_state;
}

// The Hammerstein variant fitted by HSRIVC (head of this file): cur with
// the channels u, u^2, u^3 whose numerators are the products, its
// estimate on the estimation record; estimate.ok false when HSRIVC fails
// or returns an unstable F.
template <typename S>
Status hammerstein_fit(const ResidtraceModel<S>& cur,
                       const CandidateContext<S>& ctx, std::size_t j,
                       ResidtraceModel<S>* m, HammersteinPart<S>* part) {
  const FitRecord<S>& D = ctx.D;
  const StructureChannel<S>& ch = cur.channels[j];
  const int nb = ch.nb;
  const int nf = static_cast<int>(cur.F.size()) - 1;
  *m = cur;
  m->estimate = ModelEstimate<S>();
  m->estimate.ok = false;
  *part = HammersteinPart<S>();
  const Eigen::Index N = D.y.size();
  Matrix<S> W(N, 3);
  for (Eigen::Index k = 0; k < N; ++k) {
    const S u = D.u(k, ch.col);
    W(k, 0) = u;
    W(k, 1) = u * u;
    W(k, 2) = u * u * u;
  }
  // (hsrivc refuses a basis column that is zero or data that are not
  // finite)
  if (!W.allFinite() || !D.y.allFinite()) return Status::Ok();
  for (Eigen::Index i = 0; i < 3; ++i) {
    if ((W.col(i).array() == 0).all()) return Status::Ok();
  }
  BlockOrders o;
  o.nb = nb;
  o.nf = nf;
  o.nk = ch.nk;
  BlockSettings<S> settings;
  settings.u_rule = D.rule;
  settings.y_rule = InterSample::kFoh;
  RivData<S> data;
  data.y = D.y.data();
  data.w = W.data();
  data.num_samples = N;
  data.ts = D.ts;
  BlockResult<S> r;
  const Status s =
      block_srivc<S>(BlockModel::kHammerstein, o, settings, data, 3, &r);
  if (!s.ok() && s.code() != ErrorCode::kNotConverged) return Status::Ok();
  const Vector<S>& a = r.alpha;
  if (a.size() != 3 || r.f.size() != nf || r.b.size() != nb || !a.allFinite() ||
      !r.f.allFinite() || !r.b.allFinite()) {
    return Status::Ok();
  }
  Vector<S> F(nf + 1);
  F << S(1), r.f;
  for (const std::complex<S>& pole : roots_descending<S>(F)) {
    if (pole.real() >= 0) return Status::Ok();
  }
  const Vector<S> b = r.b;
  m->F = F;
  m->channels[j].B = b;
  for (int p = 2; p <= 3; ++p) {
    StructureChannel<S> k;
    k.kind = ChannelKind::kPower;
    k.col = ch.col;
    k.param = static_cast<S>(p);
    k.nb = nb;
    k.nk = ch.nk;
    k.B = a(p - 1) * b;
    m->channels.push_back(k);
  }
  ModelSimulation<S> sim;
  Status st = simulate_model<S>(*m, D.u, D.ts, nullptr, ctx.fit.substeps,
                                nullptr, &sim);
  if (!st.ok()) return st;
  ModelEstimate<S>& e = m->estimate;
  e.e = D.y - sim.y;
  const S n = static_cast<S>(N);
  e.np = nf + nb + 2;
  e.s2 = e.e.squaredNorm() / std::max<S>(n - e.np, 1);
  e.bic = n * std::log(e.s2) + e.np * std::log(n);
  // the products theta = [f, b, a2 b, a3 b] from [f, b, a2, a3]
  Matrix<S> J = Matrix<S>::Zero(nf + 3 * nb, nf + nb + 2);
  J.topLeftCorner(nf, nf).setIdentity();
  for (int k = 0; k < 3; ++k) {
    const int row = nf + k * nb;
    J.block(row, nf, nb, nb) = a(k) * Matrix<S>::Identity(nb, nb);
    if (k > 0) J.block(row, nf + nb + k - 1, nb, 1) = b;
  }
  e.theta.resize(nf + 3 * nb);
  e.theta << r.f, b, a(1) * b, a(2) * b;
  e.cov = J * r.covariance * J.transpose();
  e.ok = true;
  e.set = true;
  part->present = true;
  part->alpha = a;
  part->sd.resize(3);
  part->sd(0) = 0;
  for (int k = 1; k < 3; ++k) {
    part->sd(k) = std::sqrt(
        std::max<S>(r.covariance(nf + nb + k - 1, nf + nb + k - 1), 0));
  }
  return Status::Ok();
}

// The name of a clip channel at level L of the input channel named nm.
inline std::string clip_name(const std::string& nm, double L) {
  return "clip(" + nm + ", " + candidate_detail::num("%.3g", L) + ")";
}

// refine_clip: the clipping level between the neighbouring quantiles of
// the grid, by a golden-section search of the BIC (head of this file).
// best: the chosen clip variant's fit, replaced with its name when the
// refined level has a smaller BIC.
template <typename S>
Status refine_clip(const std::vector<std::string>& names,
                   const CandidateContext<S>& ctx, ResidtraceModel<S>* best,
                   std::string* variant, std::string* channel_name) {
  const int col = best->channels.back().col;
  if (col < 0 || static_cast<std::size_t>(col) >= names.size()) {
    return bad_input("no channel name for the clipped input");
  }
  const std::vector<S> a = absolute<S>(ctx.D.u, col);
  const S qs[] = {S(0.2), S(0.3), S(0.5), S(0.7), S(0.85), S(0.95), S(0.99)};
  const int nq = 7;
  std::vector<S> lev;
  for (S q : qs) lev.push_back(grid_quantile<S>(a, q));
  int i = 0;
  const S p0 = best->channels.back().param;
  for (int k = 1; k < nq; ++k) {
    if (std::abs(lev[k] - p0) < std::abs(lev[i] - p0)) i = k;
  }
  S lo = lev[std::max(i - 1, 0)], hi = lev[std::min(i + 1, nq - 1)];
  const S g = (std::sqrt(S(5)) - 1) / 2;
  CandidateContext<S> quick = ctx;
  quick.fit.max_iterations =
      std::max(1, std::min(3, ctx.fit.max_iterations / 3));
  auto fit = [&](S L, const CandidateContext<S>& c, ResidtraceModel<S>* m) {
    ResidtraceModel<S> t = *best;
    t.channels.back().param = L;
    Status s = fit_model<S>(t, c.D, {best->F}, c.fit, m);
    if (s.ok() && !m->estimate.ok) {
      m->estimate.bic = std::numeric_limits<S>::infinity();
    }
    return s;
  };
  S x1 = hi - g * (hi - lo), x2 = lo + g * (hi - lo);
  ResidtraceModel<S> m1, m2;
  Status s = fit(x1, quick, &m1);
  if (s.ok()) s = fit(x2, quick, &m2);
  for (int it = 0; it < 8 && s.ok(); ++it) {
    if (m1.estimate.bic < m2.estimate.bic) {
      hi = x2;
      x2 = x1;
      m2 = m1;
      x1 = hi - g * (hi - lo);
      s = fit(x1, quick, &m1);
    } else {
      lo = x1;
      x1 = x2;
      m1 = m2;
      x2 = lo + g * (hi - lo);
      s = fit(x2, quick, &m2);
    }
  }
  if (!s.ok()) return s;
  const S L = m1.estimate.bic < m2.estimate.bic ? x1 : x2;
  ResidtraceModel<S> m;
  s = fit(L, ctx, &m);
  if (!s.ok()) return s;
  if (m.estimate.ok && m.estimate.bic < best->estimate.bic) {
    *best = m;
    *channel_name =
        clip_name(names[static_cast<std::size_t>(col)], static_cast<double>(L));
    const std::size_t at = variant->rfind("+-");
    if (at != std::string::npos) {
      *variant = variant->substr(0, at) + "+-" +
                 candidate_detail::num("%.4g", best->channels.back().param);
    }
  }
  return Status::Ok();
}

}  // namespace static_detail

// The static-nonlinearity candidate (head of this file) of the current
// model cur (its estimate's np read for the number of added parameters);
// names: the names of cur's channels (the added channels and the variants
// are named after them). part: the input nonlinearity of the Hammerstein
// variant, when that one is chosen.
template <typename S>
Status static_candidate(const ResidtraceModel<S>& cur,
                        const std::vector<std::string>& names,
                        const CandidateContext<S>& ctx, Candidate<S>* c,
                        HammersteinPart<S>* part) {
  using namespace static_detail;
  using candidate_detail::mat2str;
  using candidate_detail::num;
  if (c == nullptr || part == nullptr) return bad_input("no result");
  *c = Candidate<S>();
  *part = HammersteinPart<S>();
  c->effect = "static_nonlinearity";
  if (names.size() != cur.channels.size()) {
    return dimension_mismatch("one name per channel of the model");
  }
  bool has = false;
  for (const StructureChannel<S>& k : cur.channels) {
    has = has || k.kind == ChannelKind::kPower || k.kind == ChannelKind::kClip;
  }
  for (const OutputTerm<S>& t : cur.out) {
    has = has || t.kind == OutputTermKind::kPolynomial;
  }
  if (has) {
    c->reason = "the model has a static nonlinearity already";
    return Status::Ok();
  }
  const Matrix<S>& U = ctx.D.u;
  std::vector<Variant<S>> variants;
  std::vector<HammersteinPart<S>> parts;
  std::string why;
  for (std::size_t j = 0; j < cur.channels.size(); ++j) {
    const StructureChannel<S>& ch = cur.channels[j];
    if (ch.kind != ChannelKind::kInput) continue;
    if (ch.col < 0 || ch.col >= U.cols()) {
      return bad_input("an input channel's column is not in the record");
    }
    if (two_levels<S>(U, ch.col)) {
      why = "two-level input: an input nonlinearity is not identifiable; ";
      continue;
    }
    const std::string& nm = names[j];
    const std::vector<std::vector<int>> pw = {{2}, {3}, {2, 3}};
    for (const std::vector<int>& p : pw) {
      Variant<S> v;
      if (p.size() == 2 && hammerstein_plain(cur, ctx)) {
        v.name =
            nm + " + a2 " + nm + "^2 + a3 " + nm + "^3 (Hammerstein, hsrivc)";
        HammersteinPart<S> h;
        Status s = hammerstein_fit<S>(cur, ctx, j, &v.tmpl, &h);
        if (!s.ok()) return s;
        v.fitted = true;
        v.channel_names = {nm + "^2", nm + "^3"};
        variants.push_back(v);
        parts.push_back(h);
        continue;
      }
      v.tmpl = cur;
      std::string list;
      for (int q : p) {
        StructureChannel<S> k;
        k.kind = ChannelKind::kPower;
        k.col = ch.col;
        k.param = static_cast<S>(q);
        k.nb = ch.nb;
        k.nk = ch.nk;
        k.B = Vector<S>::Zero(ch.nb);
        v.tmpl.channels.push_back(k);
        v.channel_names.push_back(nm + "^" + std::to_string(q));
        list += (list.empty() ? "" : " ") + std::to_string(q);
      }
      v.name = nm + ": powers " + (p.size() == 1 ? list : "[" + list + "]");
      v.starts = {cur.F};
      variants.push_back(v);
      parts.push_back(HammersteinPart<S>());
    }
    const std::vector<S> a = absolute<S>(U, ch.col);
    for (S q : {S(0.3), S(0.5), S(0.7), S(0.85), S(0.95)}) {
      const S lev = grid_quantile<S>(a, q);
      if (!(lev > 0)) continue;
      Variant<S> v;
      v.tmpl = cur;
      StructureChannel<S> k;
      k.kind = ChannelKind::kClip;
      k.col = ch.col;
      k.param = lev;
      k.nb = ch.nb;
      k.nk = ch.nk;
      k.B = Vector<S>::Zero(ch.nb);
      v.tmpl.channels.push_back(k);
      v.channel_names.push_back(clip_name(nm, static_cast<double>(lev)));
      v.name = nm + " clipped at +-" + num("%.4g", lev);
      v.starts = {cur.F};
      variants.push_back(v);
      parts.push_back(HammersteinPart<S>());
    }
  }
  {
    Variant<S> v;
    v.tmpl = cur;
    OutputTerm<S> t;
    t.kind = OutputTermKind::kPolynomial;
    t.c = Vector<S>::Zero(2);
    t.cstd = Vector<S>::Zero(2);
    v.tmpl.out.push_back(t);
    v.name = "output: c2 x^2 + c3 x^3";
    v.starts = {cur.F};
    variants.push_back(v);
    parts.push_back(HammersteinPart<S>());
  }
  int best = -1;
  ResidtraceModel<S> m;
  Status s = select_variant<S>(variants, ctx, &best, &m, &c->variants);
  if (!s.ok()) return s;
  if (best < 0) {
    c->reason = why + "the estimation failed";
    c->failed = true;
    return Status::Ok();
  }
  c->variant = variants[best].name;
  c->added_channels = variants[best].channel_names;
  if (!m.channels.empty() && m.channels.back().kind == ChannelKind::kClip) {
    s = refine_clip<S>(names, ctx, &m, &c->variant, &c->added_channels.back());
    if (!s.ok()) return s;
  }
  c->applicable = true;
  c->has_model = true;
  c->model = m;
  c->chosen = best;
  c->nadd = m.estimate.np - cur.estimate.np;
  *part = parts[best];
  if (part->present) {
    c->evidence.add("term", "a2, a3");
    candidate_detail::add_row(&c->evidence, "value",
                              Vector<S>(part->alpha.tail(2)));
    candidate_detail::add_row(&c->evidence, "std", Vector<S>(part->sd.tail(2)));
    c->evidence.text =
        "Hammerstein u + a2 u^2 + a3 u^3: a2 = " + num("%.4g", part->alpha(1)) +
        " +- " + num("%.2g", part->sd(1)) +
        ", a3 = " + num("%.4g", part->alpha(2)) + " +- " +
        num("%.2g", part->sd(2));
  } else if (c->variant.compare(0, 7, "output:") == 0) {
    const OutputTerm<S>& o = m.out.back();
    c->evidence.add("term", "c2, c3");
    candidate_detail::add_row(&c->evidence, "value", o.c);
    candidate_detail::add_row(&c->evidence, "std", o.cstd);
    c->evidence.text = "output polynomial c2 = " + num("%.4g", o.c(0)) +
                       " +- " + num("%.2g", o.cstd(0)) +
                       ", c3 = " + num("%.4g", o.c(1)) + " +- " +
                       num("%.2g", o.cstd(1));
  } else {
    const ModelEstimate<S>& e = m.estimate;
    const Eigen::Index n = e.theta.size();
    const Eigen::Index k = c->nadd;
    if (k < 1 || k > n || e.cov.rows() != n || e.cov.cols() != n) {
      return numerical_failure("the fit returned no added channels' gains");
    }
    const Vector<S> val = e.theta.tail(k);
    const Vector<S> sd =
        e.cov.diagonal().tail(k).unaryExpr([](S x) { return std::sqrt(x); });
    c->evidence.add("term", "numerators of the nonlinear channels");
    candidate_detail::add_row(&c->evidence, "value", val);
    candidate_detail::add_row(&c->evidence, "std", sd);
    c->evidence.text = c->variant + ": coefficients " + mat2str<S>(val, 4) +
                       " +- " + mat2str<S>(sd, 2);
  }
  c->evidence.add("text", c->evidence.text);
  return Status::Ok();
}

}  // namespace ctid::residtrace
