// SPDX-License-Identifier: BSD-3-Clause
// Copyright (C) the ctid authors
// Throughput of RLSSVF in the core, in samples per second, on one core,
// for na = 1..4 (nb = 1, nk = 0), each with the fixed-size filter kernels
// (companion_kernels.hpp, dynamic:0, the default) and the dynamic-size
// reference (dynamic:1):
//
//   BM_RlsSvfUpdate_KF    RlsSvf::update(u, y) per sample, Kalman filter
//                         adaptation (RLSSVF-KF, eq. 1.59);
//   BM_RlsSvfUpdate_FF    the same with a forgetting factor of 0.999
//                         (eq. 1.57);
//   BM_RunRlsSvf_Thm      run_rlssvf() over the record, THM only;
//   BM_RunRlsSvf_ThmYh    run_rlssvf() with THM and YH. YH simulates the
//                         frozen model of every sample (eq. 1.60), whose
//                         denominator changes at every sample, so the ZOH
//                         discretisation (a matrix exponential) is redone per
//                         sample.
//
// Each iteration is one pass over a record of 1e6 samples generated once:
// a random binary (PRBS-like) input and the ZOH response of b0/A(p) of unit
// static gain (na = 2: 4 / (p^2 + 2.4 p + 4)) at Ts = 0.1 s plus white
// noise. Items are samples,
// so items_per_second is samples/s; a summary in million samples/s follows
// the console table. A run whose final estimate is far from the true
// parameters is labelled DIVERGED (timed all the same). Run with
// --benchmark_format=json for machine use (the Octave script
// bench/rlssvf_octave_bench.m does).
#include <benchmark/benchmark.h>

#include <cmath>
#include <cstdio>
#include <cstring>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include "ctid/filters/discretization.hpp"
#include "ctid/recursive/rlssvf.hpp"
#include "kernel_orders.hpp"

namespace {

constexpr Eigen::Index kNumSamples = 1000000;
constexpr double kTs = 0.1;
constexpr double kLambdaSvf = 3.2;
constexpr double kForgettingFactor = 0.999;

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
  static std::vector<BenchData> data(4);
  if (data[na - 1].u.empty()) data[na - 1] = make_data(na);
  return data[na - 1];
}

// Benchmark arguments: na, then 0 for the fixed-size filter kernels
// (companion_kernels.hpp, the default) or 1 for the dynamic-size reference.
int order_of(const benchmark::State& state) { return int(state.range(0)); }
ctid::FilterKernels kernels_of(const benchmark::State& state) {
  return state.range(1) == 0 ? ctid::FilterKernels::kFixedSize
                             : ctid::FilterKernels::kDynamic;
}

ctid::RlsSvfConfig<double> kf_config(const benchmark::State& state) {
  const int na = order_of(state);
  ctid::RlsSvfConfig<double> config;
  config.orders = ctid::siso_orders(na, 1, 0);
  config.svf.lambda_svf = kLambdaSvf;
  config.svf.kernels = kernels_of(state);
  config.adaptation = ctid::KalmanAdaptation<double>(
      1e-4 * Eigen::MatrixXd::Identity(na + 1, na + 1));
  config.ts = kTs;
  return config;
}

ctid::RlsSvfConfig<double> ff_config(const benchmark::State& state) {
  ctid::RlsSvfConfig<double> config = kf_config(state);
  config.adaptation =
      ctid::ForgettingFactorAdaptation<double>(kForgettingFactor);
  return config;
}

ctid::RecordView<double> record_view(const BenchData& data) {
  ctid::RecordView<double> record;
  record.y = data.y.data();
  record.u = data.u.data();
  record.num_samples = kNumSamples;
  record.num_inputs = 1;
  record.ts = kTs;
  return record;
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

void run_update_loop(benchmark::State& state,
                     const ctid::RlsSvfConfig<double>& config) {
  const BenchData& data = bench_data(order_of(state));
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
    for (Eigen::Index k = 0; k < kNumSamples; ++k) estimator.update(u[k], y[k]);
    benchmark::DoNotOptimize(estimator.theta().data());
    benchmark::ClobberMemory();
  }
  check_final_estimate(state, data, estimator.theta().data(), 1);
  report_samples(state);
}

void BM_RlsSvfUpdate_KF(benchmark::State& state) {
  run_update_loop(state, kf_config(state));
}

void BM_RlsSvfUpdate_FF(benchmark::State& state) {
  run_update_loop(state, ff_config(state));
}

void run_batch(benchmark::State& state, bool with_yh) {
  const int na = order_of(state);
  const BenchData& data = bench_data(na);
  const ctid::RlsSvfConfig<double> config = kf_config(state);
  const ctid::RecordView<double> record = record_view(data);
  std::vector<double> thm(kNumSamples * (na + 1));
  std::vector<double> yh(with_yh ? kNumSamples : 0);
  ctid::RecursiveOutputs<double> out;
  out.thm = thm.data();
  out.yh = with_yh ? yh.data() : nullptr;
  for (auto _ : state) {
    const ctid::Status status = ctid::run_rlssvf(config, record, out);
    if (!status.ok()) {
      state.SkipWithError(status.message().c_str());
      return;
    }
    benchmark::DoNotOptimize(thm.data());
    benchmark::DoNotOptimize(yh.data());
    benchmark::ClobberMemory();
  }
  check_final_estimate(state, data, thm.data() + kNumSamples - 1, kNumSamples);
  report_samples(state);
}

void BM_RunRlsSvf_Thm(benchmark::State& state) { run_batch(state, false); }

void BM_RunRlsSvf_ThmYh(benchmark::State& state) { run_batch(state, true); }

BENCHMARK(BM_RlsSvfUpdate_KF)->Apply(orders_and_kernels);
BENCHMARK(BM_RlsSvfUpdate_FF)->Apply(orders_and_kernels);
BENCHMARK(BM_RunRlsSvf_Thm)->Apply(orders_and_kernels);
BENCHMARK(BM_RunRlsSvf_ThmYh)->Apply(orders_and_kernels);

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
    std::printf("\nThroughput (million samples/s, %lld samples per pass):\n",
                static_cast<long long>(kNumSamples));
    for (const auto& [name, rate] : rates_) {
      std::printf("  %-40s %8.3f\n", name.c_str(), rate / 1e6);
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
