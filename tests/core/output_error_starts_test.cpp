// SPDX-License-Identifier: BSD-3-Clause
// Copyright (C) the ctid authors
// Tests of core/include/ctid/offline/output_error_starts.hpp: the lowest
// loss over the starts is kept (each start's run is output_error's from
// it), a delay bound below the true delay ends at the bound as the fit at
// that fixed delay, a pole at 0 by integration is recovered exactly from
// an independent simulation, the input's integral against its closed
// form, and the identified failures. Also the ARX prediction error of
// output_error.hpp against the regression's residual.
#include "ctid/offline/output_error_starts.hpp"

#include <gtest/gtest.h>

#include <vector>

#include "delayed_record.hpp"
#include "test_util.hpp"

namespace ctid {
namespace {

using test::binary_input;
using test::relative_error;

OeData<double> make_data(const std::vector<double>& y,
                         const std::vector<double>& u, double ts) {
  OeData<double> d;
  d.y = y.data();
  d.u = u.data();
  d.num_samples = static_cast<Eigen::Index>(y.size());
  d.ts = ts;
  return d;
}

// b(p)/f(p) e^(-td p) with td = 0.25 s = 2.5 samples of 0.1 s, ZOH input:
// simulated on a grid of 0.05 s on which the delay is 5 steps.
test::Record delayed(const Eigen::VectorXd& f, const Eigen::VectorXd& b) {
  return test::make_record(f, b, binary_input(600, 6, 5), 2, 0.05, 5, false);
}

OeStructure delay_structure(int nf, int nb, double delay_max) {
  OeStructure s;
  s.nf = nf;
  s.nb = nb;
  s.estimate_delay = true;
  s.delay_max = delay_max;
  return s;
}

TEST(OutputErrorStarts, IntegralOfAZohInputIsExact) {
  const std::vector<double> u = {1, -2, 0.5, 3};
  const std::vector<double> v =
      integrate_zoh_input(u.data(), 4, 0.1, static_cast<double*>(nullptr));
  const std::vector<double> expected = {0, 0.1, -0.1, -0.05};
  for (int k = 0; k < 4; ++k) EXPECT_NEAR(v[k], expected[k], 1e-15);
  const std::vector<double> t = {0, 0.1, 0.4, 0.5};
  const std::vector<double> w = integrate_zoh_input(u.data(), 4, 0.0, t.data());
  const std::vector<double> expected_w = {0, 0.1, -0.5, -0.45};
  for (int k = 0; k < 4; ++k) EXPECT_NEAR(w[k], expected_w[k], 1e-15);
}

TEST(OutputErrorStarts, TheLowestLossOverTheStartsIsKept) {
  Eigen::VectorXd f(3), b(2);
  f << 1, 1.4, 2;
  b << 0.5, 3;
  const test::Record rec = delayed(f, b);
  const OeStructure s = delay_structure(2, 2, 1.0);
  OeSettings<double> settings;
  OeStartsSettings<double> starts;
  Eigen::VectorXd near(5), far(5);
  near << 1.3, 2.2, 0.4, 3.1, 0.2;
  far << 4, 1, 0, 1, 0.9;
  starts.starts = {far, near};
  const OeData<double> d = make_data(rec.y, rec.u, 0.1);
  OeStartsResult<double> r;
  const Status st = output_error_from_starts(s, settings, starts, d, &r);
  ASSERT_TRUE(st.ok()) << st.message();
  Eigen::VectorXd expected(5);
  expected << 1.4, 2, 0.5, 3, 0.25;
  EXPECT_LT(relative_error(r.best.theta, expected), 1e-7)
      << r.best.theta.transpose();
  EXPECT_TRUE(r.delay_estimated);
  EXPECT_NEAR(r.delay, 0.25, 1e-7);
  EXPECT_EQ(r.free_parameters, 5);
  // Each start's run is output_error's from it; the lower loss is kept.
  for (const Eigen::VectorXd& start : starts.starts) {
    OeStructure one = s;
    one.delay = start(4);
    OeSettings<double> given = settings;
    given.theta_init = start;
    OeResult<double> alone;
    const Status sa = output_error(one, given, d, &alone);
    ASSERT_TRUE(sa.ok() || sa.code() == ErrorCode::kNotConverged);
    EXPECT_LE(r.best.loss, alone.loss);
  }
}

TEST(OutputErrorStarts, ADelayBoundAboveTheTrueDelayIsActive) {
  Eigen::VectorXd f(3), b(2);
  f << 1, 1.4, 2;
  b << 0.5, 3;
  const test::Record rec = delayed(f, b);
  const OeStructure s = delay_structure(2, 2, 1.0);
  OeSettings<double> settings;
  OeStartsSettings<double> starts;
  Eigen::VectorXd start(5);
  start << 1.4, 2, 0.5, 3, 0.5;
  starts.starts = {start};
  starts.delay_min = 0.4;
  const OeData<double> d = make_data(rec.y, rec.u, 0.1);
  OeStartsResult<double> r;
  const Status st = output_error_from_starts(s, settings, starts, d, &r);
  ASSERT_TRUE(st.ok()) << st.message();
  // The loss decreases towards the true 0.25 s: the bound is active, the
  // delay no parameter, the result the fit at td = 0.4 s fixed.
  EXPECT_FALSE(r.delay_estimated);
  EXPECT_EQ(r.delay, 0.4);
  ASSERT_EQ(r.best.theta.size(), 4);
  EXPECT_EQ(r.free_parameters, 4);
  OeStructure fixed;
  fixed.nf = 2;
  fixed.nb = 2;
  fixed.delay = 0.4;
  OeResult<double> at_bound;
  const Status sf = output_error(fixed, settings, d, &at_bound);
  ASSERT_TRUE(sf.ok()) << sf.message();
  EXPECT_LT(relative_error(r.best.theta, at_bound.theta), 1e-6)
      << r.best.theta.transpose() << " / " << at_bound.theta.transpose();
  EXPECT_NEAR(r.best.loss, at_bound.loss, 1e-8 * at_bound.loss);
  EXPECT_GT(r.best.loss, 0);
}

TEST(OutputErrorStarts, APoleAtZeroByIntegrationIsExact) {
  // 2 / (p (p + 3)) e^(-0.25 p), simulated independently (the state-space
  // model with its integrator, delayed_record.hpp).
  Eigen::VectorXd f(3), b(1);
  f << 1, 3, 0;
  b << 2;
  const test::Record rec = delayed(f, b);
  const OeStructure s = delay_structure(2, 1, 1.0);
  OeSettings<double> settings;
  OeStartsSettings<double> starts;
  Eigen::VectorXd start(4);
  start << 3.4, 0, 1.7, 0.2;  // [f1 f2 b0 td], f2 = 0 the fixed pole
  starts.starts = {start};
  starts.integrate = true;
  const OeData<double> d = make_data(rec.y, rec.u, 0.1);
  OeStartsResult<double> r;
  const Status st = output_error_from_starts(s, settings, starts, d, &r);
  ASSERT_TRUE(st.ok()) << st.message();
  Eigen::VectorXd expected(4);
  expected << 3, 0, 2, 0.25;
  ASSERT_EQ(r.best.theta.size(), 4);
  EXPECT_EQ(r.best.theta(1), 0.0);
  EXPECT_LT(relative_error(r.best.theta, expected), 1e-7)
      << r.best.theta.transpose();
  EXPECT_EQ(r.free_parameters, 3);
  ASSERT_EQ(r.best.covariance.rows(), 4);
  EXPECT_EQ(r.best.covariance.row(1).norm(), 0.0);
  EXPECT_EQ(r.best.covariance.col(1).norm(), 0.0);
}

TEST(OutputErrorStarts, BadInputIsReported) {
  Eigen::VectorXd f(3), b(2);
  f << 1, 1.4, 2;
  b << 0.5, 3;
  const test::Record rec = delayed(f, b);
  const OeData<double> d = make_data(rec.y, rec.u, 0.1);
  OeSettings<double> settings;
  OeStartsResult<double> r;
  OeStartsSettings<double> none;
  EXPECT_EQ(output_error_from_starts(delay_structure(2, 2, 1.0), settings, none,
                                     d, &r)
                .code(),
            ErrorCode::kBadInput);
  OeStartsSettings<double> short_start;
  short_start.starts = {Eigen::VectorXd::Ones(3)};
  EXPECT_EQ(output_error_from_starts(delay_structure(2, 2, 1.0), settings,
                                     short_start, d, &r)
                .code(),
            ErrorCode::kDimensionMismatch);
  OeStartsSettings<double> above;
  above.starts = {Eigen::VectorXd::Ones(5)};
  above.delay_min = 2;
  EXPECT_EQ(output_error_from_starts(delay_structure(2, 2, 1.0), settings,
                                     above, d, &r)
                .code(),
            ErrorCode::kBadInput);
  OeStartsSettings<double> integrate;
  integrate.starts = {Eigen::VectorXd::Ones(4)};
  integrate.integrate = true;
  OeStructure foh = delay_structure(2, 1, 1.0);
  foh.rule = InterSample::kFoh;
  EXPECT_EQ(output_error_from_starts(foh, settings, integrate, d, &r).code(),
            ErrorCode::kNotSupported);
  // B/F' must be strictly proper: nb <= nf - 1
  integrate.starts = {Eigen::VectorXd::Ones(5)};
  EXPECT_EQ(output_error_from_starts(delay_structure(2, 2, 1.0), settings,
                                     integrate, d, &r)
                .code(),
            ErrorCode::kNotSupported);
}

// An over-parametrised model with a cancelling pole-zero pair reduces to
// the model without it exactly: 2 (p + 3) / ((p^2 + 1.2 p + 1) (p + 3))
// e^(-0.3 p), with the delay kept or searched.
TEST(ReducedStart, ACancellingPairIsRemovedExactly) {
  Eigen::VectorXd f_over(3), b_over(2);
  f_over << 4.2, 4.6, 3;  // (p^2 + 1.2 p + 1)(p + 3), without its leading 1
  b_over << 2, 6;
  Eigen::VectorXd expected(4);
  expected << 1.2, 1, 2, 0.3;
  for (const bool search : {false, true}) {
    Eigen::VectorXd start;
    const Status st = reduced_start<double>(f_over, b_over, 0.3, 2, 1, 0.05,
                                            20.0, search, 1.0, &start);
    ASSERT_TRUE(st.ok()) << st.message();
    ASSERT_EQ(start.size(), 4);
    EXPECT_LT(relative_error(start, expected), 1e-7)
        << "search " << search << ": " << start.transpose();
  }
  Eigen::VectorXd start;
  EXPECT_EQ(reduced_start<double>(f_over, b_over, 0.3, 2, 1, 1.0, 0.5, false,
                                  1.0, &start)
                .code(),
            ErrorCode::kBadInput);
}

TEST(ArxPredictionError, IsTheResidualOverTheRegressionRows) {
  const int n = 300;
  const std::vector<double> u = binary_input(n, 3, 8);
  std::vector<double> y(n, 0.0);
  for (int k = 0; k < n; ++k) {
    const double noise = 0.1 * std::sin(0.7 * k * k);
    y[k] = noise + (k >= 1 ? 0.9 * y[k - 1] : 0) -
           (k >= 2 ? 0.2 * y[k - 2] : 0) + (k >= 1 ? 0.4 * u[k - 1] : 0) +
           (k >= 2 ? 0.2 * u[k - 2] : 0);
  }
  ArxResult<double> r;
  const std::vector<int> nb{2}, nk{1};
  ASSERT_TRUE(
      arx_least_squares<double>(y.data(), u.data(), n, 1, 2, nb, nk, &r).ok());
  ASSERT_EQ(r.prediction_error.size(), n);
  const Eigen::VectorXd& th = r.theta;
  // Inside the regression (k >= 2): its residual, whose mean square is
  // the loss; before it the regressor's missing values are 0.
  double sum = 0;
  for (int k = 2; k < n; ++k) {
    const double e = y[k] + th(0) * y[k - 1] + th(1) * y[k - 2] -
                     th(2) * u[k - 1] - th(3) * u[k - 2];
    EXPECT_NEAR(r.prediction_error(k), e, 1e-12);
    sum += e * e;
  }
  EXPECT_NEAR(sum / (n - 2), r.loss, 1e-12 * r.loss);
  EXPECT_EQ(r.prediction_error(0), y[0]);
  EXPECT_NEAR(r.prediction_error(1), y[1] + th(0) * y[0] - th(2) * u[0], 1e-15);
}

}  // namespace
}  // namespace ctid
