// SPDX-License-Identifier: BSD-3-Clause
// Copyright (C) the ctid authors
// The offline refined instrumental-variable engine: one implementation of
// LSSVF (thesis eq. 1.32), IVSVF (eqs. 2.4-2.7), SRIVC (eqs. 2.8-2.13) and
// CLSRIVC (eqs. 2.47-2.50) for the generalised output-error structure
//
//   y(t) = sum_g x_g(t) + y0(t) + c + e(t),
//   F_g(p) x_g(t) = sum_(j in g) B_j(p) w_j(t - nk_j Ts),
//
// where each group g has its own monic denominator F_g (one group: the
// common-denominator model; one group per input: CONTSID's 'Different'
// denominators), the channels w_j are the inputs and any extra regressors
// (effect terms, a constant for an input offset), y0 the free response
// of the initial state (optional) and c an output offset (optional).
//
// theta = [f of group 0 (f1 .. f_nf), f of group 1, .., b of channel 0
// (b_0 .. b_(nb-1), descending powers of p), b of channel 1, .., c].
// Coefficients may be fixed (moved to the left side of the regression);
// fixed trailing zeros of F_g are integrators (the Hurwitz test applies to
// F_g without them, the prefilter replaces them by a slow stable pole).
//
// Refined IV step for group g (eqs. 2.9-2.13): with the current model the
// prefilter 1/F_g (made stable) filters the target y_g = y - (everything
// but x_g), each channel (by its own intersample rule) and the auxiliary
// model output x_hat_g (instruments); Z^T Phi theta = Z^T Y is solved by
// the QR route of offline_iv.hpp with equilibrated columns. Groups are
// updated in turn (Gauss-Seidel backfitting), then y0 and c by linear
// least squares on the free responses (with every coefficient fixed this
// is the x0 estimate alone).
//
// Time scaling: the engine works in the time t' = sigma t, chosen so that
// the model's characteristic frequency |F_g(0)|^(1/n) is 1 there: the
// columns p'^i y_f then have comparable sizes even for a sixth-order model
// sampled fast (CONTSID scales time likewise). Coefficients are mapped back
// exactly: f_i = sigma^i f'_i, b_k = sigma^(n-k) b'_k (k = power of p).
//
// Start: IVSVF at a grid of cut-offs (each run in the time scaled by its
// cut-off), ranked by the simulation error of the start model; SRIVC runs
// from the best starts in turn and the best stable, converged result wins,
// so no single lucky cut-off is needed. On long records the grid is ranked
// on a leading segment and only the starts SRIVC runs from are computed on
// the whole record (kRankSamples). Every iterate is kept stable: an
// unstable IV solution is pulled back toward the previous (stable) iterate
// by step halving, and reflected as a last resort; the result's status
// says whether this happened on the final iterate (clipped) and how
// often, and flags a slowest pole that crept to p = 0 without converging
// (integrator_suspected: an integrator the structure does not declare).
// With settings.refit_integrators the engine refits such a fit with that
// pole declared at p = 0 and keeps the refit when it is better
// (refit_integrators() below; integrators, integrator_refit).
//
// The parts: refined_iv_problem.hpp (the types), refined_iv_validation.hpp
// (input checks), filters/batch_filters.hpp (the batch filters),
// refined_iv_engine.hpp (Engine, Estimator), refined_iv_starts.hpp (the
// start search); this header includes them all and holds the entry points
// refined_iv(), srivc() and clsrivc().
#pragma once

#include <complex>
#include <limits>
#include <string>
#include <utility>
#include <vector>

#include "ctid/base/polynomial.hpp"
#include "ctid/offline/offline_iv.hpp"
#include "ctid/offline/pole_determination.hpp"
#include "ctid/offline/refined_iv_engine.hpp"
#include "ctid/offline/refined_iv_problem.hpp"
#include "ctid/offline/refined_iv_starts.hpp"
#include "ctid/offline/refined_iv_validation.hpp"

