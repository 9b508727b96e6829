// SPDX-License-Identifier: BSD-3-Clause
// Copyright (C) the ctid authors
// Physical realisations of residtrace models: two nonlinear
// simulators whose nonlinearity acts on a state that is not measured, so
// that the model has no regression form and is fitted on its simulation
// error (apps/residtrace/physical_fit.hpp).
//
// End stop ("stop"): F(p) x = sum_j B_j(p) w_j in observable canonical
// form, x1 = x, x1' = -f1 x1 + x2 + ..., every channel of relative degree
// at least two (b_(1) = 0), so the velocity x1' = -f1 x1 + x2 is a function
// of the state. The position x1 is limited to [lo, hi]: a sub-step that
// crosses a level ends at it with the velocity zero (x1 = L, x2 = f1 L, an
// inelastic stop); while held, x1 and x2 stay and the states 3..n evolve
// (x3' = x4 - f3 L + (B w)_3, ...); the stop is left at the start of a
// sampling interval when the acceleration x2' = -f2 L + x3 + (B w)_2
// points away from it. Every step is exact for the channels held over the
// interval (ZOH, thesis App. A.1, eq. A.6: [Phi Gamma] = expm([A I; 0 0]
// h)); `substeps` sub-steps are taken only in the intervals where a level
// is crossed. Starts at rest at x = 0, clipped to the levels.
//
// Cascade ("cascade"): two first-order sections with the nonlinearity at
// the inner node,
//   z' = q - alpha g(z),  0 <= z <= hi,   h' = g(z) - gamma g(h),
//   h <= ho,  y = c + h,  q = sum_j b_j w_j + d,
// g = sqrt (two tanks with Torricelli outflows; z and h kept >= 0) or
// g(s) = s (a linear cascade; z and h limited above only). An upper
// level of h is a lower tank that overflows: the water above is lost.
// The water that a projection of z onto hi removes in a sub-step (an
// upper tank that overflows) is lost but for a share `spill` in [0, 1]
// that falls into the lower section (added to h, converted by 1/alpha:
// z's outflow alpha g(z) is h's inflow g(z)). Classical Runge-Kutta
// in `substeps` sub-steps per sample, the states projected onto their
// bounds after each; starts at the given levels z0, h0 (projected onto
// their bounds) or, without them, at rest for the first sample's inflow
// (max(q_1, 0)). Several parameter sets of one structure are simulated side
// by side (one column each), in one pass over the samples.
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "ctid/base/status.hpp"
#include "ctid/base/types.hpp"
#include "ctid/filters/discretization.hpp"

