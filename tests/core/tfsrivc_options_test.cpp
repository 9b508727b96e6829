// SPDX-License-Identifier: BSD-3-Clause
// Copyright (C) the ctid authors
// Tests of core/include/ctid/offline/tfsrivc_options.hpp: the defaults the
// table shows are TfsrivcConfig's member initialisers (CONTSID's tfsrivc
// defaults), a value set by name lands in its field, validate() refuses
// each range it states, and a step reduction r > 1 divides the step.
#include "ctid/offline/tfsrivc_options.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

namespace ctid {
namespace {

TEST(TfsrivcOptions, DefaultsAreTheConfigs) {
  const auto& table = tfsrivc_options<double>();
  const TfsrivcConfig<double> config;
  const auto shown = [&](const char* name) {
    const auto* decl = find_option(table, name);
    EXPECT_NE(decl, nullptr) << name;
    return decl == nullptr ? std::string() : option_default(*decl);
  };
  EXPECT_EQ(std::stod(shown("numtd")), config.num_td);
  EXPECT_EQ(std::stod(shown("maxiter")), config.max_iterations);
  EXPECT_EQ(std::stod(shown("tolpar")), config.tol_par);
  EXPECT_EQ(std::stod(shown("tolfun")), config.tol_fun);
  EXPECT_EQ(std::stod(shown("stepreduction")), config.step_reduction);
  EXPECT_EQ(std::stod(shown("focusorder")), config.focus_order);
  EXPECT_EQ(shown("fixtd"), "false");
  EXPECT_EQ(shown("integration"), "false");
  // CONTSID's documented values, tolerances tightened
  EXPECT_EQ(config.num_td, 50);
  EXPECT_EQ(config.max_iterations, 100);
  EXPECT_EQ(config.tol_par, 1e-5);
  EXPECT_EQ(config.tol_fun, 1e-8);
  EXPECT_EQ(config.focus_order, 5);
  // TdMax left out: the data's (delay_search_defaults.hpp), valid as such
  EXPECT_TRUE(std::isnan(config.td_max));
  EXPECT_EQ(shown("tdmax"), "(from the input-output cross-correlation)");
  EXPECT_TRUE(validate(config).ok());
  OptionValue v;
  TfsrivcConfig<double> c;
  EXPECT_EQ(set_option(table, "not_an_option", v, &c).code(),
            ErrorCode::kBadOption);
}

TEST(TfsrivcOptions, SetByNameAndValidated) {
  const auto& table = tfsrivc_options<double>();
  TfsrivcConfig<double> c;
  c.td_max = 1;
  EXPECT_TRUE(validate(c).ok());
  OptionValue v;
  v.real = 0.25;
  ASSERT_TRUE(set_option(table, "stepmax", v, &c).ok());
  EXPECT_EQ(c.step_max, 0.25);
  v.real = 0;
  EXPECT_EQ(set_option(table, "stepmax", v, &c).code(), ErrorCode::kBadOption);
  EXPECT_EQ(set_option(table, "lambda", v, &c).code(), ErrorCode::kBadOption);

  const auto refused = [](void (*change)(TfsrivcConfig<double>*)) {
    TfsrivcConfig<double> bad;
    bad.td_max = 1;
    change(&bad);
    return validate(bad).code() == ErrorCode::kBadOption;
  };
  EXPECT_TRUE(refused([](TfsrivcConfig<double>* b) { b->td_min = -1; }));
  EXPECT_TRUE(refused([](TfsrivcConfig<double>* b) { b->td_min = 2; }));
  EXPECT_TRUE(refused([](TfsrivcConfig<double>* b) { b->num_td = 0; }));
  EXPECT_TRUE(refused([](TfsrivcConfig<double>* b) { b->max_iterations = 0; }));
  EXPECT_TRUE(refused([](TfsrivcConfig<double>* b) { b->tol_par = 0; }));
  EXPECT_TRUE(refused([](TfsrivcConfig<double>* b) { b->tol_fun = -1; }));
  EXPECT_TRUE(refused([](TfsrivcConfig<double>* b) { b->step_reduction = 1; }));
  EXPECT_TRUE(refused([](TfsrivcConfig<double>* b) { b->step_reduction = 0; }));
  EXPECT_TRUE(refused([](TfsrivcConfig<double>* b) { b->focus_order = 11; }));
}

TEST(TfsrivcOptions, StepReductionAboveOneDivides) {
  TfsrivcConfig<double> c;
  EXPECT_EQ(c.step_factor(), 0.5);
  c.step_reduction = 0.25;
  EXPECT_EQ(c.step_factor(), 0.25);
}

}  // namespace
}  // namespace ctid
