// SPDX-License-Identifier: BSD-3-Clause
// Copyright (C) the ctid authors
// Tests of core/include/ctid/offline/relay_frequency_data.hpp: the
// harmonics of a limit cycle against a direct DFT sum, the held input's
// spectrum against the integral of the held signal (a fine quadrature),
// the harmonics a square wave does not have left out, and a record
// without two whole periods refused.
#include "ctid/offline/relay_frequency_data.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <vector>

namespace ctid {
namespace {

using C = std::complex<double>;
const double kPi = std::acos(-1.0);

// A relay-like record: a square wave of `period` samples (high for
// `high` of them) after `lead` samples at the low level, and an output
// that is a smooth function of time.
struct Cycle {
  std::vector<double> y, u;
};

Cycle square_cycle(int lead, int period, int high, int cycles) {
  Cycle r;
  const int n = lead + period * cycles + 7;
  for (int k = 0; k < n; ++k) {
    const int phase = k < lead ? -1 : (k - lead) % period;
    r.u.push_back(phase >= 0 && phase < high ? 1.0 : -0.5);
    r.y.push_back(std::sin(0.3 * k) + 0.2 * std::cos(1.1 * k + 0.4));
  }
  return r;
}

C direct_dft(const std::vector<double>& x, int first, int m, int bin) {
  C sum = 0;
  for (int k = 0; k < m; ++k) {
    sum += x[first + k] * std::polar(1.0, -2 * kPi * bin * k / m);
  }
  return sum;
}

TEST(RelayFrequencyData, HarmonicsAreTheDftOfTheWholePeriods) {
  const int lead = 5, period = 40, cycles = 6;
  const Cycle rec = square_cycle(lead, period, 13, cycles);
  const double ts = 0.02;
  for (const bool mean : {false, true}) {
    RelayFrequencyData<double> d;
    const Status st = relay_frequency_data(
        rec.y.data(), rec.u.data(), static_cast<Eigen::Index>(rec.u.size()), ts,
        mean, &d);
    ASSERT_TRUE(st.ok()) << st.message();
    // Upward crossings at lead, lead + period, .., lead + cycles period:
    // the window holds the cycles whole periods between the first and the
    // last.
    const int c = cycles, m = c * period;
    EXPECT_NEAR(d.period, period * ts, 1e-15);
    ASSERT_FALSE(d.w.empty());
    // the mean (r = 0) is not negligible: 13 of 40 samples high
    EXPECT_EQ(d.w[0], 0.0);
    for (std::size_t i = 0; i < d.w.size(); ++i) {
      const double r = d.w[i] * m * ts / (2 * kPi);
      const int bin = static_cast<int>(std::lround(r));
      EXPECT_NEAR(r, bin, 1e-9);
      EXPECT_EQ(bin % c, 0);
      EXPECT_LE(bin, m / 4);
      const C h =
          bin == 0 ? C(1)
                   : (1.0 - std::exp(C(0, -d.w[i] * ts))) / C(0, d.w[i] * ts);
      const C ud = direct_dft(rec.u, lead, m, bin);
      const C yd = direct_dft(rec.y, lead, m, bin);
      EXPECT_LT(std::abs(d.u[i] - ud * h), 1e-10 * std::abs(ud));
      const C y_expected = mean ? yd / h : yd;
      EXPECT_LT(std::abs(d.y[i] - y_expected), 1e-10 * (1 + std::abs(yd)));
    }
  }
}

TEST(RelayFrequencyData, TheHeldInputsSpectrumIsItsIntegral) {
  // U Ts = integral of the held u(t) e^(-j w t) over the window
  // (t from the window's start), by a midpoint rule on 2000 steps per
  // sample: error of order (w Ts / 2000)^2 of the sum of |u| Ts.
  const int lead = 3, period = 24, cycles = 5;
  const Cycle rec = square_cycle(lead, period, 12, cycles);
  const double ts = 0.1;
  RelayFrequencyData<double> d;
  ASSERT_TRUE(relay_frequency_data(rec.y.data(), rec.u.data(),
                                   static_cast<Eigen::Index>(rec.u.size()), ts,
                                   false, &d)
                  .ok());
  const int m = cycles * period, steps = 2000;
  for (std::size_t i = 0; i < d.w.size(); ++i) {
    C integral = 0;
    for (int k = 0; k < m; ++k) {
      for (int s = 0; s < steps; ++s) {
        const double t = (k + (s + 0.5) / steps) * ts;
        integral += rec.u[lead + k] * std::polar(1.0, -d.w[i] * t);
      }
    }
    integral *= ts / steps;
    EXPECT_LT(std::abs(d.u[i] * ts - integral), 1e-5 * std::abs(integral))
        << "w = " << d.w[i];
  }
}

TEST(RelayFrequencyData, ASymmetricSquareWaveHasOddHarmonicsOnly) {
  // 50 % duty cycle around a zero mean: the even harmonics and the mean
  // are zero (below 1 % of the fundamental) and left out.
  std::vector<double> u, y;
  const int period = 32;
  for (int k = 0; k < 8 * period; ++k) {
    u.push_back((k + period / 4) % period < period / 2 ? 1.0 : -1.0);
    y.push_back(std::cos(0.2 * k));
  }
  RelayFrequencyData<double> d;
  ASSERT_TRUE(relay_frequency_data(y.data(), u.data(),
                                   static_cast<Eigen::Index>(u.size()), 0.05,
                                   true, &d)
                  .ok());
  const double w1 = 2 * kPi / (period * 0.05);
  ASSERT_FALSE(d.w.empty());
  for (double w : d.w) {
    const double harmonic = w / w1;
    EXPECT_NEAR(harmonic, std::round(harmonic), 1e-9);
    EXPECT_EQ(static_cast<int>(std::lround(harmonic)) % 2, 1) << harmonic;
  }
}

TEST(RelayFrequencyData, FewerThanTwoPeriodsAreRefused) {
  const Cycle rec = square_cycle(4, 50, 20, 1);  // two upward crossings
  RelayFrequencyData<double> d;
  const Status st = relay_frequency_data(
      rec.y.data(), rec.u.data(), static_cast<Eigen::Index>(rec.u.size()), 0.1,
      false, &d);
  EXPECT_EQ(st.code(), ErrorCode::kBadInput);
  EXPECT_EQ(relay_frequency_data(rec.y.data(), rec.u.data(), 10, 0.0, false, &d)
                .code(),
            ErrorCode::kBadInput);
}

}  // namespace
}  // namespace ctid
