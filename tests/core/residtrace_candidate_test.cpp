// SPDX-License-Identifier: BSD-3-Clause
// Copyright (C) the ctid authors
// Tests of core/include/ctid/apps/residtrace/candidate.hpp:
//   - select_variant keeps the converged variant of smallest BIC, skips a
//     failed one and one below its order floor, and reports none when no
//     variant converged (models given as fitted, so the BICs are known);
//   - offset_candidate recovers a known output offset and a known input
//     offset (in input units) of a first-order system, with the evidence
//     text showing the value, and is not applicable when the model
//     estimates its levels or has both offsets already;
//   - viscous_candidate frees a velocity coefficient fixed at zero and
//     recovers the true one, f / b0 as its physical reading, and is not
//     applicable when the coefficient is estimated;
//   - order_candidate (candidate_order.hpp) finds the missing pole of a
//     second-order system given a first-order model, keeps an integrator
//     of the model exactly, and has no admissible order for a numerator
//     as long as every raised denominator;
//   - the evidence's rows of roots are written as Octave's num2str (x, 4)
//     writes them (its output for the same numbers);
//   - coulomb_candidate (candidate_coulomb.hpp) recovers the Coulomb level
//     of a first-order velocity system simulated with its friction, is not
//     applicable to a model that has it already or when the velocity never
//     reverses, and finds sign(v) not identifiable when a two-level input
//     decides the direction.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <random>
#include <vector>

#include "ctid/apps/residtrace/candidate.hpp"
#include "ctid/apps/residtrace/candidate_coulomb.hpp"
#include "ctid/apps/residtrace/candidate_order.hpp"
#include "test_util.hpp"

