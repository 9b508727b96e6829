// SPDX-License-Identifier: BSD-3-Clause
// Copyright (C) the ctid authors

// The parameter-drift candidate of residtrace: time variation that a
// frozen model cannot explain. This header holds its evidence on the
// estimation record, the segment test (octave/private/
// residtrace_cand_drift.m runs the tracking that follows it).
//
// The model is re-estimated (fit_model, its order kept) on K consecutive
// segments, K = min(8, floor(N / (40 np))) (at least 40 samples per
// parameter each; fewer than 3 segments: not applicable), the segments
// after the first with their initial state estimated, as they do not
// start at rest. Under a constant parameter vector the statistic
//   chi^2 = sum_k (theta_k - theta_bar)' P_k^+ (theta_k - theta_bar),
// theta_bar = (sum_k P_k^+)^+ sum_k P_k^+ theta_k the precision-weighted
// mean, is chi^2 with (K - 1) np degrees of freedom (P^+ the
// pseudo-inverse, Octave's pinv: singular values above max(size) s_max
// eps). When p >= alpha the segments agree and the candidate stops there.
//
// The trend of each parameter over the segments is the weighted
// least-squares line through (t_k, theta_k,i), t_k the segment's middle,
// weights 1 / P_k,ii, with the t value of its slope (NaN when a segment
// has no variance or the line is singular, rcond < eps). The shape of the
// random-walk covariance Qn of the tracking is the spread of consecutive
// segment estimates beyond their estimation variances,
//   vinc_i = mean_k (dtheta_k,i^2 - P_k,ii - P_k+1,ii),
// floored at 1e-3 times the model's variance of the parameter, per sample
// as a random walk averaged over a segment of L samples gives (variance
// 2 L / 3 per unit increment variance), over the noise variance s2.
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "ctid/apps/residtrace/candidate.hpp"
#include "ctid/apps/residtrace/judgement.hpp"

