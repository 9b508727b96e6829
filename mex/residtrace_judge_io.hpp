// SPDX-License-Identifier: BSD-3-Clause
// Copyright (C) the ctid authors

// The judgement methods of effect_sim_mex (core/include/ctid/apps/
// residtrace/judgement.hpp), used by octave/residtrace.m:
//
//   [ok, why, tmax] = effect_sim_mex (fname, "accept", c, cur, options)
//     the acceptance check of candidate c (fields model, evidence) against
//     the current model cur; options: n (estimation samples). The model
//     fields read: theta, cov, fixed, channels (name, nb), out (type, c,
//     cstd), phys; the evidence's share and reversals when present.
//   v = effect_sim_mex (fname, "score", e0, e1, options)
//     v = [score p stat p_dm] of the error e1 against e0; options:
//     insample (0 or 1), nadd.
//   J = effect_sim_mex (fname, "judge", rows1, rows2, options)
//     a pass judged: rows1 the candidates simulated from the input, rows2
//     those that use the validation output (struct arrays, either may be
//     []), fields effect, variant, kind ("simulation", "tracking",
//     "prediction"), applicable, score, p, nadd, e1, model (its bic, np
//     and e_est read when present); options: alpha, minscore. J:
//     significant1, order1 (1-based, best first), significant2, order2,
//     group (0 no winner, 1 or 2), winner (index into that group's rows),
//     rivals (struct array: effect, variant, score, p).
//   d = effect_sim_mex (fname, "declare", row, options)
//     is the record's initial state (row, fields as for "judge")
//     significant before the pass; options: alpha, minscore, tests (the
//     number of simulated effects tested, itself included).
//   [applicable, why] = effect_sim_mex (fname, "noise_gate", options)
//     may the coloured-noise candidate be tried; options: significant
//     (a deterministic candidate is), white_p, indep_p, alpha.
#pragma once

#include <string>
#include <vector>

#include "ctid/apps/residtrace/judgement.hpp"
#include "gateway_common.hpp"