namespace ctid::residtrace {
namespace {

constexpr double kTs = 0.05;

ResidtraceModel<double> model(const Eigen::VectorXd& F,
                              const Eigen::VectorXd& B) {
  ResidtraceModel<double> m;
  m.F = F;
  m.fixed.assign(static_cast<std::size_t>(F.size() - 1), false);
  StructureChannel<double> c;
  c.col = 0;
  c.nb = static_cast<int>(B.size());
  c.B = B;
  m.channels.push_back(c);
  return m;
}

// The record of truth driven by u + du, plus dy and a little white noise.
CandidateContext<double> context(const ResidtraceModel<double>& truth,
                                 double du, double dy, int N, unsigned seed) {
  const std::vector<double> u = test::binary_input(N, 9, seed);
  CandidateContext<double> ctx;
  ctx.D.u = Eigen::Map<const Eigen::VectorXd>(u.data(), N);
  ctx.D.ts = kTs;
  const Eigen::MatrixXd driven = ctx.D.u.array() + du;
  ModelSimulation<double> sim;
  EXPECT_TRUE(
      simulate_model<double>(truth, driven, kTs, nullptr, 1, nullptr, &sim)
          .ok());
  std::mt19937 gen(seed);
  std::normal_distribution<double> e(0.0, 1e-3);
  ctx.D.y = sim.y.array() + dy;
  for (Eigen::Index k = 0; k < ctx.D.y.size(); ++k) ctx.D.y(k) += e(gen);
  ctx.D.ysm = ctx.D.y;
  ctx.fit.max_iterations = 20;
  ctx.fit.substeps = 1;
  return ctx;
}

Variant<double> fitted(const char* name, double bic, bool ok, int order) {
  Variant<double> v;
  v.name = name;
  v.fitted = true;
  v.tmpl.F = Eigen::VectorXd::Ones(order + 1);
  v.tmpl.estimate.ok = ok;
  v.tmpl.estimate.bic = bic;
  v.tmpl.estimate.s2 = std::exp(bic / 100);
  return v;
}

TEST(ResidtraceCandidate, SelectKeepsTheSmallestBic) {
  CandidateContext<double> ctx;
  ctx.fit.max_iterations = 20;
  std::vector<Variant<double>> v = {fitted("a", -10, true, 2),
                                    fitted("b", -30, true, 2),
                                    fitted("c", -50, false, 2)};
  int best = -2;
  ResidtraceModel<double> m;
  std::vector<VariantRow<double>> table;
  ASSERT_TRUE(select_variant<double>(v, ctx, &best, &m, &table).ok());
  EXPECT_EQ(best, 1);
  EXPECT_DOUBLE_EQ(m.estimate.bic, -30);
  ASSERT_EQ(table.size(), 3u);
  EXPECT_EQ(table[0].variant, "a");
  EXPECT_DOUBLE_EQ(table[0].bic, -10);
  EXPECT_TRUE(std::isnan(table[2].bic));  // the failed one
  // an order floor above the fit's order: the variant fails
  v[1].order_floor = 3;
  ASSERT_TRUE(select_variant<double>(v, ctx, &best, &m, &table).ok());
  EXPECT_EQ(best, 0);
  v[0].tmpl.estimate.ok = false;
  ASSERT_TRUE(select_variant<double>(v, ctx, &best, &m, &table).ok());
  EXPECT_EQ(best, -1);
}

TEST(ResidtraceCandidate, OffsetRecoversAnOutputOffset) {
  const ResidtraceModel<double> truth =
      model(Eigen::Vector2d(1, 2), Eigen::VectorXd::Constant(1, 3));
  const CandidateContext<double> ctx = context(truth, 0, 0.7, 600, 3);
  Candidate<double> c;
  ASSERT_TRUE(offset_candidate<double>(truth, ctx, &c).ok());
  ASSERT_TRUE(c.applicable);
  EXPECT_EQ(c.variant, "output offset");
  EXPECT_EQ(c.nadd, 1);
  ASSERT_EQ(c.variants.size(), 2u);
  EXPECT_LT(c.variants[1].bic, c.variants[0].bic);
  const double val = c.model.out.back().c(0);
  EXPECT_NEAR(val, 0.7, 1e-3);
  EXPECT_NE(c.evidence.text.find("output offset 0.7"), std::string::npos)
      << c.evidence.text;
}

TEST(ResidtraceCandidate, OffsetRecoversAnInputOffsetInInputUnits) {
  const ResidtraceModel<double> truth =
      model(Eigen::Vector2d(1, 2), Eigen::VectorXd::Constant(1, 3));
  const CandidateContext<double> ctx = context(truth, 0.5, 0, 600, 4);
  Candidate<double> c;
  ASSERT_TRUE(offset_candidate<double>(truth, ctx, &c).ok());
  ASSERT_TRUE(c.applicable);
  EXPECT_EQ(c.variant, "input offset");
  ASSERT_EQ(c.model.channels.size(), 2u);
  EXPECT_EQ(c.model.channels[1].kind, ChannelKind::kConstant);
  // b_c / b_u = d
  const double bc = c.model.channels[1].B(0);
  const double bu = c.model.channels[0].B(0);
  EXPECT_NEAR(bc / bu, 0.5, 2e-3);
  EXPECT_NE(c.evidence.text.find("input offset 0.5"), std::string::npos)
      << c.evidence.text;
}

TEST(ResidtraceCandidate, OffsetNotApplicableWithLevelsOrBothOffsets) {
  ResidtraceModel<double> m =
      model(Eigen::Vector2d(1, 2), Eigen::VectorXd::Constant(1, 3));
  const CandidateContext<double> ctx = context(m, 0, 0, 200, 5);
  Candidate<double> c;
  m.levels = true;
  ASSERT_TRUE(offset_candidate<double>(m, ctx, &c).ok());
  EXPECT_FALSE(c.applicable);
  EXPECT_FALSE(c.failed);
  m.levels = false;
  StructureChannel<double> k;
  k.kind = ChannelKind::kConstant;
  k.col = -1;
  k.B = Eigen::VectorXd::Zero(1);
  m.channels.push_back(k);
  OutputTerm<double> t;
  t.c = t.cstd = Eigen::VectorXd::Zero(1);
  m.out.push_back(t);
  ASSERT_TRUE(offset_candidate<double>(m, ctx, &c).ok());
  EXPECT_FALSE(c.applicable);
  EXPECT_EQ(c.reason, "the model has its offsets already");
}

TEST(ResidtraceCandidate, ViscousFreesTheVelocityCoefficient) {
  // 2 / (p^2 + 1.5 p + 4): the template has f1 fixed at zero
  const ResidtraceModel<double> truth =
      model(Eigen::Vector3d(1, 1.5, 4), Eigen::VectorXd::Constant(1, 2));
  const CandidateContext<double> ctx = context(truth, 0, 0, 1500, 6);
  ResidtraceModel<double> cur = truth;
  cur.F(1) = 0;
  cur.fixed = {true, false};
  Candidate<double> c;
  ASSERT_TRUE(viscous_candidate<double>(cur, ctx, &c).ok());
  ASSERT_TRUE(c.applicable);
  EXPECT_EQ(c.variant, "free f1");
  EXPECT_NEAR(c.model.F(1), 1.5, 1e-2);
  EXPECT_NEAR(c.model.estimate.theta(0), c.model.F(1), 1e-12);
  EXPECT_EQ(c.evidence.text.substr(0, 5), "f1 = ");
  EXPECT_NE(c.evidence.text.find("viscous coefficient 0.7"), std::string::npos)
      << c.evidence.text;
  // estimated already: not applicable
  ASSERT_TRUE(viscous_candidate<double>(truth, ctx, &c).ok());
  EXPECT_FALSE(c.applicable);
}

// The current model of a candidate: its structure fitted on the record
// (the candidates read its BIC and number of parameters).
ResidtraceModel<double> fitted_model(const ResidtraceModel<double>& tmpl,
                                     const CandidateContext<double>& ctx) {
  ResidtraceModel<double> m;
  EXPECT_TRUE(fit_model<double>(tmpl, ctx.D, {tmpl.F}, ctx.fit, &m).ok());
  EXPECT_TRUE(m.estimate.ok);
  return m;
}

std::vector<std::complex<double>> sorted_roots(const Eigen::VectorXd& F) {
  std::vector<std::complex<double>> r = roots_descending<double>(F);
  std::sort(r.begin(), r.end(),
            [](auto a, auto b) { return std::abs(a) < std::abs(b); });
  return r;
}

TEST(ResidtraceCandidate, OrderFindsTheMissingPole) {
  // 4 / ((p + 1)(p + 4)) explained by a first-order model
  const ResidtraceModel<double> truth =
      model(Eigen::Vector3d(1, 5, 4), Eigen::VectorXd::Constant(1, 4));
  CandidateContext<double> ctx = context(truth, 0, 0, 1500, 7);
  ctx.wlo = 0.1;
  const ResidtraceModel<double> cur = fitted_model(
      model(Eigen::Vector2d(1, 1), Eigen::VectorXd::Constant(1, 1)), ctx);
  Candidate<double> c;
  ASSERT_TRUE(order_candidate<double>(cur, ctx, &c).ok());
  ASSERT_TRUE(c.applicable);
  EXPECT_EQ(c.variant, "na + 1, nb + 0");
  EXPECT_EQ(c.nadd, 1);
  const auto p = sorted_roots(c.model.F);
  ASSERT_EQ(p.size(), 2u);
  EXPECT_NEAR(p[0].real(), -1, 0.02);
  EXPECT_NEAR(p[1].real(), -4, 0.08);
  EXPECT_GT(c.evidence.fields[4].value(0), 100);  // the BIC's drop
  EXPECT_EQ(c.evidence.text.substr(0, 24), "na + 1, nb + 0: poles -4");
}

TEST(ResidtraceCandidate, OrderKeepsTheIntegrator) {
  // 3 / (p (p + 3)) explained by 1 / p, the integrator fixed
  const ResidtraceModel<double> truth =
      model(Eigen::Vector3d(1, 3, 0), Eigen::VectorXd::Constant(1, 3));
  CandidateContext<double> ctx = context(truth, 0, 0, 1500, 8);
  ctx.wlo = 0.1;
  ResidtraceModel<double> tmpl =
      model(Eigen::Vector2d(1, 0), Eigen::VectorXd::Constant(1, 1));
  tmpl.fixed = {true};
  const ResidtraceModel<double> cur = fitted_model(tmpl, ctx);
  Candidate<double> c;
  ASSERT_TRUE(order_candidate<double>(cur, ctx, &c).ok());
  ASSERT_TRUE(c.applicable);
  ASSERT_EQ(c.model.F.size(), 3);
  EXPECT_EQ(c.model.F(2), 0.0);
  EXPECT_NEAR(c.model.F(1), 3, 0.06);
}

TEST(ResidtraceCandidate, OrderNeedsAStrictlyProperVariant) {
  ResidtraceModel<double> cur =
      model(Eigen::Vector2d(1, 1), Eigen::VectorXd::Constant(4, 1));
  CandidateContext<double> ctx;
  ctx.wlo = 0.1;
  Candidate<double> c;
  ASSERT_TRUE(order_candidate<double>(cur, ctx, &c).ok());
  EXPECT_FALSE(c.applicable);
  EXPECT_EQ(c.reason, "no admissible order");
  ctx.wlo = 0;  // no band: refused
  EXPECT_FALSE(order_candidate<double>(cur, ctx, &c).ok());
}

TEST(ResidtraceCandidate, RootsWrittenAsOctavesNum2str) {
  using candidate_detail::num2str;
  // Octave 7: num2str ([-2 -1], 4), num2str ([-0.4357+1.923i,
  // -0.4357-1.923i, -0.1286], 4), num2str ([-0.00012345 1e7 3], 4),
  // num2str (zeros (1, 0), 4), num2str ([NaN Inf -Inf], 4)
  EXPECT_EQ(num2str<double>(Eigen::Vector2d(-2, -1), Eigen::Vector2d(0, 0), 4),
            "-2         -1");
  EXPECT_EQ(num2str<double>(Eigen::Vector3d(-0.4357, -0.4357, -0.1286),
                            Eigen::Vector3d(1.923, -1.923, 0), 4),
            "-0.4357+1.923i         -0.4357-1.923i         -0.1286+0i");
  EXPECT_EQ(num2str<double>(Eigen::Vector3d(-0.00012345, 1e7, 3),
                            Eigen::VectorXd(), 4),
            "-0.0001234      1e+07          3");
  EXPECT_EQ(num2str<double>(Eigen::VectorXd(), Eigen::VectorXd(), 4), "");
  EXPECT_EQ(num2str<double>(Eigen::Vector3d(NAN, INFINITY, -INFINITY),
                            Eigen::VectorXd(), 4),
            "NaN        Inf       -Inf");
}

// A first-order velocity system 2 / (p + 2) driven by u and braked by a
// Coulomb friction of level fc (in input units): the channel sign(y) with
// the gain -2 fc. Its record holds the velocity columns of the candidate.
CandidateContext<double> friction_record(const Eigen::VectorXd& u, double fc,
                                         unsigned seed) {
  ResidtraceModel<double> truth =
      model(Eigen::Vector2d(1, 2), Eigen::VectorXd::Constant(1, 2));
  StructureChannel<double> sv;
  sv.kind = ChannelKind::kSignOutput;
  sv.col = -1;
  sv.B = Eigen::VectorXd::Constant(1, -2 * fc);
  truth.channels.push_back(sv);
  CandidateContext<double> ctx;
  ctx.D.u = u;
  ctx.D.ts = kTs;
  ModelSimulation<double> sim;
  EXPECT_TRUE(simulate_model<double>(truth, Eigen::MatrixXd(u), kTs, nullptr, 1,
                                     nullptr, &sim)
                  .ok());
  std::mt19937 gen(seed);
  std::normal_distribution<double> e(0.0, 1e-3);
  ctx.D.y = sim.y;
  for (Eigen::Index k = 0; k < ctx.D.y.size(); ++k) ctx.D.y(k) += e(gen);
  ctx.D.ysm = ctx.D.y;
  const Eigen::Index N = ctx.D.y.size();
  Eigen::VectorXd v0, v1;
  EXPECT_TRUE(
      zero_lag_velocity<double>(ctx.D.y.data(), N, kTs, 20, false, &v0).ok());
  EXPECT_TRUE(
      zero_lag_velocity<double>(ctx.D.y.data(), N, kTs, 20, true, &v1).ok());
  ctx.D.vhat.resize(N, 2);
  ctx.D.vhat << v0, v1;
  ctx.fit.max_iterations = 20;
  ctx.fit.substeps = 1;
  ctx.wlo = 0.1;
  return ctx;
}

TEST(ResidtraceCandidate, CoulombRecoversTheFrictionLevel) {
  // a multilevel input (random levels of magnitude 0.5 to 1, above the
  // friction, held 40 samples): the velocity reverses, stays away from
  // rest, and its sign is not decided by the input alone
  const int N = 3000;
  std::mt19937 gen(11);
  std::uniform_real_distribution<double> level(-1.0, 1.0);
  Eigen::VectorXd u(N);
  for (int k = 0; k < N; ++k) {
    const double r = level(gen);
    u(k) =
        k % 40 == 0 ? (r < 0 ? -1 : 1) * (0.5 + 0.5 * std::abs(r)) : u(k - 1);
  }
  const CandidateContext<double> ctx = friction_record(u, 0.3, 12);
  const ResidtraceModel<double> cur = fitted_model(
      model(Eigen::Vector2d(1, 1), Eigen::VectorXd::Constant(1, 1)), ctx);
  Candidate<double> c;
  ASSERT_TRUE(coulomb_candidate<double>(cur, ctx, &c).ok());
  ASSERT_TRUE(c.applicable) << c.reason;
  EXPECT_EQ(c.variant.substr(0, 7), "sign(y)");
  EXPECT_EQ(c.model.channels.back().kind, ChannelKind::kSignOutput);
  const EvidenceField<double>& phys = c.evidence.fields[3];
  ASSERT_EQ(phys.name, "physical");
  EXPECT_NEAR(phys.value(0), 0.3, 0.045);  // 15 %: v near 0 is noise
  EXPECT_EQ(c.evidence.text.substr(0, 14), "Coulomb level ");
  // the model has it now: not applicable
  const ResidtraceModel<double> with_friction = c.model;
  ASSERT_TRUE(coulomb_candidate<double>(with_friction, ctx, &c).ok());
  EXPECT_FALSE(c.applicable);
  EXPECT_EQ(c.reason, "the model has Coulomb friction already");
}

TEST(ResidtraceCandidate, CoulombNeedsReversalsAndAnInputThatDoesNotDecide) {
  const int N = 1500;
  // a positive input: the velocity never reverses
  Eigen::VectorXd u = Eigen::VectorXd::Constant(N, 1.0);
  for (int k = 0; k < N; ++k) u(k) += 0.5 * ((k / 50) % 2);
  CandidateContext<double> ctx = friction_record(u, 0.3, 13);
  const ResidtraceModel<double> cur =
      model(Eigen::Vector2d(1, 2), Eigen::VectorXd::Constant(1, 2));
  Candidate<double> c;
  ASSERT_TRUE(coulomb_candidate<double>(cur, ctx, &c).ok());
  EXPECT_FALSE(c.applicable);
  EXPECT_EQ(c.reason, "the velocity never changes sign");
  // a two-level input of +-1, switching every 20 s, decides the direction
  // of a velocity that settles in 2 s
  for (int k = 0; k < N; ++k) u(k) = (k / 400) % 2 ? 1.0 : -1.0;
  ctx = friction_record(u, 0.3, 14);
  ASSERT_TRUE(coulomb_candidate<double>(cur, ctx, &c).ok());
  EXPECT_FALSE(c.applicable);
  EXPECT_NE(c.reason.find("not identifiable from these data"),
            std::string::npos)
      << c.reason;
  EXPECT_NE(c.reason.find("a two-level input"), std::string::npos);
}

}  // namespace
}  // namespace ctid::residtrace
