// SPDX-License-Identifier: BSD-3-Clause
// Copyright (C) the ctid authors
// The structure fit of residtrace: SRIVC (thesis eqs. 2.8-2.13, the
// offline refined-IV engine of offline/refined_iv.hpp) of the model
//
//   F(p) x(t) = sum_j B_j(p) w_j(t - nk_j Ts),   y = x + o(x, t) + e,
//
// where the channels w_j are signals made from the record (the inputs, a
// constant, the sign of the velocity, powers of the input or of the
// output, a clipped input, an inner node clipped: channel_signals below),
// some coefficients of F are fixed (integrators, a missing damping term)
// and o collects output terms (a level, a polynomial in x, a sinusoid, a
// saturation of the output).
//
//   channel_signals: the signals w_j, one column per channel.
//   estimate_structure: one SRIVC run of the structure from one start, with
//     the record's output level estimated jointly by the engine, missing
//     samples bridged by the model's own output (the expectation step of
//     an output-error model: they carry no error) and the initial
//     conditions of the integrators fitted as a polynomial in t.
//   fit_structure: the whole fit: several starts (the given ones first,
//     the engine's automatic start only when none of them gives a stable
//     estimate), the output terms by alternation with SRIVC (three rounds:
//     SRIVC on y minus the terms, then the terms by least squares on y
//     minus the model output), a censored output saturation (where the
//     model output lies beyond a level the measurement carries no
//     information on the linear part: SRIVC sees the model's own output
//     there and the other terms are fitted on the samples within the
//     levels), and the residual variance and BIC of the result.
//
// Why the level is estimated jointly: alternating it with SRIVC converges
// too slowly where the level and the static gain are nearly collinear (a
// slow process; a simulated linear two-tank record: static gain 0.36
// instead of 0.8 after three alternations).
#pragma once

#include <Eigen/Dense>
#include <cmath>
#include <complex>
#include <limits>
#include <string>
#include <vector>

#include "ctid/apps/residtrace/responses.hpp"
#include "ctid/base/polynomial.hpp"
#include "ctid/base/status.hpp"
#include "ctid/base/types.hpp"
#include "ctid/offline/refined_iv.hpp"

