// SPDX-License-Identifier: BSD-3-Clause
// Copyright (C) the ctid authors
// The candidates of residtrace (octave/residtrace.m): what a candidate
// reads (its context: the estimation record and the fit's settings), what
// it returns (the candidate: the fitted model, the variant chosen, the
// evidence shown to the user), the choice of a variant among fits
// (select_variant) and the candidates themselves.
//
//   select_variant: each variant's structure is fitted on the estimation
//     record (fit_model) and the one with the smallest BIC = N log s2 +
//     np log N (Schwarz) kept: the variant of an effect is chosen on the
//     estimation data only. A variant marked fitted is a model fitted
//     already (by an estimator of its own) and is only compared. With more
//     than two variants they are screened first: each fitted with three
//     SRIVC iterations (one when the caller allows only three), and only
//     the two with the smallest screening BIC iterated to convergence,
//     each from its screening estimate and then, when that fails, from
//     its own starts (the variants' loss differences are decided long
//     before their iterations end). A variant with an order floor fails
//     when its fit comes back with a lower order (the poles it adds
//     residualised by fit_model: it is then another variant).
//
//   offset_candidate: a constant entering with the input (an extra
//     regressor 1 in the filtered regression, its own gain b_c / F(p)) or
//     added to the output (y = x + c; not with an integrating model, where
//     a constant output is an initial condition); the variant with the
//     smaller BIC kept. Evidence: the constant with its standard
//     deviation, in input units (b_c over the input's static numerator)
//     for the input offset.
//
//   viscous_candidate: the model's coefficient of the velocity term, when
//     it is fixed at zero (the coefficient of p^1 for a model of order >=
//     2, whose output is read as a position; of p^0 for a first-order
//     model, read as a velocity), freed: the regressor -p y_f (resp. -y_f)
//     joins the filtered regression. Evidence: the fitted coefficient with
//     its standard deviation and, for a numerator b0 alone, the viscous
//     coefficient f / b0 in input units per unit velocity.
//
// Other candidates have a header of their own: candidate_sinusoid.hpp,
// candidate_delay.hpp, candidate_x0.hpp, candidate_colored.hpp.
#pragma once

#include <algorithm>
#include <cmath>
#include <complex>
#include <cstdio>
#include <limits>
#include <string>
#include <vector>

#include "ctid/apps/residtrace/model.hpp"
#include "ctid/apps/residtrace/model_fit.hpp"
#include "ctid/base/status.hpp"

namespace ctid::residtrace {

// What a candidate reads: the estimation record and the fit's settings
// (iterations, keep_order, substeps), the velocity filter's lower band
// edge wlo and forgetting lam_v, whether the output is read as a
// velocity.
template <typename S>
struct CandidateContext {
  FitRecord<S> D;
  ModelFitSettings fit;
  S wlo = std::numeric_limits<S>::quiet_NaN();
  S lam_v = std::numeric_limits<S>::quiet_NaN();
  bool vel_is_y = false;
  // sinusoid_candidate (candidate_sinusoid.hpp): the number of samples of
  // the validation record
  Eigen::Index validation_samples = 0;
  // delay_candidate (candidate_delay.hpp): the largest delay tried
  // (samples), the largest lag of the whiteness test, the names of the
  // current model's channels
  int max_delay = 0;
  int max_lag = 25;
  std::vector<std::string> channel_names;
  // x0_candidate (candidate_x0.hpp): the validation record continues the
  // estimation record (its initial state comes from the simulation)
  bool validation_continues = false;
};

// A named field of a candidate's evidence: a number (or a row of them), a
// column of roots (complex when one of them is) or a text.
template <typename S>
struct EvidenceField {
  std::string name;
  bool is_text = false;
  std::string text;
  Vector<S> value;
  // the imaginary parts of complex values (empty: real) and whether the
  // values are a column (roots, poles) rather than a row
  Vector<S> imag;
  bool column = false;
};

template <typename S>
struct Evidence {
  std::string text;  // shown to the user
  std::vector<EvidenceField<S>> fields;

