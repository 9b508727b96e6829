// SPDX-License-Identifier: BSD-3-Clause
// Copyright (C) the ctid authors

// The one general judgement of residtrace's candidates
// (octave/residtrace.m): every effect of the library, whatever it is, is
// fitted on the estimation record only and judged by the same rules.
//
//   accept: before it is scored, a candidate's evidence must be physical.
//     Each term it adds to the current model must be determined on the
//     estimation data (Wald z >= 2: its standard error well below its
//     value) and the added terms significant there as a whole (largest z
//     >= 3); an effect of part of the record (a saturation's level, a
//     direction of motion) must be active on part of it and inactive on
//     the rest; a friction needs velocity reversals.
//
//   score_candidate: the candidate's error e1 on the validation record
//     against the current model's e0: the share of e0's mean square it
//     removes, and the p-value of the encompassing test (statistics.hpp,
//     which accounts for the autocorrelation of both errors); for a
//     correction fitted on the validation record itself (in-sample), the
//     likelihood-ratio test instead.
//
//   judge_group / judge_pass: significance at a Bonferroni level within a
//     group, the ranking (score, parsimony, the same-footing BIC rule),
//     the rivals the data do not tell from the winner, and which group
//     names the pass's winner.
//
//   noise_gate: when the coloured-noise candidate may be tried at all.
//
// The rules are those of residtrace's manual page (doc/manual/
// 05-residtrace.md, "How candidates are scored").
#pragma once

#include <Eigen/Cholesky>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <string>
#include <vector>

#include "ctid/apps/residtrace/statistics.hpp"
#include "ctid/base/status.hpp"
#include "ctid/base/types.hpp"