namespace ctid::residtrace {

enum class ChannelKind {
  kInput,        // u(:, col); a fraction f = param of a sample: see below
  kConstant,     // 1
  kSignV,        // sign of the velocity (first column of v), eq. 4.17
  kSignOutput,   // sign of the last column of v (the output as a velocity)
  kPower,        // u(:, col)^param
  kClip,         // u(:, col) clipped to +-param
  kOutputPower,  // y^param (sign(y) |y|^param for a fractional power)
  kNode          // Fa(0)/Fa(p) u(:, col) clipped to [lo, hi]
};

template <typename S>
struct StructureChannel {
  ChannelKind kind = ChannelKind::kInput;
  int col = 0;  // the input column (0-based)
  S param = 0;  // the fraction, power or clip level (0: none)
  int nb = 1;   // numerator length
  int nk = 0;   // delay in samples
  Vector<S> B;  // numerator (descending powers): start, then estimate
  // kNode: the denominator Fa (descending powers, Fa(0) != 0), the
  // sampling interval and hold of its simulation, the levels.
  Vector<S> node_f;
  S node_ts = 0;
  InterSample node_rule = InterSample::kZoh;
  S node_lo = -std::numeric_limits<S>::infinity();
  S node_hi = std::numeric_limits<S>::infinity();
};

// The signals of the channels, one column per channel (delays not applied):
// u N-by-nu; v N-by-k (the velocity in its first column, the output read as
// a velocity in its last; may be empty when no channel uses it); y the
// output the output powers act on (may be empty likewise). An input
// channel with a fraction f in (0, 1) of a sample (a transport delay that
// is not a whole number of samples) is the held input delayed by f,
// (1 - f) u(k) + f u(k-1) with u(0) = u(1): the shifted hold replaced by
// the two held values of the same area and centre, exact at low frequency
// with an error of order (w Ts)^2. A node channel is the input through
// the unit-gain lag Fa(0)/Fa(p) (exact ZOH or FOH, from rest) clipped to
// its levels (a tank that overflows, a valve at its end stop).
template <typename S>
Status channel_signals(const std::vector<StructureChannel<S>>& channels,
                       const Matrix<S>& u, const Matrix<S>& v,
                       const Vector<S>& y, Matrix<S>* W) {
  if (W == nullptr) return bad_input("no result");
  const Eigen::Index N = u.rows();
  *W = Matrix<S>::Zero(N, static_cast<Eigen::Index>(channels.size()));
  for (std::size_t j = 0; j < channels.size(); ++j) {
    const StructureChannel<S>& c = channels[j];
    auto w = W->col(static_cast<Eigen::Index>(j));
    const bool uses_u =
        c.kind == ChannelKind::kInput || c.kind == ChannelKind::kPower ||
        c.kind == ChannelKind::kClip || c.kind == ChannelKind::kNode;
    if (uses_u && (c.col < 0 || c.col >= u.cols())) {
      return bad_input("channel " + std::to_string(j + 1) +
                       " reads an input the record does not have");
    }
    const bool uses_v =
        c.kind == ChannelKind::kSignV || c.kind == ChannelKind::kSignOutput;
    if (uses_v && (v.cols() < 1 || v.rows() != N)) {
      return dimension_mismatch("the velocity needs one row per sample");
    }
    if (c.kind == ChannelKind::kOutputPower && y.size() != N) {
      return dimension_mismatch("the output needs one value per sample");
    }
    auto sign = [](S x) {
      return x > 0 ? S(1) : (x < 0 ? S(-1) : (x == 0 ? S(0) : x));
    };
    switch (c.kind) {
      case ChannelKind::kInput:
        w = u.col(c.col);
        if (c.param != 0 && N > 1) {
          for (Eigen::Index k = 0; k < N; ++k) {
            w(k) = (1 - c.param) * u(k, c.col) +
                   c.param * u(std::max<Eigen::Index>(k - 1, 0), c.col);
          }
        }
        break;
      case ChannelKind::kConstant:
        w.setOnes();
        break;
      case ChannelKind::kSignV:
        for (Eigen::Index k = 0; k < N; ++k) w(k) = sign(v(k, 0));
        break;
      case ChannelKind::kSignOutput:
        for (Eigen::Index k = 0; k < N; ++k) w(k) = sign(v(k, v.cols() - 1));
        break;
      case ChannelKind::kPower:
        for (Eigen::Index k = 0; k < N; ++k) {
          w(k) = std::pow(u(k, c.col), c.param);
        }
        break;
      case ChannelKind::kClip:
        for (Eigen::Index k = 0; k < N; ++k) {
          w(k) = std::min(std::max(u(k, c.col), -c.param), c.param);
        }
        break;
      case ChannelKind::kOutputPower:
        for (Eigen::Index k = 0; k < N; ++k) {
          w(k) = c.param == std::trunc(c.param)
                     ? std::pow(y(k), c.param)
                     : sign(y(k)) * std::pow(std::abs(y(k)), c.param);
        }
        break;
      case ChannelKind::kNode: {
        if (c.node_f.size() < 2 || c.node_f(0) == 0 ||
            c.node_f(c.node_f.size() - 1) == 0) {
          return bad_input(
              "a node channel needs Fa of order >= 1 with "
              "Fa(0) != 0");
        }
        const Vector<S> f = c.node_f.tail(c.node_f.size() - 1) / c.node_f(0);
        const Vector<S> x = u.col(c.col);
        Matrix<S> d;
        Status s =
            filtered_derivatives<S>(f, c.node_ts, c.node_rule, x.data(), N, d);
        if (!s.ok()) return s;
        const S gain = f(f.size() - 1);
        for (Eigen::Index k = 0; k < N; ++k) {
          w(k) = std::min(std::max(gain * d(k, 0), c.node_lo), c.node_hi);
        }
        break;
      }
    }
  }
  return Status::Ok();
}

// The number r of trailing coefficients of F = [1 f1 .. fn] fixed at 0
// (the structure's integrators).
template <typename S>
int structural_integrators(const Vector<S>& F, const std::vector<bool>& fixed) {
  const int n = static_cast<int>(F.size()) - 1;
  int r = 0;
  while (r < n && fixed[n - r - 1] && F(n - r) == 0) ++r;
  return r;
}

// The roots of F(0 .. n - r) (descending powers): F without r integrators.
template <typename S>
Eigen::Matrix<std::complex<S>, Eigen::Dynamic, 1> roots_without_integrators(
    const Vector<S>& F, int r) {
  const Eigen::Index d = F.size() - 1 - r;
  if (d < 1) return Eigen::Matrix<std::complex<S>, Eigen::Dynamic, 1>();
  Vector<S> ascending(d + 1);
  for (Eigen::Index i = 0; i <= d; ++i) ascending(i) = F(d - i);
  return polynomial_roots<S>(ascending);
}

// F stable apart from its structural integrators; a model whose structure
// has no damping may be marginally stable (an undamped pair allowed to
// 1e-9 relative).
template <typename S>
bool stable_apart_from_integrators(const Vector<S>& F,
                                   const std::vector<bool>& fixed) {
  if (!F.allFinite()) return false;
  const auto z = roots_without_integrators(F, structural_integrators(F, fixed));
  for (Eigen::Index i = 0; i < z.size(); ++i) {
    if (!(z(i).real() <= S(1e-9) * std::abs(z(i)))) return false;
  }
  return true;
}

// One run of the engine: the structure (n, which f are fixed and their
// values), the channels (signals W, nb, nk, the record's hold rule).
template <typename S>
struct StructureSpec {
  int n = 1;
  std::vector<bool> fixed;  // over f1 .. fn
  Vector<S> fval;           // f1 .. fn (the fixed ones' values)
  std::vector<int> nb, nk;
  InterSample rule = InterSample::kZoh;
  bool initial_state = false;  // its free response estimated
  bool output_offset = false;  // the output level c, estimated jointly
  std::vector<bool> missing;   // empty or N flags: bridged samples
};

template <typename S>
struct StructureStart {
  Vector<S> F;  // empty: the engine's automatic start
  std::vector<Vector<S>> B;
  S c0 = 0;  // the level's start (0 or non-finite: y at rest)
};

template <typename S>
struct StructureEstimate {
  bool ok = false;
  bool converged = false;
  bool stable = false;
  int iterations = 0;
  Vector<S> F;  // [1 f1 .. fn], the fixed ones exactly
  std::vector<Vector<S>> B;
  Vector<S> theta;  // free f's, then each channel's b's
  Matrix<S> cov;    // their SRIVC covariance
  S offset = 0, offset_std = 0;
  S s2 = 0;
  Vector<S> x;  // model output (with the level and the integrators' start)
  int np = 0;   // theta's size
};

// estimate_structure: SRIVC of the structure on y with the channels W
// (N-by-m) from the start. Returns the status of a run that fails (no
// estimate); est->ok false when the estimate is not finite. With r
// integrators, x includes the polynomial of degree r - 1 of their initial
// conditions fitted to y; with missing samples, y there is replaced by the
// model's output and the fit repeated from where it ended (twice), and x
// equals y at them.
template <typename S>
Status estimate_structure(Vector<S> y, const Matrix<S>& W, S ts,
                          const StructureSpec<S>& spec,
                          const StructureStart<S>& start, S tolerance,
                          int max_iterations, StructureEstimate<S>* est) {
  *est = StructureEstimate<S>();
  const int n = spec.n;
  const Eigen::Index N = y.size();
  const int m = static_cast<int>(W.cols());
  int nb_all = 0;
  for (int v : spec.nb) nb_all += v;
  int r = 0;
  while (r < n && spec.fixed[n - r - 1] && spec.fval(n - r - 1) == 0) ++r;
  const int nc = spec.output_offset ? 1 : 0;
  const int np_all = n + nb_all;
  RivProblem<S> problem;
  problem.nf = {n};
  for (int j = 0; j < m; ++j) {
    RivChannel c;
    c.nb = spec.nb[j];
    c.nk = spec.nk[j];
    c.rule = spec.rule;
    problem.channels.push_back(c);
  }
  problem.output_offset = spec.output_offset;
  problem.initial_state = spec.initial_state;
  bool any_fixed = false;
  for (bool b : spec.fixed) any_fixed = any_fixed || b;
  Vector<S> values = Vector<S>::Zero(np_all + nc);
  if (any_fixed) {
    problem.fixed.assign(np_all + nc, false);
    for (int i = 0; i < n; ++i) {
      problem.fixed[i] = spec.fixed[i];
      if (spec.fixed[i]) values(i) = spec.fval(i);
    }
    problem.fixed_values = values;
  }
  RivSettings<S> settings;
  settings.tolerance = tolerance;
  settings.max_iterations = max_iterations;
  bool from_start = start.F.size() > 0;
  if (from_start) {
    // the engine starts from stable denominators only
    const auto z = roots_without_integrators(start.F, r);
    for (Eigen::Index i = 0; i < z.size(); ++i) {
      if (!(z(i).real() < 0)) from_start = false;
    }
  }
  if (from_start) {
    Vector<S> th(np_all + nc);
    for (int i = 0; i < n; ++i) {
      th(i) = spec.fixed[i] ? values(i) : start.F(i + 1) / start.F(0);
    }
    int off = n;
    for (int j = 0; j < m; ++j) {
      th.segment(off, spec.nb[j]) = start.B[j];
      off += spec.nb[j];
    }
    if (nc) {
      if (std::isfinite(start.c0) && start.c0 != 0) {
        th(np_all) = start.c0;
      } else {
        th(np_all) = y.head(std::min<Eigen::Index>(5, N)).mean();
      }
    }
    settings.theta_init = th;
    settings.max_starts = 1;
  }
  std::vector<bool> present(N, true);
  Eigen::Index num_present = N;
  bool any_missing = false;
  if (static_cast<Eigen::Index>(spec.missing.size()) == N) {
    for (Eigen::Index k = 0; k < N; ++k) {
      if (spec.missing[k]) {
        present[k] = false;
        --num_present;
        any_missing = true;
      }
    }
  }
  RivData<S> data;
  data.y = y.data();
  data.w = W.data();
  data.num_samples = N;
  data.ts = ts;
  RivResult<S> res;
  Status status = refined_iv(problem, settings, data, &res);
  if (!status.ok() && status.code() != ErrorCode::kNotConverged) return status;
  auto valid = [&]() {
    return res.theta.size() == np_all + nc && res.theta.allFinite();
  };
  for (int k = 0; k < (any_missing ? 2 : 0); ++k) {
    if (!valid()) break;
    for (Eigen::Index i = 0; i < N; ++i) {
      if (!present[i]) y(i) = res.simulated(i);
    }
    settings.theta_init = res.theta;
    settings.max_starts = 1;
    RivResult<S> again;
    status = refined_iv(problem, settings, data, &again);
    if (!status.ok() && status.code() != ErrorCode::kNotConverged) {
      return status;
    }
    res = std::move(again);
  }
  if (!valid()) return Status::Ok();
  est->converged = res.converged;
  est->stable = res.stable;
  est->iterations = res.iterations;
  if (nc) {
    est->offset = res.theta(np_all);
    est->offset_std = std::sqrt(std::max(res.covariance(np_all, np_all), S(0)));
  }
  est->F.resize(n + 1);
  est->F(0) = 1;
  for (int i = 0; i < n; ++i) {
    est->F(i + 1) = spec.fixed[i] ? spec.fval(i) : res.theta(i);
  }
  int off = n;
  for (int j = 0; j < m; ++j) {
    est->B.push_back(res.theta.segment(off, spec.nb[j]));
    off += spec.nb[j];
  }
  std::vector<Eigen::Index> free;
  for (int i = 0; i < n; ++i) {
    if (!spec.fixed[i]) free.push_back(i);
  }
  for (int i = n; i < np_all; ++i) free.push_back(i);
  const Eigen::Index nf = static_cast<Eigen::Index>(free.size());
  est->theta.resize(nf);
  est->cov.resize(nf, nf);
  for (Eigen::Index a = 0; a < nf; ++a) {
    est->theta(a) = res.theta(free[a]);
    for (Eigen::Index b = 0; b < nf; ++b) {
      est->cov(a, b) = res.covariance(free[a], free[b]);
    }
  }
  Vector<S> x = res.simulated;
  if (x.size() != N) return Status::Ok();
  if (r > 0) {
    Matrix<S> T(num_present, r);
    Vector<S> d(num_present);
    for (Eigen::Index k = 0, i = 0; k < N; ++k) {
      if (!present[k]) continue;
      const S t = static_cast<S>(k) * ts;
      for (int c = 0; c < r; ++c) T(i, c) = std::pow(t, c);
      d(i++) = y(k) - x(k);
    }
    const Vector<S> a = T.colPivHouseholderQr().solve(d);
    for (Eigen::Index k = 0; k < N; ++k) {
      if (!present[k]) continue;
      const S t = static_cast<S>(k) * ts;
      for (int c = 0; c < r; ++c) x(k) += std::pow(t, c) * a(c);
    }
  }
  for (Eigen::Index k = 0; k < N; ++k) {
    if (!present[k]) x(k) = y(k);  // a missing sample: no error
  }
  est->np = static_cast<int>(nf);
  est->s2 = (y - x).squaredNorm() /
            std::max<S>(static_cast<S>(num_present - nf - r), S(1));
  est->x = x;
  est->ok = x.allFinite();
  return Status::Ok();
}

enum class OutputTermKind { kOffset, kPolynomial, kSinusoid, kSaturation };

// An output term: an offset c, a polynomial c1 x^2 + c2 x^3 of the model
// output, a sinusoid c1 sin(omega t) + c2 cos(omega t) (t from the first
// sample), or a saturation of the output to the fixed levels c = [lo hi].
template <typename S>
struct OutputTerm {
  OutputTermKind kind = OutputTermKind::kOffset;
  Vector<S> c, cstd;
  S omega = 0;
  bool fitted = false;  // set by fit_structure when it estimated c
};

// The model structure (the template) and its record.
template <typename S>
struct StructureModel {
  Vector<S> F;              // [F0 f1 .. fn]: the fixed f's values
  std::vector<bool> fixed;  // over f1 .. fn
  std::vector<StructureChannel<S>> channels;
  std::vector<OutputTerm<S>> out;
  // the level (the first offset term) estimated jointly by the engine
  bool levels = false;
};

template <typename S>
struct StructureRecord {
  Vector<S> y;
  Matrix<S> u;     // N-by-nu
  Matrix<S> vhat;  // the velocity from the measured output (signv)
  Vector<S> ysm;   // the output the output powers act on
  S ts = 1;
  InterSample rule = InterSample::kZoh;
  bool initial_state = false;
  std::vector<bool> missing;  // empty or N flags
};

template <typename S>
struct StructureFit {
  bool ok = false;
  int failed_round = 0;  // the alternation round no start succeeded in
  Vector<S> F;
  std::vector<Vector<S>> B;
  std::vector<OutputTerm<S>> out;
  Vector<S> theta;
  Matrix<S> cov;
  S s2 = 0, bic = 0;
  int np = 0;
  Vector<S> e;  // y minus the model output, 0 at missing samples
};

namespace structure_detail {

// The output terms other than the saturation by least squares on r = y - x
// (x the model output without the level) over the samples used; o their
// sum on the whole record. Terms without columns keep their values.
template <typename S>
void fit_output_terms(std::vector<OutputTerm<S>*>& terms, const Vector<S>& r,
                      const Vector<S>& x, S ts, const std::vector<bool>& use,
                      Vector<S>* o) {
  const Eigen::Index N = r.size();
  std::vector<Vector<S>> cols;
  for (OutputTerm<S>* t : terms) {
    switch (t->kind) {
      case OutputTermKind::kOffset:
        cols.push_back(Vector<S>::Ones(N));
        break;
      case OutputTermKind::kPolynomial:
        cols.push_back(x.array().square());
        cols.push_back(x.array().cube());
        break;
      case OutputTermKind::kSinusoid: {
        Vector<S> s(N), c(N);
        for (Eigen::Index k = 0; k < N; ++k) {
          const S wt = t->omega * static_cast<S>(k) * ts;
          s(k) = std::sin(wt);
          c(k) = std::cos(wt);
        }
        cols.push_back(s);
        cols.push_back(c);
        break;
      }
      case OutputTermKind::kSaturation:
        break;
    }
  }
  *o = Vector<S>::Zero(N);
  if (cols.empty()) return;
  const Eigen::Index p = static_cast<Eigen::Index>(cols.size());
  Eigen::Index nu = 0;
  for (bool b : use) nu += b;
  Matrix<S> X(nu, p);
  Vector<S> ru(nu);
  for (Eigen::Index k = 0, i = 0; k < N; ++k) {
    if (!use[k]) continue;
    for (Eigen::Index c = 0; c < p; ++c) X(i, c) = cols[c](k);
    ru(i++) = r(k);
  }
  const Vector<S> c = X.colPivHouseholderQr().solve(ru);
  for (Eigen::Index j = 0; j < p; ++j) *o += c(j) * cols[j];
  const S s2 =
      (ru - X * c).squaredNorm() / std::max<S>(static_cast<S>(nu - p), S(1));
  const Vector<S> cstd =
      (s2 * (X.transpose() * X).inverse()).diagonal().cwiseSqrt();
  Eigen::Index off = 0;
  for (OutputTerm<S>* t : terms) {
    if (t->kind == OutputTermKind::kSaturation) continue;
    const Eigen::Index k = t->kind == OutputTermKind::kOffset ? 1 : 2;
    t->c = c.segment(off, k);
    t->cstd = cstd.segment(off, k);
    t->fitted = true;
    off += k;
  }
}

}  // namespace structure_detail

// fit_structure: see the header comment. starts: initial denominators
// (each of the model's order, started with the model's numerators; an
// empty one is the engine's automatic start, tried only when no given
// start gives a stable estimate); the start giving the smallest residual
// variance is kept, and starts that end on an F unstable apart from its
// integrators are discarded. fit->ok false (and failed_round the round)
// when no start gives a stable estimate. The residual variance is
// s2 = e'e / (N - np) with np the free dynamic parameters plus the finite
// coefficients of the output terms, BIC = N log s2 + np log N.
template <typename S>
Status fit_structure(const StructureModel<S>& model,
                     const StructureRecord<S>& record,
                     const std::vector<Vector<S>>& starts, int max_iterations,
                     StructureFit<S>* fit) {
  if (fit == nullptr) return bad_input("no result");
  *fit = StructureFit<S>();
  const Eigen::Index N = record.y.size();
  const int n = static_cast<int>(model.F.size()) - 1;
  if (n < 1) return bad_input("F must have order >= 1");
  if (static_cast<int>(model.fixed.size()) != n) {
    return dimension_mismatch("fixed needs one flag per coefficient of F");
  }
  if (record.u.rows() != N) {
    return dimension_mismatch("u needs one row per sample of y");
  }
  for (const StructureChannel<S>& c : model.channels) {
    if (c.B.size() != c.nb || c.nb < 1) {
      return bad_input("each channel needs nb >= 1 start coefficients");
    }
  }
  for (const Vector<S>& F0 : starts) {
    if (F0.size() != 0 && F0.size() != n + 1) {
      return dimension_mismatch("each start needs the order of F");
    }
  }
  Matrix<S> W;
  Status status =
      channel_signals(model.channels, record.u, record.vhat, record.ysm, &W);
  if (!status.ok()) return status;
  fit->out = model.out;
  int k_lev = -1, isat = -1;
  std::vector<int> others;
  for (int k = 0; k < static_cast<int>(model.out.size()); ++k) {
    const OutputTermKind kind = model.out[k].kind;
    if (model.levels && k_lev < 0 && kind == OutputTermKind::kOffset) {
      k_lev = k;
      continue;
    }
    if (isat < 0 && kind == OutputTermKind::kSaturation) isat = k;
    others.push_back(k);
  }
  if (isat >= 0 && model.out[isat].c.size() != 2) {
    return bad_input("a saturation needs its levels [lo hi]");
  }
  StructureSpec<S> spec;
  spec.n = n;
  spec.fixed = model.fixed;
  spec.fval = model.F.tail(n);
  for (const StructureChannel<S>& c : model.channels) {
    spec.nb.push_back(c.nb);
    spec.nk.push_back(c.nk);
  }
  spec.rule = record.rule;
  spec.initial_state = record.initial_state;
  spec.output_offset = k_lev >= 0;
  std::vector<bool> miss(N, false);
  if (static_cast<Eigen::Index>(record.missing.size()) == N) {
    miss = record.missing;
    spec.missing = miss;
  }
  const Vector<S>& y = record.y;
  Vector<S> o = Vector<S>::Zero(N), o_lin = o;
  std::vector<bool> mask(N, false);
  const int rounds = others.empty() ? 1 : 3;
  StructureEstimate<S> best;
  bool have_best = false;
  for (int round = 1; round <= rounds; ++round) {
    std::vector<Vector<S>> cands;
    std::vector<Vector<S>> B0;
    if (round == 1) {
      // the given starts first; the engine's automatic start (a grid of
      // SVF cut-offs, the costly one) only when none of them gives a
      // stable estimate
      for (const Vector<S>& F0 : starts)
        if (F0.size() > 0) cands.push_back(F0);
      for (const Vector<S>& F0 : starts)
        if (F0.size() == 0) cands.push_back(F0);
      if (cands.empty()) cands.push_back(Vector<S>());
      for (const StructureChannel<S>& c : model.channels) B0.push_back(c.B);
    } else {
      cands.push_back(best.F);
      B0 = best.B;
    }
    have_best = false;
    for (const Vector<S>& F0 : cands) {
      if (F0.size() == 0 && have_best) break;  // a given start was stable
      StructureStart<S> st;
      st.F = F0;
      st.B = B0;
      if (k_lev >= 0 && model.out[k_lev].c.size() > 0) {
        st.c0 = model.out[k_lev].c(0);
      }
      StructureEstimate<S> est;
      const Status s = estimate_structure<S>(y - o, W, record.ts, spec, st,
                                             S(1e-6), max_iterations, &est);
      if (!s.ok() || !est.ok ||
          !stable_apart_from_integrators(est.F, model.fixed)) {
        continue;
      }
      if (!have_best || est.s2 < best.s2) {
        best = std::move(est);
        have_best = true;
      }
    }
    if (!have_best) {
      fit->failed_round = round;
      return Status::Ok();
    }
    if (k_lev >= 0) {
      fit->out[k_lev].c = Vector<S>::Constant(1, best.offset);
      fit->out[k_lev].cstd = Vector<S>::Constant(1, best.offset_std);
      fit->out[k_lev].fitted = true;
    }
    if (!others.empty()) {
      std::vector<OutputTerm<S>*> terms;
      for (int k : others) terms.push_back(&fit->out[k]);
      std::vector<bool> use(N);
      for (Eigen::Index k = 0; k < N; ++k) use[k] = !mask[k] && !miss[k];
      const Vector<S> x = best.x.array() - best.offset;
      structure_detail::fit_output_terms<S>(terms, y - best.x, x, record.ts,
                                            use, &o_lin);
      o = o_lin;
      if (isat >= 0) {
        const S lo = model.out[isat].c(0), hi = model.out[isat].c(1);
        for (Eigen::Index k = 0; k < N; ++k) {
          const S yl = best.x(k) + o_lin(k);
          mask[k] = yl > hi || yl < lo;
          if (mask[k]) o(k) = y(k) - best.x(k);  // y - o = x: imputed
        }
      }
    }
  }
  if (isat >= 0) {
    const S lo = model.out[isat].c(0), hi = model.out[isat].c(1);
    for (Eigen::Index k = 0; k < N; ++k) {
      o(k) = std::min(std::max(best.x(k) + o_lin(k), lo), hi) - best.x(k);
    }
  }
  fit->F = best.F;
  fit->B = best.B;
  Vector<S> e = y - best.x - o;
  for (Eigen::Index k = 0; k < N; ++k)
    if (miss[k]) e(k) = 0;
  int nout = 0;
  for (const OutputTerm<S>& t : fit->out) {
    for (Eigen::Index i = 0; i < t.c.size(); ++i) nout += std::isfinite(t.c(i));
  }
  fit->np = best.np + nout;
  fit->s2 = e.squaredNorm() / std::max<S>(static_cast<S>(N - fit->np), S(1));
  fit->theta = best.theta;
  fit->cov = best.cov;
  fit->bic = static_cast<S>(N) * std::log(fit->s2) +
             static_cast<S>(fit->np) * std::log(static_cast<S>(N));
  fit->e = e;
  fit->ok = true;
  return Status::Ok();
}

}  // namespace ctid::residtrace
