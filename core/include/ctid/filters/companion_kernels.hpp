// SPDX-License-Identifier: BSD-3-Clause
// Copyright (C) the ctid authors
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
//   discretization.hpp; Discretisation::kTrapezoid):
//   Phi = (I - h/2 F)^-1 (I + h/2 F), Gamma = (I - h/2 F)^-1 e_n h/2, by a
//   fixed-size LU.
//   Exact first-order hold (Discretisation::kExactFoh): the ZOH kernel of
//   order n + 1 for p D(p), whose companion state for a unit step is
//   [int q, q, q', .., q^(n-1)] with D(p) q = 1: its last n entries are the
//   ZOH of D (Phi, Gamma0), its first n the integral of the step response,
//   which is the response to the unit ramp tau/h times h, so Gamma1 = (first
//   n entries) / h. The dynamic reference is the exponential of the
//   augmented matrix of discretization.hpp.
//
// FilterDiscretization (svf.hpp) picks these kernels once, when configured
// with FilterKernels::kFixedSize and an order up to kMaxFixedOrder; the
// dynamic-size code stays for larger orders and as the reference
// (FilterKernels::kDynamic). The frozen model of YH (frozen_model.hpp),
// whose Phi would change at every sample and be applied to one state,
// advances the state by CompanionZohAdvance below instead (the action of
// the exponential on the state, O(n) per Taylor term).
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <type_traits>

#include "ctid/base/types.hpp"
#include "ctid/filters/discretization.hpp"

