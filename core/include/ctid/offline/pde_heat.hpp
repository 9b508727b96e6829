// SPDX-License-Identifier: BSD-3-Clause
// Copyright (C) the ctid authors

// The one-dimensional heat equation with a distributed source,
//
//   dX/dt (t, x) = a d2X/dx2 (t, x) + b u(t, x),   x0 < x < xN,
//   X(t, x0) = X(t, xN) = 0 (Dirichlet),   X(t0, x) = IC(x),
//   y(t_k, x_i) = X(t_k, x_i) + v(t_k, x_i),
//
// its simulation and the estimation of theta = [a b] from a sampled field
// (Schorsch, Garnier, Gilson and Young, "Instrumental variable methods for
// identifying partial differential equation models", Int. J. Control 86(12),
// 2013).
//
// Discretisation. Space: the three-point second difference on the (possibly
// non-uniform) grid x_0 < ... < x_{N-1}, which gives the tridiagonal
// matrix L acting on the N-2 interior nodes (the boundary values are the
// known zeros). Time: Crank-Nicolson (the bilinear rule s ~ (2/h)(1 -
// q^-1)/(1 + q^-1)), so that the simulated field obeys exactly, at every
// interior node and for k >= 1,
//
//   Dt X_k = a M L X_k + b M u_k,   Dt = (1 - q^-1)/h,  M = (1 + q^-1)/2.  (1)
//
// Estimation. (1) is linear in [a b]. The three differenced arrays A = Dt y,
// B = M L y, C = M u (interior nodes, k >= 1) satisfy A = a B + b C node by
// node, so any linear filter applied to all three keeps the relation, and
// the edges of the record (the unknown boundary derivative, the initial
// field) never enter a filtered regressor:
//  * LSSVF: a two-dimensional state-variable filter, order 1 in time and 2
//    in space, lambda_t/(s + lambda_t) * (lambda_x/(p + lambda_x))^2,
//    discretised by the bilinear rule (with the time derivative of (1)) or
//    by Euler's backward rule (then (1) is read with M = 1, s ~ Dt); least
//    squares on the filtered arrays.
//  * SRIVC: the prefilter is the model itself, P = (Dt - a M L)^-1 with zero
//    initial field and boundaries (one Crank-Nicolson solve with the array
//    as source), and the instruments come from the noise-free field of the
//    current model (the auxiliary model); iterated to convergence.
//  * RIVC: as SRIVC, with a separable noise model
//    v = Ct(q_t) Cs(q_x) / (Dt(q_t) Ds(q_x)) e estimated from the residual
//    field at every iteration and its inverse added to the prefilter.
#pragma once

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <complex>
#include <memory>
#include <string>
#include <vector>

#include "ctid/base/polynomial.hpp"
#include "ctid/base/stability.hpp"
#include "ctid/base/status.hpp"

