// SPDX-License-Identifier: BSD-3-Clause
// Copyright (C) the ctid authors

// The Coulomb-friction candidate of residtrace: the extra regressor
// sign(v) in the filtered linear regression, as the thesis does for the
// throttle (sec. 4.2, eq. 4.17).
//
//   - The velocity v: the SVF derivative of the measured output (a model of
//     order >= 2 reads its output as a position), filtered forward and
//     backward so that its zero crossings are not delayed (the record's
//     vhat, first column), or the output itself when it is a velocity (its
//     second column: a variant for models of any order, the only one for a
//     first-order model). A second variant of each adds a constant:
//     Coulomb levels that differ with the direction.
//   - Each variant is fitted on its own (select_variant, one variant at a
//     time). The BIC on the estimation data chooses among the fits whose
//     sign(v) gain opposes the motion (b_s < 0, F being monic: a
//     friction), among all when none does.
//   - When no variant gives a friction, each is fitted again with v the
//     velocity of the model's own output (the current model's simulation
//     on the estimation record, then the fitted candidate's; two passes),
//     filtered the same way: at rest the sign of the measured velocity is
//     the measurement noise's, correlated with the equation error, and a
//     body that sticks between the steps of its input then gets a gain
//     pushing along the motion; the model's velocity is free of that
//     noise and is the one its simulation uses.
//   - Not applicable: a fitted gain b_s > 0 (a force along the motion is
//     not friction), and a sign(v) that the input's levels and a constant
//     explain to more than 90 % (R^2; with a two-level input through a
//     velocity sign(v) follows the input): not identifiable from these
//     data. Whether the term is determined and the velocity reverses often
//     enough is the judgement's general check (judgement.hpp, accept: the
//     evidence's share of samples moving forward and its reversals).
//
// Evidence: the fitted gain b_s with its standard deviation, the friction
// level -b_s / b_u in input units (a force when the input is a force), the
// correlation of the current residual with sign(v) through the prefilter
// (prefilter.hpp), R^2 of sign(v) on the input, the share and reversals.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <string>
#include <vector>

#include "ctid/apps/residtrace/candidate.hpp"
#include "ctid/apps/residtrace/prefilter.hpp"
#include "ctid/apps/residtrace/responses.hpp"

