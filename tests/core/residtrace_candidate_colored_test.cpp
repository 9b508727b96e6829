// SPDX-License-Identifier: BSD-3-Clause
// Copyright (C) the ctid authors

// Tests of core/include/ctid/apps/residtrace/candidate_colored.hpp:
//   - a residual e(k) = 0.8 e(k-1) + w(k) (w white): an AR noise model of
//     order >= 1 whose dominant pole and lag-1 autocorrelation are near
//     0.8, kind "prediction";
//   - an AR(2) residual with the poles 0.9 exp(+-0.5 i): the dominant pole
//     is the one with the positive imaginary part, written as a complex
//     number;
//   - a white residual and one of too few samples give their reasons; a
//     residual of the wrong length is a Status error.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "ctid/apps/residtrace/candidate_colored.hpp"

namespace ctid::residtrace {
namespace {

// A model (its structure is not used) and a record of N samples whose
// residual follows e(k) = a1 e(k-1) + a2 e(k-2) + w(k).
void record(int N, double a1, double a2, unsigned seed,
            ResidtraceModel<double>* cur, CandidateContext<double>* ctx) {
  cur->F = Eigen::Vector2d(1, 2);
  cur->fixed = {false};
  ctx->D.y = Eigen::VectorXd::Zero(N);
  ctx->D.u = Eigen::MatrixXd::Zero(N, 1);
  ctx->D.ts = 0.1;
  std::mt19937 gen(seed);
  std::normal_distribution<double> w(0.0, 1.0);
  Eigen::VectorXd e(N);
  for (int k = 0; k < N; ++k) {
    e(k) = w(gen) + (k >= 1 ? a1 * e(k - 1) : 0) + (k >= 2 ? a2 * e(k - 2) : 0);
  }
  cur->estimate.e = e;
}

const EvidenceField<double>* field(const Candidate<double>& c,
                                   const char* name) {
  for (const EvidenceField<double>& f : c.evidence.fields) {
    if (f.name == name) return &f;
  }
  return nullptr;
}

TEST(ResidtraceCandidateColored, FindsAnAr1Residual) {
  ResidtraceModel<double> cur;
  CandidateContext<double> ctx;
  record(4000, 0.8, 0, 41, &cur, &ctx);
  Candidate<double> c;
  ASSERT_TRUE(colored_candidate<double>(cur, ctx, &c).ok());
  ASSERT_TRUE(c.applicable) << c.reason;
  EXPECT_EQ(c.kind, "prediction");
  EXPECT_GE(c.nadd, 1);
  ASSERT_EQ(c.model.noise.size(), c.nadd + 1);
  EXPECT_EQ(c.model.noise(0), 1);
  const EvidenceField<double>* pole = field(c, "pole");
  ASSERT_NE(pole, nullptr);
  EXPECT_NEAR(pole->value(0), 0.8, 0.05);
  EXPECT_EQ(pole->imag.size(), 0);
  EXPECT_NEAR(field(c, "rho1")->value(0), 0.8, 0.05);
  EXPECT_EQ(c.variant, "AR(" + std::to_string(c.nadd) + ")");
}

TEST(ResidtraceCandidateColored, AComplexDominantPole) {
  ResidtraceModel<double> cur;
  CandidateContext<double> ctx;
  const double r = 0.9, th = 0.5;
  record(4000, 2 * r * std::cos(th), -r * r, 42, &cur, &ctx);
  Candidate<double> c;
  ASSERT_TRUE(colored_candidate<double>(cur, ctx, &c).ok());
  ASSERT_TRUE(c.applicable) << c.reason;
  const EvidenceField<double>* pole = field(c, "pole");
  ASSERT_NE(pole, nullptr);
  ASSERT_EQ(pole->imag.size(), 1);
  EXPECT_NEAR(pole->value(0), r * std::cos(th), 0.03);
  EXPECT_NEAR(pole->imag(0), r * std::sin(th), 0.03);
  EXPECT_NE(c.evidence.text.find("i, lag-1"), std::string::npos)
      << c.evidence.text;
}

TEST(ResidtraceCandidateColored, WhiteOrShortResidualAndBadInput) {
  ResidtraceModel<double> cur;
  CandidateContext<double> ctx;
  record(2000, 0, 0, 43, &cur, &ctx);
  Candidate<double> c;
  ASSERT_TRUE(colored_candidate<double>(cur, ctx, &c).ok());
  EXPECT_FALSE(c.applicable);
  EXPECT_EQ(c.reason, "an AR model does not improve on white noise (BIC)");
  record(19, 0.8, 0, 44, &cur, &ctx);
  ASSERT_TRUE(colored_candidate<double>(cur, ctx, &c).ok());
  EXPECT_EQ(c.reason, "too few samples for a noise model");
  cur.estimate.e.resize(3);
  EXPECT_FALSE(colored_candidate<double>(cur, ctx, &c).ok());
  EXPECT_FALSE(colored_candidate<double>(cur, ctx, nullptr).ok());
}

}  // namespace
}  // namespace ctid::residtrace
