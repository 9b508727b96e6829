// Long run of every recursive estimator under poor excitation (the
// scenario of tests/core/long_run_scenario.hpp: binary input for the first
// 10 % of the record, then constant), in double and single precision:
// reports per estimator whether P stayed finite with a positive definite
// symmetric part at every check, the smallest lambda_min / lambda_max of
// that symmetric part, on how many samples the covariance protection
// (core/include/ctid/adaptation/covariance_guard.hpp) acted and the first, the final
// estimate (true [2.4 4 4]) and the run time. Usage:
//   bench_long_run [samples (default 1e8)] [check_every (default 1)]
//                  [name filter, e.g. RSRIVC] [precision: both | double |
//                  single] [guard: on | off]
// Exit status 1 when any run lost P.
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "../tests/core/long_run_scenario.hpp"

namespace {

template <typename S>
bool run_all(const char* precision, long n, long every,
             const std::string& filter, bool guard) {
  bool ok = true;
  for (const auto& c : ctid::long_run::cases<S>(n)) {
    if (!filter.empty() && c.name.find(filter) == std::string::npos) continue;
    const auto start = std::chrono::steady_clock::now();
    const ctid::long_run::Result r = c.run(n, every, guard);
    const double seconds = std::chrono::duration<double>(
                               std::chrono::steady_clock::now() - start)
                               .count();
    const bool kept = r.first_nonfinite < 0 && r.first_indefinite < 0;
    ok = ok && kept;
    std::printf(
        "%-6s %-20s %s  min eig ratio %.3g  guard %ld (first %ld)  "
        "indefinite %ld (first %ld)  non-finite from %ld  "
        "theta_end [%.4g %.4g %.4g]  %.1f s\n",
        precision, c.name.c_str(), kept ? "P kept" : "P LOST",
        r.min_relative_eig, r.guard_actions, r.first_guard,
        r.indefinite_checks, r.first_indefinite, r.first_nonfinite,
        r.theta_end(0), r.theta_end(1), r.theta_end(2), seconds);
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
