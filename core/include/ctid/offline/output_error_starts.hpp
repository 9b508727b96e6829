// SPDX-License-Identifier: BSD-3-Clause
// Copyright (C) the ctid authors
// The output-error estimate (output_error.hpp, thesis sec. 1.3.3, eq. 1.16
// with H = 1) minimised from several starts, the lowest loss kept: the
// output-error loss of a delayed model has local minima (on a ZOH input a
// kink at every whole number of samples of delay), so a gradient method
// is run from each start a delay search gives (the toolbox's tfcoe).
//
// With the delay estimated (one input, continuous time) it is kept in
// [delay_min, delay_max]. The iteration keeps it in [0, delay_max]; a run
// that ends below delay_min is replaced by the minimum over the
// coefficients at td = delay_min (the bound active), or by the free run
// from that point when it ends within the range with a lower loss (the
// loss decreasing into the range from the bound). When the kept estimate
// lies at delay_min (to 1e-6 sampling intervals) the delay is no free
// parameter (an active constraint): the result is the minimum over the
// coefficients at delay_min, theta = [f; b] without the delay.
//
// With `integrate`, the model B(p) / (p F'(p)) e^(-td p) (a pole fixed at
// p = 0, F = p F' with f_nf = 0) is fitted as B/F' on the integral v of
// the input, v(t_k) = sum_(i<k) u(t_i) (t_(i+1) - t_i): of a ZOH input an
// exact FOH signal on the same instants, so the pole at 0 is exact and F'
// is estimated. Starts and result are in the layout of F (f_nf = 0, with
// zero rows and columns of the covariance).
//
// reduced_start gives one more start from an over-parametrised fit
// (tfcoe's OverPar): the output-error loss of an over-parametrised model
// has fewer non-global minima (Soderstrom and Stoica, "Some properties of
// the output error method", Automatica 18(1), 1982), and an extra
// pole-zero pair can take up a delay error (a first-order Pade term). The
// frequency response of that model over the band of the record is
// reduced to the asked orders by the frequency-domain output error
// (freq_srivc.hpp, TFFCOE), its delay searched or kept.
#pragma once

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "ctid/base/status.hpp"
#include "ctid/base/types.hpp"
#include "ctid/offline/freq_srivc.hpp"
#include "ctid/offline/output_error.hpp"

