// SPDX-License-Identifier: BSD-3-Clause
// Copyright (C) the ctid authors

// The sinusoidal-disturbance candidate of residtrace (candidate.hpp):
//
//   y = x + a sin(w t) + b cos(w t)
//
// for the strongest line of the periodogram I_k = |E_k|^2 / N of the
// current model's estimation residual e (its mean removed), k = 1 .. m,
// m = floor((N - 1) / 2), tested by Fisher's g = max I_k / sum I_k with
// the p-value m (1 - g)^(m - 1) over the m bins kept. Left out are
//   - bins where an input has a line of its own (its periodogram above 20
//     times its running median over the 21 neighbouring bins): a line
//     there is driven by the input, i.e. missing dynamics, not a
//     disturbance;
//   - periods the records do not resolve: at least two cycles in the
//     estimation record (duration T_e) and one in each half of the
//     validation record (T_v), w >= 4 pi / min(T_e, T_v), for the search
//     and the refined frequency alike. Over a cycle or less a sinusoid
//     cannot be told from a level or a drift.
// The frequency is refined to the maximum of |sum e(t) exp(-i w t)| on 41
// points between the neighbouring bins; a and b are then fitted with the
// model (fit_model: the sinusoid is an output term of the structure fit).
// Evidence: frequency, amplitude sqrt(a^2 + b^2) with the root mean square
// of the two standard deviations, g and its p-value.
#pragma once

#include <algorithm>
#include <cmath>
#include <complex>
#include <string>
#include <unsupported/Eigen/FFT>
#include <vector>

#include "ctid/apps/residtrace/candidate.hpp"
#include "ctid/apps/residtrace/model_fit.hpp"
#include "ctid/base/status.hpp"

