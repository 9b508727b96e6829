// SPDX-License-Identifier: BSD-3-Clause
// Copyright (C) the ctid authors
// The fit of a residtrace model (model.hpp) on its estimation record: the
// structure fit (structure_fit.hpp, SRIVC, thesis eqs. 2.8-2.13) and the
// refits around it.
//
// - Fast poles. A real pole p with p Ts > 1000 decays by e^-1000 over one
//   sampling interval: the samples cannot tell it from an infinitely fast
//   one (its in-band effect is a relative change of at most pi / (p Ts) <
//   0.3 %). A fit whose loss is flat in that direction lets such a pole run
//   off (Silverbox: a pole at -2484 rad/s went to -5.8e10 when a cubic
//   spring was added), and the companion form the simulators and the free
//   responses use is then so ill conditioned that every simulation and
//   every fit started from it fails. Such poles are residualised (singular
//   perturbation: the mode at its steady state, F / (p + s) -> F / p, each
//   numerator divided by p) when every channel stays strictly proper, and
//   the model is fitted again in the lower order (residualised,
//   fit_model). When every start of a fit fails (the engine finds its
//   instruments rank deficient because a pole of the start lies beyond
//   what the samples resolve), the template with its real poles beyond
//   the Nyquist frequency (p Ts > pi) residualised, the numerators cut to
//   the new order, is fitted instead. Neither for the re-estimates of a
//   model in its own structure (keep_order: its order is the user's).
// - A function of the output inside the dynamics (an output-power channel)
//   is first fitted with the measured output as its signal. The engine then
//   integrates that signal open loop: its noise, and the error of a start
//   from rest, are integrated too, which a model with little damping of its
//   own (a tank whose outflow is its only damping) cannot forget, so the
//   fit keeps a spurious damping. Here the signal is then the model's
//   simulated output (plus its free response when the initial state is
//   estimated), the model fitted again, and so on while the simulation
//   error on the estimation record falls (at most three rounds); the
//   residual variance and BIC are those of that simulation.
//
// A model with a physical realisation is fitted by its simulation error
// (physical_fit.hpp), not here.
#pragma once

#include <cmath>
#include <complex>
#include <limits>
#include <vector>

#include "ctid/apps/residtrace/model.hpp"
#include "ctid/apps/residtrace/responses.hpp"
#include "ctid/apps/residtrace/simulate.hpp"
#include "ctid/apps/residtrace/statistics.hpp"
#include "ctid/apps/residtrace/structure_fit.hpp"
#include "ctid/base/polynomial.hpp"
#include "ctid/base/status.hpp"

