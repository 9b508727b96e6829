// SPDX-License-Identifier: BSD-3-Clause
// Copyright (C) the ctid authors
// Throughput of the recursive IV estimators of the core (RecursiveIv), in
// samples per second, on one core, for model orders na = 1..4 (nb = 1,
// nk = 0), each with the fixed-size filter kernels (companion_kernels.hpp,
// dynamic:0, the default) and the dynamic-size reference (dynamic:1):
//
//   BM_RsrivcUpdate_KF    RecursiveIv::update(u, y, h) per sample, RSRIVC
//                         with the IV Kalman filter (eq. 2.29), Qn = 1e-4 I;
//                         the adaptive prefilter b0/A(p) and the auxiliary
//                         model are refreshed at every sample (dtupdate = 0,
//                         the same as dtupdate = Ts), so every sample redoes
//                         the stability test, one ZOH discretisation (a
//                         matrix exponential) and one trapezoidal one;
//   BM_RivsvfUpdate_KF    the same with RIVSVF: fixed SVF, only the auxiliary
//                         model is refreshed per sample (one matrix
//                         exponential);
//   BM_RunRecursiveIv_Rsrivc_Thm
//                         run_recursive_iv() over the record with THM only,
//                         RSRIVC-KF: what the gateway runs for
//                         thm = rsrivc (...), including the checks of the
//                         record and the writing of THM;
//   BM_RunRecursiveIv_Rsrivc_ThmYh
//                         the same with YH, the frozen model of each sample
//                         simulated along the record (eq. 1.60);
//   BM_RivsvfUpdate_FF    RIVSVF with the IV forgetting factor (eq. 2.30),
//                         lambda = 0.999;
//   BM_RlsSvfUpdate_Potter  RlsSvf::update per sample, PotterSVF (eq. 3.73,
//                         square-root Kalman filter), Qn = 1e-4 I;
//   BM_RlsSvfUpdate_Lmr   the same, LMR-RLSSVF (eq. 3.82), lambda = 0.999,
//                         Gamma = 1e-3 I.
// The fixed-size path (dynamic:0) takes the fixed-size filter kernels and
// the adaptation steps at compile-time size (adaptation.hpp: the
// least-squares and IV steps; potter.hpp, lmr.hpp); dynamic:1 takes the
// dynamic-size filter code and the same adaptation steps at runtime size
// (one source for both sizes, step_size.hpp).
//
// True systems b0/A(p) of unit static gain (na = 2: 4 / (p^2 + 2.4 p + 4)),
// lambda_svf = 3.2, RLSSVF until tsiv = 100 s, then IV. Each iteration is
// one pass over a record of 1e5 samples generated once: a random binary
// (PRBS-like) input and the exact ZOH response at Ts = 0.1 s plus white
// noise, as in rlssvf_bench.cpp. Items are samples, so items_per_second is
// samples/s; a summary in million samples/s follows the console table. A
// run whose final estimate is far from the true parameters is labelled
// DIVERGED (timed all the same); the counter `rejections` is the number of
// estimates refused by the stability test in the last pass. Run with
// --benchmark_format=json for machine use (the Octave script
// bench/rsrivc_octave_bench.m does).
#include <benchmark/benchmark.h>

#include <cmath>
#include <cstdio>
#include <cstring>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include "ctid/filters/discretization.hpp"
#include "ctid/recursive/recursive_iv.hpp"
#include "kernel_orders.hpp"

