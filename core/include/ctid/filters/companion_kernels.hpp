// Fixed-size (order n = 1..4, known at compile time) kernels of the filters
// refreshed at every sample: the discretisation of the companion system
//
//   z' = F z + e_n s,   F = companion(d),   D(p) = p^n + d1 p^(n-1) + .. + dn
//
// (the state-variable filters, the adaptive prefilter of RSRIVC, eq. 2.19,
// the auxiliary model, eq. 2.16, and the frozen model of YH, eq. 1.60), and
// the propagation of one channel's state, z(t_k) = Phi z(t_(k-1)) + Gamma v.
//
//   ZOH (App. A.1, eq. A.6): exp([F e_n; 0 0] h) = [Phi Gamma; 0 1] with
//       Phi = I + F h Psi,  Gamma = Psi e_n h,
//       Psi = sum_k (F h)^k / (k + 1)!
//   computed by scaling and squaring: h is halved s times until the 1-norm
//   of [F e_n] h is at most 1/2, Psi is the Taylor series truncated where
//   its next term falls below the unit roundoff (Horner form), and each
//   squaring doubles the interval,
//       Phi(2t) = Phi(t)^2,  Gamma(2t) = (Phi(t) + I) Gamma(t).
//   The filters refreshed per sample have h ||F|| of order 0.01-1, where this
//   is 5-15 products of n-by-n matrices, against a Pade approximant with an
//   LU solve on an (n+1)-by-(n+1) matrix of run-time size in Eigen's
//   MatrixExponential (the reference, discretization.hpp, checked against it
//   in tests/core/companion_kernels_test.cpp).
//   Trapezoidal rule (App. A.2, in the physical coordinates of
//   discretization.hpp): Phi = (I - h/2 F)^-1 (I + h/2 F),
//   Gamma = (I - h/2 F)^-1 e_n h/2, by a fixed-size LU.
//
// FilterDiscretization (svf.hpp) picks these kernels once, when configured
// with FilterKernels::kFixedSize and an order up to kMaxFixedOrder; the
// dynamic-size code stays for larger orders and as the reference
// (FilterKernels::kDynamic).
#pragma once

#include <cmath>
#include <limits>

#include "ctid/base/types.hpp"

