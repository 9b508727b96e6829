// SPDX-License-Identifier: BSD-3-Clause
// Copyright (C) the ctid authors

// Detection of the convergence of a recursive estimator's start-up (the
// RLSSVF run that gives the recursive IV routines their switching instant
// t_s_iv, `"tsiv", "auto"`, and rlsconverge), from its record:
//
// The record is cut into B blocks of length T_b (t relative to the first
// instant). Per block b: the mean square of the output error
// E_b = mean (y - y_hat)^2 (y_hat the simulated output of the frozen model,
// thesis eq. 1.60) and Y_b = mean y^2; the mean estimate theta_b; the
// relative change dtheta_b = |theta_b - theta_(b-1)| / |theta_b|; the ratio
// P_b = trace P / trace P0 at the block's last sample.
//
// Over the last n blocks w = b-n+1 .. b, three indices:
//   - output error steady: the steady-state test of Cao and Rhinehart
//     (1995) on X = log E_w, R = 2 sum (X - mean X)^2 / sum (diff X)^2 <
//     R_crit, or E_w <= floor^2 Y_w throughout. R = 2 / eta with eta von
//     Neumann's ratio, E[eta] = 2, var[eta] = 4 (n-2) / ((n+1) (n-1)) for
//     normal values, so R_crit = 2 / (2 - z_alpha sqrt(var eta)) with
//     z_alpha the standard normal quantile at 1 - alpha;
//   - estimates steady: sqrt(mean dtheta^2 over w(2:end)) < tol_theta;
//   - covariance small: P_w <= ptol throughout.
// The first block where every chosen index holds (and b >= n) gives
// t_s_iv = b T_b.
#pragma once

#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "ctid/base/status.hpp"
#include "ctid/base/types.hpp"

