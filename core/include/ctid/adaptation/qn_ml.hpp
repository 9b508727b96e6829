// SPDX-License-Identifier: BSD-3-Clause
// Copyright (C) the ctid authors
// Maximum-likelihood estimation of the diagonal of the normalised
// covariance matrix Qn of the Kalman-filter based estimators, thesis
// sec. 3.3 (eqs. 3.21-3.25, Suggested procedure 3.6).
//
// With the random-walk model (3.21), the prediction error
// epsilon(t_k) = y_f^(na)(t_k) - phi_f^T(t_k) theta(t_k|t_(k-1)) of the
// estimator is Gaussian with variance r(t_k) = sigma_e^2 rho(t_k),
// rho = 1 + phi_f^T P(t_k|t_(k-1)) phi_f (eq. 3.25; for the IV stage of
// RIVSVF/RSRIVC the gain denominator 1 + phi_f^T P zeta_f the recursion
// uses in its place). The cost (3.23),
//
//   V = sum_k log r(t_k) + sum_k epsilon^2(t_k) / r(t_k),
//
// depends on sigma_e^2 (the variance of the filtered noise v_f, not that of
// the measurement noise), which the thesis leaves open. Here it is
// concentrated out: sigma_e^2 = (1/N) sum epsilon^2 / rho minimises V for
// given Qn, and
//
//   V(Qn) = N log sigma_e^2 + sum_k log rho(t_k) + N.
//
// Samples at which the estimator does not update (before t_s,ls, or held
// by conditional updating) carry no likelihood and are skipped.
//
// The search (estimate_qn_diagonal) runs a bounded minimiser on log10 of
// the free diagonal elements; elements known to be constant (or fixed at
// any value) are held. The minimiser is a callable so that the core needs
// no optimisation library; nlopt_minimizer.hpp adapts NLopt.
#pragma once

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <string>
#include <vector>

#include "ctid/base/status.hpp"
#include "ctid/base/types.hpp"