namespace ctid::residtrace {

namespace detail {

// printf into a std::string (the reasons quote figures as Octave's
// sprintf does: same C conversions).
template <typename... A>
std::string format(const char* f, A... a) {
  const int n = std::snprintf(nullptr, 0, f, a...);
  std::string s(static_cast<std::size_t>(n > 0 ? n : 0), '\0');
  std::snprintf(s.data(), s.size() + 1, f, a...);
  return s;
}

// A figure as Octave's sprintf writes it with the conversion `spec`:
// "NaN", "Inf" and "-Inf" for the non-finite ones.
inline std::string number_text(const char* spec, double v) {
  if (std::isnan(v)) return "NaN";
  if (std::isinf(v)) return v > 0 ? "Inf" : "-Inf";
  return format(spec, v);
}

}  // namespace detail

// Q(a, x) = Gamma(a, x) / Gamma(a), the regularised upper incomplete gamma
// function (a > 0, x >= 0): the series of P(a, x) for x < a + 1, the
// continued fraction of Q (modified Lentz) otherwise, to machine
// precision. Q(a, 0) = 1; Q(0, x > 0) = 0 (the limit a -> 0); NaN for a
// NaN or negative argument.
template <typename S>
S gamma_q(S a, S x) {
  if (!(a >= 0) || !(x >= 0)) return std::numeric_limits<S>::quiet_NaN();
  if (x == 0) return 1;
  if (a == 0) return 0;
  if (std::isinf(x)) return 0;
  const S eps = std::numeric_limits<S>::epsilon();
  const S lead = a * std::log(x) - x - std::lgamma(a);
  if (x < a + 1) {
    S ap = a, del = 1 / a, sum = del;
    for (int n = 0; n < 100000; ++n) {
      ap += 1;
      del *= x / ap;
      sum += del;
      if (std::abs(del) < std::abs(sum) * eps) break;
    }
    return 1 - sum * std::exp(lead);
  }
  const S tiny = std::numeric_limits<S>::min() / eps;
  S b = x + 1 - a, c = 1 / tiny, d = 1 / b, h = d;
  for (int i = 1; i < 100000; ++i) {
    const S an = -i * (i - a);
    b += 2;
    d = an * d + b;
    if (std::abs(d) < tiny) d = tiny;
    c = b + an / c;
    if (std::abs(c) < tiny) c = tiny;
    d = 1 / d;
    const S del = d * c;
    h *= del;
    if (std::abs(del - 1) < eps) break;
  }
  return std::exp(lead) * h;
}

// P(chi^2(k) > x): the upper tail of the chi-square distribution with k
// degrees of freedom.
template <typename S>
S chi2_upper(S x, S k) {
  return gamma_q(k / 2, x / 2);
}

// ---- acceptance -----------------------------------------------------------

// A term the candidate adds to the current model and its Wald statistic.
template <typename S>
struct AddedTerm {
  std::string name;  // "the offset term", "the freed coefficient f2", ...
  S z = 0;
};

// z = sqrt(theta' C^-1 theta / k) of k coefficients with covariance C (for
// one coefficient |value| / std; for a sinusoid's pair its amplitude in
// standard errors whatever its phase). C is scaled to a correlation
// matrix before it is factored, so the solve is scale-free. NaN when C
// gives no standard deviation (a non-finite entry, a variance <= 0, not
// positive definite).
template <typename S>
S wald(const Vector<S>& theta, const Matrix<S>& C) {
  const S nan = std::numeric_limits<S>::quiet_NaN();
  const Eigen::Index k = theta.size();
  if (k == 0 || C.rows() != k || C.cols() != k || !C.allFinite()) return nan;
  const Vector<S> d = C.diagonal();
  if ((d.array() <= 0).any()) return nan;
  const Vector<S> s = d.array().sqrt();
  const Matrix<S> Cn = C.array() / (s * s.transpose()).array();
  // the upper triangle, as a Cholesky factor R' R = Cn
  Eigen::LLT<Matrix<S>, Eigen::Upper> llt(Cn);
  if (llt.info() != Eigen::Success) return nan;
  const Vector<S> w = llt.matrixL().solve(Vector<S>(theta.array() / s.array()));
  return std::sqrt(detail::sum_squares(w) / static_cast<S>(k));
}

// What accept reads of a candidate's model and of the current model.
struct ChannelShape {
  std::string name;
  long nb = 0;  // numerator length
};

template <typename S>
struct OutputTermShape {
  std::string type;  // "offset", "poly", "sinusoid", "sat", ...
  Vector<S> c;       // coefficients and their standard deviations
  Vector<S> cstd;
};

template <typename S>
struct StructureShape {
  bool usable = true;       // false: no structure to read (a physical
                            // realisation, or no model)
  Vector<S> theta;          // [free f's, each channel's numerator]
  Matrix<S> cov;            // covariance of theta
  std::vector<bool> fixed;  // which of f1..fn are fixed
  std::vector<ChannelShape> channels;
  std::vector<OutputTermShape<S>> out;
};

// The terms a candidate's model m adds to the current model cur, each
// with its Wald z (terms with no standard deviation are left out: a
// realisation fitted on its simulation error has no covariance here):
// the channels beyond cur's (a new input, friction or power channel: its
// numerator, jointly), the coefficients of F that cur fixes and m frees
// (the viscous candidate's damping), and the output terms beyond cur's
// with a standard deviation each (a saturation's level is judged by its
// activity, not here).
template <typename S>
std::vector<AddedTerm<S>> added_terms(const StructureShape<S>& m,
                                      const StructureShape<S>& cur) {
  std::vector<AddedTerm<S>> out;
  if (!m.usable) return out;
  const Eigen::Index nth = m.theta.size();
  const bool square = m.cov.rows() == nth && m.cov.cols() == nth;
  long nf = 0;
  for (bool f : m.fixed) nf += f ? 0 : 1;
  const std::size_t nc = cur.channels.size();
  long sum_nb = 0;
  for (const auto& ch : m.channels) sum_nb += ch.nb;
  if (m.channels.size() > nc && nth == nf + sum_nb && square) {
    long off = nf;
    for (std::size_t j = 0; j < nc; ++j) off += m.channels[j].nb;
    for (std::size_t j = nc; j < m.channels.size(); ++j) {
      const long nb = m.channels[j].nb;
      const S z =
          wald<S>(m.theta.segment(off, nb), m.cov.block(off, off, nb, nb));
      off += nb;
      if (!std::isnan(z))
        out.push_back({"the " + m.channels[j].name + " term", z});
    }
  }
  if (m.fixed.size() == cur.fixed.size() && nth >= nf && square) {
    for (std::size_t k = 0; k < m.fixed.size(); ++k) {
      if (!(cur.fixed[k] && !m.fixed[k])) continue;
      long i = 0;  // the position of f(k+1) among the free coefficients
      for (std::size_t q = 0; q <= k; ++q) i += m.fixed[q] ? 0 : 1;
      const S z =
          wald<S>(m.theta.segment(i - 1, 1), m.cov.block(i - 1, i - 1, 1, 1));
      if (!std::isnan(z)) {
        out.push_back({detail::format("the freed coefficient f%d",
                                      static_cast<int>(k + 1)),
                       z});
      }
    }
  }
  for (std::size_t k = cur.out.size(); k < m.out.size(); ++k) {
    const auto& o = m.out[k];
    if (o.type == "sat" || o.cstd.size() != o.c.size()) continue;
    const Matrix<S> C = o.cstd.array().square().matrix().asDiagonal();
    const S z = wald<S>(o.c, C);
    if (!std::isnan(z)) out.push_back({"the output " + o.type, z});
  }
  return out;
}

// The activity a candidate reports on the estimation record (NaN: not
// reported, the effect does not act on part of the record only).
template <typename S>
struct Activity {
  S share = std::numeric_limits<S>::quiet_NaN();      // active samples / N
  S reversals = std::numeric_limits<S>::quiet_NaN();  // velocity sign changes
};

template <typename S>
struct Acceptance {
  bool ok = true;
  std::string why;                               // the reason of a refusal
  S tmax = std::numeric_limits<S>::quiet_NaN();  // the largest z (screening)
};

// The one acceptance check every candidate passes before it is scored.
// Determined: each added term's z at least 2 (a standard error well below
// the value: an offset of -37 +- 2e6 is no evidence), and the largest at
// least 3 (the effect as a whole significant on the estimation data).
// Active and inactive: the share of the N estimation samples where the
// effect acts at least max(1 %, 5 samples) and at most 1 - that (a level
// reached on every sample is an offset or a gain, not a saturation; one
// reached nowhere is nothing). Switching: a velocity that never reverses
// makes sign(v) a constant, an offset, not a friction (one reversal, a
// back-and-forth motion, is enough when each direction holds its share).
template <typename S>
Acceptance<S> accept(const std::vector<AddedTerm<S>>& terms,
                     const Activity<S>& act, Eigen::Index N) {
  Acceptance<S> a;
  if (!terms.empty()) {
    std::size_t imin = 0, imax = 0;
    for (std::size_t i = 1; i < terms.size(); ++i) {
      if (terms[i].z < terms[imin].z) imin = i;
      if (terms[i].z > terms[imax].z) imax = i;
    }
    a.tmax = terms[imax].z;
    if (terms[imin].z < 2) {
      a.ok = false;
      a.why = terms[imin].name +
              detail::format(
                  " is not determined on the estimation data (z = %.2g: its "
                  "standard error is not well below its value)",
                  static_cast<double>(terms[imin].z));
      return a;
    }
    if (a.tmax < 3) {
      a.ok = false;
      a.why = detail::format(
          "the added terms are not significant on the estimation data "
          "(largest z = %.2g < 3)",
          static_cast<double>(a.tmax));
      return a;
    }
  }
  if (std::isfinite(act.share)) {
    const S lo = std::max(S(0.01), S(5) / static_cast<S>(N));
    if (act.share < lo) {
      a.ok = false;
      a.why = detail::format(
          "not physically active: active on %.2g %% of the estimation "
          "samples",
          static_cast<double>(100 * act.share));
      return a;
    }
    if (act.share > 1 - lo) {
      a.ok = false;
      a.why = detail::format(
          "not physically an effect of part of the record: active on %.4g "
          "%% of the estimation samples, inactive on none",
          static_cast<double>(100 * act.share));
      return a;
    }
  }
  if (act.reversals < 1) {
    a.ok = false;
    const double r = static_cast<double>(act.reversals);
    const std::string n =
        std::isfinite(r) && r == std::floor(r)
            ? detail::format("%lld", static_cast<long long>(r))
            : detail::number_text("%g", r);
    a.why = "not physically active: the velocity changes sign " + n +
            " time(s) on the estimation record (a friction needs reversals)";
  }
  return a;
}

// ---- scoring --------------------------------------------------------------

// The likelihood-ratio test of a correction of nadd parameters fitted on
// the validation record itself (by least squares): LR = N log(sum e0^2 /
// sum e1^2) against chi^2(nadd), the model choice a BIC would make at the
// same level. p = 1 when the correction does not reduce the error.
template <typename S>
struct LrTest {
  S lr = 0;
  S p = 1;
};

template <typename S>
LrTest<S> lr_test(const Vector<S>& e0, const Vector<S>& e1, S nadd) {
  LrTest<S> t;
  const S N = static_cast<S>(e1.size());
  t.lr = N * std::log(detail::sum_squares(e0) / detail::sum_squares(e1));
  if (t.lr > 0) t.p = chi2_upper(t.lr, nadd);
  return t;
}

template <typename S>
struct CandidateScore {
  S score = 0;  // 1 - mean(e1^2) / mean(e0^2)
  S p = 1;      // the decision's p-value
  S stat = 0;   // its statistic (encompassing z, or LR)
  S p_dm = 1;   // the Diebold-Mariano p-value (reported)
};

// A candidate's error e1 on the validation record against the current
// model's e0: its score, and the p-value of the encompassing test (does
// the correction e0 - e1, fitted on other data, explain part of e0?),
// which accounts for both errors' autocorrelation (statistics.hpp);
// in-sample corrections (fitted on the validation record) by lr_test.
template <typename S>
Status score_candidate(const Vector<S>& e0, const Vector<S>& e1, bool insample,
                       S nadd, CandidateScore<S>* out) {
  DmTest<S> t;
  const Status st = dm_test<S>(e0, e1, &t);
  if (!st.ok()) return st;
  out->score = t.score;
  out->p = t.p_corr;
  out->stat = t.z;
  out->p_dm = t.p;
  if (insample) {
    const LrTest<S> lr = lr_test<S>(e0, e1, nadd);
    out->p = lr.p;
    out->stat = lr.lr;
  }
  return Status::Ok();
}

// ---- significance, ranking, rivals ----------------------------------------

enum class CandidateKind { kSimulation, kTracking, kPrediction };

// A scored candidate as the ranking sees it.
template <typename S>
struct CandidateRow {
  std::string effect;
  std::string variant;
  CandidateKind kind = CandidateKind::kSimulation;
  bool applicable = false;  // scored (accepted, its validation error finite)
  S score = std::numeric_limits<S>::quiet_NaN();
  S p = std::numeric_limits<S>::quiet_NaN();
  S nadd = 0;    // parameters it adds (a delay counts as one)
  Vector<S> e1;  // its validation error
  // its fit on the estimation record: BIC = N log s2 + np log N with
  // n_est samples (has_fit false: unknown)
  bool has_fit = false;
  S bic = 0;
  S np = 0;
  S n_est = 0;
};

struct JudgeOptions {
  double alpha = 0.01;     // the level of a pass
  double minscore = 0.01;  // the least share of the mean square removed
};

// The effect that is part of the baseline, never an effect: the record's
// initial state (declared before the pass when significant, see
// residtrace.m's run_pass).
inline bool baseline_only(const std::string& effect) {
  return effect == "initial_state";
}

// Significant at the level `level` (the pass's alpha over the number of
// candidates tested, Bonferroni) with a share of at least minscore: an
// improvement that is real but negligible names nothing.
template <typename S>
bool significant_at(const CandidateRow<S>& r, double level, double minscore) {
  return r.applicable && r.p < level && r.score >= minscore;
}

// The record's initial state, tried before the pass: declared (estimated
// with the baseline, and the pass run again) when significant at the
// level of a full pass, alpha / (the number of simulated effects tested,
// itself included), as if it were one of them.
template <typename S>
bool declare_initial_state(const CandidateRow<S>& r, std::size_t tests,
                           const JudgeOptions& o) {
  return significant_at(
      r, o.alpha / static_cast<double>(std::max<std::size_t>(1, tests)),
      o.minscore);
}

// Bonferroni within a group: each candidate at alpha / (the number of
// applicable candidates of the group), so that testing more effects does
// not make one significant by chance.
template <typename S>
std::vector<bool> significance(const std::vector<CandidateRow<S>>& rows,
                               const JudgeOptions& o) {
  long m = 0;
  for (const auto& r : rows) m += r.applicable ? 1 : 0;
  const double level = o.alpha / static_cast<double>(std::max(1L, m));
  std::vector<bool> sig(rows.size());
  for (std::size_t k = 0; k < rows.size(); ++k) {
    sig[k] = significant_at(rows[k], level, o.minscore);
  }
  return sig;
}

// Does a's correction significantly improve on b's validation error (the
// encompassing test of b.e1 against a.e1: p < alpha and a share >=
// minscore of what b leaves)?
template <typename S>
bool better_than(const CandidateRow<S>& a, const CandidateRow<S>& b,
                 const JudgeOptions& o) {
  DmTest<S> t;
  if (!dm_test<S>(b.e1, a.e1, &t).ok()) return false;
  return t.p_corr < o.alpha && t.score >= o.minscore;
}

// A candidate's BIC on the estimation data with the parameters it adds
// counted as nadd (a delay, which a fit does not count, is one): N log s2
// + (np - added by the fit + nadd) log N, up to the current model's
// parameters, which every candidate shares. Inf when unknown.
template <typename S>
S footing_bic(const CandidateRow<S>& r) {
  if (!r.has_fit || !(r.n_est > 0) || !std::isfinite(r.bic)) {
    return std::numeric_limits<S>::infinity();
  }
  return r.bic + (r.nadd - r.np) * std::log(r.n_est);
}

// The ranking of one group (0-based indices into rows, best first):
// significant candidates first, each part by score (not applicable ones
// last, ties in their order); then sweeps over neighbouring significant
// candidates of one kind: a simpler one (fewer added parameters) moves up
// unless the more complex one's correction significantly improves on its
// error (parsimony); two simulated ones with as many added parameters
// that the validation record does not tell apart (neither improves
// significantly on the other) are put on the same footing, the smaller
// footing_bic first. At most 4 n sweeps.
template <typename S>
std::vector<std::size_t> rank_group(const std::vector<CandidateRow<S>>& rows,
                                    const std::vector<bool>& sig,
                                    const JudgeOptions& o) {
  const std::size_t n = rows.size();
  std::vector<S> key(n);
  for (std::size_t k = 0; k < n; ++k) {
    const S s = rows[k].applicable ? rows[k].score
                                   : -std::numeric_limits<S>::infinity();
    key[k] = s + (sig[k] ? 10 : 0);
  }
  std::vector<std::size_t> order(n);
  for (std::size_t k = 0; k < n; ++k) order[k] = k;
  // descending, NaN first (as a descending sort in Octave), stable
  std::stable_sort(
      order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
        const bool na = std::isnan(key[a]), nb = std::isnan(key[b]);
        if (na || nb) return na && !nb;
        return key[a] > key[b];
      });
  std::vector<std::size_t> sigpos;
  for (std::size_t k = 0; k < n; ++k) {
    if (sig[order[k]]) sigpos.push_back(k);
  }
  bool changed = true;
  std::size_t sweeps = 0;
  while (changed && sweeps < 4 * n) {
    changed = false;
    ++sweeps;
    for (std::size_t a = 0; a + 1 < sigpos.size(); ++a) {
      const auto& ri = rows[order[sigpos[a]]];
      const auto& rj = rows[order[sigpos[a + 1]]];
      const bool same = ri.kind == rj.kind;
      bool keep = true;
      if (rj.nadd < ri.nadd && same) {
        keep = better_than(ri, rj, o);
      } else if (rj.nadd == ri.nadd && same &&
                 ri.kind == CandidateKind::kSimulation) {
        keep = better_than(ri, rj, o) || better_than(rj, ri, o) ||
               !(footing_bic(rj) < footing_bic(ri));
      }
      if (!keep) {
        std::swap(order[sigpos[a]], order[sigpos[a + 1]]);
        changed = true;
      }
    }
  }
  return order;
}

