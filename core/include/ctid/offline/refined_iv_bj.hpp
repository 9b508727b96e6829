// SPDX-License-Identifier: BSD-3-Clause
// Copyright (C) the ctid authors
// Refined IV for the hybrid Box-Jenkins model (RIVC of Young and Garnier)
//
//   y(t_k) = B(p) / F(p) u(t_k - tau) + xi(t_k),
//   xi(t_k) = C(q^-1) / D(q^-1) e(t_k),   e white,
//
// a continuous-time plant (thesis sec. 2.1.2, eqs. 2.8-2.13 for its
// output-error special case) with a discrete-time ARMA noise model at the
// sampling interval Ts (CONTSID's naming: C the noise numerator, D its
// denominator; rivc's nn = [nb nc nd nf nk]).
//
// RIVC iteration (the hybrid refined IV; thesis eq. 2.9 with the optimal
// prefilter of the Box-Jenkins case): from the current plant estimate,
//   1. the auxiliary model x_hat = B/F u and the noise estimate
//      xi_hat = y - x_hat;
//   2. an ARMA model D xi_hat = C e of the noise estimate (arma_estimate:
//      Hannan-Rissanen, then Gauss-Newton prediction-error steps);
//   3. the prefilter: 1/F(p) in continuous time (exact ZOH/FOH filters of
//      refined_iv.hpp, App. A.1), then D(q^-1)/C(q^-1) on the sampled
//      filtered signals;
//   4. the IV solve Z^T Phi theta = Z^T p^n y_f (eqs. 2.10-2.12) with the
//      instruments from x_hat filtered the same way.
// With C = D = 1 this is SRIVC. The covariance is sigma_e^2 (sum zeta_f
// zeta_f^T)^-1 (eq. 2.13 with the innovation variance of the ARMA model),
// which is the asymptotic covariance when the noise model is right.
//
// Closed loop with a known continuous-time controller u = r1 + Nc/Dc (r -
// y) (CLRIVC; r1 the external signal at the plant input, r the setpoint,
// eq. 2.49b): the instruments come from the closed loop driven by them,
// x_hat = B (Nc r + Dc r1) / Acl and u_hat = F (Nc r + Dc r1) / Acl with
// Acl = F Dc + B Nc (eqs. 2.48-2.49), the noise estimate is still y - B/F
// u. Its covariance is the IV sandwich sigma_e^2 (Z^T Phi)^-1 Z^T Z
// (Phi^T Z)^-1 (Z, Phi the prefiltered instruments and regressors): equal
// to eq. 2.13's sigma_e^2 (Z^T Z)^-1 when Z is the noise-free part of Phi,
// and still right when the instruments come from another loop than the
// data's (r given at the wrong place, a controller off), where (Z^T Z)^-1
// is off by the instruments' scale.
//
// Two-stage closed loop (CL2SRIVC): SRIVC of the input's response to the
// reference, u = S(p) r, gives the noise-free input u_hat = S r; SRIVC of
// y on u_hat then gives the plant (the input noise, correlated with the
// output noise through the loop, is removed by the first stage).
//
// Time scaling as refined_iv.hpp: the iterations run in t' = sigma t with
// sigma the plant's characteristic frequency |F(0)|^(1/n).
#pragma once

#include <algorithm>
#include <cmath>
#include <complex>
#include <memory>
#include <string>
#include <vector>

#include "ctid/base/polynomial.hpp"
#include "ctid/offline/refined_iv.hpp"

