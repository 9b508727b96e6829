// SPDX-License-Identifier: BSD-3-Clause
// Copyright (C) the ctid authors
// Square-root (Potter) form of the normalised Kalman filter for the
// least-squares regression, PotterSVF, thesis eq. (3.73).
//
// The covariance is kept as a square root, P = S S^T (eq. 3.67), so that
// kappa_2(P) = kappa_2(S)^2 (eq. 3.68): the filter works with numbers whose
// spread is the square root of that of the standard form (1.59), which is
// what keeps P symmetric positive definite in single precision on badly
// scaled regressors.
//
//   time update (3.73b):  [S^T(t_k|t_k-1); 0] = T [S^T(t_k-1); Qn^(T/2)]
//     done by a Householder QR of the stacked matrix: S^- = R^T, so that
//     S^- S^-T = S S^T + Qn exactly in exact arithmetic;
//   measurement update (3.73c)-(3.73i), Potter's algorithm:
//     f = S^-T phi,  beta = 1 + f^T f,  alpha = beta + sqrt(beta),
//     L = S^- f / beta,  theta += L (target - phi^T theta),
//     S = S^- (I - f f^T / alpha).
//
// The forgetting-factor form (sec. 3.5: "both a Kalman filter based and a
// forgetting factor based approach") has no time update and
//     beta = lambda + f^T f,  alpha = beta + sqrt(lambda beta),
//     S = S (I - f f^T / alpha) / sqrt(lambda),
// which gives S S^T = (P - P phi phi^T P / (lambda + phi^T P phi)) / lambda,
// eq. (1.57): (I - f f^T/alpha)^2 = I - f f^T (2 alpha - f^T f)/alpha^2
// equals I - f f^T/beta when alpha^2 - 2 beta alpha + beta f^T f = 0, whose
// larger root is alpha = beta + sqrt(beta (beta - f^T f)) = beta +
// sqrt(lambda beta); lambda = 1 gives eq. (3.72).
//
// Qn^(1/2) is computed once, in configure(), from the eigen-decomposition of
// Qn, so a semi-definite Qn (e.g. a parameter known to be constant) is
// handled; only its nonzero directions enter the QR step, and Qn = 0 skips
// the QR step altogether. The triangularisation is a plain column-by-column
// Householder sweep in the preallocated stacked matrix (only R is needed,
// never Q): for the handful of parameters of these models a generic QR
// costs several times the rest of the step (bench/ch3_bench.cpp). No
// allocation happens in update().
//
// The step is written once, as a template on the parameter count
// (step_size.hpp): at compile-time size np when configured with
// fixed_size = true and np <= kMaxFixedParameters, on local copies of
// S^T, theta and the stacked matrix of the time update written back once;
// otherwise at runtime size on the storage itself.
#pragma once

#include <cmath>
#include <limits>
#include <type_traits>
#include <utility>

#include "ctid/adaptation/adaptation.hpp"
#include "ctid/adaptation/step_size.hpp"
#include "ctid/base/small_products.hpp"
#include "ctid/base/types.hpp"

