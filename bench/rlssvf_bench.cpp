// Throughput of RLSSVF in the core, in samples per second, on one core:
//
//   BM_RlsSvfUpdate_KF    RlsSvf::update(u, y) per sample, Kalman filter
//                         adaptation (RLSSVF-KF, eq. 1.59), na = 2, nb = 1;
//   BM_RlsSvfUpdate_FF    the same with a forgetting factor of 0.999
//                         (eq. 1.57);
//   BM_RunRlsSvf_Thm      run_rlssvf() over the record, THM only;
//   BM_RunRlsSvf_ThmYh    run_rlssvf() with THM and YH. YH simulates the
//                         frozen model of every sample (eq. 1.60), whose
//                         denominator changes at every sample, so the ZOH
//                         discretisation (a matrix exponential) is redone per
//                         sample: expect it to be much slower.
//
// Each iteration is one pass over a record of 1e6 samples generated once:
// a random binary (PRBS-like) input and the ZOH response of
// 4 / (p^2 + 2.4 p + 4) at Ts = 0.1 s plus white noise. Items are samples,
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

namespace {

constexpr Eigen::Index kNumSamples = 1000000;
constexpr double kTs = 0.1;
constexpr double kLambdaSvf = 3.2;
constexpr double kForgettingFactor = 0.999;
// True parameters [a1 a2 b0] of 4 / (p^2 + 2.4 p + 4).
const double kTheta[3] = {2.4, 4.0, 4.0};

struct BenchData {
  std::vector<double> u;
  std::vector<double> y;
};

// Random binary input that switches with probability 0.1 per sample (mean
// hold 10 samples, rich enough for the 3 parameters), the exact ZOH response
// of the true system, and output noise of standard deviation 0.05.
BenchData make_data() {
  BenchData data;
  data.u.resize(kNumSamples);
  data.y.resize(kNumSamples);
  Eigen::VectorXd d(2);
  d << kTheta[0], kTheta[1];
  Eigen::MatrixXd G = Eigen::MatrixXd::Zero(2, 1);
  G(1, 0) = 1;
  Eigen::MatrixXd Phi, Gamma;
  ctid::zoh_discretize<double>(ctid::companion_matrix<double>(d), G, kTs, Phi,
                               Gamma);
  std::mt19937_64 rng(20171127);
  std::bernoulli_distribution toggle(0.1);
  std::normal_distribution<double> noise(0.0, 0.05);
  double level = 1;
  Eigen::Vector2d z = Eigen::Vector2d::Zero();
  for (Eigen::Index k = 0; k < kNumSamples; ++k) {
    if (toggle(rng)) level = -level;
    data.u[k] = level;
    data.y[k] = kTheta[2] * z(0) + noise(rng);
    z = Phi * z + Gamma.col(0) * level;
  }
  return data;
}

const BenchData& bench_data() {
  static const BenchData data = make_data();
  return data;
}

ctid::RlsSvfConfig<double> kf_config() {
  ctid::RlsSvfConfig<double> config;
  config.orders = ctid::siso_orders(2, 1, 0);
  config.svf.lambda_svf = kLambdaSvf;
  config.adaptation =
      ctid::KalmanAdaptation<double>(1e-4 * Eigen::MatrixXd::Identity(3, 3));
  config.ts = kTs;
  return config;
}

ctid::RlsSvfConfig<double> ff_config() {
  ctid::RlsSvfConfig<double> config = kf_config();
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
void check_final_estimate(benchmark::State& state, const double* theta,
                          Eigen::Index stride) {
  for (int i = 0; i < 3; ++i) {
    if (!(std::abs(theta[i * stride] - kTheta[i]) <= 0.1 * kTheta[i])) {
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
  const BenchData& data = bench_data();
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
  check_final_estimate(state, estimator.theta().data(), 1);
  report_samples(state);
}

void BM_RlsSvfUpdate_KF(benchmark::State& state) {
  run_update_loop(state, kf_config());
}

void BM_RlsSvfUpdate_FF(benchmark::State& state) {
  run_update_loop(state, ff_config());
}

void run_batch(benchmark::State& state, bool with_yh) {
  const BenchData& data = bench_data();
  const ctid::RlsSvfConfig<double> config = kf_config();
  const ctid::RecordView<double> record = record_view(data);
  std::vector<double> thm(kNumSamples * 3);
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
  check_final_estimate(state, thm.data() + kNumSamples - 1, kNumSamples);
  report_samples(state);
}

void BM_RunRlsSvf_Thm(benchmark::State& state) { run_batch(state, false); }

void BM_RunRlsSvf_ThmYh(benchmark::State& state) { run_batch(state, true); }

BENCHMARK(BM_RlsSvfUpdate_KF)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_RlsSvfUpdate_FF)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_RunRlsSvf_Thm)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_RunRlsSvf_ThmYh)->Unit(benchmark::kMillisecond);

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
      std::printf("  %-28s %8.3f\n", name.c_str(), rate / 1e6);
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