namespace ctid::mex::residtrace_judge {

namespace rt = ctid::residtrace;

inline const mxArray* get(const mxArray* s, mwIndex k, const char* name) {
  return mxGetFieldNumber(s, name) < 0 ? nullptr : mxGetField(s, k, name);
}

// A numeric or logical scalar of any value; `missing` when absent or not
// a scalar.
inline double number(const mxArray* a, double missing) {
  if (a == nullptr || mxGetNumberOfElements(a) != 1) return missing;
  if (mxIsLogical(a)) return mxGetLogicals(a)[0] ? 1.0 : 0.0;
  if (mxIsDouble(a) && !mxIsComplex(a)) return mxGetPr(a)[0];
  return missing;
}

inline std::string string_of(const Gateway& g, const mxArray* a,
                             const std::string& what) {
  if (a != nullptr && mxIsEmpty(a)) return "";
  if (a == nullptr || !mxIsChar(a) || mxGetM(a) > 1) {
    g.fail("badInput", what + " must be a character row vector");
  }
  char* c = mxArrayToString(a);
  std::string s = c == nullptr ? "" : c;
  mxFree(c);
  return s;
}

// The values of a real double (or logical) array, column-major; any
// values.
inline Eigen::VectorXd values(const Gateway& g, const mxArray* a,
                              const std::string& what) {
  if (a == nullptr) return Eigen::VectorXd();
  const Eigen::Index n = static_cast<Eigen::Index>(mxGetNumberOfElements(a));
  Eigen::VectorXd v(n);
  if (mxIsLogical(a)) {
    const mxLogical* p = mxGetLogicals(a);
    for (Eigen::Index i = 0; i < n; ++i) v(i) = p[i] ? 1 : 0;
    return v;
  }
  g.require_real_double(a, what);
  if (n > 0) v = Eigen::Map<const Eigen::VectorXd>(mxGetPr(a), n);
  return v;
}

inline Eigen::MatrixXd matrix_of(const Gateway& g, const mxArray* a,
                                 const std::string& what) {
  if (a == nullptr) return Eigen::MatrixXd();
  g.require_real_double(a, what);
  const Eigen::Index m = static_cast<Eigen::Index>(mxGetM(a));
  const Eigen::Index n = static_cast<Eigen::Index>(mxGetN(a));
  Eigen::MatrixXd out(m, n);
  if (m * n > 0) out = Eigen::Map<const Eigen::MatrixXd>(mxGetPr(a), m, n);
  return out;
}

// A residtrace structure as the acceptance reads it; usable is false for
// no model, or a physical realisation (fitted on its simulation error).
inline rt::StructureShape<double> read_shape(const Gateway& g, const mxArray* m,
                                             const std::string& what) {
  rt::StructureShape<double> s;
  if (m == nullptr || !mxIsStruct(m) || mxGetNumberOfElements(m) != 1 ||
      get(m, 0, "channels") == nullptr) {
    s.usable = false;
    return s;
  }
  const mxArray* phys = get(m, 0, "phys");
  if (phys != nullptr && !mxIsEmpty(phys)) {
    s.usable = false;
    return s;
  }
  s.theta = values(g, get(m, 0, "theta"), what + ".theta");
  s.cov = matrix_of(g, get(m, 0, "cov"), what + ".cov");
  const Eigen::VectorXd fixed = values(g, get(m, 0, "fixed"), what + ".fixed");
  for (Eigen::Index k = 0; k < fixed.size(); ++k)
    s.fixed.push_back(fixed(k) != 0);
  const mxArray* ch = get(m, 0, "channels");
  if (!mxIsStruct(ch)) g.fail("badInput", what + ".channels must be a struct");
  for (mwIndex j = 0; j < mxGetNumberOfElements(ch); ++j) {
    rt::ChannelShape c;
    const mxArray* name = get(ch, j, "name");
    c.name = name == nullptr ? "" : string_of(g, name, what + " channel name");
    c.nb = static_cast<long>(number(get(ch, j, "nb"), 0));
    s.channels.push_back(c);
  }
  const mxArray* out = get(m, 0, "out");
  if (out != nullptr && mxIsStruct(out)) {
    for (mwIndex k = 0; k < mxGetNumberOfElements(out); ++k) {
      rt::OutputTermShape<double> o;
      o.type = string_of(g, get(out, k, "type"), what + " output term type");
      o.c = values(g, get(out, k, "c"), what + " output term c");
      o.cstd = values(g, get(out, k, "cstd"), what + " output term cstd");
      s.out.push_back(o);
    }
  }
  return s;
}

inline void accept_method(const Gateway& g, int nlhs, mxArray* plhs[], int nrhs,
                          const mxArray* prhs[]) {
  if (nrhs != 5) {
    g.fail("badInput", "accept takes (fname, 'accept', c, cur, options)");
  }
  if (nlhs > 3) g.fail("badInput", "accept has at most 3 outputs");
  const mxArray* c = prhs[2];
  if (!mxIsStruct(c) || mxGetNumberOfElements(c) != 1) {
    g.fail("badInput", "c must be a 1x1 struct");
  }
  OptionsReader opt(g, prhs[4]);
  const int n = opt.integer("n");
  opt.finish();
  const auto m = read_shape(g, get(c, 0, "model"), "c.model");
  const auto cur = read_shape(g, prhs[3], "cur");
  rt::Activity<double> act;
  const mxArray* ev = get(c, 0, "evidence");
  if (ev != nullptr && mxIsStruct(ev) && mxGetNumberOfElements(ev) == 1) {
    act.share = number(get(ev, 0, "share"), act.share);
    act.reversals = number(get(ev, 0, "reversals"), act.reversals);
  }
  const auto a = rt::accept<double>(rt::added_terms<double>(m, cur), act, n);
  plhs[0] = mxCreateLogicalScalar(a.ok);
  if (nlhs >= 2) plhs[1] = mxCreateString(a.why.c_str());
  if (nlhs >= 3) plhs[2] = mxCreateDoubleScalar(a.tmax);
}

inline void score_method(const Gateway& g, int nlhs, mxArray* plhs[], int nrhs,
                         const mxArray* prhs[]) {
  if (nrhs != 5) {
    g.fail("badInput", "score takes (fname, 'score', e0, e1, options)");
  }
  if (nlhs > 1) g.fail("badInput", "score has one output");
  const Eigen::VectorXd e0 = values(g, prhs[2], "e0");
  const Eigen::VectorXd e1 = values(g, prhs[3], "e1");
  OptionsReader opt(g, prhs[4]);
  const bool insample = opt.integer("insample") != 0;
  const double nadd = opt.scalar("nadd");
  opt.finish();
  rt::CandidateScore<double> s;
  g.check(rt::score_candidate<double>(e0, e1, insample, nadd, &s));
  plhs[0] = make_output_matrix(1, 4);
  double* v = mxGetPr(plhs[0]);
  v[0] = s.score;
  v[1] = s.p;
  v[2] = s.stat;
  v[3] = s.p_dm;
}

inline std::vector<rt::CandidateRow<double>> read_rows(
    const Gateway& g, const mxArray* a, const std::string& what) {
  std::vector<rt::CandidateRow<double>> rows;
  if (a == nullptr || mxIsEmpty(a)) return rows;
  if (!mxIsStruct(a)) g.fail("badInput", what + " must be a struct array");
  for (mwIndex k = 0; k < mxGetNumberOfElements(a); ++k) {
    rt::CandidateRow<double> r;
    r.effect = string_of(g, get(a, k, "effect"), what + ".effect");
    const mxArray* v = get(a, k, "variant");
    r.variant = v == nullptr ? "" : string_of(g, v, what + ".variant");
    const std::string kind = string_of(g, get(a, k, "kind"), what + ".kind");
    if (kind == "simulation") {
      r.kind = rt::CandidateKind::kSimulation;
    } else if (kind == "tracking") {
      r.kind = rt::CandidateKind::kTracking;
    } else if (kind == "prediction") {
      r.kind = rt::CandidateKind::kPrediction;
    } else {
      g.fail("badInput", what +
                             ".kind must be 'simulation', 'tracking' or "
                             "'prediction'");
    }
    r.applicable = number(get(a, k, "applicable"), 0) != 0;
    r.score = number(get(a, k, "score"), r.score);
    r.p = number(get(a, k, "p"), r.p);
    r.nadd = number(get(a, k, "nadd"), 0);
    r.e1 = values(g, get(a, k, "e1"), what + ".e1");
    const mxArray* m = get(a, k, "model");
    if (m != nullptr && mxIsStruct(m) && mxGetNumberOfElements(m) == 1) {
      const mxArray* bic = get(m, 0, "bic");
      const mxArray* np = get(m, 0, "np");
      const mxArray* e_est = get(m, 0, "e_est");
      if (bic != nullptr && np != nullptr && e_est != nullptr &&
          !mxIsEmpty(e_est)) {
        r.has_fit = true;
        r.bic = number(bic, r.bic);
        r.np = number(np, r.np);
        r.n_est = static_cast<double>(mxGetNumberOfElements(e_est));
      }
    }
    rows.push_back(std::move(r));
  }
  return rows;
}

inline mxArray* logical_column(const std::vector<bool>& b) {
  mxArray* a = mxCreateLogicalMatrix(b.size(), 1);
  mxLogical* p = mxGetLogicals(a);
  for (std::size_t k = 0; k < b.size(); ++k) p[k] = b[k];
  return a;
}

inline mxArray* index_column(const std::vector<std::size_t>& i) {
  mxArray* a = make_output_matrix(static_cast<long>(i.size()), 1);
  double* p = mxGetPr(a);
  for (std::size_t k = 0; k < i.size(); ++k)
    p[k] = static_cast<double>(i[k] + 1);
  return a;
}

inline void judge_method(const Gateway& g, int nlhs, mxArray* plhs[], int nrhs,
                         const mxArray* prhs[]) {
  if (nrhs != 5) {
    g.fail("badInput", "judge takes (fname, 'judge', rows1, rows2, options)");
  }
  if (nlhs > 1) g.fail("badInput", "judge has one output");
  const auto rows1 = read_rows(g, prhs[2], "rows1");
  const auto rows2 = read_rows(g, prhs[3], "rows2");
  OptionsReader opt(g, prhs[4]);
  rt::JudgeOptions o;
  o.alpha = opt.scalar("alpha");
  o.minscore = opt.scalar("minscore");
  opt.finish();
  const auto J = rt::judge_pass<double>(rows1, rows2, o);
  const char* names[] = {"significant1", "order1", "significant2", "order2",
                         "group",        "winner", "rivals"};
  plhs[0] = mxCreateStructMatrix(1, 1, 7, names);
  mxSetField(plhs[0], 0, "significant1",
             logical_column(J.simulated.significant));
  mxSetField(plhs[0], 0, "order1", index_column(J.simulated.order));
  mxSetField(plhs[0], 0, "significant2", logical_column(J.output.significant));
  mxSetField(plhs[0], 0, "order2", index_column(J.output.order));
  mxSetField(plhs[0], 0, "group", mxCreateDoubleScalar(J.winner_group));
  mxSetField(plhs[0], 0, "winner",
             mxCreateDoubleScalar(J.winner_group == 0 ? 0.0 : J.winner + 1.0));
  // (0-by-0 when there is none, as struct ("effect", {}, ...))
  const char* rnames[] = {"effect", "variant", "score", "p"};
  const std::size_t nr = J.rivals.size();
  mxArray* riv = mxCreateStructMatrix(nr > 0 ? 1 : 0, nr, 4, rnames);
  const auto& rows = J.winner_group == 2 ? rows2 : rows1;
  for (std::size_t k = 0; k < J.rivals.size(); ++k) {
    const auto& r = rows[J.rivals[k].index];
    mxSetField(riv, k, "effect", mxCreateString(r.effect.c_str()));
    mxSetField(riv, k, "variant", mxCreateString(r.variant.c_str()));
    mxSetField(riv, k, "score", mxCreateDoubleScalar(r.score));
    mxSetField(riv, k, "p", mxCreateDoubleScalar(J.rivals[k].p));
  }
  mxSetField(plhs[0], 0, "rivals", riv);
}

inline void declare_method(const Gateway& g, int nlhs, mxArray* plhs[],
                           int nrhs, const mxArray* prhs[]) {
  if (nrhs != 4) {
    g.fail("badInput", "declare takes (fname, 'declare', row, options)");
  }
  if (nlhs > 1) g.fail("badInput", "declare has one output");
  const auto rows = read_rows(g, prhs[2], "row");
  if (rows.size() != 1) g.fail("badInput", "row must be one candidate");
  OptionsReader opt(g, prhs[3]);
  rt::JudgeOptions o;
  o.alpha = opt.scalar("alpha");
  o.minscore = opt.scalar("minscore");
  const int tests = opt.integer("tests");
  opt.finish();
  if (tests < 1) g.fail("badOption", "option 'tests' must be >= 1");
  plhs[0] = mxCreateLogicalScalar(rt::declare_initial_state<double>(
      rows[0], static_cast<std::size_t>(tests), o));
}

inline void noise_gate_method(const Gateway& g, int nlhs, mxArray* plhs[],
                              int nrhs, const mxArray* prhs[]) {
  if (nrhs != 3) {
    g.fail("badInput", "noise_gate takes (fname, 'noise_gate', options)");
  }
  if (nlhs > 2) g.fail("badInput", "noise_gate has at most 2 outputs");
  OptionsReader opt(g, prhs[2]);
  const bool sig = opt.integer("significant") != 0;
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double white_p = number(opt.field("white_p"), nan);
  const double indep_p = number(opt.field("indep_p"), nan);
  const double alpha = opt.scalar("alpha");
  opt.finish();
  const auto gate = rt::noise_gate(sig, white_p, indep_p, alpha);
  plhs[0] = mxCreateLogicalScalar(gate.applicable);
  if (nlhs >= 2) plhs[1] = mxCreateString(gate.why.c_str());
}

// The judgement's methods; false when `method` is none of them.
inline bool dispatch(const std::string& method, const Gateway& g, int nlhs,
                     mxArray* plhs[], int nrhs, const mxArray* prhs[]) {
  if (method == "accept") {
    accept_method(g, nlhs, plhs, nrhs, prhs);
  } else if (method == "score") {
    score_method(g, nlhs, plhs, nrhs, prhs);
  } else if (method == "judge") {
    judge_method(g, nlhs, plhs, nrhs, prhs);
  } else if (method == "declare") {
    declare_method(g, nlhs, plhs, nrhs, prhs);
  } else if (method == "noise_gate") {
    noise_gate_method(g, nlhs, plhs, nrhs, prhs);
  } else {
    return false;
  }
  return true;
}

}  // namespace ctid::mex::residtrace_judge
