// Fixed-size kernels (fixed_size.hpp) against the dynamic-size path, which
// is the reference: the same record through both, for every order na = 1..4
// (nb = 1, and nb = 2 for na = 2), every adaptation and update form, THM,
// YH and PSET compared entry by entry; and no heap allocation per sample on the
// fixed-size path, in double and in single precision.
//
// Tolerance in double: 1e-12 relative to the largest entry of the compared
// quantity. The two paths run the same algorithms (the same Pade degree for
// the matrix exponential, the same LU, the same update formulas); only the
// order of the floating-point operations inside Eigen's kernels differs, so
// each step differs by a few ulps and the stable recursions carry that
// forward without growth beyond a few hundred ulps.
//
// Single precision: a relative 1e-12 is below float resolution (eps =
// 1.2e-7), and the rounding differences of the two paths are amplified by
// the recursion like any float rounding error. The test therefore measures
// the error of the dynamic float path against the double reference and
// requires the two float paths to differ by at most twice that (plus 100 eps
// of the scale): the fixed path may differ from the dynamic one only by
// rounding of the size that single precision itself commits.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <string>
#include <type_traits>
#include <vector>

#include "allocation_counter.hpp"
#include "ctid/recursive_iv.hpp"
#include "test_util.hpp"

namespace ctid {
namespace {

constexpr double kTs = 0.05;
constexpr int kSamples = 3000;

// The true system of order na: A(p) = (p + 1.5)^na, B(p) = A(na) (1 + .. +
// p^(nb-1)) / nb, excited by a binary input, exact ZOH response plus noise.
struct Record {
  std::vector<double> u, y;
};

Record make_record(int na, int nb, unsigned seed) {
  Record r;
  r.u = test::binary_input(kSamples, 7, seed);
  r.y.resize(kSamples);
  const ModelOrders orders = siso_orders(na, nb, 0);
  Eigen::VectorXd theta(na + nb);
  theta.head(na) = svf_denominator<double>(na, 1.5);
  theta.tail(nb).setConstant(theta(na - 1) / nb);
  const StateSpace<double> ss = to_state_space(orders, theta, 0);
  Eigen::MatrixXd Phi, Gamma;
  zoh_discretize<double>(ss.F, ss.G, kTs, Phi, Gamma);
  std::mt19937 rng(seed + 1);
  std::normal_distribution<double> noise(0.0, 0.02);
  Eigen::VectorXd z = Eigen::VectorXd::Zero(na);
  for (int k = 0; k < kSamples; ++k) {
    r.y[k] = (ss.H * z)(0) + ss.J(0, 0) * r.u[k] + noise(rng);
    z = Phi * z + Gamma * r.u[k];
  }
  return r;
}

template <typename S>
struct Outputs {
  Eigen::Matrix<S, Eigen::Dynamic, Eigen::Dynamic> thm;
  Eigen::Matrix<S, Eigen::Dynamic, 1> yh, pset;
  RecursiveOutputs<S> view(int np) {
    thm.setZero(kSamples, np);
    yh.setZero(kSamples);
    pset.setZero(static_cast<Eigen::Index>(kSamples) * np * np);
    RecursiveOutputs<S> out;
    out.thm = thm.data();
    out.yh = yh.data();
    out.pset = pset.data();
    return out;
  }
};

template <typename S>
struct Data {
  std::vector<S> u, y;
  RecordView<S> view() const {
    RecordView<S> record;
    record.y = y.data();
    record.u = u.data();
    record.num_samples = kSamples;
    record.num_inputs = 1;
    record.ts = static_cast<S>(kTs);
    return record;
  }
};

template <typename S>
Data<S> cast(const Record& r) {
  Data<S> d;
  d.u.assign(r.u.begin(), r.u.end());
  d.y.assign(r.y.begin(), r.y.end());
  return d;
}

enum class Variant { kKf, kFf, kPotterKf, kPotterFf, kLmr };

const char* name(Variant v) {
  switch (v) {
    case Variant::kKf:
      return "KF";
    case Variant::kFf:
      return "FF";
    case Variant::kPotterKf:
      return "Potter-KF";
    case Variant::kPotterFf:
      return "Potter-FF";
    case Variant::kLmr:
      return "LMR";
  }
  return "?";
}

template <typename S>
Adaptation<S> adaptation(Variant v, int np) {
  if (v == Variant::kKf || v == Variant::kPotterKf) {
    return KalmanAdaptation<S>(S(1e-4) * Matrix<S>::Identity(np, np));
  }
  return ForgettingFactorAdaptation<S>(S(0.995));
}

template <typename S>
RlsSvfConfig<S> rlssvf_config(int na, int nb, Variant v) {
  RlsSvfConfig<S> config;
  config.orders = siso_orders(na, nb, 0);
  const int np = na + nb;
  config.svf.lambda_svf = S(3);
  config.adaptation = adaptation<S>(v, np);
  if (v == Variant::kPotterKf || v == Variant::kPotterFf) {
    config.form = UpdateForm::kPotter;
  } else if (v == Variant::kLmr) {
    config.form = UpdateForm::kLevenbergMarquardt;
    config.lmr_gamma = S(1e-3) * Matrix<S>::Identity(np, np);
  }
  return config;
}

template <typename S>
RecursiveIvConfig<S> iv_config(int na, int nb, IvMethod method, bool kf) {
  RecursiveIvConfig<S> config;
  config.orders = siso_orders(na, nb, 0);
  const int np = na + nb;
  config.method = method;
  config.svf.lambda_svf = S(3);
  config.adaptation = adaptation<S>(kf ? Variant::kKf : Variant::kFf, np);
  config.t_s_iv = S(30);
  config.dtupdate = 0;  // prefilter and auxiliary model refreshed per sample
  return config;
}

// The sized batch functions are called directly (run_rlssvf and
// run_recursive_iv dispatch to them through with_fixed_sizes, tested on its
// own below) so that this program instantiates only the sizes it tests
// (each costs compile time): nb = 1 for na = 1..4 and na = 2, nb = 2 in
// double, na = 2 and 4 (nb = 1) in single precision.
template <typename S, typename F>
Status with_tested_sizes(int na, int nb, bool fixed, F f) {
  using Dynamic = SizeConstant<Eigen::Dynamic>;
  if (!fixed) return f(Dynamic{}, Dynamic{});
  if (nb == 1 && na == 2) return f(SizeConstant<2>{}, SizeConstant<3>{});
  if (nb == 1 && na == 4) return f(SizeConstant<4>{}, SizeConstant<5>{});
  if constexpr (std::is_same_v<S, double>) {
    if (nb == 1 && na == 1) return f(SizeConstant<1>{}, SizeConstant<2>{});
    if (nb == 1 && na == 3) return f(SizeConstant<3>{}, SizeConstant<4>{});
    if (na == 2 && nb == 2) return f(SizeConstant<2>{}, SizeConstant<4>{});
  }
  return bad_input("size not instantiated in this test");
}

template <typename S>
Status run_rls(const RlsSvfConfig<S>& config, bool fixed,
               const RecordView<S>& record, const RecursiveOutputs<S>& out) {
  return with_tested_sizes<S>(
      config.orders.na, config.orders.nb[0], fixed, [&](auto a, auto p) {
        return run_rlssvf_sized<S, decltype(a)::value, decltype(p)::value>(
            config, record, out);
      });
}

template <typename S>
Status run_iv(const RecursiveIvConfig<S>& config, bool fixed,
              const RecordView<S>& record, const RecursiveOutputs<S>& out,
              long* rejections = nullptr) {
  return with_tested_sizes<S>(
      config.orders.na, config.orders.nb[0], fixed, [&](auto a, auto p) {
        return run_recursive_iv_sized<S, decltype(a)::value,
                                      decltype(p)::value>(
            config, record, ClosedLoopSignals<S>(), out, rejections, nullptr);
      });
}

// Largest |a - b| over max(1, max|b|), as a double.
template <typename A, typename B>
double relative_difference(const A& a, const B& b) {
  const double scale =
      std::max(1.0, static_cast<double>(b.cwiseAbs().maxCoeff()));
  return (a.template cast<double>() - b.template cast<double>())
             .cwiseAbs()
             .maxCoeff() /
         scale;
}

template <typename S, typename Run>
void compare_paths(const std::string& what, int np, Run run, double tol) {
  Outputs<S> fixed, dynamic;
  const Status a = run(true, fixed.view(np));
  const Status b = run(false, dynamic.view(np));
  ASSERT_TRUE(a.ok()) << what << ": " << a.message();
  ASSERT_TRUE(b.ok()) << what << ": " << b.message();
  ASSERT_TRUE(dynamic.thm.allFinite()) << what;
  EXPECT_TRUE(test::MatrixNear(fixed.thm, dynamic.thm, tol)) << what << " THM";
  EXPECT_TRUE(test::MatrixNear(fixed.yh, dynamic.yh, tol)) << what << " YH";
  EXPECT_TRUE(test::MatrixNear(fixed.pset, dynamic.pset, tol))
      << what << " PSET";
}

TEST(FixedSize, DispatchCoversOrdersOneToFourWithOneInput) {
  for (int na = 1; na <= 4; ++na) {
    for (int nb = 1; nb <= na; ++nb) {
      int got_na = 0, got_np = 0;
      with_fixed_sizes<double>(siso_orders(na, nb, 0), true, [&](auto a, auto p) {
        got_na = decltype(a)::value;
        got_np = decltype(p)::value;
        return 0;
      });
      EXPECT_EQ(got_na, na);
      EXPECT_EQ(got_np, na + nb);
    }
  }
  int got = 0;
  with_fixed_sizes<double>(siso_orders(5, 1, 0), true, [&](auto a, auto) {
    got = decltype(a)::value;
    return 0;
  });
  EXPECT_EQ(got, Eigen::Dynamic);
  got = 0;
  with_fixed_sizes<double>(siso_orders(2, 3, 0), true, [&](auto a, auto) {
    got = decltype(a)::value;
    return 0;
  });
  EXPECT_EQ(got, Eigen::Dynamic) << "biproper nb = na + 1";
  ModelOrders two_inputs = siso_orders(2, 1, 0);
  two_inputs.nb.push_back(1);
  two_inputs.nk.push_back(0);
  with_fixed_sizes<double>(two_inputs, true, [&](auto a, auto) {
    got = decltype(a)::value;
    return 0;
  });
  EXPECT_EQ(got, Eigen::Dynamic);
  with_fixed_sizes<double>(siso_orders(2, 1, 0), false, [&](auto a, auto) {
    got = decltype(a)::value;
    return 0;
  });
  EXPECT_EQ(got, Eigen::Dynamic);
  got = 0;
  with_fixed_sizes<float>(siso_orders(2, 1, 0), true, [&](auto a, auto) {
    got = decltype(a)::value;
    return 0;
  });
  EXPECT_EQ(got, Eigen::Dynamic) << "the batch functions in float";
}

TEST(FixedSize, RlsSvfAgreesWithTheDynamicPathInDouble) {
  for (int na = 1; na <= 4; ++na) {
    for (int nb : {1, 2}) {
      if (nb == 2 && na != 2) continue;
      const Data<double> data = cast<double>(make_record(na, nb, 10 + na));
      for (Variant v : {Variant::kKf, Variant::kFf, Variant::kPotterKf,
                        Variant::kPotterFf, Variant::kLmr}) {
        const std::string what = std::string("RLSSVF-") + name(v) +
                                 " na=" + std::to_string(na) +
                                 " nb=" + std::to_string(nb);
        compare_paths<double>(
            what, na + nb,
            [&](bool fixed, const RecursiveOutputs<double>& out) {
              return run_rls(rlssvf_config<double>(na, nb, v), fixed,
                             data.view(), out);
            },
            1e-12);
      }
    }
  }
}

TEST(FixedSize, RecursiveIvAgreesWithTheDynamicPathInDouble) {
  for (int na = 1; na <= 4; ++na) {
    for (int nb : {1, 2}) {
      if (nb == 2 && na != 2) continue;
      const Data<double> data = cast<double>(make_record(na, nb, 20 + na));
      for (IvMethod method : {IvMethod::kRsrivc, IvMethod::kRivsvf}) {
        for (bool kf : {true, false}) {
          const std::string what =
              std::string(method == IvMethod::kRsrivc ? "RSRIVC" : "RIVSVF") +
              (kf ? "-KF" : "-FF") + " na=" + std::to_string(na) +
              " nb=" + std::to_string(nb);
          long rejections[2] = {0, 0};
          compare_paths<double>(
              what, na + nb,
              [&](bool fixed, const RecursiveOutputs<double>& out) {
                return run_iv(iv_config<double>(na, nb, method, kf), fixed,
                              data.view(), out, &rejections[fixed ? 0 : 1]);
              },
              1e-12);
          EXPECT_EQ(rejections[0], rejections[1]) << what;
        }
      }
    }
  }
}

// Float: |fixed - dynamic| <= 2 |dynamic - double| + 100 eps (see the top).
template <typename RunFloat, typename RunDouble>
void compare_float_paths(const std::string& what, int np, RunFloat run_float,
                         RunDouble run_double) {
  Outputs<float> fixed, dynamic;
  Outputs<double> reference;
  ASSERT_TRUE(run_float(true, fixed.view(np)).ok()) << what;
  ASSERT_TRUE(run_float(false, dynamic.view(np)).ok()) << what;
  ASSERT_TRUE(run_double(reference.view(np)).ok()) << what;
  const double eps = std::numeric_limits<float>::epsilon();
  const double thm_error = relative_difference(dynamic.thm, reference.thm);
  const double yh_error = relative_difference(dynamic.yh, reference.yh);
  EXPECT_LT(thm_error, 1e-2) << what << ": float far from double";
  EXPECT_LE(relative_difference(fixed.thm, dynamic.thm),
            2 * thm_error + 100 * eps)
      << what << " THM (float error of the dynamic path "
      << test::scientific(thm_error) << ")";
  EXPECT_LE(relative_difference(fixed.yh, dynamic.yh),
            2 * yh_error + 100 * eps)
      << what << " YH (float error of the dynamic path "
      << test::scientific(yh_error) << ")";
}

TEST(FixedSize, SinglePrecisionAgreesToFloatRounding) {
  for (int na : {2, 4}) {
    const int nb = 1;
    const Record record = make_record(na, nb, 30 + na);
    const Data<float> data_f = cast<float>(record);
    const Data<double> data_d = cast<double>(record);
    compare_float_paths(
        "RLSSVF-KF na=" + std::to_string(na), na + nb,
        [&](bool fixed, const RecursiveOutputs<float>& out) {
          return run_rls(rlssvf_config<float>(na, nb, Variant::kKf), fixed,
                         data_f.view(), out);
        },
        [&](const RecursiveOutputs<double>& out) {
          return run_rls(rlssvf_config<double>(na, nb, Variant::kKf), false,
                         data_d.view(), out);
        });
    compare_float_paths(
        "RSRIVC-KF na=" + std::to_string(na), na + nb,
        [&](bool fixed, const RecursiveOutputs<float>& out) {
          return run_iv(iv_config<float>(na, nb, IvMethod::kRsrivc, true),
                        fixed, data_f.view(), out);
        },
        [&](const RecursiveOutputs<double>& out) {
          return run_iv(iv_config<double>(na, nb, IvMethod::kRsrivc, true),
                        false, data_d.view(), out);
        });
  }
}

// The online objects with compile-time sizes allocate nothing per sample,
// nor do the batch functions with YH: a record ten times longer costs the
// same number of allocations.
template <typename S>
void expect_no_allocation_per_sample() {
  const std::string type = sizeof(S) == 4 ? "float" : "double";
  {  // the counter counts
    const long probe = g_allocations.load();
    std::vector<S> allocated(100);
    ASSERT_GT(g_allocations.load(), probe);
  }
  for (Variant v : {Variant::kKf, Variant::kFf, Variant::kPotterKf,
                    Variant::kLmr}) {
    RlsSvf<S, 2, 3> estimator;
    ASSERT_TRUE(estimator.configure(rlssvf_config<S>(2, 1, v)).ok());
    const S one = 1;
    for (int k = 0; k < 5; ++k) estimator.update(&one, S(0.5), S(kTs));
    const long before = g_allocations.load();
    S sum = 0;
    for (int k = 0; k < 5000; ++k) {
      const S u = std::sin(S(0.1) * k) > 0 ? S(1) : S(-1);
      sum += estimator.update(&u, std::cos(S(0.2) * k), S(kTs))(0);
    }
    EXPECT_EQ(g_allocations.load() - before, 0)
        << "RlsSvf<" << type << ", 2, 3> " << name(v);
    EXPECT_TRUE(std::isfinite(sum));
  }
  for (IvMethod method : {IvMethod::kRsrivc, IvMethod::kRivsvf}) {
    RecursiveIv<S, 2, 3> estimator;
    RecursiveIvConfig<S> config = iv_config<S>(2, 1, method, true);
    config.t_s_iv = S(1);
    ASSERT_TRUE(estimator.configure(config).ok());
    for (int k = 0; k < 5; ++k) estimator.update(S(1), S(0.5));
    const long before = g_allocations.load();
    S sum = 0;
    for (int k = 0; k < 5000; ++k) {
      const S u = std::sin(S(0.1) * k) > 0 ? S(1) : S(-1);
      sum += estimator.update(&u, std::cos(S(0.2) * k), S(kTs))(0);
    }
    EXPECT_EQ(g_allocations.load() - before, 0)
        << "RecursiveIv<" << type << ", 2, 3>";
    EXPECT_TRUE(std::isfinite(sum));
  }
  {  // the frozen model of YH, refreshed every sample
    AuxiliaryModel<S, 2, 3> model;
    model.configure(siso_orders(2, 1, 0), InterSample::kZoh);
    VectorN<S, 3> theta(S(2.4), S(4), S(4));
    model.set_parameters(theta);
    const S one = 1;
    model.step(&one, S(kTs));
    const long before = g_allocations.load();
    S sum = 0;
    for (int k = 0; k < 5000; ++k) {
      theta(0) = S(2.4) + S(0.1) * std::sin(S(0.01) * k);
      model.set_parameters(theta);
      sum += model.step(&one, S(kTs));
    }
    EXPECT_EQ(g_allocations.load() - before, 0)
        << "AuxiliaryModel<" << type << ", 2, 3>";
    EXPECT_TRUE(std::isfinite(sum));
  }
  // Batch functions, with YH and PSET: allocations independent of N.
  const Record record = make_record(2, 1, 40);
  const Data<S> data = cast<S>(record);
  auto count = [&](Eigen::Index n, bool iv) {
    RecordView<S> view = data.view();
    view.num_samples = n;
    Outputs<S> out;
    RecursiveOutputs<S> o = out.view(3);
    const long before = g_allocations.load();
    Status status;
    if (iv) {
      RecursiveIvConfig<S> config = iv_config<S>(2, 1, IvMethod::kRsrivc, true);
      config.t_s_iv = S(1);
      status = run_iv(config, true, view, o);
    } else {
      status = run_rls(rlssvf_config<S>(2, 1, Variant::kKf), true, view, o);
    }
    EXPECT_TRUE(status.ok()) << status.message();
    return g_allocations.load() - before;
  };
  EXPECT_EQ(count(kSamples / 10, false), count(kSamples, false))
      << "run_rlssvf<" << type << ">";
  EXPECT_EQ(count(kSamples / 10, true), count(kSamples, true))
      << "run_recursive_iv<" << type << ">";
}

TEST(FixedSize, NoAllocationPerSampleInDouble) {
  expect_no_allocation_per_sample<double>();
}

TEST(FixedSize, NoAllocationPerSampleInSingle) {
  expect_no_allocation_per_sample<float>();
}

TEST(FixedSize, MismatchedSizesAreRefused) {
  RlsSvf<double, 2, 3> rls;
  const Status a = rls.configure(rlssvf_config<double>(3, 1, Variant::kKf));
  EXPECT_EQ(a.code(), ErrorCode::kBadInput);
  RlsSvfConfig<double> ic = rlssvf_config<double>(2, 1, Variant::kKf);
  ic.initial_conditions = true;
  ic.adaptation = ForgettingFactorAdaptation<double>(1);
  EXPECT_EQ(rls.configure(ic).code(), ErrorCode::kBadInput);
  RecursiveIv<double, 2, 3> iv;
  EXPECT_EQ(iv.configure(iv_config<double>(2, 2, IvMethod::kRsrivc, true))
                .code(),
            ErrorCode::kBadInput);
}

}  // namespace
}  // namespace ctid
