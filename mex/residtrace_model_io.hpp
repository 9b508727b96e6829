// SPDX-License-Identifier: BSD-3-Clause
// Copyright (C) the ctid authors
// The residtrace model (core/include/ctid/apps/residtrace/model.hpp) to and
// from the Octave struct the residtrace functions pass around:
//
//   F (1-by-(n+1)), fixed (n flags), channels (a struct array: type
//   "input" | "const" | "signv" | "power" | "clip" | "ypower" | "node",
//   col (1-based or []), param ([], a number, "y" for a signv channel read
//   from the output, a struct fa/Fa, ts/Ts, rule, lo, hi for a node), nb,
//   nk, B), out (a struct array: type "offset" | "poly" | "sinusoid" |
//   "sat", c, cstd, omega), intersample, levels, x0, noise ([] or A(q)),
//   ltv ([] or the drift's struct), phys ([] or kind "stop" | "cascade",
//   substeps, yscale, lo, hi; for a cascade g, d, alpha, gamma, c, wbar,
//   yhi, spill, h0, z0) and the estimate theta, cov, s2, np, bic, e_est,
//   ok. Fields the core does not use are kept: write_model changes a copy
//   of the struct it was read from.
//
//   read_model(g, s)            the model of the struct s (with the
//                               covariance cov of its estimate)
//   read_reading_labels(g, s)   what its physical reading takes beyond it
//   write_model(s, model)       s with the model's structure and estimate
//   read_closed_loop(g, s, n)   a record's loop (num, den, r1, r2) or none
#pragma once

#include <algorithm>
#include <cctype>
#include <cmath>
#include <string>
#include <vector>

#include "ctid/apps/residtrace/model.hpp"
#include "ctid/apps/residtrace/physical_reading.hpp"
#include "options_reader.hpp"