namespace ctid {

template <typename S>
struct OeStartsSettings {
  // Starts [f; b (; td)] in the layout of the structure (the delay last
  // when it is estimated; outside [delay_min, delay_max] it is moved to
  // the nearer bound).
  std::vector<Vector<S>> starts;
  // Also the run of OeSettings as given (theta_init, or the SRIVC / ARX
  // start), first; its delay (when estimated) starts from the
  // structure's and is bounded by the iteration's [0, delay_max] only.
  bool default_start = false;
  S delay_min = 0;  // lower bound of an estimated delay (time units)
  bool integrate = false;
};

template <typename S>
struct OeStartsResult {
  OeResult<S> best;  // theta [f; b (; td)], covariance of theta
  bool delay_estimated = false;
  S delay = 0;              // the delay of the model (time units)
  int free_parameters = 0;  // the parameters minimised over
};

// The exact integral of a ZOH input at its own instants (regular: ts).
template <typename S>
std::vector<S> integrate_zoh_input(const S* u, Eigen::Index n, S ts,
                                   const S* instants) {
  std::vector<S> v(static_cast<std::size_t>(n), S(0));
  for (Eigen::Index k = 1; k < n; ++k) {
    const S h = instants != nullptr ? instants[k] - instants[k - 1] : ts;
    v[k] = v[k - 1] + u[k - 1] * h;
  }
  return v;
}

namespace oe_starts_detail {

// The median sampling interval (regular: ts).
template <typename S>
S median_interval(const OeData<S>& d) {
  if (d.instants == nullptr || d.num_samples < 2) return d.ts;
  std::vector<S> h(static_cast<std::size_t>(d.num_samples - 1));
  for (Eigen::Index k = 1; k < d.num_samples; ++k)
    h[k - 1] = d.instants[k] - d.instants[k - 1];
  std::sort(h.begin(), h.end());
  const std::size_t m = h.size();
  return m % 2 == 1 ? h[m / 2] : (h[m / 2 - 1] + h[m / 2]) / 2;
}

// One run; only a failure other than non-convergence stops the caller
// (the last iterate of a run that did not converge competes).
template <typename S>
Status run(const OeStructure& s, OeSettings<S> settings, const Vector<S>* start,
           const OeData<S>& d, OeResult<S>* r) {
  if (start != nullptr) settings.theta_init = *start;
  const Status st = output_error(s, settings, d, r);
  if (!st.ok() && st.code() != ErrorCode::kNotConverged) return st;
  return Status::Ok();
}

// The run from st = [f; b; td] with the delay kept in [delay_min,
// delay_max] (see the file comment).
template <typename S>
Status bounded_run(OeStructure s, const OeSettings<S>& settings,
                   const Vector<S>& st, S delay_min, const OeData<S>& d,
                   OeResult<S>* r) {
  const Eigen::Index np = st.size();
  s.delay = static_cast<double>(st(np - 1));
  Status status = run(s, settings, &st, d, r);
  if (!status.ok() || r->theta(np - 1) >= delay_min) return status;
  OeStructure fixed = s;
  fixed.estimate_delay = false;
  fixed.delay = static_cast<double>(delay_min);
  const Vector<S> coefficients = r->theta.head(np - 1);
  OeResult<S> rf;
  status = run(fixed, settings, &coefficients, d, &rf);
  if (!status.ok()) return status;
  Vector<S> theta(np);
  theta << rf.theta, delay_min;
  Matrix<S> P = Matrix<S>::Zero(np, np);
  P.topLeftCorner(np - 1, np - 1) = rf.covariance;
  rf.theta = theta;
  rf.covariance = P;
  s.delay = static_cast<double>(delay_min);
  OeResult<S> rk;
  status = run(s, settings, &theta, d, &rk);
  if (!status.ok()) return status;
  *r = rk.theta(np - 1) >= delay_min && rk.loss < rf.loss ? rk : rf;
  return Status::Ok();
}

// theta (and its covariance) with a zero inserted at `index`.
template <typename S>
void insert_fixed_zero(Eigen::Index index, OeResult<S>* r) {
  const Eigen::Index n = r->theta.size();
  Vector<S> theta = Vector<S>::Zero(n + 1);
  theta.head(index) = r->theta.head(index);
  theta.tail(n - index) = r->theta.tail(n - index);
  Matrix<S> P = Matrix<S>::Zero(n + 1, n + 1);
  const Matrix<S>& C = r->covariance;
  if (C.rows() == n && C.cols() == n) {
    const Eigen::Index t = n - index;
    P.topLeftCorner(index, index) = C.topLeftCorner(index, index);
    P.topRightCorner(index, t) = C.topRightCorner(index, t);
    P.bottomLeftCorner(t, index) = C.bottomLeftCorner(t, index);
    P.bottomRightCorner(t, t) = C.bottomRightCorner(t, t);
  }
  r->theta = theta;
  r->covariance = P;
}

}  // namespace oe_starts_detail

template <typename S>
Status output_error_from_starts(const OeStructure& structure,
                                const OeSettings<S>& settings,
                                const OeStartsSettings<S>& starts,
                                const OeData<S>& data,
                                OeStartsResult<S>* result) {
  using namespace oe_starts_detail;
  if (result == nullptr) return bad_input("no result given");
  if (starts.starts.empty() && !starts.default_start)
    return bad_input("no start given");
  OeStructure s = structure;
  const bool bounded = s.estimate_delay;
  if (bounded &&
      (s.time != OeTime::kContinuous || !s.inputs.empty() || s.nk != 0)) {
    return bad_input(
        "a bounded delay is estimated in continuous time, one input, nk = 0");
  }
  if (bounded && !(starts.delay_min >= 0 && starts.delay_min <= s.delay_max))
    return bad_input("delay_min must lie in [0, delay_max]");
  OeData<S> d = data;
  std::vector<S> integral;
  const Eigen::Index fixed_pole = s.nf - 1;  // f_nf in [f; b (; td)]
  if (starts.integrate) {
    if (s.time != OeTime::kContinuous || !s.inputs.empty() ||
        data.num_inputs != 1 || s.rule != InterSample::kZoh) {
      return not_supported(
          "a pole at 0 by integration needs one ZOH input in continuous time");
    }
    if (s.nf < 2 || s.nb > s.nf - 1) {
      return not_supported(
          "a pole at 0 by integration needs nf >= 2 and nb <= nf - 1");
    }
    if (data.u == nullptr) return bad_input("no data given");
    integral =
        integrate_zoh_input(data.u, data.num_samples, data.ts, data.instants);
    d.u = integral.data();
    s.nf -= 1;
    s.rule = InterSample::kFoh;
  }
  const int np = s.num_parameters();
  const int np_full = np + (starts.integrate ? 1 : 0);

  OeResult<S> best, r;
  bool have = false;
  Status status;
  if (starts.default_start) {
    status = run(s, settings, static_cast<const Vector<S>*>(nullptr), d, &best);
    if (!status.ok()) return status;
    have = true;
  }
  for (const Vector<S>& given : starts.starts) {
    if (given.size() != np_full) {
      return dimension_mismatch("each start needs " + std::to_string(np_full) +
                                " entries");
    }
    Vector<S> st = given;
    if (starts.integrate) {
      st.resize(np);
      st.head(fixed_pole) = given.head(fixed_pole);
      st.tail(np - fixed_pole) = given.tail(np - fixed_pole);
    }
    if (bounded) {
      st(np - 1) = std::min(std::max(st(np - 1), starts.delay_min),
                            static_cast<S>(s.delay_max));
      status = bounded_run(s, settings, st, starts.delay_min, d, &r);
    } else {
      status = run(s, settings, &st, d, &r);
    }
    if (!status.ok()) return status;
    if (!have || r.loss < best.loss) best = r;
    have = true;
  }

  result->delay_estimated = bounded;
  result->delay = static_cast<S>(s.delay);
  if (bounded) {
    result->delay = best.theta(np - 1);
    if (best.theta(np - 1) <= starts.delay_min + S(1e-6) * median_interval(d)) {
      OeStructure fixed = s;
      fixed.estimate_delay = false;
      fixed.delay = static_cast<double>(starts.delay_min);
      const Vector<S> coefficients = best.theta.head(np - 1);
      status = run(fixed, settings, &coefficients, d, &best);
      if (!status.ok()) return status;
      result->delay_estimated = false;
      result->delay = starts.delay_min;
    }
  }
  result->free_parameters = static_cast<int>(best.theta.size());
  if (starts.integrate) insert_fixed_zero(fixed_pole, &best);
  result->best = best;
  if (!best.converged) return Status(ErrorCode::kNotConverged, best.reason);
  return Status::Ok();
}

// The model f_over (monic, without its leading 1, descending powers of
// p), b_over, td_over as a frequency response on 200 logarithmically
// spaced frequencies in [w_lo, w_hi], reduced to nf poles and nb
// numerator coefficients by freq_srivc's output error: the delay searched
// on its grid over [0, delay_max] (search_delay) or fixed at td_over.
// start = [f; b; td]; empty when the reduced model is not stable (no
// start). A fit that did not converge still gives its last iterate.
template <typename S>
Status reduced_start(const Vector<S>& f_over, const Vector<S>& b_over,
                     S td_over, int nf, int nb, S w_lo, S w_hi,
                     bool search_delay, S delay_max, Vector<S>* start) {
  if (start == nullptr) return bad_input("no result given");
  if (!(w_lo > 0) || !(w_hi > w_lo) || !std::isfinite(w_hi))
    return bad_input("the band needs 0 < w_lo < w_hi < Inf");
  if (!f_over.allFinite() || !b_over.allFinite() || !std::isfinite(td_over))
    return bad_input("the over-parametrised model must be finite");
  const int K = 200;
  std::vector<S> w(K);
  std::vector<std::complex<S>> g(K);
  const S a = std::log10(w_lo), b = std::log10(w_hi);
  for (int k = 0; k < K; ++k) {
    w[k] = std::pow(S(10), a + (b - a) * static_cast<S>(k) / S(K - 1));
    const std::complex<S> s(0, w[k]);
    std::complex<S> num = 0, den = 1;
    for (Eigen::Index i = 0; i < b_over.size(); ++i) num = num * s + b_over(i);
    for (Eigen::Index i = 0; i < f_over.size(); ++i) den = den * s + f_over(i);
    g[k] = num / den * std::exp(-s * td_over);
  }
  FreqSettings<S> settings;
  settings.na = nf;
  settings.nb = nb;
  settings.output_error = true;
  if (search_delay) {
    settings.estimate_delay = true;
    settings.td_min = 0;
    settings.td_max = delay_max;
  } else {
    settings.delay = td_over;
  }
  FreqData<S> data;
  data.w = w.data();
  data.y = g.data();
  data.num_frequencies = K;
  FreqResult<S> r;
  const Status status = freq_srivc(settings, data, &r);
  if (!status.ok() && status.code() != ErrorCode::kNotConverged) return status;
  start->resize(0);
  if (!r.stable) return Status::Ok();
  start->resize(nf + nb + 1);
  *start << r.a, r.b, r.delay;
  return Status::Ok();
}

}  // namespace ctid