namespace ctid {

template <typename S>
struct EndStopConfig {
  Vector<S> f;  // f1..fn of the monic F (n >= 2)
  Matrix<S> b;  // n-by-m: column j holds B_j right-aligned, b(0, j) = 0
  S ts = 1;     // sampling interval (s)
  S lo = -std::numeric_limits<S>::infinity();  // levels of x1
  S hi = std::numeric_limits<S>::infinity();
  int substeps = 1;  // sub-steps in the intervals where a level is crossed
};

// W: num_samples-by-m channel signals (column-major, already delayed),
// held over each sampling interval. x: num_samples values of x1 at the
// sampling instants (before the interval's step).
template <typename S>
Status simulate_end_stop(const EndStopConfig<S>& c, const S* W,
                         long num_samples, S* x_out) {
  const Eigen::Index n = c.f.size();
  const Eigen::Index m = c.b.cols();
  if (n < 2) return bad_input("an end stop needs a model of order >= 2");
  if (c.b.rows() != n) {
    return dimension_mismatch("b must have one row per coefficient of F");
  }
  if (num_samples < 0 || (num_samples > 0 && m > 0 && W == nullptr)) {
    return bad_input("channel signals missing");
  }
  if (!(c.ts > 0) || c.substeps < 1) {
    return bad_input("ts must be > 0 and substeps >= 1");
  }
  if (!(c.lo <= c.hi)) return bad_input("the levels must satisfy lo <= hi");
  for (Eigen::Index j = 0; j < m; ++j) {
    if (c.b(0, j) != 0) {
      return bad_input("every channel needs a relative degree of at least 2");
    }
  }
  Matrix<S> A = Matrix<S>::Zero(n, n);
  A.col(0) = -c.f;
  A.topRightCorner(n - 1, n - 1).setIdentity();
  const Matrix<S> I = Matrix<S>::Identity(n, n);
  Matrix<S> Ad, Gd, As, Gs;
  const int ns = c.substeps;
  zoh_discretize<S>(A, I, c.ts, Ad, Gd);
  zoh_discretize<S>(A, I, c.ts / ns, As, Gs);
  // held: x1, x2 fixed; the states 3..n form a chain of integrators
  const Eigen::Index nh = n - 2;
  Matrix<S> Ahd, Ghd, Ahs, Ghs;
  if (nh > 0) {
    Matrix<S> Ah = Matrix<S>::Zero(nh, nh);
    if (nh > 1) Ah.topRightCorner(nh - 1, nh - 1).setIdentity();
    const Matrix<S> Ih = Matrix<S>::Identity(nh, nh);
    zoh_discretize<S>(Ah, Ih, c.ts, Ahd, Ghd);
    zoh_discretize<S>(Ah, Ih, c.ts / ns, Ahs, Ghs);
  }
  const S lo = c.lo;
  const S hi = c.hi;
  const S f1 = c.f(0);
  const S f2 = c.f(1);
  Vector<S> x = Vector<S>::Zero(n);
  Vector<S> xn(n), uk(n), wk(m), vh(nh > 0 ? nh : 0);
  int held = 0;
  if (S(0) > hi) {
    x(0) = hi;
    x(1) = f1 * hi;
    held = 1;
  } else if (S(0) < lo) {
    x(0) = lo;
    x(1) = f1 * lo;
    held = -1;
  }
  auto held_step = [&](const Matrix<S>& Ph, const Matrix<S>& Gh) {
    const S L = x(0);
    for (Eigen::Index i = 0; i < nh; ++i) vh(i) = uk(2 + i) - c.f(2 + i) * L;
    const Vector<S> xh = Ph * x.tail(nh) + Gh * vh;
    x.tail(nh) = xh;
  };
  for (long k = 0; k < num_samples; ++k) {
    x_out[k] = x(0);
    for (Eigen::Index j = 0; j < m; ++j) wk(j) = W[k + j * num_samples];
    uk.noalias() = c.b * wk;
    if (held != 0) {
      const S L = x(0);
      S acc = -f2 * L + uk(1);
      if (n > 2) acc += x(2);
      const int sg = (acc > 0) - (acc < 0);
      if (sg == held || acc == 0) {
        if (nh > 0) held_step(Ahd, Ghd);  // at the stop the whole interval
        continue;
      }
      held = 0;  // it leaves the stop
    }
    xn.noalias() = Ad * x + Gd * uk;
    if (xn(0) <= hi && xn(0) >= lo) {
      x = xn;
      continue;
    }
    // a level is crossed within the interval: sub-steps
    for (int s = 0; s < ns; ++s) {
      if (held == 0) {
        xn.noalias() = As * x + Gs * uk;
        x = xn;
        if (x(0) > hi) {
          held = 1;
          x(0) = hi;
        } else if (x(0) < lo) {
          held = -1;
          x(0) = lo;
        }
        if (held != 0) x(1) = f1 * x(0);
      } else if (nh > 0) {
        held_step(Ahs, Ghs);
      }
    }
  }
  return Status::Ok();
}

template <typename S>
struct CascadeConfig {
  bool sqrt_nodes = true;  // g = sqrt (else g(s) = s)
  Matrix<S> b;             // m-by-K: channel gains, one column per set
  Vector<S> d;             // K constant inflows
  Vector<S> alpha;         // K inner outflow coefficients
  Vector<S> gamma;         // K outflow coefficients
  Vector<S> hi;            // K upper levels of z (+inf: none)
  Vector<S> ho;            // K upper levels of h (empty or +inf: none)
  Vector<S> spill;         // K shares in [0, 1] of z's overflow that
                           // fall into h (empty: 0, all lost)
  Vector<S> c;             // K output levels
  Vector<S> z0;            // K initial inner states (empty: at rest)
  Vector<S> h0;            // K initial states of h (empty: at rest)
  S ts = 1;
  int substeps = 1;
};

// W: num_samples-by-m channel signals (column-major, already delayed).
// y, z: num_samples-by-K (column-major) outputs and inner states at the
// sampling instants; z may be null. min/max ignore a NaN operand (fmin,
// fmax), as Octave's do.
template <typename S>
Status simulate_cascade(const CascadeConfig<S>& c, const S* W, long num_samples,
                        S* y, S* z_out) {
  const Eigen::Index m = c.b.rows();
  const Eigen::Index K = c.b.cols();
  if (K < 1) return bad_input("at least one parameter set");
  if (c.d.size() != K || c.alpha.size() != K || c.gamma.size() != K ||
      c.hi.size() != K || c.c.size() != K) {
    return dimension_mismatch("d, alpha, gamma, hi, c need one entry per set");
  }
  if (c.ho.size() != 0 && c.ho.size() != K) {
    return dimension_mismatch("ho: empty or one entry per set");
  }
  if (c.spill.size() != 0 && c.spill.size() != K) {
    return dimension_mismatch("spill: empty or one entry per set");
  }
  for (Eigen::Index i = 0; i < c.spill.size(); ++i) {
    if (!(c.spill(i) >= 0 && c.spill(i) <= 1)) {
      return bad_input("spill must lie in [0, 1]");
    }
  }
  if (c.z0.size() != c.h0.size() || (c.z0.size() != 0 && c.z0.size() != K)) {
    return dimension_mismatch("z0 and h0: both empty or one entry per set");
  }
  if (num_samples < 0 || (num_samples > 0 && m > 0 && W == nullptr)) {
    return bad_input("channel signals missing");
  }
  if (!(c.ts > 0) || c.substeps < 1) {
    return bad_input("ts must be > 0 and substeps >= 1");
  }
  if (num_samples == 0) return Status::Ok();
  const long N = num_samples;
  const S h = c.ts / c.substeps;
  const S h2 = h / 2;
  const S h6 = h / 6;
  Vector<S> q(K), z(K), hh(K);
  auto inflow = [&](long k) {
    for (Eigen::Index i = 0; i < K; ++i) {
      S s = 0;
      for (Eigen::Index j = 0; j < m; ++j) s += W[k + j * N] * c.b(j, i);
      q(i) = s + c.d(i);
    }
  };
  inflow(0);
  const bool given = c.z0.size() == K;
  for (Eigen::Index i = 0; given && i < K; ++i) {
    const S lo = c.sqrt_nodes ? S(0) : -std::numeric_limits<S>::infinity();
    z(i) = std::fmin(std::fmax(c.z0(i), lo), c.hi(i));
    hh(i) = c.sqrt_nodes ? std::fmax(c.h0(i), S(0)) : c.h0(i);
  }
  const S inf = std::numeric_limits<S>::infinity();
  auto outer_top = [&](Eigen::Index i) { return c.ho.size() ? c.ho(i) : inf; };
  for (Eigen::Index i = 0; !given && i < K; ++i) {
    const S q1 = std::fmax(q(i), S(0));
    if (c.sqrt_nodes) {
      const S a = q1 / c.alpha(i);
      z(i) = std::fmin(a * a, c.hi(i));
      const S g = std::sqrt(z(i)) / c.gamma(i);
      hh(i) = g * g;
    } else {
      z(i) = std::fmin(q1 / c.alpha(i), c.hi(i));
      hh(i) = z(i) / c.gamma(i);
    }
  }
  for (Eigen::Index i = 0; i < K; ++i) {
    hh(i) = std::fmin(hh(i), outer_top(i));
  }
  auto pos = [](S v) { return std::sqrt(std::fmax(v, S(0))); };
  for (long k = 0; k < N; ++k) {
    if (k > 0) inflow(k);
    for (Eigen::Index i = 0; i < K; ++i) {
      y[k + i * N] = hh(i);
      if (z_out != nullptr) z_out[k + i * N] = z(i);
    }
    for (Eigen::Index i = 0; i < K; ++i) {
      const S qk = q(i);
      const S al = c.alpha(i);
      const S ga = c.gamma(i);
      const S top = c.hi(i);
      const S otop = outer_top(i);
      // share of the water over the inner level that reaches h, in h's
      // units (z's outflow alpha g(z) is h's inflow g(z))
      const S spill = c.spill.size() ? c.spill(i) / al : S(0);
      S zi = z(i);
      S hi_ = hh(i);
      if (c.sqrt_nodes) {
        for (int s = 0; s < c.substeps; ++s) {
          const S o1 = pos(zi);
          const S a1 = qk - al * o1;
          const S b1 = o1 - ga * pos(hi_);
          S za = zi + h2 * a1;
          S ha = hi_ + h2 * b1;
          const S o2 = pos(za);
          const S a2 = qk - al * o2;
          const S b2 = o2 - ga * pos(ha);
          za = zi + h2 * a2;
          ha = hi_ + h2 * b2;
          const S o3 = pos(za);
          const S a3 = qk - al * o3;
          const S b3 = o3 - ga * pos(ha);
          za = zi + h * a3;
          ha = hi_ + h * b3;
          const S o4 = pos(za);
          const S a4 = qk - al * o4;
          const S b4 = o4 - ga * pos(ha);
          const S zn = std::fmax(zi + h6 * (a1 + 2 * a2 + 2 * a3 + a4), S(0));
          zi = std::fmin(zn, top);
          hi_ = std::fmin(std::fmax(hi_ + h6 * (b1 + 2 * b2 + 2 * b3 + b4) +
                                        spill * (zn - zi),
                                    S(0)),
                          otop);
        }
      } else {
        for (int s = 0; s < c.substeps; ++s) {
          const S a1 = qk - al * zi;
          const S b1 = zi - ga * hi_;
          S za = zi + h2 * a1;
          S ha = hi_ + h2 * b1;
          const S a2 = qk - al * za;
          const S b2 = za - ga * ha;
          za = zi + h2 * a2;
          ha = hi_ + h2 * b2;
          const S a3 = qk - al * za;
          const S b3 = za - ga * ha;
          za = zi + h * a3;
          ha = hi_ + h * b3;
          const S a4 = qk - al * za;
          const S b4 = za - ga * ha;
          const S zn = zi + h6 * (a1 + 2 * a2 + 2 * a3 + a4);
          zi = std::fmin(zn, top);
          hi_ = std::fmin(
              hi_ + h6 * (b1 + 2 * b2 + 2 * b3 + b4) + spill * (zn - zi), otop);
        }
      }
      z(i) = zi;
      hh(i) = hi_;
    }
  }
  for (Eigen::Index i = 0; i < K; ++i) {
    for (long k = 0; k < N; ++k) y[k + i * N] += c.c(i);
  }
  return Status::Ok();
}

}  // namespace ctid
