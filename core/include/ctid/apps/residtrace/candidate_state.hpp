// SPDX-License-Identifier: BSD-3-Clause
// Copyright (C) the ctid authors
// The state-nonlinearity candidate of residtrace
// (octave/private/residtrace_cand_state.m): a function of the output
// acting inside the dynamics,
//
//   F(p) y = B(p) u + sum_k g_k y^(q_k),
//
// the terms entering like inputs (gain g_k / F(p), channels of kind
// kOutputPower). Variants:
//   - q = 1/2 (sign(y) sqrt|y|): the outflow of a tank through an orifice
//     (Torricelli), only when the output is positive on at least 95 % of
//     the samples (a level measured from its physical zero);
//   - q = 2: a time constant that depends on the operating point
//     (y' = -(a0 + a1 y) y + b u);
//   - q = 3, and q = 2 with 3: a hardening or softening spring (Duffing).
// The regression uses the measured y (its noise biases the g_k towards
// zero, as errors in variables do); fit_model then refits on the model's
// simulated output (model_fit.hpp). With the record's levels estimated the
// terms come with a constant of their own: F(p)(y - c) = B(p)(u - u0) +
// g(y) has nothing else to balance B(0) u0 where F(0) = 0 (a tank whose
// only damping is its outflow). A further variant, given by the caller,
// puts the nonlinearity at an inner node: two first-order sections with
// square-root outflows (a two-tank cascade, physical_fit.hpp) fitted on
// its simulation error; it is compared as a model fitted already.
// select_variant keeps the variant of smallest BIC on the estimation data.
// Evidence: the gains g_k with their standard deviations, or for the
// cascade its alpha, gamma and levels.
#pragma once

#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "ctid/apps/residtrace/candidate.hpp"

