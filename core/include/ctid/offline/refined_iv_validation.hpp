// SPDX-License-Identifier: BSD-3-Clause
// Copyright (C) the ctid authors
// Validation of a refined-IV problem, its settings and data
// (refined_iv_problem.hpp) before the engine runs: every bad input is a
// Status with a clear message, never a crash or a silently wrong answer.
#pragma once

#include <cmath>
#include <string>

#include "ctid/offline/refined_iv_problem.hpp"

namespace ctid {
namespace riv_detail {

template <typename S>
Status validate(const RivProblem<S>& problem, const RivSettings<S>& settings,
                const RivData<S>& data, RivResult<S>* result) {
  if (result == nullptr) return bad_input("the result output is null");
  if (data.y == nullptr) return bad_input("the record needs y");
  if (problem.nf.empty()) return bad_input("the model needs a denominator");
  for (int n : problem.nf) {
    if (n < 1) return bad_input("every denominator order must be >= 1");
  }
  if (problem.channels.empty()) return bad_input("the model needs an input");
  if (data.w == nullptr) return bad_input("the record needs the inputs");
  std::vector<int> used(problem.nf.size(), 0);
  int total_nb = 0;
  for (const RivChannel& c : problem.channels) {
    if (c.group < 0 || c.group >= problem.num_groups()) {
      return bad_input("a channel names a denominator that does not exist");
    }
    if (c.nb < 0 || c.nb > problem.nf[c.group] + 1) {
      return bad_input("nb = " + std::to_string(c.nb) +
                       " gives an improper model: nb must be <= nf + 1 = " +
                       std::to_string(problem.nf[c.group] + 1));
    }
    if (c.nk < 0) return bad_input("nk must be >= 0");
    if (!(c.delay >= 0) || !std::isfinite(c.delay)) {
      return bad_input("a channel delay must be finite and >= 0");
    }
    if (c.delay > 0 && problem.closed_loop()) {
      return Status(ErrorCode::kBadOption,
                    "a continuous delay is not supported in closed loop");
    }
    if (c.nk > 0 && data.instants != nullptr) {
      return bad_input("nk must be 0 for irregularly sampled data");
    }
    used[c.group] += c.nb;
    total_nb += c.nb;
  }
  if (total_nb == 0) {
    return bad_input("the model needs at least one numerator parameter");
  }
  for (int g = 0; g < problem.num_groups(); ++g) {
    if (used[g] == 0) {
      return bad_input("denominator " + std::to_string(g + 1) +
                       " has no numerator parameter");
    }
  }
  const int np = problem.num_parameters();
  if (!problem.fixed.empty()) {
    if (static_cast<int>(problem.fixed.size()) != np ||
        problem.fixed_values.size() != np) {
      return dimension_mismatch("fixed and its values need " +
                                std::to_string(np) + " entries");
    }
    for (int i = 0; i < np; ++i) {
      if (problem.fixed[i] && !std::isfinite(problem.fixed_values(i))) {
        return bad_input("fixed values must be finite");
      }
    }
  }
  const Eigen::Index n = data.num_samples;
  if (n < 2 * np + 2) {
    return bad_input("the record has " + std::to_string(n) +
                     " samples, too few for " + std::to_string(np) +
                     " parameters");
  }
  const Eigen::Index m = static_cast<Eigen::Index>(problem.channels.size());
  for (Eigen::Index k = 0; k < n; ++k) {
    if (!std::isfinite(data.y[k])) {
      return bad_input("y must be finite (sample " + std::to_string(k + 1) +
                       " is not)");
    }
  }
  for (Eigen::Index k = 0; k < n * m; ++k) {
    if (!std::isfinite(data.w[k])) {
      return bad_input("the inputs must be finite (sample " +
                       std::to_string(k % n + 1) + " is not)");
    }
  }
  if (data.instants == nullptr) {
    if (!(data.ts > 0) || !std::isfinite(data.ts)) {
      return bad_input("the sampling interval Ts must be finite and > 0");
    }
  } else {
    for (Eigen::Index k = 1; k < n; ++k) {
      if (!(data.instants[k] > data.instants[k - 1])) {
        return bad_input("the sampling instants must be strictly increasing");
      }
    }
  }
  if (!(settings.tolerance > 0)) return bad_input("the tolerance must be > 0");
  if (settings.max_iterations < 0) {
    return bad_input("the maximum number of iterations must be >= 0");
  }
  if (settings.max_starts < 1) {
    return Status(ErrorCode::kBadOption, "max_starts must be >= 1");
  }
  if (!(settings.time_scale >= 0) || !std::isfinite(settings.time_scale)) {
    return Status(ErrorCode::kBadOption,
                  "the time scale must be finite and >= 0 (0: automatic)");
  }
  if (!(settings.integrator_pole >= 0) ||
      !std::isfinite(settings.integrator_pole)) {
    return Status(ErrorCode::kBadOption,
                  "the integrator pole must be finite and >= 0 (0: automatic)");
  }
  for (S c : settings.cutoffs) {
    if (!(c > 0) || !std::isfinite(c)) {
      return bad_input("the cut-off frequencies must be finite and > 0");
    }
  }
  if (settings.theta_init.size() != 0 && settings.theta_init.size() != np) {
    return dimension_mismatch("the initial estimate must have " +
                              std::to_string(np) + " parameters");
  }
  if (settings.theta_init.size() != 0 && !settings.theta_init.allFinite()) {
    return bad_input("the initial estimate must be finite");
  }
  if (problem.continuous_loop() && problem.discrete_controller != nullptr) {
    return bad_input("give a continuous or a discrete controller, not both");
  }
  if (problem.closed_loop() && (problem.num_groups() != 1 || m != 1)) {
    return bad_input("closed-loop estimation needs a single input");
  }
  if (problem.discrete_controller != nullptr) {
    if (problem.channels[0].rule != InterSample::kZoh) {
      return bad_input(
          "closed-loop estimation needs ZOH data (the controller output is "
          "held between samples)");
    }
    const Status c = validate_controller(*problem.discrete_controller);
    if (!c.ok()) return bad_input("controller: " + c.message());
    if (problem.r1 == nullptr || problem.r2 == nullptr) {
      return bad_input("closed-loop estimation needs r1 and r2");
    }
    for (Eigen::Index k = 0; k < n; ++k) {
      if (!std::isfinite(problem.r1[k]) || !std::isfinite(problem.r2[k])) {
        return bad_input("r1 and r2 must be finite (sample " +
                         std::to_string(k + 1) + " is not)");
      }
    }
  }
  if (problem.continuous_loop()) {
    if (problem.reference == nullptr) {
      return bad_input("closed-loop estimation needs the reference r");
    }
    if (problem.controller_den.size() < problem.controller_num.size() ||
        problem.controller_den.size() == 0 || problem.controller_den(0) == 0) {
      return bad_input(
          "the controller must be proper with a nonzero leading "
          "denominator coefficient");
    }
    if (problem.channels[0].nk != 0) {
      return Status(ErrorCode::kBadOption,
                    "a delay nk > 0 is not supported with a continuous-time "
                    "controller");
    }
    for (Eigen::Index k = 0; k < n; ++k) {
      if (!std::isfinite(problem.reference[k]) ||
          (problem.r1 != nullptr && !std::isfinite(problem.r1[k]))) {
        return bad_input("the reference must be finite");
      }
    }
  }
  return Status::Ok();
}

}  // namespace riv_detail
}  // namespace ctid
