// SPDX-License-Identifier: BSD-3-Clause
// Copyright (C) the ctid authors
// Tests of core/include/ctid/offline/freq_srivc_options.hpp: the defaults
// the table shows are FreqSettings', a config set by name gives the
// settings written by hand and the same estimate to the last bit (and
// the transfer function of the noise-free data), several inputs give one
// channel each, and orders or delays without one entry per input are a
// dimension mismatch. freq_fit_data: the fit on data with rows of zero
// input and frequencies outside the Focus band is the fit on the data
// without them, and the delay range's defaults follow their rule.
#include "ctid/offline/freq_srivc_options.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <limits>
#include <string>
#include <vector>

namespace ctid {
namespace {

using C = std::complex<double>;

TEST(FreqSrivcOptions, DefaultsAreTheSettings) {
  const auto& table = freq_srivc_options<double>();
  const FreqSettings<double> settings;
  const auto shown = [&](const char* name) {
    const auto* decl = find_option(table, name);
    EXPECT_NE(decl, nullptr) << name;
    return decl == nullptr ? std::string() : option_default(*decl);
  };
  EXPECT_EQ(std::stod(shown("maxiter")), settings.max_iterations);
  EXPECT_EQ(std::stod(shown("tol")), settings.tolerance);
  EXPECT_EQ(std::stod(shown("num_td")), settings.num_td);
  EXPECT_EQ(shown("grid"), settings.grid ? "true" : "false");
  EXPECT_EQ(shown("output_error"), settings.output_error ? "true" : "false");
  OptionValue v;
  FreqConfig<double> config;
  EXPECT_EQ(set_option(table, "not_an_option", v, &config).code(),
            ErrorCode::kBadOption);
}

TEST(FreqSrivcOptions, ConfigByNameGivesTheSameEstimate) {
  // G(s) = 2 / (s^2 + 1.2 s + 1) e^(-0.3 s) on 40 frequencies.
  std::vector<double> w;
  std::vector<C> g;
  for (int k = 0; k < 40; ++k) {
    const double wk = 0.1 * std::pow(100.0, k / 39.0);
    const C s(0, wk);
    w.push_back(wk);
    g.push_back(2.0 / (s * s + 1.2 * s + 1.0) * std::exp(-0.3 * s));
  }
  FreqData<double> data;
  data.w = w.data();
  data.y = g.data();
  data.num_frequencies = static_cast<Eigen::Index>(w.size());
  const auto& table = freq_srivc_options<double>();
  FreqConfig<double> config;
  OptionValue v;
  v.integers = {2};
  ASSERT_TRUE(set_option(table, "na", v, &config).ok());
  v.integers = {1};
  ASSERT_TRUE(set_option(table, "nb", v, &config).ok());
  v.matrix = Matrix<double>::Constant(1, 1, 0.3);
  ASSERT_TRUE(set_option(table, "delay", v, &config).ok());
  v.flag = true;
  ASSERT_TRUE(set_option(table, "output_error", v, &config).ok());
  v.integer = 30;
  ASSERT_TRUE(set_option(table, "maxiter", v, &config).ok());
  FreqSettings<double> by_name;
  ASSERT_TRUE(freq_settings(config, 1, &by_name).ok());
  FreqSettings<double> by_hand;
  by_hand.na = 2;
  by_hand.nb = 1;
  by_hand.delay = 0.3;
  by_hand.output_error = true;
  by_hand.max_iterations = 30;
  FreqResult<double> a, b;
  ASSERT_TRUE(freq_srivc(by_name, data, &a).ok());
  ASSERT_TRUE(freq_srivc(by_hand, data, &b).ok());
  EXPECT_EQ(a.a, b.a);
  EXPECT_EQ(a.b, b.b);
  EXPECT_NEAR(a.a(0), 1.2, 1e-8);
  EXPECT_NEAR(a.a(1), 1.0, 1e-8);
  EXPECT_NEAR(a.b(0), 2.0, 1e-8);
  EXPECT_TRUE(by_name.inputs.empty());
  // two inputs: one channel each; the wrong number of entries is refused
  FreqSettings<double> two;
  EXPECT_EQ(freq_settings(config, 2, &two).code(),
            ErrorCode::kDimensionMismatch);
  v.integers = {2, 1};
  ASSERT_TRUE(set_option(table, "na", v, &config).ok());
  v.integers = {1, 1};
  ASSERT_TRUE(set_option(table, "nb", v, &config).ok());
  v.matrix = Matrix<double>::Zero(2, 1);
  ASSERT_TRUE(set_option(table, "delay", v, &config).ok());
  ASSERT_TRUE(freq_settings(config, 2, &two).ok());
  ASSERT_EQ(two.inputs.size(), 2u);
  EXPECT_EQ(two.inputs[1].na, 1);
  v.integers = {2, 2000};
  ASSERT_TRUE(set_option(table, "na", v, &config).ok());
  EXPECT_EQ(freq_settings(config, 2, &two).code(), ErrorCode::kBadInput);
}

// G(s) = 2 / (s^2 + 1.2 s + 1) e^(-0.3 s) at w.
std::vector<C> plant_response(const std::vector<double>& w) {
  std::vector<C> g;
  for (double wk : w) {
    const C s(0, wk);
    g.push_back(2.0 / (s * s + 1.2 * s + 1.0) * std::exp(-0.3 * s));
  }
  return g;
}

// Rows of zero input and frequencies outside the band are left out: the
// estimate equals the one on the data written without them, to the last
// bit; a non-finite value in a row left out is no error, in a row used it
// is; a band that holds no frequency is a bad option.
TEST(FreqSrivcOptions, FitDataLeavesOutZeroInputsAndTheBand) {
  std::vector<double> w;
  for (int k = 0; k < 60; ++k) w.push_back(0.1 * std::pow(100.0, k / 59.0));
  const std::vector<C> g = plant_response(w);
  std::vector<C> y, u;
  std::vector<double> w_kept;
  std::vector<C> y_kept, u_kept;
  const double band[2] = {0.3, 4.0};
  for (std::size_t k = 0; k < w.size(); ++k) {
    const C uk = k % 4 == 1 ? C(0) : C(1.0 + 0.1 * k, -0.5);
    u.push_back(uk);
    y.push_back(uk == C(0) ? C(std::numeric_limits<double>::quiet_NaN())
                           : g[k] * uk);
    if (uk != C(0) && w[k] >= band[0] && w[k] <= band[1]) {
      w_kept.push_back(w[k]);
      y_kept.push_back(y.back());
      u_kept.push_back(uk);
    }
  }
  FreqConfig<double> config;
  config.na = {2};
  config.nb = {1};
  config.delay = {0.3};
  config.band = {band[0], band[1]};
  FreqFitData<double> used;
  FreqSettings<double> s;
  ASSERT_TRUE(freq_fit_data(config, w.data(), y.data(), u.data(),
                            static_cast<Eigen::Index>(w.size()), 1, &used, &s)
                  .ok());
  ASSERT_EQ(used.w, w_kept);
  ASSERT_EQ(used.y, y_kept);
  ASSERT_EQ(used.u, u_kept);
  FreqData<double> by_hand;
  by_hand.w = w_kept.data();
  by_hand.y = y_kept.data();
  by_hand.u = u_kept.data();
  by_hand.num_frequencies = static_cast<Eigen::Index>(w_kept.size());
  FreqResult<double> a, b;
  ASSERT_TRUE(freq_srivc(s, used.view(), &a).ok());
  ASSERT_TRUE(freq_srivc(s, by_hand, &b).ok());
  EXPECT_EQ(a.a, b.a);
  EXPECT_EQ(a.b, b.b);
  EXPECT_NEAR(a.a(0), 1.2, 1e-8);
  EXPECT_NEAR(a.b(0), 2.0, 1e-8);

  std::vector<C> y_bad = y;
  y_bad[2] = C(std::numeric_limits<double>::infinity());  // a row used
  EXPECT_EQ(freq_fit_data(config, w.data(), y_bad.data(), u.data(),
                          static_cast<Eigen::Index>(w.size()), 1, &used, &s)
                .code(),
            ErrorCode::kBadInput);
  config.band = {500, 600};
  EXPECT_EQ(freq_fit_data(config, w.data(), y.data(), u.data(),
                          static_cast<Eigen::Index>(w.size()), 1, &used, &s)
                .code(),
            ErrorCode::kBadOption);
}

// The estimated delay's range: td_max half the period of periodic data,
// else pi over the median positive frequency used (w = 0 not counted), a
// start delay outside the range widens it; the given td_max is kept.
TEST(FreqSrivcOptions, FitDataDelayRange) {
  const std::vector<double> w = {0, 1, 2, 4, 8, 16};
  const std::vector<C> y = plant_response(w);
  FreqConfig<double> config;
  config.na = {2};
  config.nb = {1};
  config.settings.estimate_delay = true;
  FreqFitData<double> used;
  FreqSettings<double> s;
  const auto run = [&]() {
    return freq_fit_data(config, w.data(), y.data(),
                         static_cast<const C*>(nullptr), 6, 1, &used, &s);
  };
  ASSERT_TRUE(run().ok());
  EXPECT_EQ(s.td_max, M_PI / 4);  // median of 1 2 4 8 16
  config.band = {0, 3};           // 0 1 2 used: median of 1 2
  ASSERT_TRUE(run().ok());
  EXPECT_EQ(s.td_max, M_PI / 1.5);
  config.band.clear();
  config.period = 5;
  ASSERT_TRUE(run().ok());
  EXPECT_EQ(s.td_max, 2.5);
  config.delay = {3.5};  // a start beyond the range widens it
  config.settings.td_min = 0.5;
  ASSERT_TRUE(run().ok());
  EXPECT_EQ(s.td_max, 3.5);
  EXPECT_EQ(s.td_min, 0.5);
  config.td_max = 7;
  ASSERT_TRUE(run().ok());
  EXPECT_EQ(s.td_max, 7);
  config.td_max = 0.25;  // below TdMin
  EXPECT_EQ(run().code(), ErrorCode::kBadOption);
  config.td_max = std::numeric_limits<double>::quiet_NaN();
  config.settings.td_min = -1;
  EXPECT_EQ(run().code(), ErrorCode::kBadOption);
  // not estimated: no range is read
  config.settings.estimate_delay = false;
  ASSERT_TRUE(run().ok());
}

}  // namespace
}  // namespace ctid