namespace ctid {

struct InnovationLikelihood {
  double cost = 0;    // V of eq. (3.23) with sigma_e^2 concentrated out
  double sigma2 = 0;  // the ML sigma_e^2
  long samples = 0;   // samples that entered the sums
};

// V from the prediction errors and normalised innovation variances of a
// run (n samples; NaN rho: sample skipped). Non-finite or non-positive rho
// at an updating sample makes the cost +inf (the filter diverged).
template <typename S>
InnovationLikelihood concentrated_likelihood(const S* error,
                                             const S* innovation,
                                             Eigen::Index n) {
  InnovationLikelihood out;
  double sum_log = 0;
  double sum_sq = 0;
  for (Eigen::Index k = 0; k < n; ++k) {
    const double rho = static_cast<double>(innovation[k]);
    if (std::isnan(rho)) continue;
    const double e = static_cast<double>(error[k]);
    if (!(rho > 0) || !std::isfinite(rho) || !std::isfinite(e)) {
      out.cost = std::numeric_limits<double>::infinity();
      return out;
    }
    sum_log += std::log(rho);
    sum_sq += e * e / rho;
    ++out.samples;
  }
  if (out.samples == 0 || !(sum_sq > 0)) {
    out.cost = std::numeric_limits<double>::infinity();
    return out;
  }
  const double N = static_cast<double>(out.samples);
  out.sigma2 = sum_sq / N;
  out.cost = N * std::log(out.sigma2) + sum_log + N;
  return out;
}

// The search: start q0 (np values; fixed elements keep theirs), bounds per
// element (used for the free ones, which need 0 < lower <= q0 <= upper),
// and which elements are free.
struct QnSearchSettings {
  std::vector<double> q0, lower, upper;
  std::vector<bool> free;
  int max_evaluations = 200;
  double xtol_log10 = 1e-3;  // stop when log10 q moves less than this
};

struct QnSearchResult {
  std::vector<double> q;  // the ML diagonal (fixed elements as given)
  double cost = 0;
  double sigma2 = 0;
  int evaluations = 0;
  bool converged = false;  // the minimiser met its tolerance
  std::string message;     // the minimiser's stopping reason
};

inline Status validate_qn_search(const QnSearchSettings& s, std::size_t np) {
  const auto n_text = std::to_string(np);
  if (s.q0.size() != np || s.lower.size() != np || s.upper.size() != np ||
      s.free.size() != np) {
    return dimension_mismatch(
        "q0, the bounds and the free/fixed mask must have " + n_text +
        " elements (one per parameter)");
  }
  std::size_t nfree = 0;
  for (std::size_t i = 0; i < np; ++i) {
    const std::string which = "element " + std::to_string(i + 1);
    const double q = s.q0[i], lb = s.lower[i], ub = s.upper[i];
    if (!std::isfinite(q) || q < 0) {
      return bad_input("q0 must be finite and >= 0 (" + which + ")");
    }
    if (!s.free[i]) {
      // A fixed element with bounds of its own must respect them.
      if (std::isfinite(lb) && std::isfinite(ub) && (q < lb || q > ub)) {
        return bad_input("the fixed " + which + " (" + std::to_string(q) +
                         ") lies outside its bounds [" + std::to_string(lb) +
                         ", " + std::to_string(ub) + "]");
      }
      continue;
    }
    ++nfree;
    if (!std::isfinite(lb) || !std::isfinite(ub)) {
      return bad_input("the bounds of the free " + which + " must be finite");
    }
    if (!(lb > 0)) {
      return bad_input("the lower bound of the free " + which +
                       " must be > 0 (the search is on a log scale)");
    }
    if (lb > ub) {
      return bad_input("the bounds of " + which + " cross: lower " +
                       std::to_string(lb) + " > upper " + std::to_string(ub));
    }
    if (q < lb || q > ub) {
      return bad_input("the start value of " + which + " (" +
                       std::to_string(q) + ") lies outside its bounds [" +
                       std::to_string(lb) + ", " + std::to_string(ub) + "]");
    }
  }
  if (nfree == 0) return bad_input("no element of Qn is free to estimate");
  if (s.max_evaluations < 1) return bad_input("maxeval must be >= 1");
  if (!(s.xtol_log10 > 0) || !std::isfinite(s.xtol_log10)) {
    return bad_input("the tolerance must be finite and > 0");
  }
  return Status::Ok();
}

// A bounded minimiser: minimize(f, x, lower, upper, settings) overwrites x
// with the minimiser of f on the box and returns the result's bookkeeping
// (evaluations, converged, message; cost is filled by the caller).
using BoundedMinimizer = std::function<QnSearchResult(
    const std::function<double(const std::vector<double>&)>& f,
    std::vector<double>& x, const std::vector<double>& lower,
    const std::vector<double>& upper, const QnSearchSettings& settings)>;

// Minimises cost(q) (q the full diagonal) over log10 of the free elements.
// `cost` returns V (+inf when the run fails) and may report sigma_e^2.
inline Status estimate_qn_diagonal(
    const std::function<double(const std::vector<double>&, double*)>& cost,
    const QnSearchSettings& settings, const BoundedMinimizer& minimize,
    QnSearchResult& result) {
  const std::size_t np = settings.q0.size();
  const Status status = validate_qn_search(settings, np);
  if (!status.ok()) return status;
  std::vector<std::size_t> index;
  std::vector<double> x, lower, upper;
  for (std::size_t i = 0; i < np; ++i) {
    if (!settings.free[i]) continue;
    index.push_back(i);
    x.push_back(std::log10(settings.q0[i]));
    lower.push_back(std::log10(settings.lower[i]));
    upper.push_back(std::log10(settings.upper[i]));
  }
  std::vector<double> q = settings.q0;
  auto to_q = [&](const std::vector<double>& xs) {
    for (std::size_t j = 0; j < index.size(); ++j) {
      const double clipped = std::min(upper[j], std::max(lower[j], xs[j]));
      q[index[j]] = std::pow(10.0, clipped);
    }
    return q;
  };
  auto objective = [&](const std::vector<double>& xs) {
    const double v = cost(to_q(xs), nullptr);
    // Minimisers cope badly with inf: a large finite penalty instead.
    return std::isfinite(v) ? v : 1e300;
  };
  result = minimize(objective, x, lower, upper, settings);
  result.q = to_q(x);
  result.cost = cost(result.q, &result.sigma2);
  if (!std::isfinite(result.cost)) {
    return numerical_failure(
        "the estimator diverged at the optimum of the Qn search; check the "
        "bounds, lambda_svf and the scaling of the data");
  }
  return Status::Ok();
}

}  // namespace ctid
