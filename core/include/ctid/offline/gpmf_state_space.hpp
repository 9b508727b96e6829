// SPDX-License-Identifier: BSD-3-Clause
// Copyright (C) the ctid authors
// Multivariable continuous-time state-space identification by generalised
// Poisson moment functionals (GPMF): least squares (sslsgpmf) and
// instrumental variables with an auxiliary model (ssivgpmf), after Garnier,
// Sibille and Richard, "Continuous-time canonical state-space model
// identification via Poisson moment functionals", CDC 1995.
//
// Model: the observable canonical form of Guidorzi built from the
// observability indices n_1 .. n_p (n = sum n_i). State block i holds
// x_(i,1) = y_i and x_(i,k)' = x_(i,k+1) + b_(i,k)^T u for k < n_i; the last
// row of block i is free: x_(i,n_i)' = sum_j sum_k a_(ij,k) x_(j,k+1) +
// b_(i,n_i)^T u, with k = 0 .. nu_ij - 1 and
//
//   nu_ii = n_i,  nu_ij = min(n_i + 1, n_j) (j < i),  min(n_i, n_j) (j > i).
//
// Eliminating the states gives one input-output equation per output,
//
//   p^(n_i) y_i + sum_j sum_k alpha_(ij,k) p^k y_j
//       = sum_l sum_(k<n_i) beta_(il,k) p^k u_l,   alpha = -a,
//
// linear in (alpha, beta). Its GPMF of order n_i (the Poisson filter
// (lambda_i/(p+lambda_i))^(n_i+1), one lambda per output) is the output of
// the normalised state-variable filter of svf.hpp (thesis eq. 3.1): the
// filtered equation is a linear regression zeta_i = phi_i^T theta_i, solved per
// output by least squares, or by IV with instruments built from the
// noise-free output of the LS model (auxiliary model). B follows from beta
// by the triangular change of coordinates beta = T(alpha) b (see
// coefficient_map below).
//
// sid_gpmf is the GPMF-based subspace method (sidgpmf; Bastogne, Garnier,
// Sibille, Int. J. Control 74(2), 2001): the GPMF of order j of the time
// derivatives p^k y, p^k u, k = 0 .. i-1, obey the data equation of the
// discrete 4SID methods with derivatives in place of shifts,
//
//   Y_i = Gamma_i (F x) + H_i U_i,   Gamma_i = [C; C A; ..; C A^(i-1)],
//
// H_i the block Toeplitz matrix of D, C B, C A B, ..; the MOESP projection
// of Y_i onto the complement of U_i (LQ factorisation) spans Gamma_i, whose
// shift invariance gives A and whose first block gives C; B and D then
// solve a least-squares fit of the measured outputs by the exact
// simulation of (A, I, C) for each input.
//
// The inputs are filtered with the data's intersample rule and the
// outputs, never piecewise constant, as linear between samples (exact
// first-order hold, InterSample::kFoh; the SVF estimators of
// svf_regressor.hpp use the trapezoidal rule there by default).
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <unsupported/Eigen/MatrixFunctions>
#include <vector>

#include "ctid/base/record.hpp"
#include "ctid/base/status.hpp"
#include "ctid/base/types.hpp"
#include "ctid/filters/batch_filters.hpp"
#include "ctid/filters/discretization.hpp"
#include "ctid/filters/svf.hpp"

namespace ctid {

// A multi-output record: y N-by-p and u N-by-m, column-major, and either a
// constant sampling interval or the N sampling instants.
template <typename S>
struct MultiRecordView {
  const S* y = nullptr;
  const S* u = nullptr;
  Eigen::Index num_samples = 0;
  Eigen::Index num_outputs = 0;
  Eigen::Index num_inputs = 0;
  S ts = 0;
  const S* instants = nullptr;
  InterSample u_intersample = InterSample::kZoh;