namespace {

constexpr Eigen::Index kNumSamples = 100000;
constexpr double kTs = 0.1;
constexpr double kLambdaSvf = 3.2;
constexpr double kTsIv = 100;  // s: RLSSVF for the first 1000 samples

// True denominators [a1 .. a_na] of b0 / A(p), na = 1..4, unit static gain
// (b0 = a_na); na = 2 is 4 / (p^2 + 2.4 p + 4).
const std::vector<double>& true_denominator(int na) {
  static const std::vector<std::vector<double>> a = {
      {2.0},                   // p + 2
      {2.4, 4.0},              // p^2 + 2.4 p + 4
      {3.0, 7.0, 5.0},         // (p + 1)(p^2 + 2 p + 5)
      {3.2, 8.4, 10.4, 8.0}};  // (p^2 + 1.2 p + 4)(p^2 + 2 p + 2)
  return a[na - 1];
}

struct BenchData {
  std::vector<double> u;
  std::vector<double> y;
  std::vector<double> theta;  // [a1 .. a_na b0]
};

// Random binary input that switches with probability 0.1 per sample (mean
// hold 10 samples), the exact ZOH response of the true system of order na,
// and output noise of standard deviation 0.05.
BenchData make_data(int na) {
  BenchData data;
  const std::vector<double>& a = true_denominator(na);
  data.theta = a;
  data.theta.push_back(a.back());
  data.u.resize(kNumSamples);
  data.y.resize(kNumSamples);
  const Eigen::VectorXd d = Eigen::Map<const Eigen::VectorXd>(a.data(), na);
  Eigen::MatrixXd G = Eigen::MatrixXd::Zero(na, 1);
  G(na - 1, 0) = 1;
  Eigen::MatrixXd Phi, Gamma;
  ctid::zoh_discretize<double>(ctid::companion_matrix<double>(d), G, kTs, Phi,
                               Gamma);
  std::mt19937_64 rng(20171127);
  std::bernoulli_distribution toggle(0.1);
  std::normal_distribution<double> noise(0.0, 0.05);
  double level = 1;
  Eigen::VectorXd z = Eigen::VectorXd::Zero(na);
  for (Eigen::Index k = 0; k < kNumSamples; ++k) {
    if (toggle(rng)) level = -level;
    data.u[k] = level;
    data.y[k] = data.theta[na] * z(0) + noise(rng);
    z = Phi * z + Gamma.col(0) * level;
  }
  return data;
}

const BenchData& bench_data(int na) {
  static const std::vector<BenchData> data = {make_data(1), make_data(2),
                                              make_data(3), make_data(4)};
  return data[na - 1];
}

// Benchmark arguments: na, then 0 for the fixed-size filter kernels
// (companion_kernels.hpp, the default) or 1 for the dynamic-size reference.
int order_of(const benchmark::State& state) { return int(state.range(0)); }
ctid::FilterKernels kernels_of(const benchmark::State& state) {
  return state.range(1) == 0 ? ctid::FilterKernels::kFixedSize
                             : ctid::FilterKernels::kDynamic;
}

ctid::RecursiveIvConfig<double> iv_config(ctid::IvMethod method, int na,
                                          ctid::FilterKernels kernels) {
  ctid::RecursiveIvConfig<double> config;
  config.orders = ctid::siso_orders(na, 1, 0);
  config.method = method;
  config.svf.lambda_svf = kLambdaSvf;
  config.svf.kernels = kernels;
  config.ts = kTs;
  config.t_s_iv = kTsIv;
  config.dtupdate = 0;  // refresh every sample
  config.adaptation = ctid::KalmanAdaptation<double>(
      1e-4 * Eigen::MatrixXd::Identity(na + 1, na + 1));
  return config;
}

// The last estimate should be near the true parameters; if it is not, the
// recursion diverged (or was optimised away) and the timing does not stand
// for a working estimator. It is still reported, flagged in the label, so
// that the cost of the arithmetic stays visible.
void check_final_estimate(benchmark::State& state, const BenchData& data,
                          const double* theta, Eigen::Index stride) {
  for (size_t i = 0; i < data.theta.size(); ++i) {
    if (!(std::abs(theta[i * stride] - data.theta[i]) <=
          0.1 * std::abs(data.theta[i]))) {
      state.SetLabel("DIVERGED: final estimate far from the truth");
      return;
    }
  }
}

void report_samples(benchmark::State& state) {
  state.SetItemsProcessed(static_cast<int64_t>(state.iterations()) *
                          kNumSamples);
}

void run_update_loop(benchmark::State& state, ctid::IvMethod method,
                     bool kalman = true) {
  const int na = order_of(state);
  const BenchData& data = bench_data(na);
  ctid::RecursiveIv<double> estimator;
  ctid::RecursiveIvConfig<double> config =
      iv_config(method, na, kernels_of(state));
  if (!kalman) {
    config.adaptation = ctid::ForgettingFactorAdaptation<double>(0.999);
  }
  const ctid::Status status = estimator.configure(config);
  if (!status.ok()) {
    state.SkipWithError(status.message().c_str());
    return;
  }
  const double* u = data.u.data();
  const double* y = data.y.data();
  for (auto _ : state) {
    estimator.reset();
    for (Eigen::Index k = 0; k < kNumSamples; ++k) {
      estimator.update(u + k, y[k], kTs);
    }
    benchmark::DoNotOptimize(estimator.theta().data());
    benchmark::ClobberMemory();
  }
  check_final_estimate(state, data, estimator.theta().data(), 1);
  state.counters["rejections"] =
      static_cast<double>(estimator.stability_rejections());
  report_samples(state);
}

void BM_RsrivcUpdate_KF(benchmark::State& state) {
  run_update_loop(state, ctid::IvMethod::kRsrivc);
}

void BM_RivsvfUpdate_KF(benchmark::State& state) {
  run_update_loop(state, ctid::IvMethod::kRivsvf);
}

void BM_RivsvfUpdate_FF(benchmark::State& state) {
  run_update_loop(state, ctid::IvMethod::kRivsvf, false);
}

// RlsSvf::update per sample in the square-root (Potter) or regularised
// (LMR) form, on the same records.
void run_rlssvf_loop(benchmark::State& state, ctid::UpdateForm form) {
  const int na = order_of(state);
  const BenchData& data = bench_data(na);
  ctid::RlsSvfConfig<double> config;
  config.orders = ctid::siso_orders(na, 1, 0);
  config.svf.lambda_svf = kLambdaSvf;
  config.svf.kernels = kernels_of(state);
  config.ts = kTs;
  config.form = form;
  const Eigen::MatrixXd identity = Eigen::MatrixXd::Identity(na + 1, na + 1);
  if (form == ctid::UpdateForm::kPotter) {
    config.adaptation = ctid::KalmanAdaptation<double>(1e-4 * identity);
  } else {
    config.adaptation = ctid::ForgettingFactorAdaptation<double>(0.999);
    config.lmr_gamma = 1e-3 * identity;
  }
  ctid::RlsSvf<double> estimator;
  const ctid::Status status = estimator.configure(config);
  if (!status.ok()) {
    state.SkipWithError(status.message().c_str());
    return;
  }
  const double* u = data.u.data();
  const double* y = data.y.data();
  for (auto _ : state) {
    estimator.reset();
    for (Eigen::Index k = 0; k < kNumSamples; ++k) {
      estimator.update(u + k, y[k], kTs);
    }
    benchmark::DoNotOptimize(estimator.theta().data());
    benchmark::ClobberMemory();
  }
  check_final_estimate(state, data, estimator.theta().data(), 1);
  report_samples(state);
}

void BM_RlsSvfUpdate_Potter(benchmark::State& state) {
  run_rlssvf_loop(state, ctid::UpdateForm::kPotter);
}

void BM_RlsSvfUpdate_Lmr(benchmark::State& state) {
  run_rlssvf_loop(state, ctid::UpdateForm::kLevenbergMarquardt);
}

void run_batch(benchmark::State& state, bool with_yh) {
  const int na = order_of(state);
  const BenchData& data = bench_data(na);
  const ctid::RecursiveIvConfig<double> config =
      iv_config(ctid::IvMethod::kRsrivc, na, kernels_of(state));
  ctid::RecordView<double> record;
  record.y = data.y.data();
  record.u = data.u.data();
  record.num_samples = kNumSamples;
  record.num_inputs = 1;
  record.ts = kTs;
  std::vector<double> thm(kNumSamples * (na + 1)), yh(kNumSamples);
  ctid::RecursiveOutputs<double> out;
  out.thm = thm.data();
  if (with_yh) out.yh = yh.data();
  long rejections = 0;
  for (auto _ : state) {
    const ctid::Status status = ctid::run_recursive_iv(
        config, record, ctid::ClosedLoopSignals<double>(), out, &rejections);
    if (!status.ok()) {
      state.SkipWithError(status.message().c_str());
      return;
    }
    benchmark::DoNotOptimize(thm.data());
    benchmark::DoNotOptimize(yh.data());
    benchmark::ClobberMemory();
  }
  check_final_estimate(state, data, thm.data() + kNumSamples - 1, kNumSamples);
  state.counters["rejections"] = static_cast<double>(rejections);
  report_samples(state);
}

void BM_RunRecursiveIv_Rsrivc_Thm(benchmark::State& state) {
  run_batch(state, false);
}

void BM_RunRecursiveIv_Rsrivc_ThmYh(benchmark::State& state) {
  run_batch(state, true);
}

BENCHMARK(BM_RsrivcUpdate_KF)->Apply(orders_and_kernels);
BENCHMARK(BM_RivsvfUpdate_KF)->Apply(orders_and_kernels);
BENCHMARK(BM_RunRecursiveIv_Rsrivc_Thm)->Apply(orders_and_kernels);
BENCHMARK(BM_RunRecursiveIv_Rsrivc_ThmYh)->Apply(orders_and_kernels);
BENCHMARK(BM_RivsvfUpdate_FF)->Apply(orders_and_kernels);
BENCHMARK(BM_RlsSvfUpdate_Potter)->Apply(orders_and_kernels);
BENCHMARK(BM_RlsSvfUpdate_Lmr)->Apply(orders_and_kernels);

// The console table, then one line per benchmark in million samples/s.
class SummaryReporter : public benchmark::ConsoleReporter {
 public:
  SummaryReporter() : benchmark::ConsoleReporter(OO_None) {}

