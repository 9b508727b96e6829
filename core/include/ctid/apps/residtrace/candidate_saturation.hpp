// SPDX-License-Identifier: BSD-3-Clause
// Copyright (C) the ctid authors

// The saturation candidate of residtrace: a level that a signal of the
// system cannot pass, the level(s) estimated. Its variants:
//
//   - Output saturation (a sensor range, a position at its end stop): y =
//     min(max(x, lo), hi), x the model output; upper, lower or both levels,
//     the side chosen by the BIC of a screening. Fitted as censored data
//     (fit_model): where the model output lies beyond a level the sample
//     tells nothing about the linear part.
//   - Saturation of an inner node (a tank that overflows, a valve at its
//     end stop): the denominator is split into its first-order sections
//     (real poles, complex pairs), F = F_a F_b; the node z = F_a(0) /
//     F_a(p) u (static gain 1: its levels in input units) is clipped and y
//     = B(p) / F_b(p) clip(z) re-estimated by SRIVC. Every split into
//     upstream F_a and downstream F_b is tried (two to four sections, no
//     integrator, one input channel, no fixed coefficient, open loop).
//   - An end stop: the output is a position held at a level with its
//     velocity reset while the model pushes it into the stop (kind "stop"
//     of physical_fit.hpp); tried when the output saturation's screening
//     lowers the BIC by at least 10.
//   - The inner state of a two-section tank cascade that overflows (kind
//     "cascade", cascade_template of physical_model.hpp, square-root and
//     linear nodes) and the same with the outer state limited too; a
//     cascade whose inner state sits at its level on more than half of
//     the samples is dropped (not an overflow: a single tank fed through
//     the spill).
//   The realisations are fitted on their simulation error (thesis eq.
//   1.16), the others by SRIVC (thesis eqs. 2.8-2.13); the variant with
//   the smallest BIC = N log s2 + np log N on the estimation record is
//   kept (select_variant).
//
// Levels: the level minimising the squared error of the current model
// with the clip (for a node its gain refitted by least squares) on a grid
// of 25 quantiles of the clipped signal between its median and its 99.5 %
// quantile (resp. 0.5 %), refined by 12 golden-section steps between the
// grid neighbours of the best one; the side by the screening BIC N log
// (sse / N) + (finite levels) log N. The kept variant's levels are then
// searched again with the fitted model (a node's gain refitted with each
// level) and the model refitted, while its BIC falls (three rounds at
// most). Evidence: the levels, the share of samples at a level, a node's
// upstream poles.
#pragma once

#include <algorithm>
#include <cmath>
#include <complex>
#include <cstdio>
#include <limits>
#include <string>
#include <vector>

#include "ctid/apps/residtrace/candidate.hpp"
#include "ctid/apps/residtrace/model.hpp"
#include "ctid/apps/residtrace/model_fit.hpp"
#include "ctid/apps/residtrace/physical_model.hpp"
#include "ctid/apps/residtrace/simulate.hpp"
#include "ctid/base/polynomial.hpp"
#include "ctid/base/status.hpp"