namespace ctid {

enum class FilterKernels { kFixedSize, kDynamic };

constexpr int kMaxFixedOrder = 4;

// Column-major n-by-n Phi and n-vector Gamma of the interval h for the
// denominator coefficients d (n values).
template <typename S>
using CompanionDiscretizer = void (*)(const S* d, S h, S* phi, S* gamma);

// The exact FOH: Phi, Gamma0 and Gamma1 (discretization.hpp's form).
template <typename S>
using CompanionFohDiscretizer = void (*)(const S* d, S h, S* phi, S* gamma0,
                                         S* gamma1);

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

// For finite x: e with |x| < 2^e (from the exponent bits: no library
// call), false when x is not finite. Zero and subnormals give the bound of
// the smallest normal exponent.
template <typename S>
bool exponent_bound(S x, int& e) {
  static_assert(std::numeric_limits<S>::is_iec559, "IEEE 754 binary type");
  constexpr int kMantissa = std::numeric_limits<S>::digits - 1;
  constexpr int kBias = std::numeric_limits<S>::max_exponent - 1;
  using Bits = std::conditional_t<sizeof(S) == 8, std::uint64_t, std::uint32_t>;
  Bits bits;
  std::memcpy(&bits, &x, sizeof bits);
  const int biased = int((bits >> kMantissa) & Bits(2 * kBias + 1));
  if (biased == 2 * kBias + 1) return false;  // Inf, NaN
  e = std::max(biased, 1) - kBias + 1;
  return true;
}

// 2^p for p within the normal exponent range.
template <typename S>
S power_of_two(int p) {
  constexpr int kMantissa = std::numeric_limits<S>::digits - 1;
  constexpr int kBias = std::numeric_limits<S>::max_exponent - 1;
  using Bits = std::conditional_t<sizeof(S) == 8, std::uint64_t, std::uint32_t>;
  const Bits bits = Bits(p + kBias) << kMantissa;
  S x;
  std::memcpy(&x, &bits, sizeof x);
  return x;
}

// The first q with theta^(q+1) / (q+1)! <= eps/4 (at most 24), for
// 0 <= theta <= 1 (the loop of companion_zoh, without its dependent chain
// of multiplications: theta against the root of each degree, computed
// once).
template <typename S>
int taylor_degree(S theta) {
  struct Table {
    S limit[25];
    Table() {
      const double tolerance = std::numeric_limits<S>::epsilon() / 4;
      double factorial = 1;
      for (int q = 0; q < 25; ++q) {
        factorial *= q + 1;  // (q + 1)!
        // theta^(q+1)/(q+1)! <= tol  <=>  theta <= (tol (q+1)!)^(1/(q+1)),
        // rounded down one unit so that the test is not looser than the
        // loop's.
        limit[q] = std::nextafter(
            S(std::pow(tolerance * factorial, 1.0 / (q + 1))), S(0));
      }
    }
  };
  static const Table table;
  int q = 0;
  while (q < 24 && theta > table.limit[q]) ++q;
  return q;
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

// The exact FOH of D from the ZOH of p D(p) (see the header comment).
template <int N, typename S>
void companion_foh(const S* d, S h, S* phi, S* gamma0, S* gamma1) {
  constexpr int M = N + 1;
  S augmented[M];
  for (int i = 0; i < N; ++i) augmented[i] = d[i];
  augmented[N] = 0;
  S phi_m[M * M], gamma_m[M];
  companion_zoh<M, S>(augmented, h, phi_m, gamma_m);
  for (int j = 0; j < N; ++j) {  // column-major, the trailing block
    for (int i = 0; i < N; ++i) phi[j * N + i] = phi_m[(j + 1) * M + i + 1];
  }
  const S inverse_h = S(1) / h;
  for (int i = 0; i < N; ++i) {
    gamma0[i] = gamma_m[i + 1];
    gamma1[i] = gamma_m[i] * inverse_h;
  }
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

// The ZOH advance of one state without forming Phi and Gamma (the frozen
// model of YH, whose denominator changes at every sample and whose Phi would
// be applied to a single state):
//
//   z <- exp([F e_n; 0 0] h) [z; v]   (first n entries; App. A.1, eq. A.6).
//
// n = 1: the closed form Phi = e^x, Gamma = (1 - e^x) / d1 with x = -d1 h,
// written without cancellation as Phi = exp(x), Gamma = h expm1(x)/x
// (Gamma = h at x = 0).
// n >= 2: the truncated Taylor series of the action of the augmented
// matrix on one vector, O(n) per term by the companion structure:
//   - a similarity by T = diag(1, rho, .., rho^(n-1)), rho = 2^p (exact in
//     floating point), turns F into rho times the companion matrix of
//     a_k = d_k / rho^k, k = 1..n, and z, v into zh_i = z_i / rho^i,
//     vh = v / rho^n; p is the smallest integer with |a_k| < 1 for every k
//     (so that the 1-norm is of the order of the largest pole, not of
//     d_n h: no squarings where the matrix kernel above needs them);
//   - with tau = rho h, the i-th entry of (tau M)^j [zh; vh] / j! is
//     g_(i+j) tau^j / j!, where g_0..g_(n-1) = zh, g_n = vh - sum_k a_k
//     g_(n-k) and g_j = -sum_k a_k g_(j-k) beyond (the derivatives of the
//     first state of the ODE at the start of the interval), so that
//     zh_i(tau) = sum_(j=0..q) g_(i+j) tau^j / j!.
// The degree q is n plus the first with theta^(q+1)/(q+1)! below a quarter
// of the unit roundoff (the criterion of companion_zoh above), theta = 2 tau, a
// bound of the 1-norm of tau [A e_n] in the scaled coordinates (its column
// sums are |a_k| + 1 < 2 and the input column's 1); when theta > 1 the
// interval is split into 2^s equal steps (at most kMaxSubsteps). These
// depend on tau only and are kept from one call to the next while tau is
// the same.
// prepare() returns false where this does not apply (a coefficient or h not
// finite, rho outside 2^(+-kMaxScaleExponent / n), more substeps; n = 1:
// |x| > 32): the caller then takes the matrix kernels, which behave as
// before there.
template <int N, typename S>
class CompanionZohAdvance {
 public:
  static constexpr int kMaxTerms = 24 + N;
  static constexpr int kMaxSubsteps = 8;
  // The scaling factors rho^(+-i), i <= n, stay within 2^(+-this).
  static constexpr int kMaxScaleExponent =
      std::numeric_limits<S>::max_exponent / 4;

  // Prepares the interval h of D(p) = p^n + d1 p^(n-1) + .. + dn.
  bool prepare(const S* d, S h) {
    if constexpr (N == 1) {
      const S x = -d[0] * h;
      if (!(std::abs(x) <= S(32))) return false;  // NaN too
      // Phi = exp(x) itself: 1 + expm1(x) would cancel where e^x << 1
      // (found by the test at x = -8: 1e-12 relative in Phi).
      const S em1 = std::expm1(x);
      phi_ = std::exp(x);
      gamma_ = x == S(0) ? h : h * (em1 / x);
      return true;
    } else {
      if (!std::isfinite(h)) return false;
      // The smallest p with 2^(p k) > |d_k| for every k, from the binary
      // exponent of each coefficient: |d_k| < 2^e_k.
      int p = -kMaxScaleExponent / N;
      for (int k = 1; k <= N; ++k) {
        int e = 0;
        if (!detail::exponent_bound(d[k - 1], e)) return false;
        const int pk = e >= 0 ? (e + k - 1) / k : -((-e) / k);
        p = std::max(p, pk);
      }
      if (p * N > kMaxScaleExponent) return false;
      const S rho = detail::power_of_two<S>(p);
      const S inv_rho = detail::power_of_two<S>(-p);
      S power = 1;
      for (int k = 1; k <= N; ++k) {
        power *= inv_rho;  // rho^-k, exact
        minus_a_[k - 1] = -(d[k - 1] * power);
      }
      input_scale_ = power;  // rho^-n
      S scale = 1;
      S inverse = 1;
      for (int i = 0; i < N; ++i) {
        scale_[i] = scale;
        inv_scale_[i] = inverse;
        scale *= rho;
        inverse *= inv_rho;
      }
      // The substeps, the degree and tau^j/j! depend on tau = rho h only
      // (theta bounded by 2 tau): kept while tau stays the same (rho is a
      // power of two, so it changes only when a coefficient crosses one).
      const S tau = h * rho;
      if (!(tau == tau_)) {
        S step = tau;
        int substeps = 1;
        while (2 * step > S(1)) {
          if (substeps == kMaxSubsteps) return false;
          substeps *= 2;
          step *= S(0.5);
        }
        tau_ = tau;
        substeps_ = substeps;
        // n more terms than the criterion asks: it bounds the error in
        // the scaled 1-norm, which mixes the components, and the unscaling
        // (rho^i) magnifies what it neglects; the state of component l
        // (and v) first enters component i at the power l - i (n - i), so
        // that each of these paths keeps the criterion's degree beyond its
        // first term (found by the test of the integrator chain d = 0,
        // where rho is the lower clamp and rho h ~ 1e-7 gave degree 2).
        terms_ = detail::taylor_degree<S>(2 * step) + N;
        S c = 1;
        coefficient_[0] = 1;
        for (int j = 1; j <= terms_; ++j) {
          c *= step * detail::reciprocal<S>(j);
          coefficient_[j] = c;
        }
      }
      return true;
    }
  }

  // z <- Phi z + Gamma v for the prepared interval.
  void advance(S* z, S v) const {
    if constexpr (N == 1) {
      z[0] = phi_ * z[0] + gamma_ * v;
    } else {
      S x[N];
#pragma GCC unroll 4
      for (int i = 0; i < N; ++i) x[i] = z[i] * inv_scale_[i];
      const S vh = v * input_scale_;
      const int q = terms_;
      for (int step = 0; step < substeps_; ++step) {
        // The last n derivatives in a window, g[N - 1] the newest, and
        // the sums accumulated as each derivative appears (ascending
        // powers, so that the sums do not wait for the last derivative).
        S g[N], sum[N];
#pragma GCC unroll 4
        for (int i = 0; i < N; ++i) g[i] = x[i];
#pragma GCC unroll 4
        for (int i = 0; i < N; ++i) {
          sum[i] = x[i];
#pragma GCC unroll 4
          for (int l = i + 1; l < N; ++l) {
            if (l - i <= q) sum[i] += coefficient_[l - i] * x[l];
          }
        }
        for (int j = N; j < N + q; ++j) {
          // g_j, the newest derivative added last: the chain from one
          // derivative to the next is one multiply and one add.
          S next = j == N ? vh : S(0);
#pragma GCC unroll 4
          for (int k = N; k >= 1; --k) next += minus_a_[k - 1] * g[N - k];
#pragma GCC unroll 4
          for (int i = 0; i + 1 < N; ++i) g[i] = g[i + 1];
          g[N - 1] = next;
          // g_j enters sum_i with tau^(j-i)/(j-i)!, for j - i <= q.
#pragma GCC unroll 4
          for (int i = 0; i < N; ++i) {
            if (j - i <= q) sum[i] += coefficient_[j - i] * next;
          }
        }
#pragma GCC unroll 4
        for (int i = 0; i < N; ++i) x[i] = sum[i];
      }
#pragma GCC unroll 4
      for (int i = 0; i < N; ++i) z[i] = x[i] * scale_[i];
    }
  }

 private:
  // n = 1
  S phi_ = 1;
  S gamma_ = 0;
  // n >= 2
  S minus_a_[N] = {};
  S scale_[N] = {};
  S inv_scale_[N] = {};
  S input_scale_ = 1;
  S coefficient_[kMaxTerms + 1] = {};
  S tau_ = std::numeric_limits<S>::quiet_NaN();  // of the cached terms
  int terms_ = 0;
  int substeps_ = 1;
};

// The kernels of order n (nullptr when n is outside 1..kMaxFixedOrder, and
// for the exact first-order hold, whose kernel has a second Gamma:
// companion_foh_discretizer below).
template <typename S>
CompanionDiscretizer<S> companion_discretizer(int n, Discretisation rule) {
  if (rule == Discretisation::kExactFoh) return nullptr;
  const bool zoh = rule == Discretisation::kExactZoh;
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
CompanionFohDiscretizer<S> companion_foh_discretizer(int n) {
  switch (n) {
    case 1:
      return &detail::companion_foh<1, S>;
    case 2:
      return &detail::companion_foh<2, S>;
    case 3:
      return &detail::companion_foh<3, S>;
    case 4:
      return &detail::companion_foh<4, S>;
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
