// SPDX-License-Identifier: BSD-3-Clause
// Copyright (C) the ctid authors
// Refined instrumental variable estimation of continuous-time LPV
// input/output models (CONTSID's lpvsrivc and lpvrivc): the LPV output-error
// model (SRIVC) and the LPV Box-Jenkins model with a discrete-time ARMA
// noise model (RIVC),
//
//   A(D, rho) chi = B(D, rho) u,   y = chi + C(q^-1)/D(q^-1) e,
//
// with the model, the basis functions and the Euler derivative operator D
// of lpv_simulator.hpp (the leading coefficient of A normalised to 1).
//
// Linear regression. With f_ij(rho_k) the basis functions, a_ij, b_ij the
// parameters, the model reads at every sample
//
//   D^na chi + sum_ij a_ij f_ij(rho) D^(na-i) chi = sum_ij b_ij g_ij(rho)
//   D^(nb-i) u,
//
// linear in the parameters, with regressors that are products of the basis
// functions with the derivatives of chi and u (the coefficients multiply the
// derivatives: the product is formed after differentiation). Any LTI filter
// L applied to every product keeps the equation exact, so the products are
// prefiltered like the signals of the LTI refined IV.
//
// The refined IV iteration (Laurain, Gilson, Toth, Garnier, Automatica 46,
// 2010; continuous time: Laurain, Toth, Gilson, Garnier, IET Control Theory
// Appl. 5(7), 2011). Split A into its time-invariant part A_0(D) (the
// coefficients of the basis functions that are constant over the record)
// and the rest. With y = chi + v,
//
//   A_0(D) y + [A(D, rho) - A_0(D)] chi = B(D, rho) u + A_0(D) v,
//
// so with the regressors of the constant basis functions taken from y, the
// others from the noise-free output chi_hat of the auxiliary model
// (simulate_lpv with the previous estimate), the equation error is A_0 v:
// the prefilter L = 1/A_0(D) (times D(q)/C(q), the inverse of the ARMA model
// of y - chi_hat, in RIVC) whitens it. The instruments are the same
// products built from chi_hat alone. Each iteration solves
//
//   theta = [sum zeta_f phi_f^T]^-1 sum zeta_f D^na y_f.
//
// When the constant part A_0 is not stable, the frozen model averaged over
// the record is used, its unstable roots reflected.
//
// Initialisation (no A, B given): least squares on the same regression with
// every product built from y, prefiltered by 1/(D + lambda)^na, for lambda
// from 0.3/Ts down by factors of 3; the start is the estimate whose
// auxiliary model fits the data best. During the iteration an estimate
// whose auxiliary model is unstable (output not finite or 1e4 times the
// data's scale) is pulled back towards the previous estimate.
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "ctid/base/polynomial.hpp"
#include "ctid/base/stability.hpp"
#include "ctid/base/status.hpp"
#include "ctid/base/types.hpp"
#include "ctid/offline/refined_iv_bj.hpp"
#include "ctid/simulation/lpv_simulator.hpp"

