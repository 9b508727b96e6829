// SPDX-License-Identifier: BSD-3-Clause
// Copyright (C) the ctid authors
// residtrace's candidates (core/include/ctid/apps/residtrace/candidate.hpp)
// to and from the Octave structs the residtrace functions pass around:
//
//   read_fit_record(g, D)        the estimation record D: y, u, Ts,
//                                intersample, vhat, ysm, initial_state,
//                                missing, loop
//   read_context(g, D, opt)      a candidate's context: the record D and
//                                the options maxiter, keep_order,
//                                substeps (absent: 1), wlo, lam_v,
//                                vel_is_y (octave/private/
//                                residtrace_fitopts.m makes them of ctx);
//                                for the sinusoid validation_samples;
//                                for the delay maxdelay, maxlag; for the
//                                initial state validation_continues
//   read_starts(g, a)            a cell of initial denominators
//   write_model_struct(base, m, names)
//                                the struct of a model fitted from a
//                                template that extends base
//   write_candidate(cur, c)      the candidate struct: effect, applicable,
//                                reason, variant, model, nadd, kind,
//                                evidence, variants, insample, failed
//
// and the methods of effect_sim_mex (dispatch):
//
//   c = effect_sim_mex (fname, "candidate", effect, cur, D, options)
//     the candidate effect ("offset", "viscous", "order", "coulomb",
//     "sinusoid", "delay", "initial_state", "colored_noise",
//     "state_nonlinearity", "static_nonlinearity", "saturation") of the
//     current model cur (its estimation residual e_est read when present;
//     "saturation" needs it and the number of parameters np); for
//     "state_nonlinearity" options.cascade is the two-section cascade with
//     square-root outflows fitted already (octave/private/
//     residtrace_physfit.m; absent or []: none).
//   [best, table] = effect_sim_mex (fname, "select", tmpls, names, D,
//                                   options)
//     the variant chosen among the templates (select_variant), options.starts
//     a cell (one cell of starts a template): best the fitted model with
//     its field variant_ ([] when none converged), table the variants'
//     names, bic, s2 and converged. A template with the field fitted is a
//     model fitted already (its ok, bic, s2 and F are read); one with
//     order_floor_ fails when its fit comes back with a lower order.
//   [t, why] = effect_sim_mex (fname, "physcascade", cur, D, options)
//     the cascade realisation started from the model cur
//     (physical_model.hpp, cascade_template): t the model struct ([] with
//     the reason why when there is none); options: g ("sqrt" or "lin"),
//     clip (an inner level).
//   s = effect_sim_mex (fname, "driftsegments", cur, D, options)
//     the segment test of the drift candidate (candidate_drift.hpp,
//     drift_segments) of the model cur (its theta, cov and s2 read):
//     s.reason ("" when the segments disagree), failed, K, L, segments,
//     theta (segments-by-np), P (np-by-np-by-segments), tmid, chi2, dof,
//     p, slope, tval, shape; options: alpha and those of read_context.
//   model = effect_sim_mex (fname, "physmodelfit", tmpl, D, options)
//     the model tmpl with a physical realisation fitted on D by its
//     simulation error (physical_model.hpp, fit_physical_model); ok false
//     when it fails; options: maxiter.
#pragma once

#include <cctype>
#include <cmath>
#include <string>
#include <vector>

#include "ctid/apps/residtrace/candidate.hpp"
#include "ctid/apps/residtrace/candidate_colored.hpp"
#include "ctid/apps/residtrace/candidate_coulomb.hpp"
#include "ctid/apps/residtrace/candidate_delay.hpp"
#include "ctid/apps/residtrace/candidate_drift.hpp"
#include "ctid/apps/residtrace/candidate_order.hpp"
#include "ctid/apps/residtrace/candidate_saturation.hpp"
#include "ctid/apps/residtrace/candidate_sinusoid.hpp"
#include "ctid/apps/residtrace/candidate_state.hpp"
#include "ctid/apps/residtrace/candidate_static.hpp"
#include "ctid/apps/residtrace/candidate_x0.hpp"
#include "residtrace_model_io.hpp"

