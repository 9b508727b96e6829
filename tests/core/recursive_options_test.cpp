// SPDX-License-Identifier: BSD-3-Clause
// Copyright (C) the ctid authors
// The options tables of the recursive estimators: every option declared
// once with a help line and a range; the table's defaults are the config
// structs'; setting options through the table gives the configuration
// (and so the estimates) that setting the members directly gives; bad
// names and words are bad options, bad values are caught by validate().
#include "ctid/recursive/recursive_options.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <set>
#include <string>
#include <vector>

#include "ctid/simulation/ltv_simulator.hpp"
#include "test_util.hpp"

namespace ctid {
namespace {

OptionValue real(double v) {
  OptionValue value;
  value.real = v;
  return value;
}
OptionValue word(const char* w) {
  OptionValue value;
  value.word = w;
  return value;
}
OptionValue matrix(const Eigen::MatrixXd& m) {
  OptionValue value;
  value.matrix = m;
  return value;
}
OptionValue integers(std::vector<int> v) {
  OptionValue value;
  value.integers = std::move(v);
  return value;
}
OptionValue integer(int v) {
  OptionValue value;
  value.integer = v;
  return value;
}

template <typename Config>
void expect_well_formed(const OptionTable<Config>& table) {
  std::set<std::string> names;
  for (const auto& decl : table) {
    EXPECT_TRUE(names.insert(decl.name).second) << decl.name << " twice";
    EXPECT_GT(std::string(decl.help).size(), 10u) << decl.name;
    EXPECT_FALSE(std::string(decl.range).empty()) << decl.name;
    EXPECT_EQ(decl.type == OptionType::kChoice, !decl.choices.empty())
        << decl.name;
    EXPECT_FALSE(option_default(decl).empty()) << decl.name;
  }
}

TEST(RecursiveOptions, TablesAreWellFormed) {
  expect_well_formed(rlssvf_options<double>());
  expect_well_formed(recursive_iv_options<double>());
  expect_well_formed(recursive_iv_options<float>());
}

// The defaults the table reports are the config structs' members.
TEST(RecursiveOptions, DefaultsAreTheConfigStructs) {
  const auto& iv = recursive_iv_options<double>();
  const RecursiveIvConfig<double> c;
  EXPECT_EQ(option_default(*find_option(iv, "antiwindup_lambda")),
            options_detail::number(c.antiwindup_lambda));
  EXPECT_EQ(std::stod(option_default(*find_option(iv, "antiwindup_lambda"))),
            0.998);
  EXPECT_EQ(option_default(*find_option(iv, "stability")), "keep");
  EXPECT_EQ(option_default(*find_option(iv, "prefilter")), "unit");
  EXPECT_EQ(option_default(*find_option(iv, "method")), "rsrivc");
  EXPECT_EQ(option_default(*find_option(iv, "adm")), "ff");
  EXPECT_EQ(option_default(*find_option(iv, "adg")), "1");
  EXPECT_EQ(option_default(*find_option(iv, "covariance_guard")), "true");
  EXPECT_EQ(option_default(*find_option(iv, "intersample")), "zoh");
  const auto& ls = rlssvf_options<double>();
  EXPECT_EQ(option_default(*find_option(ls, "form")), "standard");
  EXPECT_EQ(option_default(*find_option(ls, "ic")), "false");
}

// Each choice word set through the table reads back (aliases aside).
TEST(RecursiveOptions, ChoicesReadBack) {
  const auto& iv = recursive_iv_options<double>();
  for (const auto& decl : iv) {
    if (decl.type != OptionType::kChoice) continue;
    for (const char* w : decl.choices) {
      if (std::string(w) == "normalized") continue;  // alias of normalised
      RecursiveIvConfig<double> c;
      ASSERT_TRUE(set_option(iv, decl.name, word(w), &c).ok());
      EXPECT_EQ(decl.show(c), w) << decl.name;
    }
  }
}

struct Data {
  std::vector<double> u, y;
};

// (p^2 + 2.4 p + 4) x = 4 u from a binary input, plus white noise.
Data make_data(int n, double ts) {
  Data d;
  std::mt19937 rng(3);
  std::normal_distribution<double> normal;
  d.u.resize(n);
  double level = 1;
  for (int k = 0; k < n; ++k) {
    if (k % 20 == 0) level = (rng() & 1) ? 1.0 : -1.0;
    d.u[k] = level;
  }
  Eigen::VectorXd num(1), den(3);
  num << 4;
  den << 1, 2.4, 4;
  d.y = test::simulate_zoh(num, den, d.u, ts);
  for (auto& v : d.y) v += 0.05 * normal(rng);
  return d;
}

Eigen::MatrixXd run(const RecursiveIvConfig<double>& config, const Data& d,
                    double ts) {
  RecordView<double> record;
  record.y = d.y.data();
  record.u = d.u.data();
  record.num_samples = d.y.size();
  record.num_inputs = 1;
  record.ts = ts;
  Eigen::MatrixXd thm(d.y.size(), 3);
  RecursiveOutputs<double> out;
  out.thm = thm.data();
  const Status status = run_recursive_iv(config, record, {}, out);
  EXPECT_TRUE(status.ok()) << status.message();
  return thm;
}

// Setting every kind of option through the table and setting the members
// directly give the same estimates, sample by sample.
TEST(RecursiveOptions, TableSetsTheMembersItNames) {
  const double ts = 0.05;
  const Data d = make_data(3000, ts);
  RecursiveIvConfig<double> direct;
  direct.orders.na = 2;
  direct.orders.nb = {1};
  direct.orders.nk = {0};
  direct.svf.lambda_svf = 2.5;
  direct.svf.u_intersample = InterSample::kFoh;
  direct.adaptation =
      KalmanAdaptation<double>(1e-6 * Eigen::Matrix3d::Identity());
  direct.method = IvMethod::kRivsvf;
  direct.t_s_iv = 30;
  direct.dtupdate = 0.5;
  direct.stability = StabilityPolicy::kReflect;
  direct.prefilter_gain = PrefilterGain::kMonic;
  direct.theta0 = Eigen::Vector3d(1, 2, 1);
  direct.P0 = 100 * Eigen::Matrix3d::Identity();
  direct.antiwindup_gamma = 1e6;
  direct.antiwindup_lambda = 0.99;

  const auto& t = recursive_iv_options<double>();
  RecursiveIvConfig<double> via;
  const std::vector<std::pair<const char*, OptionValue>> given = {
      {"na", integer(2)},
      {"nb", integers({1})},
      {"nk", integers({0})},
      {"lambda_svf", real(2.5)},
      {"intersample", word("foh")},
      {"adm", word("kf")},
      {"adg", matrix(1e-6 * Eigen::Matrix3d::Identity())},
      {"method", word("rivsvf")},
      {"tsiv", real(30)},
      {"dtupdate", real(0.5)},
      {"stability", word("reflect")},
      {"prefilter", word("monic")},
      {"th0", matrix(Eigen::Vector3d(1, 2, 1))},
      {"P0", matrix(100 * Eigen::Matrix3d::Identity())},
      {"antiwindup", real(1e6)},
      {"antiwindup_lambda", real(0.99)}};
  for (const auto& [name, value] : given) {
    ASSERT_TRUE(set_option(t, name, value, &via).ok()) << name;
  }
  ASSERT_TRUE(validate(via).ok()) << validate(via).message();
  const Eigen::MatrixXd a = run(direct, d, ts);
  const Eigen::MatrixXd b = run(via, d, ts);
  EXPECT_TRUE(test::MatrixNear(b, a, 0.0));
  // and the options do change the run: the defaults give other estimates
  RecursiveIvConfig<double> plain;
  plain.orders = direct.orders;
  plain.svf.lambda_svf = 2.5;
  EXPECT_FALSE(test::MatrixNear(run(plain, d, ts), a, 1e-6));
}

TEST(RecursiveOptions, BadNamesWordsAndValues) {
  const auto& t = recursive_iv_options<double>();
  RecursiveIvConfig<double> c;
  EXPECT_EQ(set_option(t, "lambda", real(1), &c).code(),
            ErrorCode::kBadOption);
  EXPECT_EQ(set_option(t, "stability", word("maybe"), &c).code(),
            ErrorCode::kBadOption);
  // adg with the forgetting factor is one number
  EXPECT_EQ(set_option(t, "adg", matrix(Eigen::Matrix2d::Identity()), &c)
                .code(),
            ErrorCode::kBadInput);
  // ranges: checked by validate() once everything is set
  RecursiveIvConfig<double> r;
  r.orders.na = 2;
  r.orders.nb = {1};
  r.orders.nk = {0};
  r.svf.lambda_svf = 3;
  ASSERT_TRUE(validate(r).ok());
  for (const auto& [name, v] :
       std::vector<std::pair<const char*, double>>{{"antiwindup_lambda", 1.5},
                                                   {"tsiv", -1},
                                                   {"dtupdate", NAN},
                                                   {"lambda_svf", 0},
                                                   {"gap_settle", -2}}) {
    RecursiveIvConfig<double> bad = r;
    if (std::string(name) == "antiwindup_lambda") bad.antiwindup_gamma = 100;
    ASSERT_TRUE(set_option(t, name, real(v), &bad).ok()) << name;
    EXPECT_FALSE(validate(bad).ok()) << name;
  }
  RecursiveIvConfig<double> kf = r;
  ASSERT_TRUE(set_option(t, "adm", word("kf"), &kf).ok());
  ASSERT_TRUE(set_option(t, "adg", matrix(Eigen::Matrix2d::Identity()), &kf)
                  .ok());
  EXPECT_EQ(validate(kf).code(), ErrorCode::kDimensionMismatch);
}

}  // namespace
}  // namespace ctid