namespace ctid {

namespace riv_detail {

// The engine without the integrator refit (refined_iv() below).
//
// With an output offset c estimated, c is refitted between refined-IV
// steps. With an input of nonzero mean the step response of c and the
// model's gain are nearly collinear and that alternation can crawl
// (y = 20 + G (5 + 3 u), noise-free and in the model class: not
// converged after 60 iterations, c = 18.6). A run that does not converge is
// therefore repeated once with c as a column of the regression
// (offset_in_regression), and the repeat is returned when it converges. Only
// then: on records outside the model class the two schemes stop at different
// points, and a fit that converges with the alternation keeps its result.
template <typename S>
Status refined_iv_offset(const RivProblem<S>& problem,
                         const RivSettings<S>& settings, const RivData<S>& data,
                         RivResult<S>* result) {
  Status status = riv_detail::refined_iv_run(problem, settings, data, result);
  if (settings.method != RivMethod::kSrivc || !problem.output_offset ||
      problem.closed_loop() || settings.offset_in_regression ||
      status.code() != ErrorCode::kNotConverged) {
    return status;
  }
  RivSettings<S> joint = settings;
  joint.offset_in_regression = true;
  RivResult<S> second;
  const Status repeat =
      riv_detail::refined_iv_run(problem, joint, data, &second);
  if (repeat.ok() && second.converged) {
    second.reason +=
        "; with the output offset in the refined-IV regression "
        "(the run refitting it between steps did not converge)";
    *result = std::move(second);
    return repeat;
  }
  return status;
}

// Per group, the trailing coefficients of F_g fixed at 0: its declared
// integrators.
template <typename S>
std::vector<int> declared_integrators(const RivProblem<S>& problem) {
  std::vector<int> have(problem.num_groups(), 0);
  if (problem.fixed.empty()) return have;
  int off = 0;
  for (int g = 0; g < problem.num_groups(); ++g) {
    const int n = problem.nf[g];
    while (have[g] < n && problem.fixed[off + n - 1 - have[g]] &&
           problem.fixed_values(off + n - 1 - have[g]) == 0)
      ++have[g];
    off += n;
  }
  return have;
}

template <typename S>
S mean_square_error(const RivData<S>& data, const Vector<S>& simulated) {
  if (simulated.size() != data.num_samples) {
    return std::numeric_limits<S>::infinity();
  }
  return (Eigen::Map<const Vector<S>>(data.y, data.num_samples) - simulated)
             .squaredNorm() /
         static_cast<S>(data.num_samples);
}

inline bool any_flag(const std::vector<int>& v) {
  for (int x : v)
    if (x != 0) return true;
  return false;
}

}  // namespace riv_detail

// The reason of a refit from the lowest-loss run (RivResult::lowest_*),
// given the returned fit's reason.
inline std::string lowest_run_reason(const std::string& reason) {
  return "a run from another start reached a lower loss than the converged "
         "one (" +
         reason + ") without converging";
}

// The integrator refit: a fit whose slowest pole crept toward p = 0
// without converging (integrator_suspected, per group) has its loss
// minimum on the stability boundary, an integrator the structure does not
// declare (an integrating plant, e.g. force -> position of an axis). The
// fit is repeated with that pole declared at p = 0 (F_g's last free
// coefficient fixed at 0), started from theta with its slowest pole moved
// there, and kept (*kept, *out) when it converges to a model whose other
// poles are stable and whose mean squared simulation error is not above
// base_mse; while the refit's own slowest pole still creeps to p = 0, a
// further pole is declared (at most nf_g in all). base_reason: the
// unrefitted fit's reason, quoted in the refit's.
template <typename S>
Status refit_integrators(const RivProblem<S>& problem,
                         const RivSettings<S>& settings, const RivData<S>& data,
                         Vector<S> theta, std::vector<int> suspected,
                         S base_mse, const std::string& base_reason,
                         RivResult<S>* out, bool* kept) {
  if (out == nullptr || kept == nullptr) return bad_input("no result");
  *kept = false;
  const int groups = problem.num_groups();
  const int np = problem.num_parameters();
  if (theta.size() != np) {
    return dimension_mismatch("the start needs " + std::to_string(np) +
                              " coefficients");
  }
  const std::vector<int> have0 = riv_detail::declared_integrators(problem);
  std::vector<int> have = have0;
  RivProblem<S> p = problem;
  if (p.fixed.empty()) {
    p.fixed.assign(np, false);
    p.fixed_values = Vector<S>::Zero(np);
  }
  int most = 0;
  for (int n : problem.nf) most = std::max(most, n);
  for (int pass = 0; pass < most; ++pass) {
    std::vector<int> add(groups, 0);
    for (int g = 0; g < groups; ++g) {
      add[g] = g < static_cast<int>(suspected.size()) && suspected[g] != 0 &&
               have[g] < problem.nf[g];
    }
    if (!riv_detail::any_flag(add)) return Status::Ok();
    Vector<S> start = theta;
    int off = 0;
    for (int g = 0; g < groups; ++g) {
      const int n = problem.nf[g];
      if (add[g]) {
        // the free part of F_g (without its have[g] integrators), its
        // root nearest p = 0 removed
        const int m = n - have[g];
        Vector<S> ascending(m + 1);
        for (int i = 0; i < m; ++i) ascending(i) = theta(off + m - 1 - i);
        ascending(m) = 1;
        auto roots = polynomial_roots<S>(ascending);
        Eigen::Index k = 0;
        for (Eigen::Index i = 1; i < roots.size(); ++i)
          if (std::abs(roots(i)) < std::abs(roots(k))) k = i;
        Eigen::Matrix<std::complex<S>, Eigen::Dynamic, 1> rest(m - 1);
        for (Eigen::Index i = 0, j = 0; i < roots.size(); ++i)
          if (i != k) rest(j++) = roots(i);
        const auto f1 = monic_from_roots<S>(rest);
        start.segment(off, n).setZero();
        for (int i = 0; i + 1 < m; ++i) start(off + i) = f1(i + 1).real();
        for (int i = 0; i < have[g] + 1; ++i) {
          p.fixed[off + n - 1 - i] = true;
          p.fixed_values(off + n - 1 - i) = 0;
        }
      }
      off += n;
    }
    RivSettings<S> st = settings;
    st.theta_init = start;
    st.refit_integrators = false;
    RivResult<S> r;
    const Status s = riv_detail::refined_iv_offset(p, st, data, &r);
    if (!s.ok() && s.code() != ErrorCode::kNotConverged) return Status::Ok();
    for (int g = 0; g < groups; ++g) have[g] += add[g];
    if (r.converged && r.stable &&
        riv_detail::mean_square_error(data, r.simulated) <= base_mse) {
      int total = 0;
      r.integrators.assign(groups, 0);
      for (int g = 0; g < groups; ++g) {
        r.integrators[g] = have[g] - have0[g];
        total += r.integrators[g];
      }
      r.integrator_refit = 1;
      r.reason +=
          ", with " + std::to_string(total) +
          " pole(s) at p = 0 detected (the fit without: " + base_reason + ")";
      *out = std::move(r);
      *kept = true;
      return Status::Ok();
    }
    if (!(r.stable && riv_detail::any_flag(r.integrator_suspected))) {
      return Status::Ok();
    }
    theta = r.theta;
    suspected = r.integrator_suspected;
  }
  return Status::Ok();
}

// Where the integrator refit of a fit starts: the fit itself when it did
// not converge to a stable model while its slowest pole crept to p = 0
// (from 1), else the lowest-loss run from another start when that run
// crept so (RivResult::lowest_*, from 2); from 0: no refit. theta,
// suspected, mse (the mean squared simulation error) and reason are those
// of the run it starts from.
template <typename S>
struct IntegratorRefitStart {
  int from = 0;
  Vector<S> theta;
  std::vector<int> suspected;
  S mse = 0;
  std::string reason;
};

template <typename S>
IntegratorRefitStart<S> integrator_refit_start(const RivResult<S>& fit,
                                               const RivData<S>& data) {
  IntegratorRefitStart<S> start;
  if (!(fit.converged && fit.stable) &&
      riv_detail::any_flag(fit.integrator_suspected)) {
    start.from = 1;
    start.theta = fit.theta;
    start.suspected = fit.integrator_suspected;
    start.mse = riv_detail::mean_square_error(data, fit.simulated);
    start.reason = fit.reason;
  } else if (fit.lowest_theta.size() > 0 &&
             riv_detail::any_flag(fit.lowest_integrator_suspected)) {
    start.from = 2;
    start.theta = fit.lowest_theta;
    start.suspected = fit.lowest_integrator_suspected;
    start.mse = riv_detail::mean_square_error(data, fit.lowest_simulated);
    start.reason = lowest_run_reason(fit.reason);
  }
  return start;
}

// The integrator refit of a fit of (problem, settings, data), from where
// integrator_refit_start() says: *fit becomes the refit when it is kept
// (integrator_refit 1); otherwise it stays, marked -1 (refitted from
// itself, its reason saying so) or -2 (from its lowest-loss run), or 0
// when no refit applies. fit->integrators: the poles declared per group.
template <typename S>
Status refit_integrators(const RivProblem<S>& problem,
                         const RivSettings<S>& settings, const RivData<S>& data,
                         RivResult<S>* fit) {
  if (fit == nullptr) return bad_input("no result");
  fit->integrators.assign(problem.num_groups(), 0);
  const IntegratorRefitStart<S> start = integrator_refit_start(*fit, data);
  if (start.from == 0) return Status::Ok();
  RivResult<S> refit;
  bool kept = false;
  const Status s =
      refit_integrators(problem, settings, data, start.theta, start.suspected,
                        start.mse, start.reason, &refit, &kept);
  if (!s.ok()) return s;
  if (kept) {
    *fit = std::move(refit);
  } else if (start.from == 1) {
    fit->integrator_refit = -1;
    fit->reason +=
        "; a refit with a pole at p = 0 did not converge to a better model";
  } else {
    fit->integrator_refit = -2;
  }
  return Status::Ok();
}

// The engine: see the header comment. Returns kNotConverged (result filled,
// converged = false) when SRIVC did not converge, numerical_failure when no
// start gave an estimate.
//
// With settings.refit_integrators (SRIVC in open loop), the fit is refitted
// with the pole its slowest creeps toward declared at p = 0, from itself or
// from its lowest-loss run (refit_integrators above); the refit replaces
// the fit when it is better (result->integrator_refit says what happened).
//
// A converged SRIVC fit whose real pole the data do not determine
// (pole_determination.hpp) has determined = false and the pole named in
// its reason, as one whose parameters still moved when the loss stopped.
template <typename S>
Status refined_iv(const RivProblem<S>& problem, const RivSettings<S>& settings,
                  const RivData<S>& data, RivResult<S>* result) {
  Status status =
      riv_detail::refined_iv_offset(problem, settings, data, result);
  if (settings.refit_integrators && settings.method == RivMethod::kSrivc &&
      !problem.closed_loop() &&
      (status.ok() || status.code() == ErrorCode::kNotConverged)) {
    const Status s = refit_integrators(problem, settings, data, result);
    if (!s.ok()) return s;
    if (result->integrator_refit == 1) status = Status::Ok();
  }
  if (status.ok() && settings.method == RivMethod::kSrivc &&
      result->converged) {
    const std::string why = undetermined_pole(
        problem, result->theta, result->covariance, typical_interval(data));
    if (!why.empty()) {
      result->determined = false;
      result->reason += "; " + why;
    }
  }
  return status;
}

// The SRIVC fit of `problem` to `data` as the start of another estimator's
// iterations (output_error.hpp, refined_iv_bj.hpp): a fit that did not
// converge is still a start; any other failure is returned, its message
// after "<what>: ".
template <typename S>
Status refined_iv_start(const RivProblem<S>& problem,
                        const RivSettings<S>& settings, const RivData<S>& data,
                        const std::string& what, Vector<S>* theta) {
  RivResult<S> r;
  const Status status = refined_iv<S>(problem, settings, data, &r);
  if (!status.ok() && status.code() != ErrorCode::kNotConverged) {
    return Status(status.code(), what + ": " + status.message());
  }
  *theta = r.theta;
  return Status::Ok();
}

namespace riv_detail {

// The SISO/MISO common-denominator problem of offline_iv.hpp's interface
// (ModelOrders, one SVF cut-off for the start) run by the engine.
template <typename S>
Status run_orders(const ModelOrders& orders, const SvfSettings<S>& init_svf,
                  const SrivcSettings<S>& settings, const RecordView<S>& record,
                  const offline_iv_detail::Loop<S>& loop,
                  OfflineEstimate<S>* estimate) {
  Status status = offline_iv_detail::validate_problem(orders, init_svf, record,
                                                      loop, estimate);
  if (!status.ok()) return status;
  status = offline_iv_detail::validate_srivc_settings(orders, settings);
  if (!status.ok()) return status;
  RivProblem<S> problem;
  problem.nf = {orders.na};
  for (int j = 0; j < orders.num_inputs(); ++j) {
    RivChannel c;
    c.nb = orders.nb[j];
    c.nk = orders.nk[j];
    c.rule = init_svf.u_intersample;
    problem.channels.push_back(c);
  }
  // The refined steps filter y (never piecewise constant) by the exact
  // first-order hold; init_svf's y rule is that of the per-sample SVF
  // methods (the trapezoid of the thesis' recursive estimators).
  problem.y_rule = InterSample::kFoh;
  problem.discrete_controller = loop.controller;
  problem.r1 = loop.r1;
  problem.r2 = loop.r2;
  RivSettings<S> riv;
  riv.tolerance = settings.tolerance;
  riv.max_iterations = settings.max_iterations;
  riv.theta_init = settings.theta_init;
  riv.cutoffs = {init_svf.lambda_svf};
  riv.max_starts = 1;
  const RivData<S> data{record.y, record.u, record.num_samples, record.ts,
                        record.instants};
  RivResult<S> result;
  status = refined_iv(problem, riv, data, &result);
  if (!status.ok() && status.code() != ErrorCode::kNotConverged) {
    return status;
  }
  estimate->theta = result.theta;
  estimate->covariance = result.covariance;
  estimate->noise_variance = result.noise_variance;
  estimate->iterations = result.iterations;
  estimate->converged = result.converged;
  return status;
}

}  // namespace riv_detail

// SRIVC, eqs. (2.8)-(2.13), for the common-denominator model of
// ModelOrders: the engine started from settings.theta_init or IVSVF with
// init_svf. Returns kNotConverged (estimate filled with the last iterate,
// converged = false) after max_iterations.
template <typename S>
Status srivc(const ModelOrders& orders, const SvfSettings<S>& init_svf,
             const SrivcSettings<S>& settings, const RecordView<S>& record,
             OfflineEstimate<S>* estimate) {
  return riv_detail::run_orders(orders, init_svf, settings, record,
                                offline_iv_detail::Loop<S>(), estimate);
}

// CLSRIVC, eqs. (2.47)-(2.50), for u = r1 + C(q^-1)(r2 - y) (single ZOH
// input), started from settings.theta_init or CLIVSVF (eq. 2.44).
template <typename S>
Status clsrivc(const ModelOrders& orders, const SvfSettings<S>& init_svf,
               const SrivcSettings<S>& settings, const RecordView<S>& record,
               const S* r1, const S* r2,
               const DiscreteTransferFunction<S>& controller,
               OfflineEstimate<S>* estimate) {
  offline_iv_detail::Loop<S> loop;
  loop.r1 = r1;
  loop.r2 = r2;
  loop.controller = &controller;
  return riv_detail::run_orders(orders, init_svf, settings, record, loop,
                                estimate);
}

}  // namespace ctid