namespace ctid::residtrace {

namespace coulomb_detail {

// The variants on a record, their names and sign(v) signals.
template <typename S>
struct Variants {
  std::vector<Variant<S>> v;
  std::vector<Vector<S>> sign;
};

// sign(v) and sign(v) with a constant, for each velocity (0: dy/dt, the
// record's vhat column 0; 1: y, column 1) that changes sign; each name is
// its velocity's name followed by suffix.
template <typename S>
Variants<S> variants_on(const ResidtraceModel<S>& cur, const Matrix<S>& vhat,
                        const std::vector<int>& kinds,
                        const std::vector<std::string>& vnames,
                        const std::string& suffix) {
  Variants<S> out;
  bool has_const = false;
  for (const StructureChannel<S>& ch : cur.channels) {
    has_const = has_const || ch.kind == ChannelKind::kConstant;
  }
  for (std::size_t i = 0; i < kinds.size(); ++i) {
    const int col = kinds[i];
    if (vhat.cols() <= col) continue;
    Vector<S> s(vhat.rows());
    bool pos = false, neg = false;
    for (Eigen::Index k = 0; k < s.size(); ++k) {
      const S x = vhat(k, col);
      s(k) = x > 0 ? S(1) : (x < 0 ? S(-1) : (x == 0 ? S(0) : x));
      pos = pos || x > 0;
      neg = neg || x < 0;
    }
    if (!(pos && neg)) continue;
    StructureChannel<S> sv;
    sv.kind = col == 1 ? ChannelKind::kSignOutput : ChannelKind::kSignV;
    sv.col = -1;
    sv.nb = 1;
    sv.nk = 0;
    sv.B = Vector<S>::Zero(1);
    Variant<S> v;
    v.name = vnames[i] + suffix;
    v.tmpl = cur;
    v.tmpl.channels.push_back(sv);
    v.channel_names = {"sign(v)"};
    v.starts = {cur.F};
    out.v.push_back(v);
    out.sign.push_back(s);
    if (!has_const && !cur.levels) {
      // unequal levels for the two directions: sign(v) plus a constant
      StructureChannel<S> k;
      k.kind = ChannelKind::kConstant;
      k.col = -1;
      k.nb = 1;
      k.nk = 0;
      k.B = Vector<S>::Zero(1);
      Variant<S> a;
      a.name = vnames[i] + ", asymmetric" + suffix;
      a.tmpl = cur;
      a.tmpl.channels.push_back(k);
      a.tmpl.channels.push_back(sv);
      a.channel_names = {"offset", "sign(v)"};
      a.starts = {cur.F};
      out.v.push_back(a);
      out.sign.push_back(s);
    }
  }
  return out;
}

// The fit of one variant on its own, or none (has = false).
template <typename S>
struct Fit {
  bool has = false;
  ResidtraceModel<S> model;
};

template <typename S>
Status fit_each(const std::vector<Variant<S>>& variants,
                const CandidateContext<S>& ctx, std::vector<Fit<S>>* fits,
                std::vector<VariantRow<S>>* table) {
  for (const Variant<S>& v : variants) {
    int best = -1;
    Fit<S> f;
    std::vector<VariantRow<S>> t;
    Status s = select_variant<S>({v}, ctx, &best, &f.model, &t);
    if (!s.ok()) return s;
    f.has = best >= 0;
    fits->push_back(f);
    table->insert(table->end(), t.begin(), t.end());
  }
  return Status::Ok();
}

// The fit of smallest BIC among those whose sign(v) gain opposes the
// motion, among all when none does; -1 when none was fitted.
template <typename S>
int choose(const std::vector<Fit<S>>& fits, std::size_t from = 0) {
  bool any_friction = false;
  for (std::size_t i = from; i < fits.size(); ++i) {
    any_friction =
        any_friction ||
        (fits[i].has && fits[i].model.estimate.theta(
                            fits[i].model.estimate.theta.size() - 1) < 0);
  }
  int best = -1;
  S bic = std::numeric_limits<S>::infinity();
  for (std::size_t i = from; i < fits.size(); ++i) {
    if (!fits[i].has) continue;
    const ModelEstimate<S>& e = fits[i].model.estimate;
    const S b = any_friction && !(e.theta(e.theta.size() - 1) < 0)
                    ? std::numeric_limits<S>::infinity()
                    : e.bic;
    // the first of the smallest; a BIC that is not a number only when all are
    if (best < 0 || b < bic || (std::isnan(bic) && !std::isnan(b))) {
      best = static_cast<int>(i);
      bic = b;
    }
  }
  return best;
}

// R^2 of s regressed on the inputs' levels (each distinct level of an
// input of at most four levels its own indicator, a continuous input
// itself) and a constant; 1 when s is constant.
// The distinct values of x in ascending order; *nans: how many are not a
// number (each its own value, as Octave's unique counts them).
template <typename S>
std::vector<S> levels(const Vector<S>& x, std::size_t* nans) {
  std::vector<S> lv;
  *nans = 0;
  for (Eigen::Index k = 0; k < x.size(); ++k) {
    if (std::isnan(x(k))) {
      ++*nans;
    } else {
      lv.push_back(x(k));
    }
  }
  std::sort(lv.begin(), lv.end());
  lv.erase(std::unique(lv.begin(), lv.end()), lv.end());
  return lv;
}

template <typename S>
S explained(const Vector<S>& s, const Matrix<S>& u) {
  const Eigen::Index N = s.size();
  std::vector<Vector<S>> cols(1, Vector<S>::Ones(N));
  for (Eigen::Index j = 0; j < u.cols(); ++j) {
    std::size_t nans = 0;
    const std::vector<S> lv = levels<S>(u.col(j), &nans);
    if (lv.size() + nans <=
        4) {  // (a level that is not a number: a zero column)
      for (std::size_t i = 1; i < lv.size(); ++i) {
        cols.push_back((u.col(j).array() == lv[i]).template cast<S>());
      }
    } else {
      cols.push_back(u.col(j));
    }
  }
  const Vector<S> sc = s.array() - s.mean();
  if ((sc.array() == 0).all()) return 1;
  Matrix<S> X(N, static_cast<Eigen::Index>(cols.size()));
  for (std::size_t i = 0; i < cols.size(); ++i) {
    X.col(static_cast<Eigen::Index>(i)) = cols[i];
  }
  const Vector<S> r = s - X * X.colPivHouseholderQr().solve(s);
  return 1 - r.squaredNorm() / sc.squaredNorm();
}

template <typename S>
bool two_level(const Matrix<S>& u) {
  for (Eigen::Index j = 0; j < u.cols(); ++j) {
    std::size_t nans = 0;
    if (levels<S>(u.col(j), &nans).size() + nans == 2) return true;
  }
  return false;
}

// Sign changes of s, its zeros skipped.
template <typename S>
int reversals(const Vector<S>& s) {
  int n = 0;
  S last = 0;
  for (Eigen::Index k = 0; k < s.size(); ++k) {
    if (s(k) == 0) continue;
    if (last != 0 && s(k) != last) ++n;
    last = s(k);
  }
  return n;
}

template <typename S>
S correlation(const Vector<S>& a, const Vector<S>& b) {
  if (a.size() != b.size() || a.size() == 0) {
    return std::numeric_limits<S>::quiet_NaN();
  }
  const Vector<S> x = a.array() - a.mean(), y = b.array() - b.mean();
  return x.dot(y) / std::sqrt(x.squaredNorm() * y.squaredNorm());
}

}  // namespace coulomb_detail

// The Coulomb-friction candidate (head of this file).
template <typename S>
Status coulomb_candidate(const ResidtraceModel<S>& cur,
                         const CandidateContext<S>& ctx, Candidate<S>* c) {
  using candidate_detail::num;
  namespace cd = coulomb_detail;
  if (c == nullptr) return bad_input("no result");
  *c = Candidate<S>();
  c->effect = "coulomb";
  for (const StructureChannel<S>& ch : cur.channels) {
    if (ch.kind == ChannelKind::kSignV || ch.kind == ChannelKind::kSignOutput) {
      c->reason = "the model has Coulomb friction already";
      return Status::Ok();
    }
  }
  const Eigen::Index N = ctx.D.y.size();
  const int n = static_cast<int>(cur.F.size()) - 1;
  // which velocity: dy/dt (the output a position), or the output itself
  // (a velocity; for a first-order model both columns are y)
  std::vector<int> kinds = {0, 1};
  std::vector<std::string> vnames = {"sign(dy/dt)", "sign(y)"};
  if (n == 1) {
    kinds = {1};
    vnames = {"sign(y)"};
  }
  cd::Variants<S> vars = cd::variants_on<S>(cur, ctx.D.vhat, kinds, vnames, "");
  if (vars.v.empty()) {
    c->reason = "the velocity never changes sign";
    return Status::Ok();
  }
  std::vector<cd::Fit<S>> fits;
  Status s = cd::fit_each<S>(vars.v, ctx, &fits, &c->variants);
  if (!s.ok()) return s;
  int m = cd::choose<S>(fits);
  const Vector<S>& e_cur = cur.estimate.e;
  if ((m < 0 || fits[m].model.estimate.theta(
                    fits[m].model.estimate.theta.size() - 1) >= 0) &&
      !std::isnan(ctx.lam_v) && e_cur.size() == N) {
    // the velocity of the model's own output (head of this file)
    Vector<S> x = ctx.D.y - e_cur;
    for (int it = 1; it <= 2; ++it) {
      CandidateContext<S> cm = ctx;
      Vector<S> v0, v1;
      s = zero_lag_velocity<S>(x.data(), N, ctx.D.ts, ctx.lam_v, ctx.vel_is_y,
                               &v0);
      if (!s.ok()) return s;
      s = zero_lag_velocity<S>(x.data(), N, ctx.D.ts, ctx.lam_v, true, &v1);
      if (!s.ok()) return s;
      cm.D.vhat.resize(N, 2);
      cm.D.vhat.col(0) = v0;
      cm.D.vhat.col(1) = v1;
      char suffix[48];
      std::snprintf(suffix, sizeof(suffix), ", model's velocity (%d)", it);
      std::vector<std::string> names2;
      for (const std::string& name : vnames) names2.push_back(name + suffix);
      cd::Variants<S> v2 =
          cd::variants_on<S>(cur, cm.D.vhat, kinds, names2, "");
      if (v2.v.empty()) break;
      const std::size_t from = fits.size();
      s = cd::fit_each<S>(v2.v, cm, &fits, &c->variants);
      if (!s.ok()) return s;
      vars.v.insert(vars.v.end(), v2.v.begin(), v2.v.end());
      vars.sign.insert(vars.sign.end(), v2.sign.begin(), v2.sign.end());
      const int m2 = cd::choose<S>(fits, from);
      if (m2 < 0 || fits[m2].model.estimate.e.size() != N) break;
      x = ctx.D.y - fits[m2].model.estimate.e;
    }
  }
  m = cd::choose<S>(fits);
  if (m < 0) {
    c->reason = "the estimation failed";
    c->failed = true;
    return Status::Ok();
  }
  const ResidtraceModel<S>& fit = fits[m].model;
  const Vector<S>& sv = vars.sign[m];
  const Eigen::Index k = fit.estimate.theta.size() - 1;
  const S val = fit.estimate.theta(k);
  const S sd = std::sqrt(fit.estimate.cov(k, k));
  const Vector<S>& b1 = fit.channels[0].B;
  const S bu = b1(b1.size() - 1);
  // identifiable? sign(v) must not be (nearly) a function of the input:
  // with a two-level input through a velocity, sign(v) follows sign(u)
  const S r2 = cd::explained<S>(sv, ctx.D.u);
  if (r2 > S(0.9)) {
    c->reason = "not identifiable from these data: sign(v) is " +
                num("%.0f", 100 * r2) +
                " % explained by the input and a constant (" +
                (cd::two_level<S>(ctx.D.u)
                     ? std::string("a two-level input")
                     : std::string("the input decides the direction")) +
                ")";
    return Status::Ok();
  }
  if (val > 0) {  // F monic: friction needs b_s < 0
    c->reason = "the fitted term " + num("%.3g", val) +
                " sign(v) pushes along the motion: not a friction";
    return Status::Ok();
  }
  c->applicable = true;
  c->has_model = true;
  c->model = fit;
  c->chosen = m;
  c->variant = vars.v[m].name;
  c->added_channels = vars.v[m].channel_names;
  c->nadd = fit.estimate.np - cur.estimate.np;
  Vector<S> Fp;
  s = prefilter_denominator<S>(cur.F, ctx.wlo, &Fp);
  if (!s.ok()) return s;
  const Vector<S> f = Fp.tail(Fp.size() - 1) / Fp(0);
  Matrix<S> sf;
  s = filtered_derivatives<S>(f, ctx.D.ts, InterSample::kZoh, sv.data(), N, sf);
  if (!s.ok()) return s;
  const S r = cd::correlation<S>(e_cur, sf.col(0));
  S share = 0;
  for (Eigen::Index i = 0; i < N; ++i) share += sv(i) > 0 ? 1 : 0;
  share /= static_cast<S>(N);
  c->evidence.add("term", "b_s (gain of sign(v))");
  c->evidence.add("value", val);
  c->evidence.add("std", sd);
  c->evidence.add("physical", -val / bu);
  c->evidence.add("physical_std", sd / std::abs(bu));
  c->evidence.add("corr", r);
  c->evidence.add("r2_input", r2);
  c->evidence.add("share", share);
  c->evidence.add("reversals", static_cast<S>(cd::reversals<S>(sv)));
  c->evidence.text =
      "Coulomb level " + num("%.4g", -val / bu) + " +- " +
      num("%.2g", sd / std::abs(bu)) +
      " (input units); corr(residual, sign(v)/F) = " + num("%.2f", r);
  c->evidence.add("text", c->evidence.text);
  return Status::Ok();
}

}  // namespace ctid::residtrace
