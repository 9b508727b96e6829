// SPDX-License-Identifier: BSD-3-Clause
// Copyright (C) the ctid authors
// Tests of core/include/ctid/offline/hammerstein.hpp: HSRIVC recovers a
// Hammerstein system exactly from a noise-free record (simulated
// independently: controllable canonical state space, exact ZOH step by
// the matrix exponential), from the engine's start and from a given
// start (settings.theta_init); the given start is the one used (one
// iteration from it differs from one from the engine's, and equals one
// from the same start again); HRIVC's ARMA step uses
// settings.arma_method: its noise model is arma_estimate's, with that
// method, of the final simulation residual.
#include "ctid/offline/hammerstein.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "test_util.hpp"

namespace ctid {
namespace {

using test::relative_error;
using test::simulate_zoh;

// CONTSID's Hammerstein demo: ubar = u + 0.5 u^2 + 0.25 u^3 into
// (10 p + 30)/(p^2 + p + 5), u uniform on [-2, 2], Ts = 0.5.
struct Record {
  std::vector<double> y, w;  // w: N x 3, column-major [u u^2 u^3]
  int n = 1000;
  double ts = 0.5;
};

Record hammerstein_record(double noise_sd, unsigned seed) {
  Record r;
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> uniform(-2, 2);
  std::normal_distribution<double> normal(0, 1);
  std::vector<double> u(r.n), ubar(r.n);
  r.w.resize(3 * r.n);
  for (int k = 0; k < r.n; ++k) {
    u[k] = uniform(rng);
    ubar[k] = u[k] + 0.5 * u[k] * u[k] + 0.25 * u[k] * u[k] * u[k];
    r.w[k] = u[k];
    r.w[r.n + k] = u[k] * u[k];
    r.w[2 * r.n + k] = u[k] * u[k] * u[k];
  }
  Eigen::VectorXd num(2), den(3);
  num << 10, 30;
  den << 1, 1, 5;
  r.y = simulate_zoh(num, den, ubar, r.ts);
  for (double& v : r.y) v += noise_sd * normal(rng);
  return r;
}

RivData<double> view(const Record& r) {
  RivData<double> d;
  d.y = r.y.data();
  d.w = r.w.data();
  d.num_samples = r.n;
  d.ts = r.ts;
  return d;
}

Eigen::VectorXd separated(const BlockResult<double>& res) {
  Eigen::VectorXd s(6);
  s << res.f, res.b, res.alpha.tail(2);
  return s;
}

TEST(Hsrivc, NoiseFreeExactFromTheEngineAndFromAGivenStart) {
  const Record r = hammerstein_record(0, 3);
  BlockOrders o;
  o.nb = 2;
  o.nf = 2;
  Eigen::VectorXd truth(6);
  truth << 1, 5, 10, 30, 0.5, 0.25;
  BlockSettings<double> settings;
  BlockResult<double> res;
  ASSERT_TRUE(
      block_srivc(BlockModel::kHammerstein, o, settings, view(r), 3, &res)
          .ok());
  EXPECT_LT(relative_error(separated(res), truth), 1e-8);
  // A rough stable start [f; B_1; B_2; B_3] (MISO layout).
  settings.theta_init.resize(8);
  settings.theta_init << 2, 3, 5, 20, 2, 10, 1, 5;
  ASSERT_TRUE(
      block_srivc(BlockModel::kHammerstein, o, settings, view(r), 3, &res)
          .ok());
  EXPECT_LT(relative_error(separated(res), truth), 1e-8);
}

TEST(Hsrivc, TheGivenStartIsUsed) {
  const Record r = hammerstein_record(2.0, 5);
  BlockOrders o;
  o.nb = 2;
  o.nf = 2;
  BlockSettings<double> settings;
  settings.max_iterations = 1;
  BlockResult<double> engine, given, again;
  block_srivc(BlockModel::kHammerstein, o, settings, view(r), 3, &engine);
  settings.theta_init.resize(8);
  settings.theta_init << 2, 3, 5, 20, 2, 10, 1, 5;
  block_srivc(BlockModel::kHammerstein, o, settings, view(r), 3, &given);
  block_srivc(BlockModel::kHammerstein, o, settings, view(r), 3, &again);
  ASSERT_EQ(given.iterations, 1);
  EXPECT_GT(relative_error(separated(given), separated(engine)), 1e-3);
  EXPECT_EQ(relative_error(separated(given), separated(again)), 0);
}

TEST(Hsrivc, AStartOfTheWrongSizeIsBadInput) {
  const Record r = hammerstein_record(0, 3);
  BlockOrders o;
  o.nb = 2;
  o.nf = 2;
  BlockSettings<double> settings;
  settings.theta_init = Eigen::VectorXd::Ones(6);
  BlockResult<double> res;
  EXPECT_EQ(block_srivc(BlockModel::kHammerstein, o, settings, view(r), 3, &res)
                .code(),
            ErrorCode::kBadInput);
}

TEST(Hrivc, TheNoiseModelIsTheChosenArmaEstimatorsOnTheResidual) {
  Record r = hammerstein_record(0, 7);
  // ARMA(1,1) noise (1 + 0.5 q^-1)/(1 - 0.85 q^-1), fitted as ARMA(2,2).
  std::mt19937 rng(11);
  std::normal_distribution<double> normal(0, 0.6);
  double e_prev = 0, v_prev = 0;
  for (double& y : r.y) {
    const double e = normal(rng);
    const double v = 0.85 * v_prev + e + 0.5 * e_prev;
    y += v;
    e_prev = e;
    v_prev = v;
  }
  BlockOrders o;
  o.nb = 2;
  o.nf = 2;
  o.nc = 2;
  o.nd = 2;
  BlockSettings<double> settings;
  BlockResult<double> pem, ivarma;
  ASSERT_TRUE(
      block_srivc(BlockModel::kHammersteinArma, o, settings, view(r), 3, &pem)
          .ok());
  settings.arma_method = ArmaMethod::kIvarma;
  ASSERT_TRUE(block_srivc(BlockModel::kHammersteinArma, o, settings, view(r), 3,
                          &ivarma)
                  .ok());
  for (const BlockResult<double>* res : {&pem, &ivarma}) {
    const Eigen::VectorXd residual =
        Eigen::Map<const Eigen::VectorXd>(r.y.data(), r.n) - res->simulated;
    ArmaSettings<double> arma;
    arma.method = res == &pem ? ArmaMethod::kPem : ArmaMethod::kIvarma;
    ArmaResult<double> direct;
    ASSERT_TRUE(
        arma_estimate<double>(residual.data(), r.n, 2, 2, arma, &direct).ok());
    EXPECT_LT(relative_error(res->c, direct.c), 1e-12);
    EXPECT_LT(relative_error(res->d, direct.d), 1e-12);
  }
  Eigen::VectorXd a(6), b(6);
  a << pem.c, pem.d;
  b << ivarma.c, ivarma.d;
  EXPECT_GT((a - b).norm(), 1e-3) << "pem and ivarma gave the same model";
}

}  // namespace
}  // namespace ctid