namespace ctid::residtrace {

namespace saturation_detail {

enum class Side { kUpper, kLower, kBoth };

inline const char* side_name(Side s) {
  return s == Side::kUpper ? "upper" : (s == Side::kLower ? "lower" : "both");
}

template <typename S>
S sum_squares(const Vector<S>& x) {
  S s = 0;
  for (Eigen::Index k = 0; k < x.size(); ++k) s += x(k) * x(k);
  return s;
}

// 25 quantile fractions from 0.5 to 0.995, evenly spaced (built from both
// ends, as Octave's linspace).
template <typename S>
std::vector<S> fractions() {
  const int n = 25;
  const S a = S(0.5), b = S(0.995);
  const S delta = (b - a) / (n - 1);
  std::vector<S> q(n);
  q[0] = a;
  q[n - 1] = b;
  for (int i = 1; i < n / 2; ++i) {
    q[i] = a + i * delta;
    q[n - 1 - i] = b - i * delta;
  }
  q[n / 2] = (a + b) / 2;
  return q;
}

// The level on the quantile grid of z minimising f, refined by a
// golden-section search between its grid neighbours; false when the grid
// has fewer than two distinct values (a flat signal).
template <typename S, typename Fn>
bool best_level(const Fn& f, const Vector<S>& z, bool upper, S* L) {
  std::vector<S> zs(z.data(), z.data() + z.size());
  std::sort(zs.begin(), zs.end());
  const Eigen::Index n = z.size();
  if (n == 0) return false;
  std::vector<S> grid;
  for (S q : fractions<S>()) {
    if (!upper) q = 1 - q;
    const S r = std::round(q * static_cast<S>(n));
    const Eigen::Index i = std::max<Eigen::Index>(
        1, std::min<Eigen::Index>(n, static_cast<Eigen::Index>(r)));
    grid.push_back(zs[i - 1]);
  }
  std::sort(grid.begin(), grid.end());
  grid.erase(std::unique(grid.begin(), grid.end()), grid.end());
  if (grid.size() < 2) return false;
  std::vector<S> v(grid.size());
  std::size_t i = 0;
  for (std::size_t k = 0; k < grid.size(); ++k) {
    v[k] = f(grid[k]);
    if (v[k] < v[i] || (std::isnan(v[i]) && !std::isnan(v[k]))) i = k;
  }
  S lo = grid[i > 0 ? i - 1 : 0];
  S hi = grid[std::min(i + 1, grid.size() - 1)];
  const S g = (std::sqrt(S(5)) - 1) / 2;
  S a = hi - g * (hi - lo), b = lo + g * (hi - lo);
  S fa = f(a), fb = f(b);
  for (int it = 0; it < 12; ++it) {
    if (fa < fb) {
      hi = b;
      b = a;
      fb = fa;
      a = hi - g * (hi - lo);
      fa = f(a);
    } else {
      lo = a;
      a = b;
      fa = fb;
      b = lo + g * (hi - lo);
      fb = f(b);
    }
  }
  *L = grid[i];
  // (Octave's min: a NaN loses against a number)
  const S m = std::isnan(fa) ? fb : (std::isnan(fb) ? fa : std::min(fa, fb));
  if (m < v[i]) *L = fa < fb ? a : b;
  return true;
}

// N log(max(sse, realmin) / N) + (finite levels) log N.
template <typename S>
S bic_of(S sse, Eigen::Index N, int finite_levels) {
  const S n = static_cast<S>(N);
  return n * std::log(std::max(sse, std::numeric_limits<S>::min()) / n) +
         finite_levels * std::log(n);
}

inline int finite_count(double lo, double hi) {
  return (std::isfinite(lo) ? 1 : 0) + (std::isfinite(hi) ? 1 : 0);
}

template <typename S>
Vector<S> clipped(const Vector<S>& x, S lo, S hi) {
  Vector<S> r(x.size());
  for (Eigen::Index k = 0; k < x.size(); ++k) {
    r(k) = std::fmin(std::fmax(x(k), lo), hi);
  }
  return r;
}

// The output's levels [lo hi] on the side(s) that best explain y by the
// clipped model output x; false when a level has no grid.
template <typename S>
bool out_levels(const Vector<S>& y, const Vector<S>& x, Side side, S* lo,
                S* hi) {
  *hi = std::numeric_limits<S>::infinity();
  *lo = -*hi;
  if (side != Side::kLower) {
    auto f = [&](S L) {
      S s = 0;
      for (Eigen::Index k = 0; k < y.size(); ++k) {
        const S d = y(k) - std::fmin(x(k), L);
        s += d * d;
      }
      return s;
    };
    if (!best_level<S>(f, x, true, hi)) return false;
  }
  if (side != Side::kUpper) {
    const S h = *hi;
    auto f = [&](S L) {
      S s = 0;
      for (Eigen::Index k = 0; k < y.size(); ++k) {
        const S d = y(k) - std::fmax(std::fmin(x(k), h), L);
        s += d * d;
      }
      return s;
    };
    if (!best_level<S>(f, x, false, lo)) return false;
  }
  return true;
}

// The side whose output clip has the smallest screening BIC: false when no
// side has a level to try.
template <typename S>
bool best_side(const Vector<S>& y, const Vector<S>& x, S* best, S* lo, S* hi,
               Side* side) {
  *best = std::numeric_limits<S>::infinity();
  bool any = false;
  for (Side s : {Side::kUpper, Side::kLower, Side::kBoth}) {
    S l, h;
    if (!out_levels<S>(y, x, s, &l, &h)) continue;
    const S v = bic_of<S>(sum_squares<S>(Vector<S>(y - clipped<S>(x, l, h))),
                          y.size(), finite_count(l, h));
    if (v < *best) {
      *best = v;
      *lo = l;
      *hi = h;
      *side = s;
      any = true;
    }
  }
  return any;
}

// sum (t - k yb)^2 with the gain k of yb fitted by least squares.
template <typename S>
S gain_sse(const Vector<S>& t, const Vector<S>& yb) {
  const S k = yb.dot(t) / std::max(yb.dot(yb), std::numeric_limits<S>::min());
  return sum_squares<S>(Vector<S>(t - k * yb));
}

// sum (t - [yb 1] c)^2 with c fitted by least squares.
template <typename S>
S affine_sse(const Vector<S>& t, const Vector<S>& yb) {
  Matrix<S> X(yb.size(), 2);
  X.col(0) = yb;
  X.col(1).setOnes();
  const Vector<S> c = X.completeOrthogonalDecomposition().solve(t);
  return sum_squares<S>(Vector<S>(t - X * c));
}

// The response of F(end) / F(p) (static gain 1) to w from rest with the
// hold rule.
template <typename S>
Status unit_gain_response(const Vector<S>& F, const Vector<S>& w, S ts,
                          InterSample rule, Vector<S>* x) {
  const Eigen::Index n = F.size() - 1;
  ModelOrders orders;
  orders.na = static_cast<int>(n);
  orders.nb.push_back(1);
  orders.nk.push_back(0);
  Matrix<S> theta(1, n + 1);
  for (Eigen::Index i = 0; i < n; ++i) theta(0, i) = F(i + 1) / F(0);
  theta(0, n) = F(n) / F(0);
  return simulate_detail::ltv_simulate<S>(orders, rule, Matrix<S>(w), ts, theta,
                                          x);
}

// Octave's num2str (v, prec) of a row of numbers, real or complex.
template <typename S>
std::string num2str(const Eigen::Matrix<std::complex<S>, Eigen::Dynamic, 1>& r,
                    int prec) {
  bool cplx = false;
  for (Eigen::Index i = 0; i < r.size(); ++i) cplx = cplx || r(i).imag() != 0;
  std::string s;
  char buf[96];
  for (Eigen::Index i = 0; i < r.size(); ++i) {
    std::snprintf(buf, sizeof(buf), "%*.*g", prec + 7, prec,
                  static_cast<double>(r(i).real()));
    s += buf;
    if (cplx) {
      std::snprintf(buf, sizeof(buf), "%-+*.*g", prec + 7, prec,
                    static_cast<double>(r(i).imag()));
      std::string im = buf;
      const std::size_t end = im.find_last_not_of(' ');
      const std::size_t pad = im.size() - (end + 1);
      s += im.substr(0, end + 1) + "i" + std::string(pad, ' ');
    }
  }
  const std::size_t a = s.find_first_not_of(" \t\n");
  const std::size_t b = s.find_last_not_of(" \t\n");
  return a == std::string::npos ? std::string() : s.substr(a, b - a + 1);
}

// The roots of F (descending powers) with the real ones exactly real.
template <typename S>
Eigen::Matrix<std::complex<S>, Eigen::Dynamic, 1> poles(const Vector<S>& F) {
  const std::vector<std::complex<S>> r = roots_descending<S>(F);
  return Eigen::Map<const Eigen::Matrix<std::complex<S>, Eigen::Dynamic, 1>>(
      r.data(), static_cast<Eigen::Index>(r.size()));
}

// The node's input channel: the single input channel, or -1.
template <typename S>
int single_input(const ResidtraceModel<S>& m) {
  int ins = -1, count = 0;
  for (std::size_t j = 0; j < m.channels.size(); ++j) {
    if (m.channels[j].kind == ChannelKind::kInput) {
      ins = static_cast<int>(j);
      ++count;
    }
  }
  return count == 1 ? ins : -1;
}

// The model's output without the channel j (its numerator zeroed).
template <typename S>
Status output_without(const ResidtraceModel<S>& m, std::size_t j,
                      const CandidateContext<S>& ctx, Vector<S>* xo) {
  ResidtraceModel<S> t0 = m;
  t0.channels[j].B.setZero();
  ModelSimulation<S> sim;
  Status s = simulate_model<S>(t0, ctx.D.u, ctx.D.ts,
                               ctx.D.closed ? &ctx.D.loop : nullptr,
                               ctx.fit.substeps, nullptr, &sim);
  *xo = sim.y;
  return s;
}

// The inner-node variants (head of this file).
template <typename S>
Status node_variants(const ResidtraceModel<S>& cur,
                     const CandidateContext<S>& ctx, const Vector<S>& y,
                     std::vector<Variant<S>>* variants) {
  const int ins = single_input(cur);
  bool any_fixed = false;
  for (bool f : cur.fixed) any_fixed = any_fixed || f;
  if (ctx.D.closed || ins < 0 || any_fixed || cur.F.size() < 3) {
    return Status::Ok();
  }
  const auto r = poles<S>(cur.F);
  const Eigen::Index nr = r.size();
  std::vector<std::vector<std::complex<S>>> sec;
  std::vector<bool> used(static_cast<std::size_t>(nr), false);
  for (Eigen::Index k = 0; k < nr; ++k) {
    if (used[k]) continue;
    if (r(k).imag() == 0) {
      sec.push_back({r(k)});
      used[k] = true;
    } else {
      Eigen::Index j = -1;
      for (Eigen::Index i = 0; i < nr && j < 0; ++i) {
        if (i != k && !used[i] &&
            std::abs(r(i) - std::conj(r(k))) < S(1e-9) * std::abs(r(k))) {
          j = i;
        }
      }
      if (j < 0) return Status::Ok();
      sec.push_back({r(k), r(j)});
      used[k] = used[j] = true;
    }
  }
  const int K = static_cast<int>(sec.size());
  S largest = 0;
  for (Eigen::Index k = 0; k < nr; ++k)
    largest = std::max(largest, std::abs(r(k)));
  bool origin = false;
  for (Eigen::Index k = 0; k < nr; ++k) {
    origin = origin || std::abs(r(k)) < S(1e-9) * largest;
  }
  if (K < 2 || K > 4 || origin) return Status::Ok();
  const FitRecord<S>& D = ctx.D;
  const StructureChannel<S>& ch = cur.channels[ins];
  const Eigen::Index N = D.u.rows();
  Vector<S> uk = Vector<S>::Zero(N);
  if (ch.nk < N) uk.tail(N - ch.nk) = D.u.col(ch.col).head(N - ch.nk);
  Vector<S> xo;
  Status s = output_without<S>(cur, ins, ctx, &xo);
  if (!s.ok()) return s;
  const Vector<S> tgt = y - xo;
  for (int mask = 1; mask <= (1 << K) - 2; ++mask) {
    std::vector<std::complex<S>> ra, rb;
    for (int i = 0; i < K; ++i) {
      auto& dst = (mask >> i) & 1 ? ra : rb;
      dst.insert(dst.end(), sec[i].begin(), sec[i].end());
    }
    const Vector<S> Fa = real_monic_from_roots<S>(ra),
                    Fb = real_monic_from_roots<S>(rb);
    Vector<S> z;
    s = unit_gain_response<S>(Fa, uk, D.ts, D.rule, &z);
    if (!s.ok()) return s;
    Status inner = Status::Ok();
    auto sse = [&](const Vector<S>& w) {
      Vector<S> yb;
      Status st = unit_gain_response<S>(Fb, w, D.ts, D.rule, &yb);
      if (!st.ok()) inner = st;
      return affine_sse<S>(tgt, yb);
    };
    S hi, lo;
    const bool has_hi = best_level<S>(
        [&](S L) {
          return sse(clipped<S>(z, -std::numeric_limits<S>::infinity(), L));
        },
        z, true, &hi);
    if (!inner.ok()) return inner;
    const bool has_lo = best_level<S>(
        [&](S L) {
          return sse(clipped<S>(z, L, std::numeric_limits<S>::infinity()));
        },
        z, false, &lo);
    if (!inner.ok()) return inner;
    if (!has_hi || !has_lo) continue;
    const S inf = std::numeric_limits<S>::infinity();
    const S los[3] = {-inf, lo, lo}, his[3] = {hi, inf, hi};
    const Side sides[3] = {Side::kUpper, Side::kLower, Side::kBoth};
    int best = 0;
    S bv = 0;
    for (int i = 0; i < 3; ++i) {
      const S v = bic_of<S>(sse(clipped<S>(z, los[i], his[i])), y.size(),
                            finite_count(los[i], his[i]));
      if (!inner.ok()) return inner;
      if (i == 0 || v < bv || (std::isnan(bv) && !std::isnan(v))) {
        bv = v;
        best = i;
      }
    }
    Variant<S> v;
    v.tmpl = cur;
    v.tmpl.F = Fb;
    v.tmpl.fixed.assign(static_cast<std::size_t>(Fb.size() - 1), false);
    const int nb = std::min(ch.nb, static_cast<int>(Fb.size()) - 1);
    StructureChannel<S> nc;
    nc.kind = ChannelKind::kNode;
    nc.col = ch.col;
    nc.nb = nb;
    nc.nk = ch.nk;
    nc.node_f = Fa;
    nc.node_ts = D.ts;
    nc.node_rule = D.rule;
    nc.node_lo = los[best];
    nc.node_hi = his[best];
    // started from the current model: B / F = (B / F_a(0)) / F_b times
    // the node's unit-gain F_a(0) / F_a (a zero numerator would leave the
    // engine's first auxiliary model, hence its instruments, at zero)
    const Vector<S> b0 = ch.B / cur.F(0) / Fa(Fa.size() - 1);
    nc.B = Vector<S>::Zero(nb);
    const Eigen::Index take = std::min<Eigen::Index>(nb, b0.size());
    nc.B.tail(take) = b0.tail(take);
    v.tmpl.channels[ins] = nc;
    v.starts = {Fb};
    Eigen::Matrix<std::complex<S>, Eigen::Dynamic, 1> pa = poles<S>(Fa);
    v.name = "inner node after pole(s) " + num2str<S>(pa, 3) + ", " +
             side_name(sides[best]) + " level";
    variants->push_back(v);
  }
  return Status::Ok();
}

// The end-stop template (head of this file): false when it does not apply
// or the screening shows no level.
template <typename S>
bool stop_template(const ResidtraceModel<S>& cur,
                   const CandidateContext<S>& ctx, const Vector<S>& y,
                   const Vector<S>& x, ResidtraceModel<S>* t,
                   std::string* name) {
  const int n = static_cast<int>(cur.F.size()) - 1;
  if (ctx.D.closed || n < 2) return false;
  for (const StructureChannel<S>& c : cur.channels) {
    const bool ok =
        c.kind == ChannelKind::kInput || c.kind == ChannelKind::kConstant ||
        c.kind == ChannelKind::kPower || c.kind == ChannelKind::kClip;
    if (!ok || c.nb > n - 1) return false;
  }
  for (const OutputTerm<S>& o : cur.out) {
    if (o.kind != OutputTermKind::kOffset) return false;
  }
  S best, lo, hi;
  Side side;
  if (!best_side<S>(y, x, &best, &lo, &hi, &side)) return false;
  // the costly fit only where the screening's clip shows a level
  if (!(best < bic_of<S>(sum_squares<S>(Vector<S>(y - x)), y.size(), 0) - 10)) {
    return false;
  }
  *t = cur;
  t->has_phys = true;
  t->phys = PhysicalModel<S>();
  t->phys.kind = PhysicalKind::kStop;
  t->phys.lo = lo;
  t->phys.hi = hi;
  t->phys.substeps = 20;
  t->phys.yscale = physical_model_detail::sample_std(y);
  *name = std::string("output (a position) at an end stop, velocity reset, ") +
          side_name(side) + " level";
  return true;
}

// A cascade whose inner state sits at its level on more than half of the
// samples does not overflow: its estimate marked failed.
template <typename S>
Status overflowing(ResidtraceModel<S>* m, const FitRecord<S>& D) {
  if (!m->estimate.ok || m->phys.kind != PhysicalKind::kCascade) {
    return Status::Ok();
  }
  Vector<S> ys, z;
  Status s = simulate_physical_model<S>(*m, D.u, D.ts, &ys, &z);
  if (!s.ok()) return s;
  const S hi = m->phys.hi;
  Eigen::Index at = 0;
  for (Eigen::Index k = 0; k < z.size(); ++k) {
    at += z(k) >= hi - S(1e-9) * std::abs(hi) ? 1 : 0;
  }
  m->estimate.ok = static_cast<S>(at) / static_cast<S>(z.size()) <= S(0.5);
  return Status::Ok();
}

template <typename S>
int sat_term(const ResidtraceModel<S>& m) {
  for (std::size_t k = 0; k < m.out.size(); ++k) {
    if (m.out[k].kind == OutputTermKind::kSaturation)
      return static_cast<int>(k);
  }
  return -1;
}

template <typename S>
int node_channel(const ResidtraceModel<S>& m) {
  for (std::size_t j = 0; j < m.channels.size(); ++j) {
    if (m.channels[j].kind == ChannelKind::kNode) return static_cast<int>(j);
  }
  return -1;
}

// One refinement of the levels with the fitted model m: *better when the
// model refitted with them has a smaller BIC (then *m is that fit).
template <typename S>
Status refine(ResidtraceModel<S>* m, const CandidateContext<S>& ctx,
              bool* better) {
  const FitRecord<S>& D = ctx.D;
  const Vector<S>& y = D.y;
  const S inf = std::numeric_limits<S>::infinity();
  ResidtraceModel<S> t = *m;
  const int k = sat_term(*m);
  Status s;
  if (k >= 0) {
    ResidtraceModel<S> u = *m;
    u.out[k].c = Vector<S>(2);
    u.out[k].c << -inf, inf;
    ModelSimulation<S> sim;
    s = simulate_model<S>(u, D.u, D.ts, D.closed ? &D.loop : nullptr,
                          ctx.fit.substeps, nullptr, &sim);
    if (!s.ok()) return s;
    const Vector<S>& xs = sim.y;
    Vector<S> lv = m->out[k].c;
    if (std::isfinite(lv(1))) {
      const S lo = lv(0);
      auto f = [&](S L) {
        S v = 0;
        for (Eigen::Index i = 0; i < y.size(); ++i) {
          const S d = y(i) - std::fmax(std::fmin(xs(i), L), lo);
          v += d * d;
        }
        return v;
      };
      S L;
      if (!best_level<S>(f, xs, true, &L)) {
        return numerical_failure("a saturation level without a grid");
      }
      lv(1) = L;
    }
    if (std::isfinite(lv(0))) {
      const S hi = lv(1);
      auto f = [&](S L) {
        S v = 0;
        for (Eigen::Index i = 0; i < y.size(); ++i) {
          const S d = y(i) - std::fmax(std::fmin(xs(i), hi), L);
          v += d * d;
        }
        return v;
      };
      S L;
      if (!best_level<S>(f, xs, false, &L)) {
        return numerical_failure("a saturation level without a grid");
      }
      lv(0) = L;
    }
    t.out[k].c = lv;
  } else {
    const int j = node_channel(*m);
    if (j < 0) return bad_input("no level to refine");
    const StructureChannel<S>& ch = m->channels[j];
    StructureChannel<S> open = ch;
    open.node_lo = -inf;
    open.node_hi = inf;
    Matrix<S> Wz;
    s = simulate_detail::channel_signals_at_rest<S>({open}, D.u, &Wz);
    if (!s.ok()) return s;
    const Eigen::Index N = Wz.rows();
    Vector<S> z = Vector<S>::Zero(N);
    if (ch.nk < N) z.tail(N - ch.nk) = Wz.col(0).head(N - ch.nk);
    Vector<S> xo;
    s = output_without<S>(*m, static_cast<std::size_t>(j), ctx, &xo);
    if (!s.ok()) return s;
    const Vector<S> tgt = y - xo;
    // the gain refitted with each level (as in the screening): with the
    // numerator held, a level found too wide is kept so by the gain the
    // fit lowered to match it
    Status inner = Status::Ok();
    auto sse = [&](const Vector<S>& w) {
      ModelOrders orders;
      const Vector<S> Bt =
          simulate_detail::trimmed<S>(Vector<S>(ch.B / m->F(0)));
      orders.na = static_cast<int>(m->F.size() - 1);
      orders.nb.push_back(static_cast<int>(Bt.size()));
      orders.nk.push_back(0);
      Matrix<S> theta(1, orders.num_parameters());
      for (int i = 0; i < orders.na; ++i) theta(0, i) = m->F(i + 1) / m->F(0);
      theta.block(0, orders.na, 1, Bt.size()) = Bt.transpose();
      Vector<S> yb;
      Status st = simulate_detail::ltv_simulate<S>(orders, D.rule, Matrix<S>(w),
                                                   D.ts, theta, &yb);
      if (!st.ok()) inner = st;
      return gain_sse<S>(tgt, yb);
    };
    S lo = ch.node_lo, hi = ch.node_hi;
    if (std::isfinite(hi)) {
      S L;
      if (!best_level<S>([&](S v) { return sse(clipped<S>(z, lo, v)); }, z,
                         true, &L)) {
        return numerical_failure("a node level without a grid");
      }
      if (!inner.ok()) return inner;
      hi = L;
    }
    if (std::isfinite(lo)) {
      S L;
      if (!best_level<S>([&](S v) { return sse(clipped<S>(z, v, hi)); }, z,
                         false, &L)) {
        return numerical_failure("a node level without a grid");
      }
      if (!inner.ok()) return inner;
      lo = L;
    }
    t.channels[j].node_lo = lo;
    t.channels[j].node_hi = hi;
  }
  ResidtraceModel<S> m2;
  s = fit_model<S>(t, D, {m->F}, ctx.fit, &m2);
  if (!s.ok()) return s;
  *better = m2.estimate.ok && m2.estimate.bic < m->estimate.bic;
  if (*better) *m = m2;
  return Status::Ok();
}

template <typename S>
S share_of(const Vector<S>& z, S lo, S hi, bool tolerant) {
  Eigen::Index at = 0;
  for (Eigen::Index k = 0; k < z.size(); ++k) {
    const bool up = tolerant ? z(k) >= hi - S(1e-9) * std::abs(hi) : z(k) >= hi;
    at += up || z(k) <= lo ? 1 : 0;
  }
  return static_cast<S>(at) / static_cast<S>(z.size());
}

}  // namespace saturation_detail

// The saturation candidate (head of this file). cur.estimate.e holds the
// current model's errors on the estimation record and cur.estimate.np its
// number of parameters.
template <typename S>
Status saturation_candidate(const ResidtraceModel<S>& cur,
                            const CandidateContext<S>& ctx, Candidate<S>* c) {
  using namespace saturation_detail;
  using candidate_detail::num;
  if (c == nullptr) return bad_input("no result");
  *c = Candidate<S>();
  c->effect = "saturation";
  bool has = cur.has_phys;
  for (const OutputTerm<S>& o : cur.out) {
    has = has || o.kind == OutputTermKind::kSaturation;
  }
  for (const StructureChannel<S>& ch : cur.channels) {
    has = has || ch.kind == ChannelKind::kNode;
  }
  if (has) {
    c->reason = "the model has a saturation already";
    return Status::Ok();
  }
  const FitRecord<S>& D = ctx.D;
  const Vector<S>& y = D.y;
  if (cur.estimate.e.size() != y.size()) {
    return dimension_mismatch("the current model's errors need one a sample");
  }
  const Vector<S> x = y - cur.estimate.e;  // the current model's output
  std::vector<Variant<S>> variants;
  // output saturation: the side(s) by the screening's BIC
  {
    S best, lo, hi;
    Side side;
    if (best_side<S>(y, x, &best, &lo, &hi, &side) && std::isfinite(best)) {
      Variant<S> v;
      v.tmpl = cur;
      OutputTerm<S> o;
      o.kind = OutputTermKind::kSaturation;
      o.c = Vector<S>(2);
      o.c << lo, hi;
      o.cstd = Vector<S>::Constant(2, std::numeric_limits<S>::quiet_NaN());
      o.omega = 0;
      v.tmpl.out.push_back(o);
      v.starts = {cur.F};
      v.name = std::string("output, ") + side_name(side) + " level";
      variants.push_back(v);
    }
  }
  Status s = node_variants<S>(cur, ctx, y, &variants);
  if (!s.ok()) return s;
  // the physical realisations, fitted here on their simulation error and
  // only compared by select_variant
  std::vector<ResidtraceModel<S>> ph;
  std::vector<std::string> pn;
  {
    ResidtraceModel<S> t;
    std::string name;
    if (stop_template<S>(cur, ctx, y, x, &t, &name)) {
      ph.push_back(t);
      pn.push_back(name);
    }
    for (const bool sq : {true, false}) {
      bool made = false;
      std::string why;
      s = cascade_template<S>(cur, D, sq, true, &t, &made, &why);
      if (!s.ok()) return s;
      if (made) {
        ph.push_back(t);
        pn.push_back(std::string("inner state of a ") + (sq ? "sqrt" : "lin") +
                     " cascade, upper level");
      }
    }
  }
  const int maxiter = ctx.fit.max_iterations;
  for (std::size_t k = 0; k < ph.size(); ++k) {
    ResidtraceModel<S> m;
    s = fit_physical_model<S>(ph[k], D, maxiter, &m);
    if (!s.ok()) return s;
    const bool cascade = m.phys.kind == PhysicalKind::kCascade;
    if (m.estimate.ok && cascade) {
      // a cascade's fit from the linearisation often ends on its
      // iteration budget: restarted once from where it ended
      ResidtraceModel<S> m2;
      s = fit_physical_model<S>(m, D, maxiter, &m2);
      if (!s.ok()) return s;
      if (m2.estimate.ok && m2.estimate.bic < m.estimate.bic) m = m2;
    }
    s = overflowing<S>(&m, D);
    if (!s.ok()) return s;
    if (m.estimate.ok && cascade) {
      // the lower tank's rim too, started from this fit with the rim at
      // the highest sample; a rim the fitted output never reaches is not
      // estimated: dropped
      ResidtraceModel<S> t = m;
      t.phys.has_yhi = true;
      t.phys.yhi = y.maxCoeff();
      ResidtraceModel<S> mo;
      s = fit_physical_model<S>(t, D, maxiter, &mo);
      if (!s.ok()) return s;
      s = overflowing<S>(&mo, D);
      if (!s.ok()) return s;
      if (mo.estimate.ok) {
        const Vector<S> yo = y - mo.estimate.e;
        const S yhi = mo.phys.yhi;
        bool reached = false;
        for (Eigen::Index i = 0; i < yo.size(); ++i) {
          reached = reached || yo(i) >= yhi - S(1e-9) * std::abs(yhi);
        }
        mo.estimate.ok = reached;
      }
      if (mo.estimate.ok) {
        Variant<S> v;
        v.tmpl = mo;
        v.fitted = true;
        v.name = std::string("inner and outer states of a ") +
                 (m.phys.sqrt_nodes ? "sqrt" : "lin") +
                 " cascade, upper levels";
        variants.push_back(v);
      }
    }
    if (m.estimate.ok) {
      Variant<S> v;
      v.tmpl = m;
      v.fitted = true;
      v.name = pn[k];
      variants.push_back(v);
    }
  }
  if (variants.empty()) {
    c->reason = "no level to try";
    return Status::Ok();
  }
  int best = -1;
  ResidtraceModel<S> m;
  s = select_variant<S>(variants, ctx, &best, &m, &c->variants);
  if (!s.ok()) return s;
  if (best < 0) {
    c->reason = "the estimation failed";
    c->failed = true;
    return Status::Ok();
  }
  for (int it = 0; it < 3 && !m.has_phys; ++it) {
    // the levels and the model, alternately
    bool better = false;
    s = refine<S>(&m, ctx, &better);
    if (!s.ok()) return s;
    if (!better) break;
  }
  c->applicable = true;
  c->has_model = true;
  c->model = m;
  c->chosen = best;
  c->variant = variants[best].name;
  c->nadd = m.estimate.np - cur.estimate.np;
  const S nan = std::numeric_limits<S>::quiet_NaN();
  Evidence<S>& ev = c->evidence;
  if (m.has_phys) {
    const PhysicalModel<S>& P = m.phys;
    S lo, hi;
    Vector<S> z;
    std::string what;
    if (P.kind == PhysicalKind::kStop) {
      lo = P.lo;
      hi = P.hi;
      z = y - m.estimate.e;
      what = "output (a position) held at";
    } else {
      lo = -std::numeric_limits<S>::infinity();
      hi = P.hi;
      Vector<S> ys;
      s = simulate_physical_model<S>(m, D.u, D.ts, &ys, &z);
      if (!s.ok()) return s;
      what = std::string("inner state of the ") +
             (P.sqrt_nodes ? "sqrt" : "lin") + " cascade limited to";
    }
    const S share = share_of<S>(z, lo, hi, true);
    std::string txt = what + " [" + num("%.4g", lo) + ", " + num("%.4g", hi) +
                      "] (" + num("%.1f", 100 * share) +
                      " % of the estimation samples)";
    if (P.kind == PhysicalKind::kCascade && P.has_yhi) {
      const Vector<S> yo = y - m.estimate.e;
      Eigen::Index at = 0;
      for (Eigen::Index i = 0; i < yo.size(); ++i) {
        at += yo(i) >= P.yhi - S(1e-9) * std::abs(P.yhi) ? 1 : 0;
      }
      const S so = static_cast<S>(at) / static_cast<S>(yo.size());
      txt += "; output limited to " + num("%.4g", P.yhi) + " (" +
             num("%.1f", 100 * so) + " %)";
    }
    ev.add("term", "levels [lo hi]");
    EvidenceField<S> f;
    f.name = "value";
    f.value = Vector<S>(2);
    f.value << lo, hi;
    ev.fields.push_back(f);
    ev.add("std", nan);
    ev.add("share", share);
    ev.text = txt;
  } else if (sat_term(m) >= 0) {
    const Vector<S>& lv = m.out[sat_term(m)].c;
    const Vector<S> xo = y - m.estimate.e;
    const S share = share_of<S>(xo, lv(0), lv(1), false);
    ev.add("term", "output levels [lo hi]");
    EvidenceField<S> f;
    f.name = "value";
    f.value = lv;
    ev.fields.push_back(f);
    ev.add("std", nan);
    ev.add("share", share);
    ev.text = "output saturated at [" + num("%.4g", lv(0)) + ", " +
              num("%.4g", lv(1)) + "] (" + num("%.1f", 100 * share) +
              " % of the estimation samples)";
  } else {
    const int j = node_channel(m);
    const StructureChannel<S>& ch = m.channels[j];
    Matrix<S> Wz;
    s = simulate_detail::channel_signals_at_rest<S>({ch}, D.u, &Wz);
    if (!s.ok()) return s;
    const S share =
        share_of<S>(Vector<S>(Wz.col(0)), ch.node_lo, ch.node_hi, false);
    const auto pa = poles<S>(ch.node_f);
    ev.add("term", "node levels [lo hi] (input units)");
    EvidenceField<S> f;
    f.name = "value";
    f.value = Vector<S>(2);
    f.value << ch.node_lo, ch.node_hi;
    ev.fields.push_back(f);
    ev.add("std", nan);
    ev.add("share", share);
    EvidenceField<S> p;
    p.name = "poles_upstream";
    p.value = pa.real();
    p.imag = pa.imag();
    p.column = true;
    ev.fields.push_back(p);
    ev.text = "inner node after the pole(s) " + num2str<S>(pa, 4) +
              " clipped at [" + num("%.4g", ch.node_lo) + ", " +
              num("%.4g", ch.node_hi) + "] (input units; " +
              num("%.1f", 100 * share) + " % of the samples)";
  }
  ev.add("text", ev.text);
  return Status::Ok();
}

}  // namespace ctid::residtrace
