// SPDX-License-Identifier: BSD-3-Clause
// Copyright (C) the ctid authors
// Tests of core/include/ctid/offline/freq_srivc_options.hpp: the defaults
// the table shows are FreqSettings', a config set by name gives the
// settings written by hand and the same estimate to the last bit (and
// the transfer function of the noise-free data), several inputs give one
// channel each, and orders or delays without one entry per input are a
// dimension mismatch.
#include "ctid/offline/freq_srivc_options.hpp"

#include <gtest/gtest.h>

#include <complex>
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

}  // namespace
}  // namespace ctid