template <typename S>
struct Rival {
  std::size_t index = 0;  // into the rows
  S p = 1;                // the winner's encompassing p against it
};

// The candidates the data do not tell from the winner: the other
// significant rows of its group, of another effect, with a finite
// validation error, whose error the winner's correction does not
// significantly improve on (the test the ranking uses). Two candidates
// that explain the same part of the residual (a clipped input and a
// saturated first state behind it) are then reported together.
template <typename S>
std::vector<Rival<S>> rivals(const CandidateRow<S>& winner,
                             const std::vector<CandidateRow<S>>& rows,
                             const std::vector<bool>& sig,
                             const JudgeOptions& o) {
  std::vector<Rival<S>> out;
  for (std::size_t j = 0; j < rows.size(); ++j) {
    const auto& r = rows[j];
    if (!sig[j] || r.effect == winner.effect || !r.e1.allFinite()) continue;
    DmTest<S> t;
    if (!dm_test<S>(r.e1, winner.e1, &t).ok()) continue;
    if (t.p_corr < o.alpha && t.score >= o.minscore) continue;
    out.push_back({j, t.p_corr});
  }
  return out;
}

template <typename S>
struct GroupJudgement {
  std::vector<bool> significant;   // per row, in the rows' order
  std::vector<std::size_t> order;  // the ranking, best first
};

