// Throughput of the recursive IV estimators of the core (RecursiveIv), in
// samples per second, on one core:
//
//   BM_RsrivcUpdate_KF    RecursiveIv::update(u, y, h) per sample, RSRIVC
//                         with the IV Kalman filter (eq. 2.29), Qn = 1e-4 I;
//                         the adaptive prefilter a2/A(p) and the auxiliary
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
//                         record and the writing of THM.
//
// Model nn = [2 1 0] (na = 2, nb = 1, nk = 0, three parameters [a1 a2 b0]),
// lambda_svf = 3.2, RLSSVF until tsiv = 100 s, then IV. Each iteration is
// one pass over a record of 1e5 samples generated once: a random binary
// (PRBS-like) input and the exact ZOH response of 4 / (p^2 + 2.4 p + 4) at
// Ts = 0.1 s plus white noise, as in rlssvf_bench.cpp. Items are samples, so
// items_per_second is samples/s; a summary in million samples/s follows the
// console table. A run whose final estimate is far from the true parameters
// is labelled DIVERGED (timed all the same); the counter `rejections` is the
// number of estimates refused by the stability test in the last pass. Run
// with --benchmark_format=json for machine use (the Octave script
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

namespace {

constexpr Eigen::Index kNumSamples = 100000;
constexpr double kTs = 0.1;
constexpr double kLambdaSvf = 3.2;
constexpr double kTsIv = 100;  // s: RLSSVF for the first 1000 samples
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

ctid::RecursiveIvConfig<double> iv_config(ctid::IvMethod method) {
  ctid::RecursiveIvConfig<double> config;
  config.orders = ctid::siso_orders(2, 1, 0);
  config.method = method;
  config.svf.lambda_svf = kLambdaSvf;
  config.ts = kTs;
  config.t_s_iv = kTsIv;
  config.dtupdate = 0;  // refresh every sample
  config.adaptation =
      ctid::KalmanAdaptation<double>(1e-4 * Eigen::MatrixXd::Identity(3, 3));
  return config;
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

void run_update_loop(benchmark::State& state, ctid::IvMethod method) {
  const BenchData& data = bench_data();
  ctid::RecursiveIv<double> estimator;
  const ctid::Status status = estimator.configure(iv_config(method));
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
  check_final_estimate(state, estimator.theta().data(), 1);
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

void BM_RunRecursiveIv_Rsrivc_Thm(benchmark::State& state) {
  const BenchData& data = bench_data();
  const ctid::RecursiveIvConfig<double> config =
      iv_config(ctid::IvMethod::kRsrivc);
  ctid::RecordView<double> record;
  record.y = data.y.data();
  record.u = data.u.data();
  record.num_samples = kNumSamples;
  record.num_inputs = 1;
  record.ts = kTs;
  std::vector<double> thm(kNumSamples * 3);
  ctid::RecursiveOutputs<double> out;
  out.thm = thm.data();
  long rejections = 0;
  for (auto _ : state) {
    const ctid::Status status = ctid::run_recursive_iv(
        config, record, ctid::ClosedLoopSignals<double>(), out, &rejections);
    if (!status.ok()) {
      state.SkipWithError(status.message().c_str());
      return;
    }
    benchmark::DoNotOptimize(thm.data());
    benchmark::ClobberMemory();
  }
  check_final_estimate(state, thm.data() + kNumSamples - 1, kNumSamples);
  state.counters["rejections"] = static_cast<double>(rejections);
  report_samples(state);
}

BENCHMARK(BM_RsrivcUpdate_KF)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_RivsvfUpdate_KF)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_RunRecursiveIv_Rsrivc_Thm)->Unit(benchmark::kMillisecond);

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
        "target for RSRIVC-KF: 1):\n",
        static_cast<long long>(kNumSamples));
    for (const auto& [name, rate] : rates_) {
      std::printf("  %-36s %8.3f\n", name.c_str(), rate / 1e6);
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
