// SPDX-License-Identifier: BSD-3-Clause
// Copyright (C) the ctid authors
// Tests of core/include/ctid/offline/output_error.hpp: exact recovery from
// noise-free records (continuous time ZOH/FOH and with a fractional delay,
// discrete time), the exact Jacobian against central differences of the
// simulation, the optimum as a stationary point, ARX against the normal
// equations, and the identified failures.
#include "ctid/offline/output_error.hpp"

#include <gtest/gtest.h>

#include <random>
#include <vector>

#include "ctid/offline/output_error_options.hpp"
#include "delayed_record.hpp"
#include "test_util.hpp"

namespace ctid {
namespace {

using test::binary_input;
using test::relative_error;
using test::simulate_fine;  // the exact simulation, delayed_record.hpp

OeData<double> make_data(const std::vector<double>& y,
                         const std::vector<double>& u, double ts) {
  OeData<double> d;
  d.y = y.data();
  d.u = u.data();
  d.num_samples = static_cast<Eigen::Index>(y.size());
  d.ts = ts;
  return d;
}

TEST(OutputError, ContinuousNoiseFreeZohIsExact) {
  const std::vector<double> u = binary_input(1000, 7, 3);
  Eigen::VectorXd f(3), b(2);
  f << 1, 1.2, 4;
  b << 1.5, 4;
  const std::vector<double> y = simulate_fine(f, b, u, 0.05, false);
  OeStructure s;
  s.nf = 2;
  s.nb = 2;
  OeSettings<double> settings;
  OeResult<double> r;
  const Status st = output_error(s, settings, make_data(y, u, 0.05), &r);
  ASSERT_TRUE(st.ok()) << st.message();
  Eigen::VectorXd expected(4);
  expected << 1.2, 4, 1.5, 4;
  EXPECT_LT(relative_error(r.theta, expected), 1e-8) << r.theta.transpose();
  EXPECT_EQ(r.start, "srivc");
  EXPECT_LT(r.loss, 1e-18);
}

TEST(OutputError, ContinuousFohFromAPerturbedStartIsExact) {
  const std::vector<double> u = binary_input(800, 5, 4);
  Eigen::VectorXd f(3), b(1);
  f << 1, 0.8, 9;
  b << 9;
  const std::vector<double> y = simulate_fine(f, b, u, 0.02, true);
  OeStructure s;
  s.nf = 2;
  s.nb = 1;
  s.rule = InterSample::kFoh;
  OeSettings<double> settings;
  settings.theta_init = Eigen::Vector3d(1.2, 7, 6);
  OeResult<double> r;
  const Status st = output_error(s, settings, make_data(y, u, 0.02), &r);
  ASSERT_TRUE(st.ok()) << st.message();
  EXPECT_LT(relative_error(r.theta, Eigen::Vector3d(0.8, 9, 9)), 1e-8)
      << r.theta.transpose();
  EXPECT_EQ(r.start, "given");
}

TEST(OutputError, ContinuousFractionalDelayIsExact) {
  // A delay of 2.5 samples: simulate on a grid of Ts/2 with 5 fine steps of
  // delay, keep every second sample.
  const std::vector<double> coarse = binary_input(600, 6, 5);
  std::vector<double> fine(2 * coarse.size());
  for (std::size_t k = 0; k < fine.size(); ++k) fine[k] = coarse[k / 2];
  std::vector<double> shifted(fine.size(), 0.0);
  for (std::size_t k = 5; k < fine.size(); ++k) shifted[k] = fine[k - 5];
  Eigen::VectorXd f(2), b(1);
  f << 1, 2;
  b << 3;
  const std::vector<double> yf = simulate_fine(f, b, shifted, 0.05, false);
  std::vector<double> y(coarse.size());
  for (std::size_t k = 0; k < y.size(); ++k) y[k] = yf[2 * k];
  OeStructure s;
  s.nf = 1;
  s.nb = 1;
  s.nk = 2;
  s.delay = 0.05;
  OeSettings<double> settings;
  OeResult<double> r;
  const Status st = output_error(s, settings, make_data(y, coarse, 0.1), &r);
  ASSERT_TRUE(st.ok()) << st.message();
  EXPECT_LT(relative_error(r.theta, Eigen::Vector2d(2, 3)), 1e-8)
      << r.theta.transpose();
}

TEST(OutputError, ContinuousDelayIsEstimatedWithinItsBounds) {
  // The record of the previous test (td = 0.25 s = 2.5 samples); the delay
  // is estimated from 0.18 s, kept in [0, 0.5].
  const std::vector<double> coarse = binary_input(600, 6, 5);
  std::vector<double> fine(2 * coarse.size());
  for (std::size_t k = 0; k < fine.size(); ++k) fine[k] = coarse[k / 2];
  std::vector<double> shifted(fine.size(), 0.0);
  for (std::size_t k = 5; k < fine.size(); ++k) shifted[k] = fine[k - 5];
  Eigen::VectorXd f(3), b(2);
  f << 1, 1.4, 2;
  b << 0.5, 3;
  const std::vector<double> yf = simulate_fine(f, b, shifted, 0.05, false);
  std::vector<double> y(coarse.size());
  for (std::size_t k = 0; k < y.size(); ++k) y[k] = yf[2 * k];
  OeStructure s;
  s.nf = 2;
  s.nb = 2;
  s.delay = 0.18;
  s.estimate_delay = true;
  s.delay_max = 0.5;
  OeSettings<double> settings;
  OeResult<double> r;
  const Status st = output_error(s, settings, make_data(y, coarse, 0.1), &r);
  ASSERT_TRUE(st.ok()) << st.message();
  Eigen::VectorXd expected(5);
  expected << 1.4, 2, 0.5, 3, 0.25;
  EXPECT_LT(relative_error(r.theta, expected), 1e-7) << r.theta.transpose();
  EXPECT_EQ(r.covariance.rows(), 5);
  // A start outside the bounds is refused.
  s.delay = 0.6;
  EXPECT_EQ(output_error(s, settings, make_data(y, coarse, 0.1), &r).code(),
            ErrorCode::kBadInput);
}

// The model's Jacobian against central differences of its simulation.
template <typename Fn>
Eigen::MatrixXd central_differences(const Eigen::VectorXd& theta, Fn&& sim) {
  const Eigen::VectorXd y0 = sim(theta);
  Eigen::MatrixXd J(y0.size(), theta.size());
  for (int i = 0; i < theta.size(); ++i) {
    const double h = 1e-6 * std::max(1.0, std::abs(theta(i)));
    Eigen::VectorXd tp = theta, tm = theta;
    tp(i) += h;
    tm(i) -= h;
    J.col(i) = (sim(tp) - sim(tm)) / (2 * h);
  }
  return J;
}

// The model's Jacobian at theta against central differences of its
// simulation.
void expect_jacobian_exact(oe_detail::OeModel<double>& model,
                           const Eigen::VectorXd& theta) {
  Eigen::VectorXd yhat;
  Eigen::MatrixXd J;
  model.evaluate(theta, yhat, &J);
  const Eigen::MatrixXd Jd =
      central_differences(theta, [&](const Eigen::VectorXd& t) {
        Eigen::VectorXd out;
        model.evaluate(t, out, nullptr);
        return out;
      });
  EXPECT_TRUE(test::MatrixNear(J, Jd, 1e-6));
}

TEST(OutputError, JacobianMatchesCentralDifferences) {
  const std::vector<double> u = binary_input(300, 4, 6);
  const std::vector<double> y(u.size(), 0.0);
  for (OeTime time : {OeTime::kContinuous, OeTime::kDiscrete}) {
    for (InterSample rule : {InterSample::kZoh, InterSample::kFoh}) {
      OeStructure s;
      s.time = time;
      s.nf = 2;
      s.nb = 2;
      s.nk = 1;
      s.rule = rule;
      s.delay = time == OeTime::kContinuous ? 0.013 : 0;
      s.estimate_delay = time == OeTime::kContinuous;
      s.nb = time == OeTime::kContinuous ? 1 : 2;
      oe_detail::OeModel<double> model(s, make_data(y, u, 0.05));
      Eigen::Vector4d theta;
      if (time == OeTime::kContinuous) {
        theta << 1.5, 6, 5, 0.083;  // f1 f2 b0 td
      } else {
        theta << -1.2, 0.5, 0.3, 0.2;
      }
      expect_jacobian_exact(model, theta);
    }
  }
}

// Two inputs, each with its own denominator (theta = [f_1 f_2 b_1 b_2]):
// the Jacobian against central differences of the simulation, continuous
// (ZOH and FOH, a fractional delay on the second input) and discrete time.
TEST(OutputError, TwoInputJacobianMatchesCentralDifferences) {
  const std::vector<double> u1 = binary_input(300, 4, 6);
  const std::vector<double> u2 = binary_input(300, 3, 9);
  std::vector<double> u(u1);
  u.insert(u.end(), u2.begin(), u2.end());
  const std::vector<double> y(u1.size(), 0.0);
  for (OeTime time : {OeTime::kContinuous, OeTime::kDiscrete}) {
    for (InterSample rule : {InterSample::kZoh, InterSample::kFoh}) {
      OeStructure s;
      s.time = time;
      OeChannel c1, c2;
      c1.nf = 2;
      c1.nb = time == OeTime::kContinuous ? 1 : 2;
      c1.nk = 1;
      c1.rule = rule;
      c2.nf = 1;
      c2.nb = 2;
      c2.nk = time == OeTime::kContinuous ? 0 : 2;
      c2.delay = time == OeTime::kContinuous ? 0.037 : 0;
      c2.rule = rule;
      s.inputs = {c1, c2};
      OeData<double> data = make_data(y, u, 0.05);
      data.num_inputs = 2;
      oe_detail::OeModel<double> model(s, data);
      Eigen::VectorXd theta(s.num_parameters());
      if (time == OeTime::kContinuous) {
        theta << 1.5, 6, 2, 5, 0.5, 3;  // f1 f2 | f | b0 | b0 b1
      } else {
        theta << -1.2, 0.5, -0.6, 0.3, 0.2, 1.2, -0.4;
      }
      expect_jacobian_exact(model, theta);
    }
  }
}

// Two inputs, noise-free ZOH record y = b_1/f_1 u_1 + b_2/f_2 u_2 (each
// simulated by the matrix exponential): exact from the SRIVC start.
TEST(OutputError, TwoInputContinuousNoiseFreeIsExact) {
  const std::vector<double> u1 = binary_input(1000, 7, 3);
  const std::vector<double> u2 = binary_input(1000, 5, 11);
  Eigen::VectorXd f1(3), b1(2), f2(2), b2(1);
  f1 << 1, 1.2, 4;
  b1 << 1.5, 4;
  f2 << 1, 0.8;
  b2 << 2;
  const std::vector<double> x1 = simulate_fine(f1, b1, u1, 0.05, false);
  const std::vector<double> x2 = simulate_fine(f2, b2, u2, 0.05, false);
  std::vector<double> y(x1.size()), u(u1);
  for (std::size_t k = 0; k < y.size(); ++k) y[k] = x1[k] + x2[k];
  u.insert(u.end(), u2.begin(), u2.end());
  OeStructure s;
  OeChannel c1, c2;
  c1.nf = 2;
  c1.nb = 2;
  c2.nf = 1;
  c2.nb = 1;
  s.inputs = {c1, c2};
  OeData<double> data = make_data(y, u, 0.05);
  data.num_inputs = 2;
  OeResult<double> r;
  ASSERT_TRUE(output_error<double>(s, OeSettings<double>(), data, &r).ok())
      << r.reason;
  Eigen::VectorXd truth(6);
  truth << 1.2, 4, 0.8, 1.5, 4, 2;
  EXPECT_LT(relative_error(r.theta, truth), 1e-8);
  EXPECT_EQ(r.start, "srivc");
}

// A structure whose number of inputs differs from the data's, and a
// delay estimated with several inputs: identified errors.
TEST(OutputError, TwoInputBadStructureIsReported) {
  const std::vector<double> u = binary_input(400, 4, 6);
  const std::vector<double> y(200, 0.0);
  OeStructure s;
  s.inputs = {OeChannel(), OeChannel()};
  OeData<double> data = make_data(y, u, 0.05);
  OeResult<double> r;
  EXPECT_EQ(output_error<double>(s, OeSettings<double>(), data, &r).code(),
            ErrorCode::kDimensionMismatch);
  data.num_inputs = 2;
  s.estimate_delay = true;
  s.delay_max = 1;
  EXPECT_EQ(output_error<double>(s, OeSettings<double>(), data, &r).code(),
            ErrorCode::kBadInput);
}

// The options table: its defaults are the settings' own, an option set by
// name lands in the config, and a bad name or word is a bad option.
TEST(OutputErrorOptions, DefaultsAreTheSettingsAndNamesSetTheConfig) {
  const auto& table = output_error_options<double>();
  const OeSettings<double> settings;
  const auto shown = [&](const char* name) {
    const auto* decl = find_option(table, name);
    EXPECT_NE(decl, nullptr) << name;
    return decl == nullptr ? std::string() : option_default(*decl);
  };
  EXPECT_EQ(std::stod(shown("maxiter")), settings.max_iterations);
  EXPECT_EQ(std::stod(shown("tol")), settings.tolerance);
  EXPECT_EQ(std::stod(shown("cutoff")), settings.srivc_cutoff);
  EXPECT_EQ(shown("intersample"), "zoh");
  OeConfig<double> config;
  OptionValue v;
  v.integer = 7;
  ASSERT_TRUE(set_option(table, "maxiter", v, &config).ok());
  EXPECT_EQ(config.settings.max_iterations, 7);
  v.word = "foh";
  ASSERT_TRUE(set_option(table, "intersample", v, &config).ok());
  EXPECT_EQ(config.rule, InterSample::kFoh);
  v.word = "trapezoid";  // not an output-error rule
  EXPECT_EQ(set_option(table, "intersample", v, &config).code(),
            ErrorCode::kBadOption);
  EXPECT_EQ(set_option(table, "lambda_svf", v, &config).code(),
            ErrorCode::kBadOption);
}

// A config set by name gives the structure written by hand, and the same
// estimate to the last bit; orders with the wrong number of entries are a
// dimension mismatch.
TEST(OutputErrorOptions, ConfigByNameGivesTheSameEstimate) {
  const std::vector<double> u = binary_input(800, 7, 3);
  Eigen::VectorXd f(3), b(2);
  f << 1, 1.2, 4;
  b << 1.5, 4;
  const std::vector<double> y = simulate_fine(f, b, u, 0.05, true);
  const auto& table = output_error_options<double>();
  OeConfig<double> config;
  OptionValue v;
  v.integers = {2};
  ASSERT_TRUE(set_option(table, "nf", v, &config).ok());
  ASSERT_TRUE(set_option(table, "nb", v, &config).ok());
  v.word = "foh";
  ASSERT_TRUE(set_option(table, "intersample", v, &config).ok());
  v.real = 1e-10;
  ASSERT_TRUE(set_option(table, "tol", v, &config).ok());
  OeStructure by_name;
  ASSERT_TRUE(oe_structure(config, 1, &by_name).ok());
  OeStructure by_hand;
  by_hand.nf = 2;
  by_hand.nb = 2;
  by_hand.rule = InterSample::kFoh;
  OeSettings<double> settings;
  settings.tolerance = 1e-10;
  OeResult<double> a, c;
  ASSERT_TRUE(
      output_error(by_name, config.settings, make_data(y, u, 0.05), &a).ok());
  ASSERT_TRUE(output_error(by_hand, settings, make_data(y, u, 0.05), &c).ok());
  EXPECT_EQ(a.theta, c.theta);
  EXPECT_LT(relative_error(a.theta, Eigen::Vector4d(1.2, 4, 1.5, 4)), 1e-8);
  OeStructure two;
  EXPECT_EQ(oe_structure(config, 2, &two).code(),
            ErrorCode::kDimensionMismatch);
}

TEST(OutputError, DiscreteNoiseFreeIsExactAndNoisyIsStationary) {
  const std::vector<double> u = binary_input(2000, 3, 7);
  const int n = static_cast<int>(u.size());
  // y = (0.5 q^-2 + 0.3 q^-3) / (1 - 1.5 q^-1 + 0.7 q^-2) u
  std::vector<double> x(n, 0.0);
  for (int k = 0; k < n; ++k) {
    double v = 0;
    if (k >= 2) v += 0.5 * u[k - 2];
    if (k >= 3) v += 0.3 * u[k - 3];
    if (k >= 1) v += 1.5 * x[k - 1];
    if (k >= 2) v -= 0.7 * x[k - 2];
    x[k] = v;
  }
  OeStructure s;
  s.time = OeTime::kDiscrete;
  s.nf = 2;
  s.nb = 2;
  s.nk = 2;
  OeSettings<double> settings;
  OeResult<double> r;
  Status st = output_error(s, settings, make_data(x, u, 1), &r);
  ASSERT_TRUE(st.ok()) << st.message();
  EXPECT_LT(relative_error(r.theta, Eigen::Vector4d(-1.5, 0.7, 0.5, 0.3)),
            1e-9);
  // Noisy: the optimum is a stationary point (the full gradient J^T e is
  // ~0 relative to its size at the start) and a local minimum (a
  // perturbation in any coordinate raises the loss).
  std::mt19937 gen(11);
  std::normal_distribution<double> noise(0, 0.5);
  std::vector<double> y = x;
  for (double& v : y) v += noise(gen);
  st = output_error(s, settings, make_data(y, u, 1), &r);
  ASSERT_TRUE(st.ok()) << st.message();
  oe_detail::OeModel<double> model(s, make_data(y, u, 1));
  Eigen::VectorXd yhat;
  Eigen::MatrixXd J;
  model.evaluate(r.theta, yhat, &J);
  const Eigen::Map<const Eigen::VectorXd> ym(y.data(), n);
  const Eigen::VectorXd e = ym - yhat;
  const Eigen::VectorXd g = J.transpose() * e;
  const Eigen::VectorXd scale = J.colwise().norm().transpose();
  EXPECT_LT(g.cwiseQuotient(scale).norm() / e.norm(), 1e-6);
  EXPECT_NEAR(e.squaredNorm() / n, r.loss, 1e-12 * r.loss);
  for (int i = 0; i < 4; ++i) {
    for (double sign : {-1.0, 1.0}) {
      Eigen::VectorXd t = r.theta;
      t(i) += sign * 1e-4 * std::max(1.0, std::abs(t(i)));
      model.evaluate(t, yhat, nullptr);
      EXPECT_GT((ym - yhat).squaredNorm() / n, r.loss);
    }
  }
}

TEST(OutputError, ArxEqualsTheNormalEquations) {
  const std::vector<double> u = binary_input(500, 2, 8);
  std::mt19937 gen(2);
  std::normal_distribution<double> noise(0, 1);
  const int n = 500;
  std::vector<double> y(n, 0.0);
  for (int k = 0; k < n; ++k) {
    double v = noise(gen);
    if (k >= 1) v += 0.9 * y[k - 1] + 0.4 * u[k - 1];
    y[k] = v;
  }
  ArxResult<double> r;
  ASSERT_TRUE(
      arx_least_squares<double>(y.data(), u.data(), n, 1, 2, {2}, {1}, &r)
          .ok());
  // Normal equations over k = 2..n-1.
  Eigen::MatrixXd Phi(n - 2, 4);
  Eigen::VectorXd Y(n - 2);
  for (int k = 2; k < n; ++k) {
    Phi.row(k - 2) << -y[k - 1], -y[k - 2], u[k - 1], u[k - 2];
    Y(k - 2) = y[k];
  }
  const Eigen::MatrixXd A = Phi.transpose() * Phi;
  const Eigen::VectorXd th = A.ldlt().solve(Phi.transpose() * Y);
  EXPECT_LT(relative_error(r.theta, th), 1e-10);
  const double s2 = (Y - Phi * th).squaredNorm() / (n - 2 - 4);
  EXPECT_TRUE(test::MatrixNear(r.covariance, s2 * A.inverse(), 1e-9));
}

TEST(OutputError, BadInputAndNonConvergenceAreReported) {
  const std::vector<double> u = binary_input(200, 3, 9);
  const std::vector<double> y = u;
  OeStructure s;
  s.nf = 1;
  s.nb = 3;  // improper
  OeSettings<double> settings;
  OeResult<double> r;
  EXPECT_EQ(output_error(s, settings, make_data(y, u, 0.1), &r).code(),
            ErrorCode::kBadInput);
  s.nb = 1;
  settings.theta_init = Eigen::Vector2d(-1, 1);  // unstable start
  EXPECT_EQ(output_error(s, settings, make_data(y, u, 0.1), &r).code(),
            ErrorCode::kBadInput);
  settings.theta_init = Eigen::Vector3d(1, 1, 1);
  EXPECT_EQ(output_error(s, settings, make_data(y, u, 0.1), &r).code(),
            ErrorCode::kDimensionMismatch);
  // One iteration from a poor start: not converged, said so.
  Eigen::VectorXd f(2), b(1);
  f << 1, 2;
  b << 3;
  const std::vector<double> y2 = simulate_fine(f, b, u, 0.1, false);
  settings.theta_init = Eigen::Vector2d(0.5, 0.2);
  settings.max_iterations = 1;
  const Status st = output_error(s, settings, make_data(y2, u, 0.1), &r);
  EXPECT_EQ(st.code(), ErrorCode::kNotConverged);
  EXPECT_FALSE(r.converged);
  EXPECT_EQ(r.iterations, 1);
  // No excitation: ARX reports it.
  const std::vector<double> zero(200, 0.0);
  ArxResult<double> a;
  EXPECT_EQ(
      arx_least_squares<double>(y.data(), zero.data(), 200, 1, 1, {1}, {1}, &a)
          .code(),
      ErrorCode::kNumericalFailure);
  // Orders near INT_MAX (their sum overflows int): refused, no allocation
  // (the public fuzz test found a heap corruption here through tfest).
  OeStructure huge;
  huge.nf = 1000000000;
  huge.nb = 1000000000;
  OeSettings<double> fresh;
  EXPECT_EQ(output_error(huge, fresh, make_data(y, u, 0.1), &r).code(),
            ErrorCode::kBadInput);
  EXPECT_EQ(arx_least_squares<double>(y.data(), u.data(), 200, 1, 1000000000,
                                      {1000000000}, {1}, &a)
                .code(),
            ErrorCode::kBadInput);
}

}  // namespace
}  // namespace ctid