namespace ctid {

struct ConvergenceSettings {
  double block_length = 0;  // T_b (time units), > 0
  int num_blocks = 10;      // n, >= 3
  double alpha = 0.05;      // in (0, 0.5)
  double tol_theta = 0.05;  // > 0
  double ey_floor = 1e-3;   // >= 0
  double p_tol = 1e-2;      // > 0
  bool use_output_error = true;
  bool use_theta = true;
  bool use_p = true;  // needs the trace ratio
};

template <typename S>
struct ConvergenceReport {
  Eigen::Index num_blocks = 0;  // B, the complete blocks of the record
  S r_crit = 0;
  // per block (B values): E, Y, R, dtheta, theta index, P index
  Vector<S> ey_ms, y_ms, r, dtheta, theta_index, p_index;
  std::vector<bool> steady_ey, steady_theta, small_p;
  bool converged = false;
  Eigen::Index block = -1;  // 0-based index of the first passing block
  S tsiv = std::numeric_limits<S>::quiet_NaN();
  Eigen::Index sample = -1;  // 0-based first sample at or after tsiv
};

// Standard normal quantile z with P(Z > z) = p, 0 < p < 1, by bisection on
// erfc (to the last bit; a few hundred evaluations).
template <typename S>
S normal_upper_quantile(S p) {
  S lo = -40, hi = 40;
  for (int it = 0; it < 200 && hi - lo > 0; ++it) {
    const S mid = (lo + hi) / 2;
    if (mid == lo || mid == hi) break;
    if (S(0.5) * std::erfc(mid / std::sqrt(S(2))) > p) {
      lo = mid;
    } else {
      hi = mid;
    }
  }
  return (lo + hi) / 2;
}

// t: N instants relative to the record's start (t[0] = 0, increasing);
// y, y_hat: N values; theta: N-by-np estimates; trace_ratio: N values of
// trace P / trace P0 (null when settings.use_p is false).
template <typename S>
Status detect_convergence(const S* t, const S* y, const S* y_hat,
                          const Matrix<S>& theta, const S* trace_ratio,
                          const ConvergenceSettings& settings,
                          ConvergenceReport<S>& report) {
  const Eigen::Index num = theta.rows();
  const Eigen::Index np = theta.cols();
  const S tb = static_cast<S>(settings.block_length);
  const int n = settings.num_blocks;
  if (!(tb > 0) || !std::isfinite(tb)) {
    return bad_input("the block length must be finite and > 0");
  }
  if (n < 3) return bad_input("nblocks must be an integer >= 3");
  if (!(settings.alpha > 0 && settings.alpha < 0.5)) {
    return bad_input("alpha must lie in (0, 0.5)");
  }
  if (!(settings.tol_theta > 0) || !(settings.p_tol > 0) ||
      !(settings.ey_floor >= 0)) {
    return bad_input("tol_theta and ptol must be > 0, eyfloor >= 0");
  }
  if (settings.use_p && trace_ratio == nullptr) {
    return bad_input("the covariance index needs trace P / trace P0");
  }
  if (num < 1) return bad_input("the record is empty");
  const S slack = 1 + S(1e-12);  // instants on a block boundary
  const Eigen::Index blocks =
      static_cast<Eigen::Index>(std::floor(t[num - 1] / tb * slack));
  if (blocks < n) {
    return bad_input("the training record (" +
                     std::to_string(static_cast<double>(t[num - 1])) +
                     " s) is too short for nblocks = " + std::to_string(n) +
                     " blocks of " + std::to_string(static_cast<double>(tb)) +
                     " s");
  }
  report = ConvergenceReport<S>();
  report.num_blocks = blocks;
  const S nan = std::numeric_limits<S>::quiet_NaN();
  const S inf = std::numeric_limits<S>::infinity();
  Vector<S> count = Vector<S>::Zero(blocks);
  report.ey_ms = Vector<S>::Zero(blocks);
  report.y_ms = Vector<S>::Zero(blocks);
  Matrix<S> mean_theta = Matrix<S>::Zero(blocks, np);
  report.p_index = Vector<S>::Constant(blocks, nan);
  for (Eigen::Index k = 0; k < num; ++k) {
    const Eigen::Index b =
        static_cast<Eigen::Index>(std::floor(t[k] / tb * slack));
    if (b >= blocks) continue;
    const S e = y[k] - y_hat[k];
    count(b) += 1;
    report.ey_ms(b) += e * e;
    report.y_ms(b) += y[k] * y[k];
    mean_theta.row(b) += theta.row(k);
    if (trace_ratio != nullptr) report.p_index(b) = trace_ratio[k];
  }
  for (Eigen::Index b = 0; b < blocks; ++b) {
    report.ey_ms(b) /= count(b);
    report.y_ms(b) /= count(b);
    mean_theta.row(b) /= count(b);
    if (!std::isfinite(report.ey_ms(b))) report.ey_ms(b) = inf;
  }
  report.dtheta = Vector<S>::Constant(blocks, nan);
  for (Eigen::Index b = 1; b < blocks; ++b) {
    const S d = (mean_theta.row(b) - mean_theta.row(b - 1)).norm() /
                mean_theta.row(b).norm();
    report.dtheta(b) = std::isfinite(d) ? d : inf;
  }

  const S z = normal_upper_quantile<S>(static_cast<S>(settings.alpha));
  const S spread = std::sqrt(S(4) * (n - 2) / (S(n + 1) * (n - 1)));
  report.r_crit = 2 / (2 - z * spread);
  if (!(report.r_crit > 0)) report.r_crit = inf;  // the test never fails

  report.r = Vector<S>::Constant(blocks, nan);
  report.theta_index = Vector<S>::Constant(blocks, nan);
  report.steady_ey.assign(blocks, false);
  report.steady_theta.assign(blocks, false);
  report.small_p.assign(blocks, false);
  const S floor2 = static_cast<S>(settings.ey_floor * settings.ey_floor);
  for (Eigen::Index b = n - 1; b < blocks; ++b) {
    const Eigen::Index first = b - n + 1;
    bool finite = true;
    S mean = 0;
    for (Eigen::Index i = first; i <= b; ++i) {
      const S x = std::log(report.ey_ms(i));
      finite = finite && std::isfinite(x);
      mean += x;
    }
    if (finite) {
      mean /= n;
      S s1 = 0, s2 = 0;
      for (Eigen::Index i = first; i <= b; ++i) {
        const S x = std::log(report.ey_ms(i));
        s1 += (x - mean) * (x - mean);
        if (i > first) {
          const S dx = x - std::log(report.ey_ms(i - 1));
          s2 += dx * dx;
        }
      }
      // s2 = 0: every value equal, a constant level (s1 is then 0 up to
      // the rounding of the mean)
      report.r(b) = s2 > 0 ? 2 * s1 / s2 : S(0);
    }
    bool below_floor = true;
    bool p_small = true;
    S sum_d2 = 0;
    for (Eigen::Index i = first; i <= b; ++i) {
      below_floor = below_floor && report.ey_ms(i) <= floor2 * report.y_ms(i);
      p_small = p_small && report.p_index(i) <= static_cast<S>(settings.p_tol);
      if (i > first) sum_d2 += report.dtheta(i) * report.dtheta(i);
    }
    report.steady_ey[b] = report.r(b) < report.r_crit || below_floor;
    report.theta_index(b) = std::sqrt(sum_d2 / (n - 1));
    report.steady_theta[b] =
        report.theta_index(b) < static_cast<S>(settings.tol_theta);
    report.small_p[b] = p_small;
    const bool pass = (!settings.use_output_error || report.steady_ey[b]) &&
                      (!settings.use_theta || report.steady_theta[b]) &&
                      (!settings.use_p || report.small_p[b]);
    if (pass && !report.converged) {
      report.converged = true;
      report.block = b;
    }
  }
  if (report.converged) {
    report.tsiv = S(report.block + 1) * tb;
    for (Eigen::Index k = 0; k < num; ++k) {
      if (t[k] >= report.tsiv * (1 - S(1e-12))) {
        report.sample = k;
        break;
      }
    }
  }
  return Status::Ok();
}

}  // namespace ctid
