// SPDX-License-Identifier: BSD-3-Clause
// Copyright (C) the ctid authors
// SRIVC (thesis eqs. 2.8-2.13) of B(p)/F(p) e^(-td p) with a continuous
// delay td (any fraction of a sample; the delayed ZOH/FOH input is filtered
// exactly), the delay estimated by delay_search.hpp's search: a grid of
// the simulation-error variance V(td) of the model fitted at td, then
// Gauss-Newton steps on td (CONTSID's tfsrivc, TDSRIVC). With a noise model
// (tfrivc) the model fitted at td is RIVC's (refined_iv_bj.hpp: the plant
// and a discrete ARMA noise model C/D, thesis sec. 2.1.2), V the
// innovation variance, and the Gauss-Newton residual and sensitivities
// are prefiltered by D/C(q^-1), the whitening filter of the noise model
// (the discrete part of RIVC's prefilter, eq. 2.9 for the Box-Jenkins
// model): the delay is then estimated jointly with the plant and the
// noise model, as a prediction-error estimate.
//
// The sensitivities of the simulated output y_hat to td and to the free
// coefficients are central differences of the model output (the engine
// run without iterations from the coefficients); the covariance of
// [theta; td] (td estimated) or theta is sigma^2 (J^T J)^-1 with J those
// (whitened) sensitivities and sigma^2 = V, for theta alone SRIVC's eq.
// (2.13) covariance.
#pragma once

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "ctid/base/stability.hpp"
#include "ctid/offline/delay_search.hpp"
#include "ctid/offline/refined_iv.hpp"
#include "ctid/offline/refined_iv_bj.hpp"

namespace ctid {

template <typename S>
struct RivDelaySettings {
  // The range, grid and refinement; refinement kGaussNewton estimates the
  // delay, kNone keeps the start (grid = false) or the best grid point.
  DelaySearchSettings<S> search;
  // RIVC with the ARMA noise model C/D of orders nc, nd instead of SRIVC
  // (regular sampling only).
  bool noise_model = false;
  int nc = 0, nd = 0;
  int arma_max_iterations = 50;
};

template <typename S>
struct RivDelayResult {
  S delay = 0;
  bool delay_estimated = false;
  Vector<S> theta;       // [f b] of the model at the delay kept
  Matrix<S> covariance;  // of [theta; td] (delay estimated) or theta
  S loss = 0;            // V at the delay kept
  Vector<S> simulated;   // the plant model's output there
  std::vector<S> grid, grid_loss;
  S td_max = 0;  // the upper end of the range used
  int iterations = 0;
  bool converged = true;
  std::string reason;
  RivResult<S> engine;  // SRIVC at the delay kept (no noise model)
  RivcResult<S> rivc;   // RIVC at the delay kept (noise model)
};

namespace riv_delay_detail {

template <typename S>
struct DelayFit {
  S td = 0;
  S loss = std::numeric_limits<S>::infinity();
  Vector<S> theta;
  RivResult<S> engine;
  RivcResult<S> rivc;
  const Vector<S>& simulated(bool noise) const {
    return noise ? rivc.simulated : engine.simulated;
  }
};

// x (columns) through D/C(q^-1), in place.
template <typename S>
void whiten(const Vector<S>& d, const Vector<S>& c, Matrix<S>& x) {
  const Eigen::Index n = x.rows();
  for (Eigen::Index j = 0; j < x.cols(); ++j) {
    Vector<S> in = x.col(j);
    for (Eigen::Index t = 0; t < n; ++t) {
      S v = 0;
      for (Eigen::Index k = 0; k < d.size() && k <= t; ++k)
        v += d(k) * in(t - k);
      for (Eigen::Index k = 1; k < c.size() && k <= t; ++k)
        v -= c(k) * x(t - k, j);
      x(t, j) = v / c(0);
    }
  }
}

template <typename S>
class Model {
 public:
  using Fit = DelayFit<S>;
  Model(const RivProblem<S>& problem, const RivSettings<S>& settings,
        const RivData<S>& data, const RivDelaySettings<S>& delay)
      : problem_(problem), settings_(settings), data_(data), delay_(delay) {
    const int np = problem.num_parameters();
    for (int i = 0; i < np; ++i) {
      if (problem.fixed.empty() || !problem.fixed[i]) free_.push_back(i);
    }
    h_ = data.ts;
    if (data.instants != nullptr) {
      std::vector<S> dt;
      for (Eigen::Index k = 1; k < data.num_samples; ++k)
        dt.push_back(data.instants[k] - data.instants[k - 1]);
      std::sort(dt.begin(), dt.end());
      const std::size_t m = dt.size();
      h_ = m % 2 ? dt[m / 2] : (dt[m / 2 - 1] + dt[m / 2]) / 2;
    }
  }
  S sampling() const { return h_; }
  bool noise() const { return delay_.noise_model; }