namespace ctid {

enum class FilterKernels { kFixedSize, kDynamic };

constexpr int kMaxFixedOrder = 4;

// Column-major n-by-n Phi and n-vector Gamma of the interval h for the
// denominator coefficients d (n values).
template <typename S>
using CompanionDiscretizer = void (*)(const S* d, S h, S* phi, S* gamma);

// z <- Phi z + Gamma v, z of n values.
template <typename S>
using CompanionPropagator = void (*)(const S* phi, const S* gamma, S* z, S v);

namespace detail {

// 1/k, k = 0..25 (the Horner steps multiply instead of dividing: a division
// in the dependency chain of each step would dominate its latency).
template <typename S>
S reciprocal(int k) {
  static constexpr double kTable[26] = {
      0,        1,        1.0 / 2,  1.0 / 3,  1.0 / 4,  1.0 / 5,  1.0 / 6,
      1.0 / 7,  1.0 / 8,  1.0 / 9,  1.0 / 10, 1.0 / 11, 1.0 / 12, 1.0 / 13,
      1.0 / 14, 1.0 / 15, 1.0 / 16, 1.0 / 17, 1.0 / 18, 1.0 / 19, 1.0 / 20,
      1.0 / 21, 1.0 / 22, 1.0 / 23, 1.0 / 24, 1.0 / 25};
  return S(kTable[k]);
}

// Row-major n-by-n matrices as plain arrays: the Horner step below works on
// rows, and fully unrolled scalar code is faster than packet code here.
template <int N, typename S>
struct SmallSquare {
  S a[N][N];
};

// out = I + r A X for the companion matrix A = h F: rows 0..n-2 of A X are
// h times rows 1..n-1 of X, its last row is c^T X with c the last row of
// A (n^2 operations instead of n^3).
template <int N, typename S>
inline void identity_plus_companion_times(const S* c, S h, S r,
                                          const SmallSquare<N, S>& X,
                                          SmallSquare<N, S>& out) {
  const S hr = h * r;
  for (int i = 0; i + 1 < N; ++i) {
    for (int j = 0; j < N; ++j) out.a[i][j] = X.a[i + 1][j] * hr;
  }
  for (int j = 0; j < N; ++j) {
    S sum = 0;
    for (int l = 0; l < N; ++l) sum += c[l] * X.a[l][j];
    out.a[N - 1][j] = sum * r;
  }
  for (int i = 0; i < N; ++i) out.a[i][i] += S(1);
}

template <int N, typename S>
void companion_zoh(const S* d, S h, S* phi, S* gamma) {
  // Last row c of A = F h, and the 1-norm of the augmented matrix
  // [F e_n; 0 0] h: the column sums of F h and |h| for the input column.
  S c[N];
  for (int j = 0; j < N; ++j) c[j] = -d[N - 1 - j] * h;
  const S ah = std::abs(h);
  S norm = ah;
  for (int j = 0; j < N; ++j) {
    norm = std::max(norm, std::abs(c[j]) + (j > 0 ? ah : S(0)));
  }
  int squarings = 0;
  if (norm > S(0.5)) {
    // A non-finite norm leaves squarings at 0 and lets NaN propagate, as
    // the reference does.
    squarings = std::max(0, int(std::ceil(std::log2(norm / S(0.5)))));
    const S scale = std::ldexp(S(1), -squarings);
    for (int j = 0; j < N; ++j) c[j] *= scale;
    h *= scale;
    norm *= scale;
  }
  // Degree m of Psi: the first neglected term of exp, norm^(m+1)/(m+1)!,
  // below a quarter of the unit roundoff.
  const S tolerance = std::numeric_limits<S>::epsilon() / 4;
  int m = 0;
  S term = norm;
  while (term > tolerance && m < 24) {
    ++m;
    term *= norm * reciprocal<S>(m + 1);
  }
  // Psi = I + A/2 (I + A/3 (... (I + A/(m+1)))), then Phi = I + A Psi.
  // Two buffers used in turn (a copy of each step's result would be
  // reloaded wider than it was stored, stalling store forwarding).
  SmallSquare<N, S> buffers[2] = {};
  int current = 0;
  for (int i = 0; i < N; ++i) buffers[0].a[i][i] = 1;
  for (int k = m + 1; k >= 2; --k) {
    identity_plus_companion_times<N, S>(c, h, reciprocal<S>(k),
                                        buffers[current], buffers[1 - current]);
    current = 1 - current;
  }
  const SmallSquare<N, S>& psi = buffers[current];
  SmallSquare<N, S> Phi;
  identity_plus_companion_times<N, S>(c, h, S(1), psi, Phi);
  S Gamma[N];
  for (int i = 0; i < N; ++i) Gamma[i] = psi.a[i][N - 1] * h;
  // Doubling the interval: Gamma <- (Phi + I) Gamma, Phi <- Phi^2.
  for (int q = 0; q < squarings; ++q) {
    S g[N];
    for (int i = 0; i < N; ++i) {
      S sum = Gamma[i];
      for (int l = 0; l < N; ++l) sum += Phi.a[i][l] * Gamma[l];
      g[i] = sum;
    }
    for (int i = 0; i < N; ++i) Gamma[i] = g[i];
    SmallSquare<N, S> square;
    for (int i = 0; i < N; ++i) {
      for (int j = 0; j < N; ++j) {
        S sum = 0;
        for (int l = 0; l < N; ++l) sum += Phi.a[i][l] * Phi.a[l][j];
        square.a[i][j] = sum;
      }
    }
    Phi = square;
  }
  for (int j = 0; j < N; ++j) {  // column-major out
    for (int i = 0; i < N; ++i) phi[j * N + i] = Phi.a[i][j];
  }
  for (int i = 0; i < N; ++i) gamma[i] = Gamma[i];
}

// X = (I - h/2 F)^-1; Phi = X (I + h/2 F) = 2 X - I, Gamma = X e_n h/2.
// The inverse of these 1-by-1 to 4-by-4 matrices is Eigen's closed form
// (cofactors), the dynamic reference a partial-pivoting LU.
template <int N, typename S>
void companion_trapezoidal(const S* d, S h, S* phi, S* gamma) {
  using Mat = Eigen::Matrix<S, N, N>;
  using Vec = Eigen::Matrix<S, N, 1>;
  Mat M = Mat::Identity();
  for (int i = 0; i + 1 < N; ++i) M(i, i + 1) = -h / 2;
  for (int j = 0; j < N; ++j) M(N - 1, j) += d[N - 1 - j] * (h / 2);
  const Mat X = M.inverse();
  Mat Phi = 2 * X;
  Phi.diagonal().array() -= S(1);
  Eigen::Map<Mat>{phi} = Phi;
  Eigen::Map<Vec>{gamma} = X.col(N - 1) * (h / 2);
}

template <int N, typename S>
void companion_propagate(const S* phi, const S* gamma, S* z, S v) {
  using Mat = Eigen::Matrix<S, N, N>;
  using Vec = Eigen::Matrix<S, N, 1>;
  Eigen::Map<Vec> state(z);
  const Vec next =
      Eigen::Map<const Mat>(phi) * state + Eigen::Map<const Vec>(gamma) * v;
  state = next;
}

}  // namespace detail

// The kernels of order n (nullptr when n is outside 1..kMaxFixedOrder).
template <typename S>
CompanionDiscretizer<S> companion_discretizer(int n, InterSample rule) {
  const bool zoh = rule == InterSample::kZoh;
  switch (n) {
    case 1:
      return zoh ? &detail::companion_zoh<1, S>
                 : &detail::companion_trapezoidal<1, S>;
    case 2:
      return zoh ? &detail::companion_zoh<2, S>
                 : &detail::companion_trapezoidal<2, S>;
    case 3:
      return zoh ? &detail::companion_zoh<3, S>
                 : &detail::companion_trapezoidal<3, S>;
    case 4:
      return zoh ? &detail::companion_zoh<4, S>
                 : &detail::companion_trapezoidal<4, S>;
    default:
      return nullptr;
  }
}

template <typename S>
CompanionPropagator<S> companion_propagator(int n) {
  switch (n) {
    case 1:
      return &detail::companion_propagate<1, S>;
    case 2:
      return &detail::companion_propagate<2, S>;
    case 3:
      return &detail::companion_propagate<3, S>;
    case 4:
      return &detail::companion_propagate<4, S>;
    default:
      return nullptr;
  }
}

}  // namespace ctid
