// SPDX-License-Identifier: BSD-3-Clause
// Copyright (C) the ctid authors
// The search of a continuous time delay td of B(p)/F(p) e^(-td p), for the
// time-domain (tfsrivc, tfrivc: refined_iv_delay.hpp) and the
// frequency-domain (tffsrivc: freq_srivc.hpp) estimators alike. The model
// is re-estimated at every delay tried (SRIVC, thesis eqs. 2.8-2.13, or
// RIVC with a noise model, sec. 2.1.2), so the search minimises the loss
// concentrated on td, V(td) = loss of the model fitted at td: the
// separable formulation of SRIVC with a time delay (CONTSID's TDSRIVC,
// tfsrivc; Chen, Garnier & Gilson, J. Process Control 2015, and in the
// frequency domain Chen, Zhuan, Garnier & Gilson, Automatica 2018).
//
// 1. Grid: V at num_td delays equally spaced in [td_min, td_max] (the end
//    points included). With extend_limit > td_max, while the grid's
//    minimum lies at its upper end the grid is extended by its own step,
//    to at most twice its length per extension and extend_limit overall (a
//    default upper bound is a guess).
// 2. Refinement, from the grid, by one of two rules:
//    - kGaussNewton (time domain): from the best grid point, Gauss-Newton
//      steps on td, td += (g^T e) / (g^T g), with e the (whitened) output
//      error and g the sensitivity dy/dtd with the part that the
//      coefficients re-estimated at the new delay absorb projected out
//      (variable projection: g - J (J^+ g), J = dy/dtheta); a step that
//      does not lower V is reduced by step_reduction (at most ten times),
//      steps are bounded by max_step and the range. Stops when the step
//      is below step_tolerance or the relative decrease of V below
//      loss_tolerance, or when no reduced step lowers V.
//    - kScanGolden (frequency domain): around each of the best
//      max_minima local minima of the grid a scan of the two neighbouring
//      grid steps with a sixteenth of a step, and golden section between
//      the neighbours of each local minimum of that scan; the lowest
//      refined loss is kept. (The loss of relay data has several minima
//      within one grid step, the harmonics' phases wrapping at different
//      td: the fine scan puts the golden section in the basin of the
//      lowest.)
//
// The estimator is a Model with
//   using Fit = ...;  // members S td, S loss (Inf: unusable), Vector<S>
//                     // theta
//   Status fit(S td, const Vector<S>& start, Fit* out);
//     the model fitted at td from start (empty: the model's own start);
//     kNumericalFailure and kNotConverged make that delay unusable (loss
//     Inf), any other error stops the search;
// and, for kGaussNewton,
//   Status step_terms(const Fit& f, Vector<S>* e, Vector<S>* g,
//                     Matrix<S>* J);
//     the whitened output error, td sensitivity and free-coefficient
//     sensitivities at f.
#pragma once

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "ctid/base/status.hpp"
#include "ctid/base/types.hpp"