  Status fit(S td, const Vector<S>& start, Fit* out) {
    out->td = td;
    const Vector<S>& from = start.size() > 0 ? start : settings_.theta_init;
    Status s;
    if (delay_.noise_model) {
      s = fit_rivc(td, from, out);
    } else {
      RivProblem<S> p = problem_;
      p.channels[0].delay = td;
      RivSettings<S> st = settings_;
      st.theta_init = from;
      s = refined_iv(p, st, data_, &out->engine);
      if (s.code() == ErrorCode::kNotConverged) s = Status::Ok();
      if (!s.ok()) return s;
      out->theta = out->engine.theta;
      out->loss = out->engine.stable ? out->engine.noise_variance
                                     : std::numeric_limits<S>::infinity();
    }
    return s;
  }

  // The whitened output error, td sensitivity and sensitivities to the
  // free coefficients at f.
  Status step_terms(const Fit& f, Vector<S>* e, Vector<S>* g, Matrix<S>* J) {
    Matrix<S> x(data_.num_samples, 1);
    x.col(0) = Eigen::Map<const Vector<S>>(data_.y, data_.num_samples) -
               f.simulated(noise());
    whiten_at(f, x);
    *e = x.col(0);
    Status s = sensitivities(f, false, J);
    if (!s.ok()) return s;
    Matrix<S> gt;
    s = sensitivities(f, true, &gt);
    if (!s.ok()) return s;
    *g = gt.col(0);
    return s;
  }

  // Columns dy/dtheta_i (free i) or dy/dtd, whitened with f's noise model.
  Status sensitivities(const Fit& f, bool td, Matrix<S>* J) {
    const Eigen::Index n = data_.num_samples;
    Vector<S> yp, ym;
    Status s;
    if (td) {
      J->resize(n, 1);
      const S dt = S(1e-3) * h_;
      const S lo = std::max(f.td - dt, S(0));
      s = simulate(f.theta, f.td + dt, &yp);
      if (s.ok()) s = simulate(f.theta, lo, &ym);
      if (!s.ok()) return s;
      J->col(0) = (yp - ym) / (f.td + dt - lo);
    } else {
      J->resize(n, static_cast<Eigen::Index>(free_.size()));
      const S scale = S(1e-3) * f.theta.norm();
      for (std::size_t c = 0; c < free_.size(); ++c) {
        const int i = free_[c];
        const S dp = S(1e-6) * std::max(std::abs(f.theta(i)), scale);
        Vector<S> tp = f.theta, tm = f.theta;
        tp(i) += dp;
        tm(i) -= dp;
        s = simulate(tp, f.td, &yp);
        if (s.ok()) s = simulate(tm, f.td, &ym);
        if (!s.ok()) return s;
        J->col(c) = (yp - ym) / (2 * dp);
      }
    }
    whiten_at(f, *J);
    return Status::Ok();
  }

  const std::vector<int>& free() const { return free_; }

 private:
  void whiten_at(const Fit& f, Matrix<S>& x) const {
    if (delay_.noise_model && x.cols() > 0)
      whiten(f.rivc.noise.d, f.rivc.noise.c, x);
  }

  // The model's output at theta, td: the engine without iterations.
  Status simulate(const Vector<S>& theta, S td, Vector<S>* y) {
    RivProblem<S> p = problem_;
    p.channels[0].delay = td;
    RivSettings<S> st = settings_;
    st.theta_init = theta;
    st.max_iterations = 0;
    RivResult<S> r;
    Status s = refined_iv(p, st, data_, &r);
    if (s.code() == ErrorCode::kNotConverged) s = Status::Ok();
    if (!s.ok()) return s;
    *y = r.simulated;
    return s;
  }

  // RIVC of the plant and the noise model at td: nk whole samples and the
  // fraction, filtered exactly.
  Status fit_rivc(S td, const Vector<S>& from, Fit* out) {
    const RivChannel& c = problem_.channels[0];
    RivcProblem<S> p;
    p.nf = problem_.nf[0];
    p.nb = c.nb;
    p.nc = delay_.nc;
    p.nd = delay_.nd;
    p.nk = static_cast<int>(std::floor(td / data_.ts + S(1e-9)));
    p.delay = std::max(td - p.nk * data_.ts, S(0));
    p.u_rule = c.rule;
    RivcSettings<S> st;
    st.tolerance = settings_.tolerance;
    st.max_iterations = settings_.max_iterations;
    st.theta_init = from;
    st.start.cutoffs = settings_.cutoffs;
    st.start.max_starts = 3;
    st.start.tolerance = settings_.tolerance;
    st.start.max_iterations = std::max(settings_.max_iterations, 30);
    st.arma.max_iterations = delay_.arma_max_iterations;
    const RivcData<S> d{data_.y, data_.w, data_.num_samples, data_.ts};
    Status s = rivc<S>(p, st, d, &out->rivc);
    if (s.code() == ErrorCode::kNotConverged) s = Status::Ok();
    if (!s.ok()) return s;
    out->theta = out->rivc.theta;
    HurwitzTest<S> hurwitz(p.nf);
    out->rivc.stable = hurwitz.is_stable(out->theta.head(p.nf));
    const S v = out->rivc.noise.innovation_variance;
    out->loss = out->rivc.stable && std::isfinite(v)
                    ? v
                    : std::numeric_limits<S>::infinity();
    return s;
  }