namespace ctid {

// How the ARMA noise model is estimated (rivc's 'ArmaMethod'): by
// prediction error (Gauss-Newton) or by Young's IVARMA (ivarma_estimate).
enum class ArmaMethod { kPem, kIvarma };

template <typename S>
struct ArmaSettings {
  ArmaMethod method = ArmaMethod::kPem;
  int max_iterations = 50;  // Gauss-Newton (or IVARMA) iterations
  S tolerance = S(1e-8);    // relative decrease of the loss
  int long_ar_order = 0;    // Hannan-Rissanen's long AR; 0: automatic
  // A warm start [d1 .. d_nd, c1 .. c_nc] (e.g. the previous RIVC
  // iteration's model) in place of Hannan-Rissanen; empty: none.
  Vector<S> start;
};

template <typename S>
struct ArmaResult {
  Vector<S> c;                // [1 c1 .. c_nc], q^-1
  Vector<S> d;                // [1 d1 .. d_nd], q^-1
  Matrix<S> covariance;       // of [d1 .. d_nd, c1 .. c_nc]
  S innovation_variance = 0;  // mean of e^2
  int iterations = 0;
  bool converged = false;
};

namespace bj_detail {

// y = b(q^-1) / a(q^-1) x, a(0) = 1, at rest (direct form II transposed;
// the coefficients padded to one length so that the inner loop has no
// branches: this filter runs a few dozen times per RIVC iteration).
template <typename S>
void filter_dt(const Vector<S>& b, const Vector<S>& a, const S* x,
               Eigen::Index n, S* y) {
  const Eigen::Index m = std::max(b.size(), a.size());
  if (m <= 1) {
    const S g = b.size() > 0 ? b(0) : S(0);
    for (Eigen::Index k = 0; k < n; ++k) y[k] = g * x[k];
    return;
  }
  std::vector<S> bp(static_cast<std::size_t>(m), S(0));
  std::vector<S> ap(static_cast<std::size_t>(m), S(0));
  std::vector<S> z(static_cast<std::size_t>(m), S(0));
  for (Eigen::Index i = 0; i < b.size(); ++i) bp[i] = b(i);
  for (Eigen::Index i = 1; i < a.size(); ++i) ap[i] = a(i);
  const S b0 = bp[0];
  for (Eigen::Index k = 0; k < n; ++k) {
    const S xk = x[k];
    const S out = b0 * xk + z[0];
    for (Eigen::Index i = 1; i < m - 1; ++i) {
      z[i - 1] = bp[i] * xk - ap[i] * out + z[i];
    }
    z[m - 2] = bp[m - 1] * xk - ap[m - 1] * out;
    y[k] = out;
  }
}

template <typename S>
Vector<S> filter_dt(const Vector<S>& b, const Vector<S>& a,
                    const Vector<S>& x) {
  Vector<S> y(x.size());
  filter_dt(b, a, x.data(), x.size(), y.data());
  return y;
}

// Roots of the q^-1 polynomial [1 p1 .. pn] (as z-polynomial) inside the
// circle of radius `radius`: roots outside are reflected, 1/conj(z).
template <typename S>
Vector<S> reflect_into_circle(const Vector<S>& p, S radius,
                              bool* changed = nullptr) {
  if (changed) *changed = false;
  if (p.size() < 2) return p;
  std::vector<std::complex<S>> r = roots_descending<S>(p);
  bool any = false;
  for (auto& z : r) {
    const S m = std::abs(z);
    if (m >= radius) {
      z = (m > S(1) ? S(1) / std::conj(z) : z * (radius / m));
      if (std::abs(z) >= radius) z *= radius / std::abs(z) * S(0.999);
      any = true;
    }
  }
  if (changed) *changed = any;
  if (!any) return p;
  return real_monic_from_roots<S>(r);
}

template <typename S>
bool inside_circle(const Vector<S>& p, S radius) {
  for (const auto& z : roots_descending<S>(p)) {
    if (!(std::abs(z) < radius)) return false;
  }
  return true;
}

// Least squares x = argmin ||A x - b|| (column-pivoting QR); false if rank
// deficient.
template <typename S>
bool least_squares(const Matrix<S>& A, const Vector<S>& b, Vector<S>& x,
                   Matrix<S>* inverse_gram = nullptr) {
  const Eigen::ColPivHouseholderQR<Matrix<S>> qr(A);
  if (qr.rank() < A.cols()) return false;
  x = qr.solve(b);
  if (inverse_gram) {
    *inverse_gram = (A.transpose() * A)
                        .ldlt()
                        .solve(Matrix<S>::Identity(A.cols(), A.cols()));
  }
  return x.allFinite();
}

// The length and finiteness checks of an ARMA(nd, nc) noise record, shared
// by arma_estimate and ivarma_estimate (after their own order checks).
template <typename S>
Status noise_record_status(const S* xi, Eigen::Index n, int nd, int nc) {
  const int np = nd + nc;
  const Eigen::Index need = 10 * (np + 1) + 4 * (np + 10);
  if (n < need) {
    return bad_input("the noise record has " + std::to_string(n) +
                     " samples; ARMA(" + std::to_string(nd) + "," +
                     std::to_string(nc) + ") needs at least " +
                     std::to_string(need));
  }
  if (!Eigen::Map<const Vector<S>>(xi, n).allFinite()) {
    return bad_input("the noise record is not finite");
  }
  return Status::Ok();
}

// The monic D and C of the ARMA parameters p = [d_1 .. d_nd, c_1 .. c_nc].
template <typename S>
void arma_polynomials(const Vector<S>& p, int nd, int nc, Vector<S>& dpoly,
                      Vector<S>& cpoly) {
  dpoly.resize(nd + 1);
  cpoly.resize(nc + 1);
  dpoly(0) = cpoly(0) = 1;
  dpoly.tail(nd) = p.head(nd);
  cpoly.tail(nc) = p.tail(nc);
}

// The roots of D and C reflected into the circle of radius 0.999 (the
// ARMA estimators keep both minimum phase and stable).
template <typename S>
void project_arma(int nd, int nc, Vector<S>& p) {
  Vector<S> dpoly, cpoly;
  arma_polynomials<S>(p, nd, nc, dpoly, cpoly);
  dpoly = reflect_into_circle<S>(dpoly, S(0.999));
  cpoly = reflect_into_circle<S>(cpoly, S(0.999));
  p.head(nd) = dpoly.tail(nd);
  p.tail(nc) = cpoly.tail(nc);
}

}  // namespace bj_detail

// ARMA model D(q^-1) xi = C(q^-1) e of a sampled record xi (N samples),
// by prediction error: Hannan-Rissanen's start (a long AR model gives the
// innovations, then xi is regressed on its past and their past), then
// Gauss-Newton steps on sum e^2, e = D/C xi (filters at rest), with step
// halving and the roots of C and D kept inside the unit circle. The
// covariance is sigma_e^2 (J^T J)^-1 of the final Jacobian.
template <typename S>
Status ivarma_estimate(const S* xi, Eigen::Index n, int nd, int nc,
                       const ArmaSettings<S>& settings, ArmaResult<S>* result);

template <typename S>
Status arma_estimate(const S* xi, Eigen::Index n, int nd, int nc,
                     const ArmaSettings<S>& settings, ArmaResult<S>* result) {
  using namespace bj_detail;
  if (result == nullptr) return bad_input("arma_estimate: no result");
  if (settings.method == ArmaMethod::kIvarma && nc > 0) {
    return ivarma_estimate<S>(xi, n, nd, nc, settings, result);
  }
  if (xi == nullptr || n < 1) return bad_input("the noise record is empty");
  if (nd < 0 || nc < 0 || nd > 50 || nc > 50) {
    return bad_input("the ARMA orders nd, nc must be in 0..50");
  }
  const int np = nd + nc;
  const Status record = noise_record_status(xi, n, nd, nc);
  if (!record.ok()) return record;
  const Eigen::Map<const Vector<S>> x(xi, n);
  result->c = Vector<S>::Ones(1);
  result->d = Vector<S>::Ones(1);
  result->iterations = 0;
  result->converged = true;
  const S power = x.squaredNorm() / static_cast<S>(n);
  if (np == 0) {
    result->innovation_variance = power;
    result->covariance.resize(0, 0);
    return Status::Ok();
  }
  if (!(power > 0)) {
    // No noise at all (noise-free data at the true plant): white, C = D
    // = 1 with zero variance; the coefficients are not identifiable.
    result->c = Vector<S>::Zero(nc + 1);
    result->d = Vector<S>::Zero(nd + 1);
    result->c(0) = result->d(0) = 1;
    result->innovation_variance = 0;
    result->covariance = Matrix<S>::Zero(np, np);
    return Status::Ok();
  }

  // Regression of xi(t) on -xi(t-1..t-nd) and e(t-1..t-nc).
  auto regress = [&](const Vector<S>& e, Vector<S>& eta) -> bool {
    const Eigen::Index start = std::max(nd, nc);
    const Eigen::Index rows = n - start;
    Matrix<S> A(rows, np);
    for (Eigen::Index k = 0; k < rows; ++k) {
      const Eigen::Index t = k + start;
      for (int i = 1; i <= nd; ++i) A(k, i - 1) = -x(t - i);
      for (int i = 1; i <= nc; ++i) A(k, nd + i - 1) = e(t - i);
    }
    return least_squares<S>(A, x.tail(rows), eta);
  };

  Vector<S> eta(np);
  if (nc > 0 && settings.start.size() == np && settings.start.allFinite()) {
    eta = settings.start;
  } else if (nc == 0) {
    if (!regress(Vector<S>::Zero(n), eta)) {
      return numerical_failure("the AR regression is rank deficient");
    }
  } else {
    int L = settings.long_ar_order;
    if (L <= 0) {
      L = std::max(20, 3 * np + 10);
      L = static_cast<int>(std::min<Eigen::Index>(L, n / 10));
    }
    const Eigen::Index rows = n - L;
    Matrix<S> A(rows, L);
    for (Eigen::Index k = 0; k < rows; ++k) {
      for (int i = 1; i <= L; ++i) A(k, i - 1) = -x(k + L - i);
    }
    Vector<S> a;
    if (!least_squares<S>(A, x.tail(rows), a)) {
      return numerical_failure("the long AR regression is rank deficient");
    }
    Vector<S> ar(L + 1);
    ar(0) = 1;
    ar.tail(L) = a;
    const Vector<S> e = filter_dt<S>(ar, Vector<S>::Ones(1), Vector<S>(x));
    if (!regress(e, eta)) {
      return numerical_failure(
          "the Hannan-Rissanen regression is rank "
          "deficient");
    }
  }

  auto polys = [&](const Vector<S>& p, Vector<S>& dpoly, Vector<S>& cpoly) {
    arma_polynomials<S>(p, nd, nc, dpoly, cpoly);
  };
  auto project = [&](Vector<S>& p) { project_arma<S>(nd, nc, p); };
  auto loss = [&](const Vector<S>& p, Vector<S>& e) -> S {
    Vector<S> dpoly, cpoly;
    polys(p, dpoly, cpoly);
    e.resize(n);
    filter_dt<S>(dpoly, cpoly, xi, n, e.data());
    const S v = e.squaredNorm() / static_cast<S>(n);
    return std::isfinite(v) ? v : std::numeric_limits<S>::infinity();
  };
  project(eta);
  Vector<S> e;
  S v = loss(eta, e);
  Matrix<S> J(n, np);
  Vector<S> xc(n), ec(n);
  auto jacobian = [&](const Vector<S>& p, const Vector<S>& err) {
    Vector<S> dpoly, cpoly;
    polys(p, dpoly, cpoly);
    const Vector<S> one = Vector<S>::Ones(1);
    filter_dt<S>(one, cpoly, xi, n, xc.data());
    filter_dt<S>(one, cpoly, err.data(), n, ec.data());
    for (int i = 1; i <= nd; ++i) {
      J.col(i - 1).head(i).setZero();
      J.col(i - 1).tail(n - i) = xc.head(n - i);
    }
    for (int i = 1; i <= nc; ++i) {
      J.col(nd + i - 1).head(i).setZero();
      J.col(nd + i - 1).tail(n - i) = -ec.head(n - i);
    }
  };
  result->converged = nc == 0;  // AR: the LS solution is the minimum
  for (int it = 0; nc > 0 && it < settings.max_iterations; ++it) {
    jacobian(eta, e);
    // Gauss-Newton direction from the normal equations (np is small; the
    // step is checked by the loss below, so their conditioning only
    // matters for a rank-deficient J, refused here).
    const Matrix<S> gram = J.transpose() * J;
    const Eigen::LDLT<Matrix<S>> ldlt(gram);
    const auto pivots = ldlt.vectorD();
    if (ldlt.info() != Eigen::Success ||
        !(pivots.minCoeff() > std::numeric_limits<S>::epsilon() * S(np) *
                                  pivots.cwiseAbs().maxCoeff())) {
      return numerical_failure(
          "the ARMA Gauss-Newton step is rank deficient "
          "(ARMA orders too high for the noise?)");
    }
    const Vector<S> step = ldlt.solve(J.transpose() * e);
    S alpha = 1;
    bool improved = false;
    Vector<S> trial, e_trial;
    S v_trial = v;
    for (int h = 0; h < 20; ++h, alpha /= 2) {
      trial = eta - alpha * step;
      project(trial);
      v_trial = loss(trial, e_trial);
      if (v_trial < v) {
        improved = true;
        break;
      }
    }
    result->iterations = it + 1;
    if (!improved) {
      result->converged = true;  // no descent: a (local) minimum
      break;
    }
    const S decrease = (v - v_trial) / v;
    eta = trial;
    v = v_trial;
    e.swap(e_trial);
    if (decrease < settings.tolerance) {
      result->converged = true;
      break;
    }
  }
  jacobian(eta, e);
  const Matrix<S> gram = J.transpose() * J;
  const Eigen::LDLT<Matrix<S>> ldlt(gram);
  result->covariance = v * ldlt.solve(Matrix<S>::Identity(np, np));
  polys(eta, result->d, result->c);
  result->innovation_variance = v;
  if (!result->covariance.allFinite()) {
    return numerical_failure("the ARMA covariance is not finite");
  }
  return Status::Ok();
}

// IVARMA: Young's instrumental-variable estimation of the ARMA noise model
// (P. C. Young, "The refined instrumental variable method: unified
// estimation of discrete and continuous-time transfer function models",
// J. Europeen des Systemes Automatises 42, 2008, 149-179; Young,
// "Recursive Estimation and Time-Series Analysis", 2nd ed., Springer
// 2011: the IVARMA algorithm of the RIVBJ/RIVCBJ noise model). The ARMA
// model D xi = C e is the pseudo-linear regression
//   xi(k) = phi(k)^T eta + e(k),
//   phi(k) = [-xi(k-1) .. -xi(k-nd), e_hat(k-1) .. e_hat(k-nc)],
// eta = [d c], with the innovation estimate e_hat = D_j/C_j xi of the
// previous iterate (the first from Hannan-Rissanen's long AR). Each
// iteration solves it by IV with the refined instruments zeta(k) =
// phi(k) / C_j(q^-1) (the prefilter 1/C of the refined IV; they are the
// negative gradient of the prediction error D/C xi):
//   eta_(j+1) = (sum zeta phi^T)^-1 sum zeta xi.
// Since xi - phi^T eta_j = e_hat exactly, eta_(j+1) = eta_j + (sum zeta
// phi^T)^-1 sum zeta e_hat: a fixed point satisfies the prediction-error
// score equation sum zeta e_hat = 0, so IVARMA and PEM share their
// asymptotic distribution (the estimator's covariance is sigma_e^2 (sum
// zeta zeta^T)^-1, evaluated at the fixed point). The roots of C and D are
// kept inside the unit circle (reflected, as in arma_estimate).
template <typename S>
Status ivarma_estimate(const S* xi, Eigen::Index n, int nd, int nc,
                       const ArmaSettings<S>& settings, ArmaResult<S>* result) {
  using namespace bj_detail;
  if (result == nullptr) return bad_input("ivarma_estimate: no result");
  if (xi == nullptr || n < 1) return bad_input("the noise record is empty");
  if (nd < 0 || nc < 1 || nd > 50 || nc > 50) {
    return bad_input("IVARMA needs nd in 0..50 and nc in 1..50");
  }
  const int np = nd + nc;
  const Status record = noise_record_status(xi, n, nd, nc);
  if (!record.ok()) return record;
  const Eigen::Map<const Vector<S>> x(xi, n);
  if (!(x.squaredNorm() > 0) || settings.max_iterations < 1) {
    // No noise (white, zero variance) or no iteration asked for
    // (Hannan-Rissanen's estimate): as arma_estimate.
    ArmaSettings<S> pem = settings;
    pem.method = ArmaMethod::kPem;
    return arma_estimate<S>(xi, n, nd, nc, pem, result);
  }
  // The start: Hannan-Rissanen (arma_estimate without Gauss-Newton steps)
  // or the caller's warm start.
  Vector<S> eta(np);
  if (settings.start.size() == np && settings.start.allFinite()) {
    eta = settings.start;
  } else {
    ArmaSettings<S> hr;
    hr.max_iterations = 0;
    hr.long_ar_order = settings.long_ar_order;
    ArmaResult<S> start;
    Status status = arma_estimate<S>(xi, n, nd, nc, hr, &start);
    if (!status.ok()) return status;
    eta << start.d.tail(nd), start.c.tail(nc);
  }
  auto polys = [&](const Vector<S>& p, Vector<S>& dpoly, Vector<S>& cpoly) {
    arma_polynomials<S>(p, nd, nc, dpoly, cpoly);
  };
  auto project = [&](Vector<S>& p) { project_arma<S>(nd, nc, p); };
  project(eta);
  Matrix<S> Phi(n, np), Z(n, np);
  Vector<S> e(n), col(n);
  const Vector<S> one = Vector<S>::Ones(1);
  // phi and zeta = phi / C at eta; e = D/C xi.
  auto build = [&](const Vector<S>& p) {
    Vector<S> dpoly, cpoly;
    polys(p, dpoly, cpoly);
    filter_dt<S>(dpoly, cpoly, xi, n, e.data());
    for (int i = 1; i <= nd; ++i) {
      Phi.col(i - 1).head(i).setZero();
      Phi.col(i - 1).tail(n - i) = -x.head(n - i);
    }
    for (int i = 1; i <= nc; ++i) {
      Phi.col(nd + i - 1).head(i).setZero();
      Phi.col(nd + i - 1).tail(n - i) = e.head(n - i);
    }
    for (int i = 0; i < np; ++i) {
      col = Phi.col(i);
      filter_dt<S>(one, cpoly, col.data(), n, Z.col(i).data());
    }
  };
  result->converged = false;
  result->iterations = 0;
  for (int it = 0; it < settings.max_iterations; ++it) {
    build(eta);
    const Matrix<S> zphi = Z.transpose() * Phi;
    const Eigen::FullPivLU<Matrix<S>> lu(zphi);
    if (!lu.isInvertible() || !zphi.allFinite()) {
      // A noise estimate that the current ARMA model predicts (almost)
      // exactly, e.g. the deterministic misfit of an early RIVC iterate on
      // noise-free data: no IV step; the current model is kept (not
      // converged), as a Gauss-Newton step without descent would be.
      break;
    }
    Vector<S> next = lu.solve(Z.transpose() * x);
    project(next);
    const S change = (next - eta).norm() / std::max(next.norm(), S(1));
    eta = next;
    result->iterations = it + 1;
    if (change < settings.tolerance) {
      result->converged = true;
      break;
    }
  }
  build(eta);
  const S v = e.squaredNorm() / static_cast<S>(n);
  const Matrix<S> gram = Z.transpose() * Z;
  // A pseudo-inverse: the directions a (near-)deterministic noise estimate
  // does not determine get no variance instead of an infinite one.
  const Eigen::CompleteOrthogonalDecomposition<Matrix<S>> cod(gram);
  result->covariance = v * cod.pseudoInverse();
  polys(eta, result->d, result->c);
  result->innovation_variance = v;
  if (!result->covariance.allFinite() || !std::isfinite(v)) {
    return numerical_failure("the IVARMA covariance is not finite");
  }
  return Status::Ok();
}

template <typename S>
struct RivcProblem {
  int nb = 1;   // B(p) = b_0 p^(nb-1) + .. + b_(nb-1)
  int nc = 0;   // C(q^-1) = 1 + c1 q^-1 + .. (noise numerator)
  int nd = 0;   // D(q^-1) = 1 + d1 q^-1 + .. (noise denominator)
  int nf = 1;   // F(p) = p^nf + f1 p^(nf-1) + .. + f_nf
  int nk = 0;   // input delay in samples
  S delay = 0;  // continuous delay on top of nk (time units, >= 0)
  InterSample u_rule = InterSample::kZoh;
  // Closed loop u = r1 + Nc(p) / Dc(p) (r - y) (descending powers of p);
  // empty Nc: open loop. The setpoint r and the plant-input signal r1 (N
  // samples each, ZOH; r1 nullptr: 0).
  Vector<S> controller_num, controller_den;
  const S* reference = nullptr;
  const S* r1 = nullptr;
  bool closed_loop() const { return controller_num.size() > 0; }
  int num_parameters() const { return nf + nb; }
};

template <typename S>
struct RivcSettings {
  S tolerance = S(1e-6);  // on ||theta_i - theta_(i-1)|| / ||theta_i||, t'
  int max_iterations = 30;
  Vector<S> theta_init;  // [f b], original time; empty: the SRIVC start
  RivSettings<S> start;  // the SRIVC (or CLSRIVC) start's settings
  ArmaSettings<S> arma;
};

template <typename S>
struct RivcResult {
  Vector<S> theta;  // [f1 .. f_nf, b_0 .. b_(nb-1)], original time
  // sigma_e^2 (sum zeta_f zeta_f^T)^-1, eq. 2.13 (closed loop: the IV
  // sandwich, see the header comment)
  Matrix<S> covariance;
  ArmaResult<S> noise;        // C, D, innovation variance, their covariance
  Vector<S> start_theta;      // the SRIVC start
  S simulation_variance = 0;  // ||y - x_hat||^2 / (N - np)
  S condition = 0;
  int iterations = 0;
  bool converged = false;
  bool stable = false;
  std::string reason;
  Vector<S> simulated;  // x_hat = B/F u at the samples
};

template <typename S>
struct RivcData {
  const S* y = nullptr;
  const S* u = nullptr;
  Eigen::Index num_samples = 0;
  S ts = 0;  // regular sampling only (the noise model is discrete)
};

namespace bj_detail {

// theta' = scale .* theta for t' = sigma t: f_i' = f_i / sigma^i,
// b_j' = b_j sigma^(pow_j - n) (pow_j the power of p of b_j).
template <typename S>
Vector<S> scale_factors(int nf, int nb, S sigma) {
  Vector<S> d(nf + nb);
  for (int i = 1; i <= nf; ++i) d(i - 1) = std::pow(sigma, S(-i));
  for (int j = 0; j < nb; ++j) {
    const int pow = nb - 1 - j;
    d(nf + j) = std::pow(sigma, S(pow - nf));
  }
  return d;
}

template <typename S>
Status validate(const RivcProblem<S>& problem, const RivcData<S>& data) {
  if (data.y == nullptr || data.u == nullptr) {
    return bad_input("y and u are required");
  }
  if (problem.nf < 1 || problem.nf > 20) {
    return bad_input("nf must be in 1..20, got " + std::to_string(problem.nf));
  }
  if (problem.nb < 1 || problem.nb > problem.nf + 1) {
    return bad_input("nb must be in 1..nf+1 (a proper plant), got " +
                     std::to_string(problem.nb));
  }
  if (problem.nc < 0 || problem.nd < 0 || problem.nc > 20 || problem.nd > 20) {
    return bad_input("nc and nd must be in 0..20");
  }
  if (!(data.ts > 0) || !std::isfinite(data.ts)) {
    return bad_input(
        "the sampling interval must be finite and > 0 (RIVC "
        "needs regularly sampled data)");
  }
  const Eigen::Index n = data.num_samples;
  const int np = problem.num_parameters() + problem.nc + problem.nd;
  if (problem.nk < 0 || problem.nk >= n / 2) {
    return bad_input("nk must be in 0..N/2 (" + std::to_string(n / 2) +
                     "), got " + std::to_string(problem.nk));
  }
  if (!(problem.delay >= 0) || !std::isfinite(problem.delay) ||
      problem.delay + problem.nk * data.ts >= S(0.5) * n * data.ts) {
    return bad_input("the delay must be >= 0 and below half the record");
  }
  if (n < 10 * (np + 1) + 4 * (problem.nc + problem.nd + 10)) {
    return bad_input("too few samples (" + std::to_string(n) + ") for " +
                     std::to_string(np) + " parameters");
  }
  const Eigen::Map<const Vector<S>> y(data.y, n), u(data.u, n);
  if (!y.allFinite() || !u.allFinite()) {
    return bad_input("y and u must be finite");
  }
  if (problem.closed_loop()) {
    if (problem.reference == nullptr) {
      return bad_input("a closed loop needs the reference r");
    }
    if (problem.controller_den.size() < 1 ||
        problem.controller_num.size() > problem.controller_den.size() ||
        problem.controller_den(0) == S(0) ||
        !problem.controller_num.allFinite() ||
        !problem.controller_den.allFinite()) {
      return bad_input(
          "the controller must be proper with finite "
          "coefficients and a non-zero leading denominator");
    }
    if (problem.nk != 0 || problem.delay != 0) {
      return bad_input("the closed loop takes no input delay (nk = 0)");
    }
    if (!Eigen::Map<const Vector<S>>(problem.reference, n).allFinite() ||
        (problem.r1 != nullptr &&
         !Eigen::Map<const Vector<S>>(problem.r1, n).allFinite())) {
      return bad_input("the reference r must be finite");
    }
  }
  return Status::Ok();
}

// The RIVC iteration in the scaled time t' = sigma t.
template <typename S>
class BjIteration {
 public:
  BjIteration(const RivcProblem<S>& problem, const RivcData<S>& data, S sigma)
      : problem_(problem), n_(data.num_samples), sigma_(sigma) {
    clock_.ts = data.ts;
    clock_.n = n_;
    clock_.sigma = sigma;
    y_ = Eigen::Map<const Vector<S>>(data.y, n_);
    u_ = Vector<S>::Zero(n_);
    for (Eigen::Index k = problem.nk; k < n_; ++k) {
      u_(k) = data.u[k - problem.nk];
    }
    if (problem.closed_loop()) {
      r_ = Eigen::Map<const Vector<S>>(problem.reference, n_);
      if (problem.r1 != nullptr) {
        r1_ = Eigen::Map<const Vector<S>>(problem.r1, n_);
      }
    }
  }