// One group judged: significance (Bonferroni), the baseline-only row
// never significant, the ranking.
template <typename S>
GroupJudgement<S> judge_group(const std::vector<CandidateRow<S>>& rows,
                              const JudgeOptions& o) {
  GroupJudgement<S> g;
  g.significant = significance(rows, o);
  for (std::size_t k = 0; k < rows.size(); ++k) {
    if (baseline_only(rows[k].effect)) g.significant[k] = false;
  }
  g.order = rank_group(rows, g.significant, o);
  return g;
}

template <typename S>
struct PassJudgement {
  GroupJudgement<S> simulated;   // effects simulated from the input
  GroupJudgement<S> output;      // effects that use the validation output
  int winner_group = 0;          // 0 none, 1 simulated, 2 output
  std::size_t winner = 0;        // index into that group's rows
  std::vector<Rival<S>> rivals;  // of the winner, in its group
};

// A pass: the effects simulated from the input and those that use the
// validation output itself (tracking, prediction) are two groups, each
// with its own Bonferroni level and ranking; the second names the winner
// only when nothing in the first is significant (a simulation from the
// input is the stronger evidence; tracking or prediction would absorb a
// deterministic effect).
template <typename S>
PassJudgement<S> judge_pass(const std::vector<CandidateRow<S>>& simulated,
                            const std::vector<CandidateRow<S>>& output,
                            const JudgeOptions& o) {
  PassJudgement<S> p;
  p.simulated = judge_group(simulated, o);
  p.output = judge_group(output, o);
  const std::vector<CandidateRow<S>>* rows = nullptr;
  const GroupJudgement<S>* g = nullptr;
  if (!simulated.empty() && p.simulated.significant[p.simulated.order[0]]) {
    p.winner_group = 1;
    rows = &simulated;
    g = &p.simulated;
  } else if (!output.empty() && p.output.significant[p.output.order[0]]) {
    p.winner_group = 2;
    rows = &output;
    g = &p.output;
  }
  if (rows != nullptr) {
    p.winner = g->order[0];
    p.rivals = rivals((*rows)[p.winner], *rows, g->significant, o);
  }
  return p;
}

// ---- the coloured-noise gate ----------------------------------------------

struct NoiseGate {
  bool applicable = true;
  std::string why;
};

// A noise model changes the one-step prediction, never the simulation: it
// is tried only when nothing deterministic is significant (it would
// otherwise absorb the effect), and the residual is not white (white_p <
// alpha, Ljung-Box) but independent of the input (indep_p > alpha, Haugh):
// a residual that depends on the input is a deterministic error no noise
// model explains.
inline NoiseGate noise_gate(bool deterministic_significant, double white_p,
                            double indep_p, double alpha) {
  NoiseGate g;
  if (deterministic_significant) {
    g.applicable = false;
    g.why = "a deterministic effect explains the residual";
  } else if (!(white_p < alpha && indep_p > alpha)) {
    g.applicable = false;
    if (white_p >= alpha) {
      g.why =
          "the residual is white (p = " + detail::number_text("%.2g", white_p) +
          " >= alpha)";
    } else {
      g.why = "the residual depends on the input (p = " +
              detail::number_text("%.2g", indep_p) +
              " < alpha): a noise model cannot explain it";
    }
  }
  return g;
}

}  // namespace ctid::residtrace
