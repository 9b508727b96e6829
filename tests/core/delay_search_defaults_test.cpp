// SPDX-License-Identifier: BSD-3-Clause
// Copyright (C) the ctid authors
// Tests of core/include/ctid/offline/delay_search_defaults.hpp: the
// cross-correlation TdMax finds the lag of an output that is the input
// delayed by a known number of samples, its bounds (a tenth of the record
// or 50 intervals below, half the record above) hold, irregular instants
// that only add samples on the regular grid's segments give the regular
// record's value, and the range keeps what is given and fills in the rest
// by the stated rule.
#include "ctid/offline/delay_search_defaults.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

namespace ctid {
namespace {

// u: a random binary sequence held for `clock` samples; y(k) = u(k - lag).
struct DelayedRecord {
  std::vector<double> u, y;
  RecordView<double> view(double ts) const {
    RecordView<double> r;
    r.y = y.data();
    r.u = u.data();
    r.num_samples = static_cast<Eigen::Index>(y.size());
    r.num_inputs = 1;
    r.ts = ts;
    return r;
  }
};

DelayedRecord delayed(int n, int lag, int clock, unsigned seed) {
  std::mt19937 gen(seed);
  std::bernoulli_distribution coin(0.5);
  DelayedRecord d;
  d.u.resize(n);
  d.y.assign(n, 0);
  double level = 1;
  for (int k = 0; k < n; ++k) {
    if (k % clock == 0) level = coin(gen) ? 1 : -1;
    d.u[k] = level;
  }
  for (int k = lag; k < n; ++k) d.y[k] = d.u[k - lag];
  return d;
}

TEST(DelaySearchDefaults, CrossCorrelationFindsTheLag) {
  const double ts = 0.01;
  const int n = 4000;
  for (int lag : {0, 37, 120, 333}) {
    const DelayedRecord d = delayed(n, lag, 1, 3u + lag);
    const double span = ts * (n - 1);
    const double expected =
        std::max(std::min(span / 10, 50 * ts), (lag + 10) * ts);
    EXPECT_NEAR(default_td_max(d.view(ts)), expected, 1e-12) << lag;
  }
}

TEST(DelaySearchDefaults, BoundsHold) {
  const double ts = 0.5;
  // a short record: the lower bound min(T/10, 50 ts) = T/10 wins
  const DelayedRecord a = delayed(200, 2, 1, 7u);
  EXPECT_NEAR(default_td_max(a.view(ts)), ts * 199 / 10, 1e-12);
  // a lag beyond half the record is out of the search: at most T/2
  const DelayedRecord b = delayed(101, 49, 1, 9u);
  EXPECT_LE(default_td_max(b.view(ts)), ts * 100 / 2 + 1e-12);
  // fewer than 4 samples: the lower bound
  const DelayedRecord c = delayed(3, 0, 1, 1u);
  EXPECT_NEAR(default_td_max(c.view(ts)), std::min(ts * 2 / 10, 50 * ts),
              1e-15);
}

// Samples added inside some intervals (fewer than half: the median
// interval stays ts) with u held and y on the line between its neighbours
// put the record back on its regular grid unchanged.
TEST(DelaySearchDefaults, IrregularInstantsOnTheRegularGrid) {
  const double ts = 0.02;
  const int n = 1500;
  const DelayedRecord d = delayed(n, 61, 3, 11u);
  std::vector<double> t, y, u;
  for (int k = 0; k < n; ++k) {
    t.push_back(k * ts);
    y.push_back(d.y[k]);
    u.push_back(d.u[k]);
    if (k + 1 < n && k % 5 == 2) {
      const double a = 0.3;
      t.push_back((k + a) * ts);
      y.push_back((1 - a) * d.y[k] + a * d.y[k + 1]);
      u.push_back(d.u[k]);
    }
  }
  RecordView<double> r;
  r.y = y.data();
  r.u = u.data();
  r.num_samples = static_cast<Eigen::Index>(t.size());
  r.num_inputs = 1;
  r.instants = t.data();
  EXPECT_NEAR(median_sampling_interval(r), ts, 1e-15);
  EXPECT_NEAR(default_td_max(r), default_td_max(d.view(ts)), 1e-12);
  EXPECT_NEAR(default_td_max(r), (61 + 10) * ts, 1e-12);
  // too sparse for a regular grid (one long gap): the lower bound alone
  std::vector<double> t2 = {0, 0.1, 0.2, 0.3, 1000};
  std::vector<double> y2(5, 1.0), u2 = {1, -1, 1, -1, 1};
  RecordView<double> s;
  s.y = y2.data();
  s.u = u2.data();
  s.num_samples = 5;
  s.num_inputs = 1;
  s.instants = t2.data();
  EXPECT_NEAR(default_td_max(s), std::min(1000.0 / 10, 50 * 0.1), 1e-12);
}

TEST(DelaySearchDefaults, RangeKeepsWhatIsGivenAndFillsTheRest) {
  const double ts = 0.01;
  const int n = 4000;
  const DelayedRecord d = delayed(n, 37, 1, 5u);
  const RecordView<double> r = d.view(ts);
  const double half = ts * (n - 1) / 2;
  const double data = default_td_max(r);
  DelayRange<double> out;

  DelayRangeRequest<double> given;
  ASSERT_TRUE(delay_search_range(r, given, &out).ok());
  EXPECT_TRUE(out.td_max_from_data);
  EXPECT_EQ(out.td_max, data);
  EXPECT_EQ(out.extend_limit, half);
  EXPECT_NEAR(out.step_max, std::max(data / 49, ts), 1e-15);

  // at least twice TdMin and twice the start delay, at most half the record
  given.td_min = 0.6;
  given.td_start = 0.9;
  given.num_td = 11;
  ASSERT_TRUE(delay_search_range(r, given, &out).ok());
  EXPECT_EQ(out.td_max, 1.8);
  EXPECT_NEAR(out.step_max, (1.8 - 0.6) / 10, 1e-15);
  given.td_start = 15;
  ASSERT_TRUE(delay_search_range(r, given, &out).ok());
  EXPECT_EQ(out.td_max, half);

  // given values are kept, the grid not extended
  given.td_max = 2.5;
  given.step_max = 0.125;
  ASSERT_TRUE(delay_search_range(r, given, &out).ok());
  EXPECT_FALSE(out.td_max_from_data);
  EXPECT_EQ(out.td_max, 2.5);
  EXPECT_EQ(out.step_max, 0.125);
  EXPECT_EQ(out.extend_limit, 0);
  // a grid spacing below one sampling interval: one interval
  given.step_max = std::numeric_limits<double>::quiet_NaN();
  given.td_min = 0;
  given.td_max = 0.1;
  given.num_td = 50;
  ASSERT_TRUE(delay_search_range(r, given, &out).ok());
  EXPECT_EQ(out.step_max, ts);

  given.td_min = -1;
  EXPECT_EQ(delay_search_range(r, given, &out).code(), ErrorCode::kBadOption);
  given.td_min = 0;
  given.num_td = 0;
  EXPECT_EQ(delay_search_range(r, given, &out).code(), ErrorCode::kBadOption);
  EXPECT_EQ(delay_search_range<double>(r, given, nullptr).code(),
            ErrorCode::kBadInput);
}

}  // namespace
}  // namespace ctid