namespace ctid::mex {

namespace model_io_detail {

inline const mxArray* field(const mxArray* s, const char* name, mwIndex i = 0) {
  return s != nullptr && mxIsStruct(s) ? mxGetField(s, i, name) : nullptr;
}

inline bool empty(const mxArray* a) { return a == nullptr || mxIsEmpty(a); }

// The values of a real double or logical array, non-finite ones included.
inline Eigen::VectorXd values(const Gateway& g, const mxArray* a,
                              const std::string& what) {
  if (a == nullptr) return Eigen::VectorXd();
  const std::size_t n = mxGetNumberOfElements(a);
  Eigen::VectorXd v(static_cast<Eigen::Index>(n));
  if (mxIsLogical(a)) {
    const mxLogical* p = mxGetLogicals(a);
    for (std::size_t i = 0; i < n; ++i) v(i) = p[i] ? 1 : 0;
    return v;
  }
  g.require_real_double(a, what);
  const double* p = mxGetPr(a);
  for (std::size_t i = 0; i < n; ++i) v(i) = p[i];
  return v;
}

inline double number(const Gateway& g, const mxArray* a,
                     const std::string& what, double fallback) {
  if (empty(a)) return fallback;
  const Eigen::VectorXd v = values(g, a, what);
  if (v.size() != 1) g.fail("badInput", what + " must be a scalar");
  return v(0);
}

// A whole number in [0, 1e6] (empty: fallback).
inline int count(const Gateway& g, const mxArray* a, const std::string& what,
                 int fallback) {
  const double v = number(g, a, what, fallback);
  if (!(v >= 0 && v <= 1e6) || v != std::floor(v)) {
    g.fail("badInput", what + " must be a whole number >= 0");
  }
  return static_cast<int>(v);
}

inline std::string word(const Gateway& g, const mxArray* a,
                        const std::string& what) {
  return g.text(a, what);
}

inline InterSample hold(const Gateway& g, const mxArray* a) {
  if (empty(a)) return InterSample::kZoh;
  std::string s = word(g, a, "model.intersample");
  for (char& c : s) c = static_cast<char>(std::tolower(c));
  if (s == "zoh") return InterSample::kZoh;
  if (s == "foh") return InterSample::kFoh;
  g.fail("badInput", "model.intersample must be 'zoh' or 'foh'");
}

inline residtrace::StructureChannel<double> read_channel(const Gateway& g,
                                                         const mxArray* s,
                                                         mwIndex j) {
  using residtrace::ChannelKind;
  residtrace::StructureChannel<double> c;
  const std::string type = word(g, field(s, "type", j), "channel type");
  const mxArray* param = field(s, "param", j);
  if (type == "input") {
    c.kind = ChannelKind::kInput;
  } else if (type == "const") {
    c.kind = ChannelKind::kConstant;
  } else if (type == "signv") {
    c.kind = !empty(param) && mxIsChar(param) &&
                     word(g, param, "channel param") == "y"
                 ? ChannelKind::kSignOutput
                 : ChannelKind::kSignV;
  } else if (type == "power") {
    c.kind = ChannelKind::kPower;
  } else if (type == "clip") {
    c.kind = ChannelKind::kClip;
  } else if (type == "ypower") {
    c.kind = ChannelKind::kOutputPower;
  } else if (type == "node") {
    c.kind = ChannelKind::kNode;
  } else {
    g.fail("badInput", "unknown channel type '" + type + "'");
  }
  c.col = count(g, field(s, "col", j), "channel col", 0) - 1;
  c.nb = count(g, field(s, "nb", j), "channel nb", 1);
  c.nk = count(g, field(s, "nk", j), "channel nk", 0);
  c.B = values(g, field(s, "B", j), "channel B");
  if (c.kind == ChannelKind::kNode) {
    if (empty(param) || !mxIsStruct(param)) {
      g.fail("badInput", "a node channel needs its node struct");
    }
    auto get = [&](const char* a, const char* b) {
      const mxArray* f = field(param, a);
      return f != nullptr ? f : field(param, b);
    };
    c.node_f = values(g, get("Fa", "fa"), "node Fa");
    c.node_ts = number(g, get("Ts", "ts"), "node Ts", 1);
    c.node_rule = hold(g, get("rule", "rule"));
    c.node_lo = number(g, field(param, "lo"), "node lo", -INFINITY);
    c.node_hi = number(g, field(param, "hi"), "node hi", INFINITY);
  } else if (!empty(param) && !mxIsChar(param)) {
    c.param = number(g, param, "channel param", 0);
  }
  return c;
}

inline residtrace::OutputTerm<double> read_term(const Gateway& g,
                                                const mxArray* s, mwIndex k) {
  using residtrace::OutputTermKind;
  residtrace::OutputTerm<double> t;
  const std::string type = word(g, field(s, "type", k), "output term type");
  if (type == "offset") {
    t.kind = OutputTermKind::kOffset;
  } else if (type == "poly") {
    t.kind = OutputTermKind::kPolynomial;
  } else if (type == "sinusoid") {
    t.kind = OutputTermKind::kSinusoid;
  } else if (type == "sat") {
    t.kind = OutputTermKind::kSaturation;
  } else {
    g.fail("badInput", "unknown output term '" + type + "'");
  }
  t.c = values(g, field(s, "c", k), "output term c");
  t.cstd = values(g, field(s, "cstd", k), "output term cstd");
  t.omega = number(g, field(s, "omega", k), "output term omega", 0);
  return t;
}

inline residtrace::PhysicalModel<double> read_phys(const Gateway& g,
                                                   const mxArray* P) {
  using residtrace::PhysicalKind;
  residtrace::PhysicalModel<double> p;
  const std::string kind = word(g, field(P, "kind"), "phys.kind");
  if (kind == "stop") {
    p.kind = PhysicalKind::kStop;
  } else if (kind == "cascade") {
    p.kind = PhysicalKind::kCascade;
  } else {
    g.fail("notSupported", "realisation '" + kind + "'");
  }
  p.substeps = count(g, field(P, "substeps"), "phys.substeps", 1);
  if (p.substeps < 1 || p.substeps > 10000) {
    g.fail("badInput", "phys.substeps must lie in [1, 1e4]");
  }
  p.yscale = number(g, field(P, "yscale"), "phys.yscale", 1);
  const double lo = number(g, field(P, "lo"), "phys.lo", -INFINITY);
  const double hi = number(g, field(P, "hi"), "phys.hi", INFINITY);
  if (std::isfinite(lo)) p.lo = lo;
  if (std::isfinite(hi)) p.hi = hi;
  if (p.kind == PhysicalKind::kStop) return p;
  const std::string gname = word(g, field(P, "g"), "phys.g");
  if (gname != "sqrt" && gname != "lin") {
    g.fail("badInput", "phys.g must be 'sqrt' or 'lin'");
  }
  p.sqrt_nodes = gname == "sqrt";
  p.d = number(g, field(P, "d"), "phys.d", 0);
  p.alpha = number(g, field(P, "alpha"), "phys.alpha", 1);
  p.gamma = number(g, field(P, "gamma"), "phys.gamma", 1);
  p.c = number(g, field(P, "c"), "phys.c", 0);
  p.wbar = values(g, field(P, "wbar"), "phys.wbar");
  auto optional = [&](const char* name, bool* has, double* v) {
    const mxArray* a = field(P, name);
    *has = !empty(a);
    if (*has) *v = number(g, a, std::string("phys.") + name, 0);
  };
  optional("yhi", &p.has_yhi, &p.yhi);
  optional("spill", &p.has_spill, &p.spill);
  optional("h0", &p.has_h0, &p.h0);
  optional("z0", &p.has_z0, &p.z0);
  if (p.has_spill && !(p.spill >= 0 && p.spill <= 1)) {
    g.fail("badInput", "phys.spill must lie in [0, 1]");
  }
  return p;
}

// A real double or logical matrix with its shape (empty or absent: 0x0).
inline Eigen::MatrixXd shaped(const Gateway& g, const mxArray* a,
                              const std::string& what) {
  if (empty(a)) return Eigen::MatrixXd();
  const Eigen::VectorXd v = values(g, a, what);
  return Eigen::Map<const Eigen::MatrixXd>(
      v.data(), static_cast<Eigen::Index>(mxGetM(a)),
      static_cast<Eigen::Index>(v.size() /
                                std::max<std::size_t>(mxGetM(a), 1)));
}

inline mxArray* row(const Eigen::VectorXd& v) {
  mxArray* a = make_output_matrix(1, static_cast<std::size_t>(v.size()));
  for (Eigen::Index i = 0; i < v.size(); ++i) mxGetPr(a)[i] = v(i);
  return a;
}

inline mxArray* matrix(const Eigen::MatrixXd& m) {
  mxArray* a = make_output_matrix(static_cast<std::size_t>(m.rows()),
                                  static_cast<std::size_t>(m.cols()));
  Eigen::Map<Eigen::MatrixXd>(mxGetPr(a), m.rows(), m.cols()) = m;
  return a;
}

// s.name = value (the field added when absent).
inline void set(mxArray* s, mwIndex i, const char* name, mxArray* value) {
  if (mxGetFieldNumber(s, name) < 0) mxAddField(s, name);
  mxArray* old = mxGetField(s, i, name);
  if (old != nullptr) mxDestroyArray(old);
  mxSetField(s, i, name, value);
}

}  // namespace model_io_detail

inline residtrace::ResidtraceModel<double> read_model(const Gateway& g,
                                                      const mxArray* s) {
  using namespace model_io_detail;
  if (s == nullptr || !mxIsStruct(s) || mxGetNumberOfElements(s) != 1) {
    g.fail("badInput", "the model must be a 1x1 struct");
  }
  residtrace::ResidtraceModel<double> m;
  m.F = values(g, field(s, "F"), "model.F");
  const Eigen::Index n = m.F.size() - 1;
  if (n < 1) g.fail("badInput", "model.F must have order >= 1");
  const Eigen::VectorXd fixed = values(g, field(s, "fixed"), "model.fixed");
  if (fixed.size() != n) {
    g.fail("dimensionMismatch",
           "model.fixed needs one flag per coefficient of F");
  }
  for (Eigen::Index i = 0; i < n; ++i) m.fixed.push_back(fixed(i) != 0);
  const mxArray* ch = field(s, "channels");
  if (ch == nullptr || !mxIsStruct(ch)) {
    g.fail("badInput", "model.channels must be a struct array");
  }
  for (mwIndex j = 0; j < mxGetNumberOfElements(ch); ++j) {
    m.channels.push_back(read_channel(g, ch, j));
  }
  const mxArray* out = field(s, "out");
  if (out != nullptr && mxIsStruct(out)) {
    for (mwIndex k = 0; k < mxGetNumberOfElements(out); ++k) {
      m.out.push_back(read_term(g, out, k));
    }
  }
  m.levels = number(g, field(s, "levels"), "model.levels", 0) != 0;
  m.rule = hold(g, field(s, "intersample"));
  m.x0 = number(g, field(s, "x0"), "model.x0", 0) != 0;
  m.noise = values(g, field(s, "noise"), "model.noise");
  m.drifting = !empty(field(s, "ltv"));
  m.estimate.cov = shaped(g, field(s, "cov"), "model.cov");
  m.estimate.np = count(g, field(s, "np"), "model.np", 0);
  m.estimate.bic = number(g, field(s, "bic"), "model.bic", NAN);
  m.estimate.e = values(g, field(s, "e_est"), "model.e_est");
  const mxArray* phys = field(s, "phys");
  m.has_phys = !empty(phys);
  if (m.has_phys) m.phys = read_phys(g, phys);
  if (m.has_phys && m.phys.kind == residtrace::PhysicalKind::kStop &&
      (out == nullptr || !mxIsStruct(out))) {
    // its output offsets are parameters of the realisation
    g.fail("badInput", "an end stop needs model.out as a struct array");
  }
  return m;
}

// The channels' names, the diagonal of the drift's Qn (ltv.Qn) and the
// standard deviations of a physical realisation's parameters (phys.theta;
// the square roots of diag(phys.cov), NaN without it) of the model struct
// s.
inline residtrace::ReadingLabels<double> read_reading_labels(const Gateway& g,
                                                             const mxArray* s) {
  using namespace model_io_detail;
  residtrace::ReadingLabels<double> x;
  const mxArray* ch = field(s, "channels");
  for (mwIndex j = 0; ch != nullptr && j < mxGetNumberOfElements(ch); ++j) {
    const mxArray* name = field(ch, "name", j);
    x.channel_names.push_back(empty(name) ? std::string()
                                          : word(g, name, "channel name"));
  }
  const mxArray* ltv = field(s, "ltv");
  if (!empty(ltv)) x.drift_q = shaped(g, field(ltv, "Qn"), "ltv.Qn").diagonal();
  const mxArray* phys = field(s, "phys");
  if (!empty(phys)) {
    const Eigen::MatrixXd C = shaped(g, field(phys, "cov"), "phys.cov");
    if (field(phys, "cov") != nullptr) {
      x.phys_std = C.diagonal().unaryExpr(
          [](double v) { return std::sqrt(std::fmax(v, 0.0)); });
    } else {
      x.phys_std = Eigen::VectorXd::Constant(
          static_cast<Eigen::Index>(
              values(g, field(phys, "theta"), "phys.theta").size()),
          NAN);
    }
  }
  return x;
}

// A copy of the struct s with the model's F, fixed, channel numerators
// and nb, the fitted output terms' c and cstd and, when set, the estimate
// (theta, cov, s2, np, bic, e_est); ok always.
inline mxArray* write_model(const mxArray* s,
                            const residtrace::ResidtraceModel<double>& m) {
  using namespace model_io_detail;
  mxArray* r = mxDuplicateArray(s);
  const residtrace::ModelEstimate<double>& e = m.estimate;
  if (e.set) {
    mxArray* out = mxGetField(r, 0, "out");
    for (std::size_t k = 0; k < m.out.size(); ++k) {
      if (!m.out[k].fitted || out == nullptr) continue;
      set(out, k, "c", row(m.out[k].c));
      set(out, k, "cstd", row(m.out[k].cstd));
    }
    set(r, 0, "F", row(m.F));
    // fixed and nb change with the order only (a residualised fast pole)
    const mxArray* f0 = mxGetField(r, 0, "fixed");
    bool same = f0 != nullptr && mxGetNumberOfElements(f0) == m.fixed.size();
    for (std::size_t i = 0; same && i < m.fixed.size(); ++i) {
      same = (mxIsLogical(f0) ? mxGetLogicals(f0)[i] != 0
                              : mxGetPr(f0)[i] != 0) == m.fixed[i];
    }
    if (!same) {
      mxArray* fixed = mxCreateLogicalMatrix(1, m.fixed.size());
      for (std::size_t i = 0; i < m.fixed.size(); ++i) {
        mxGetLogicals(fixed)[i] = m.fixed[i];
      }
      set(r, 0, "fixed", fixed);
    }
    mxArray* ch = mxGetField(r, 0, "channels");
    for (std::size_t j = 0; j < m.channels.size(); ++j) {
      set(ch, j, "B", row(m.channels[j].B));
      const mxArray* nb = mxGetField(ch, j, "nb");
      if (nb == nullptr || !mxIsDouble(nb) || mxGetNumberOfElements(nb) != 1 ||
          mxGetPr(nb)[0] != m.channels[j].nb) {
        set(ch, j, "nb", mxCreateDoubleScalar(m.channels[j].nb));
      }
    }
    set(r, 0, "np", mxCreateDoubleScalar(e.np));
    set(r, 0, "s2", mxCreateDoubleScalar(e.s2));
    set(r, 0, "theta", matrix(e.theta));
    set(r, 0, "cov", matrix(e.cov));
    set(r, 0, "bic", mxCreateDoubleScalar(e.bic));
    set(r, 0, "e_est", matrix(e.e));
  }
  set(r, 0, "ok", mxCreateLogicalScalar(e.ok));
  return r;
}

// The closed loop of a record (the struct with num, den, r1, r2; [] or
// absent: open loop) of n samples.
inline bool read_closed_loop(const Gateway& g, const mxArray* s, long n,
                             residtrace::ClosedLoop<double>* loop) {
  using namespace model_io_detail;
  if (empty(s)) return false;
  if (!mxIsStruct(s)) g.fail("badInput", "the loop must be a struct");
  loop->num = values(g, field(s, "num"), "loop.num");
  loop->den = values(g, field(s, "den"), "loop.den");
  loop->r1 = values(g, field(s, "r1"), "loop.r1");
  loop->r2 = values(g, field(s, "r2"), "loop.r2");
  if (loop->r1.size() != n || loop->r2.size() != n) {
    g.fail("dimensionMismatch", "loop.r1 and loop.r2 need one value a sample");
  }
  if (loop->den.size() == 0 || loop->den(0) == 0 || loop->num.size() == 0) {
    g.fail("badInput", "the loop's controller needs num and den(1) != 0");
  }
  return true;
}

}  // namespace ctid::mex
