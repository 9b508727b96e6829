// SPDX-License-Identifier: BSD-3-Clause
// Copyright (C) the ctid authors

// The input-delay candidate of residtrace (candidate.hpp): the delay nk of
// an input channel raised by 1 .. ctx.max_delay samples. Every delay is
// screened with three SRIVC iterations (one when the caller allows only
// three) from the current model, the two best are iterated to convergence
// from their screening estimates and the one with the smallest BIC on the
// estimation data is kept (fit_model).
//
// A transport delay need not be a whole number of samples: the delay is
// then refined continuously between its neighbours (nk - 1, nk + 1, not
// below the current model's delay), the fraction f of a sample entering
// as the held input delayed by f (structure_fit.hpp, channel_signals), by
// a golden-section search of the BIC (seven steps), each delay screened
// with three SRIVC iterations from the whole-sample fit, the best one
// iterated to convergence; it replaces the whole number when its BIC is
// lower by more than log N (the fraction counted as one more parameter),
// so that a delay of whole samples stays one. Not in a closed loop, whose
// controlled input is formed sample by sample. An extra pole or zero
// mimics a delay that is rounded to whole samples; with its fraction the
// delay is compared with the order candidate on the same footing.
//
// A model with a physical realisation (an end stop or a tank cascade,
// physical_model.hpp) is fitted by its own simulation error
// (fit_physical_model) at each whole delay, the screening with the same
// few iterations, the two best refitted from their screening estimates;
// its delay stays whole samples (the fraction enters the linear
// structure fit only).
//
// Evidence: the chosen delay (samples and seconds) and the lag at which
// the prewhitened cross-correlation of the current residual with the
// channel's input peaks (statistics.hpp, whiteness_statistics, over
// max(ctx.max_lag, ctx.max_delay + 1) lags).
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <string>
#include <vector>

#include "ctid/apps/residtrace/candidate.hpp"
#include "ctid/apps/residtrace/model_fit.hpp"
#include "ctid/apps/residtrace/physical_model.hpp"
#include "ctid/apps/residtrace/statistics.hpp"
#include "ctid/base/status.hpp"