namespace ctid {

// A square root R of the symmetric positive semi-definite matrix M,
// M = R R^T, with only the columns of the nonzero directions (R is
// n-by-rank). Eigenvalues below n * eps * max|lambda| are treated as zero;
// slightly negative ones (rounding) are clipped.
template <typename S>
Matrix<S> semidefinite_square_root(const Matrix<S>& M) {
  const Eigen::Index n = M.rows();
  if (n == 0) return Matrix<S>(0, 0);
  const Eigen::SelfAdjointEigenSolver<Matrix<S>> eig(M);
  const Vector<S>& lambda = eig.eigenvalues();
  const S largest = lambda.cwiseAbs().maxCoeff();
  const S threshold = S(n) * std::numeric_limits<S>::epsilon() * largest;
  Eigen::Index rank = 0;
  for (Eigen::Index i = 0; i < n; ++i) rank += lambda(i) > threshold;
  Matrix<S> root(n, rank);
  for (Eigen::Index i = 0, j = 0; i < n; ++i) {
    if (lambda(i) > threshold) {
      root.col(j++) = eig.eigenvectors().col(i) * std::sqrt(lambda(i));
    }
  }
  return root;
}

// kappa_2(P) for P = S S^T, from the singular values of the square root:
// sigma_max(S)^2 / sigma_min(S)^2 (eq. 3.68). Infinity when S is singular.
template <typename S>
S condition_number_from_square_root(const Matrix<S>& sqrt_P) {
  if (sqrt_P.size() == 0) return S(1);
  const Eigen::JacobiSVD<Matrix<S>> svd(sqrt_P);
  const Vector<S>& sigma = svd.singularValues();
  const S smallest = sigma(sigma.size() - 1);
  if (!(smallest > 0)) return std::numeric_limits<S>::infinity();
  const S ratio = sigma(0) / smallest;
  return ratio * ratio;
}

template <typename S>
class PotterUpdate {
 public:
  using RowMatrix =
      Eigen::Matrix<S, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;

  PotterUpdate() = default;
  PotterUpdate(Eigen::Index np, Adaptation<S> adaptation,
               bool fixed_size = false) {
    configure(np, std::move(adaptation), fixed_size);
  }

  // A default-constructed KalmanAdaptation (empty Qn) means Qn = 0. Qn must
  // otherwise be np-by-np and positive semi-definite (validate_covariance);
  // a forgetting factor must lie in (0, 1]. fixed_size: the compile-time-size
  // step when np <= kMaxFixedParameters (chosen here, once).
  void configure(Eigen::Index np, Adaptation<S> adaptation,
                 bool fixed_size = false) {
    fixed_np_ = fixed_step_size(np, fixed_size);
    step_ = select_size(np, fixed_size, [](auto size) {
      return &PotterUpdate::step<decltype(size)::value>;
    });
    lambda_ = 1;
    Matrix<S> qn;
    if (const auto* ff =
            std::get_if<ForgettingFactorAdaptation<S>>(&adaptation)) {
      lambda_ = ff->lambda();
    } else {
      qn = std::get<KalmanAdaptation<S>>(adaptation).qn();
    }
    adaptation_ = std::move(adaptation);
    qn_root_t_ = qn.size() == 0
                     ? Matrix<S>(0, np)
                     : Matrix<S>(semidefinite_square_root(qn).transpose());
    theta_ = Vector<S>::Zero(np);
    S_ = Matrix<S>::Identity(np, np);
    P_ = Matrix<S>::Identity(np, np);
    stacked_ = RowMatrix::Zero(np + qn_root_t_.rows(), np);
    stacked_.topRows(np).setIdentity();
    f_ = Vector<S>::Zero(np);
    s_f_ = Vector<S>::Zero(np);
    gain_ = Vector<S>::Zero(np);
    phi_copy_ = Vector<S>::Zero(np);
    shrink_ = lambda_ != S(1) ? S(1) / std::sqrt(lambda_) : S(1);
  }

  // S(t_0) is the Cholesky factor of P0; a P0 that is only semi-definite
  // (within rounding) gets its eigen-based square root instead.
  void reset(const Vector<S>& theta0, const Matrix<S>& P0) {
    const Eigen::LLT<Matrix<S>> llt(P0);
    if (llt.info() == Eigen::Success) {
      reset_square_root(theta0, llt.matrixL());
    } else {
      const Matrix<S> root = semidefinite_square_root<S>(P0);
      Matrix<S> S0 = Matrix<S>::Zero(P0.rows(), P0.cols());
      S0.leftCols(root.cols()) = root;
      reset_square_root(theta0, S0);
    }
  }

  // Starts from a given square root, P0 = S0 S0^T.
  void reset_square_root(const Vector<S>& theta0, const Matrix<S>& S0) {
    theta_ = theta0;
    stacked_.topRows(S0.rows()) = S0.transpose();
  }

