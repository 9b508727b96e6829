// SPDX-License-Identifier: BSD-3-Clause
// Copyright (C) the ctid authors
// Long run of every recursive estimator under poor excitation (the
// scenario of tests/core/long_run_scenario.hpp: binary input for the first
// 10 % of the record, then constant), in double and single precision:
// reports per estimator (the 18 cases of long_run::cases: RLSSVF FF(1),
// FF(0.999), KF; Potter KF, FF(1); LMR FF(0.998); RIVSVF, RSRIVC,
// CLRIVSVF, CLRSRIVC each FF(1), KF, FF(0.999)+AW) whether P stayed finite
// with a positive definite symmetric part at every check (LMR: P = R^-1
// from R's factor; decided by a Cholesky in double of the stored entries,
// with the samples where a Cholesky in the run's own precision failed
// counted apart: see long_run_scenario.hpp), the smallest lambda_min / lambda_max of that symmetric
// part, on how many samples the covariance protection
// (core/include/ctid/adaptation/covariance_guard.hpp; for LMR its guard on
// R, lmr.hpp) acted, the first, how many were repairs and ceilings, the
// final estimate (true [2.4 4 4]), the run time and the throughput in
// millions of samples per second (checks included). Usage:
//   bench_long_run [samples (default 1e8)] [check_every (default 1)]
//                  [name filter, e.g. RSRIVC or LMR,Potter]
//                  [precision: both | double | single] [guard: on | off]
// Exit status 1 when any run lost P.
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "../tests/core/long_run_scenario.hpp"

namespace {

// Empty filter: every case; otherwise a comma-separated list of parts of
// names, any of which selects a case.
bool selected(const std::string& name, const std::string& filter) {
  if (filter.empty()) return true;
  std::size_t begin = 0;
  while (begin <= filter.size()) {
    std::size_t end = filter.find(',', begin);
    if (end == std::string::npos) end = filter.size();
    const std::string part = filter.substr(begin, end - begin);
    if (!part.empty() && name.find(part) != std::string::npos) return true;
    begin = end + 1;
  }
  return false;
}

template <typename S>
bool run_all(const char* precision, long n, long every,
             const std::string& filter, bool guard) {
  bool ok = true;
  for (const auto& c : ctid::long_run::cases<S>(n)) {
    if (!selected(c.name, filter)) continue;
    const auto start = std::chrono::steady_clock::now();
    // A line every 10^7 samples, so that a run cut short still says how
    // far P was kept.
    ctid::long_run::progress_interval = 10000000L;
    ctid::long_run::progress = [&](long k, const ctid::long_run::Result& r) {
      const double s = std::chrono::duration<double>(
                           std::chrono::steady_clock::now() - start)
                           .count();
      std::printf("  progress %s %s: %ld samples, %s, guard %ld, %.1f s\n",
                  precision, c.name.c_str(), k,
                  r.first_nonfinite < 0 && r.first_indefinite < 0
                      ? "P kept so far"
                      : "P LOST",
                  r.guard_actions, s);
      std::fflush(stdout);
    };
    const ctid::long_run::Result r = c.run(n, every, guard);
    const double seconds = std::chrono::duration<double>(
                               std::chrono::steady_clock::now() - start)
                               .count();
    const bool kept = r.first_nonfinite < 0 && r.first_indefinite < 0;
    ok = ok && kept;
    std::printf(
        "%-6s %-20s %s  min eig ratio %.3g  guard %ld (first %ld; repair "
        "%ld, ceiling %ld)  indefinite %ld (first %ld)  Cholesky in %s "
        "failed %ld  non-finite from %ld  "
        "theta_end [%.4g %.4g %.4g]  %.1f s  %.3f M samples/s\n",
        precision, c.name.c_str(), kept ? "P kept" : "P LOST",
        r.min_relative_eig, r.guard_actions, r.first_guard, r.guard_repairs,
        r.guard_ceilings, r.indefinite_checks, r.first_indefinite, precision,
        r.precision_cholesky_failures,
        r.first_nonfinite, r.theta_end(0), r.theta_end(1), r.theta_end(2),
        seconds, n / seconds / 1e6);
    std::fflush(stdout);
  }
  return ok;
}

}  // namespace

int main(int argc, char** argv) {
  const long n = argc > 1 ? std::atol(argv[1]) : 100000000L;
  const long every = argc > 2 ? std::atol(argv[2]) : 1L;
  const std::string filter = argc > 3 ? argv[3] : "";
  const std::string precision = argc > 4 ? argv[4] : "both";
  const bool guard = !(argc > 5 && std::string(argv[5]) == "off");
  std::printf("%ld samples, P checked every %ld, guard %s\n", n, every,
              guard ? "on" : "off");
  bool ok = true;
  if (precision != "single") {
    ok = run_all<double>("double", n, every, filter, guard) && ok;
  }
  if (precision != "double") {
    ok = run_all<float>("single", n, every, filter, guard) && ok;
  }
  return ok ? 0 : 1;
}