  // p'^i s / D', i = 0..order, s the (delayed) input.
  void filter_input(const Vector<S>& d, Matrix<S>& out) const {
    if (problem_.delay > 0) {
      riv_detail::filter_delayed_derivatives<S>(
          d, S(1), problem_.u_rule, clock_, u_.data(), problem_.delay, out);
    } else {
      riv_detail::filter_derivatives<S>(d, S(1), problem_.u_rule, clock_,
                                        u_.data(), out);
    }
  }

  // x_hat = B/F u at the samples (theta scaled).
  Vector<S> simulate(const Vector<S>& theta) const {
    const int nf = problem_.nf, nb = problem_.nb;
    Matrix<S> U;
    filter_input(theta.head(nf), U);
    Vector<S> x = Vector<S>::Zero(n_);
    for (int j = 0; j < nb; ++j) x += theta(nf + j) * U.col(nb - 1 - j);
    return x;
  }

  // One RIVC step from theta (scaled): the new IV solution, the noise
  // model of y - x_hat, (Z^T Z)^-1 in `inverse_gram` (closed loop: the
  // sandwich (Z^T Phi)^-1 Z^T Z (Phi^T Z)^-1, see the header comment).
  Status step(const Vector<S>& theta, const ArmaSettings<S>& arma_settings,
              bool refined, Vector<S>& next, Matrix<S>& inverse_gram,
              ArmaResult<S>& arma, Vector<S>& x_hat, S& condition) const {
    const int nf = problem_.nf, nb = problem_.nb;
    const Vector<S> f = theta.head(nf);
    const Vector<S> b = theta.tail(nb);
    Vector<S> fpoly(nf + 1);
    fpoly(0) = 1;
    fpoly.tail(nf) = f;
    // p'^m u / F^2, m = 0..2 nf: x_hat and its prefiltered derivatives.
    const Vector<S> f2 = convolve<S>(fpoly, fpoly);
    // The large signal matrices are members, reused from one iteration to
    // the next (no fresh pages per iteration).
    Matrix<S>& U2 = u2_;
    Matrix<S>& U1 = u1_;
    filter_input(f2.tail(2 * nf), U2);
    filter_input(f, U1);
    x_hat = Vector<S>::Zero(n_);
    for (int j = 0; j < nb; ++j) x_hat += b(j) * U1.col(nb - 1 - j);
    Matrix<S>& Xf = xf_;  // p'^i x_hat / F
    Xf.setZero(n_, nf + 1);
    for (int i = 0; i <= nf; ++i) {
      for (int j = 0; j < nb; ++j) {
        Xf.col(i) += b(j) * U2.col(nb - 1 - j + i);
      }
    }
    const Vector<S> xi = y_ - x_hat;
    // p'^i y / F = p'^i x_hat / F + p'^i xi / F (xi linear between
    // samples): exact where the model fits, as refined_iv.hpp does.
    Matrix<S>& Yf = yf_;
    riv_detail::filter_derivatives<S>(f, S(1), InterSample::kFoh, clock_,
                                      xi.data(), Yf);
    Yf += Xf;

    // Instruments: closed loop, from the loop driven by r.
    const Matrix<S>* Zx = &Xf;
    const Matrix<S>* Zu = &U1;
    Matrix<S> loop_x, loop_u;
    if (problem_.closed_loop()) {
      Status s = closed_loop_instruments(fpoly, b, loop_x, loop_u);
      if (!s.ok()) return s;
      Zx = &loop_x;
      Zu = &loop_u;
    }

    const int np = nf + nb;
    Matrix<S>& Phi = phi_;
    Matrix<S>& Z = z_;
    Phi.resize(n_, np);
    Z.resize(n_, np);
    for (int i = 0; i < nf; ++i) {
      Phi.col(i) = -Yf.col(nf - 1 - i);
      Z.col(i) = -Zx->col(nf - 1 - i);
    }
    for (int j = 0; j < nb; ++j) {
      Phi.col(nf + j) = U1.col(nb - 1 - j);
      Z.col(nf + j) = Zu->col(nb - 1 - j);
    }
    Vector<S>& target = target_;
    target = Yf.col(nf);

    if (refined) {
      Status s = arma_estimate<S>(xi.data(), n_, problem_.nd, problem_.nc,
                                  arma_settings, &arma);
      if (!s.ok()) {
        return Status(s.code(), "the noise model: " + s.message());
      }
      if (arma.c.size() > 1 || arma.d.size() > 1) {
        // The discrete part of the prefilter, D / C (eq. 2.9's 1/H).
        // (In place: the direct form reads x_k before it writes y_k.)
        for (int i = 0; i < np; ++i) {
          filter_dt<S>(arma.d, arma.c, Phi.col(i).data(), n_,
                       Phi.col(i).data());
          filter_dt<S>(arma.d, arma.c, Z.col(i).data(), n_, Z.col(i).data());
        }
        filter_dt<S>(arma.d, arma.c, target.data(), n_, target.data());
      }
    }
    offline_iv_detail::IvSolution<S> solution;
    Status s = riv_detail::solve_equilibrated<S>(
        Z, Phi, target, "RIVC instrument", solution, condition);
    if (!s.ok()) return s;
    next = solution.theta;
    inverse_gram =
        problem_.closed_loop() ? solution.sandwich : solution.inverse_gram;
    return Status::Ok();
  }

