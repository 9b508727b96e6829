// SPDX-License-Identifier: BSD-3-Clause
// Copyright (C) the ctid authors

// The unknown-initial-state candidate of residtrace (candidate.hpp): the
// record did not start at rest. The model's free response from an initial
// state x0 (n basis functions: the responses of F(p) h = 0 from the n unit
// initial conditions, responses.hpp, free_responses) is fitted by least
// squares on each record's simulation error, as MATLAB's compare
// estimates x0: n parameters per record, declared in the result (every
// simulation of a model with this effect is "simulated from the input
// plus an estimated initial state"; its validation output fits them on the
// validation record itself, insample). Not when the validation record
// continues the estimation record (its initial state is where the
// simulation of the estimation part left it), nor in a closed loop.
// Evidence: the share of the estimation residual's sum of squares the
// free response removes, and the estimated x0.
#pragma once

#include <cstdio>
#include <string>

#include "ctid/apps/residtrace/candidate.hpp"
#include "ctid/apps/residtrace/responses.hpp"
#include "ctid/base/status.hpp"

namespace ctid::residtrace {

namespace x0_detail {

// A row as Octave's mat2str (v, 3) writes it: "[a b c]", one value
// without brackets.
template <typename S>
std::string row_text(const Vector<S>& v) {
  std::string s;
  for (Eigen::Index i = 0; i < v.size(); ++i) {
    if (i > 0) s += " ";
    s += candidate_detail::num("%.3g", v(i));
  }
  return v.size() == 1 ? s : "[" + s + "]";
}

}  // namespace x0_detail

// The initial-state candidate (head of this file); ctx.validation_continues
// when the validation record continues the estimation record.
template <typename S>
Status x0_candidate(const ResidtraceModel<S>& cur,
                    const CandidateContext<S>& ctx, Candidate<S>* c) {
  using candidate_detail::num;
  if (c == nullptr) return bad_input("no result");
  *c = Candidate<S>();
  c->effect = "initial_state";
  if (cur.x0) {
    c->reason = "the initial state is estimated already";
    return Status::Ok();
  }
  if (ctx.validation_continues) {
    c->reason =
        "the validation record continues the estimation record: its "
        "initial state comes from the simulation";
    return Status::Ok();
  }
  if (ctx.D.closed) {
    c->reason = "not in closed loop";
    return Status::Ok();
  }
  const Eigen::Index N = ctx.D.y.size();
  const Vector<S>& e = cur.estimate.e;
  if (e.size() != N) {
    return bad_input(
        "the model's estimation residual needs one value a sample of the "
        "record");
  }
  const Eigen::Index n = cur.F.size() - 1;
  if (n < 1 || cur.F(0) == 0) {
    return bad_input("F must have order >= 1 and a leading coefficient != 0");
  }
  Matrix<S> X;
  Status s =
      free_responses<S>(Vector<S>(cur.F.tail(n) / cur.F(0)), ctx.D.ts, N, X);
  if (!s.ok()) return s;
  const Vector<S> x0 = X.colPivHouseholderQr().solve(e);
  const S share = 1 - (e - X * x0).squaredNorm() / e.squaredNorm();
  c->applicable = true;
  c->has_model = true;
  c->model = cur;
  c->model.x0 = true;
  c->insample = true;
  char variant[64];
  std::snprintf(variant, sizeof(variant),
                "x0 of %d states fitted on each record", static_cast<int>(n));
  c->variant = variant;
  c->nadd = static_cast<int>(n);
  c->evidence.add("term", "x0 (observable form)");
  EvidenceField<S> v;
  v.name = "value";
  v.value = x0;
  c->evidence.fields.push_back(v);
  c->evidence.add("std", std::numeric_limits<S>::quiet_NaN());
  c->evidence.add("share_estimation", share);
  c->evidence.text = "the free response from x0 = " + x0_detail::row_text(x0) +
                     " removes " + num("%.1f", 100 * share) +
                     " % of the estimation residual";
  c->evidence.add("text", c->evidence.text);
  return Status::Ok();
}

}  // namespace ctid::residtrace