namespace ctid::residtrace {

// The segment test of the drift candidate. reason is empty when the
// segments disagree (p < alpha: the tracking follows), otherwise the
// reason the candidate is not applicable (failed: the segment fits
// failed).
template <typename S>
struct DriftSegments {
  std::string reason;
  bool failed = false;
  int K = 0;                 // segments tried
  Eigen::Index L = 0;        // samples per segment
  int segments = 0;          // segments fitted (Kk)
  Matrix<S> theta;           // segments-by-np estimates
  std::vector<Matrix<S>> P;  // their covariances
  Vector<S> tmid;            // the segments' middles (time)
  S chi2 = 0, p = std::numeric_limits<S>::quiet_NaN();
  int dof = 0;
  Vector<S> slope, tval;  // per-parameter trend and its t value
  Vector<S> shape;        // the diagonal of Qn's shape (over s2)
};

namespace drift_detail {

// Octave's pinv: the SVD pseudo-inverse, singular values above
// max(rows, cols) s_max eps kept.
template <typename S>
Matrix<S> pinv(const Matrix<S>& A) {
  Eigen::JacobiSVD<Matrix<S>> svd(A, Eigen::ComputeThinU | Eigen::ComputeThinV);
  const Vector<S>& s = svd.singularValues();
  const S tol = static_cast<S>(std::max(A.rows(), A.cols())) *
                (s.size() > 0 ? s(0) : S(0)) *
                std::numeric_limits<S>::epsilon();
  Vector<S> si = Vector<S>::Zero(s.size());
  for (Eigen::Index i = 0; i < s.size(); ++i) {
    if (s(i) > tol) si(i) = 1 / s(i);
  }
  return svd.matrixV() * si.asDiagonal() * svd.matrixU().transpose();
}

template <typename S>
FitRecord<S> slice(const FitRecord<S>& D, Eigen::Index first, Eigen::Index n) {
  FitRecord<S> d = D;
  d.y = D.y.segment(first, n);
  d.u = D.u.middleRows(first, n);
  if (D.vhat.rows() == D.y.size()) d.vhat = D.vhat.middleRows(first, n);
  if (D.ysm.size() == D.y.size()) d.ysm = D.ysm.segment(first, n);
  if (D.missing.size() == static_cast<std::size_t>(D.y.size())) {
    d.missing.assign(D.missing.begin() + first, D.missing.begin() + first + n);
  }
  d.closed = false;
  d.loop = ClosedLoop<S>();
  d.initial_state = first > 0;  // a segment does not start at rest
  return d;
}

}  // namespace drift_detail

// The segment test of the drift candidate on the estimation record
// ctx.D; alpha the level of the test.
template <typename S>
Status drift_segments(const ResidtraceModel<S>& cur,
                      const CandidateContext<S>& ctx, S alpha,
                      DriftSegments<S>* out) {
  using candidate_detail::num;
  using drift_detail::pinv;
  if (out == nullptr) return bad_input("no result");
  *out = DriftSegments<S>();
  DriftSegments<S>& r = *out;
  if (cur.has_phys) {
    r.reason = "a physical realisation (end stop, cascade) is not tracked";
    return Status::Ok();
  }
  const Eigen::Index N = ctx.D.y.size();
  const Eigen::Index np = cur.estimate.theta.size();
  if (ctx.D.u.rows() != N) {
    return dimension_mismatch("the record's input and output lengths differ");
  }
  if (cur.estimate.cov.rows() != np || cur.estimate.cov.cols() != np) {
    return dimension_mismatch("the model's cov must be np-by-np");
  }
  r.K = static_cast<int>(
      std::min<Eigen::Index>(8, N / (40 * std::max<Eigen::Index>(np, 1))));
  if (r.K < 3) {
    r.reason = std::to_string(N) + " samples are too few for segment fits of " +
               std::to_string(np) + " parameters";
    return Status::Ok();
  }
  r.L = N / r.K;
  ModelFitSettings fs = ctx.fit;
  fs.keep_order = true;
  std::vector<Vector<S>> th;
  std::vector<S> tm;
  for (int k = 0; k < r.K; ++k) {
    ResidtraceModel<S> m;
    Status s = fit_model<S>(cur, drift_detail::slice<S>(ctx.D, k * r.L, r.L),
                            {cur.F}, fs, &m);
    if (!s.ok()) return s;
    if (!m.estimate.ok || m.estimate.theta.size() != np) continue;
    th.push_back(m.estimate.theta);
    r.P.push_back(m.estimate.cov);
    tm.push_back((k + S(0.5)) * static_cast<S>(r.L) * ctx.D.ts);
  }
  r.segments = static_cast<int>(th.size());
  if (r.segments < 3) {
    r.reason = "the segment fits failed";
    r.failed = true;
    return Status::Ok();
  }
  const int Kk = r.segments;
  r.theta.resize(Kk, np);
  r.tmid.resize(Kk);
  for (int k = 0; k < Kk; ++k) {
    r.theta.row(k) = th[k].transpose();
    r.tmid(k) = tm[k];
  }
  Matrix<S> Wsum = Matrix<S>::Zero(np, np);
  Vector<S> wth = Vector<S>::Zero(np);
  std::vector<Matrix<S>> W(Kk);
  for (int k = 0; k < Kk; ++k) {
    W[k] = pinv<S>(r.P[k]);
    Wsum += W[k];
    wth += W[k] * th[k];
  }
  const Vector<S> tbar = pinv<S>(Wsum) * wth;
  r.chi2 = 0;
  for (int k = 0; k < Kk; ++k) {
    const Vector<S> d = th[k] - tbar;
    r.chi2 += d.dot(W[k] * d);
  }
  r.dof = static_cast<int>((Kk - 1) * np);
  r.p = chi2_upper<S>(r.chi2, static_cast<S>(r.dof));
  if (r.p >= alpha) {
    r.reason = "the segment fits agree (K = " + std::to_string(Kk) +
               ": chi^2 = " + num("%.1f", r.chi2) + " on " +
               std::to_string(r.dof) + " dof, p = " + num("%.2g", r.p) +
               " >= alpha)";
    return Status::Ok();
  }
  const S nan = std::numeric_limits<S>::quiet_NaN();
  const S eps = std::numeric_limits<S>::epsilon();
  r.slope = Vector<S>::Constant(np, nan);
  r.tval = Vector<S>::Constant(np, nan);
  for (Eigen::Index i = 0; i < np; ++i) {
    Vector<S> v(Kk);
    bool ok = true;
    for (int k = 0; k < Kk; ++k) {
      v(k) = r.P[k](i, i);
      if (!(v(k) > 0 && std::isfinite(v(k)))) ok = false;
    }
    if (!ok) continue;  // a segment without a variance
    Matrix<S> X(Kk, 2);
    Vector<S> t(Kk);
    for (int k = 0; k < Kk; ++k) {
      const S w = std::sqrt(v(k));
      X(k, 0) = 1 / w;
      X(k, 1) = r.tmid(k) / w;
      t(k) = r.theta(k, i) / w;
    }
    Eigen::HouseholderQR<Matrix<S>> qr(X);
    const Matrix<S> R =
        qr.matrixQR().topRows(2).template triangularView<Eigen::Upper>();
    // rcond of the triangular factor (1-norm, exact for 2-by-2)
    const S a = R(0, 0), b = R(0, 1), c = R(1, 1);
    const S n1 = std::max(std::abs(a), std::abs(b) + std::abs(c));
    const S ni =
        std::max(1 / std::abs(a), std::abs(b / (a * c)) + 1 / std::abs(c));
    const S rc = (a == 0 || c == 0) ? S(0) : 1 / (n1 * ni);
    if (!(rc >= eps)) continue;
    const Matrix<S> Ri = R.template triangularView<Eigen::Upper>().solve(
        Matrix<S>::Identity(2, 2));
    const Matrix<S> Cb = Ri * Ri.transpose();
    const Vector<S> beta = Cb * (X.transpose() * t);
    r.slope(i) = beta(1);
    r.tval(i) = beta(1) / std::sqrt(Cb(1, 1));
  }
  r.shape.resize(np);
  for (Eigen::Index i = 0; i < np; ++i) {
    S sum = 0;
    for (int k = 0; k + 1 < Kk; ++k) {
      const S d = r.theta(k + 1, i) - r.theta(k, i);
      sum += d * d - (r.P[k](i, i) + r.P[k + 1](i, i));
    }
    const S vinc = sum / (Kk - 1);
    r.shape(i) = std::max(vinc, S(1e-3) * cur.estimate.cov(i, i)) /
                 (2 * static_cast<S>(r.L) / 3) / cur.estimate.s2;
  }
  return Status::Ok();
}

}  // namespace ctid::residtrace