namespace ctid::mex::residtrace_candidate {

using namespace ctid::mex::model_io_detail;

inline const mxArray* required_field(const Gateway& g, const mxArray* s,
                                     const char* name, const char* what) {
  const mxArray* a = field(s, name);
  if (a == nullptr) {
    g.fail("badInput", std::string(what) + " has no field " + name);
  }
  return a;
}

inline Eigen::MatrixXd signal(const Gateway& g, const mxArray* a,
                              const std::string& what, long rows) {
  const double* p = g.matrix(a, what, rows, -1, false);
  return Eigen::Map<const Eigen::MatrixXd>(
      p, static_cast<Eigen::Index>(mxGetM(a)),
      static_cast<Eigen::Index>(mxGetN(a)));
}

inline Eigen::MatrixXd optional_signal(const Gateway& g, const mxArray* a,
                                       const std::string& what, long rows) {
  if (empty(a)) return Eigen::MatrixXd();
  return signal(g, a, what, rows);
}

inline residtrace::FitRecord<double> read_fit_record(const Gateway& g,
                                                     const mxArray* s) {
  if (s == nullptr || !mxIsStruct(s) || mxGetNumberOfElements(s) != 1) {
    g.fail("badInput", "D must be a 1x1 struct");
  }
  residtrace::FitRecord<double> D;
  D.y = signal(g, required_field(g, s, "y", "the record"), "y", -1).reshaped();
  const long n = static_cast<long>(D.y.size());
  D.u = signal(g, required_field(g, s, "u", "the record"), "u", n);
  D.ts = g.scalar(field(s, "Ts"), "D.Ts");
  if (!(D.ts > 0)) g.fail("badInput", "D.Ts must be > 0");
  const mxArray* rule = field(s, "intersample");
  std::string r = rule ? g.text(rule, "D.intersample") : std::string("zoh");
  for (char& c : r) c = static_cast<char>(std::tolower(c));
  if (r != "zoh" && r != "foh") {
    g.fail("badInput", "D.intersample must be 'zoh' or 'foh'");
  }
  D.rule = r == "foh" ? ctid::InterSample::kFoh : ctid::InterSample::kZoh;
  D.vhat = optional_signal(g, field(s, "vhat"), "D.vhat", n);
  const Eigen::MatrixXd ysm = optional_signal(g, field(s, "ysm"), "D.ysm", n);
  if (ysm.size()) D.ysm = ysm.col(0);
  const mxArray* x0 = field(s, "initial_state");
  D.initial_state = !empty(x0) && number(g, x0, "D.initial_state", 0) != 0;
  const mxArray* miss = field(s, "missing");
  if (miss != nullptr &&
      mxGetNumberOfElements(miss) == static_cast<std::size_t>(n)) {
    const Eigen::VectorXd mv = values(g, miss, "D.missing");
    for (long k = 0; k < n; ++k) D.missing.push_back(mv(k) != 0);
  }
  D.closed = read_closed_loop(g, field(s, "loop"), n, &D.loop);
  return D;
}

inline void check_settings(const Gateway& g,
                           const residtrace::ModelFitSettings& s) {
  if (s.substeps < 1 || s.substeps > 10000) {
    g.fail("badOption", "option 'substeps' must lie in [1, 1e4]");
  }
  if (s.max_iterations < 1) {
    g.fail("badOption", "option 'maxiter' must be >= 1");
  }
}

// The starts of a fit: a cell of initial denominators (an empty entry:
// the engine's automatic start).
inline std::vector<Eigen::VectorXd> read_starts(const Gateway& g,
                                                const mxArray* st) {
  std::vector<Eigen::VectorXd> starts;
  if (empty(st)) return starts;
  if (!mxIsCell(st)) g.fail("badOption", "starts must be a cell");
  for (std::size_t i = 0; i < mxGetNumberOfElements(st); ++i) {
    const mxArray* F0 = mxGetCell(st, i);
    if (F0 == nullptr || mxIsEmpty(F0)) {
      starts.push_back(Eigen::VectorXd());
    } else {
      const auto v = g.eigen_matrix(F0, "a start");
      starts.push_back(Eigen::Map<const Eigen::VectorXd>(v.data(), v.size()));
    }
  }
  return starts;
}

inline residtrace::CandidateContext<double> read_context(const Gateway& g,
                                                         const mxArray* D,
                                                         OptionsReader& opt) {
  residtrace::CandidateContext<double> c;
  c.D = read_fit_record(g, D);
  c.fit.max_iterations = opt.integer("maxiter");
  c.fit.keep_order = opt.flag("keep_order", false);
  c.fit.substeps = opt.integer("substeps", 1);
  check_settings(g, c.fit);
  c.wlo = opt.scalar("wlo", c.wlo);
  c.lam_v = opt.scalar("lam_v", c.lam_v);
  c.vel_is_y = opt.flag("vel_is_y", false);
  // sinusoid
  c.validation_samples = opt.integer("validation_samples", 0);
  // delay
  c.max_delay = opt.integer("maxdelay", 0);
  c.max_lag = opt.integer("maxlag", 25);
  // initial state
  c.validation_continues = opt.flag("validation_continues", false);
  return c;
}

inline const char* channel_type(residtrace::ChannelKind k) {
  using residtrace::ChannelKind;
  switch (k) {
    case ChannelKind::kInput:
      return "input";
    case ChannelKind::kConstant:
      return "const";
    case ChannelKind::kSignV:
    case ChannelKind::kSignOutput:
      return "signv";
    case ChannelKind::kPower:
      return "power";
    case ChannelKind::kClip:
      return "clip";
    case ChannelKind::kOutputPower:
      return "ypower";
    case ChannelKind::kNode:
      return "node";
  }
  return "input";
}

inline const char* term_type(residtrace::OutputTermKind k) {
  using residtrace::OutputTermKind;
  switch (k) {
    case OutputTermKind::kOffset:
      return "offset";
    case OutputTermKind::kPolynomial:
      return "poly";
    case OutputTermKind::kSinusoid:
      return "sinusoid";
    case OutputTermKind::kSaturation:
      return "sat";
  }
  return "offset";
}

// A 1-by-n struct array with the field names of a (when a struct) or the
// given ones, its first elements copies of a's.
inline mxArray* extended(const mxArray* a, std::size_t n,
                         const std::vector<const char*>& names) {
  std::vector<std::string> f;
  if (a != nullptr && mxIsStruct(a)) {
    for (int i = 0; i < mxGetNumberOfFields(a); ++i) {
      f.push_back(mxGetFieldNameByNumber(a, i));
    }
  }
  for (const char* s : names) {
    bool have = false;
    for (const std::string& x : f) have = have || x == s;
    if (!have) f.push_back(s);
  }
  std::vector<const char*> p;
  for (const std::string& x : f) p.push_back(x.c_str());
  mxArray* r = mxCreateStructMatrix(1, n, static_cast<int>(p.size()), p.data());
  const std::size_t n0 =
      a != nullptr && mxIsStruct(a) ? mxGetNumberOfElements(a) : 0;
  for (std::size_t j = 0; j < n0 && j < n; ++j) {
    for (int i = 0; i < mxGetNumberOfFields(a); ++i) {
      const mxArray* v = mxGetFieldByNumber(a, j, i);
      if (v != nullptr) {
        mxSetField(r, j, mxGetFieldNameByNumber(a, i), mxDuplicateArray(v));
      }
    }
  }
  return r;
}

// The struct of the model m fitted from a template that extends the model
// struct base by channels (named names) and output terms: a copy of base
// with the template's F, fixed (of base's class), channels and output
// terms, and the estimate (write_model); a Hammerstein nonlinearity of
// base (field nlin) is dropped from a fitted model, being stale.
inline mxArray* write_model_struct(const mxArray* base,
                                   const residtrace::ResidtraceModel<double>& m,
                                   const std::vector<std::string>& names) {
  mxArray* t = mxDuplicateArray(base);
  if (m.estimate.set && mxGetFieldNumber(t, "nlin") >= 0)
    mxRemoveField(t, mxGetFieldNumber(t, "nlin"));
  const mxArray* f0 = mxGetField(t, 0, "fixed");
  if (f0 != nullptr && mxGetNumberOfElements(f0) == m.fixed.size()) {
    mxArray* fixed = mxDuplicateArray(f0);
    for (std::size_t i = 0; i < m.fixed.size(); ++i) {
      if (mxIsLogical(fixed)) {
        mxGetLogicals(fixed)[i] = m.fixed[i];
      } else {
        mxGetPr(fixed)[i] = m.fixed[i] ? 1 : 0;
      }
    }
    set(t, 0, "fixed", fixed);
  }
  const mxArray* ch = mxGetField(t, 0, "channels");
  const std::size_t nc0 = ch != nullptr ? mxGetNumberOfElements(ch) : 0;
  // the delays of base's channels (whole samples nk, the fraction of an
  // input channel in param), when the template changed them (before the
  // channels array is replaced by an extended one below)
  for (std::size_t j = 0; j < nc0 && j < m.channels.size(); ++j) {
    const residtrace::StructureChannel<double>& k = m.channels[j];
    const mxArray* nk = mxGetField(ch, j, "nk");
    const double nk0 = nk != nullptr && mxIsDouble(nk) && !mxIsEmpty(nk)
                           ? mxGetScalar(nk)
                           : 0.0;
    if (nk0 != k.nk)
      set(mxGetField(t, 0, "channels"), j, "nk", mxCreateDoubleScalar(k.nk));
    if (k.kind != residtrace::ChannelKind::kInput) continue;
    const mxArray* p = mxGetField(ch, j, "param");
    const double p0 =
        p != nullptr && mxIsDouble(p) && !mxIsEmpty(p) ? mxGetScalar(p) : 0.0;
    if (p0 != k.param)
      set(mxGetField(t, 0, "channels"), j, "param",
          mxCreateDoubleScalar(k.param));
  }
  if (m.channels.size() > nc0) {
    mxArray* c = extended(ch, m.channels.size(),
                          {"name", "type", "col", "param", "nb", "nk", "B"});
    for (std::size_t j = nc0; j < m.channels.size(); ++j) {
      const residtrace::StructureChannel<double>& k = m.channels[j];
      const std::size_t i = j - nc0;
      set(c, j, "name",
          mxCreateString(i < names.size() ? names[i].c_str() : ""));
      set(c, j, "type", mxCreateString(channel_type(k.kind)));
      set(c, j, "col", mxCreateDoubleScalar(k.col + 1));
      set(c, j, "param",
          k.kind == residtrace::ChannelKind::kSignOutput ? mxCreateString("y")
          : k.kind == residtrace::ChannelKind::kSignV
              ? mxCreateString("dy")
              : (k.param != 0 ? mxCreateDoubleScalar(k.param)
                              : mxCreateDoubleMatrix(0, 0, mxREAL)));
      set(c, j, "nb", mxCreateDoubleScalar(k.nb));
      set(c, j, "nk", mxCreateDoubleScalar(k.nk));
      set(c, j, "B", row(k.B));
    }
    set(t, 0, "channels", c);
  }
  // the initial state and the noise model, when the template changed them
  const mxArray* x0 = mxGetField(t, 0, "x0");
  const bool x00 = x0 != nullptr && !mxIsEmpty(x0) && mxGetScalar(x0) != 0;
  if (m.x0 != x00) set(t, 0, "x0", mxCreateLogicalScalar(m.x0));
  const mxArray* A = mxGetField(t, 0, "noise");
  if (m.noise.size() > 0 &&
      (A == nullptr ||
       mxGetNumberOfElements(A) != static_cast<std::size_t>(m.noise.size()))) {
    set(t, 0, "noise", row(m.noise));
  }
  const mxArray* out = mxGetField(t, 0, "out");
  const std::size_t no0 =
      out != nullptr && mxIsStruct(out) ? mxGetNumberOfElements(out) : 0;
  if (m.out.size() > no0) {
    mxArray* o = extended(out, m.out.size(), {"type", "c", "cstd", "omega"});
    for (std::size_t k = no0; k < m.out.size(); ++k) {
      set(o, k, "type", mxCreateString(term_type(m.out[k].kind)));
      set(o, k, "c", row(m.out[k].c));
      set(o, k, "cstd", row(m.out[k].cstd));
      set(o, k, "omega", mxCreateDoubleScalar(m.out[k].omega));
    }
    set(t, 0, "out", o);
  }
  mxArray* r = write_model(t, m);
  mxDestroyArray(t);
  return r;
}

inline mxArray* write_evidence(const residtrace::Evidence<double>& e) {
  if (e.fields.empty()) {
    const char* f[] = {"text"};
    mxArray* s = mxCreateStructMatrix(1, 1, 1, f);
    mxSetField(s, 0, "text", mxCreateString(e.text.c_str()));
    return s;
  }
  mxArray* s = mxCreateStructMatrix(1, 1, 0, nullptr);
  for (const residtrace::EvidenceField<double>& f : e.fields) {
    mxArray* v = nullptr;
    if (f.is_text) {
      v = mxCreateString(f.text.c_str());
    } else if (f.column || f.imag.size() > 0) {
      // a column (roots, poles) or a row, complex when a part is nonzero
      const bool complex = (f.imag.array() != 0).any();
      const std::size_t n = static_cast<std::size_t>(f.value.size());
      v = mxCreateDoubleMatrix(f.column ? n : 1, f.column ? 1 : n,
                               complex ? mxCOMPLEX : mxREAL);
      std::copy(f.value.data(), f.value.data() + n, mxGetPr(v));
      if (complex) std::copy(f.imag.data(), f.imag.data() + n, mxGetPi(v));
    } else {
      v = f.value.size() == 1 ? mxCreateDoubleScalar(f.value(0)) : row(f.value);
    }
    set(s, 0, f.name.c_str(), v);
  }
  return s;
}

inline mxArray* write_table(
    const std::vector<residtrace::VariantRow<double>>& t) {
  const char* f[] = {"variant", "bic", "s2", "converged"};
  mxArray* s = mxCreateStructMatrix(1, t.size(), 4, f);
  for (std::size_t i = 0; i < t.size(); ++i) {
    mxSetField(s, i, "variant", mxCreateString(t[i].variant.c_str()));
    mxSetField(s, i, "bic", mxCreateDoubleScalar(t[i].bic));
    mxSetField(s, i, "s2", mxCreateDoubleScalar(t[i].s2));
    mxSetField(s, i, "converged", mxCreateLogicalScalar(t[i].converged));
  }
  return s;
}

inline mxArray* write_candidate(const mxArray* cur,
                                const residtrace::Candidate<double>& c) {
  const char* f[] = {"effect",   "applicable", "reason", "variant",
                     "model",    "nadd",       "kind",   "evidence",
                     "variants", "insample",   "failed"};
  mxArray* s = mxCreateStructMatrix(1, 1, 11, f);
  mxSetField(s, 0, "effect", mxCreateString(c.effect.c_str()));
  mxSetField(s, 0, "applicable", mxCreateLogicalScalar(c.applicable));
  mxSetField(s, 0, "reason", mxCreateString(c.reason.c_str()));
  mxSetField(s, 0, "variant", mxCreateString(c.variant.c_str()));
  if (c.has_model) {
    mxArray* m = write_model_struct(cur, c.model, c.added_channels);
    if (c.chosen >= 0) set(m, 0, "variant_", mxCreateString(c.variant.c_str()));
    mxSetField(s, 0, "model", m);
  } else {
    mxSetField(s, 0, "model", mxCreateDoubleMatrix(0, 0, mxREAL));
  }
  mxSetField(s, 0, "nadd", mxCreateDoubleScalar(c.nadd));
  mxSetField(s, 0, "kind", mxCreateString(c.kind.c_str()));
  mxSetField(s, 0, "evidence", write_evidence(c.evidence));
  mxSetField(
      s, 0, "variants",
      c.variants.empty() ? mxCreateCellMatrix(0, 0) : write_table(c.variants));
  mxSetField(s, 0, "insample", mxCreateLogicalScalar(c.insample));
  mxSetField(s, 0, "failed", mxCreateLogicalScalar(c.failed));
  return s;
}

// A template struct without the selection's own fields.
inline mxArray* bare_template(const mxArray* s) {
  mxArray* t = mxDuplicateArray(s);
  for (const char* f : {"order_floor_", "fitted"}) {
    if (mxGetFieldNumber(t, f) >= 0) mxRemoveField(t, mxGetFieldNumber(t, f));
  }
  return t;
}

// The names of a model struct's channels.
inline std::vector<std::string> channel_names(const Gateway& g,
                                              const mxArray* s) {
  const mxArray* ch = field(s, "channels");
  std::vector<std::string> names;
  for (std::size_t j = 0; ch != nullptr && j < mxGetNumberOfElements(ch); ++j) {
    const mxArray* n = mxGetField(ch, j, "name");
    names.push_back(n != nullptr && mxIsChar(n) ? g.text(n, "a channel's name")
                                                : std::string());
  }
  return names;
}

// A model fitted already (by an estimator of its own): its structure and
// the estimate's ok, bic, s2 and np.
inline residtrace::ResidtraceModel<double> read_fitted(const Gateway& g,
                                                       const mxArray* s) {
  mxArray* bare = bare_template(s);
  residtrace::ResidtraceModel<double> m = read_model(g, bare);
  mxDestroyArray(bare);
  residtrace::ModelEstimate<double>& e = m.estimate;
  e.ok = number(g, field(s, "ok"), "a fitted model's ok", 0) != 0;
  e.bic = number(g, field(s, "bic"), "a fitted model's bic", NAN);
  e.s2 = number(g, field(s, "s2"), "a fitted model's s2", NAN);
  e.np = count(g, field(s, "np"), "a fitted model's np", 0);
  return m;
}
// The struct of a model m made from the model struct cur by the
// saturation candidate (saturation_candidate) or the physical
// realisations (physical_model.hpp): an output saturation added to its
// output terms, an input channel replaced by a node (named "clip(z)",
// param Fa, lo, hi, Ts, rule), or a physical realisation (a cascade keeps
// the input, power and clip channels only and no output term); with the
// field variant_ when variant is not empty.
inline mxArray* write_saturation_model(
    const mxArray* cur, const residtrace::ResidtraceModel<double>& m,
    const std::string& variant, const mxArray* rule) {
  using residtrace::ChannelKind;
  mxArray* t = mxDuplicateArray(cur);
  if (!m.has_phys && mxGetFieldNumber(t, "nlin") >= 0) {
    mxRemoveField(t, mxGetFieldNumber(t, "nlin"));  // stale
  }
  const bool cascade =
      m.has_phys && m.phys.kind == residtrace::PhysicalKind::kCascade;
  const mxArray* ch = mxGetField(t, 0, "channels");
  const std::size_t nc0 = ch != nullptr ? mxGetNumberOfElements(ch) : 0;
  std::vector<std::size_t> src;
  for (std::size_t j = 0; j < nc0; ++j) {
    if (cascade) {
      const mxArray* ty = mxGetField(ch, j, "type");
      char buf[16] = {0};
      if (ty != nullptr && mxIsChar(ty)) mxGetString(ty, buf, sizeof(buf));
      const std::string s = buf;
      if (s != "input" && s != "power" && s != "clip") continue;
    }
    src.push_back(j);
  }
  mxArray* nch = nullptr;
  {
    std::vector<std::string> f;
    for (int i = 0; ch != nullptr && i < mxGetNumberOfFields(ch); ++i) {
      f.push_back(mxGetFieldNameByNumber(ch, i));
    }
    std::vector<const char*> p;
    for (const std::string& x : f) p.push_back(x.c_str());
    nch = mxCreateStructMatrix(1, m.channels.size(), static_cast<int>(p.size()),
                               p.data());
  }
  for (std::size_t j = 0; j < m.channels.size() && j < src.size(); ++j) {
    for (int i = 0; i < mxGetNumberOfFields(ch); ++i) {
      const mxArray* v = mxGetFieldByNumber(ch, src[j], i);
      if (v != nullptr) {
        mxSetFieldByNumber(nch, j, i, mxDuplicateArray(v));
      }
    }
    const residtrace::StructureChannel<double>& k = m.channels[j];
    set(nch, j, "B", row(k.B));
    set(nch, j, "nb", mxCreateDoubleScalar(k.nb));
    if (k.kind != ChannelKind::kNode) continue;
    set(nch, j, "name", mxCreateString("clip(z)"));
    set(nch, j, "type", mxCreateString("node"));
    set(nch, j, "col", mxCreateDoubleScalar(k.col + 1));
    const char* pf[] = {"Fa", "lo", "hi", "Ts", "rule"};
    mxArray* P = mxCreateStructMatrix(1, 1, 5, pf);
    mxSetField(P, 0, "Fa", row(k.node_f));
    mxSetField(P, 0, "lo", mxCreateDoubleScalar(k.node_lo));
    mxSetField(P, 0, "hi", mxCreateDoubleScalar(k.node_hi));
    mxSetField(P, 0, "Ts", mxCreateDoubleScalar(k.node_ts));
    mxSetField(
        P, 0, "rule",
        rule != nullptr && mxIsChar(rule)
            ? mxDuplicateArray(rule)
            : mxCreateString(k.node_rule == ctid::InterSample::kFoh ? "foh"
                                                                    : "zoh"));
    set(nch, j, "param", P);
    set(nch, j, "nb", mxCreateDoubleScalar(k.nb));
    set(nch, j, "nk", mxCreateDoubleScalar(k.nk));
  }
  set(t, 0, "channels", nch);
  set(t, 0, "F", row(m.F));
  bool node = false;
  for (const auto& k : m.channels) node = node || k.kind == ChannelKind::kNode;
  if (node || cascade) {
    mxArray* fixed = mxCreateLogicalMatrix(1, m.fixed.size());
    for (std::size_t i = 0; i < m.fixed.size(); ++i) {
      mxGetLogicals(fixed)[i] = m.fixed[i];
    }
    set(t, 0, "fixed", fixed);
  }
  const mxArray* out = mxGetField(t, 0, "out");
  const std::size_t no0 =
      out != nullptr && mxIsStruct(out) ? mxGetNumberOfElements(out) : 0;
  if (cascade) {
    std::vector<std::string> f;
    for (int i = 0;
         out != nullptr && mxIsStruct(out) && i < mxGetNumberOfFields(out);
         ++i) {
      f.push_back(mxGetFieldNameByNumber(out, i));
    }
    std::vector<const char*> p;
    for (const std::string& x : f) p.push_back(x.c_str());
    set(t, 0, "out",
        mxCreateStructMatrix(0, 0, static_cast<int>(p.size()), p.data()));
  } else if (m.out.size() >= no0 && !m.out.empty()) {
    mxArray* o = extended(out, m.out.size(), {"type", "c", "cstd", "omega"});
    int first = -1;  // the first offset: an end stop's parameter
    for (std::size_t k = 0; k < m.out.size() && first < 0; ++k) {
      if (m.out[k].kind == residtrace::OutputTermKind::kOffset) {
        first = static_cast<int>(k);
      }
    }
    for (std::size_t k = 0; k < m.out.size(); ++k) {
      const bool added = k >= no0;
      const bool sat = m.out[k].kind == residtrace::OutputTermKind::kSaturation;
      const bool stop_offset = m.has_phys && static_cast<int>(k) == first;
      if (added) {
        set(o, k, "type", mxCreateString(term_type(m.out[k].kind)));
        set(o, k, "omega", mxCreateDoubleScalar(m.out[k].omega));
      }
      if (added || sat) {
        set(o, k, "c", row(m.out[k].c));
        set(o, k, "cstd", row(m.out[k].cstd));
      } else if (stop_offset) {
        set(o, k, "c", row(m.out[k].c));
      }
    }
    set(t, 0, "out", o);
  }
  if (m.has_phys) {
    const residtrace::PhysicalModel<double>& P = m.phys;
    // the realisation's fields set in the struct it had (its other fields
    // kept) or in a new one
    const mxArray* p0 = mxGetField(t, 0, "phys");
    mxArray* ps =
        p0 != nullptr && mxIsStruct(p0) && mxGetNumberOfElements(p0) == 1
            ? mxDuplicateArray(p0)
            : mxCreateStructMatrix(1, 1, 0, nullptr);
    auto put = [&](const char* name, mxArray* v) { set(ps, 0, name, v); };
    auto num = [](double v) { return mxCreateDoubleScalar(v); };
    if (!cascade) {
      put("kind", mxCreateString("stop"));
      put("lo", num(P.lo));
      put("hi", num(P.hi));
      put("substeps", num(P.substeps));
      put("yscale", num(P.yscale));
    } else {
      put("kind", mxCreateString("cascade"));
      put("g", mxCreateString(P.sqrt_nodes ? "sqrt" : "lin"));
      put("d", num(P.d));
      put("alpha", num(P.alpha));
      put("gamma", num(P.gamma));
      put("c", num(P.c));
      put("hi", num(P.hi));
      put("substeps", num(P.substeps));
      put("wbar", row(P.wbar));
      put("yscale", num(P.yscale));
      if (P.has_h0) put("h0", num(P.h0));
      if (P.has_spill) put("spill", num(P.spill));
      if (P.has_yhi) put("yhi", num(P.yhi));
      if (P.has_z0) put("z0", num(P.z0));
    }
    if (P.theta.size() > 0) {
      put("theta", matrix(P.theta));
      put("cov", matrix(P.cov));
    }
    set(t, 0, "phys", ps);
  }
  mxArray* r = write_model(t, m);
  mxDestroyArray(t);
  if (!m.estimate.set) {
    // a template (no fit): its ok as it was
    const mxArray* ok = mxGetField(cur, 0, "ok");
    if (ok != nullptr) {
      set(r, 0, "ok", mxDuplicateArray(ok));
    } else {
      mxRemoveField(r, mxGetFieldNumber(r, "ok"));
    }
  }
  if (!variant.empty()) {
    set(r, 0, "variant_", mxCreateString(variant.c_str()));
  }
  return r;
}

inline void candidate_method(const Gateway& g, int nlhs, mxArray* plhs[],
                             int nrhs, const mxArray* prhs[]) {
  if (nrhs != 6) {
    g.fail("badInput",
           "candidate takes (fname, 'candidate', effect, cur, D, options)");
  }
  if (nlhs > 1) g.fail("badInput", "candidate has one output");
  const std::string effect = g.text(prhs[2], "the effect");
  auto cur = read_model(g, prhs[3]);
  // whether the current model's fit succeeded
  cur.estimate.ok = number(g, field(prhs[3], "ok"), "model.ok", 1) != 0;
  if ((effect == "state_nonlinearity" || effect == "static_nonlinearity") &&
      empty(field(prhs[3], "np"))) {
    // (their number of added parameters is counted from the model's)
    g.fail("badInput", "the model has no field np");
  }
  // (the initial state and the noise model extend a physical realisation
  // as they do a linear model: neither is fitted with it; the
  // state-nonlinearity candidate reports a realisation itself; the delay
  // refits it)
  if (cur.has_phys && effect != "initial_state" && effect != "colored_noise" &&
      effect != "state_nonlinearity" && effect != "saturation" &&
      effect != "delay") {
    g.fail("notSupported",
           "a physical realisation holds no " + effect + " candidate");
  }
  OptionsReader opt(g, prhs[5]);
  auto ctx = read_context(g, prhs[4], opt);
  const mxArray* cascade_struct = opt.field("cascade");
  opt.finish();
  ctx.channel_names = channel_names(g, prhs[3]);
  residtrace::Candidate<double> c;
  if (effect == "saturation") {
    if (cur.estimate.e.size() != ctx.D.y.size()) {
      g.fail("dimensionMismatch", "cur.e_est needs one error a sample");
    }
    g.check(residtrace::saturation_candidate<double>(cur, ctx, &c));
    residtrace::Candidate<double> bare = c;
    bare.has_model = false;
    plhs[0] = write_candidate(prhs[3], bare);
    if (c.has_model) {
      set(plhs[0], 0, "model",
          write_saturation_model(prhs[3], c.model, c.variant,
                                 field(prhs[4], "intersample")));
    }
    return;
  } else if (effect == "state_nonlinearity") {
    const bool has = !empty(cascade_struct);
    residtrace::ResidtraceModel<double> cascade;
    if (has) cascade = read_fitted(g, cascade_struct);
    g.check(residtrace::state_candidate<double>(cur, ctx,
                                                has ? &cascade : nullptr, &c));
    if (has && c.has_model && c.model.has_phys) {
      // the cascade chosen: the model is the caller's, named by its variant
      c.has_model = false;
      plhs[0] = write_candidate(prhs[3], c);
      mxArray* m = bare_template(cascade_struct);
      set(m, 0, "variant_", mxCreateString(c.variant.c_str()));
      set(plhs[0], 0, "model", m);
      return;
    }
  } else if (effect == "static_nonlinearity") {
    residtrace::HammersteinPart<double> part;
    g.check(residtrace::static_candidate<double>(cur, ctx.channel_names, ctx,
                                                 &c, &part));
    plhs[0] = write_candidate(prhs[3], c);
    if (part.present) {
      // the Hammerstein fit: its input nonlinearity, and theta a row as
      // hsrivc gives it
      mxArray* m = mxGetField(plhs[0], 0, "model");
      const char* f[] = {"alpha", "sd"};
      mxArray* nlin = mxCreateStructMatrix(1, 1, 2, f);
      mxSetField(nlin, 0, "alpha", row(part.alpha));
      mxSetField(nlin, 0, "sd", row(part.sd));
      set(m, 0, "nlin", nlin);
      set(m, 0, "theta", row(c.model.estimate.theta));
    }
    return;
  } else if (effect == "offset") {
    g.check(residtrace::offset_candidate<double>(cur, ctx, &c));
  } else if (effect == "viscous") {
    if (cur.fixed.empty()) g.fail("badInput", "the model has no order");
    g.check(residtrace::viscous_candidate<double>(cur, ctx, &c));
  } else if (effect == "order") {
    g.check(residtrace::order_candidate<double>(cur, ctx, &c));
  } else if (effect == "coulomb") {
    g.check(residtrace::coulomb_candidate<double>(cur, ctx, &c));
  } else if (effect == "sinusoid") {
    g.check(residtrace::sinusoid_candidate<double>(cur, ctx, &c));
  } else if (effect == "delay") {
    g.check(residtrace::delay_candidate<double>(cur, ctx, &c));
    if (c.has_model && c.model.has_phys) {
      // the realisation refitted: written as the physical fits are, into
      // cur with the channels' new delays
      residtrace::Candidate<double> bare = c;
      bare.has_model = false;
      plhs[0] = write_candidate(prhs[3], bare);
      mxArray* t = mxDuplicateArray(prhs[3]);
      mxArray* ch = mxGetField(t, 0, "channels");
      for (std::size_t j = 0; ch != nullptr && j < c.model.channels.size() &&
                              j < mxGetNumberOfElements(ch);
           ++j) {
        const mxArray* nk = mxGetField(ch, j, "nk");
        const double nk0 = nk != nullptr && mxIsDouble(nk) && !mxIsEmpty(nk)
                               ? mxGetScalar(nk)
                               : 0.0;
        if (nk0 != c.model.channels[j].nk) {
          set(ch, j, "nk", mxCreateDoubleScalar(c.model.channels[j].nk));
        }
      }
      set(plhs[0], 0, "model", write_saturation_model(t, c.model, "", nullptr));
      mxDestroyArray(t);
      return;
    }
  } else if (effect == "initial_state") {
    g.check(residtrace::x0_candidate<double>(cur, ctx, &c));
  } else if (effect == "colored_noise") {
    g.check(residtrace::colored_candidate<double>(cur, ctx, &c));
  } else {
    g.fail("notSupported", "no candidate '" + effect + "' in the core");
  }
  plhs[0] = write_candidate(prhs[3], c);
}

inline void select_method(const Gateway& g, int nlhs, mxArray* plhs[], int nrhs,
                          const mxArray* prhs[]) {
  if (nrhs != 6) {
    g.fail("badInput",
           "select takes (fname, 'select', tmpls, names, D, options)");
  }
  if (nlhs > 2) g.fail("badInput", "select has at most 2 outputs");
  const mxArray* T = prhs[2];
  const mxArray* N = prhs[3];
  OptionsReader opt(g, prhs[5]);
  const mxArray* S = opt.required("starts");
  if (!mxIsCell(T) || !mxIsCell(N) || !mxIsCell(S)) {
    g.fail("badInput", "tmpls, names and starts must be cells");
  }
  const std::size_t n = mxGetNumberOfElements(T);
  if (mxGetNumberOfElements(N) != n || mxGetNumberOfElements(S) != n) {
    g.fail("dimensionMismatch", "one name and one start cell a template");
  }
  const auto ctx = read_context(g, prhs[4], opt);
  opt.finish();
  std::vector<residtrace::Variant<double>> variants(n);
  for (std::size_t i = 0; i < n; ++i) {
    const mxArray* t = mxGetCell(T, i);
    residtrace::Variant<double>& v = variants[i];
    v.name = g.text(mxGetCell(N, i), "a variant's name");
    if (t == nullptr || !mxIsStruct(t) || mxGetNumberOfElements(t) != 1) {
      g.fail("badInput", "a template must be a 1x1 struct");
    }
    v.order_floor = count(g, field(t, "order_floor_"), "order_floor_", 0);
    v.fitted = field(t, "fitted") != nullptr;
    if (v.fitted) {
      // a model fitted already: only its estimate is compared
      residtrace::ModelEstimate<double>& e = v.tmpl.estimate;
      e.ok = number(g, field(t, "ok"), "a fitted model's ok", 0) != 0;
      e.bic = number(g, field(t, "bic"), "a fitted model's bic", NAN);
      e.s2 = number(g, field(t, "s2"), "a fitted model's s2", NAN);
      v.tmpl.F = values(g, field(t, "F"), "a fitted model's F");
      continue;
    }
    mxArray* bare = bare_template(t);
    v.tmpl = read_model(g, bare);
    mxDestroyArray(bare);
    if (v.tmpl.has_phys) {
      g.fail("notSupported",
             "a physical realisation is compared once fitted (field fitted)");
    }
    v.starts = read_starts(g, mxGetCell(S, i));
  }
  int best = -1;
  residtrace::ResidtraceModel<double> model;
  std::vector<residtrace::VariantRow<double>> table;
  g.check(
      residtrace::select_variant<double>(variants, ctx, &best, &model, &table));
  if (best < 0) {
    plhs[0] = mxCreateDoubleMatrix(0, 0, mxREAL);
  } else {
    mxArray* bare = bare_template(mxGetCell(T, best));
    if (variants[best].fitted) {
      plhs[0] = bare;
    } else {
      if (mxGetFieldNumber(bare, "nlin") >= 0) {
        mxRemoveField(bare, mxGetFieldNumber(bare, "nlin"));
      }
      plhs[0] = write_model(bare, model);
      mxDestroyArray(bare);
    }
    set(plhs[0], 0, "variant_", mxCreateString(variants[best].name.c_str()));
  }
  if (nlhs > 1) plhs[1] = write_table(table);
}

inline void physcascade_method(const Gateway& g, int nlhs, mxArray* plhs[],
                               int nrhs, const mxArray* prhs[]) {
  if (nrhs != 5) {
    g.fail("badInput",
           "physcascade takes (fname, 'physcascade', cur, D, options)");
  }
  if (nlhs > 2) g.fail("badInput", "physcascade has at most 2 outputs");
  const auto cur = read_model(g, prhs[2]);
  OptionsReader opt(g, prhs[4]);
  const bool sq = opt.choice<bool>("g", {{"sqrt", true}, {"lin", false}}, true);
  const bool clip = opt.flag("clip", false);
  const residtrace::FitRecord<double> D = read_fit_record(g, prhs[3]);
  opt.finish();
  residtrace::ResidtraceModel<double> t;
  bool made = false;
  std::string why;
  g.check(
      residtrace::cascade_template<double>(cur, D, sq, clip, &t, &made, &why));
  plhs[0] = made ? write_saturation_model(prhs[2], t, "", nullptr)
                 : mxCreateDoubleMatrix(0, 0, mxREAL);
  if (nlhs > 1) plhs[1] = mxCreateString(why.c_str());
}

inline void physmodelfit_method(const Gateway& g, int nlhs, mxArray* plhs[],
                                int nrhs, const mxArray* prhs[]) {
  if (nrhs != 5) {
    g.fail("badInput",
           "physmodelfit takes (fname, 'physmodelfit', tmpl, D, options)");
  }
  if (nlhs > 1) g.fail("badInput", "physmodelfit has one output");
  const auto tmpl = read_model(g, prhs[2]);
  if (!tmpl.has_phys) {
    g.fail("badInput", "the template has no physical realisation");
  }
  OptionsReader opt(g, prhs[4]);
  const int maxiter = opt.integer("maxiter");
  const residtrace::FitRecord<double> D = read_fit_record(g, prhs[3]);
  opt.finish();
  if (maxiter < 1) g.fail("badOption", "option 'maxiter' must be >= 1");
  residtrace::ResidtraceModel<double> m;
  g.check(residtrace::fit_physical_model<double>(tmpl, D, maxiter, &m));
  if (!m.estimate.ok) {
    plhs[0] = mxDuplicateArray(prhs[2]);
    set(plhs[0], 0, "ok", mxCreateLogicalScalar(false));
    return;
  }
  plhs[0] = write_saturation_model(prhs[2], m, "", nullptr);
}

inline void driftsegments_method(const Gateway& g, int nlhs, mxArray* plhs[],
                                 int nrhs, const mxArray* prhs[]) {
  if (nrhs != 5) {
    g.fail("badInput",
           "driftsegments takes (fname, 'driftsegments', cur, D, options)");
  }
  if (nlhs > 1) g.fail("badInput", "driftsegments has one output");
  auto cur = read_model(g, prhs[2]);
  cur.estimate.theta = values(g, field(prhs[2], "theta"), "model.theta");
  cur.estimate.s2 = number(g, field(prhs[2], "s2"), "model.s2", NAN);
  OptionsReader opt(g, prhs[4]);
  const double alpha = opt.scalar("alpha");
  auto ctx = read_context(g, prhs[3], opt);
  opt.finish();
  if (!(alpha > 0 && alpha < 1)) {
    g.fail("badOption", "option 'alpha' must lie in (0, 1)");
  }
  residtrace::DriftSegments<double> r;
  g.check(residtrace::drift_segments<double>(cur, ctx, alpha, &r));
  const char* f[] = {"reason", "failed", "K",    "L",    "segments",
                     "theta",  "P",      "tmid", "chi2", "dof",
                     "p",      "slope",  "tval", "shape"};
  plhs[0] = mxCreateStructMatrix(1, 1, 14, f);
  mxArray* s = plhs[0];
  auto scalar = [](double v) { return mxCreateDoubleScalar(v); };
  mxSetField(s, 0, "reason", mxCreateString(r.reason.c_str()));
  mxSetField(s, 0, "failed", mxCreateLogicalScalar(r.failed));
  mxSetField(s, 0, "K", scalar(r.K));
  mxSetField(s, 0, "L", scalar(static_cast<double>(r.L)));
  mxSetField(s, 0, "segments", scalar(r.segments));
  mxSetField(s, 0, "theta", matrix(r.theta));
  const mwSize np = static_cast<mwSize>(r.theta.cols());
  const mwSize dims[3] = {np, np, static_cast<mwSize>(r.P.size())};
  mxArray* P = mxCreateNumericArray(3, dims, mxDOUBLE_CLASS, mxREAL);
  for (std::size_t k = 0; k < r.P.size(); ++k) {
    Eigen::Map<Eigen::MatrixXd>(mxGetPr(P) + k * np * np, r.P[k].rows(),
                                r.P[k].cols()) = r.P[k];
  }
  mxSetField(s, 0, "P", P);
  mxSetField(s, 0, "tmid", row(r.tmid));
  mxSetField(s, 0, "chi2", scalar(r.chi2));
  mxSetField(s, 0, "dof", scalar(r.dof));
  mxSetField(s, 0, "p", scalar(r.p));
  mxSetField(s, 0, "slope", row(r.slope));
  mxSetField(s, 0, "tval", row(r.tval));
  mxSetField(s, 0, "shape", row(r.shape));
}

inline bool dispatch(const std::string& method, const Gateway& g, int nlhs,
                     mxArray* plhs[], int nrhs, const mxArray* prhs[]) {
  if (method == "candidate") {
    candidate_method(g, nlhs, plhs, nrhs, prhs);
  } else if (method == "select") {
    select_method(g, nlhs, plhs, nrhs, prhs);
  } else if (method == "physcascade") {
    physcascade_method(g, nlhs, plhs, nrhs, prhs);
  } else if (method == "physmodelfit") {
    physmodelfit_method(g, nlhs, plhs, nrhs, prhs);
  } else if (method == "driftsegments") {
    driftsegments_method(g, nlhs, plhs, nrhs, prhs);
  } else {
    return false;
  }
  return true;
}

}  // namespace ctid::mex::residtrace_candidate
