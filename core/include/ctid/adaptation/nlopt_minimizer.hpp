// SPDX-License-Identifier: BSD-3-Clause
// Copyright (C) the ctid authors
// NLopt as the bounded minimiser of the Qn search (qn_ml.hpp). A separate
// header so that the numerical core needs no optimisation library: include
// it where NLopt is linked (the CMake target ctid::nlopt, the qnml gateway).
//
// Derivative-free and bounded: BOBYQA (Powell's quadratic-model trust
// region) for two or more free elements; NLopt's BOBYQA needs at least two,
// so one free element uses COBYLA. Both stop when the step in log10 q falls
// below settings.xtol_log10 or after settings.max_evaluations evaluations.
#pragma once

#include <nlopt.h>

#include <algorithm>
#include <functional>
#include <string>
#include <vector>

#include "ctid/adaptation/qn_ml.hpp"

namespace ctid {

namespace detail {
struct NloptObjective {
  const std::function<double(const std::vector<double>&)>* f;
  std::vector<double> x;
  int evaluations = 0;
};

inline double nlopt_objective(unsigned n, const double* x, double* grad,
                              void* data) {
  (void)grad;  // derivative-free algorithms only
  auto* objective = static_cast<NloptObjective*>(data);
  objective->x.assign(x, x + n);
  ++objective->evaluations;
  return (*objective->f)(objective->x);
}

inline const char* nlopt_result_text(nlopt_result r) {
  switch (r) {
    case NLOPT_SUCCESS:
      return "success";
    case NLOPT_STOPVAL_REACHED:
      return "stopval reached";
    case NLOPT_FTOL_REACHED:
      return "ftol reached";
    case NLOPT_XTOL_REACHED:
      return "xtol reached";
    case NLOPT_MAXEVAL_REACHED:
      return "maximum number of evaluations reached";
    case NLOPT_MAXTIME_REACHED:
      return "maximum time reached";
    case NLOPT_FAILURE:
      return "generic failure";
    case NLOPT_INVALID_ARGS:
      return "invalid arguments";
    case NLOPT_OUT_OF_MEMORY:
      return "out of memory";
    case NLOPT_ROUNDOFF_LIMITED:
      return "roundoff limited";
    case NLOPT_FORCED_STOP:
      return "forced stop";
    default:
      return "unknown";
  }
}
}  // namespace detail

inline QnSearchResult nlopt_minimize(
    const std::function<double(const std::vector<double>&)>& f,
    std::vector<double>& x, const std::vector<double>& lower,
    const std::vector<double>& upper, const QnSearchSettings& settings) {
  const unsigned n = static_cast<unsigned>(x.size());
  QnSearchResult result;
  nlopt_opt opt = nlopt_create(n >= 2 ? NLOPT_LN_BOBYQA : NLOPT_LN_COBYLA, n);
  if (opt == nullptr) {
    result.message = "NLopt could not create the optimiser";
    return result;
  }
  detail::NloptObjective objective{&f, {}, 0};
  nlopt_set_min_objective(opt, detail::nlopt_objective, &objective);
  nlopt_set_lower_bounds(opt, lower.data());
  nlopt_set_upper_bounds(opt, upper.data());
  nlopt_set_xtol_abs1(opt, settings.xtol_log10);
  nlopt_set_maxeval(opt, settings.max_evaluations);
  // First step: a quarter of each box (at least 0.1 decade).
  std::vector<double> step(n);
  for (unsigned i = 0; i < n; ++i) {
    step[i] = std::max(0.1, (upper[i] - lower[i]) / 4);
  }
  nlopt_set_initial_step(opt, step.data());
  double value = 0;
  const nlopt_result r = nlopt_optimize(opt, x.data(), &value);
  nlopt_destroy(opt);
  result.evaluations = objective.evaluations;
  result.converged =
      r == NLOPT_XTOL_REACHED || r == NLOPT_FTOL_REACHED || r == NLOPT_SUCCESS;
  result.message = detail::nlopt_result_text(r);
  for (unsigned i = 0; i < n; ++i) {
    x[i] = std::min(upper[i], std::max(lower[i], x[i]));
  }
  return result;
}

}  // namespace ctid