namespace ctid::residtrace {

namespace delay_detail {

// The template t fitted from the denominator start: by the structure fit,
// or by its simulation error when it has a physical realisation (which
// starts from its own parameters).
template <typename S>
Status fit_template(const ResidtraceModel<S>& t, const FitRecord<S>& D,
                    const Vector<S>& start, const ModelFitSettings& settings,
                    ResidtraceModel<S>* m) {
  if (t.has_phys) {
    return fit_physical_model<S>(t, D, settings.max_iterations, m);
  }
  return fit_model<S>(t, D, {start}, settings, m);
}

// The delay of channel j of tmpl set to d samples (whole part nk, the
// fraction in param), fitted from tmpl's denominator; its BIC, infinite
// when the fit failed.
template <typename S>
Status fit_delay(S d, const ResidtraceModel<S>& tmpl, std::size_t j,
                 const FitRecord<S>& D, const ModelFitSettings& settings,
                 ResidtraceModel<S>* m, S* bic) {
  ResidtraceModel<S> t = tmpl;
  t.channels[j].nk = static_cast<int>(std::floor(d));
  t.channels[j].param = d - std::floor(d);
  Status s = fit_model<S>(t, D, {tmpl.F}, settings, m);
  if (!s.ok()) return s;
  *bic = m->estimate.ok ? m->estimate.bic : std::numeric_limits<S>::infinity();
  return Status::Ok();
}

// The delay of channel j of best (whole samples) refined continuously
// (head of this file); best replaced when the refined fit is better by
// more than log N.
template <typename S>
Status refine_fraction(ResidtraceModel<S>* best, std::size_t j,
                       const ResidtraceModel<S>& cur,
                       const CandidateContext<S>& ctx,
                       const ModelFitSettings& quick) {
  const S nk = static_cast<S>(best->channels[j].nk);
  const S d0 = static_cast<S>(cur.channels[j].nk) + cur.channels[j].param;
  S lo = std::max(nk - 1, d0 + S(0.05)), hi = nk + 1;
  if (!(hi > lo)) return Status::Ok();
  const ResidtraceModel<S> tmpl = *best;
  ResidtraceModel<S> m;
  auto bic_at = [&](S d, S* b) {
    return fit_delay<S>(d, tmpl, j, ctx.D, quick, &m, b);
  };
  const S g = (std::sqrt(S(5)) - 1) / 2;
  S x1 = hi - g * (hi - lo), x2 = lo + g * (hi - lo), b1 = 0, b2 = 0;
  Status s = bic_at(x1, &b1);
  if (s.ok()) s = bic_at(x2, &b2);
  for (int it = 1; it <= 7 && s.ok(); ++it) {
    if (b1 < b2) {
      hi = x2;
      x2 = x1;
      b2 = b1;
      x1 = hi - g * (hi - lo);
      s = bic_at(x1, &b1);
    } else {
      lo = x1;
      x1 = x2;
      b1 = b2;
      x2 = lo + g * (hi - lo);
      s = bic_at(x2, &b2);
    }
  }
  if (!s.ok()) return s;
  const S d = b1 < b2 ? x1 : x2;
  S b = 0;
  s = fit_delay<S>(d, tmpl, j, ctx.D, ctx.fit, &m, &b);
  if (!s.ok()) return s;
  const S N = static_cast<S>(ctx.D.y.size());
  if (m.estimate.ok && m.estimate.bic < best->estimate.bic - std::log(N)) {
    *best = m;
  }
  return Status::Ok();
}

}  // namespace delay_detail

// The delay candidate (head of this file); ctx.max_delay the largest delay
// tried, ctx.max_lag the whiteness test's lags, ctx.channel_names the
// names of cur's channels (for the variant's text).
template <typename S>
Status delay_candidate(const ResidtraceModel<S>& cur,
                       const CandidateContext<S>& ctx, Candidate<S>* c) {
  using candidate_detail::num;
  using namespace delay_detail;
  if (c == nullptr) return bad_input("no result");
  *c = Candidate<S>();
  c->effect = "delay";
  const Eigen::Index N = ctx.D.y.size();
  if (cur.estimate.e.size() != N) {
    return bad_input(
        "the model's estimation residual needs one value a sample of the "
        "record");
  }
  if (ctx.max_lag < 1) return bad_input("the largest lag must be >= 1");
  std::vector<std::size_t> cols;
  for (std::size_t j = 0; j < cur.channels.size(); ++j) {
    if (cur.channels[j].kind == ChannelKind::kInput) cols.push_back(j);
  }
  if (ctx.max_delay < 1 || cols.empty()) {
    c->reason = "no delay to try";
    return Status::Ok();
  }
  for (std::size_t j : cols) {
    const int col = cur.channels[j].col;
    if (col < 0 || col >= ctx.D.u.cols()) {
      return bad_input("an input channel's column is not an input");
    }
  }
  ModelFitSettings quick = ctx.fit;
  quick.max_iterations = std::max(1, std::min(3, ctx.fit.max_iterations / 3));
  struct Trial {
    std::size_t j;
    int dd;
    S bic;
    ResidtraceModel<S> m;
  };
  std::vector<Trial> trials;
  for (std::size_t j : cols) {
    for (int dd = 1; dd <= ctx.max_delay; ++dd) {
      ResidtraceModel<S> t = cur;
      t.channels[j].nk += dd;
      ResidtraceModel<S> m;
      Status s = fit_template<S>(t, ctx.D, cur.F, quick, &m);
      if (!s.ok()) return s;
      if (m.estimate.ok) trials.push_back({j, dd, m.estimate.bic, m});
    }
  }
  if (trials.empty()) {
    c->reason = "the estimation failed";
    c->failed = true;
    return Status::Ok();
  }
  // the two smallest screening BICs (a stable sort: ties keep their
  // order), each iterated to convergence
  std::vector<std::size_t> idx(trials.size());
  std::iota(idx.begin(), idx.end(), std::size_t(0));
  std::stable_sort(idx.begin(), idx.end(), [&](std::size_t a, std::size_t b) {
    return trials[a].bic < trials[b].bic;
  });
  bool found = false;
  ResidtraceModel<S> best;
  std::size_t bj = 0;
  int bd = 0;
  for (std::size_t r = 0; r < std::min<std::size_t>(2, idx.size()); ++r) {
    const Trial& tr = trials[idx[r]];
    ResidtraceModel<S> m;
    Status s = fit_template<S>(tr.m, ctx.D, tr.m.F, ctx.fit, &m);
    if (!s.ok()) return s;
    if (m.estimate.ok && (!found || m.estimate.bic < best.estimate.bic)) {
      found = true;
      best = m;
      bj = tr.j;
      bd = tr.dd;
    }
  }
  if (!found) {
    c->reason = "the estimation failed";
    c->failed = true;
    return Status::Ok();
  }
  if (!ctx.D.closed && !cur.has_phys) {
    Status s = refine_fraction<S>(&best, bj, cur, ctx, quick);
    if (!s.ok()) return s;
  }
  c->applicable = true;
  c->has_model = true;
  c->model = best;
  const S nk = static_cast<S>(best.channels[bj].nk) + best.channels[bj].param;
  const std::string name =
      bj < ctx.channel_names.size() ? ctx.channel_names[bj] : std::string();
  c->variant =
      (nk == std::trunc(nk) ? num("nk = %.0f", nk) : num("nk = %.2f", nk)) +
      " on " + name;
  c->nadd = 1;
  WhitenessStatistics<S> w;
  const int maxlag = std::max(ctx.max_lag, ctx.max_delay + 1);
  Status s = whiteness_statistics<S>(
      cur.estimate.e, ctx.D.u.col(cur.channels[bj].col), maxlag, S(0), &w);
  if (!s.ok()) return s;
  S peak = std::numeric_limits<S>::quiet_NaN();
  if (w.testable) {
    // the first largest |r_eu(k)| over the lags k = 0 .. maxlag
    S top = -1;
    for (int k = 0; k <= maxlag; ++k) {
      const S r = std::abs(w.xcorr(maxlag + k, 0));
      if (r > top) {
        top = r;
        peak = static_cast<S>(k);
      }
    }
  }
  const S ts = ctx.D.ts;
  c->evidence.add("term", "nk");
  c->evidence.add("value", nk);
  c->evidence.add("std", std::numeric_limits<S>::quiet_NaN());
  c->evidence.add("physical", nk * ts);
  c->evidence.add("physical_std", std::numeric_limits<S>::quiet_NaN());
  c->evidence.add("xcorr_peak_lag", peak);
  c->evidence.text = "delay nk = " + num("%.4g", nk) + " samples (" +
                     num("%.4g", nk * ts) + " s, +" + std::to_string(bd) +
                     "); residual-input cross-correlation peaks at lag " +
                     num("%.0f", peak);
  c->evidence.add("text", c->evidence.text);
  return Status::Ok();
}

}  // namespace ctid::residtrace