namespace ctid {

enum class DelayRefinement { kNone, kGaussNewton, kScanGolden };

template <typename S>
struct DelaySearchSettings {
  bool grid = true;  // search the grid; false: start from td_start
  S td_start = 0;
  S td_min = 0, td_max = 0;  // the range (grid and refinement)
  int num_td = 50;           // grid points, >= 1 (kScanGolden: >= 2)
  // > td_max: the grid is extended while its minimum lies at its upper end
  // (step 1 above); 0: no extension.
  S extend_limit = 0;
  DelayRefinement refinement = DelayRefinement::kGaussNewton;
  // kGaussNewton
  int max_iterations = 20;
  S step_tolerance = 0;  // time units
  S loss_tolerance = 0;  // relative decrease of V
  S max_step = std::numeric_limits<S>::infinity();
  S step_reduction = S(0.5);
  // kScanGolden
  int max_minima = 8;
  S golden_tolerance = S(1e-10);  // relative interval (times resolution)
  S resolution = 1;               // a time scale of the problem (1/sigma)
  S min_scan_step = 0;            // scan step without a grid: range / 20
};

template <typename S, typename Fit>
struct DelaySearchOutcome {
  Fit best;                        // the model at the delay kept
  std::vector<S> grid, grid_loss;  // empty without a grid
  S td_max = 0;                    // the upper end of the range used
  int iterations = 0;              // Gauss-Newton steps
  bool converged = true;
  std::string reason;
};

namespace delay_detail {

inline bool unusable(const Status& s) {
  return s.code() == ErrorCode::kNumericalFailure ||
         s.code() == ErrorCode::kNotConverged;
}

// The model at td (loss Inf where it is unusable).
template <typename S, typename Model>
Status evaluate(Model& model, S td, const Vector<S>& start,
                typename Model::Fit* out) {
  const Status s = model.fit(td, start, out);
  if (s.ok()) {
    if (!std::isfinite(out->loss))
      out->loss = std::numeric_limits<S>::infinity();
    return s;
  }
  if (!unusable(s)) return s;
  out->td = td;
  out->loss = std::numeric_limits<S>::infinity();
  return Status::Ok();
}

template <typename S>
std::size_t argmin(const std::vector<S>& v) {
  std::size_t k = 0;
  for (std::size_t i = 1; i < v.size(); ++i)
    if (v[i] < v[k]) k = i;
  return k;
}

// Step 1: the grid (with its extension).
template <typename S, typename Model>
Status grid_search(Model& model, const DelaySearchSettings<S>& settings,
                   std::vector<typename Model::Fit>* fits,
                   DelaySearchOutcome<S, typename Model::Fit>* out) {
  // (one point: td_max, as Octave's linspace)
  const int count = settings.num_td;
  const S step =
      count > 1 ? (settings.td_max - settings.td_min) / (count - 1) : S(0);
  const Vector<S> none;
  auto add = [&](S td) -> Status {
    typename Model::Fit f;
    const Status s = evaluate(model, td, none, &f);
    if (!s.ok()) return s;
    out->grid.push_back(td);
    out->grid_loss.push_back(f.loss);
    fits->push_back(f);
    return s;
  };
  for (int i = 0; i < count; ++i) {
    const S td = i == count - 1 ? settings.td_max : settings.td_min + step * i;
    const Status s = add(td);
    if (!s.ok()) return s;
  }
  S td_max = settings.td_max;
  std::size_t best = argmin(out->grid_loss);
  while (best + 1 == out->grid.size() && step > 0 &&
         td_max < settings.extend_limit) {
    const S hi = std::min(2 * td_max - settings.td_min, settings.extend_limit);
    const S last = out->grid.back();
    const int more = static_cast<int>(std::floor((hi - last) / step));
    if (more < 1) {
      const Status s = add(hi);
      if (!s.ok()) return s;
    }
    for (int k = 1; k <= more; ++k) {
      const Status s = add(last + step * k);
      if (!s.ok()) return s;
    }
    td_max = out->grid.back();
    best = argmin(out->grid_loss);
  }
  out->td_max = td_max;
  return Status::Ok();
}

// Step 2, kGaussNewton, from out->best.
template <typename S, typename Model>
Status gauss_newton(Model& model, const DelaySearchSettings<S>& settings,
                    S td_max, DelaySearchOutcome<S, typename Model::Fit>* out) {
  using Fit = typename Model::Fit;
  Fit& cur = out->best;
  out->converged = false;
  for (int it = 1; it <= settings.max_iterations; ++it) {
    out->iterations = it;
    Vector<S> e, g;
    Matrix<S> J;
    Status s = model.step_terms(cur, &e, &g, &J);
    if (!s.ok()) return s;
    if (J.cols() > 0) {
      const Vector<S> c = J.colPivHouseholderQr().solve(g);
      g -= J * c;
    }
    const S gg = g.squaredNorm();
    if (!(gg > 0)) {
      out->reason = "the output does not depend on the delay";
      return Status::Ok();
    }
    S step = g.dot(e) / gg;
    if (std::abs(step) > settings.max_step)
      step = std::copysign(settings.max_step, step);
    bool accepted = false;
    Fit next;
    for (int k = 0; k < 10; ++k) {
      const S td = std::min(std::max(cur.td + step, settings.td_min), td_max);
      if (td == cur.td) break;
      s = evaluate(model, td, cur.theta, &next);
      if (!s.ok()) return s;
      if (next.loss < cur.loss) {
        accepted = true;
        break;
      }
      step *= settings.step_reduction;
    }
    if (!accepted) {
      out->converged = true;
      out->reason = "delay refined in " + std::to_string(it - 1) +
                    " Gauss-Newton step(s) (no further decrease)";
      return Status::Ok();
    }
    const S decrease = (cur.loss - next.loss) / cur.loss;
    const S moved = std::abs(next.td - cur.td);
    cur = next;
    if (moved < settings.step_tolerance || decrease < settings.loss_tolerance) {
      out->converged = true;
      out->reason =
          "delay refined in " + std::to_string(it) + " Gauss-Newton step(s)";
      return Status::Ok();
    }
  }
  out->reason = "the delay did not converge in " +
                std::to_string(settings.max_iterations) + " Gauss-Newton steps";
  return Status::Ok();
}

// Step 2, kScanGolden: the delay kept (the model is fitted there by the
// caller of scan_golden's result).
template <typename S, typename Model>
Status scan_golden(Model& model, const DelaySearchSettings<S>& settings,
                   const std::vector<S>& starts, S step, S* td_best) {
  const Vector<S> none;
  Status failed;
  auto loss = [&](S t) {
    typename Model::Fit f;
    const Status s = evaluate(model, t, none, &f);
    if (!s.ok()) {
      failed = s;
      return std::numeric_limits<S>::infinity();
    }
    return f.loss;
  };
  const S lo_end = settings.td_min, hi_end = settings.td_max;
  // Golden section on [lo, hi]: the minimiser.
  auto golden = [&](S lo, S hi, S* at) {
    S a = std::max(lo_end, lo);
    S b = std::min(hi_end, hi);
    const S g = (std::sqrt(S(5)) - 1) / 2;
    S x1 = b - g * (b - a), x2 = a + g * (b - a);
    S f1 = loss(x1), f2 = loss(x2);
    for (int it = 0; it < 60 && (b - a) > settings.golden_tolerance *
                                              (S(1) + b) * settings.resolution;
         ++it) {
      if (f1 < f2) {
        b = x2;
        x2 = x1;
        f2 = f1;
        x1 = b - g * (b - a);
        f1 = loss(x1);
      } else {
        a = x1;
        x1 = x2;
        f1 = f2;
        x2 = a + g * (b - a);
        f2 = loss(x2);
      }
    }
    *at = (a + b) / 2;
    return loss(*at);
  };
  S best_cost = std::numeric_limits<S>::infinity();
  const int sub = 16;
  for (const S centre : starts) {
    const S h = step / sub;
    std::vector<S> at(2 * sub + 1), c(2 * sub + 1);
    for (int i = 0; i <= 2 * sub; ++i) {
      at[i] = std::min(std::max(centre + (i - sub) * h, lo_end), hi_end);
      c[i] = loss(at[i]);
    }
    for (int i = 0; i <= 2 * sub; ++i) {
      if (!std::isfinite(c[i])) continue;
      if ((i > 0 && c[i] > c[i - 1]) || (i < 2 * sub && c[i] > c[i + 1]))
        continue;
      S x = at[i];
      const S cx = golden(at[i] - h, at[i] + h, &x);
      const S cbest = std::min(cx, c[i]);
      if (cbest < best_cost || !std::isfinite(best_cost)) {
        best_cost = cbest;
        *td_best = cx <= c[i] ? x : at[i];
      }
    }
  }
  return failed;
}

}  // namespace delay_detail

// The search (see the header comment). Without a grid, out->best is the
// model at settings.td_start; with refinement kNone, the best grid point.
template <typename S, typename Model>
Status delay_search(Model& model, const DelaySearchSettings<S>& settings,
                    DelaySearchOutcome<S, typename Model::Fit>* out) {
  using Fit = typename Model::Fit;
  if (out == nullptr) return bad_input("the outcome must not be null");
  if (!(settings.td_min >= 0) || !(settings.td_max >= settings.td_min) ||
      !std::isfinite(settings.td_max)) {
    return Status(ErrorCode::kBadOption,
                  "the delay range must satisfy 0 <= TdMin <= TdMax < Inf");
  }
  if (settings.grid &&
      (settings.num_td <
           (settings.refinement == DelayRefinement::kScanGolden ? 2 : 1) ||
       settings.num_td > 100000)) {
    return Status(ErrorCode::kBadOption, "NumTd out of range (1e5 at most)");
  }
  if (!(settings.step_reduction > 0 && settings.step_reduction < 1) ||
      !(settings.max_step > 0) || settings.max_iterations < 0) {
    return Status(ErrorCode::kBadOption,
                  "StepReduction must be in (0, 1), StepMax > 0 and MaxIter "
                  ">= 0");
  }
  *out = DelaySearchOutcome<S, Fit>();
  out->td_max = settings.td_max;
  Status s;
  std::vector<Fit> fits;
  if (settings.grid) {
    s = delay_detail::grid_search(model, settings, &fits, out);
    if (!s.ok()) return s;
    const std::size_t best = delay_detail::argmin(out->grid_loss);
    if (!std::isfinite(out->grid_loss[best])) {
      return numerical_failure("the fit failed at every delay of the grid");
    }
    out->best = fits[best];
    out->reason =
        "grid search over " + std::to_string(out->grid.size()) + " delays";
  } else {
    s = model.fit(settings.td_start, Vector<S>(), &out->best);
    if (!s.ok()) return s;
    out->reason = "delay fixed";
  }
  if (settings.refinement == DelayRefinement::kGaussNewton) {
    DelaySearchSettings<S> ranged = settings;
    ranged.td_max = out->td_max;
    return delay_detail::gauss_newton(model, ranged, out->td_max, out);
  }
  if (settings.refinement == DelayRefinement::kScanGolden) {
    // The best max_minima local minima of the grid (or the start).
    S step = 0;
    std::vector<S> starts;
    if (settings.grid) {
      const std::vector<S>& c = out->grid_loss;
      const int count = static_cast<int>(c.size());
      step = (settings.td_max - settings.td_min) / (settings.num_td - 1);
      std::vector<int> minima;
      for (int i = 0; i < count; ++i) {
        if (!std::isfinite(c[i])) continue;
        if ((i == 0 || c[i] <= c[i - 1]) &&
            (i == count - 1 || c[i] <= c[i + 1]))
          minima.push_back(i);
      }
      std::sort(minima.begin(), minima.end(),
                [&](int i, int j) { return c[i] < c[j]; });
      const std::size_t kept =
          std::min<std::size_t>(minima.size(), settings.max_minima);
      for (std::size_t k = 0; k < kept; ++k)
        starts.push_back(out->grid[minima[k]]);
    } else {
      step = std::max((settings.td_max - settings.td_min) / 20,
                      settings.min_scan_step);
      starts.push_back(std::min(std::max(settings.td_start, settings.td_min),
                                settings.td_max));
    }
    S td = out->best.td;
    s = delay_detail::scan_golden(model, settings, starts, step, &td);
    if (!s.ok() && !delay_detail::unusable(s)) return s;
    s = model.fit(td, Vector<S>(), &out->best);
    if (!s.ok()) return s;
    out->reason = "delay refined by golden section";
  }
  return Status::Ok();
}

}  // namespace ctid
