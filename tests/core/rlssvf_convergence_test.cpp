// SPDX-License-Identifier: BSD-3-Clause
// Copyright (C) the ctid authors
// Tests of core/include/ctid/recursive/rlssvf_convergence.hpp: the
// composite equals its parts (run_rlssvf, trace P / trace P0 from the
// stored covariances, detect_convergence); a noise-free record converges
// well before its end and a record too short for the window is refused;
// the settings are checked before the run; the options table sets them.
#include "ctid/recursive/rlssvf_convergence.hpp"

#include <gtest/gtest.h>

#include <vector>

#include "ctid/simulation/ltv_simulator.hpp"
#include "test_util.hpp"

namespace ctid {
namespace {

struct Case {
  double ts = 0.01;
  ModelOrders orders = siso_orders(2, 1, 0);
  std::vector<double> u, y;
  RlsSvfConfig<double> config;
  Case() {
    u = test::binary_input(20000, 150, 7);  // 200 s
    LtvSimulationConfig<double> sim_config;
    sim_config.orders = orders;
    LtvSimulator<double> sim;
    EXPECT_TRUE(sim.configure(sim_config).ok());
    const Eigen::Vector3d theta(2.4, 4.0, 4.0);
    y.assign(u.size(), 0.0);
    SimulationOutputs<double> out;
    out.x = y.data();
    EXPECT_TRUE(sim.simulate([&](double, Eigen::VectorXd& th) { th = theta; },
                             record(), nullptr, nullptr, out)
                    .ok());
    config.orders = orders;
    config.svf.lambda_svf = 3;
  }
  RecordView<double> record() const {
    RecordView<double> r;
    r.y = y.data();
    r.u = u.data();
    r.num_samples = static_cast<Eigen::Index>(u.size());
    r.num_inputs = 1;
    r.ts = ts;
    return r;
  }
};

ConvergenceSettings settings() {
  ConvergenceSettings s;
  s.block_length = 2 * 2 * 3.141592653589793 / 3;  // two cut-off periods
  return s;
}

TEST(RlsSvfConvergence, EqualsItsParts) {
  const Case c;
  ConvergenceRun<double> run;
  ASSERT_TRUE(rlssvf_convergence(c.config, c.record(), settings(), &run).ok());

  const Eigen::Index n = c.record().num_samples, np = 3;
  Eigen::MatrixXd thm(n, np);
  std::vector<double> yh(n), pset(n * np * np);
  RecursiveOutputs<double> out;
  out.thm = thm.data();
  out.yh = yh.data();
  out.pset = pset.data();
  ASSERT_TRUE(run_rlssvf(c.config, c.record(), out).ok());
  std::vector<double> t(n), ratio(n);
  for (Eigen::Index k = 0; k < n; ++k) {
    t[k] = k * c.ts;
    const double* p = &pset[k * np * np];
    ratio[k] = (p[0] + p[4] + p[8]) / (3 * 1e4);  // P0 = 1e4 I
  }
  ConvergenceReport<double> report;
  ASSERT_TRUE(detect_convergence(t.data(), c.y.data(), yh.data(), thm,
                                 ratio.data(), settings(), report)
                  .ok());
  EXPECT_EQ(run.thm, thm);
  for (Eigen::Index k = 0; k < n; ++k) EXPECT_EQ(run.yh[k], yh[k]);
  EXPECT_EQ(run.report.converged, report.converged);
  EXPECT_EQ(run.report.tsiv, report.tsiv);
  EXPECT_EQ(run.report.p_index, report.p_index);
  // (the first block has no previous one: NaN in both)
  EXPECT_EQ(run.report.dtheta.array().isNaN().matrix(),
            report.dtheta.array().isNaN().matrix());
  EXPECT_EQ(run.report.dtheta.tail(report.dtheta.size() - 1),
            report.dtheta.tail(report.dtheta.size() - 1));
}

TEST(RlsSvfConvergence, NoiseFreeRecordConvergesEarly) {
  const Case c;
  ConvergenceRun<double> run;
  ASSERT_TRUE(rlssvf_convergence(c.config, c.record(), settings(), &run).ok());
  ASSERT_TRUE(run.report.converged);
  const double duration = (c.u.size() - 1) * c.ts;
  EXPECT_LT(run.report.tsiv, 0.5 * duration);
  EXPECT_GE(run.report.tsiv, settings().num_blocks * settings().block_length);
  // the estimates have converged at tsiv
  const Eigen::RowVectorXd at = run.thm.row(run.report.sample);
  EXPECT_LT((at - Eigen::RowVector3d(2.4, 4.0, 4.0)).norm(), 0.05 * 4);
}

TEST(RlsSvfConvergence, SettingsCheckedBeforeTheRun) {
  const Case c;
  ConvergenceRun<double> run;
  ConvergenceSettings s = settings();
  s.block_length = 1.5 * c.ts;  // fewer than two samples per block
  EXPECT_EQ(rlssvf_convergence(c.config, c.record(), s, &run).code(),
            ErrorCode::kBadInput);
  EXPECT_EQ(run.thm.size(), 0);  // refused before RLSSVF ran
  s = settings();
  s.alpha = 0.5;
  EXPECT_EQ(rlssvf_convergence(c.config, c.record(), s, &run).code(),
            ErrorCode::kBadInput);
  s = settings();
  s.num_blocks = 1000;  // the record holds fewer blocks
  EXPECT_EQ(rlssvf_convergence(c.config, c.record(), s, &run).code(),
            ErrorCode::kBadInput);
  s = settings();
  s.use_output_error = s.use_theta = s.use_p = false;
  EXPECT_EQ(rlssvf_convergence(c.config, c.record(), s, &run).code(),
            ErrorCode::kBadOption);
}

TEST(RlsSvfConvergence, OptionsTableSetsTheSettings) {
  ConvergenceSettings s;
  OptionValue v;
  v.real = 0.2;
  ASSERT_TRUE(set_option(convergence_options(), "alpha", v, &s).ok());
  EXPECT_EQ(s.alpha, 0.2);
  v.integer = 7;
  ASSERT_TRUE(set_option(convergence_options(), "nblocks", v, &s).ok());
  EXPECT_EQ(s.num_blocks, 7);
  v.flag = false;
  ASSERT_TRUE(set_option(convergence_options(), "use_P", v, &s).ok());
  EXPECT_FALSE(s.use_p);
  EXPECT_FALSE(set_option(convergence_options(), "bogus", v, &s).ok());
  EXPECT_EQ(option_default(*find_option(convergence_options(), "ptol")),
            "0.01");
}

}  // namespace
}  // namespace ctid
