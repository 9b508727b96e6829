// SPDX-License-Identifier: BSD-3-Clause
// Copyright (C) the ctid authors

// The prefilter of residtrace's SRIVC iterations: a stable denominator Fp
// with well separated roots for the prefilter 1/Fp(p) and the auxiliary
// model, built from the current model's denominator F. Only the prefilter
// changes; the model keeps its own F.
//
//   - roots of F at the origin (integrators of the model, |r| below 1e-9
//     of the largest root or wlo) are moved to -wlo, wlo the lower edge of
//     the band the record excites: an integrator has no stable prefilter
//     of its own;
//   - roots in the right half-plane are reflected into the left one (as
//     the SRIVC iterations reflect an unstable auxiliary model, thesis
//     sec. 2.3.3), and every root gets a damping of at least 1e-3
//     (Re r <= -1e-3 |r|);
//   - a complex pair gets an imaginary part of at least 5e-3 |r|, and roots
//     closer than 1e-2 of their modulus to another are moved apart (the
//     one of larger modulus, or the later one of equal modulus, scaled by
//     1.02; at most ten passes): near-equal roots make the filtered
//     regressors nearly collinear.
//
// The roots are taken in a fixed order (by modulus, then by imaginary
// part) before they are separated, so that the result does not depend on
// the order in which an eigenvalue solver returns them.
#pragma once

#include <algorithm>
#include <cmath>
#include <complex>
#include <vector>

#include "ctid/base/polynomial.hpp"
#include "ctid/base/status.hpp"
#include "ctid/base/types.hpp"

namespace ctid::residtrace {

// Fp (descending powers, monic) from F (descending powers, F(0) != 0) and
// the band's lower edge wlo > 0 (head of this file).
template <typename S>
Status prefilter_denominator(const Vector<S>& F, S wlo, Vector<S>* Fp) {
  using C = std::complex<S>;
  if (Fp == nullptr) return bad_input("no result");
  if (F.size() < 1 || !F.allFinite() || F(0) == 0) {
    return bad_input("F must be finite with a nonzero leading coefficient");
  }
  if (!(wlo > 0) || !std::isfinite(wlo)) {
    return bad_input("the band's lower edge must be finite and > 0");
  }
  const Eigen::Index n = F.size() - 1;
  std::vector<C> r;
  if (n > 0) {
    Vector<S> ascending(n + 1);
    for (Eigen::Index i = 0; i <= n; ++i) ascending(i) = F(n - i);
    const auto z = polynomial_roots<S>(ascending);
    r.assign(z.data(), z.data() + z.size());
  }
  S scale = wlo;
  for (const C& x : r) scale = std::max(scale, std::abs(x));
  for (C& x : r) {
    if (std::abs(x) < S(1e-9) * scale) x = C(-wlo, 0);
    const S m = std::abs(x);
    x = C(std::min(-std::abs(x.real()), S(-1e-3) * m), x.imag());
  }
  // each real root, and each complex pair once (its upper member)
  std::vector<C> u;
  for (const C& x : r) {
    if (x.imag() >= 0) u.push_back(x);
  }
  std::stable_sort(u.begin(), u.end(), [](const C& a, const C& b) {
    const S ma = std::abs(a), mb = std::abs(b);
    return ma < mb || (ma == mb && a.imag() < b.imag());
  });
  const S s = S(1e-2);
  std::vector<bool> pair(u.size());
  for (std::size_t k = 0; k < u.size(); ++k) {
    pair[k] = u[k].imag() > 0;
    const S m = std::abs(u[k]);
    if (pair[k] && u[k].imag() < s / 2 * m) u[k] = C(u[k].real(), s / 2 * m);
  }
  for (int pass = 0; pass < 10; ++pass) {
    bool moved = false;
    for (std::size_t i = 0; i < u.size(); ++i) {
      for (std::size_t j = i + 1; j < u.size(); ++j) {
        const S m = std::max(std::abs(u[i]), std::abs(u[j]));
        if (std::abs(u[i] - u[j]) < s * m) {
          u[j] *= 1 + 2 * s;
          moved = true;
        }
      }
    }
    if (!moved) break;
  }
  Eigen::Index count = 0;
  for (std::size_t i = 0; i < u.size(); ++i) count += pair[i] ? 2 : 1;
  if (count != n) {
    return numerical_failure("the roots of F are not in conjugate pairs");
  }
  Eigen::Matrix<C, Eigen::Dynamic, 1> all(n);
  Eigen::Index k = 0;
  for (std::size_t i = 0; i < u.size(); ++i) {
    all(k++) = u[i];
    if (pair[i]) all(k++) = std::conj(u[i]);
  }
  *Fp = monic_from_roots<S>(all).real();
  return Status::Ok();
}

}  // namespace ctid::residtrace