namespace ctid {

namespace pde_detail {

// The interior second-difference matrix L on the grid x (N >= 3 nodes):
// row i (interior node i + 1) is lo[i] X_i + di[i] X_{i+1} + up[i] X_{i+2}.
struct Laplacian {
  Eigen::VectorXd lo, di, up;
  long n() const { return di.size(); }
  void apply(const double* z, double* out) const {
    const long n = di.size();
    for (long i = 0; i < n; ++i) {
      double s = di[i] * z[i];
      if (i > 0) s += lo[i] * z[i - 1];
      if (i + 1 < n) s += up[i] * z[i + 1];
      out[i] = s;
    }
  }
};

inline Laplacian make_laplacian(const Eigen::VectorXd& x) {
  const long n = x.size() - 2;
  Laplacian l;
  l.lo.resize(n);
  l.di.resize(n);
  l.up.resize(n);
  for (long i = 0; i < n; ++i) {
    const double hl = x[i + 1] - x[i];
    const double hr = x[i + 2] - x[i + 1];
    l.lo[i] = 2.0 / (hl * (hl + hr));
    l.di[i] = -2.0 / (hl * hr);
    l.up[i] = 2.0 / (hr * (hl + hr));
  }
  return l;
}

// One Crank-Nicolson step operator: (I/h - a/2 L) z_k = (I/h + a/2 L)
// z_{k-1} + w_k, factorised once (Thomas algorithm; the matrix is
// diagonally dominant for a >= 0).
class CrankNicolson {
 public:
  CrankNicolson(const Laplacian& l, double a, double h) : l_(l), a_(a), h_(h) {
    const long n = l.n();
    cp_.resize(n);
    inv_.resize(n);
    double prev_c = 0.0;
    for (long i = 0; i < n; ++i) {
      const double sub = i > 0 ? -0.5 * a * l.lo[i] : 0.0;
      const double diag = 1.0 / h - 0.5 * a * l.di[i];
      const double denom = diag - sub * prev_c;
      inv_[i] = 1.0 / denom;
      prev_c = (i + 1 < n ? -0.5 * a * l.up[i] : 0.0) * inv_[i];
      cp_[i] = prev_c;
    }
  }
  // z_new from z_old and the source w (all of length n); z_new may not
  // alias z_old.
  void step(const double* z_old, const double* w, double* z_new) const {
    const long n = l_.n();
    // right-hand side (I/h + a/2 L) z_old + w, then forward elimination
    double prev = 0.0;
    for (long i = 0; i < n; ++i) {
      double lz = l_.di[i] * z_old[i];
      if (i > 0) lz += l_.lo[i] * z_old[i - 1];
      if (i + 1 < n) lz += l_.up[i] * z_old[i + 1];
      const double rhs = z_old[i] / h_ + 0.5 * a_ * lz + w[i];
      const double sub = i > 0 ? -0.5 * a_ * l_.lo[i] : 0.0;
      prev = (rhs - sub * prev) * inv_[i];
      z_new[i] = prev;
    }
    for (long i = n - 2; i >= 0; --i) z_new[i] -= cp_[i] * z_new[i + 1];
  }

