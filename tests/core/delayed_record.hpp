// SPDX-License-Identifier: BSD-3-Clause
// Copyright (C) the ctid authors

// Noise-free records of b(p)/f(p) with a delay, simulated independently of
// the estimators: on a fine grid on which the delay is a whole number of
// fine steps, by the matrix exponential of the state-space model.
#pragma once

#include <Eigen/Dense>
#include <cmath>
#include <unsupported/Eigen/MatrixFunctions>
#include <vector>

namespace ctid {
namespace test {

// b(p) / f(p) driven by v (fine samples, held or linear between them over
// the fine step h), output at every fine sample; f monic [1 f1 .. fn].
inline std::vector<double> simulate_fine(const Eigen::VectorXd& f,
                                         const Eigen::VectorXd& b,
                                         const std::vector<double>& v, double h,
                                         bool foh) {
  const int n = static_cast<int>(f.size()) - 1;
  // Controllable canonical form, x = [w^(n-1) .. w], y = sum b_k p^k w.
  Eigen::MatrixXd big = Eigen::MatrixXd::Zero(n + 2, n + 2);
  for (int i = 0; i < n; ++i) big(0, i) = -f(i + 1) * h;
  for (int i = 1; i < n; ++i) big(i, i - 1) = h;
  big(0, n) = h;
  big(n, n + 1) = 1;
  const Eigen::MatrixXd e = big.exp();
  const Eigen::MatrixXd phi = e.topLeftCorner(n, n);
  const Eigen::VectorXd g0 = e.block(0, n, n, 1), g1 = e.block(0, n + 1, n, 1);
  Eigen::VectorXd c = Eigen::VectorXd::Zero(n);
  const int nb = static_cast<int>(b.size());
  for (int l = 0; l < nb; ++l) c(n - nb + l) = b(l);
  Eigen::VectorXd x = Eigen::VectorXd::Zero(n);
  std::vector<double> y(v.size());
  for (std::size_t k = 0; k < v.size(); ++k) {
    if (k > 0) {
      Eigen::VectorXd next = phi * x + g0 * v[k - 1];
      if (foh) next += g1 * (v[k] - v[k - 1]);
      x = next;
    }
    y[k] = c.dot(x);
  }
  return y;
}

struct Record {
  std::vector<double> y, u, instants;
};

// u on the coarse grid (every `ratio` fine steps), the system delayed by
// `delay_steps` fine steps; fine input 0 before the start.
inline Record make_record(const Eigen::VectorXd& f, const Eigen::VectorXd& b,
                          const std::vector<double>& u, int ratio, double h,
                          int delay_steps, bool foh) {
  const int n = static_cast<int>(u.size());
  const int fine = (n - 1) * ratio + 1;
  std::vector<double> v(fine, 0.0);
  for (int i = 0; i < fine; ++i) {
    const int src = i - delay_steps;  // fine index of the undelayed signal
    double value = 0;
    if (foh) {
      // linear between coarse samples, a ramp from 0 over the interval
      // before the first sample
      const double pos = static_cast<double>(src) / ratio;
      const int j = static_cast<int>(std::floor(pos));
      const double frac = pos - j;
      const double a = j >= 0 && j < n ? u[j] : (j >= n ? u[n - 1] : 0.0);
      const double c =
          j + 1 >= 0 && j + 1 < n ? u[j + 1] : (j + 1 >= n ? u[n - 1] : 0.0);
      value = a + (c - a) * frac;
    } else if (src >= 0) {
      value = u[src / ratio];
    }
    v[i] = value;
  }
  const std::vector<double> yf = simulate_fine(f, b, v, h, foh);
  Record r;
  r.u = u;
  for (int k = 0; k < n; ++k) r.y.push_back(yf[k * ratio]);
  return r;
}

}  // namespace test
}  // namespace ctid