namespace ctid {

template <typename S>
struct LpvProblem {
  const S* y = nullptr;
  const S* u = nullptr;
  Eigen::Index num_samples = 0;
  S ts = 0;
  LpvBasis<S> dep_a;  // n_dep_a x na x N
  LpvBasis<S> dep_b;  // n_dep_b x nb x N
  int nc = 0;         // ARMA noise model orders (0, 0: output error)
  int nd = 0;
};

template <typename S>
struct LpvSettings {
  S tolerance = S(1e-4);  // on the relative change of the parameters
  int max_iterations = 50;
  Matrix<S> a_init;  // (na+1) x n_dep_a and nb x n_dep_b, or empty
  Matrix<S> b_init;
  ArmaSettings<S> arma;
};

template <typename S>
struct LpvResult {
  Vector<S> theta;  // the used a_ij (row by row), then the used b_ij
  Matrix<S> a;      // (na+1) x n_dep_a, first row [1 0 .. 0]
  Matrix<S> b;      // nb x n_dep_b
  Vector<S> c;      // [1 c1 .. c_nc]
  Vector<S> d;      // [1 d1 .. d_nd]
  S cost = 0;       // noise variance: mean (y - ysim)^2, or the ARMA
                    // innovation variance for RIVC
  int iterations = 0;
  bool converged = false;
  Vector<S> ysim;  // noise-free output of the estimated model
};

// Least-squares starts tried (prefilter cut-offs 0.3/Ts, 0.1/Ts, ..) and
// halvings of a step towards the previous estimate when the new auxiliary
// model is unstable.
inline constexpr int kLpvInitialCutoffs = 8;
inline constexpr int kLpvBacktracks = 8;

namespace lpv_detail {

// One parameter a_ij or b_ij of the regression.
struct LpvTerm {
  bool is_a;
  Eigen::Index coefficient;  // i (0-based: a_(i+1) or b_(i+1))
  Eigen::Index function;     // j
  bool constant;             // basis constant over the record
};

template <typename S>
std::vector<LpvTerm> active_terms(const LpvBasis<S>& dep_a,
                                  const LpvBasis<S>& dep_b) {
  std::vector<LpvTerm> terms;
  for (Eigen::Index i = 0; i < dep_a.num_coefficients; ++i) {
    for (Eigen::Index j = 0; j < dep_a.num_functions; ++j) {
      if (dep_a.active(j, i)) {
        terms.push_back({true, i, j, dep_a.constant(j, i)});
      }
    }
  }
  for (Eigen::Index i = 0; i < dep_b.num_coefficients; ++i) {
    for (Eigen::Index j = 0; j < dep_b.num_functions; ++j) {
      if (dep_b.active(j, i)) {
        terms.push_back({false, i, j, dep_b.constant(j, i)});
      }
    }
  }
  return terms;
}

template <typename S>
void theta_to_matrices(const Vector<S>& theta,
                       const std::vector<LpvTerm>& terms,
                       const LpvBasis<S>& dep_a, const LpvBasis<S>& dep_b,
                       Matrix<S>* a, Matrix<S>* b) {
  *a = Matrix<S>::Zero(dep_a.num_coefficients + 1, dep_a.num_functions);
  *b = Matrix<S>::Zero(dep_b.num_coefficients, dep_b.num_functions);
  (*a)(0, 0) = 1;
  for (std::size_t p = 0; p < terms.size(); ++p) {
    const LpvTerm& t = terms[p];
    if (t.is_a) {
      (*a)(t.coefficient + 1, t.function) = theta(p);
    } else {
      (*b)(t.coefficient, t.function) = theta(p);
    }
  }
}

// The polynomial in q^-1 of A(D) = D^n + a1 D^(n-1) + .. + an with
// D = (1 - q^-1)/Ts, normalised so that its q^0 coefficient is 1.
template <typename S>
Vector<S> euler_polynomial(const Vector<S>& a_monic, S ts) {
  const Eigen::Index n = a_monic.size();
  Vector<S> poly = Vector<S>::Zero(n + 1);
  const auto w = difference_weights<S>(static_cast<int>(n), ts);
  for (Eigen::Index i = 0; i <= n; ++i) {
    const S coef = i == 0 ? S(1) : a_monic(i - 1);
    const Eigen::Index m = n - i;
    for (Eigen::Index l = 0; l <= m; ++l) poly(l) += coef * w[m][l];
  }
  return poly / poly(0);
}

// The columns of a regression matrix are scaled to unit norm; a column of
// zeros or a (numerically) singular matrix means too little excitation.
template <typename S>
Status solve_scaled(const Matrix<S>& zeta, const Matrix<S>& phi,
                    const Vector<S>& target, Vector<S>* theta) {
  const Eigen::Index np = phi.cols();
  Vector<S> scale(np);
  for (Eigen::Index c = 0; c < np; ++c) {
    const S norm = phi.col(c).norm();
    const S znorm = zeta.col(c).norm();
    if (!std::isfinite(norm) || !std::isfinite(znorm)) {
      return numerical_failure("regressor " + std::to_string(c + 1) +
                               " overflows (not finite)");
    }
    if (!(norm > 0) || !(znorm > 0)) {
      return numerical_failure("too little excitation: regressor " +
                               std::to_string(c + 1) +
                               " is zero (check u and the dependency arrays)");
    }
    scale(c) = S(1) / norm;
  }
  Vector<S> zscale(np);
  for (Eigen::Index c = 0; c < np; ++c) zscale(c) = S(1) / zeta.col(c).norm();
  const Matrix<S> m =
      zscale.asDiagonal() * (zeta.transpose() * phi) * scale.asDiagonal();
  const Eigen::JacobiSVD<Matrix<S>> svd(
      m, Eigen::ComputeFullU | Eigen::ComputeFullV);
  const auto& sv = svd.singularValues();
  if (!(sv(np - 1) > S(1e-11) * sv(0))) {
    return numerical_failure(
        "too little excitation: the regressors are (nearly) collinear "
        "(condition number " +
        std::to_string(sv(0) / sv(np - 1)) +
        "); the input or the scheduling signal does not excite every basis "
        "function");
  }
  const Vector<S> rhs = zscale.asDiagonal() * (zeta.transpose() * target);
  *theta = scale.asDiagonal() * svd.solve(rhs);
  if (!theta->allFinite())
    return numerical_failure("the estimate is not finite");
  return Status::Ok();
}

}  // namespace lpv_detail

template <typename S>
Status validate(const LpvProblem<S>& problem) {
  const Eigen::Index n = problem.num_samples;
  if (problem.y == nullptr || problem.u == nullptr || n < 1) {
    return bad_input("the data are empty");
  }
  if (!(problem.ts > 0) || !std::isfinite(problem.ts)) {
    return bad_input("the sampling interval must be > 0");
  }
  for (const LpvBasis<S>* basis : {&problem.dep_a, &problem.dep_b}) {
    if (basis->num_samples != n) {
      return dimension_mismatch(
          std::string(basis == &problem.dep_a ? "DepA" : "DepB") + " has " +
          std::to_string(basis->num_samples) +
          " samples (third dimension) but the data have " + std::to_string(n) +
          ": the scheduling signal must have one value per sample");
    }
    const Eigen::Index total =
        basis->num_functions * basis->num_coefficients * n;
    for (Eigen::Index k = 0; k < total; ++k) {
      if (!std::isfinite(basis->values[k])) {
        return bad_input("the dependency arrays must be finite");
      }
    }
  }
  if (problem.dep_a.num_coefficients < 1 || problem.dep_a.num_functions < 1) {
    return bad_input("the model needs na >= 1");
  }
  if (problem.dep_b.num_coefficients < 1 || problem.dep_b.num_functions < 1) {
    return bad_input("the model needs nb >= 1");
  }
  if (problem.dep_b.num_coefficients > problem.dep_a.num_coefficients + 1) {
    return bad_input("nb must be <= na + 1 (a proper model)");
  }
  if (problem.nc < 0 || problem.nd < 0 || problem.nc > 50 || problem.nd > 50) {
    return bad_input("the noise orders nc, nd must be in 0..50");
  }
  for (Eigen::Index k = 0; k < n; ++k) {
    if (!std::isfinite(problem.y[k]) || !std::isfinite(problem.u[k])) {
      return bad_input("y and u must be finite");
    }
  }
  return Status::Ok();
}

template <typename S>
Status lpv_refined_iv(const LpvProblem<S>& problem,
                      const LpvSettings<S>& settings, LpvResult<S>* result) {
  using namespace lpv_detail;
  if (result == nullptr) return bad_input("lpv_refined_iv: no result");
  Status status = validate(problem);
  if (!status.ok()) return status;
  if (!(settings.tolerance > 0) || settings.max_iterations < 1) {
    return Status(ErrorCode::kBadOption, "tol must be > 0 and maxiter >= 1");
  }
  const LpvBasis<S>& dep_a = problem.dep_a;
  const LpvBasis<S>& dep_b = problem.dep_b;
  const Eigen::Index n = problem.num_samples;
  const int na = static_cast<int>(dep_a.num_coefficients);
  const int nb = static_cast<int>(dep_b.num_coefficients);
  const S ts = problem.ts;
  const std::vector<LpvTerm> terms = active_terms(dep_a, dep_b);
  const Eigen::Index np = static_cast<Eigen::Index>(terms.size());
  bool any_b = false;
  for (const LpvTerm& t : terms) any_b = any_b || !t.is_a;
  if (!any_b) {
    return bad_input("every basis function of B is zero: nothing to estimate");
  }
  if (n < 2 * (np + na + problem.nc + problem.nd) + 10) {
    return bad_input("too few samples (" + std::to_string(n) + ") for " +
                     std::to_string(np) + " parameters");
  }
  const auto w = difference_weights<S>(na, ts);
  const Eigen::Map<const Vector<S>> y(problem.y, n);
  // Derivatives D^m y and D^m u (m = 0..na), and the u products (fixed).
  Matrix<S> dy(n, na + 1), du(n, nb);
  for (int m = 0; m <= na; ++m) {
    backward_difference(problem.y, n, w[m], dy.col(m).data());
  }
  for (int m = 0; m < nb; ++m) {
    backward_difference(problem.u, n, w[m], du.col(m).data());
  }
  // Raw (unfiltered) product of term t with the derivatives in d (a terms:
  // -f D^(na-i) s; b terms: g D^(nb-i) u).
  auto product = [&](const LpvTerm& t, const Matrix<S>& d, S* out) {
    for (Eigen::Index k = 0; k < n; ++k) {
      if (t.is_a) {
        out[k] = -dep_a.value(t.function, t.coefficient, k) *
                 d(k, na - 1 - t.coefficient);
      } else {
        out[k] = dep_b.value(t.function, t.coefficient, k) *
                 du(k, nb - 1 - t.coefficient);
      }
    }
  };
  Matrix<S> phi_raw_y(n, np);  // every product from y
  for (Eigen::Index p = 0; p < np; ++p) {
    product(terms[p], dy, phi_raw_y.col(p).data());
  }
  Matrix<S> phi(n, np), zeta(n, np), raw(n, np);
  Vector<S> target(n);
  auto filter_columns = [&](const Vector<S>& num, const Vector<S>& den,
                            const Matrix<S>& in, Matrix<S>& out) {
    for (Eigen::Index c = 0; c < in.cols(); ++c) {
      bj_detail::filter_dt<S>(num, den, in.col(c).data(), n, out.col(c).data());
    }
  };

  Matrix<S> a_hat, b_hat;
  const S y_scale = y.cwiseAbs().maxCoeff();
  // The auxiliary model of theta, simulated into chi: false when it cannot
  // be simulated or its output leaves the scale of the data by far (an
  // unstable model).
  auto simulate_theta = [&](const Vector<S>& th, Vector<S>& out) {
    theta_to_matrices<S>(th, terms, dep_a, dep_b, &a_hat, &b_hat);
    if (!simulate_lpv<S>(problem.u, n, ts, a_hat, dep_a, b_hat, dep_b,
                         out.data())
             .ok()) {
      return false;
    }
    return out.cwiseAbs().maxCoeff() <= S(1e4) * y_scale;
  };

  Vector<S> theta(np), chi(n), trial(n);
  if (settings.a_init.size() > 0 || settings.b_init.size() > 0) {
    status = check_lpv_model(settings.a_init, dep_a, settings.b_init, dep_b);
    if (!status.ok()) return status;
    const S a0 = settings.a_init(0, 0);
    for (Eigen::Index p = 0; p < np; ++p) {
      const LpvTerm& t = terms[p];
      theta(p) = (t.is_a ? settings.a_init(t.coefficient + 1, t.function)
                         : settings.b_init(t.coefficient, t.function)) /
                 a0;
    }
    if (!simulate_theta(theta, chi)) {
      return numerical_failure(
          "the initial model Ainit, Binit cannot be simulated on these data "
          "(unstable)");
    }
  } else {
    // Least squares with the prefilter 1/(D + lambda)^na for lambda on a
    // grid from 0.3/Ts down by factors of 3; the start is the estimate
    // whose auxiliary model fits the data best.
    const Vector<S> one = Vector<S>::Ones(1);
    S best = std::numeric_limits<S>::infinity();
    Status last = Status::Ok();
    for (int c = 0; c < kLpvInitialCutoffs; ++c) {
      const S lambda = S(0.3) / ts * std::pow(S(3), -S(c));
      Vector<S> lti(na);
      S binomial = 1;
      for (int i = 1; i <= na; ++i) {
        binomial = binomial * S(na - i + 1) / S(i);
        lti(i - 1) = binomial * std::pow(lambda, S(i));
      }
      const Vector<S> den = euler_polynomial<S>(lti, ts);
      filter_columns(one, den, phi_raw_y, phi);
      bj_detail::filter_dt<S>(one, den, dy.col(na).data(), n, target.data());
      Vector<S> candidate;
      last = solve_scaled<S>(phi, phi, target, &candidate);
      if (!last.ok()) {
        if (c == 0) return last;  // the data do not excite the model
        continue;
      }
      if (!simulate_theta(candidate, trial)) continue;
      const S fit = (y - trial).squaredNorm();
      if (fit < best) {
        best = fit;
        theta = candidate;
        chi = trial;
      }
    }
    if (!std::isfinite(best)) {
      return numerical_failure(
          "no least-squares start gives a stable auxiliary model; give an "
          "initial model Ainit, Binit");
    }
  }

  Vector<S> xi(n);
  Matrix<S> dchi(n, na + 1);
  dchi.col(na).setZero();
  ArmaResult<S> arma;
  const bool noise_model = problem.nc + problem.nd > 0;
  HurwitzTest<S> hurwitz(na);
  result->converged = false;
  int iteration = 0;
  for (iteration = 1; iteration <= settings.max_iterations; ++iteration) {
    theta_to_matrices<S>(theta, terms, dep_a, dep_b, &a_hat, &b_hat);
    // LTI part A_0 of the prefilter.
    Vector<S> a_lti = Vector<S>::Zero(na);
    for (Eigen::Index p = 0; p < np; ++p) {
      const LpvTerm& t = terms[p];
      if (t.is_a && t.constant) {
        a_lti(t.coefficient) +=
            theta(p) * dep_a.value(t.function, t.coefficient, 0);
      }
    }
    if (!hurwitz.is_stable(a_lti)) {
      const Matrix<S> frozen = coefficient_trajectories<S>(a_hat, 1, dep_a);
      a_lti = frozen.colwise().mean().transpose();
      if (!hurwitz.is_stable(a_lti)) a_lti = reflect_unstable_roots<S>(a_lti);
    }
    Vector<S> den = euler_polynomial<S>(a_lti, ts);
    Vector<S> num = Vector<S>::Ones(1);
    if (noise_model) {
      xi = y - chi;
      status = arma_estimate<S>(xi.data(), n, problem.nd, problem.nc,
                                settings.arma, &arma);
      if (!status.ok()) return status;
      num = arma.d;
      den = convolve<S>(den, arma.c);
    }
    for (int m = 0; m < na; ++m) {
      backward_difference(chi.data(), n, w[m], dchi.col(m).data());
    }
    // Instruments: every product from chi_hat; regressors: those of the
    // constant basis functions from y.
    for (Eigen::Index p = 0; p < np; ++p) {
      const LpvTerm& t = terms[p];
      if (t.is_a) {
        product(t, dchi, raw.col(p).data());
      } else {
        raw.col(p) = phi_raw_y.col(p);
      }
    }
    filter_columns(num, den, raw, zeta);
    for (Eigen::Index p = 0; p < np; ++p) {
      const LpvTerm& t = terms[p];
      if (t.is_a && t.constant) raw.col(p) = phi_raw_y.col(p);
    }
    filter_columns(num, den, raw, phi);
    bj_detail::filter_dt<S>(num, den, dy.col(na).data(), n, target.data());
    Vector<S> next;
    status = solve_scaled<S>(zeta, phi, target, &next);
    if (!status.ok()) return status;
    // An estimate whose auxiliary model is unstable is pulled back towards
    // the previous one; if that fails the iteration stops (not converged).
    bool usable = false;
    for (int h = 0; h <= kLpvBacktracks && !usable; ++h) {
      if (h > 0) next = (theta + next) / S(2);
      usable = simulate_theta(next, trial);
    }
    if (!usable) break;
    const S change = (next - theta).norm() / std::max(next.norm(), S(1e-300));
    theta = next;
    chi = trial;
    if (change < settings.tolerance) {
      result->converged = true;
      break;
    }
  }
  result->iterations = std::min(iteration, settings.max_iterations);
  theta_to_matrices<S>(theta, terms, dep_a, dep_b, &a_hat, &b_hat);
  result->theta = theta;
  result->a = a_hat;
  result->b = b_hat;
  result->ysim = chi;
  xi = y - chi;
  result->cost = xi.squaredNorm() / S(n);
  result->c = Vector<S>::Ones(1);
  result->d = Vector<S>::Ones(1);
  if (noise_model) {
    status = arma_estimate<S>(xi.data(), n, problem.nd, problem.nc,
                              settings.arma, &arma);
    if (!status.ok()) return status;
    result->c = arma.c;
    result->d = arma.d;
    result->cost = arma.innovation_variance;
  }
  return Status::Ok();
}

}  // namespace ctid