 private:
  // p'^i x_hat / F and p'^i u_hat / F from x_hat = B (Nc r + Dc r1) /
  // Acl, u_hat = F (Nc r + Dc r1) / Acl, Acl = F Dc + B Nc (scaled time;
  // eqs. 2.48-2.49b). A zero signal is not filtered.
  Status closed_loop_instruments(const Vector<S>& fpoly, const Vector<S>& b,
                                 Matrix<S>& Zx, Matrix<S>& Zu) const {
    const int nf = problem_.nf, nb = problem_.nb;
    Vector<S> nc = problem_.controller_num, dc = problem_.controller_den;
    for (Eigen::Index k = 0; k < nc.size(); ++k) {
      nc(k) *= std::pow(sigma_, S(nc.size() - 1 - k));
    }
    for (Eigen::Index k = 0; k < dc.size(); ++k) {
      dc(k) *= std::pow(sigma_, S(dc.size() - 1 - k));
    }
    const Vector<S> bnc = convolve<S>(b, nc);
    Vector<S> acl = convolve<S>(fpoly, dc);
    acl.tail(bnc.size()) += bnc;
    const S lead = acl(0);
    if (!(std::abs(lead) > 0)) {
      return numerical_failure("the closed loop F Dc + B Nc is improper");
    }
    acl /= lead;
    HurwitzTest<S> hurwitz(static_cast<int>(acl.size() - 1));
    if (!hurwitz.is_stable(acl.tail(acl.size() - 1))) {
      return numerical_failure(
          "the closed loop F Dc + B Nc of the current estimate is unstable");
    }
    const Vector<S> den = convolve<S>(acl, fpoly);  // monic, order nf + ncl
    Matrix<S> R;
    // sum_k num_k p'^(k + i) s / (Acl F), num in descending powers.
    auto apply = [&](const Vector<S>& num, int count, Matrix<S>& out) {
      const int deg = static_cast<int>(num.size()) - 1;
      for (int i = 0; i < count; ++i) {
        for (int k = 0; k <= deg; ++k) {
          const int col = deg - k + i;
          if (col < R.cols()) out.col(i) += num(k) * R.col(col);
        }
      }
    };
    Zx = Matrix<S>::Zero(n_, nf + 1);
    Zu = Matrix<S>::Zero(n_, nb);
    if (!r_.isZero(0)) {
      riv_detail::filter_derivatives<S>(den.tail(den.size() - 1), S(1) / lead,
                                        InterSample::kZoh, clock_, r_.data(),
                                        R);
      apply(bnc, nf + 1, Zx);
      apply(convolve<S>(fpoly, nc), nb, Zu);
    }
    if (r1_.size() > 0 && !r1_.isZero(0)) {
      riv_detail::filter_derivatives<S>(den.tail(den.size() - 1), S(1) / lead,
                                        InterSample::kZoh, clock_, r1_.data(),
                                        R);
      apply(convolve<S>(b, dc), nf + 1, Zx);
      apply(convolve<S>(fpoly, dc), nb, Zu);
    }
    return Status::Ok();
  }

