// SPDX-License-Identifier: BSD-3-Clause
// Copyright (C) the ctid authors
// The physical reading of a residtrace model (model.hpp): a list of named
// quantities with their standard deviations (NaN when not available),
//
//   the static gain B1(0)/F(0) (with r integrators, the gain of the rest:
//     the last coefficients of B1 and of F without its r trailing zeros),
//   each pole as a time constant -1/p (real) or natural frequency |p| and
//     damping ratio -Re(p)/|p| (a complex pair), the zeros of B1, the delay
//     (nk + f) Ts of the first channel,
//   for a numerator b0 alone with one integrator and order 2, the mass 1/b0
//     and the viscous coefficient f1/b0 (F = [1 f1 0]: m v' + f1/b0 v =
//     u/b0),
//   a node's poles and levels, each added channel in input units of the
//     first (offset b_c/b0, Coulomb level -b_s/b0, coefficients b_k/b0),
//     the output terms, the diagonal of the drift's Qn, the parameters of a
//     physical realisation and the order of the AR noise model.
//
// The standard deviation of a ratio a/b is the first-order delta method
// from the SRIVC covariance (var a/b^2 + a^2 var b/b^4 - 2 a cov(a,b)/b^3,
// negative or not-a-number values read as 0); those of a realisation's
// parameters are the square roots of its covariance's diagonal (alpha and
// gamma are fitted as logarithms: their std is the value times that of
// the logarithm).
#pragma once

#include <algorithm>
#include <cmath>
#include <complex>
#include <limits>
#include <string>
#include <vector>

#include "ctid/apps/residtrace/model.hpp"
#include "ctid/base/polynomial.hpp"
#include "ctid/base/types.hpp"

