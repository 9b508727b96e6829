// SPDX-License-Identifier: BSD-3-Clause
// Copyright (C) the ctid authors

// Tests of core/include/ctid/apps/residtrace/judgement.hpp against
// independent computations:
//   - the regularised upper incomplete gamma function against closed
//     forms (Q(1, x) = exp(-x), Q(1/2, x) = erfc(sqrt(x)), Q(2, x) = (1 +
//     x) exp(-x)) on both of its branches, and the likelihood-ratio test
//     with two added parameters against exp(-LR / 2) (chi^2(2));
//   - the Wald statistic against |value| / std and the amplitude of an
//     uncorrelated pair;
//   - the acceptance rules on constructed evidence: an undetermined term,
//     terms determined but not significant, a saturation active on every
//     sample or on none, a friction without velocity reversals;
//   - Bonferroni within a group on a hand-made set, and the level at which
//     the record's initial state is declared before a pass;
//   - the ranking: significant first by score, the parsimony swap of a
//     simpler candidate that the complex one does not improve on, none
//     when it does, the same-footing BIC rule;
//   - the rivals, the group that names the winner, the coloured-noise
//     gate.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include "ctid/apps/residtrace/judgement.hpp"

namespace ctid {
namespace {

using residtrace::CandidateKind;
using residtrace::CandidateRow;
using residtrace::JudgeOptions;

TEST(ResidtraceJudgement, GammaQAgainstClosedForms) {
  for (double x : {0.01, 0.3, 1.0, 1.9, 2.5, 7.0, 30.0, 200.0}) {
    // Q(1, x) = exp(-x); Q(2, x) = (1 + x) exp(-x); Q(1/2, x) = erfc(sqrt x)
    EXPECT_NEAR(residtrace::gamma_q(1.0, x) / std::exp(-x), 1.0, 1e-13) << x;
    EXPECT_NEAR(residtrace::gamma_q(2.0, x) / ((1 + x) * std::exp(-x)), 1.0,
                1e-13)
        << x;
    EXPECT_NEAR(residtrace::gamma_q(0.5, x) / std::erfc(std::sqrt(x)), 1.0,
                1e-12)
        << x;
  }
  EXPECT_EQ(residtrace::gamma_q(3.0, 0.0), 1.0);
  EXPECT_EQ(residtrace::gamma_q(0.0, 2.0), 0.0);
  EXPECT_TRUE(std::isnan(residtrace::gamma_q(-1.0, 2.0)));
}

TEST(ResidtraceJudgement, LikelihoodRatioTestWithTwoParameters) {
  const int n = 400;
  Vector<double> e0(n), e1(n);
  std::mt19937 gen(3);
  std::normal_distribution<double> w(0.0, 1.0);
  for (int k = 0; k < n; ++k) {
    e1(k) = w(gen);
    e0(k) = e1(k) + 0.15 * std::sin(0.05 * k);
  }
  const auto t = residtrace::lr_test<double>(e0, e1, 2.0);
  double s0 = 0, s1 = 0;
  for (int k = 0; k < n; ++k) {
    s0 += e0(k) * e0(k);
    s1 += e1(k) * e1(k);
  }
  const double lr = n * std::log(s0 / s1);
  ASSERT_GT(lr, 0);
  EXPECT_NEAR(t.lr, lr, 1e-12 * lr);
  EXPECT_NEAR(t.p / std::exp(-lr / 2), 1.0, 1e-12);  // chi^2(2)
  // no improvement: p = 1
  EXPECT_EQ(residtrace::lr_test<double>(e1, e0, 2.0).p, 1.0);
  // in-sample scoring uses it; the share is the same either way
  residtrace::CandidateScore<double> in, out;
  ASSERT_TRUE(residtrace::score_candidate<double>(e0, e1, true, 2, &in).ok());
  ASSERT_TRUE(residtrace::score_candidate<double>(e0, e1, false, 2, &out).ok());
  EXPECT_DOUBLE_EQ(in.p, t.p);
  EXPECT_DOUBLE_EQ(in.stat, t.lr);
  EXPECT_NEAR(in.score, 1 - s1 / s0, 1e-12);
  EXPECT_DOUBLE_EQ(in.score, out.score);
  EXPECT_DOUBLE_EQ(in.p_dm, out.p_dm);
}

TEST(ResidtraceJudgement, WaldStatistic) {
  Vector<double> th(1);
  th << -37;
  Matrix<double> C(1, 1);
  C << 4;
  EXPECT_NEAR(residtrace::wald<double>(th, C), 18.5, 1e-12);
  // an uncorrelated pair: sqrt(((a/sa)^2 + (b/sb)^2) / 2)
  Vector<double> ab(2);
  ab << 0.5, 0.001;
  Matrix<double> D = Matrix<double>::Zero(2, 2);
  D(0, 0) = 1e-4;
  D(1, 1) = 1e-4;
  EXPECT_NEAR(residtrace::wald<double>(ab, D),
              std::sqrt((50.0 * 50.0 + 0.1 * 0.1) / 2), 1e-9);
  C(0, 0) = 0;
  EXPECT_TRUE(std::isnan(residtrace::wald<double>(th, C)));
}

// cur: one input channel (nb 1) over F = [1 f1 f2]; the candidate adds a
// constant channel with the gain val +- sd.
void offset_case(double val, double sd, residtrace::StructureShape<double>* m,
                 residtrace::StructureShape<double>* cur) {
  cur->theta = Vector<double>(3);
  cur->theta << 1.2, 1, 2;
  cur->cov = 1e-4 * Matrix<double>::Identity(3, 3);
  cur->fixed = {false, false};
  cur->channels = {{"u1", 1}};
  *m = *cur;
  m->channels.push_back({"offset", 1});
  m->theta = Vector<double>(4);
  m->theta << 1.2, 1, 2, val;
  m->cov = 1e-4 * Matrix<double>::Identity(4, 4);
  m->cov(3, 3) = sd * sd;
}

TEST(ResidtraceJudgement, AcceptanceRefusesAnUndeterminedTerm) {
  residtrace::StructureShape<double> m, cur;
  offset_case(-37, 2e6, &m, &cur);
  const auto terms = residtrace::added_terms(m, cur);
  ASSERT_EQ(terms.size(), 1u);
  EXPECT_EQ(terms[0].name, "the offset term");
  auto a = residtrace::accept(terms, residtrace::Activity<double>(), 1000);
  EXPECT_FALSE(a.ok);
  EXPECT_NE(a.why.find("the offset term is not determined"), std::string::npos);
  offset_case(-37, 2, &m, &cur);
  a = residtrace::accept(residtrace::added_terms(m, cur),
                         residtrace::Activity<double>(), 1000);
  EXPECT_TRUE(a.ok);
  EXPECT_NEAR(a.tmax, 18.5, 1e-12);
  // determined (z >= 2) but not significant as a whole (z < 3)
  offset_case(2.5, 1, &m, &cur);
  a = residtrace::accept(residtrace::added_terms(m, cur),
                         residtrace::Activity<double>(), 1000);
  EXPECT_FALSE(a.ok);
  EXPECT_NE(a.why.find("not significant"), std::string::npos);
  // a physical realisation's terms are not judged here
  offset_case(-37, 2e6, &m, &cur);
  m.usable = false;
  a = residtrace::accept(residtrace::added_terms(m, cur),
                         residtrace::Activity<double>(), 1000);
  EXPECT_TRUE(a.ok);
  EXPECT_TRUE(std::isnan(a.tmax));
}

TEST(ResidtraceJudgement, AcceptanceOfAFreedCoefficient) {
  residtrace::StructureShape<double> m, cur;
  offset_case(0, 1, &m, &cur);
  m = cur;
  cur.fixed = {true, false};  // f1 fixed at 0 in cur (no damping)
  cur.theta = Vector<double>(2);
  cur.theta << 1, 2;
  cur.cov = 1e-4 * Matrix<double>::Identity(2, 2);
  m.cov(0, 0) = 0.01 * 0.01;  // f1 = 1.2 +- 0.01
  const auto terms = residtrace::added_terms(m, cur);
  ASSERT_EQ(terms.size(), 1u);
  EXPECT_EQ(terms[0].name, "the freed coefficient f1");
  EXPECT_NEAR(terms[0].z, 120, 1e-9);
}

TEST(ResidtraceJudgement, AcceptanceNeedsActivityOnPartOfTheRecord) {
  std::vector<residtrace::AddedTerm<double>> none;
  residtrace::Activity<double> act;
  act.share = 1;  // a saturation at its level on every sample
  auto a = residtrace::accept(none, act, 1000);
  EXPECT_FALSE(a.ok);
  EXPECT_NE(a.why.find("inactive on none"), std::string::npos);
  act.share = 0.002;  // on 2 samples of 1000: below 1 %
  EXPECT_FALSE(residtrace::accept(none, act, 1000).ok);
  act.share = 0.3;
  EXPECT_TRUE(residtrace::accept(none, act, 1000).ok);
  act.share = 0.012;  // 1.2 %, but 6 samples of 500 > 5: accepted
  EXPECT_TRUE(residtrace::accept(none, act, 500).ok);
  act.share = 0.012;  // 1.2 % of 300 samples is 3.6 < 5: refused
  EXPECT_FALSE(residtrace::accept(none, act, 300).ok);
}

TEST(ResidtraceJudgement, AcceptanceRefusesAFrictionWithoutReversals) {
  std::vector<residtrace::AddedTerm<double>> none;
  residtrace::Activity<double> act;
  act.share = 0.6;
  act.reversals = 0;
  auto a = residtrace::accept(none, act, 1000);
  EXPECT_FALSE(a.ok);
  EXPECT_NE(a.why.find("changes sign 0 time"), std::string::npos);
  act.reversals = 1;  // there and back: both directions
  EXPECT_TRUE(residtrace::accept(none, act, 1000).ok);
  act.share = 0.999;  // one direction on all but 0.1 %
  EXPECT_FALSE(residtrace::accept(none, act, 1000).ok);
}

CandidateRow<double> row(const std::string& effect, double score, double p,
                         bool applicable = true, double nadd = 1) {
  CandidateRow<double> r;
  r.effect = effect;
  r.variant = effect + " variant";
  r.score = score;
  r.p = p;
  r.applicable = applicable;
  r.nadd = nadd;
  return r;
}

TEST(ResidtraceJudgement, BonferroniWithinAGroup) {
  // four applicable candidates: the level is alpha / 4 = 0.0025
  std::vector<CandidateRow<double>> rows = {
      row("a", 0.5, 0.002), row("b", 0.5, 0.003), row("c", 0.005, 1e-9),
      row("d", 0.2, 0.0001), row("e", 0.9, 1e-12, false)};
  JudgeOptions o;
  const auto sig = residtrace::significance(rows, o);
  // a: 0.002 < 0.0025; b: 0.003 is not; c: share below minscore; d: yes;
  // e: not applicable
  EXPECT_EQ(sig, (std::vector<bool>{true, false, false, true, false}));
  // with only a and d applicable the level is 0.005: b passes too
  rows[2].applicable = false;
  rows[3].applicable = false;
  EXPECT_TRUE(residtrace::significance(rows, o)[1]);
  // before the pass, the initial state is declared at alpha / (the
  // simulated effects tested): 0.002 < 0.01 / 4 but not < 0.01 / 8
  const auto x = row("initial_state", 0.5, 0.002);
  EXPECT_TRUE(residtrace::declare_initial_state(x, 4, o));
  EXPECT_FALSE(residtrace::declare_initial_state(x, 8, o));
  EXPECT_FALSE(residtrace::declare_initial_state(
      row("initial_state", 0.005, 1e-9), 4, o));
  // the record's initial state is never significant in the ranking
  std::vector<CandidateRow<double>> x0 = {row("initial_state", 0.5, 1e-9)};
  EXPECT_FALSE(residtrace::judge_group(x0, o).significant[0]);
}

// n samples of e + c, e white of unit variance (seeded).
Vector<double> noise(int n, unsigned seed, double scale = 1) {
  std::mt19937 gen(seed);
  std::normal_distribution<double> w(0.0, scale);
  Vector<double> e(n);
  for (int k = 0; k < n; ++k) e(k) = w(gen);
  return e;
}

TEST(ResidtraceJudgement, RankingAndParsimony) {
  const int n = 4000;
  const Vector<double> base = noise(n, 11, 0.1);
  Vector<double> wave(n);
  for (int k = 0; k < n; ++k) wave(k) = 0.1 * std::sin(2 * M_PI * k / 400.0);
  JudgeOptions o;
  // the complex candidate (3 parameters) removes a little more than the
  // simple one (1 parameter) only by independent noise below minscore:
  // not significantly better, so the simple one goes first
  auto complex = row("order", 0.92, 1e-20, true, 3);
  complex.e1 = base;
  auto simple = row("delay", 0.90, 1e-20, true, 1);
  simple.e1 = base + noise(n, 12, 0.003);
  auto weak = row("offset", 0.95, 0.5, true, 1);    // not significant
  auto na = row("coulomb", 0.99, 1e-30, false, 1);  // not applicable
  std::vector<CandidateRow<double>> rows = {weak, simple, complex, na};
  auto g = residtrace::judge_group(rows, o);
  EXPECT_EQ(g.order, (std::vector<std::size_t>{1, 2, 0, 3}));
  // the complex one removes a structured error the simple one leaves:
  // it stays ahead
  rows[1].e1 = base + wave;
  rows[1].score = 0.5;
  g = residtrace::judge_group(rows, o);
  EXPECT_EQ(g.order, (std::vector<std::size_t>{2, 1, 0, 3}));
}

TEST(ResidtraceJudgement, SameFootingBic) {
  const int n = 4000;
  const Vector<double> base = noise(n, 21, 0.1);
  JudgeOptions o;
  // as many added parameters, errors the record does not tell apart: the
  // smaller BIC on the estimation data goes first
  auto a = row("static_nonlinearity", 0.90, 1e-20, true, 2);
  a.e1 = base;
  auto b = row("state_nonlinearity", 0.89, 1e-20, true, 2);
  b.e1 = base + noise(n, 22, 0.003);
  a.has_fit = b.has_fit = true;
  a.n_est = b.n_est = 1000;
  a.np = b.np = 5;
  a.bic = -3000;
  b.bic = -3100;  // b is the better fit on the estimation record
  std::vector<CandidateRow<double>> rows = {a, b};
  EXPECT_EQ(residtrace::judge_group(rows, o).order,
            (std::vector<std::size_t>{1, 0}));
  // footing: bic + (nadd - np) log N
  EXPECT_NEAR(residtrace::footing_bic(rows[1]),
              -3100 + (2 - 5) * std::log(1000.0), 1e-9);
  // unknown BIC: Inf, no swap
  rows[1].has_fit = false;
  EXPECT_EQ(residtrace::judge_group(rows, o).order,
            (std::vector<std::size_t>{0, 1}));
  // candidates of another kind are never swapped
  rows[1].has_fit = true;
  rows[0].kind = rows[1].kind = CandidateKind::kTracking;
  EXPECT_EQ(residtrace::judge_group(rows, o).order,
            (std::vector<std::size_t>{0, 1}));
}

TEST(ResidtraceJudgement, RivalsAndTheWinningGroup) {
  const int n = 4000;
  const Vector<double> e_w = noise(n, 7, 0.1);
  Vector<double> wave(n);
  for (int k = 0; k < n; ++k) wave(k) = 0.1 * std::sin(2 * M_PI * k / 400.0);
  JudgeOptions o;
  auto w = row("saturation", 0.9, 1e-20);
  w.e1 = e_w;
  auto same = row("static_nonlinearity", 0.8, 1e-20);
  same.e1 = e_w + noise(n, 8, 0.003);  // not told apart
  auto worse = row("order", 0.8, 1e-20);
  worse.e1 = e_w + wave;  // the winner removes what it leaves
  auto unsig = row("delay", 0.8, 0.5);
  unsig.e1 = e_w;
  auto also = row("saturation", 0.7, 1e-20);  // the winner's effect
  also.e1 = e_w + noise(n, 9, 0.003);
  auto diverged = row("coulomb", 0.6, 1e-20);  // a non-finite error
  diverged.e1 = e_w;
  diverged.e1(5) = std::numeric_limits<double>::infinity();
  std::vector<CandidateRow<double>> sim = {w,     same, worse,
                                           unsig, also, diverged};
  auto drift = row("drift", 0.95, 1e-20);
  drift.kind = CandidateKind::kTracking;
  drift.e1 = e_w;
  std::vector<CandidateRow<double>> out = {drift};
  auto p = residtrace::judge_pass(sim, out, o);
  EXPECT_EQ(p.winner_group, 1);
  EXPECT_EQ(p.winner, 0u);
  ASSERT_EQ(p.rivals.size(), 1u);
  EXPECT_EQ(p.rivals[0].index, 1u);
  residtrace::DmTest<double> t;
  ASSERT_TRUE(residtrace::dm_test<double>(same.e1, e_w, &t).ok());
  EXPECT_EQ(p.rivals[0].p, t.p_corr);
  // nothing simulated is significant: the output group names the winner
  for (auto& r : sim) r.p = 0.5;
  p = residtrace::judge_pass(sim, out, o);
  EXPECT_EQ(p.winner_group, 2);
  EXPECT_EQ(p.winner, 0u);
  EXPECT_TRUE(p.rivals.empty());
  out[0].p = 0.5;
  EXPECT_EQ(residtrace::judge_pass(sim, out, o).winner_group, 0);
}

TEST(ResidtraceJudgement, NoiseGate) {
  EXPECT_FALSE(residtrace::noise_gate(true, 1e-6, 0.5, 0.01).applicable);
  EXPECT_TRUE(residtrace::noise_gate(false, 1e-6, 0.5, 0.01).applicable);
  const auto white = residtrace::noise_gate(false, 0.3, 0.5, 0.01);
  EXPECT_FALSE(white.applicable);
  EXPECT_EQ(white.why, "the residual is white (p = 0.3 >= alpha)");
  const auto dep = residtrace::noise_gate(false, 1e-6, 1e-4, 0.01);
  EXPECT_FALSE(dep.applicable);
  EXPECT_NE(dep.why.find("depends on the input (p = 0.0001 < alpha)"),
            std::string::npos);
  // an untestable residual (NaN p-values): not tried, the figure as NaN
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const auto untested = residtrace::noise_gate(false, nan, nan, 0.01);
  EXPECT_FALSE(untested.applicable);
  EXPECT_NE(untested.why.find("(p = NaN < alpha)"), std::string::npos);
}

}  // namespace
}  // namespace ctid