namespace ctid::residtrace {

namespace candidate_detail {

// A row of numbers as Octave's mat2str (x, precision) writes it: a
// scalar bare, several in brackets separated by spaces.
template <typename S>
std::string mat2str(const Vector<S>& v, int precision) {
  char spec[16];
  std::snprintf(spec, sizeof(spec), "%%.%dg", precision);
  std::string s;
  for (Eigen::Index i = 0; i < v.size(); ++i) {
    if (i > 0) s += " ";
    s += num(spec, v(i));
  }
  return v.size() == 1 ? s : "[" + s + "]";
}

// An evidence field holding a row of numbers.
template <typename S>
void add_row(Evidence<S>* e, const std::string& name, const Vector<S>& v) {
  EvidenceField<S> f;
  f.name = name;
  f.value = v;
  e->fields.push_back(f);
}

template <typename S>
StructureChannel<S> added_channel(ChannelKind kind, S param) {
  StructureChannel<S> k;
  k.kind = kind;
  k.col = -1;
  k.param = param;
  k.nb = 1;
  k.nk = 0;
  k.B = Vector<S>::Zero(1);
  return k;
}

template <typename S>
bool has_channel(const ResidtraceModel<S>& m, ChannelKind kind) {
  for (const StructureChannel<S>& c : m.channels) {
    if (c.kind == kind) return true;
  }
  return false;
}

}  // namespace candidate_detail

// The state-nonlinearity candidate (head of this file) of the current
// model cur (its estimate's np read for the number of added parameters).
// cascade: the two-section cascade with square-root outflows fitted on its
// simulation error (a physical realisation with its estimate ok, bic, s2,
// np), or nullptr for none; it is a variant only when the output is
// positive on 95 % of the samples.
template <typename S>
Status state_candidate(const ResidtraceModel<S>& cur,
                       const CandidateContext<S>& ctx,
                       const ResidtraceModel<S>* cascade, Candidate<S>* c) {
  using namespace candidate_detail;
  if (c == nullptr) return bad_input("no result");
  *c = Candidate<S>();
  c->effect = "state_nonlinearity";
  if (has_channel(cur, ChannelKind::kOutputPower) || cur.has_phys) {
    c->reason = "the model has a nonlinearity of the output already";
    return Status::Ok();
  }
  if (cascade != nullptr && !cascade->has_phys) {
    return bad_input("the cascade variant must be a physical realisation");
  }
  const Vector<S>& y = ctx.D.y;
  if (y.size() == 0) return bad_input("the record is empty");
  Eigen::Index npos = 0;
  for (Eigen::Index k = 0; k < y.size(); ++k) npos += y(k) > 0 ? 1 : 0;
  const bool positive =
      static_cast<S>(npos) / static_cast<S>(y.size()) >= S(0.95);
  std::vector<std::vector<S>> pw = {{2}, {3}, {2, 3}};
  if (positive) pw.insert(pw.begin(), std::vector<S>{S(0.5)});
  const bool lev = cur.levels && !has_channel(cur, ChannelKind::kConstant);
  std::vector<Variant<S>> variants;
  for (const std::vector<S>& p : pw) {
    Variant<S> v;
    v.tmpl = cur;
    if (lev) {
      v.tmpl.channels.push_back(added_channel<S>(ChannelKind::kConstant, S(0)));
      v.channel_names.push_back("1");
    }
    std::string names;
    for (S q : p) {
      v.tmpl.channels.push_back(added_channel<S>(ChannelKind::kOutputPower, q));
      const std::string nm = q == S(0.5)
                                 ? std::string("sqrt(y)")
                                 : "y^" + std::to_string(static_cast<int>(q));
      v.channel_names.push_back(nm);
      names += (names.empty() ? "" : ", ") + nm;
    }
    v.name = "output in the dynamics: " + names;
    v.starts = {cur.F};
    variants.push_back(v);
  }
  if (positive && cascade != nullptr && cascade->estimate.ok) {
    Variant<S> v;
    v.name = "square-root outflows of a two-section cascade";
    v.tmpl = *cascade;
    v.fitted = true;
    variants.push_back(v);
  }
  Status s = adopt_best_variant<S>(variants, ctx, c);
  if (!s.ok() || !c->applicable) return s;
  const ResidtraceModel<S>& m = c->model;
  const int nadd = m.estimate.np - cur.estimate.np;
  if (m.has_phys) {
    // a realisation fitted on its simulation error: its parameters are
    // not added terms (no three-sigma test)
    const PhysicalModel<S>& P = m.phys;
    c->nadd = std::max(nadd, 1);
    Vector<S> val(3);
    val << P.alpha, P.gamma, P.hi;
    c->evidence.add("term", "alpha, gamma, inner level");
    add_row(&c->evidence, "value", val);
    c->evidence.add("std", std::numeric_limits<S>::quiet_NaN());
    c->evidence.text = c->variant + ": alpha " + num("%.4g", P.alpha) +
                       ", gamma " + num("%.4g", P.gamma) + ", output level " +
                       num("%.4g", P.c);
    c->evidence.add("text", c->evidence.text);
    return Status::Ok();
  }
  c->nadd = nadd;
  Eigen::Index nlin = 0;
  for (const StructureChannel<S>& k : m.channels) {
    nlin += k.kind == ChannelKind::kOutputPower ? 1 : 0;
  }
  const ModelEstimate<S>& e = m.estimate;
  const Eigen::Index n = e.theta.size();
  if (nlin > n || e.cov.rows() != n || e.cov.cols() != n) {
    return numerical_failure("the fit returned no output terms' gains");
  }
  const Vector<S> val = e.theta.tail(nlin);
  const Vector<S> sd =
      e.cov.diagonal().tail(nlin).unaryExpr([](S x) { return std::sqrt(x); });
  c->evidence.add("term", "gains of the output terms");
  add_row(&c->evidence, "value", val);
  add_row(&c->evidence, "std", sd);
  c->evidence.text = c->variant + ": coefficients " + mat2str<S>(val, 4) +
                     " +- " + mat2str<S>(sd, 2);
  c->evidence.add("text", c->evidence.text);
  return Status::Ok();
}

}  // namespace ctid::residtrace
