// SPDX-License-Identifier: BSD-3-Clause
// Copyright (C) the ctid authors

// The order candidate of residtrace: a missing pole or zero.
//
// The variants raise the denominator order by 1 or 2 and the numerator
// order of every input channel by 0, 1 or 2 (strictly proper models only:
// a variant whose numerator would reach the denominator's length is not
// built). The model's integrators (trailing zeros of F held fixed) stay;
// its other structural zeros of F are freed. Each variant is started from
// the current F times a factor placed at 1/3 and 3 times (order + 1), or
// 1/2 and 2 times (order + 2), the geometric mean wg of the moduli of the
// prefilter's roots (prefilter.hpp: the current poles made stable and
// separated, an integrator at the band's lower edge), and from the
// engine's automatic start: the added pole may lie below or above the
// band of the current ones. select_variant keeps the variant of smallest
// BIC on the estimation data; a variant whose fit sends an added pole
// beyond the samples (residualised by fit_model) comes back with a lower
// order, is not that variant and is dropped (its order floor).
//
// Evidence: the poles and zeros (of the first channel) of the chosen
// model and the drop in BIC from the current model.
#pragma once

#include <cmath>
#include <complex>
#include <cstdio>
#include <initializer_list>
#include <limits>
#include <string>
#include <vector>

#include "ctid/apps/residtrace/candidate.hpp"
#include "ctid/apps/residtrace/prefilter.hpp"
#include "ctid/base/polynomial.hpp"

namespace ctid::residtrace {

template <typename S>
Status order_candidate(const ResidtraceModel<S>& cur,
                       const CandidateContext<S>& ctx, Candidate<S>* c) {
  using candidate_detail::num;
  using candidate_detail::num2str;
  if (c == nullptr) return bad_input("no result");
  *c = Candidate<S>();
  c->effect = "order";
  const int n = static_cast<int>(cur.F.size()) - 1;
  if (n < 0 || static_cast<int>(cur.fixed.size()) != n) {
    return bad_input("the model's F and fixed do not match");
  }
  // the integrators: trailing zeros of F held fixed
  int r = 0;
  while (r < n && cur.fixed[n - r - 1] && cur.F(n - r) == 0) ++r;
  Vector<S> Fp;
  Status s = prefilter_denominator<S>(cur.F, ctx.wlo, &Fp);
  if (!s.ok()) return s;
  S wg = std::numeric_limits<S>::quiet_NaN();
  if (n > 0) {
    S sum = 0;
    for (const std::complex<S>& z : roots_descending<S>(Fp)) {
      sum += std::log(std::abs(z));
    }
    wg = std::exp(sum / n);
  }
  auto times = [&](std::initializer_list<S> f) {
    Vector<S> g(static_cast<Eigen::Index>(f.size()));
    Eigen::Index i = 0;
    for (S x : f) g(i++) = x;
    return convolve<S>(cur.F, g);
  };
  const int steps[6][2] = {{1, 0}, {1, 1}, {0, 1}, {2, 0}, {2, 1}, {2, 2}};
  std::vector<Variant<S>> variants;
  for (const auto& step : steps) {
    const int da = step[0], db = step[1];
    const int nn = n + da;
    bool proper = true;
    for (const StructureChannel<S>& ch : cur.channels) {
      if (ch.kind == ChannelKind::kInput && ch.nb + db > nn) proper = false;
    }
    if (!proper) continue;
    Variant<S> v;
    if (da == 0) {
      v.starts = {cur.F};
    } else if (da == 1) {
      v.starts = {times({S(1), wg / 3}), times({S(1), 3 * wg}), Vector<S>()};
    } else {
      v.starts = {times({S(1), S(0.3) * wg, (wg / 2) * (wg / 2)}),
                  times({S(1), S(1.2) * wg, (2 * wg) * (2 * wg)}), Vector<S>()};
    }
    v.tmpl = cur;
    v.tmpl.F = Vector<S>::Zero(nn + 1);
    v.tmpl.F(0) = 1;
    v.tmpl.fixed.assign(static_cast<std::size_t>(nn), false);
    for (int i = nn - r; i < nn; ++i) v.tmpl.fixed[i] = true;
    v.order_floor = nn;  // a fit that drops the added poles is not it
    for (StructureChannel<S>& ch : v.tmpl.channels) {
      if (ch.kind != ChannelKind::kInput) continue;
      Vector<S> B = Vector<S>::Zero(ch.B.size() + db);
      B.tail(ch.B.size()) = ch.B;
      ch.B = B;
      ch.nb += db;
    }
    char name[32];
    std::snprintf(name, sizeof(name), "na + %d, nb + %d", da, db);
    v.name = name;
    variants.push_back(v);
  }
  if (variants.empty()) {
    c->reason = "no admissible order";
    return Status::Ok();
  }
  s = adopt_best_variant<S>(variants, ctx, c);
  if (!s.ok() || !c->applicable) return s;
  const ResidtraceModel<S>& m = c->model;
  c->nadd = m.estimate.np - cur.estimate.np;
  const std::vector<std::complex<S>> p = roots_descending<S>(m.F);
  const std::vector<std::complex<S>> z =
      m.channels.empty() ? std::vector<std::complex<S>>()
                         : roots_descending<S>(m.channels[0].B);
  const S drop = cur.estimate.bic - m.estimate.bic;
  c->evidence.add("term", "poles");
  c->evidence.add("value", p);
  c->evidence.add("std", std::numeric_limits<S>::quiet_NaN());
  c->evidence.add("zeros", z);
  c->evidence.add("bic_drop", drop);
  auto row = [](const std::vector<std::complex<S>>& x) {
    Vector<S> re(static_cast<Eigen::Index>(x.size())), im(re.size());
    for (std::size_t i = 0; i < x.size(); ++i) {
      re(static_cast<Eigen::Index>(i)) = x[i].real();
      im(static_cast<Eigen::Index>(i)) = x[i].imag();
    }
    return num2str<S>(re, im, 4);
  };
  c->evidence.text = c->variant + ": poles " + row(p) + ", zeros " + row(z) +
                     "; BIC " + num("%.1f", drop) + " lower";
  c->evidence.add("text", c->evidence.text);
  return Status::Ok();
}

}  // namespace ctid::residtrace