  // One PotterSVF step. Returns the prediction error
  // target - phi^T theta(t_k|t_(k-1)), eq. (3.73d).
  template <typename Derived>
  S update(const Eigen::MatrixBase<Derived>& phi, S target) {
    return (this->*step_)(contiguous(phi, phi_copy_), target);
  }

  // beta of the last step: lambda (or 1) + phi^T P(t_k|t_k-1) phi, the
  // normalised variance of the prediction error (eq. 3.25 over sigma_e^2).
  S innovation_scale() const { return innovation_scale_; }
  // kappa_2(P) from the square root, eq. (3.68).
  S condition_number() const {
    return condition_number_from_square_root(sqrt_P());
  }

  const Vector<S>& theta() const { return theta_; }
  // Gain L(t_k) of the last step, eq. (3.73h).
  const Vector<S>& gain() const { return gain_; }
  // S(t_k), formed on request; not unique (any S Q with Q orthogonal gives
  // the same P).
  const Matrix<S>& sqrt_P() const {
    S_ = stacked_.topRows(theta_.size()).transpose();
    return S_;
  }
  // P(t_k) = S S^T, formed on request (exactly symmetric).
  const Matrix<S>& P() const {
    const Matrix<S>& root = sqrt_P();
    P_.noalias() = root * root.transpose();
    for (Eigen::Index j = 1; j < P_.cols(); ++j) {
      for (Eigen::Index i = 0; i < j; ++i) P_(i, j) = P_(j, i);
    }
    return P_;
  }
  const Adaptation<S>& adaptation() const { return adaptation_; }
  // N of the compile-time-size step in use, 0 for the runtime-size one.
  int fixed_size() const { return fixed_np_; }

 private:
  using Step = S (PotterUpdate::*)(const S*, S);

  // The step for np = N (step_size.hpp) on st[k * n + i] = S(i, k), the
  // rows of stacked_'s top block.
  template <int N>
  S step(const S* phi, S target) {
    const int n = step_size<N>(theta_.size());
    Working<S, N> theta(theta_.data(), true), f(f_.data(), false),
        sf(s_f_.data(), false), gain(gain_.data(), false);
    Working<S, array_size(N, N)> st(stacked_.data(), true);
    predict<N>(st);
    S prediction = 0;
#pragma GCC unroll 8
    for (int i = 0; i < n; ++i) prediction += phi[i] * theta[i];
    const S error = target - prediction;
    // f = S^-T phi (3.73c), beta (3.73e), alpha (3.73f).
    multiply_transposed(n, st, phi, f);
    S ff = 0;
#pragma GCC unroll 8
    for (int k = 0; k < n; ++k) ff += f[k] * f[k];
    const S lambda = lambda_;
    const S beta = lambda + ff;
    const S alpha = beta + std::sqrt(lambda * beta);
    // S^- f, the gain (3.73h) and theta (3.73g).
#pragma GCC unroll 8
    for (int i = 0; i < n; ++i) sf[i] = 0;
#pragma GCC unroll 8
    for (int k = 0; k < n; ++k) {
#pragma GCC unroll 8
      for (int i = 0; i < n; ++i) sf[i] += f[k] * st[k * n + i];
    }
#pragma GCC unroll 8
    for (int i = 0; i < n; ++i) {
      gain[i] = sf[i] / beta;
      theta[i] += gain[i] * error;
    }
    // S = S^- (I - f f^T / alpha) (3.73i), / sqrt(lambda) for the
    // forgetting factor.
    const S shrink = shrink_;
#pragma GCC unroll 8
    for (int k = 0; k < n; ++k) {
      const S c = f[k] / alpha;
#pragma GCC unroll 8
      for (int i = 0; i < n; ++i) st[k * n + i] -= c * sf[i];
      if (shrink != S(1)) {
#pragma GCC unroll 8
        for (int i = 0; i < n; ++i) st[k * n + i] *= shrink;
      }
    }
    st.write_back();
    theta.write_back();
    gain.write_back();
    innovation_scale_ = beta;
    return error;
  }