namespace ctid::residtrace {

// A named quantity: its value (a number, a complex zero or pole, a pair
// [lo hi]) and its standard deviation.
template <typename S>
struct PhysicalQuantity {
  std::string name;
  std::vector<std::complex<S>> value;
  S std = std::numeric_limits<S>::quiet_NaN();
};

// What the reading takes beyond the model: the channels' names (labels of
// the added channels), the diagonal of the drift's Qn (empty: no drift)
// and the standard deviations of a physical realisation's parameters, one
// a parameter (NaN: no covariance).
template <typename S>
struct ReadingLabels {
  std::vector<std::string> channel_names;
  Vector<S> drift_q;
  Vector<S> phys_std;
};

namespace reading_detail {

// The entry (i, j) of C (0-based), NaN outside.
template <typename S>
S entry(const Matrix<S>& C, Eigen::Index i, Eigen::Index j) {
  if (i < 0 || j < 0 || i >= C.rows() || j >= C.cols()) {
    return std::numeric_limits<S>::quiet_NaN();
  }
  return C(i, j);
}

// The std of a / b by the delta method (a NaN variance reads as 0).
template <typename S>
S ratio_std(S a, S b, S va, S vb, S cab) {
  const S v =
      va / (b * b) + a * a * vb / (b * b * b * b) - 2 * a * cab / (b * b * b);
  return std::sqrt(std::fmax(v, S(0)));
}

template <typename S>
S at(const Vector<S>& v, Eigen::Index i) {
  return i >= 0 && i < v.size() ? v(i) : std::numeric_limits<S>::quiet_NaN();
}

template <typename S>
S last(const Vector<S>& v) {
  return at(v, v.size() - 1);
}

}  // namespace reading_detail

// The physical reading of the model m sampled at ts (see the top).
template <typename S>
std::vector<PhysicalQuantity<S>> physical_reading(const ResidtraceModel<S>& m,
                                                  S ts,
                                                  const ReadingLabels<S>& x) {
  using reading_detail::entry;
  using reading_detail::last;
  using reading_detail::ratio_std;
  using C = std::complex<S>;
  const S nan = std::numeric_limits<S>::quiet_NaN();
  std::vector<PhysicalQuantity<S>> p;
  auto add = [&](const std::string& name, std::vector<C> value, S sd) {
    p.push_back(PhysicalQuantity<S>{name, std::move(value), sd});
  };
  if (m.channels.empty() || m.F.size() < 2) return p;
  const Vector<S>& F = m.F;
  const Eigen::Index n = F.size() - 1;
  const Matrix<S>& cov = m.estimate.cov;
  // positions in theta: the free f's, then each channel's nb b's
  Eigen::Index nfree = 0;
  std::vector<Eigen::Index> free_index(m.fixed.size(), -1);
  for (std::size_t i = 0; i < m.fixed.size(); ++i) {
    if (!m.fixed[i]) free_index[i] = nfree++;
  }
  std::vector<Eigen::Index> b_last;  // each channel's last b
  Eigen::Index off = nfree;
  for (const StructureChannel<S>& c : m.channels) {
    off += c.nb;
    b_last.push_back(off - 1);
  }
  const StructureChannel<S>& ch1 = m.channels[0];
  const Vector<S>& b = ch1.B;
  const S b0 = last(b);
  Eigen::Index r = 0;
  while (r < n && F(n - r) == 0) ++r;
  if (F(n - r) != 0) {
    const std::string name =
        r > 0 ? "gain after " + std::to_string(r) + " integrator(s)"
              : "static gain";
    add(name, {C(b0 / F(n - r))}, nan);
  }
  const std::vector<C> poles = roots_descending<S>(F);
  std::vector<bool> done(poles.size(), false);
  for (std::size_t k = 0; k < poles.size(); ++k) {
    if (done[k]) continue;
    const C pk = poles[k];
    if (std::abs(pk) == 0) {
      add("pole", {C(0)}, nan);
    } else if (pk.imag() == 0) {
      add("time constant (s)", {C(-1 / pk.real())}, nan);
    } else {
      for (std::size_t j = 0; j < poles.size(); ++j) {
        if (!done[j] &&
            std::abs(poles[j] - std::conj(pk)) < S(1e-9) * std::abs(pk)) {
          done[j] = true;
        }
      }
      const S wn = std::abs(pk);
      add("natural frequency (rad/s)", {C(wn)}, nan);
      add("damping ratio", {C(-pk.real() / wn)}, nan);
    }
    done[k] = true;
  }
  for (const C& z : roots_descending<S>(b)) add("zero", {z}, nan);
  const S f = ch1.kind == ChannelKind::kInput ? ch1.param : S(0);
  if (ch1.nk + f > 0) add("delay (s)", {C((ch1.nk + f) * ts)}, nan);
  const Eigen::Index ib0 = b_last[0];
  if (b.size() == 1 && r == 1 && n == 2) {
    add("mass 1/b0", {C(1 / b0)},
        ratio_std<S>(1, b0, 0, entry(cov, ib0, ib0), 0));
    if (!m.fixed[0]) {
      const Eigen::Index i1 = free_index[0];
      add("viscous coefficient f1/b0", {C(F(1) / b0)},
          ratio_std<S>(F(1), b0, entry(cov, i1, i1), entry(cov, ib0, ib0),
                       entry(cov, i1, ib0)));
    }
  }
  if (ch1.kind == ChannelKind::kNode) {
    for (const C& z : roots_descending<S>(ch1.node_f)) {
      add("pole before the clipped node", {z}, nan);
    }
    add("node levels [lo hi] (input units)", {C(ch1.node_lo), C(ch1.node_hi)},
        nan);
  }
  for (std::size_t j = 1; j < m.channels.size(); ++j) {
    const StructureChannel<S>& c = m.channels[j];
    const std::string label =
        j < x.channel_names.size() ? x.channel_names[j] : std::string();
    const Eigen::Index k = b_last[j];
    std::string name = "gain of " + label + " (b/b0)";
    S sign = 1;
    switch (c.kind) {
      case ChannelKind::kConstant:
        name = "input offset b_c/b0";
        break;
      case ChannelKind::kSignV:
      case ChannelKind::kSignOutput:
        name = "Coulomb level -b_s/b0";
        sign = -1;
        break;
      case ChannelKind::kPower:
        name = "coefficient of " + label + " (b/b0)";
        break;
      case ChannelKind::kOutputPower:
        name = "coefficient of " + label + " in the dynamics (g/b0)";
        break;
      default:
        break;
    }
    const S bk = last(c.B);
    add(name, {C(sign * bk / b0)},
        ratio_std(bk, b0, entry(cov, k, k), entry(cov, ib0, ib0),
                  entry(cov, k, ib0)));
  }
  for (const OutputTerm<S>& o : m.out) {
    using reading_detail::at;
    switch (o.kind) {
      case OutputTermKind::kOffset:
        add("output offset", {C(at(o.c, 0))}, at(o.cstd, 0));
        break;
      case OutputTermKind::kPolynomial:
        add("output c2", {C(at(o.c, 0))}, at(o.cstd, 0));
        add("output c3", {C(at(o.c, 1))}, at(o.cstd, 1));
        break;
      case OutputTermKind::kSaturation:
        add("output saturation [lo hi]", {C(at(o.c, 0)), C(at(o.c, 1))}, nan);
        break;
      case OutputTermKind::kSinusoid:
        add("disturbance frequency (Hz)", {C(o.omega / (2 * S(M_PI)))}, nan);
        add("disturbance amplitude", {C(std::hypot(at(o.c, 0), at(o.c, 1)))},
            o.cstd.size() ? std::sqrt(o.cstd.squaredNorm() /
                                      static_cast<S>(o.cstd.size()))
                          : nan);
        break;
    }
  }
  for (Eigen::Index k = 0; k < x.drift_q.size(); ++k) {
    const std::string i = std::to_string(k + 1);
    add("Qn(" + i + "," + i + ")", {C(x.drift_q(k))}, nan);
  }
  if (m.has_phys) {
    using reading_detail::at;
    const PhysicalModel<S>& P = m.phys;
    const Vector<S>& sd = x.phys_std;
    if (P.kind == PhysicalKind::kStop) {
      const S lv[2] = {P.lo, P.hi};
      Eigen::Index k =
          sd.size() - 1 - std::isfinite(P.lo) - std::isfinite(P.hi);
      for (int s = 0; s < 2; ++s) {
        if (!std::isfinite(lv[s])) continue;
        ++k;
        add(s == 0 ? "lower end stop" : "upper end stop", {C(lv[s])},
            at(sd, k));
      }
    } else {
      const Eigen::Index nc = static_cast<Eigen::Index>(m.channels.size());
      add("inner outflow coefficient alpha", {C(P.alpha)},
          P.alpha * at(sd, nc + 1));
      add("outflow coefficient gamma", {C(P.gamma)}, P.gamma * at(sd, nc + 2));
      add("constant inflow d", {C(P.d)}, at(sd, nc));
      if (std::isfinite(P.hi)) {
        add("inner state's upper level", {C(P.hi)}, last(sd));
      }
      add("output level c", {C(P.c)}, P.sqrt_nodes ? at(sd, nc + 3) : nan);
    }
  }
  if (m.noise.size() > 0) {
    add("AR noise order", {C(static_cast<S>(m.noise.size() - 1))}, nan);
  }
  return p;
}

}  // namespace ctid::residtrace