  void add(const std::string& name, S v) {
    EvidenceField<S> f;
    f.name = name;
    f.value = Vector<S>::Constant(1, v);
    fields.push_back(f);
  }
  void add(const std::string& name, const std::vector<std::complex<S>>& r) {
    EvidenceField<S> f;
    f.name = name;
    f.column = true;
    f.value.resize(static_cast<Eigen::Index>(r.size()));
    f.imag.resize(f.value.size());
    for (std::size_t i = 0; i < r.size(); ++i) {
      f.value(static_cast<Eigen::Index>(i)) = r[i].real();
      f.imag(static_cast<Eigen::Index>(i)) = r[i].imag();
    }
    fields.push_back(f);
  }
  void add(const std::string& name, const std::string& t) {
    EvidenceField<S> f;
    f.name = name;
    f.is_text = true;
    f.text = t;
    fields.push_back(f);
  }
};

// One row of the variants' table: BIC and residual variance after
// screening or converged (NaN: the fit failed).
template <typename S>
struct VariantRow {
  std::string variant;
  S bic = std::numeric_limits<S>::quiet_NaN();
  S s2 = std::numeric_limits<S>::quiet_NaN();
  bool converged = false;
};

// A variant of an effect: its structure and starts (initial denominators;
// an empty one is the engine's automatic start), or a model fitted
// already; the least order its fit may come back with.
template <typename S>
struct Variant {
  std::string name;
  ResidtraceModel<S> tmpl;
  std::vector<Vector<S>> starts;
  bool fitted = false;
  int order_floor = 0;
  // the template's channels and output terms beyond those of the model it
  // extends (their names, for the caller's record of the structure)
  std::vector<std::string> channel_names;
};

// A candidate: not applicable until a candidate fills in the fitted model,
// the variant chosen, the number of added parameters nadd, the kind of
// its validation output ("simulation", "tracking" or "prediction") and
// its evidence; insample when its validation output fits parameters on
// the validation record itself; failed when it applies but its
// estimation failed.
template <typename S>
struct Candidate {
  std::string effect;
  bool applicable = false;
  std::string reason;
  std::string variant;
  bool has_model = false;
  ResidtraceModel<S> model;
  int chosen = -1;  // the variant the model is (select_variant), or -1
  std::vector<std::string> added_channels;  // names of the added channels
  int nadd = 0;
  std::string kind = "simulation";
  Evidence<S> evidence;
  std::vector<VariantRow<S>> variants;
  bool insample = false;
  bool failed = false;
};

namespace candidate_detail {

template <typename S>
int order(const ResidtraceModel<S>& m) {
  return static_cast<int>(m.F.size()) - 1;
}

// A number as Octave's sprintf writes it with the conversion spec (e.g.
// "%.4g"): NaN and Inf spelt so.
template <typename S>
std::string num(const char* spec, S v) {
  if (std::isnan(v)) return "NaN";
  if (std::isinf(v)) return v > 0 ? "Inf" : "-Inf";
  char buf[64];
  std::snprintf(buf, sizeof(buf), spec, static_cast<double>(v));
  return buf;
}

// A row of numbers as Octave's num2str (x, prec) writes it: each number
// in a field of prec + 7 characters with prec significant digits, the row
// trimmed; a complex row (imag non-empty and one of its parts nonzero) as
// re+imi pairs, the imaginary part left-aligned with its sign.
template <typename S>
std::string num2str(const Vector<S>& re, const Vector<S>& im, int prec) {
  const int w = prec + 7;
  auto field = [&](S v, bool sign, bool left) {
    char buf[64];
    if (std::isnan(v) || std::isinf(v)) {
      const std::string t = std::isnan(v) ? "NaN" : (v > 0 ? "Inf" : "-Inf");
      const std::string u = (sign && !(v < 0)) ? "+" + t : t;
      std::snprintf(buf, sizeof(buf), left ? "%-*s" : "%*s", w, u.c_str());
    } else {
      std::snprintf(
          buf, sizeof(buf),
          left ? (sign ? "%-+*.*g" : "%-*.*g") : (sign ? "%+*.*g" : "%*.*g"), w,
          prec, static_cast<double>(v == 0 ? S(0) : v));
    }
    return std::string(buf);
  };
  const bool complex = im.size() == re.size() && (im.array() != 0).any();
  std::string out;
  for (Eigen::Index i = 0; i < re.size(); ++i) {
    out += field(re(i), false, false);
    if (complex) {
      // the padding of the imaginary part moved after its i, the last
      // one's dropped
      std::string t = field(im(i), true, true);
      const std::size_t end = t.find_last_not_of(' ');
      const std::string pad = t.substr(end + 1);
      out += t.substr(0, end + 1) + "i" + (i + 1 < re.size() ? pad : "");
    }
  }
  const std::size_t a = out.find_first_not_of(" \t");
  if (a == std::string::npos) return "";
  const std::size_t b = out.find_last_not_of(" \t");
  return out.substr(a, b - a + 1);
}

}  // namespace candidate_detail

// select_variant: the variants fitted and compared (head of this file).
// best: the index of the variant kept, -1 when none converged; *model its
// fit; *table one row a variant.
template <typename S>
Status select_variant(const std::vector<Variant<S>>& variants,
                      const CandidateContext<S>& ctx, int* best,
                      ResidtraceModel<S>* model,
                      std::vector<VariantRow<S>>* table) {
  using candidate_detail::order;
  if (best == nullptr || model == nullptr || table == nullptr) {
    return bad_input("no result");
  }
  const std::size_t n = variants.size();
  const std::size_t keep = 2;
  const bool screen = n > keep;
  ModelFitSettings quick = ctx.fit;
  if (screen) {
    quick.max_iterations = std::max(1, std::min(3, ctx.fit.max_iterations / 3));
  }
  table->assign(n, VariantRow<S>());
  std::vector<ResidtraceModel<S>> fits(n);
  for (std::size_t i = 0; i < n; ++i) {
    const Variant<S>& v = variants[i];
    (*table)[i].variant = v.name;
    if (v.fitted) {
      fits[i] = v.tmpl;
      (*table)[i].converged = true;
    } else {
      Status s = fit_model<S>(v.tmpl, ctx.D, v.starts, quick, &fits[i]);
      if (!s.ok()) return s;
      (*table)[i].converged = !screen;
    }
    ModelEstimate<S>& e = fits[i].estimate;
    e.ok = e.ok && order(fits[i]) >= v.order_floor;
    if (e.ok) {
      (*table)[i].bic = e.bic;
      (*table)[i].s2 = e.s2;
    }
  }
  if (screen) {
    // the two smallest screening BICs (a stable sort: ties keep their
    // order), each iterated to convergence
    std::vector<std::size_t> idx(n);
    std::vector<S> b(n);
    for (std::size_t i = 0; i < n; ++i) {
      idx[i] = i;
      b[i] = std::isnan((*table)[i].bic) ? std::numeric_limits<S>::infinity()
                                         : (*table)[i].bic;
    }
    std::stable_sort(idx.begin(), idx.end(),
                     [&](std::size_t x, std::size_t y) { return b[x] < b[y]; });
    for (std::size_t r = 0; r < keep; ++r) {
      const std::size_t i = idx[r];
      if (!std::isfinite(b[i]) || (*table)[i].converged) continue;
      const Variant<S>& v = variants[i];
      ResidtraceModel<S> m;
      Status s = fit_model<S>(fits[i], ctx.D, {fits[i].F}, ctx.fit, &m);
      if (!s.ok()) return s;
      m.estimate.ok = m.estimate.ok && order(m) >= v.order_floor;
      if (!m.estimate.ok) {
        s = fit_model<S>(v.tmpl, ctx.D, v.starts, ctx.fit, &m);
        if (!s.ok()) return s;
        m.estimate.ok = m.estimate.ok && order(m) >= v.order_floor;
      }
      (*table)[i].converged = true;
      if (m.estimate.ok) {
        fits[i] = m;
        (*table)[i].bic = m.estimate.bic;
        (*table)[i].s2 = m.estimate.s2;
      } else {
        (*table)[i].bic = std::numeric_limits<S>::quiet_NaN();
      }
    }
  }
  *best = -1;
  for (std::size_t i = 0; i < n; ++i) {
    if (!(*table)[i].converged || !fits[i].estimate.ok) continue;
    if (*best < 0 || fits[i].estimate.bic < fits[*best].estimate.bic) {
      *best = static_cast<int>(i);
    }
  }
  if (*best >= 0) *model = fits[*best];
  return Status::Ok();
}

// The variants fitted and compared (select_variant) for the candidate c:
// the variant kept becomes its model (c applicable, with the variant's
// name and added channels); when none converged c failed ("the estimation
// failed").
template <typename S>
Status adopt_best_variant(const std::vector<Variant<S>>& variants,
                          const CandidateContext<S>& ctx, Candidate<S>* c) {
  int best = -1;
  ResidtraceModel<S> m;
  Status s = select_variant<S>(variants, ctx, &best, &m, &c->variants);
  if (!s.ok()) return s;
  if (best < 0) {
    c->reason = "the estimation failed";
    c->failed = true;
    return Status::Ok();
  }
  c->applicable = true;
  c->has_model = true;
  c->model = m;
  c->chosen = best;
  c->added_channels = variants[best].channel_names;
  c->variant = variants[best].name;
  return Status::Ok();
}

// The offset candidate (head of this file).
template <typename S>
Status offset_candidate(const ResidtraceModel<S>& cur,
                        const CandidateContext<S>& ctx, Candidate<S>* c) {
  using candidate_detail::num;
  if (c == nullptr) return bad_input("no result");
  *c = Candidate<S>();
  c->effect = "offset";
  if (cur.levels) {
    c->reason = "the record's levels are estimated with the model already";
    return Status::Ok();
  }
  std::vector<Variant<S>> variants;
  bool has_const = false;
  for (const StructureChannel<S>& ch : cur.channels) {
    has_const = has_const || ch.kind == ChannelKind::kConstant;
  }
  if (!has_const) {
    Variant<S> v;
    v.name = "input offset";
    v.tmpl = cur;
    StructureChannel<S> k;
    k.kind = ChannelKind::kConstant;
    k.col = -1;
    k.nb = 1;
    k.nk = 0;
    k.B = Vector<S>::Zero(1);
    v.tmpl.channels.push_back(k);
    v.channel_names.push_back("offset");
    v.starts = {cur.F};
    variants.push_back(v);
  }
  bool has_out_offset = false;
  for (const OutputTerm<S>& t : cur.out) {
    has_out_offset = has_out_offset || t.kind == OutputTermKind::kOffset;
  }
  if (cur.F(cur.F.size() - 1) != 0 && !has_out_offset) {
    Variant<S> v;
    v.name = "output offset";
    v.tmpl = cur;
    OutputTerm<S> t;
    t.kind = OutputTermKind::kOffset;
    t.c = Vector<S>::Zero(1);
    t.cstd = Vector<S>::Zero(1);
    v.tmpl.out.push_back(t);
    v.starts = {cur.F};
    variants.push_back(v);
  }
  if (variants.empty()) {
    c->reason = "the model has its offsets already";
    return Status::Ok();
  }
  Status s = adopt_best_variant<S>(variants, ctx, c);
  if (!s.ok() || !c->applicable) return s;
  const ResidtraceModel<S>& m = c->model;
  c->nadd = 1;
  if (c->variant == "input offset") {
    const ModelEstimate<S>& e = m.estimate;
    const Eigen::Index k = e.theta.size() - 1;  // the constant's gain
    const S val = e.theta(k), sd = std::sqrt(e.cov(k, k));
    const Vector<S>& B = m.channels[0].B;
    const S bu = B(B.size() - 1);
    c->evidence.add("term", "b_c (gain of the constant input)");
    c->evidence.add("value", val);
    c->evidence.add("std", sd);
    c->evidence.add("physical", val / bu);
    c->evidence.add("physical_std", sd / std::abs(bu));
    c->evidence.text = "input offset " + num("%.4g", val / bu) + " +- " +
                       num("%.2g", sd / std::abs(bu)) +
                       " (input units; b_c = " + num("%.4g", val) + " +- " +
                       num("%.2g", sd) + ")";
  } else {
    const OutputTerm<S>& o = m.out.back();
    c->evidence.add("term", "output offset");
    c->evidence.add("value", o.c(0));
    c->evidence.add("std", o.cstd(0));
    c->evidence.add("physical", o.c(0));
    c->evidence.add("physical_std", o.cstd(0));
    c->evidence.text = "output offset " + num("%.4g", o.c(0)) + " +- " +
                       num("%.2g", o.cstd(0));
  }
  c->evidence.add("text", c->evidence.text);
  return Status::Ok();
}

// The viscous-friction candidate (head of this file).
template <typename S>
Status viscous_candidate(const ResidtraceModel<S>& cur,
                         const CandidateContext<S>& ctx, Candidate<S>* c) {
  using candidate_detail::num;
  if (c == nullptr) return bad_input("no result");
  *c = Candidate<S>();
  c->effect = "viscous";
  const int n = static_cast<int>(cur.F.size()) - 1;
  const int k = std::max(n - 1, 1);  // the velocity term among f1..fn
  if (!cur.fixed[k - 1] || cur.F(k) != 0) {
    c->reason = "the model's damping (velocity) coefficient is estimated";
    return Status::Ok();
  }
  ResidtraceModel<S> t = cur;
  t.fixed[k - 1] = false;
  ResidtraceModel<S> m;
  Status s = fit_model<S>(t, ctx.D, {cur.F}, ctx.fit, &m);
  if (!s.ok()) return s;
  if (!m.estimate.ok) {
    c->reason = "the estimation failed";
    c->failed = true;
    return Status::Ok();
  }
  c->applicable = true;
  c->has_model = true;
  c->model = m;
  char name[32];
  std::snprintf(name, sizeof(name), "free f%d", k);
  c->variant = name;
  c->nadd = 1;
  int i = 0;  // f_k among the free f's
  for (int j = 0; j < k; ++j) i += t.fixed[j] ? 0 : 1;
  const S val = m.estimate.theta(i - 1);
  const S sd = std::sqrt(m.estimate.cov(i - 1, i - 1));
  const Vector<S>& b0 = m.channels[0].B;
  S phys = std::numeric_limits<S>::quiet_NaN(), psd = phys;
  if (b0.size() == 1) {
    phys = val / b0(0);
    psd = sd / std::abs(b0(0));
  }
  char term[64];
  std::snprintf(term, sizeof(term), "f%d (velocity coefficient)", k);
  c->evidence.add("term", term);
  c->evidence.add("value", val);
  c->evidence.add("std", sd);
  c->evidence.add("physical", phys);
  c->evidence.add("physical_std", psd);
  c->evidence.text = "f" + std::to_string(k) + " = " + num("%.4g", val) +
                     " +- " + num("%.2g", sd) + "; viscous coefficient " +
                     num("%.4g", phys) + " +- " + num("%.2g", psd) +
                     " (input units per unit velocity)";
  c->evidence.add("text", c->evidence.text);
  return Status::Ok();
}

}  // namespace ctid::residtrace