  // S S^T + Qn = [S^T; Qn^(T/2)]^T [S^T; Qn^(T/2)] = R^T R, eq. (3.73b):
  // the orthogonal T is a product of Householder reflections, applied in
  // place on a (stacked_ itself at runtime size); R is the new S^T (upper
  // triangular).
  template <int N, typename Square>
  void predict(Square& st) {
    const int r = int(qn_root_t_.rows());
    if (r == 0) return;
    const int n = step_size<N>(theta_.size());
    Working<S, array_size(array_size(2, N), N)> a(stacked_.data(), false);
#pragma GCC unroll 64
    for (int i = 0; i < n * n; ++i) a[i] = st[i];
    const S* q = qn_root_t_.data();  // column-major, r-by-n
    for (int k = 0; k < r; ++k) {
#pragma GCC unroll 8
      for (int i = 0; i < n; ++i) a[(n + k) * n + i] = q[i * r + k];
    }
    if constexpr (N != Eigen::Dynamic) {
      // The local array's rows below n + r are never read; defined so
      // that the compiler sees no uninitialised value.
      for (int i = (n + r) * n; i < 2 * n * n; ++i) a[i] = 0;
    }
    triangularize<N>(a, n + r);
#pragma GCC unroll 8
    for (int k = 0; k < n; ++k) {
#pragma GCC unroll 8
      for (int i = 0; i < n; ++i) st[k * n + i] = i < k ? S(0) : a[k * n + i];
    }
  }

  // Overwrites the upper triangle of the first n rows of a (m-by-n,
  // row-major) with R of a = Q R (R's diagonal may be negative: R^T R =
  // a^T a is what matters); the entries below it are left as workspace.
  template <int N, typename Rows>
  void triangularize(Rows& a, int m) const {
    const int n = step_size<N>(theta_.size());
#pragma GCC unroll 8
    for (int j = 0; j < n; ++j) {
      S norm2 = 0;
      for (int i = j; i < m; ++i) norm2 += a[i * n + j] * a[i * n + j];
      if (!(norm2 > 0)) continue;
      const S norm = std::sqrt(norm2);
      const S x = a[j * n + j];
      const S diagonal = x > 0 ? -norm : norm;
      a[j * n + j] = x - diagonal;  // v = x - diagonal e_j, |v_j| >= norm
      const S v_norm2 = a[j * n + j] * a[j * n + j] + (norm2 - x * x);
#pragma GCC unroll 8
      for (int k = j + 1; k < n; ++k) {
        S dot = 0;
        for (int i = j; i < m; ++i) dot += a[i * n + j] * a[i * n + k];
        const S f = 2 * dot / v_norm2;
        for (int i = j; i < m; ++i) a[i * n + k] -= f * a[i * n + j];
      }
      a[j * n + j] = diagonal;
    }
  }

  Adaptation<S> adaptation_;
  S lambda_ = 1;  // forgetting factor (1 for the Kalman filter)
  S innovation_scale_ = 1;
  Matrix<S> qn_root_t_;  // Qn^(T/2), rank-by-np
  Vector<S> theta_;
  mutable Matrix<S> S_;
  mutable Matrix<S> P_;
  // [S^T; Qn^(T/2)], row-major: the top rows are S^T (the state), the
  // bottom ones the workspace of the time update.
  RowMatrix stacked_;
  Vector<S> f_;
  Vector<S> s_f_;
  Vector<S> gain_;
  Vector<S> phi_copy_;  // phi when not contiguous
  S shrink_ = 1;        // 1 / sqrt(lambda)
  Step step_ = nullptr;
  int fixed_np_ = 0;
};

}  // namespace ctid
