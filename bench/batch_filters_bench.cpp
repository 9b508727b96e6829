// SPDX-License-Identifier: BSD-3-Clause
// Copyright (C) the ctid authors
// The batch filters' regular-grid kernel (batch_filters.hpp) at a fixed
// order (the orders 1-6 and 8 that filter_derivatives dispatches to)
// against the same kernel with the order taken at run time, measured side
// by side in one run on the same signal. The refined-IV engine and the
// GPMF estimators spend most of their time here.
//
// The machine is shared and noisy: the two kernels run interleaved, round
// after round, and the program prints for each order the median over the
// rounds of the time per sample of each and their ratio (any-order /
// fixed; above 1: the fixed kernel is faster), and checks that both give
// the same columns.
//
//   build/bench/bench_batch_filters [rounds]      (default 9)
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <random>
#include <vector>

#include "ctid/filters/batch_filters.hpp"

namespace {

constexpr Eigen::Index kNumSamples = 200000;
constexpr double kTs = 0.01;

template <int N>
double seconds(const Eigen::VectorXd& d,
               const ctid::batch::CompanionFilter<double>& f,
               const std::vector<double>& s, Eigen::MatrixXd& out) {
  const auto start = std::chrono::steady_clock::now();
  ctid::batch::filter_regular_kernel<double, N>(
      d, 2.0, true, f.Phi(), f.g0(), f.g1(), s.data(), kNumSamples, out);
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start)
      .count();
}

double median(std::vector<double> v) {
  std::nth_element(v.begin(), v.begin() + v.size() / 2, v.end());
  return v[v.size() / 2];
}

template <int N>
void compare(const std::vector<double>& s, int rounds) {
  const Eigen::VectorXd d = ctid::svf_denominator<double>(N, 3.0);
  ctid::batch::CompanionFilter<double> filter(d, ctid::InterSample::kFoh);
  filter.ensure(kTs);
  Eigen::MatrixXd fixed(kNumSamples, N + 1), any(kNumSamples, N + 1);
  std::vector<double> t_fixed, t_any;
  for (int r = 0; r < rounds; ++r) {
    t_fixed.push_back(seconds<N>(d, filter, s, fixed));
    t_any.push_back(seconds<0>(d, filter, s, any));
  }
  const double a = median(t_fixed) / kNumSamples * 1e9;
  const double b = median(t_any) / kNumSamples * 1e9;
  std::printf("%5d %12.2f %12.2f %8.2f %12.2g\n", N, a, b, b / a,
              (fixed - any).cwiseAbs().maxCoeff());
}

}  // namespace

int main(int argc, char** argv) {
  const int rounds = argc > 1 ? std::max(1, std::atoi(argv[1])) : 9;
  std::mt19937 generator(1);
  std::uniform_real_distribution<double> uniform(-1, 1);
  std::vector<double> s(kNumSamples);
  for (double& v : s) v = uniform(generator);
  std::printf("%5s %12s %12s %8s %12s\n", "order", "fixed ns/s", "any ns/s",
              "ratio", "max |diff|");
  compare<1>(s, rounds);
  compare<2>(s, rounds);
  compare<3>(s, rounds);
  compare<4>(s, rounds);
  compare<5>(s, rounds);
  compare<6>(s, rounds);
  compare<8>(s, rounds);
  return 0;
}