  S y_at(Eigen::Index k, Eigen::Index i) const {
    return y[i * num_samples + k];
  }
  S u_at(Eigen::Index k, Eigen::Index l) const {
    return u[l * num_samples + k];
  }
  // t_k - t_(k-1); for k = 0 the first interval of the record.
  S interval(Eigen::Index k) const {
    return sampling_interval(instants, ts, num_samples, k);
  }
};

template <typename S>
struct GpmfSettings {
  std::vector<int> observability_indices;  // n_1 .. n_p, each >= 1
  std::vector<S> lambda;                   // Poisson filter pole per output
  Eigen::Index first_sample = 0;           // n0 - 1: samples used from here
};

template <typename S>
struct StateSpaceEstimate {
  Matrix<S> A, B, C, D;
  // Per output: [alpha_(i1,0..nu_i1-1) .. alpha_(ip,..) beta_(i1,0..n_i-1)
  // .. beta_(im,..)], concatenated over the outputs.
  Vector<S> theta;
};

namespace gpmf_detail {

inline int coupling_degree(const std::vector<int>& n, int i, int j) {
  if (i == j) return n[i];
  return j < i ? std::min(n[i] + 1, n[j]) : std::min(n[i], n[j]);
}

inline int block_start(const std::vector<int>& n, int i) {
  int start = 0;
  for (int j = 0; j < i; ++j) start += n[j];
  return start;
}

inline Eigen::Index num_alpha(const std::vector<int>& n, int i) {
  Eigen::Index count = 0;
  for (int j = 0; j < static_cast<int>(n.size()); ++j) {
    count += coupling_degree(n, i, j);
  }
  return count;
}

template <typename S>
Status validate(const MultiRecordView<S>& record,
                const GpmfSettings<S>& settings) {
  const auto& n = settings.observability_indices;
  if (record.num_outputs < 1 || record.num_inputs < 1) {
    return bad_input("the data need at least one output and one input");
  }
  if (static_cast<Eigen::Index>(n.size()) != record.num_outputs) {
    return dimension_mismatch("nni must have one entry per output (" +
                              std::to_string(record.num_outputs) + "), got " +
                              std::to_string(n.size()));
  }
  if (static_cast<Eigen::Index>(settings.lambda.size()) != record.num_outputs) {
    return dimension_mismatch("param must have one entry per output (" +
                              std::to_string(record.num_outputs) + "), got " +
                              std::to_string(settings.lambda.size()));
  }
  for (std::size_t i = 0; i < n.size(); ++i) {
    if (n[i] < 1 || n[i] > 20) {
      return bad_input("the observability indices must be integers in 1..20");
    }
    if (!(settings.lambda[i] > 0) || !std::isfinite(settings.lambda[i])) {
      return bad_input("the filter parameters must be finite and > 0");
    }
  }
  Eigen::Index largest = 0;
  for (int i = 0; i < static_cast<int>(n.size()); ++i) {
    largest = std::max(largest, num_alpha(n, i) + n[i] * record.num_inputs);
  }
  if (settings.first_sample < 0 ||
      record.num_samples - settings.first_sample < largest) {
    return bad_input("the data from sample n0 on have fewer samples than the " +
                     std::to_string(largest) +
                     " parameters of an output equation");
  }
  const Eigen::Index count = record.num_samples;
  for (Eigen::Index k = 0; k < count * record.num_outputs; ++k) {
    if (!std::isfinite(record.y[k])) return bad_input("y must be finite");
  }
  for (Eigen::Index k = 0; k < count * record.num_inputs; ++k) {
    if (!std::isfinite(record.u[k])) return bad_input("u must be finite");
  }
  if (record.instants == nullptr) {
    if (!(record.ts > 0) || !std::isfinite(record.ts)) {
      return bad_input("the sampling interval Ts must be finite and > 0");
    }
  } else {
    for (Eigen::Index k = 0; k < count; ++k) {
      if (!std::isfinite(record.instants[k]) ||
          (k > 0 && !(record.instants[k] > record.instants[k - 1]))) {
        return bad_input(
            "the sampling instants must be finite and strictly increasing");
      }
    }
  }
  return Status::Ok();
}

// The GPMF regressors of output i over the record: row k holds
// [-p^k F y_j (k < nu_ij), j = 1..p | p^k F u_l (k < n_i), l = 1..m] with
// the outputs y_hat (instruments) or y, and zeta = p^(n_i) F y_i.
//
// With input_roots (r roots, the bias-compensated estimator), the inputs
// are first passed through the artificial filter 1/F(p), F(p) = prod (p -
// root): the columns of input l are then p^k F u_l / F(p), k < n_i + r,
// whose coefficients beta_bar = beta F carry the r known zeros of F.
template <typename S>
void gpmf_regressors(const MultiRecordView<S>& record,
                     const GpmfSettings<S>& settings, int i, const S* outputs,
                     Matrix<S>* phi, Vector<S>* zeta,
                     const std::vector<S>* input_roots = nullptr) {
  const auto& n = settings.observability_indices;
  const int p = static_cast<int>(record.num_outputs);
  const int m = static_cast<int>(record.num_inputs);
  const int order = n[i] + 1;  // GPMF of order n_i: Poisson filter ^(n_i+1)
  const int extra =
      input_roots == nullptr ? 0 : static_cast<int>(input_roots->size());
  const int u_order = order + extra;
  const int u_columns = n[i] + extra;
  const S lambda = settings.lambda[i];
  const Vector<S> d = svf_denominator(order, lambda);
  const S gain = svf_gain(order, lambda, true);
  // D(p) F(p), descending coefficients without the leading 1.
  Vector<S> du(u_order);
  {
    Vector<S> poly(order + 1);
    poly(0) = 1;
    poly.tail(order) = d;
    for (int r = 0; r < extra; ++r) {
      Vector<S> next = Vector<S>::Zero(poly.size() + 1);
      next.head(poly.size()) = poly;
      next.tail(poly.size()) -= (*input_roots)[r] * poly;
      poly = next;
    }
    du = poly.tail(u_order);
  }
  // Each channel is filtered over the whole record by the batch filters
  // (batch_filters.hpp: the per-sample filters' discretisation, fixed-size
  // kernels on a regular grid), then its columns are copied into phi.
  const Eigen::Index count = record.num_samples;
  const Eigen::Index first = settings.first_sample;
  const Eigen::Index rows = count - first;
  const Eigen::Index columns = num_alpha(n, i) + u_columns * m;
  phi->resize(rows, columns);
  zeta->resize(rows);
  batch::Clock<S> clock;
  clock.ts = record.ts;
  clock.instants = record.instants;
  clock.n = count;
  Matrix<S> filtered;
  Eigen::Index col = 0;
  for (int j = 0; j < p; ++j) {
    batch::filter_derivatives<S>(d, gain, InterSample::kFoh, clock,
                                 outputs + j * count, filtered);
    for (int q = 0; q < coupling_degree(n, i, j); ++q) {
      phi->col(col++) = -filtered.col(q).tail(rows);
    }
    if (j == i) *zeta = filtered.col(n[i]).tail(rows);
  }
  for (int l = 0; l < m; ++l) {
    batch::filter_derivatives<S>(du, gain, record.u_intersample, clock,
                                 record.u + l * count, filtered);
    for (int q = 0; q < u_columns; ++q) {
      phi->col(col++) = filtered.col(q).tail(rows);
    }
  }
}

// The least-squares solution of phi theta = zeta by Householder QR, or
// false when the diagonal of R shows phi rank deficient (|R_kk| at most
// eps * columns times the largest, the threshold of Eigen's
// ColPivHouseholderQR). Without column pivoting: the GPMF regressions
// have a handful of columns and many rows, where pivoting costs more than
// the whole solve.
template <typename S>
bool least_squares(const Matrix<S>& phi, const Vector<S>& zeta,
                   Vector<S>* theta) {
  const Eigen::HouseholderQR<Matrix<S>> qr(phi);
  const Vector<S> diagonal = qr.matrixQR().diagonal().cwiseAbs();
  const S largest = diagonal.size() == 0 ? S(0) : diagonal.maxCoeff();
  const S threshold =
      std::numeric_limits<S>::epsilon() * static_cast<S>(phi.cols()) * largest;
  if (!(largest > 0) || !diagonal.allFinite() ||
      (diagonal.array() <= threshold).any()) {
    return false;
  }
  if (theta != nullptr) *theta = qr.solve(zeta);
  return true;
}

// The canonical (A, B, C) of the parameters theta. beta_(i,d) (the p^d
// coefficient of row i, one input) = b_(i,n_i-d) + sum_j sum_(k>d)
// alpha_(ij,k) b_(j,k-d): a square linear map T(alpha) from b to beta,
// inverted column by column of B.
template <typename S>
Status canonical_model(const std::vector<int>& n, int num_inputs,
                       const Vector<S>& theta, StateSpaceEstimate<S>* model) {
  const int p = static_cast<int>(n.size());
  const int m = num_inputs;
  int total = 0;
  for (int ni : n) total += ni;
  Matrix<S> A = Matrix<S>::Zero(total, total);
  Matrix<S> T = Matrix<S>::Zero(total, total);
  Matrix<S> beta(total, m);
  Eigen::Index offset = 0;
  for (int i = 0; i < p; ++i) {
    const int start = block_start(n, i);
    for (int k = 0; k + 1 < n[i]; ++k) A(start + k, start + k + 1) = 1;
    const int last = start + n[i] - 1;
    // Row (i, d) of T and beta: index start + d.
    for (int d = 0; d < n[i]; ++d) T(start + d, start + n[i] - 1 - d) = 1;
    for (int j = 0; j < p; ++j) {
      const int start_j = block_start(n, j);
      for (int k = 0; k < coupling_degree(n, i, j); ++k) {
        const S alpha = theta(offset++);
        A(last, start_j + k) = -alpha;
        for (int d = 0; d < k; ++d) T(start + d, start_j + k - d - 1) += alpha;
      }
    }
    for (int l = 0; l < m; ++l) {
      for (int d = 0; d < n[i]; ++d) beta(start + d, l) = theta(offset++);
    }
  }
  Eigen::FullPivLU<Matrix<S>> lu(T);
  if (!lu.isInvertible()) {
    return numerical_failure(
        "the estimated model has no canonical realisation");
  }
  model->A = A;
  model->B = lu.solve(beta);
  model->C = Matrix<S>::Zero(p, total);
  for (int i = 0; i < p; ++i) model->C(i, block_start(n, i)) = 1;
  model->D = Matrix<S>::Zero(p, m);
  model->theta = theta;
  return Status::Ok();
}

// Noise-free output of x' = A x + B u, y = C x from rest, exact for the
// record's intersample rule (ZOH: Phi, Gamma; FOH: the augmented
// exponential with the input's slope as a state).
template <typename S>
Status simulate_state_space(const Matrix<S>& A, const Matrix<S>& B,
                            const Matrix<S>& C,
                            const MultiRecordView<S>& record,
                            Matrix<S>* output) {
  const Eigen::Index n = A.rows();
  const Eigen::Index m = B.cols();
  const Eigen::Index count = record.num_samples;
  const bool foh = record.u_intersample == InterSample::kFoh;
  Matrix<S> Phi, Gamma0, Gamma1;
  S h_last = -1;
  Vector<S> x = Vector<S>::Zero(n);
  Vector<S> u_prev(m), u_now(m);
  output->resize(count, C.rows());
  for (Eigen::Index k = 0; k < count; ++k) {
    for (Eigen::Index l = 0; l < m; ++l) u_now(l) = record.u_at(k, l);
    if (k > 0) {
      const S h = record.interval(k);
      if (h != h_last) {
        const Eigen::Index size = n + (foh ? 2 * m : m);
        Matrix<S> F = Matrix<S>::Zero(size, size);
        F.topLeftCorner(n, n) = A * h;
        F.block(0, n, n, m) = B * h;
        if (foh) F.block(n, n + m, m, m) = Matrix<S>::Identity(m, m);
        const Matrix<S> E = F.exp();
        Phi = E.topLeftCorner(n, n);
        Gamma0 = E.block(0, n, n, m);
        if (foh) Gamma1 = E.block(0, n + m, n, m);
        h_last = h;
      }
      // FOH: in the normalised time tau = s/h of the interval,
      // u = u_(k-1) + tau (u_k - u_(k-1)); the augmented state carries u
      // and its constant increment (the identity block above).
      Vector<S> next = Phi * x + Gamma0 * u_prev;
      if (foh) next += Gamma1 * (u_now - u_prev);
      x = next;
    }
    output->row(k) = (C * x).transpose();
    u_prev = u_now;
  }
  if (!output->allFinite()) {
    return numerical_failure("the simulated auxiliary model diverged");
  }
  return Status::Ok();
}

// The canonical model from one estimate per output equation:
// solve(i, &part) returns the parameters of output i's equation (or a
// failure), stacked in output order.
template <typename S, typename Solve>
Status estimate_by_output(const MultiRecordView<S>& record,
                          const GpmfSettings<S>& settings, Solve&& solve,
                          StateSpaceEstimate<S>* estimate) {
  const int p = static_cast<int>(record.num_outputs);
  std::vector<Vector<S>> parts(p);
  Eigen::Index total = 0;
  for (int i = 0; i < p; ++i) {
    const Status status = solve(i, &parts[i]);
    if (!status.ok()) return status;
    total += parts[i].size();
  }
  Vector<S> theta(total);
  Eigen::Index offset = 0;
  for (const auto& part : parts) {
    theta.segment(offset, part.size()) = part;
    offset += part.size();
  }
  return canonical_model(settings.observability_indices,
                         static_cast<int>(record.num_inputs), theta, estimate);
}

}  // namespace gpmf_detail

// Least-squares GPMF estimate of the canonical state-space model (sslsgpmf).
template <typename S>
Status ss_ls_gpmf(const MultiRecordView<S>& record,
                  const GpmfSettings<S>& settings,
                  StateSpaceEstimate<S>* estimate) {
  const Status status = gpmf_detail::validate(record, settings);
  if (!status.ok()) return status;
  auto solve = [&](int i, Vector<S>* part) -> Status {
    Matrix<S> phi;
    Vector<S> zeta;
    gpmf_detail::gpmf_regressors(record, settings, i, record.y, &phi, &zeta);
    if (!gpmf_detail::least_squares(phi, zeta, part)) {
      return numerical_failure(
          "the GPMF regression of output " + std::to_string(i + 1) +
          " is rank deficient (input not exciting enough, or nni too large)");
    }
    return Status::Ok();
  };
  return gpmf_detail::estimate_by_output(record, settings, solve, estimate);
}

// Instrumental-variable GPMF estimate (ssivgpmf): the instruments are the
// GPMF regressors of the noise-free output of the LS model, simulated from
// the input alone; the LS model must therefore be stable.
template <typename S>
Status ss_iv_gpmf(const MultiRecordView<S>& record,
                  const GpmfSettings<S>& settings,
                  StateSpaceEstimate<S>* estimate) {
  StateSpaceEstimate<S> ls;
  Status status = ss_ls_gpmf(record, settings, &ls);
  if (!status.ok()) return status;
  const Eigen::EigenSolver<Matrix<S>> eig(ls.A, false);
  if (eig.info() != Eigen::Success ||
      (eig.eigenvalues().real().array() >= 0).any()) {
    return numerical_failure(
        "the least-squares auxiliary model is not stable: no instruments");
  }
  Matrix<S> y_hat;
  status = gpmf_detail::simulate_state_space(ls.A, ls.B, ls.C, record, &y_hat);
  if (!status.ok()) return status;
  auto solve = [&](int i, Vector<S>* part) -> Status {
    Matrix<S> phi, psi;
    Vector<S> zeta, unused;
    gpmf_detail::gpmf_regressors(record, settings, i, record.y, &phi, &zeta);
    gpmf_detail::gpmf_regressors(record, settings, i, y_hat.data(), &psi,
                                 &unused);
    const Matrix<S> R = psi.transpose() * phi;
    Eigen::FullPivLU<Matrix<S>> lu(R);
    if (!lu.isInvertible()) {
      return numerical_failure("the IV normal matrix of output " +
                               std::to_string(i + 1) + " is singular");
    }
    *part = lu.solve(psi.transpose() * zeta);
    return Status::Ok();
  };
  return gpmf_detail::estimate_by_output(record, settings, solve, estimate);
}

// Bias-compensated least-squares GPMF estimate (ssbcgpmf), after Garnier,
// Sibille and Bastogne, "A bias-free least-squares parameter estimator for
// continuous-time state-space models", CDC 1997, on the bias-eliminated LS
// principle of Feng and Zheng (IEE Proc. D 138, 1991) and Zhang and Feng
// (Automatica 33(5), 1997).
//
// Each output equation i is augmented with a known factor: the inputs pass
// through 1/F_i(p), F_i(p) = prod_r (p - roots_i(r)), so the numerators
// beta_bar_(il) = beta_(il) F_i of the augmented equation vanish at the
// roots: H^T beta_bar_(il) = 0 with H the left null space of the
// convolution by F_i. With white output noise of variances sigma_j^2 on
// the samples, the GPMF normal equations of output i are
//
//   E[Phi^T Phi] = R_0 + sum_j sigma_j^2 D_ij,  E[Phi^T zeta] = r_0 +
//   sigma_i^2 d_i,
//
// D_ij and d_i the known noise Gram of the Poisson filter (its impulse
// response, summed exactly over the rows used) in the columns of y_j, so
// the compensated estimate theta(sigma) = (Phi^T Phi - sum_j sigma_j^2
// D_ij)^-1 (Phi^T zeta - sigma_i^2 d_i) is consistent. The constraints
// H^T theta(sigma) = 0 of every output equation and input, written around
// the current theta, have the Jacobian
//
//   d g / d sigma_j^2 = H^T R_i^-1 (D_ij theta_i - [i = j] d_i),
//   R_i = Phi^T Phi - sum_j sigma_j^2 D_ij,
//
// and sigma^2 >= 0 minimising |g|^2 is found by Gauss-Newton with step
// halving, keeping every R_i positive definite (it estimates the
// noise-free normal matrix). beta then follows from beta_bar = F beta by
// least squares. Uniform sampling only (the noise Gram assumes one filter).
// A root at a pole of the system makes the augmented equation non-unique.
template <typename S>
Status ss_bc_gpmf(const MultiRecordView<S>& record,
                  const GpmfSettings<S>& settings,
                  const std::vector<std::vector<S>>& roots,
                  StateSpaceEstimate<S>* estimate,
                  Vector<S>* noise_variance = nullptr) {
  Status status = gpmf_detail::validate(record, settings);
  if (!status.ok()) return status;
  const auto& n = settings.observability_indices;
  const int p = static_cast<int>(record.num_outputs);
  const int m = static_cast<int>(record.num_inputs);
  if (static_cast<int>(roots.size()) != p) {
    return dimension_mismatch("root must have one row per output (" +
                              std::to_string(p) + "), got " +
                              std::to_string(roots.size()));
  }
  for (const auto& row : roots) {
    if (row.empty() || row.size() > 20) {
      return bad_input("each output needs 1..20 filter roots");
    }
    for (S r : row) {
      if (!std::isfinite(r) || !(r < 0)) {
        return bad_input("the filter roots must be finite and < 0");
      }
    }
  }
  if (record.instants != nullptr) {
    return bad_input("bias compensation needs uniformly sampled data");
  }
  const Eigen::Index count = record.num_samples;
  const Eigen::Index first = settings.first_sample;
  for (int i = 0; i < p; ++i) {
    const Eigen::Index columns =
        gpmf_detail::num_alpha(n, i) +
        (n[i] + static_cast<Eigen::Index>(roots[i].size())) * m;
    if (count - first < columns) {
      return bad_input(
          "the data from sample n0 on have fewer samples than "
          "the " +
          std::to_string(columns) +
          " parameters of an augmented output equation");
    }
  }
  struct Equation {
    Matrix<S> P;               // Phi^T Phi
    Vector<S> c;               // Phi^T zeta
    Vector<S> theta;           // augmented parameters
    std::vector<Matrix<S>> D;  // noise Gram of y_j, j = 1..p
    Vector<S> d;               // noise cross term of y_i and zeta
    Matrix<S> H;               // left null space of the convolution by F
    Matrix<S> T;               // convolution by F: beta_bar = T beta
    Eigen::Index alpha_count = 0;
  };
  std::vector<Equation> eq(p);
  for (int i = 0; i < p; ++i) {
    Equation& e = eq[i];
    const int r = static_cast<int>(roots[i].size());
    Matrix<S> phi;
    Vector<S> zeta;
    gpmf_detail::gpmf_regressors(record, settings, i, record.y, &phi, &zeta,
                                 &roots[i]);
    // The rank test only: theta(sigma^2) is solved from P and c below.
    if (!gpmf_detail::least_squares<S>(phi, zeta, nullptr)) {
      return numerical_failure(
          "the augmented GPMF regression of output " + std::to_string(i + 1) +
          " is rank deficient (input not exciting enough, nni too large or "
          "too many roots)");
    }
    e.P = phi.transpose() * phi;
    e.c = phi.transpose() * zeta;
    e.alpha_count = gpmf_detail::num_alpha(n, i);
    // Impulse response g(tau) of the y filter (outputs 0..n_i), from rest;
    // the noise Gram of the rows k = first..N-1 is sum_k G(k - 1), G(t) =
    // sum_(tau <= t) g(tau) g(tau)^T (sample 0 sets the rest state), that
    // is sum_tau w(tau) g(tau) g(tau)^T, w(tau) the number of rows k >=
    // max(tau + 1, first).
    const int order = n[i] + 1;
    FilterDiscretization<S> disc;
    disc.configure(order, InterSample::kFoh);
    disc.set_denominator(svf_denominator(order, settings.lambda[i]));
    disc.ensure(record.ts);
    FilterChannel<S> channel;
    channel.configure(order);
    channel.set_rest_at_first_sample(true);
    const S gain = svf_gain(order, settings.lambda[i], true);
    channel.step(disc, gain, S(0));
    Matrix<S> W = Matrix<S>::Zero(order + 1, order + 1);
    // The filter is stable (all its poles at -lambda): once the impulse
    // response (whose first n_i + 1 outputs are the state) has fallen to
    // 1e-16 of its largest norm, the rest of the sum is below rounding.
    S largest = 0;
    for (Eigen::Index t = 0; t + 1 < count; ++t) {
      channel.step(disc, gain, t == 0 ? S(1) : S(0));
      const Vector<S>& g = channel.outputs();
      const S weight = static_cast<S>(count - std::max(t + 1, first));
      W.noalias() += weight * g * g.transpose();
      const S size = g.squaredNorm();
      largest = std::max(largest, size);
      if (t > order && size <= S(1e-32) * largest) break;
    }
    e.D.assign(p, Matrix<S>::Zero(phi.cols(), phi.cols()));
    e.d = Vector<S>::Zero(phi.cols());
    Eigen::Index offset = 0;
    for (int j = 0; j < p; ++j) {
      const int nu = gpmf_detail::coupling_degree(n, i, j);
      e.D[j].block(offset, offset, nu, nu) = W.topLeftCorner(nu, nu);
      if (j == i) e.d.segment(offset, nu) = -W.col(n[i]).head(nu);
      offset += nu;
    }
    // Convolution by F (ascending powers): beta_bar = T beta.
    Vector<S> f = Vector<S>::Ones(1);
    for (int q = 0; q < r; ++q) {
      Vector<S> next = Vector<S>::Zero(f.size() + 1);
      next.tail(f.size()) = f;
      next.head(f.size()) -= roots[i][q] * f;
      f = next;
    }
    e.T = Matrix<S>::Zero(n[i] + r, n[i]);
    for (int k = 0; k < n[i]; ++k) e.T.col(k).segment(k, r + 1) = f;
    Eigen::JacobiSVD<Matrix<S>> svd(e.T, Eigen::ComputeFullU);
    e.H = svd.matrixU().rightCols(r);
  }
  // sigma^2 >= 0 minimising |g(sigma^2)|^2, g the stacked constraints
  // H^T beta_bar_(il)(sigma^2), by Gauss-Newton with step halving; the
  // Jacobian column j of output i is H^T R_i^-1 (D_ij theta_i - [i = j]
  // d_i), R_i = P_i - sum_j sigma_j^2 D_ij.
  Eigen::Index rows = 0;
  for (int i = 0; i < p; ++i) rows += eq[i].H.cols() * m;
  const auto evaluate = [&](const Vector<S>& sigma2, Vector<S>* g,
                            Matrix<S>* J) -> bool {
    g->resize(rows);
    if (J != nullptr) J->resize(rows, p);
    Eigen::Index row = 0;
    for (int i = 0; i < p; ++i) {
      Equation& e = eq[i];
      Matrix<S> R = e.P;
      for (int j = 0; j < p; ++j) R -= sigma2(j) * e.D[j];
      // R_i estimates the noise-free normal matrix: positive definite.
      const Eigen::LLT<Matrix<S>> lu(R);
      if (lu.info() != Eigen::Success) return false;
      e.theta = lu.solve(e.c - sigma2(i) * e.d);
      if (!e.theta.allFinite()) return false;
      Matrix<S> response(e.theta.size(), p);
      if (J != nullptr) {
        for (int j = 0; j < p; ++j) {
          Vector<S> v = e.D[j] * e.theta;
          if (j == i) v -= e.d;
          response.col(j) = lu.solve(v);
        }
      }
      const Eigen::Index width = e.H.rows();
      const Eigen::Index h = e.H.cols();
      for (int l = 0; l < m; ++l) {
        const Eigen::Index start = e.alpha_count + l * width;
        g->segment(row, h) = e.H.transpose() * e.theta.segment(start, width);
        if (J != nullptr) {
          J->middleRows(row, h) =
              e.H.transpose() * response.middleRows(start, width);
        }
        row += h;
      }
    }
    return true;
  };
  S power = 0;
  for (Eigen::Index k = 0; k < count * p; ++k) {
    power = std::max(power, record.y[k] * record.y[k]);
  }
  const S floor = std::max(power, std::numeric_limits<S>::min()) *
                  std::numeric_limits<S>::epsilon();
  Vector<S> sigma2 = Vector<S>::Zero(p);
  Vector<S> g;
  Matrix<S> J;
  if (!evaluate(sigma2, &g, &J)) {
    return numerical_failure("the least-squares GPMF estimate is not finite");
  }
  const int max_iterations = 100;
  bool converged = false;
  for (int iteration = 0; iteration < max_iterations && !converged;
       ++iteration) {
    const Vector<S> step = J.colPivHouseholderQr().solve(-g);
    S cost = g.squaredNorm();
    S scale = 1;
    bool improved = false;
    Vector<S> trial(p), g_trial;
    for (int halving = 0; halving < 40; ++halving, scale /= 2) {
      trial = (sigma2 + scale * step).cwiseMax(S(0));
      if (evaluate(trial, &g_trial, nullptr) && g_trial.squaredNorm() < cost) {
        improved = true;
        break;
      }
    }
    const S moved = improved ? (trial - sigma2).norm() : S(0);
    if (improved) sigma2 = trial;
    converged = !improved || moved <= S(1e-10) * std::max(sigma2.norm(), floor);
    if (!evaluate(sigma2, &g, &J)) {
      return numerical_failure("the bias-compensated estimate is not finite");
    }
  }
  if (!converged) {
    return Status(ErrorCode::kNotConverged,
                  "the bias compensation did not converge (try other roots "
                  "or filter parameters)");
  }
  // beta from beta_bar = T beta, per input, and the canonical model.
  Eigen::Index total = 0;
  for (int i = 0; i < p; ++i) total += eq[i].alpha_count + n[i] * m;
  Vector<S> theta(total);
  Eigen::Index offset = 0;
  for (int i = 0; i < p; ++i) {
    const Equation& e = eq[i];
    theta.segment(offset, e.alpha_count) = e.theta.head(e.alpha_count);
    offset += e.alpha_count;
    const Eigen::Index width = e.T.rows();
    const Eigen::ColPivHouseholderQR<Matrix<S>> qr(e.T);
    for (int l = 0; l < m; ++l) {
      theta.segment(offset, n[i]) = qr.solve(
          Vector<S>(e.theta.segment(e.alpha_count + l * width, width)));
      offset += n[i];
    }
  }
  if (noise_variance != nullptr) *noise_variance = sigma2;
  return gpmf_detail::canonical_model(n, m, theta, estimate);
}

struct SubspaceGpmfSettings {
  int block_rows = 3;    // i: derivatives 0 .. i-1
  int filter_order = 3;  // j: the Poisson filter (lambda/(p+lambda))^(j+1)
  double lambda = 1;
  int order = 0;  // n; 0: chosen at the largest gap of the singular values
  Eigen::Index first_sample = 0;
};

template <typename S>
struct SubspaceGpmfEstimate {
  StateSpaceEstimate<S> model;
  Vector<S> singular_values;  // of the projected GPMF data, i p of them
};

// GPMF 4SID (sidgpmf); see the header comment.
template <typename S>
Status sid_gpmf(const MultiRecordView<S>& record,
                const SubspaceGpmfSettings& settings,
                SubspaceGpmfEstimate<S>* estimate) {
  const int p = static_cast<int>(record.num_outputs);
  const int m = static_cast<int>(record.num_inputs);
  const int i = settings.block_rows;
  const int j = settings.filter_order;
  if (i < 2 || j < i - 1 || j > 20) {
    return bad_input("i must be >= 2 and j an integer in i-1 .. 20");
  }
  if (settings.order < 0 || settings.order > (i - 1) * p) {
    return bad_input("the order n must be in 1 .. (i-1) p = " +
                     std::to_string((i - 1) * p));
  }
  GpmfSettings<S> check;
  check.observability_indices.assign(p, 1);
  check.lambda.assign(p, static_cast<S>(settings.lambda));
  check.first_sample = settings.first_sample;
  Status status = gpmf_detail::validate(record, check);
  if (!status.ok()) return status;
  const Eigen::Index count = record.num_samples;
  const Eigen::Index used = count - settings.first_sample;
  const Eigen::Index rows_u = i * m, rows_y = i * p;
  if (used < 2 * (rows_u + rows_y)) {
    return bad_input("the data from sample n0 on have fewer than " +
                     std::to_string(2 * (rows_u + rows_y)) +
                     " samples, twice the rows of the GPMF data matrix");
  }
  // The GPMF data matrix, one column per sample: [U_i; Y_i], block k of
  // each holding p^k F of every input or output.
  const int order = j + 1;
  const S lambda = static_cast<S>(settings.lambda);
  const Vector<S> d = svf_denominator(order, lambda);
  const S gain = svf_gain(order, lambda, true);
  FilterDiscretization<S> y_disc, u_disc;
  y_disc.configure(order, InterSample::kFoh);
  y_disc.set_denominator(d);
  u_disc.configure(order, record.u_intersample);
  u_disc.set_denominator(d);
  std::vector<FilterChannel<S>> y_channels(p), u_channels(m);
  for (auto* channels : {&y_channels, &u_channels}) {
    for (auto& c : *channels) {
      c.configure(order);
      c.set_rest_at_first_sample(true);
    }
  }
  Matrix<S> data(used, rows_u + rows_y);  // transposed: samples in rows
  for (Eigen::Index k = 0; k < count; ++k) {
    const S h = record.interval(k);
    y_disc.ensure(h);
    u_disc.ensure(h);
    for (int q = 0; q < p; ++q)
      y_channels[q].step(y_disc, gain, record.y_at(k, q));
    for (int l = 0; l < m; ++l)
      u_channels[l].step(u_disc, gain, record.u_at(k, l));
    if (k < settings.first_sample) continue;
    const Eigen::Index row = k - settings.first_sample;
    for (int r = 0; r < i; ++r) {
      for (int l = 0; l < m; ++l)
        data(row, r * m + l) = u_channels[l].outputs()(r);
      for (int q = 0; q < p; ++q) {
        data(row, rows_u + r * p + q) = y_channels[q].outputs()(r);
      }
    }
  }
  // LQ of [U; Y] as the QR of its transpose: R22' is Y projected onto the
  // orthogonal complement of the rows of U.
  Eigen::HouseholderQR<Matrix<S>> qr(data);
  const Matrix<S> R = qr.matrixQR()
                          .topRows(rows_u + rows_y)
                          .template triangularView<Eigen::Upper>();
  const Matrix<S> L22 = R.bottomRightCorner(rows_y, rows_y).transpose();
  Eigen::JacobiSVD<Matrix<S>> svd(L22, Eigen::ComputeFullU);
  estimate->singular_values = svd.singularValues();
  const Vector<S>& sv = svd.singularValues();
  int n = settings.order;
  if (n == 0) {
    S best = -1;
    const S floor = sv(0) * std::numeric_limits<S>::epsilon();
    for (int r = 1; r <= (i - 1) * p; ++r) {
      const S ratio = sv(r - 1) / std::max(sv(r), floor);
      if (ratio > best) {
        best = ratio;
        n = r;
      }
    }
  }
  if (!(sv(n - 1) > sv(0) * 1e3 * std::numeric_limits<S>::epsilon())) {
    return numerical_failure(
        "the GPMF data have rank below the order n = " + std::to_string(n) +
        " (input not exciting enough, or n too large)");
  }
  const Matrix<S> gamma =
      svd.matrixU().leftCols(n) * sv.head(n).cwiseSqrt().asDiagonal();
  Matrix<S> A = gamma.topRows(rows_y - p)
                    .completeOrthogonalDecomposition()
                    .solve(gamma.bottomRows(rows_y - p));
  const Matrix<S> C = gamma.topRows(p);
  // B and D: y(t_k) = sum_(r,l) B(r,l) C x_(r,l)(t_k) + D u(t_k), with
  // x_(r,l)' = A x_(r,l) + e_r u_l from rest, one least-squares fit of all
  // outputs.
  const Eigen::Index columns = n * m + p * m;
  Matrix<S> phi(used * p, columns);
  Vector<S> target(used * p);
  for (int q = 0; q < p; ++q) {
    for (Eigen::Index k = 0; k < used; ++k) {
      target(q * used + k) = record.y_at(k + settings.first_sample, q);
    }
  }
  for (int l = 0; l < m; ++l) {
    MultiRecordView<S> single = record;
    single.u = record.u + l * count;
    single.num_inputs = 1;
    for (int r = 0; r < n; ++r) {
      Matrix<S> response;
      status = gpmf_detail::simulate_state_space(
          A, Matrix<S>(Matrix<S>::Identity(n, n).col(r)), C, single, &response);
      if (!status.ok()) {
        return numerical_failure(
            "the estimated A gives a diverging response: "
            "no B and D (try another n, i or lambda)");
      }
      for (int q = 0; q < p; ++q) {
        phi.col(l * n + r).segment(q * used, used) = response.col(q).tail(used);
      }
    }
    for (int q = 0; q < p; ++q) {
      phi.col(n * m + l * p + q).setZero();
      for (Eigen::Index k = 0; k < used; ++k) {
        phi(q * used + k, n * m + l * p + q) =
            record.u_at(k + settings.first_sample, l);
      }
    }
  }
  Eigen::ColPivHouseholderQR<Matrix<S>> fit(phi);
  if (fit.rank() < columns) {
    return numerical_failure("the least-squares fit of B and D is singular");
  }
  const Vector<S> bd = fit.solve(target);
  StateSpaceEstimate<S>& model = estimate->model;
  model.A = A;
  model.C = C;
  model.B.resize(n, m);
  model.D.resize(p, m);
  for (int l = 0; l < m; ++l) {
    model.B.col(l) = bd.segment(l * n, n);
    model.D.col(l) = bd.segment(n * m + l * p, p);
  }
  model.theta.resize(0);
  return Status::Ok();
}

}  // namespace ctid