  void ReportRuns(const std::vector<Run>& runs) override {
    benchmark::ConsoleReporter::ReportRuns(runs);
    for (const Run& run : runs) {
      // The coefficient of variation is a fraction, not a rate.
      if (run.error_occurred || run.aggregate_name == "cv") continue;
      const auto rate = run.counters.find("items_per_second");
      if (rate == run.counters.end()) continue;
      rates_.emplace_back(run.benchmark_name(), rate->second.value);
    }
  }

  void Finalize() override {
    benchmark::ConsoleReporter::Finalize();
    if (rates_.empty()) return;
    std::printf(
        "\nThroughput (million samples/s, %lld samples per pass; "
        "bar for RSRIVC-KF na = 2: 3):\n",
        static_cast<long long>(kNumSamples));
    for (const auto& [name, rate] : rates_) {
      std::printf("  %-48s %8.3f\n", name.c_str(), rate / 1e6);
    }
    std::fflush(stdout);
  }

 private:
  std::vector<std::pair<std::string, double>> rates_;
};

// True unless another output format than the console was asked for.
bool console_format(int argc, char** argv) {
  const char* flag = "--benchmark_format=";
  for (int i = 1; i < argc; ++i) {
    if (std::strncmp(argv[i], flag, std::strlen(flag)) == 0) {
      return std::strcmp(argv[i] + std::strlen(flag), "console") == 0;
    }
  }
  return true;
}

}  // namespace

int main(int argc, char** argv) {
  const bool console = console_format(argc, argv);
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  if (console) {
    SummaryReporter reporter;
    benchmark::RunSpecifiedBenchmarks(&reporter);
  } else {
    benchmark::RunSpecifiedBenchmarks();
  }
  benchmark::Shutdown();
  return 0;
}
