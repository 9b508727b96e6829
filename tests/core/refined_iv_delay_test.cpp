// SPDX-License-Identifier: BSD-3-Clause
// Copyright (C) the ctid authors
// Tests of core/include/ctid/offline/refined_iv_delay.hpp: the delay
// search (grid and Gauss-Newton on td) with SRIVC inside recovers a known
// delay that is not a multiple of Ts (ZOH and FOH input, an integrating
// plant) from noise-free records simulated independently (delayed_record.hpp:
// matrix exponential on a fine grid on which the delay is whole); with
// the delay fixed it is SRIVC at that delay; the frequency-domain search
// (freq_srivc.hpp) on the exact frequency response of the same system
// finds the same delay and model.
#include "ctid/offline/refined_iv_delay.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <random>
#include <vector>

#include "ctid/offline/freq_srivc.hpp"
#include "delayed_record.hpp"
#include "test_util.hpp"

namespace ctid {
namespace {

using test::binary_input;
using test::make_record;
using test::Record;

const Eigen::VectorXd kF = (Eigen::VectorXd(3) << 1, 1.2, 4).finished();
const Eigen::VectorXd kB = (Eigen::VectorXd(2) << 0.5, 4).finished();
const Eigen::VectorXd kTheta =
    (Eigen::VectorXd(4) << 1.2, 4, 0.5, 4).finished();

RivProblem<double> plant(int nf, int nb, InterSample rule) {
  RivProblem<double> problem;
  problem.nf = {nf};
  RivChannel c;
  c.nb = nb;
  c.rule = rule;
  problem.channels.push_back(c);
  return problem;
}

RivData<double> view(const Record& r, double ts) {
  RivData<double> data;
  data.y = r.y.data();
  data.w = r.u.data();
  data.num_samples = static_cast<Eigen::Index>(r.y.size());
  data.ts = ts;
  return data;
}

// tfsrivc's defaults (TolPar 1e-5 samples, TolFun 1e-8, StepMax one grid
// step) on the grid [0, td_max] of num_td delays.
RivDelaySettings<double> search(double td_max, int num_td) {
  RivDelaySettings<double> s;
  s.search.td_min = 0;
  s.search.td_max = td_max;
  s.search.num_td = num_td;
  s.search.max_iterations = 100;
  s.search.step_tolerance = 1e-5;
  s.search.loss_tolerance = 1e-8;
  s.search.max_step = td_max / (num_td - 1);
  return s;
}

// A delay of 2.35 samples (47 fine steps of 2.5 ms), off the grid of
// whole samples: the grid's best point is a whole sample away at most and
// Gauss-Newton on td reaches the delay and the coefficients.
void expect_fractional_delay(bool foh) {
  const double ts = 0.05;
  const int ratio = 20;
  const double h = ts / ratio;
  const std::vector<double> u = binary_input(1500, 8, 5u);
  const Record r = make_record(kF, kB, u, ratio, h, 47, foh);
  const InterSample rule = foh ? InterSample::kFoh : InterSample::kZoh;
  RivSettings<double> settings;
  RivDelayResult<double> result;
  ASSERT_TRUE(refined_iv_delay(plant(2, 2, rule), settings, view(r, ts),
                               search(0.5, 11), &result)
                  .ok())
      << result.reason;
  EXPECT_TRUE(result.converged) << result.reason;
  EXPECT_TRUE(result.delay_estimated);
  EXPECT_EQ(result.grid.size(), 11u);
  EXPECT_NEAR(result.delay, 47 * h, 1e-6 * ts) << result.reason;
  EXPECT_TRUE(test::MatrixNear(result.theta, kTheta, 1e-5))
      << result.theta.transpose();
  EXPECT_EQ(result.covariance.rows(), 5);
  EXPECT_LT(result.loss, 1e-12);
}

TEST(RefinedIvDelaySearch, FractionalDelayZohIsRecovered) {
  expect_fractional_delay(false);
}

TEST(RefinedIvDelaySearch, FractionalDelayFohIsRecovered) {
  expect_fractional_delay(true);
}

// An integrating plant, 2 / (p (p + 3)) e^(-0.1375 p) (2.75 samples), with
// its integrator declared (f2 fixed at 0): the delay and f1, b recovered.
TEST(RefinedIvDelaySearch, IntegratingPlantWithFractionalDelayIsRecovered) {
  const double ts = 0.05;
  const int ratio = 20;
  const double h = ts / ratio;
  const Eigen::VectorXd f = (Eigen::VectorXd(3) << 1, 3, 0).finished();
  const Eigen::VectorXd b = (Eigen::VectorXd(1) << 2).finished();
  const std::vector<double> u = binary_input(1200, 10, 11u);
  const Record r = make_record(f, b, u, ratio, h, 55, false);
  RivProblem<double> problem = plant(2, 1, InterSample::kZoh);
  problem.fixed = {false, true, false};
  problem.fixed_values = Eigen::VectorXd::Zero(3);
  RivSettings<double> settings;
  RivDelayResult<double> result;
  ASSERT_TRUE(
      refined_iv_delay(problem, settings, view(r, ts), search(0.5, 11), &result)
          .ok())
      << result.reason;
  EXPECT_NEAR(result.delay, 55 * h, 1e-6 * ts) << result.reason;
  EXPECT_NEAR(result.theta(0), 3, 1e-5);
  EXPECT_EQ(result.theta(1), 0);
  EXPECT_NEAR(result.theta(2), 2, 1e-5);
  // no covariance for the fixed coefficient
  EXPECT_EQ(result.covariance.row(1).norm(), 0);
}

// With the delay fixed (no grid, no refinement) the result is SRIVC's at
// that delay, and a grid without refinement keeps its best point, each
// grid loss being SRIVC's simulation-error variance at that delay.
TEST(RefinedIvDelaySearch, FixedDelayAndGridAreSrivcAtThoseDelays) {
  const double ts = 0.05;
  const int ratio = 20;
  const double h = ts / ratio;
  const std::vector<double> u = binary_input(1500, 8, 5u);
  const Record r = make_record(kF, kB, u, ratio, h, 47, false);
  const RivProblem<double> problem = plant(2, 2, InterSample::kZoh);
  RivSettings<double> settings;
  RivDelaySettings<double> fixed = search(0.5, 11);
  fixed.search.grid = false;
  fixed.search.td_start = 0.1;
  fixed.search.refinement = DelayRefinement::kNone;
  RivDelayResult<double> at;
  ASSERT_TRUE(
      refined_iv_delay(problem, settings, view(r, ts), fixed, &at).ok());
  RivProblem<double> delayed = problem;
  delayed.channels[0].delay = 0.1;
  RivResult<double> direct;
  refined_iv(delayed, settings, view(r, ts), &direct);
  EXPECT_EQ(at.delay, 0.1);
  EXPECT_FALSE(at.delay_estimated);
  EXPECT_TRUE(test::MatrixNear(at.theta, direct.theta, 1e-12));
  EXPECT_EQ(at.loss, direct.noise_variance);
  EXPECT_EQ(at.covariance.rows(), 4);

  RivDelaySettings<double> grid = search(0.5, 11);
  grid.search.refinement = DelayRefinement::kNone;
  RivDelayResult<double> best;
  ASSERT_TRUE(
      refined_iv_delay(problem, settings, view(r, ts), grid, &best).ok());
  ASSERT_EQ(best.grid.size(), 11u);
  std::size_t k = 0;
  for (std::size_t i = 1; i < best.grid_loss.size(); ++i)
    if (best.grid_loss[i] < best.grid_loss[k]) k = i;
  EXPECT_EQ(best.delay, best.grid[k]);
  EXPECT_NEAR(best.delay, 0.1, 1e-12);  // the grid point nearest 0.1175
  for (std::size_t i : {std::size_t(0), std::size_t(4)}) {
    delayed.channels[0].delay = best.grid[i];
    refined_iv(delayed, settings, view(r, ts), &direct);
    EXPECT_EQ(best.grid_loss[i], direct.noise_variance) << i;
  }
}

// A delay beyond the grid's upper end: with extend_limit the grid grows
// while its minimum lies at the end, and the delay is found.
TEST(RefinedIvDelaySearch, GridIsExtendedPastAnUnderestimatedTdMax) {
  const double ts = 0.05;
  const int ratio = 20;
  const double h = ts / ratio;
  const std::vector<double> u = binary_input(1500, 8, 5u);
  const Record r = make_record(kF, kB, u, ratio, h, 147, false);  // 0.3675 s
  RivDelaySettings<double> s = search(0.2, 5);
  s.search.extend_limit = 10;
  RivSettings<double> settings;
  RivDelayResult<double> result;
  ASSERT_TRUE(refined_iv_delay(plant(2, 2, InterSample::kZoh), settings,
                               view(r, ts), s, &result)
                  .ok())
      << result.reason;
  EXPECT_GT(result.td_max, 0.3675);
  EXPECT_GT(result.grid.size(), 5u);
  EXPECT_NEAR(result.delay, 147 * h, 1e-6 * ts);
}

// The time-domain search on a sampled record and the frequency-domain one
// on the exact frequency response G(jw) of the same system find the same
// delay and coefficients (both the truth).
TEST(RefinedIvDelaySearch, TimeAndFrequencyDomainSearchesAgree) {
  const double ts = 0.05;
  const int ratio = 20;
  const double h = ts / ratio;
  const double td = 148 * h;  // 0.37 s, 7.4 samples
  const std::vector<double> u = binary_input(2000, 8, 7u);
  const Record r = make_record(kF, kB, u, ratio, h, 148, false);
  RivSettings<double> settings;
  RivDelayResult<double> time;
  ASSERT_TRUE(refined_iv_delay(plant(2, 2, InterSample::kZoh), settings,
                               view(r, ts), search(1, 21), &time)
                  .ok())
      << time.reason;

  std::vector<double> w;
  std::vector<std::complex<double>> g;
  for (int k = 0; k < 60; ++k) {
    const double wk = 0.1 * std::pow(100.0, k / 59.0);
    const std::complex<double> s(0, wk);
    w.push_back(wk);
    g.push_back((0.5 * s + 4.0) / (s * s + 1.2 * s + 4.0) *
                std::exp(std::complex<double>(0, -wk * td)));
  }
  FreqData<double> data;
  data.w = w.data();
  data.y = g.data();
  data.num_frequencies = 60;
  FreqSettings<double> fs;
  fs.na = 2;
  fs.nb = 2;
  fs.estimate_delay = true;
  fs.td_min = 0;
  fs.td_max = 1;
  fs.num_td = 21;
  FreqResult<double> freq;
  ASSERT_TRUE(freq_srivc(fs, data, &freq).ok()) << freq.reason;
  EXPECT_NEAR(time.delay, freq.delay, 1e-6 * ts);
  EXPECT_NEAR(freq.delay, td, 1e-6 * ts);
  Eigen::VectorXd ft(4);
  ft << freq.a, freq.b;
  EXPECT_TRUE(test::MatrixNear(time.theta, ft, 1e-5))
      << time.theta.transpose() << " | " << ft.transpose();
}

// RIVC inside the search (a noise model): the record of the same system
// with a delay of 2.35 samples plus AR(1) noise e / (1 - 0.9 q^-1), e white
// with sd 0.05. The delay is found within four of its reported standard
// deviations, which are below a quarter of a sample (the grid step is one
// sample), and the loss kept is the innovation variance, near 0.05^2.
TEST(RefinedIvDelaySearch, DelayWithANoiseModelIsFound) {
  const double ts = 0.05;
  const int ratio = 20;
  const double h = ts / ratio;
  const std::vector<double> u = binary_input(2000, 8, 5u);
  Record r = make_record(kF, kB, u, ratio, h, 47, false);
  std::mt19937 rng(5);
  std::normal_distribution<double> white(0, 0.05);
  double v = 0;
  for (double& y : r.y) {
    v = 0.9 * v + white(rng);
    y += v;
  }
  RivDelaySettings<double> s = search(0.5, 11);
  s.noise_model = true;
  s.nd = 1;
  s.nc = 0;
  RivSettings<double> settings;
  RivDelayResult<double> result;
  ASSERT_TRUE(refined_iv_delay(plant(2, 2, InterSample::kZoh), settings,
                               view(r, ts), s, &result)
                  .ok())
      << result.reason;
  ASSERT_EQ(result.covariance.rows(), 5);
  const double sd = std::sqrt(result.covariance(4, 4));
  EXPECT_LT(sd, 0.25 * ts);
  EXPECT_LT(std::abs(result.delay - 47 * h), 4 * sd) << result.reason;
  EXPECT_EQ(result.loss, result.rivc.noise.innovation_variance);
  EXPECT_NEAR(result.loss, 0.05 * 0.05, 0.2 * 0.05 * 0.05);
  EXPECT_NEAR(result.rivc.noise.d(1), -0.9, 0.05);
}

TEST(RefinedIvDelaySearch, BadProblemsAreRejected) {
  const double ts = 0.05;
  const std::vector<double> u = binary_input(200, 8, 5u);
  const Record r = make_record(kF, kB, u, 1, ts, 2, false);
  RivSettings<double> settings;
  RivDelayResult<double> result;
  RivDelaySettings<double> s = search(0.5, 11);
  s.search.td_max = -1;
  EXPECT_EQ(refined_iv_delay(plant(2, 2, InterSample::kZoh), settings,
                             view(r, ts), s, &result)
                .code(),
            ErrorCode::kBadOption);
  s = search(0.5, 11);
  s.search.step_reduction = 1;
  EXPECT_EQ(refined_iv_delay(plant(2, 2, InterSample::kZoh), settings,
                             view(r, ts), s, &result)
                .code(),
            ErrorCode::kBadOption);
  RivProblem<double> two = plant(2, 2, InterSample::kZoh);
  two.output_offset = true;
  EXPECT_EQ(
      refined_iv_delay(two, settings, view(r, ts), search(0.5, 11), &result)
          .code(),
      ErrorCode::kNotSupported);
  EXPECT_EQ(refined_iv_delay(plant(2, 2, InterSample::kZoh), settings,
                             view(r, ts), search(0.5, 11),
                             static_cast<RivDelayResult<double>*>(nullptr))
                .code(),
            ErrorCode::kBadInput);
}

}  // namespace
}  // namespace ctid