  const RivProblem<S>& problem_;
  const RivSettings<S>& settings_;
  const RivData<S>& data_;
  const RivDelaySettings<S>& delay_;
  std::vector<int> free_;
  S h_ = 0;
};

}  // namespace riv_delay_detail

// SRIVC (or RIVC) with the delay searched (see the header comment). The
// problem: one group, one channel, open loop, no offset or initial state;
// its channel's delay is the search's. A fit that does not converge at
// the delay kept is returned with its engine status in result->engine
// (or rivc); the search's own convergence is result->converged.
template <typename S>
Status refined_iv_delay(const RivProblem<S>& problem,
                        const RivSettings<S>& settings, const RivData<S>& data,
                        const RivDelaySettings<S>& delay,
                        RivDelayResult<S>* result) {
  if (result == nullptr) return bad_input("the result must not be null");
  if (problem.nf.size() != 1 || problem.channels.size() != 1 ||
      problem.closed_loop() || problem.output_offset || problem.initial_state ||
      settings.method != RivMethod::kSrivc) {
    return not_supported(
        "the delay search takes one input, one denominator, open loop, "
        "SRIVC, no offset or initial state");
  }
  if (delay.noise_model &&
      (data.instants != nullptr || !(data.ts > 0) || !problem.fixed.empty())) {
    return not_supported(
        "a noise model needs regularly sampled data and no fixed "
        "coefficients");
  }
  if (data.num_samples < 2 || data.y == nullptr || data.w == nullptr) {
    return bad_input("the record is empty");
  }
  riv_delay_detail::Model<S> model(problem, settings, data, delay);
  DelaySearchSettings<S> search = delay.search;
  search.step_tolerance = delay.search.step_tolerance * model.sampling();
  DelaySearchOutcome<S, riv_delay_detail::DelayFit<S>> out;
  Status s = delay_search(model, search, &out);
  if (!s.ok()) return s;
  const riv_delay_detail::DelayFit<S>& cur = out.best;
  const bool estimated = search.refinement == DelayRefinement::kGaussNewton;
  // Covariance sigma^2 (J^T J)^-1 from the output sensitivities.
  Matrix<S> J, g;
  s = model.sensitivities(cur, false, &J);
  if (!s.ok()) return s;
  if (estimated) {
    s = model.sensitivities(cur, true, &g);
    if (!s.ok()) return s;
    J.conservativeResize(Eigen::NoChange, J.cols() + 1);
    J.col(J.cols() - 1) = g.col(0);
  }
  const Matrix<S> A = J.transpose() * J;
  Matrix<S> C = Matrix<S>::Constant(A.rows(), A.cols(),
                                    std::numeric_limits<S>::quiet_NaN());
  if (A.rows() > 0) {
    Eigen::PartialPivLU<Matrix<S>> lu(A);
    if (lu.rcond() > std::numeric_limits<S>::epsilon())
      C = cur.loss * lu.inverse();
  }
  const int np = problem.num_parameters();
  std::vector<int> sel = model.free();
  if (estimated) sel.push_back(np);
  result->covariance =
      Matrix<S>::Zero(np + (estimated ? 1 : 0), np + (estimated ? 1 : 0));
  for (std::size_t i = 0; i < sel.size(); ++i)
    for (std::size_t j = 0; j < sel.size(); ++j)
      result->covariance(sel[i], sel[j]) = (C(i, j) + C(j, i)) / 2;
  result->delay = cur.td;
  result->delay_estimated = estimated;
  result->theta = cur.theta;
  result->loss = cur.loss;
  result->simulated = cur.simulated(delay.noise_model);
  result->grid = out.grid;
  result->grid_loss = out.grid_loss;
  result->td_max = out.td_max;
  result->iterations = out.iterations;
  result->converged = out.converged;
  result->reason = out.reason;
  result->engine = cur.engine;
  result->rivc = cur.rivc;
  return Status::Ok();
}

}  // namespace ctid