 private:
  const Laplacian& l_;
  double a_, h_;
  Eigen::VectorXd cp_, inv_;
};

// P = (Dt - a M L)^-1 along the columns of w (n-by-K, one column per
// instant, zero initial field): z_0 = step(0, w_0), z_k = step(z_{k-1}, w_k).
inline Eigen::MatrixXd model_filter(const Laplacian& l, double a, double h,
                                    const Eigen::MatrixXd& w) {
  const CrankNicolson cn(l, a, h);
  Eigen::MatrixXd z(w.rows(), w.cols());
  const Eigen::VectorXd zero = Eigen::VectorXd::Zero(w.rows());
  for (long k = 0; k < w.cols(); ++k) {
    cn.step(k == 0 ? zero.data() : z.col(k - 1).data(), w.col(k).data(),
            z.col(k).data());
  }
  return z;
}

inline bool is_uniform(const Eigen::VectorXd& v) {
  const long n = v.size();
  const double h = (v[n - 1] - v[0]) / static_cast<double>(n - 1);
  for (long i = 1; i < n; ++i) {
    if (std::abs(v[i] - v[i - 1] - h) > 1e-6 * std::abs(h)) return false;
  }
  return true;
}

inline Status check_grid(const Eigen::VectorXd& v, const char* name,
                         long min_size) {
  if (v.size() < min_size) {
    return bad_input(std::string(name) + " needs at least " +
                     std::to_string(min_size) + " points");
  }
  if (!v.allFinite()) return bad_input(std::string(name) + " must be finite");
  for (long i = 1; i < v.size(); ++i) {
    if (!(v[i] > v[i - 1])) {
      return bad_input(std::string(name) + " must be strictly increasing");
    }
  }
  return Status::Ok();
}

// The checks shared by the estimators: grids, field sizes, finite values.
inline Status check_problem(const Eigen::VectorXd& t, const Eigen::VectorXd& x,
                            const Eigen::MatrixXd& y,
                            const Eigen::MatrixXd& u) {
  Status s = check_grid(t, "the time grid t", 4);
  if (!s.ok()) return s;
  s = check_grid(x, "the space grid x", 4);
  if (!s.ok()) return s;
  if (!is_uniform(t) || !is_uniform(x)) {
    return Status(ErrorCode::kBadInput,
                  "the estimators need uniform time and space grids");
  }
  if (y.rows() != t.size() || y.cols() != x.size()) {
    return dimension_mismatch("the output field must be numel(t)-by-numel(x)");
  }
  if (u.rows() != t.size() || u.cols() != x.size()) {
    return dimension_mismatch("the input field must be numel(t)-by-numel(x)");
  }
  if (!y.allFinite() || !u.allFinite()) {
    return bad_input("the input and output fields must be finite");
  }
  return Status::Ok();
}

// Interior nodes of a Nt-by-Nx field, transposed: (Nx-2)-by-Nt.
inline Eigen::MatrixXd interior(const Eigen::MatrixXd& f) {
  return f.middleCols(1, f.cols() - 2).transpose();
}

// The differenced arrays of (1) (n-by-(Nt-1)): A = Dt y, B = M L y (or
// L y), C = M u (or u); `bilinear` false reads (1) with M = 1 (Euler).
struct Differenced {
  Eigen::MatrixXd A, B, C;
};

inline Eigen::MatrixXd apply_ml(const Laplacian& l, const Eigen::MatrixXd& z,
                                bool bilinear) {
  const long n = z.rows(), K = z.cols() - 1;
  Eigen::MatrixXd out(n, K);
  Eigen::VectorXd tmp(n);
  for (long k = 0; k < K; ++k) {
    if (bilinear) {
      tmp = 0.5 * (z.col(k + 1) + z.col(k));
    } else {
      tmp = z.col(k + 1);
    }
    l.apply(tmp.data(), out.col(k).data());
  }
  return out;
}

inline Differenced difference(const Laplacian& l, double h,
                              const Eigen::MatrixXd& yi,
                              const Eigen::MatrixXd& ui, bool bilinear) {
  const long K = yi.cols() - 1;
  Differenced d;
  d.A = (yi.rightCols(K) - yi.leftCols(K)) / h;
  d.B = apply_ml(l, yi, bilinear);
  d.C = bilinear ? Eigen::MatrixXd(0.5 * (ui.rightCols(K) + ui.leftCols(K)))
                 : Eigen::MatrixXd(ui.rightCols(K));
  return d;
}

// Solves the 2-by-2 IV normal equations (Z' Phi) theta = Z' A with the
// columns scaled to unit norm.
inline Status solve_iv(const Eigen::MatrixXd& zb, const Eigen::MatrixXd& zc,
                       const Eigen::MatrixXd& pb, const Eigen::MatrixXd& pc,
                       const Eigen::MatrixXd& a, Eigen::Vector2d* theta) {
  const auto v = [](const Eigen::MatrixXd& m) {
    return Eigen::Map<const Eigen::VectorXd>(m.data(), m.size());
  };
  const double s1 = v(pb).norm(), s2 = v(pc).norm();
  const double z1 = v(zb).norm(), z2 = v(zc).norm();
  if (!(s1 > 0) || !(s2 > 0) || !(z1 > 0) || !(z2 > 0)) {
    return numerical_failure(
        "a filtered regressor is zero: the field or the source is zero "
        "on the interior nodes");
  }
  Eigen::Matrix2d r;
  r << v(zb).dot(v(pb)) / (z1 * s1), v(zb).dot(v(pc)) / (z1 * s2),
      v(zc).dot(v(pb)) / (z2 * s1), v(zc).dot(v(pc)) / (z2 * s2);
  const Eigen::Vector2d f(v(zb).dot(v(a)) / z1, v(zc).dot(v(a)) / z2);
  Eigen::JacobiSVD<Eigen::Matrix2d> svd(r);
  const Eigen::Vector2d sv = svd.singularValues();
  if (!(sv[1] > 1e-12 * sv[0])) {
    return numerical_failure(
        "the normal equations are singular: the data do not separate a "
        "and b");
  }
  const Eigen::Vector2d th = r.fullPivLu().solve(f);
  (*theta)[0] = th[0] / s1;
  (*theta)[1] = th[1] / s2;
  if (!theta->allFinite())
    return numerical_failure("the estimate is not finite");
  return Status::Ok();
}

// Reflects the roots of c = [1 c1 .. cn] on or outside the unit circle
// inside (same spectrum shape; one on the circle moves to |z| = 0.999);
// c itself when none is.
inline Eigen::VectorXd make_minimum_phase(const Eigen::VectorXd& c) {
  const long n = c.size() - 1;
  if (n < 1) return c;
  bool moved = false;
  const Eigen::VectorXd reflected =
      reflect_roots_into_unit_disc<double>(c.tail(n), 1.0, 0.999, &moved);
  if (!moved) return c;
  Eigen::VectorXd out = c;
  out.tail(n) = reflected;
  return out;
}

}  // namespace pde_detail

// Two-dimensional recursive (quarter-plane) filter: with num (p1-by-p2)
// and den (r1-by-r2) the coefficients of q1^-(i) q2^-(j) at (i+1, j+1),
//   sum_ij den(i,j) y(k-i, l-j) = sum_ij num(i,j) x(k-i, l-j),
// the values before the first sample of either dimension being zero. den(0,0)
// must be nonzero. in and out are n1-by-n2 (column-major); out may not
// alias in.
inline Status filter_2d(const Eigen::MatrixXd& num, const Eigen::MatrixXd& den,
                        const Eigen::MatrixXd& in, Eigen::MatrixXd* out) {
  if (num.size() == 0 || den.size() == 0) {
    return bad_input("the numerator and denominator must not be empty");
  }
  if (!num.allFinite() || !den.allFinite() || !in.allFinite()) {
    return bad_input("the coefficients and the data must be finite");
  }
  if (den(0, 0) == 0.0) {
    return bad_input("the leading denominator coefficient den(1,1) is zero");
  }
  const long n1 = in.rows(), n2 = in.cols();
  const Eigen::MatrixXd b = num / den(0, 0), a = den / den(0, 0);
  out->setZero(n1, n2);
  for (long l = 0; l < n2; ++l) {
    for (long k = 0; k < n1; ++k) {
      double s = 0.0;
      for (long j = 0; j < b.cols() && j <= l; ++j) {
        for (long i = 0; i < b.rows() && i <= k; ++i) {
          s += b(i, j) * in(k - i, l - j);
        }
      }
      for (long j = 0; j < a.cols() && j <= l; ++j) {
        for (long i = 0; i < a.rows() && i <= k; ++i) {
          if (i == 0 && j == 0) continue;
          s -= a(i, j) * (*out)(k - i, l - j);
        }
      }
      (*out)(k, l) = s;
    }
  }
  if (!out->allFinite()) {
    return numerical_failure(
        "the filtered data are not finite (unstable "
        "denominator)");
  }
  return Status::Ok();
}

// Crank-Nicolson / second-difference simulation of the heat equation: t
// (Nt) and x (Nx) strictly increasing (non-uniform steps allowed), u and the
// result y Nt-by-Nx, ic of length Nx. y's first row is ic, the boundary
// columns are zero afterwards; the source enters as b (u_k + u_{k-1})/2.
inline Status simulate_heat(double a, double b, const Eigen::VectorXd& t,
                            const Eigen::VectorXd& x, const Eigen::MatrixXd& u,
                            const Eigen::VectorXd& ic, Eigen::MatrixXd* y) {
  Status s = pde_detail::check_grid(t, "the time grid t", 1);
  if (!s.ok()) return s;
  s = pde_detail::check_grid(x, "the space grid x", 3);
  if (!s.ok()) return s;
  if (!std::isfinite(a) || !std::isfinite(b)) {
    return bad_input("theta = [a b] must be finite");
  }
  if (a < 0) {
    return bad_input(
        "the diffusion coefficient a must be >= 0 (a < 0 is "
        "the ill-posed backward heat equation)");
  }
  if (u.rows() != t.size() || u.cols() != x.size()) {
    return dimension_mismatch("the input field must be numel(t)-by-numel(x)");
  }
  if (ic.size() != x.size()) {
    return dimension_mismatch(
        "the initial condition must have numel(x) values");
  }
  if (!u.allFinite() || !ic.allFinite()) {
    return bad_input(
        "the input field and the initial condition must be finite");
  }
  const long nt = t.size(), nx = x.size(), n = nx - 2;
  const pde_detail::Laplacian l = pde_detail::make_laplacian(x);
  const Eigen::MatrixXd ui = pde_detail::interior(u);
  Eigen::MatrixXd z(n, nt);
  z.col(0) = ic.segment(1, n);
  Eigen::VectorXd w(n);
  std::unique_ptr<pde_detail::CrankNicolson> cn;
  double h_factorised = 0.0;
  for (long k = 1; k < nt; ++k) {
    const double h = t[k] - t[k - 1];
    // equal steps reuse the factorisation; a new step refactorises.
    if (!cn || h != h_factorised) {
      cn = std::make_unique<pde_detail::CrankNicolson>(l, a, h);
      h_factorised = h;
    }
    w = 0.5 * b * (ui.col(k) + ui.col(k - 1));
    cn->step(z.col(k - 1).data(), w.data(), z.col(k).data());
  }
  y->setZero(nt, nx);
  y->middleCols(1, n) = z.transpose();
  y->row(0) = ic.transpose();
  if (!y->allFinite()) {
    return numerical_failure(
        "the simulated field is not finite (theta or "
        "the source too large)");
  }
  return Status::Ok();
}

enum class HeatRule { kBilinear, kEuler };

// LSSVF estimate of theta = [a b] (see the head of this file). lambda_t
// (rad per time unit) and lambda_x (rad per space unit) are the cut-offs of
// the time and space state-variable filters.
inline Status heat_lssvf(const Eigen::VectorXd& t, const Eigen::VectorXd& x,
                         const Eigen::MatrixXd& y, const Eigen::MatrixXd& u,
                         HeatRule rule, double lambda_t, double lambda_x,
                         Eigen::Vector2d* theta) {
  Status s = pde_detail::check_problem(t, x, y, u);
  if (!s.ok()) return s;
  if (!(lambda_t > 0) || !(lambda_x > 0) || !std::isfinite(lambda_t) ||
      !std::isfinite(lambda_x)) {
    return Status(ErrorCode::kBadOption,
                  "the filter cut-offs must be finite and > 0");
  }
  const bool bili = rule == HeatRule::kBilinear;
  const double h = t[1] - t[0], dx = x[1] - x[0];
  const pde_detail::Laplacian l = pde_detail::make_laplacian(x);
  const pde_detail::Differenced d = pde_detail::difference(
      l, h, pde_detail::interior(y), pde_detail::interior(u), bili);
  // Arrays are space-by-time: dimension 1 is space, dimension 2 time.
  Eigen::Vector2d ns, ds, nt, dt;  // first order sections
  const double lx = lambda_x * dx, lt = lambda_t * h;
  if (bili) {
    ns << lx, lx;
    ds << 2 + lx, -(2 - lx);
    nt << 2 * lt, 0;  // G = F/M (the M of (1) is already in B and C)
    dt << 2 + lt, -(2 - lt);
  } else {
    ns << lx, 0;
    ds << 1 + lx, -1;
    nt << lt, 0;
    dt << 1 + lt, -1;
  }
  Eigen::Vector3d ns2(ns[0] * ns[0], 2 * ns[0] * ns[1], ns[1] * ns[1]);
  Eigen::Vector3d ds2(ds[0] * ds[0], 2 * ds[0] * ds[1], ds[1] * ds[1]);
  const Eigen::MatrixXd num = ns2 * nt.transpose(), den = ds2 * dt.transpose();
  Eigen::MatrixXd fa, fb, fc;
  if (!(s = filter_2d(num, den, d.A, &fa)).ok()) return s;
  if (!(s = filter_2d(num, den, d.B, &fb)).ok()) return s;
  if (!(s = filter_2d(num, den, d.C, &fc)).ok()) return s;
  return pde_detail::solve_iv(fb, fc, fb, fc, fa, theta);
}

struct HeatIvOptions {
  double tol = 1e-6;  // relative change of theta that stops the iterations
  int maxiter = 50;
  // RIVC noise model orders [ndt nct nds ncs] (time AR, time MA, space AR,
  // space MA); unused by SRIVC.
  int orders[4] = {0, 0, 0, 0};
};

struct HeatIvResult {
  Eigen::Vector2d theta = Eigen::Vector2d::Zero();
  int iterations = 0;
  bool converged = false;
  // noise model (monic, [1 c1 .. cn]); 1 for SRIVC
  Eigen::VectorXd ct = Eigen::VectorXd::Ones(1), dt = Eigen::VectorXd::Ones(1);
  Eigen::VectorXd cs = Eigen::VectorXd::Ones(1), ds = Eigen::VectorXd::Ones(1);
};

namespace pde_detail {

// Pooled ARMA(na, nc) fit of the columns of v (each column one record):
// least squares for nc = 0, Hannan-Rissanen otherwise (a long AR for the
// innovations, then least squares on past values and past innovations).
inline Status pooled_arma(const Eigen::MatrixXd& v, int na, int nc,
                          Eigen::VectorXd* d, Eigen::VectorXd* c) {
  const long len = v.rows(), nrec = v.cols();
  d->setZero(na + 1);
  (*d)[0] = 1.0;
  c->setZero(nc + 1);
  (*c)[0] = 1.0;
  if (na == 0 && nc == 0) return Status::Ok();
  Eigen::MatrixXd e = v;  // innovations estimate
  if (nc > 0) {
    const long p = std::min<long>(std::max(20, 3 * (na + nc)), len / 4);
    if (p < 1)
      return bad_input("the records are too short for the noise model");
    Eigen::MatrixXd g = Eigen::MatrixXd::Zero(p, p);
    Eigen::VectorXd f = Eigen::VectorXd::Zero(p);
    for (long r = 0; r < nrec; ++r) {
      for (long k = p; k < len; ++k) {
        Eigen::VectorXd phi(p);
        for (long i = 0; i < p; ++i) phi[i] = -v(k - 1 - i, r);
        g.noalias() += phi * phi.transpose();
        f += phi * v(k, r);
      }
    }
    const Eigen::VectorXd ar = g.ldlt().solve(f);
    for (long r = 0; r < nrec; ++r) {
      for (long k = 0; k < len; ++k) {
        double s = v(k, r);
        for (long i = 0; i < p && i < k; ++i) s += ar[i] * v(k - 1 - i, r);
        e(k, r) = s;
      }
    }
  }
  const long m = na + nc, start = std::max<long>(na, nc);
  if (len <= start + m)
    return bad_input("the records are too short for the noise model");
  Eigen::MatrixXd g = Eigen::MatrixXd::Zero(m, m);
  Eigen::VectorXd f = Eigen::VectorXd::Zero(m);
  Eigen::VectorXd phi(m);
  for (long r = 0; r < nrec; ++r) {
    for (long k = start; k < len; ++k) {
      for (long i = 0; i < na; ++i) phi[i] = -v(k - 1 - i, r);
      for (long i = 0; i < nc; ++i) phi[na + i] = e(k - 1 - i, r);
      g.noalias() += phi * phi.transpose();
      f += phi * v(k, r);
    }
  }
  Eigen::JacobiSVD<Eigen::MatrixXd> svd(g);
  if (!(svd.singularValues()[m - 1] > 1e-12 * svd.singularValues()[0])) {
    return numerical_failure("the noise model regression is singular");
  }
  const Eigen::VectorXd th = g.ldlt().solve(f);
  d->segment(1, na) = th.head(na);
  c->segment(1, nc) = th.tail(nc);
  *c = make_minimum_phase(*c);
  return Status::Ok();
}

inline Status heat_iv(const Eigen::VectorXd& t, const Eigen::VectorXd& x,
                      const Eigen::MatrixXd& y, const Eigen::MatrixXd& u,
                      const Eigen::VectorXd& ic, const HeatIvOptions& opt,
                      bool refined, HeatIvResult* res) {
  Status s = check_problem(t, x, y, u);
  if (!s.ok()) return s;
  if (ic.size() != x.size()) {
    return dimension_mismatch(
        "the initial condition must have numel(x) values");
  }
  if (!ic.allFinite()) return bad_input("the initial condition must be finite");
  if (!(opt.tol > 0) || opt.maxiter < 1) {
    return Status(ErrorCode::kBadOption, "tol must be > 0 and maxiter >= 1");
  }
  const long nt = t.size();
  const double h = t[1] - t[0];
  if (refined) {
    for (int i = 0; i < 4; ++i) {
      if (opt.orders[i] < 0) {
        return Status(ErrorCode::kBadOption, "the noise orders must be >= 0");
      }
    }
    if (opt.orders[0] + opt.orders[1] >= nt / 4 ||
        opt.orders[2] + opt.orders[3] >= (x.size() - 2) / 4) {
      return Status(ErrorCode::kBadOption,
                    "the noise orders are too large for the grid");
    }
  }
  const Laplacian l = make_laplacian(x);
  const Eigen::MatrixXd yi = interior(y), ui = interior(u);
  const Differenced d = difference(l, h, yi, ui, true);
  // Initial estimate: LSSVF with the cut-offs 20/span of the record in time
  // and in space (about three cycles over the record: above its slowest
  // variations, far below the grids' Nyquist bands).
  Eigen::Vector2d theta;
  const double span_t = t[nt - 1] - t[0], span_x = x[x.size() - 1] - x[0];
  s = heat_lssvf(t, x, y, u, HeatRule::kBilinear, 20.0 / span_t, 20.0 / span_x,
                 &theta);
  if (!s.ok()) return s;
  if (!(theta[0] > 0)) {
    return numerical_failure(
        "the initial least-squares estimate of a is not positive");
  }
  HeatIvResult r;
  for (int it = 1; it <= opt.maxiter; ++it) {
    const double a = theta[0];
    Eigen::MatrixXd xs;
    s = simulate_heat(a, theta[1], t, x, u, ic, &xs);
    if (!s.ok()) return s;
    const Eigen::MatrixXd xi = interior(xs);
    Eigen::MatrixXd fa = model_filter(l, a, h, d.A);
    Eigen::MatrixXd fb = model_filter(l, a, h, d.B);
    Eigen::MatrixXd fc = model_filter(l, a, h, d.C);
    Eigen::MatrixXd fz = model_filter(l, a, h, apply_ml(l, xi, true));
    if (refined) {
      // residual field of the auxiliary model: time records are the rows
      // of the (space-by-time) interior arrays.
      const Eigen::MatrixXd v = (yi - xi).transpose();  // time-by-space
      Eigen::VectorXd dtp, ctp, dsp, csp;
      s = pooled_arma(v, opt.orders[0], opt.orders[1], &dtp, &ctp);
      if (!s.ok()) return s;
      Eigen::MatrixXd w;  // white in time
      if (!(s = filter_2d(dtp, ctp, v, &w)).ok()) return s;
      s = pooled_arma(w.transpose(), opt.orders[2], opt.orders[3], &dsp, &csp);
      if (!s.ok()) return s;
      r.dt = dtp;
      r.ct = ctp;
      r.ds = dsp;
      r.cs = csp;
      // prefilter D/C, separable: dimension 1 space, dimension 2 time.
      const Eigen::MatrixXd num = dsp * dtp.transpose();
      const Eigen::MatrixXd den = csp * ctp.transpose();
      Eigen::MatrixXd tmp;
      for (Eigen::MatrixXd* m : {&fa, &fb, &fc, &fz}) {
        if (!(s = filter_2d(num, den, *m, &tmp)).ok()) return s;
        *m = tmp;
      }
    }
    Eigen::Vector2d next;
    s = solve_iv(fz, fc, fb, fc, fa, &next);
    if (!s.ok()) return s;
    if (!(next[0] > 0)) {
      return numerical_failure(
          "the estimate of a is not positive at "
          "iteration " +
          std::to_string(it));
    }
    const double change =
        ((next - theta).array().abs() / next.array().abs().max(1e-300))
            .maxCoeff();
    theta = next;
    r.iterations = it;
    if (change < opt.tol) {
      r.converged = true;
      break;
    }
  }
  r.theta = theta;
  *res = r;
  return Status::Ok();
}

}  // namespace pde_detail

// SRIVC estimate of theta = [a b] (white measurement noise).
inline Status heat_srivc(const Eigen::VectorXd& t, const Eigen::VectorXd& x,
                         const Eigen::MatrixXd& y, const Eigen::MatrixXd& u,
                         const Eigen::VectorXd& ic, const HeatIvOptions& opt,
                         HeatIvResult* res) {
  return pde_detail::heat_iv(t, x, y, u, ic, opt, false, res);
}

// RIVC estimate of theta = [a b] and of the separable noise model with the
// orders opt.orders = [ndt nct nds ncs].
inline Status heat_rivc(const Eigen::VectorXd& t, const Eigen::VectorXd& x,
                        const Eigen::MatrixXd& y, const Eigen::MatrixXd& u,
                        const Eigen::VectorXd& ic, const HeatIvOptions& opt,
                        HeatIvResult* res) {
  return pde_detail::heat_iv(t, x, y, u, ic, opt, true, res);
}

}  // namespace ctid