namespace ctid::residtrace {

namespace sinusoid_detail {

// The median of x[lo .. hi] (the mean of the two middle values for an even
// count).
template <typename S>
S median_of(const Vector<S>& x, Eigen::Index lo, Eigen::Index hi) {
  std::vector<S> w(x.data() + lo, x.data() + hi + 1);
  const std::size_t n = w.size(), h = n / 2;
  std::nth_element(w.begin(), w.begin() + h, w.end());
  const S upper = w[h];
  if (n % 2 == 1) return upper;
  const S lower = *std::max_element(w.begin(), w.begin() + h);
  return (lower + upper) / 2;
}

// The running median over windows of L (odd) samples, shortened at the
// ends.
template <typename S>
Vector<S> running_median(const Vector<S>& x, Eigen::Index L) {
  const Eigen::Index n = x.size(), h = L / 2;
  Vector<S> m(n);
  for (Eigen::Index i = 0; i < n; ++i) {
    m(i) = median_of<S>(x, std::max<Eigen::Index>(0, i - h),
                        std::min<Eigen::Index>(n - 1, i + h));
  }
  return m;
}

// |X_k|^2, k = 1 .. m, of the discrete Fourier transform of x.
template <typename S>
Vector<S> power_bins(const Vector<S>& x, Eigen::Index m) {
  Eigen::FFT<S> fft;
  std::vector<S> in(x.data(), x.data() + x.size());
  std::vector<std::complex<S>> X;
  fft.fwd(X, in);
  Vector<S> p(m);
  for (Eigen::Index k = 0; k < m; ++k) p(k) = std::norm(X[k + 1]);
  return p;
}

}  // namespace sinusoid_detail

// The sinusoid candidate (head of this file); ctx.validation_samples the
// length of the validation record.
template <typename S>
Status sinusoid_candidate(const ResidtraceModel<S>& cur,
                          const CandidateContext<S>& ctx, Candidate<S>* c) {
  using candidate_detail::num;
  using namespace sinusoid_detail;
  if (c == nullptr) return bad_input("no result");
  *c = Candidate<S>();
  c->effect = "sinusoid";
  const Eigen::Index N = cur.estimate.e.size();
  if (N != ctx.D.y.size()) {
    return bad_input(
        "the model's estimation residual needs one value a sample of the "
        "record");
  }
  if (ctx.D.u.rows() != N) return bad_input("the inputs need N rows");
  const Vector<S> e = cur.estimate.e.array() - cur.estimate.e.mean();
  const S ts = ctx.D.ts;
  const Eigen::Index m = (N - 1) / 2;
  if (m < 8) {
    c->reason = "too few samples for a periodogram";
    return Status::Ok();
  }
  const Vector<S> I = power_bins<S>(e, m) / static_cast<S>(N);
  std::vector<bool> keep(static_cast<std::size_t>(m), true);
  for (Eigen::Index j = 0; j < ctx.D.u.cols(); ++j) {
    const Vector<S> uj = ctx.D.u.col(j).array() - ctx.D.u.col(j).mean();
    const Vector<S> Iu = power_bins<S>(uj, m);
    const Vector<S> loc = running_median<S>(Iu, 21);
    for (Eigen::Index k = 0; k < m; ++k) {
      if (Iu(k) > 20 * loc(k)) keep[static_cast<std::size_t>(k)] = false;
    }
  }
  // periods the records resolve (see the head of this file)
  const S pi = S(3.141592653589793238462643);
  const S Tv = static_cast<S>(ctx.validation_samples) * ts;
  const S wmin = 4 * pi / std::min(static_cast<S>(N) * ts, Tv);
  bool any_resolved = false, any_kept = false;
  for (Eigen::Index k = 0; k < m; ++k) {
    const S wk = 2 * pi * static_cast<S>(k + 1) / (static_cast<S>(N) * ts);
    const bool resolved = wk >= wmin;
    any_resolved = any_resolved || resolved;
    keep[static_cast<std::size_t>(k)] =
        keep[static_cast<std::size_t>(k)] && resolved;
    any_kept = any_kept || keep[static_cast<std::size_t>(k)];
  }
  if (!any_resolved) {
    c->reason =
        "the records are too short for a sinusoid (at least two cycles: a "
        "period of at most " +
        num("%.4g", 2 * pi / wmin) + " s)";
    return Status::Ok();
  }
  if (!any_kept) {
    c->reason = "every frequency carries input power";
    return Status::Ok();
  }
  // the strongest kept line (the first of equal ones) and Fisher's g
  Eigen::Index kmax = 0;
  S Imax = -1, sum = 0, mk = 0;
  for (Eigen::Index k = 0; k < m; ++k) {
    const S Ik = keep[static_cast<std::size_t>(k)] ? I(k) : S(0);
    if (Ik > Imax) {
      Imax = Ik;
      kmax = k + 1;
    }
    if (keep[static_cast<std::size_t>(k)]) {
      sum += I(k);
      mk += 1;
    }
  }
  const S g = Imax / sum;
  const S pg = std::min(S(1), mk * std::pow(1 - g, mk - 1));
  // the frequency refined between the neighbouring bins
  const S dw = 2 * pi / (static_cast<S>(N) * ts);
  const S w0 = static_cast<S>(kmax) * dw;
  const S lo = std::max(w0 - dw, wmin), hi = w0 + dw;
  S w = lo, best = -1;
  const S step = (hi - lo) / 40;
  for (int i = 0; i < 41; ++i) {
    const S wi = i < 40 ? lo + static_cast<S>(i) * step : hi;
    std::complex<S> s(0, 0);
    for (Eigen::Index k = 0; k < N; ++k) {
      const S t = static_cast<S>(k) * ts;
      s += e(k) * std::exp(std::complex<S>(0, -wi * t));
    }
    if (std::abs(s) > best) {
      best = std::abs(s);
      w = wi;
    }
  }
  ResidtraceModel<S> tm = cur;
  OutputTerm<S> term;
  term.kind = OutputTermKind::kSinusoid;
  term.c = Vector<S>::Zero(2);
  term.cstd = Vector<S>::Zero(2);
  term.omega = w;
  tm.out.push_back(term);
  ResidtraceModel<S> mdl;
  Status s = fit_model<S>(tm, ctx.D, {cur.F}, ctx.fit, &mdl);
  if (!s.ok()) return s;
  if (!mdl.estimate.ok) {
    c->reason = "the estimation failed";
    c->failed = true;
    return Status::Ok();
  }
  c->applicable = true;
  c->has_model = true;
  c->model = mdl;
  c->variant = num("%.4g", w / (2 * pi)) + " Hz";
  c->nadd = 2;
  const OutputTerm<S>& o = mdl.out.back();
  const S A = std::hypot(o.c(0), o.c(1));
  const S sA = std::sqrt(o.cstd.squaredNorm() / 2);
  c->evidence.add("term", "amplitude");
  c->evidence.add("value", A);
  c->evidence.add("std", sA);
  c->evidence.add("omega", w);
  c->evidence.add("freq_hz", w / (2 * pi));
  c->evidence.add("g", g);
  c->evidence.add("g_p", pg);
  c->evidence.text =
      "line at " + num("%.4g", w / (2 * pi)) + " Hz (" + num("%.4g", w) +
      " rad/s), amplitude " + num("%.4g", A) + " +- " + num("%.2g", sA) +
      "; Fisher g = " + num("%.3f", g) + ", p = " + num("%.2g", pg);
  c->evidence.add("text", c->evidence.text);
  return Status::Ok();
}

}  // namespace ctid::residtrace