namespace ctid::residtrace {

// The estimation record: the structure fit's, with its closed loop.
template <typename S>
struct FitRecord : StructureRecord<S> {
  bool closed = false;
  ClosedLoop<S> loop;
};

struct ModelFitSettings {
  int max_iterations = 20;
  bool keep_order = false;  // no residualisation of fast poles
  int substeps = 10;        // of the simulations of the refit
  bool simulated = false;   // the output powers' signal is simulated
};

namespace model_fit_detail {

// [e, yh] of the model simulated on the estimation record (its own output
// fed back), with its free response fitted when the initial state is
// estimated; e all infinite when the simulation fails.
template <typename S>
void simulation_error(const ResidtraceModel<S>& model, const FitRecord<S>& D,
                      int substeps, Vector<S>* e, Vector<S>* yh) {
  const Eigen::Index N = D.y.size();
  ModelSimulation<S> sim;
  const Status status = simulate_model<S>(
      model, D.u, D.ts, D.closed ? &D.loop : nullptr, substeps, nullptr, &sim);
  if (status.ok()) {
    *yh = sim.y;
  } else {
    *yh = Vector<S>::Constant(N, std::numeric_limits<S>::infinity());
  }
  *e = D.y - *yh;
  if (D.initial_state && e->allFinite()) {
    Matrix<S> X;
    if (free_responses<S>(
            Vector<S>(model.F.tail(model.F.size() - 1) / model.F(0)), D.ts, N,
            X)
            .ok()) {
      const Vector<S> f = simulate_detail::projection<S>(X, *e);
      *yh += f;
      *e -= f;
    }
  }
  if (!e->allFinite()) {
    *e = Vector<S>::Constant(N, std::numeric_limits<S>::infinity());
  } else if (static_cast<Eigen::Index>(D.missing.size()) == N) {
    for (Eigen::Index k = 0; k < N; ++k)
      if (D.missing[k]) (*e)(k) = 0;  // bridged samples carry no error
  }
}

}  // namespace model_fit_detail

// The model with its real poles p with p Ts > limit residualised (see the
// head of this file); with trim, a numerator that would no longer be
// strictly proper is cut to its nn lowest-order coefficients (the in-band
// part, re-estimated by the fit), else such a model is not reduced.
// Returns false when there is nothing to remove. The fixed coefficients
// of F other than its integrators are freed.
template <typename S>
bool residualised(const ResidtraceModel<S>& model, S ts, S limit, bool trim,
                  ResidtraceModel<S>* red) {
  const Vector<S> F = model.F / model.F(0);
  const Eigen::Index n = F.size() - 1;
  if (!F.allFinite()) return false;
  const std::vector<std::complex<S>> z = roots_descending<S>(F);
  std::vector<bool> fast(static_cast<std::size_t>(n));
  Eigen::Index nfast = 0;
  for (Eigen::Index i = 0; i < n; ++i) {
    fast[i] = z[i].imag() == 0 && -z[i].real() * ts > limit;
    nfast += fast[i];
  }
  const Eigen::Index nn = n - nfast;
  bool long_numerator = false;
  for (const StructureChannel<S>& c : model.channels) {
    long_numerator = long_numerator || c.nb > nn;
  }
  if (nfast == 0 || nn < 1 || (!trim && long_numerator)) return false;
  Eigen::Index r = 0;
  while (r < n && model.fixed[n - r - 1] && F(n - r) == 0) ++r;
  if (nn < r) return false;
  *red = model;
  Eigen::Matrix<std::complex<S>, Eigen::Dynamic, 1> slow(nn);
  S g = 1;
  for (Eigen::Index i = 0, k = 0; i < n; ++i) {
    if (fast[i]) {
      g *= -z[i].real();
    } else {
      slow(k++) = z[i];
    }
  }
  const auto c = monic_from_roots<S>(slow);
  red->F = c.real();
  for (Eigen::Index i = nn - r + 1; i <= nn; ++i) red->F(i) = 0;
  red->fixed.assign(static_cast<std::size_t>(nn), false);
  for (Eigen::Index i = nn - r; i < nn; ++i) red->fixed[i] = true;
  for (StructureChannel<S>& ch : red->channels) {
    Vector<S> B = ch.B / g;
    if (B.size() > nn) {
      B = Vector<S>(B.tail(nn));
      ch.nb = static_cast<int>(nn);
    }
    ch.B = B;
  }
  return true;
}

// fit_model: the structure fit of the template from the starts (see
// fit_structure) and the refits of the head of this file. out: the
// template with the estimate, or with estimate.ok false (and its values
// otherwise kept) when no start gives a stable estimate.
template <typename S>
Status fit_model(const ResidtraceModel<S>& tmpl, const FitRecord<S>& D,
                 const std::vector<Vector<S>>& starts,
                 const ModelFitSettings& settings, ResidtraceModel<S>* out) {
  using namespace model_fit_detail;
  if (out == nullptr) return bad_input("no result");
  if (tmpl.has_phys) {
    return not_supported(
        "a physical realisation is fitted by its simulation error");
  }
  ResidtraceModel<S> model = tmpl;
  StructureFit<S> r;
  Status status =
      fit_structure<S>(tmpl, D, starts, settings.max_iterations, &r);
  if (!status.ok()) return status;
  if (!r.ok) {
    model.estimate.ok = false;
    ResidtraceModel<S> red;
    if (r.failed_round == 1 && !settings.keep_order &&
        residualised<S>(tmpl, D.ts, S(3.141592653589793238462643), true,
                        &red)) {
      ResidtraceModel<S> m;
      status = fit_model<S>(red, D, {red.F}, settings, &m);
      if (!status.ok()) return status;
      if (m.estimate.ok) model = m;
    }
    *out = model;
    return Status::Ok();
  }
  for (std::size_t k = 0; k < r.out.size(); ++k) {
    if (!r.out[k].fitted) continue;
    model.out[k].c = r.out[k].c;
    model.out[k].cstd = r.out[k].cstd;
    model.out[k].fitted = true;
  }
  model.F = r.F;
  for (std::size_t j = 0; j < model.channels.size(); ++j) {
    model.channels[j].B = r.B[j];
  }
  ModelEstimate<S>& est = model.estimate;
  est.np = r.np;
  est.s2 = r.s2;
  est.theta = r.theta;
  est.cov = r.cov;
  est.bic = r.bic;
  est.e = r.e;
  est.ok = true;
  est.set = true;
  if (!settings.keep_order) {
    ResidtraceModel<S> red;
    if (residualised<S>(model, D.ts, S(1000), false, &red)) {
      // a pole beyond what the samples can see: the fit is repeated in the
      // structure without it, started from the residualised model
      ResidtraceModel<S> m;
      status = fit_model<S>(red, D, {red.F}, settings, &m);
      if (!status.ok()) return status;
      if (m.estimate.ok) {
        *out = m;
        return Status::Ok();
      }
    }
  }
  bool output_power = false;
  for (const StructureChannel<S>& c : tmpl.channels) {
    output_power = output_power || c.kind == ChannelKind::kOutputPower;
  }
  if (output_power && !settings.simulated) {
    // the output powers' signal simulated (see the head of this file)
    ModelFitSettings s = settings;
    s.simulated = true;
    Vector<S> e, yh;
    simulation_error<S>(model, D, settings.substeps, &e, &yh);
    S sse = detail::sum_squares(e);
    for (int round = 1; round <= 3; ++round) {
      if (!std::isfinite(sse)) break;
      FitRecord<S> Dk = D;
      Dk.ysm = yh;
      ResidtraceModel<S> m;
      status = fit_model<S>(model, Dk, {model.F}, s, &m);
      if (!status.ok()) return status;
      if (!m.estimate.ok) break;
      Vector<S> e2, yh2;
      simulation_error<S>(m, D, settings.substeps, &e2, &yh2);
      const S sse2 = detail::sum_squares(e2);
      if (!(sse2 < sse)) break;
      model = m;
      e = e2;
      yh = yh2;
      sse = sse2;
    }
    if (!std::isfinite(sse)) {
      model.estimate.ok = false;
      *out = model;
      return Status::Ok();
    }
    const Eigen::Index N = D.y.size();
    model.estimate.s2 =
        sse / std::max<S>(static_cast<S>(N - model.estimate.np), S(1));
    model.estimate.bic =
        static_cast<S>(N) * std::log(model.estimate.s2) +
        static_cast<S>(model.estimate.np) * std::log(static_cast<S>(N));
    model.estimate.e = e;
  }
  *out = model;
  return Status::Ok();
}

}  // namespace ctid::residtrace