  const RivcProblem<S>& problem_;
  Eigen::Index n_;
  S sigma_;
  riv_detail::Clock<S> clock_;
  Vector<S> y_, u_, r_, r1_;
  mutable Matrix<S> u1_, u2_, xf_, yf_, phi_, z_;
  mutable Vector<S> target_;

 public:
  // The last step's prefiltered instruments Z, regressors Phi and target
  // (scaled time; the two-stage covariance of cl2srivc reads them).
  const Matrix<S>& instruments() const { return z_; }
  const Matrix<S>& regressors() const { return phi_; }
  const Vector<S>& target() const { return target_; }
  // B/F s at the samples for a sampled signal s linear between samples
  // (theta scaled).
  Vector<S> simulate_signal(const Vector<S>& theta, const S* s) const {
    const int nf = problem_.nf, nb = problem_.nb;
    Matrix<S> X;
    riv_detail::filter_derivatives<S>(theta.head(nf), S(1), InterSample::kFoh,
                                      clock_, s, X);
    Vector<S> x = Vector<S>::Zero(n_);
    for (int j = 0; j < nb; ++j) x += theta(nf + j) * X.col(nb - 1 - j);
    return x;
  }
};

// One Box-Jenkins refined-IV iteration of [f b] (scaled time), shared by
// rivc and each input of rivc_miso: the RIVC step from theta, the ARMA
// noise model of this step kept as the next step's Gauss-Newton start
// (the noise estimate changes little between iterations), then F kept
// stable by step halving toward theta (the previous, stable iterate).
// what names the iterate in the instability message.
template <typename S>
Status stable_bj_step(BjIteration<S>& iteration, const Vector<S>& theta, int nf,
                      int nd, int nc, HurwitzTest<S>& hurwitz,
                      const std::string& what, ArmaSettings<S>& arma_settings,
                      Vector<S>& next, Matrix<S>& inverse_gram,
                      ArmaResult<S>& arma, Vector<S>& x_hat, S& condition) {
  const Status status = iteration.step(theta, arma_settings, true, next,
                                       inverse_gram, arma, x_hat, condition);
  if (!status.ok()) return status;
  if (nc > 0) {
    arma_settings.start.resize(nd + nc);
    arma_settings.start << arma.d.tail(nd), arma.c.tail(nc);
  }
  int halvings = 0;
  while (!hurwitz.is_stable(next.head(nf)) && halvings < 30) {
    next = theta + S(0.5) * (next - theta);
    ++halvings;
  }
  if (!hurwitz.is_stable(next.head(nf))) {
    return numerical_failure(what + " is unstable");
  }
  return Status::Ok();
}

// The iterations' start [f b] in original time, shared by rivc and
// rivc_miso: settings.theta_init when given (np finite entries, in the
// order `layout`), else the SRIVC (CLSRIVC with a controller) fit of
// make_start()'s problem to the record, kept when it did not converge.
template <typename S, typename Record, typename MakeStart>
Status srivc_start(const RivcSettings<S>& settings, const Record& data, int np,
                   const std::string& layout, MakeStart make_start,
                   Vector<S>* theta0) {
  *theta0 = settings.theta_init;
  if (theta0->size() == 0) {
    return refined_iv_start<S>(make_start(), settings.start,
                               {data.y, data.u, data.num_samples, data.ts},
                               "the SRIVC start", theta0);
  }
  if (theta0->size() != np || !theta0->allFinite()) {
    return bad_input("theta_init needs " + std::to_string(np) +
                     " finite entries " + layout);
  }
  return Status::Ok();
}

// The time scale sigma = |F(0)|^(1/nf) of a start with F(0) = f_nf, or
// 1 / Ts when that is not a positive number.
template <typename S>
S start_time_scale(S f_nf, int nf, S ts) {
  S sigma = std::pow(std::abs(f_nf), S(1) / nf);
  if (!(sigma > 0) || !std::isfinite(sigma)) sigma = S(1) / ts;
  return sigma;
}

// The end of rivc and rivc_miso, once result->simulated holds x_hat: the
// simulation-error variance ||y - x_hat||^2 / (N - np), and kNotConverged
// when the iterations stopped at max_iterations.
template <typename S>
Status rivc_outcome(const S* y_data, Eigen::Index n, int np, int max_iterations,
                    RivcResult<S>* result) {
  const Eigen::Map<const Vector<S>> y(y_data, n);
  result->simulation_variance =
      (y - result->simulated).squaredNorm() / static_cast<S>(n - np);
  result->stable = true;
  if (!result->converged) {
    return Status(ErrorCode::kNotConverged, "RIVC did not converge in " +
                                                std::to_string(max_iterations) +
                                                " iterations");
  }
  return Status::Ok();
}

}  // namespace bj_detail

// RIVC / CLRIVC: see the header comment. Returns kNotConverged (result
// filled with the last iterate, converged = false) after max_iterations.
template <typename S>
Status rivc(const RivcProblem<S>& problem, const RivcSettings<S>& settings,
            const RivcData<S>& data, RivcResult<S>* result) {
  using namespace bj_detail;
  if (result == nullptr) return bad_input("rivc: no result");
  Status status = validate(problem, data);
  if (!status.ok()) return status;
  if (!(settings.tolerance > 0) || settings.max_iterations < 1) {
    return Status(ErrorCode::kBadOption, "tol must be > 0 and maxiter >= 1");
  }
  const int nf = problem.nf, nb = problem.nb, np = nf + nb;
  const Eigen::Index n = data.num_samples;

  // The start: SRIVC (CLSRIVC with the controller) of the plant.
  Vector<S> theta0;
  status = srivc_start(
      settings, data, np, "[f b]",
      [&] {
        RivProblem<S> start;
        start.nf = {nf};
        RivChannel c;
        c.nb = nb;
        c.nk = problem.nk;
        c.rule = problem.u_rule;
        c.delay = static_cast<double>(problem.delay);
        start.channels.push_back(c);
        if (problem.closed_loop()) {
          start.controller_num = problem.controller_num;
          start.controller_den = problem.controller_den;
          start.reference = problem.reference;
          start.r1 = problem.r1;
        }
        return start;
      },
      &theta0);
  if (!status.ok()) return status;
  result->start_theta = theta0;
  HurwitzTest<S> hurwitz(nf);
  if (!hurwitz.is_stable(theta0.head(nf))) {
    return numerical_failure(
        "the start model is unstable: no stable prefilter 1/F");
  }
  const S sigma = start_time_scale(theta0(nf - 1), nf, data.ts);
  const Vector<S> scale = scale_factors<S>(nf, nb, sigma);
  BjIteration<S> iteration(problem, data, sigma);

  Vector<S> theta = theta0.cwiseProduct(scale);
  Vector<S> next;
  Matrix<S> inverse_gram;
  ArmaResult<S> arma;
  Vector<S> x_hat;
  S condition = 0;
  result->converged = false;
  result->reason = "maximum number of iterations reached";
  int it = 0;
  // The noise model of each iteration starts Gauss-Newton from the
  // previous one (the noise estimate changes little between iterations).
  ArmaSettings<S> arma_settings = settings.arma;
  for (; it < settings.max_iterations; ++it) {
    status = stable_bj_step(iteration, theta, nf, problem.nd, problem.nc,
                            hurwitz, "the RIVC iterate", arma_settings, next,
                            inverse_gram, arma, x_hat, condition);
    if (!status.ok()) return status;
    const S change = (next - theta).norm() / next.norm();
    theta = next;
    if (change < settings.tolerance) {
      result->converged = true;
      result->reason = "relative change below tol";
      ++it;
      break;
    }
  }
  result->iterations = it;
  // The noise model, covariance and fit at the final estimate.
  status = iteration.step(theta, arma_settings, true, next, inverse_gram, arma,
                          x_hat, condition);
  if (!status.ok()) return status;
  result->noise = arma;
  result->condition = condition;
  const Vector<S> inv = scale.cwiseInverse();
  result->theta = theta.cwiseProduct(inv);
  result->covariance = arma.innovation_variance *
                       (inv.asDiagonal() * inverse_gram * inv.asDiagonal());
  result->simulated = iteration.simulate(theta);
  return rivc_outcome(data.y, n, np, settings.max_iterations, result);
}

// Multi-input RIVC (CONTSID's rivc on MISO data, nn = [nb_1..nb_m nc nd
// nf_1..nf_m nk_1..nk_m], one denominator per input: CONTSID's
// 'Different'):
//
//   y(t_k) = sum_i B_i(p) / F_i(p) u_i(t_k - nk_i Ts) + C/D e(t_k).
//
// Young and Garnier's MISO refined IV (Garnier and Young, "The advantages
// of directly identifying continuous-time transfer function models in
// practical applications", Int. J. Control 87(7), 2014, sec. 3; Young,
// "Recursive Estimation and Time-Series Analysis", 2nd ed. 2011, ch. 7,
// the MISO RIV with different denominators) by backfitting: for input i
// the partial target y_i = y - sum_(j != i) x_hat_j carries the other
// inputs' auxiliary model outputs, and one RIVC step of the SISO
// iteration (the prefilter D / (C F_i), instruments from x_hat_i, the
// ARMA model of the common residual xi = y - sum_j x_hat_j) updates
// [f_i b_i]. The covariance is sigma_e^2 (sum zeta_f zeta_f^T)^-1 (eq.
// 2.13) with zeta_f the instruments of all inputs stacked, so the
// cross-input blocks are included.
struct RivcInput {
  int nb = 1;  // B_i(p) = b_0 p^(nb-1) + .. + b_(nb-1)
  int nf = 1;  // F_i(p) = p^nf + f1 p^(nf-1) + .. + f_nf
  int nk = 0;  // delay in samples
};

template <typename S>
struct RivcMisoProblem {
  std::vector<RivcInput> inputs;
  int nc = 0;
  int nd = 0;
  InterSample u_rule = InterSample::kZoh;
  int num_parameters() const {
    int n = 0;
    for (const RivcInput& i : inputs) n += i.nb + i.nf;
    return n;
  }
};

template <typename S>
struct RivcMisoData {
  const S* y = nullptr;
  const S* u = nullptr;  // N x m, column-major
  Eigen::Index num_samples = 0;
  S ts = 0;
};

// theta (result and settings.theta_init): [f_1 .. f_m, b_1 .. b_m], the
// order of the MISO SRIVC engine (refined_iv) and of CONTSID's theta.
template <typename S>
Status rivc_miso(const RivcMisoProblem<S>& problem,
                 const RivcSettings<S>& settings, const RivcMisoData<S>& data,
                 RivcResult<S>* result) {
  using namespace bj_detail;
  if (result == nullptr) return bad_input("rivc: no result");
  const int m = static_cast<int>(problem.inputs.size());
  if (m < 1 || m > 50) return bad_input("rivc: 1..50 inputs");
  if (data.u == nullptr || data.y == nullptr) {
    return bad_input("y and u are required");
  }
  if (!(settings.tolerance > 0) || settings.max_iterations < 1) {
    return Status(ErrorCode::kBadOption, "tol must be > 0 and maxiter >= 1");
  }
  const Eigen::Index n = data.num_samples;
  // Each input's SISO problem, checked by the SISO validation (orders,
  // delays, record length with all the parameters counted).
  std::vector<RivcProblem<S>> sub(m);
  std::vector<int> f_at(m), b_at(m);
  int nf_total = 0;
  for (int i = 0; i < m; ++i) nf_total += problem.inputs[i].nf;
  for (int i = 0, fa = 0, ba = nf_total; i < m; ++i) {
    const RivcInput& in = problem.inputs[i];
    sub[i].nb = in.nb;
    sub[i].nf = in.nf;
    sub[i].nk = in.nk;
    sub[i].nc = problem.nc;
    sub[i].nd = problem.nd;
    sub[i].u_rule = problem.u_rule;
    const RivcData<S> d{data.y, data.u + i * n, n, data.ts};
    Status status = validate(sub[i], d);
    if (!status.ok()) {
      return Status(status.code(),
                    "input " + std::to_string(i + 1) + ": " + status.message());
    }
    f_at[i] = fa;
    b_at[i] = ba;
    fa += in.nf;
    ba += in.nb;
  }
  const int np = problem.num_parameters();
  if (n < 10 * (np + problem.nc + problem.nd + 1) +
              4 * (problem.nc + problem.nd + 10)) {
    return bad_input("too few samples (" + std::to_string(n) + ") for " +
                     std::to_string(np) + " plant parameters");
  }

  // The start: MISO SRIVC with one denominator per input.
  Vector<S> theta0;
  const Status start_status = srivc_start(
      settings, data, np, "[f_1 .. f_m b_1 .. b_m]",
      [&] {
        RivProblem<S> start;
        for (int i = 0; i < m; ++i) {
          start.nf.push_back(problem.inputs[i].nf);
          RivChannel c;
          c.group = i;
          c.nb = problem.inputs[i].nb;
          c.nk = problem.inputs[i].nk;
          c.rule = problem.u_rule;
          start.channels.push_back(c);
        }
        return start;
      },
      &theta0);
  if (!start_status.ok()) return start_status;
  result->start_theta = theta0;

  // Per input: [f_i b_i] in its own scaled time (sigma_i = |F_i(0)|^(1/nf_i)).
  std::vector<Vector<S>> th(m), scale(m);
  std::vector<S> sigma(m);
  std::vector<HurwitzTest<S>> hurwitz;
  for (int i = 0; i < m; ++i) {
    const int nf = problem.inputs[i].nf, nb = problem.inputs[i].nb;
    Vector<S> t(nf + nb);
    t << theta0.segment(f_at[i], nf), theta0.segment(b_at[i], nb);
    hurwitz.emplace_back(nf);
    if (!hurwitz[i].is_stable(t.head(nf))) {
      return numerical_failure("the start model of input " +
                               std::to_string(i + 1) +
                               " is unstable: no stable prefilter 1/F");
    }
    sigma[i] = start_time_scale(t(nf - 1), nf, data.ts);
    scale[i] = scale_factors<S>(nf, nb, sigma[i]);
    th[i] = t.cwiseProduct(scale[i]);
  }
  const Eigen::Map<const Vector<S>> y(data.y, n);
  std::vector<Vector<S>> x(m);
  auto channel = [&](int i, const Vector<S>& target) {
    const RivcData<S> d{target.data(), data.u + i * n, n, data.ts};
    return std::make_unique<BjIteration<S>>(sub[i], d, sigma[i]);
  };
  for (int i = 0; i < m; ++i) x[i] = channel(i, Vector<S>(y))->simulate(th[i]);
  auto partial = [&](int i) {
    Vector<S> t = y;
    for (int j = 0; j < m; ++j) {
      if (j != i) t -= x[j];
    }
    return t;
  };

  ArmaSettings<S> arma_settings = settings.arma;
  ArmaResult<S> arma;
  Vector<S> next, x_hat;
  Matrix<S> inverse_gram;
  S condition = 0;
  result->converged = false;
  result->reason = "maximum number of iterations reached";
  int it = 0;
  for (; it < settings.max_iterations; ++it) {
    S change2 = 0, norm2 = 0;
    for (int i = 0; i < m; ++i) {
      const Vector<S> target = partial(i);
      const auto iteration = channel(i, target);
      const Status status = stable_bj_step(
          *iteration, th[i], problem.inputs[i].nf, problem.nd, problem.nc,
          hurwitz[i], "the RIVC iterate", arma_settings, next, inverse_gram,
          arma, x_hat, condition);
      if (!status.ok()) {
        return Status(status.code(), "input " + std::to_string(i + 1) + ": " +
                                         status.message());
      }
      change2 += (next - th[i]).squaredNorm();
      norm2 += next.squaredNorm();
      th[i] = next;
      x[i] = iteration->simulate(th[i]);
    }
    if (std::sqrt(change2 / norm2) < settings.tolerance) {
      result->converged = true;
      result->reason = "relative change below tol";
      ++it;
      break;
    }
  }
  result->iterations = it;

  // The noise model and the stacked instruments at the final estimate.
  Matrix<S> Z(n, np);
  std::vector<int> column(np);  // stacked column -> theta index
  int col = 0;
  result->condition = 0;
  for (int i = 0; i < m; ++i) {
    const Vector<S> target = partial(i);
    const auto iteration = channel(i, target);
    Status status = iteration->step(th[i], arma_settings, true, next,
                                    inverse_gram, arma, x_hat, condition);
    if (!status.ok()) {
      return Status(status.code(),
                    "input " + std::to_string(i + 1) + ": " + status.message());
    }
    result->condition = std::max(result->condition, condition);
    const int nf = problem.inputs[i].nf, nb = problem.inputs[i].nb;
    // Back to the original time: zeta' = zeta / scale (theta' = scale
    // theta, so zeta^T theta = zeta'^T theta').
    const Matrix<S>& Zi = iteration->instruments();
    for (int k = 0; k < nf + nb; ++k, ++col) {
      Z.col(col) = Zi.col(k) * scale[i](k);
      column[col] = k < nf ? f_at[i] + k : b_at[i] + (k - nf);
    }
  }
  result->noise = arma;
  const Matrix<S> gram = Z.transpose() * Z;
  const Vector<S> d = gram.diagonal().cwiseSqrt();
  if (!(d.minCoeff() > 0)) {
    return numerical_failure("an instrument is identically zero");
  }
  const Vector<S> di = d.cwiseInverse();
  const Eigen::FullPivLU<Matrix<S>> lu(di.asDiagonal() * gram *
                                       di.asDiagonal());
  if (!lu.isInvertible()) {
    return numerical_failure(
        "the stacked instruments are rank deficient (inputs not "
        "persistently exciting for the structure?)");
  }
  const Matrix<S> stacked = arma.innovation_variance *
                            (di.asDiagonal() * lu.inverse() * di.asDiagonal());
  result->theta.resize(np);
  result->covariance.resize(np, np);
  for (int i = 0, at = 0; i < m; ++i) {
    const Vector<S> t = th[i].cwiseQuotient(scale[i]);
    for (int k = 0; k < t.size(); ++k, ++at) result->theta(column[at]) = t(k);
  }
  for (int a = 0; a < np; ++a) {
    for (int b = 0; b < np; ++b) {
      result->covariance(column[a], column[b]) = stacked(a, b);
    }
  }
  result->simulated = Vector<S>::Zero(n);
  for (int i = 0; i < m; ++i) result->simulated += x[i];
  return rivc_outcome(data.y, n, np, settings.max_iterations, result);
}

template <typename S>
struct Cl2srivcResult {
  RivResult<S> plant;        // stage 2: y on u_hat (its covariance: SRIVC's)
  RivResult<S> sensitivity;  // stage 1: u on r
  // The two-stage estimator's covariance of [f b] (see two_stage_covariance;
  // empty when the structure has fixed parameters, offsets or initial
  // states, which it does not model).
  Matrix<S> covariance;
  int covariance_lags = 0;  // the lag window's length L
};

namespace bj_detail {

// The IV pieces of one SRIVC stage at its estimate, in the stage's scaled
// time (sigma = |F(0)|^(1/nf)): instruments Z, M = (Z^T Phi)^-1, the IV
// residual eps = target - Phi theta', theta' and the scale factors.
template <typename S>
struct StagePieces {
  Matrix<S> Z, M;
  Vector<S> eps, theta, scale;
  S sigma = 1;
};

template <typename S>
Status stage_pieces(const RivcProblem<S>& problem, const RivcData<S>& data,
                    const Vector<S>& theta, StagePieces<S>& out,
                    std::unique_ptr<BjIteration<S>>& iteration) {
  const int nf = problem.nf, nb = problem.nb;
  out.sigma = std::pow(std::abs(theta(nf - 1)), S(1) / nf);
  if (!(out.sigma > 0) || !std::isfinite(out.sigma)) out.sigma = S(1) / data.ts;
  out.scale = scale_factors<S>(nf, nb, out.sigma);
  out.theta = theta.cwiseProduct(out.scale);
  iteration = std::make_unique<BjIteration<S>>(problem, data, out.sigma);
  Vector<S> next, x_hat;
  Matrix<S> inverse_gram;
  ArmaResult<S> arma;
  S condition = 0;
  Status s = iteration->step(out.theta, ArmaSettings<S>(), false, next,
                             inverse_gram, arma, x_hat, condition);
  if (!s.ok()) return s;
  out.Z = iteration->instruments();
  const Matrix<S> zphi = out.Z.transpose() * iteration->regressors();
  const Eigen::FullPivLU<Matrix<S>> lu(zphi);
  if (!lu.isInvertible()) {
    return numerical_failure("the instrumental product matrix is singular");
  }
  out.M = lu.inverse();
  out.eps = iteration->target() - iteration->regressors() * out.theta;
  return Status::Ok();
}

// First lag at which the sample autocorrelation of x falls below `level`
// in magnitude (at most max_lag).
template <typename S>
Eigen::Index decorrelation_lag(const Vector<S>& x, S level,
                               Eigen::Index max_lag) {
  const Eigen::Index n = x.size();
  const S r0 = x.squaredNorm();
  if (!(r0 > 0)) return 1;
  for (Eigen::Index tau = 1; tau < max_lag; ++tau) {
    const S r = x.head(n - tau).dot(x.tail(n - tau));
    if (std::abs(r / r0) < level) return tau;
  }
  return max_lag;
}

}  // namespace bj_detail

// The covariance of the two-stage estimate (CL2SRIVC), derived here: the
// thesis' closed-loop IV estimate (eq. 2.47, instruments eq. 2.48-2.50)
// at the two stages, with the first stage's u_hat = B1/F1 r in place of
// the loop's noise-free input. Linearising both IV equations Z_k^T
// (target_k - Phi_k theta_k) = 0 about the true parameters,
//   theta1 - theta1o = M1 sum zeta1(t) eps1(t),
//   theta2 - theta2o = M2 sum zeta2(t) eps2(t) - M2 Z2^T D (theta1 - theta1o),
// M_k = (Z_k^T Phi_k)^-1, eps_k the IV residuals (eps1 ~ u - u_hat,
// eps2 ~ y - G u_hat: coloured, both driven by the loop's noise), and D =
// G dU, dU = d u_hat / d theta1, whose columns are the first stage's own
// noise-free instruments (d u_hat / d b_j = p^j r / F1, d u_hat / d f_i =
// -p^i u_hat / F1, eq. 2.48 with x_hat = u_hat). So theta2 - theta2o =
// sum_t w(t), w(t) = a(t) eps2(t) + b(t) eps1(t), a = M2 zeta2, b = -K
// zeta1, K = M2 Z2^T D M1, and its covariance sums a(t) a(s)^T E eps2(t)
// eps2(s) and the three like terms over all pairs (t, s): the residuals'
// auto- and cross-covariances at lags |tau| <= L, weighted by (1 -
// |tau|/(L+1)) (Bartlett), L = 8 times the lag at which the residuals'
// autocorrelation falls below 0.05 (at most N/4). With white eps2 and no
// first-stage error this is SRIVC's sigma^2 (Z^T Z)^-1 (eq. 2.13).
template <typename S>
Status two_stage_covariance(const RivProblem<S>& plant,
                            const RivProblem<S>& loop, const S* y, const S* u,
                            const S* r, Eigen::Index n, S ts,
                            Cl2srivcResult<S>* result) {
  using namespace bj_detail;
  RivcProblem<S> p1, p2;
  p1.nb = loop.channels[0].nb;
  p1.nf = loop.nf[0];
  p1.nk = loop.channels[0].nk;
  p1.u_rule = loop.channels[0].rule;
  p2.nb = plant.channels[0].nb;
  p2.nf = plant.nf[0];
  p2.nk = plant.channels[0].nk;
  p2.u_rule = plant.channels[0].rule;
  const Vector<S>& u_hat = result->sensitivity.simulated;
  const RivcData<S> d1{u, r, n, ts};
  const RivcData<S> d2{y, u_hat.data(), n, ts};
  StagePieces<S> s1, s2;
  std::unique_ptr<BjIteration<S>> it1, it2;
  Status status = stage_pieces(p1, d1, result->sensitivity.theta, s1, it1);
  if (!status.ok()) return status;
  status = stage_pieces(p2, d2, result->plant.theta, s2, it2);
  if (!status.ok()) return status;
  // D = G dU: the stage-1 instruments (scaled stage-1 time) through the
  // stage-2 model (its own scaled time; same sampled signals).
  const int np1 = static_cast<int>(s1.theta.size());
  const int np2 = static_cast<int>(s2.theta.size());
  Matrix<S> D(n, np1);
  for (int j = 0; j < np1; ++j) {
    const Vector<S> col = s1.Z.col(j);
    D.col(j) = it2->simulate_signal(s2.theta, col.data());
  }
  const Matrix<S> K = s2.M * (s2.Z.transpose() * D) * s1.M;
  // a(t) = M2 zeta2(t), b(t) = -K zeta1(t) (rows), deterministic given r.
  const Matrix<S> a = s2.Z * s2.M.transpose();
  const Matrix<S> b = -(s1.Z * K.transpose());
  const Eigen::Index max_lag = std::max<Eigen::Index>(1, n / 4);
  const Eigen::Index tau0 =
      std::max(decorrelation_lag<S>(s1.eps, S(0.05), max_lag),
               decorrelation_lag<S>(s2.eps, S(0.05), max_lag));
  const Eigen::Index L = std::min<Eigen::Index>(max_lag, 8 * tau0);
  // Var sum_t (a(t) eps2(t) + b(t) eps1(t)) = sum_(t,s) [a(t) a(s)^T
  // R22(s-t) + a(t) b(s)^T R21(s-t) + b(t) a(s)^T R12(s-t) + b(t) b(s)^T
  // R11(s-t)], R_ij(tau) = E eps_i(t) eps_j(t+tau): the products of a, b
  // summed exactly, the residuals' (cross-)covariances estimated and
  // weighted by Bartlett's window. (A lag window on w(t) = a eps2 + b eps1
  // itself would be biased low: sum_t a(t) eps2_hat(t) = 0 exactly.)
  auto lagged = [&](const Matrix<S>& x, const Matrix<S>& y, Eigen::Index t) {
    return Matrix<S>(
        x.topRows(n - t).transpose().lazyProduct(y.bottomRows(n - t)));
  };
  auto rcov = [&](const Vector<S>& x, const Vector<S>& y, Eigen::Index t) {
    return x.head(n - t).dot(y.tail(n - t)) / static_cast<S>(n);
  };
  Matrix<S> cov = lagged(a, a, 0) * rcov(s2.eps, s2.eps, 0) +
                  lagged(b, b, 0) * rcov(s1.eps, s1.eps, 0);
  const Matrix<S> ab0 = lagged(a, b, 0) * rcov(s2.eps, s1.eps, 0);
  cov += ab0 + ab0.transpose();
  for (Eigen::Index tau = 1; tau <= L; ++tau) {
    const S weight = S(1) - static_cast<S>(tau) / static_cast<S>(L + 1);
    const Matrix<S> aa = lagged(a, a, tau), bb = lagged(b, b, tau);
    Matrix<S> ab = lagged(a, b, tau) * rcov(s2.eps, s1.eps, tau) +
                   lagged(b, a, tau).transpose() * rcov(s1.eps, s2.eps, tau);
    cov += weight * ((aa + aa.transpose()) * rcov(s2.eps, s2.eps, tau) +
                     (bb + bb.transpose()) * rcov(s1.eps, s1.eps, tau) + ab +
                     ab.transpose());
  }
  const Vector<S> inv = s2.scale.cwiseInverse();
  result->covariance = inv.asDiagonal() * cov * inv.asDiagonal();
  result->covariance_lags = static_cast<int>(L);
  if (!result->covariance.allFinite() || np2 < 1) {
    return numerical_failure("the two-stage covariance is not finite");
  }
  return Status::Ok();
}

// CL2SRIVC (two-stage SRIVC): stage 1 SRIVC of u on r (orders `loop`),
// stage 2 SRIVC of y on u_hat = the stage-1 simulation (orders `plant`,
// u_hat with the intersample rule of plant.channels[0]). settings.
// theta_init starts stage 2, loop_theta_init stage 1 (empty: the
// automatic start). The covariance: two_stage_covariance.
template <typename S>
Status cl2srivc(const RivProblem<S>& plant, const RivProblem<S>& loop,
                const RivSettings<S>& settings, const S* y, const S* u,
                const S* r, Eigen::Index n, S ts, Cl2srivcResult<S>* result,
                const Vector<S>& loop_theta_init = Vector<S>()) {
  if (result == nullptr) return bad_input("cl2srivc: no result");
  if (plant.num_groups() != 1 || plant.channels.size() != 1 ||
      loop.num_groups() != 1 || loop.channels.size() != 1) {
    return bad_input("cl2srivc: one input and one denominator per stage");
  }
  for (const RivProblem<S>* stage : {&plant, &loop}) {
    if (stage->channels[0].nb > stage->nf[0] + 1) {
      return bad_input(
          "cl2srivc: nb must be at most nf + 1 (a proper "
          "model) in each stage");
    }
  }
  RivData<S> d1;
  d1.y = u;
  d1.w = r;
  d1.num_samples = n;
  d1.ts = ts;
  RivSettings<S> settings1 = settings;
  settings1.theta_init = loop_theta_init;
  // A stage that does not converge returns its last iterate (reported as
  // kNotConverged at the end, as refined_iv does).
  Status status = refined_iv<S>(loop, settings1, d1, &result->sensitivity);
  std::string not_converged;
  if (status.code() == ErrorCode::kNotConverged) {
    not_converged = "stage 1 (u on r): " + status.message();
  } else if (!status.ok()) {
    return Status(status.code(), "stage 1 (u on r): " + status.message());
  }
  const Vector<S> u_hat = result->sensitivity.simulated;
  RivData<S> d2;
  d2.y = y;
  d2.w = u_hat.data();
  d2.num_samples = n;
  d2.ts = ts;
  status = refined_iv<S>(plant, settings, d2, &result->plant);
  if (status.code() == ErrorCode::kNotConverged) {
    if (!not_converged.empty()) not_converged += "; ";
    not_converged += "stage 2 (y on u_hat): " + status.message();
  } else if (!status.ok()) {
    return Status(status.code(), "stage 2 (y on u_hat): " + status.message());
  }
  result->covariance.resize(0, 0);
  result->covariance_lags = 0;
  bool plain = true;
  for (const RivProblem<S>* stage : {&plant, &loop}) {
    plain = plain && stage->fixed.empty() && !stage->output_offset &&
            !stage->initial_state && stage->channels[0].delay == 0;
  }
  if (plain) {
    status = two_stage_covariance<S>(plant, loop, y, u, r, n, ts, result);
    if (!status.ok()) {
      return Status(status.code(),
                    "the two-stage covariance: " + status.message());
    }
  }
  if (!not_converged.empty()) {
    return Status(ErrorCode::kNotConverged, not_converged);
  }
  return Status::Ok();
}

}  // namespace ctid
