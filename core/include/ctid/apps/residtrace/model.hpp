// SPDX-License-Identifier: BSD-3-Clause
// Copyright (C) the ctid authors
// The model of residtrace: the structure of structure_fit.hpp,
//
//   F(p) x(t) = sum_j B_j(p) w_j(t - nk_j Ts),   y = x + o(x, t),
//
// with what the tool adds around it: the hold of the record's inputs, an
// initial state estimated on each record, an AR noise model A(q) of the
// output error (its one-step-ahead predictor), a physical realisation
// (physical_fit.hpp: an end stop, a tank cascade) that replaces the linear
// dynamics, whether its parameters drift, and the estimate of its last
// fit. The closed loop of a record, u1 = r1 + C(q^-1)(r2 - y) (thesis eq.
// 2.39), is the record's, not the model's.
#pragma once

#include <algorithm>
#include <cmath>
#include <vector>

#include "ctid/apps/residtrace/physical_fit.hpp"
#include "ctid/apps/residtrace/structure_fit.hpp"
#include "ctid/base/types.hpp"

namespace ctid::residtrace {

// The estimate of a fit (fit_model, model_fit.hpp): the free dynamic
// parameters theta (free f's, then each channel's b's) with their SRIVC
// covariance, the residual variance, the number of estimated parameters,
// BIC = N log s2 + np log N and the errors on the estimation record.
template <typename S>
struct ModelEstimate {
  bool ok = false;
  bool set = false;  // theta .. e hold a fit's values
  Vector<S> theta;
  Matrix<S> cov;
  S s2 = 0, bic = 0;
  int np = 0;
  Vector<S> e;
};

// The structure (F, fixed, channels, output terms, levels) and:
template <typename S>
struct ResidtraceModel : StructureModel<S> {
  InterSample rule = InterSample::kZoh;  // the hold of the inputs
  bool x0 = false;  // an initial state, fitted on each record
  Vector<S> noise;  // A(q) = [1 a1 .. ap] of the output error; empty: none
  // A physical realisation: its own fields (kind, substeps, yscale, the
  // levels; for a cascade g, d, alpha, gamma, c, wbar, yhi, spill, h0,
  // z0); F, fixed, the numerators and the output offsets are the
  // structure's (physical_realisation below).
  bool has_phys = false;
  PhysicalModel<S> phys;
  bool drifting = false;  // tracked parameters (their path is given)
  ModelEstimate<S> estimate;
};

// The closed loop of a record: the first input is r1 + C(q^-1)(r2 - y),
// C = num / den in powers of q^-1.
template <typename S>
struct ClosedLoop {
  Vector<S> num, den;
  Vector<S> r1, r2;
};

// The sum of the output terms other than a saturation at the model output
// x (t = k ts from the first sample): an offset c, c1 x^2 + c2 x^3,
// c1 sin(omega t) + c2 cos(omega t); then a saturation (levels c = [lo
// hi]) clips y = x + o. Returns o with y = x + o.
template <typename S>
Vector<S> output_terms(const std::vector<OutputTerm<S>>& out,
                       const Vector<S>& x, S ts) {
  const Eigen::Index N = x.size();
  Vector<S> o = Vector<S>::Zero(N);
  const OutputTerm<S>* sat = nullptr;
  for (const OutputTerm<S>& m : out) {
    switch (m.kind) {
      case OutputTermKind::kOffset:
        for (Eigen::Index k = 0; k < N; ++k) o(k) += m.c(0);
        break;
      case OutputTermKind::kPolynomial:
        for (Eigen::Index k = 0; k < N; ++k) {
          o(k) += m.c(0) * (x(k) * x(k)) + m.c(1) * (x(k) * x(k) * x(k));
        }
        break;
      case OutputTermKind::kSinusoid:
        for (Eigen::Index k = 0; k < N; ++k) {
          const S t = static_cast<S>(k) * ts;
          o(k) +=
              m.c(0) * std::sin(m.omega * t) + m.c(1) * std::cos(m.omega * t);
        }
        break;
      case OutputTermKind::kSaturation:
        sat = &m;
        break;
    }
  }
  if (sat != nullptr) {
    for (Eigen::Index k = 0; k < N; ++k) {
      const S y = x(k) + o(k);
      // (fmax, fmin: a level that is not a number is none)
      o(k) = std::fmin(std::fmax(y, sat->c(0)), sat->c(1)) - x(k);
    }
  }
  return o;
}

// The physical realisation of a model with the structure's parameters: for
// an end stop F, fixed, the channels' numerators and the output offsets
// (the first a parameter, the others fixed); for a cascade each channel's
// gain (the last coefficient of its numerator).
template <typename S>
PhysicalModel<S> physical_realisation(const ResidtraceModel<S>& m) {
  PhysicalModel<S> p = m.phys;
  const std::size_t nc = m.channels.size();
  if (p.kind == PhysicalKind::kStop) {
    p.F = m.F;
    p.fixed = m.fixed;
    p.B.clear();
    for (const StructureChannel<S>& c : m.channels) p.B.push_back(c.B);
    p.has_offset = false;
    p.offset = 0;
    p.offset_fixed = 0;
    for (const OutputTerm<S>& t : m.out) {
      if (t.kind != OutputTermKind::kOffset) continue;
      if (!p.has_offset) {
        p.has_offset = true;
        p.offset = t.c(0);
      } else {
        p.offset_fixed += t.c(0);
      }
    }
  } else {
    p.b.resize(static_cast<Eigen::Index>(nc));
    for (std::size_t j = 0; j < nc; ++j) {
      const Vector<S>& B = m.channels[j].B;
      p.b(static_cast<Eigen::Index>(j)) = B.size() ? B(B.size() - 1) : S(0);
    }
    if (p.wbar.size() != static_cast<Eigen::Index>(nc)) {
      p.wbar = Vector<S>::Zero(static_cast<Eigen::Index>(nc));
    }
  }
  return p;
}

}  // namespace ctid::residtrace
