// Long run of every recursive estimator under poor excitation (the
// scenario of tests/core/long_run_scenario.hpp: binary input for the first
// 10 % of the record, then constant), in double and single precision:
// reports per estimator whether P stayed finite with a positive definite
// symmetric part at every check, the smallest lambda_min / lambda_max of
// that symmetric part, how many samples the covariance protection
// (core/include/ctid/covariance_guard.hpp) acted on, the final estimate
// and the run time. Usage:
//   bench_long_run [samples (default 1e8)] [check_every (default 10000)]
//                  [name filter, e.g. RSRIVC]
// Exit status 1 when any run lost P.
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "../tests/core/long_run_scenario.hpp"

namespace {

template <typename S>
bool run_all(const char* precision, long n, long every,
             const std::string& filter) {
  bool ok = true;
  for (const auto& c : ctid::long_run::cases<S>(n)) {
    if (!filter.empty() && c.name.find(filter) == std::string::npos) continue;
    const auto start = std::chrono::steady_clock::now();
    const ctid::long_run::Result r = c.run(n, every);
    const double seconds = std::chrono::duration<double>(
                               std::chrono::steady_clock::now() - start)
                               .count();
    const bool kept = r.first_nonfinite < 0 && r.first_indefinite < 0;
    ok = ok && kept;
    std::printf(
        "%-6s %-17s %s  min eig ratio %.3g  guard %ld  first indefinite "
        "%ld  first non-finite %ld  theta_end [%.4g %.4g %.4g]  %.1f s\n",
        precision, c.name.c_str(), kept ? "P kept" : "P LOST",
        r.min_relative_eig, r.guard_actions, r.first_indefinite,
        r.first_nonfinite, r.theta_end(0), r.theta_end(1), r.theta_end(2),
        seconds);
    std::fflush(stdout);
  }
  return ok;
}

}  // namespace

int main(int argc, char** argv) {
  const long n = argc > 1 ? std::atol(argv[1]) : 100000000L;
  const long every = argc > 2 ? std::atol(argv[2]) : 10000L;
  const std::string filter = argc > 3 ? argv[3] : "";
  std::printf("%ld samples, P checked every %ld\n", n, every);
  const bool d = run_all<double>("double", n, every, filter);
  const bool f = run_all<float>("single", n, every, filter);
  return d && f ? 0 : 1;
}
