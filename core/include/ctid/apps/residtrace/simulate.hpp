// SPDX-License-Identifier: BSD-3-Clause
// Copyright (C) the ctid authors
// The simulation of a residtrace model (model.hpp) and its error on a
// record that was not used to fit it, by the core's simulators:
//
//   simulate_model: the output from rest on the inputs u (N-by-nu),
//     y = x + o(x, t) (model.hpp, output_terms). The dynamic part x:
//     - a physical realisation: simulate_physical (physical_fit.hpp) on
//       the channel signals delayed by nk, open loop only;
//     - drifting parameters (a path thm, N rows: the free f's, then the
//       numerator) of a model with one input channel in open loop: the LTV
//       simulator (ltv_simulator.hpp, thesis eq. 1.49), the parameters
//       linear between the samples;
//     - an LTI model in open loop without a channel fed by its own output:
//       the LTV simulator with constant parameters, exact for inputs held
//       by ZOH or FOH (thesis App. A.1);
//     - otherwise (the sign of the velocity, powers of the output, a closed
//       loop, drifting parameters of several channels): the effect-model
//       simulator (effect_simulator.hpp) in `substeps` sub-steps per
//       sampling interval, each exact for the held channels; with a path
//       thm, the parameters of each interval's first sample.
//   validation_error: e = y - yh on a record, yh the simulation from the
//     start of the whole record when the record is the end of a split one
//     (u_pre: the inputs before it), plus the least-squares fit on e of the
//     free responses of 1/F (responses.hpp) when the model has an initial
//     state, plus the sinusoids' amplitudes fitted on each half of the
//     residual and applied to the other (two-fold cross-fitting: their
//     phases are unknown on another record), then the one-step-ahead
//     prediction error A(q) e of a noise model; 0 at missing samples.
#pragma once

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "ctid/apps/residtrace/model.hpp"
#include "ctid/apps/residtrace/physical_fit.hpp"
#include "ctid/apps/residtrace/responses.hpp"
#include "ctid/apps/residtrace/structure_fit.hpp"
#include "ctid/base/model.hpp"
#include "ctid/base/status.hpp"
#include "ctid/base/types.hpp"
#include "ctid/simulation/effect_simulator.hpp"
#include "ctid/simulation/ltv_simulator.hpp"

namespace ctid::residtrace {

template <typename S>
struct ModelSimulation {
  Vector<S> y;   // the output
  Vector<S> x;   // the dynamic part (the output of a physical realisation)
  Matrix<S> uc;  // the inputs applied (u, the first one from the loop)
};

namespace simulate_detail {

template <typename S>
Status channel_signals_at_rest(const std::vector<StructureChannel<S>>& chans,
                               const Matrix<S>& u, Matrix<S>* W) {
  const Eigen::Index N = u.rows();
  return channel_signals(chans, u, Matrix<S>(Matrix<S>::Zero(N, 1)),
                         Vector<S>(Vector<S>::Zero(N)), W);
}

// The LTV simulator (ltv_simulator.hpp) on the inputs W (N-by-m) with the
// parameters theta (1 row, or N rows linear between the samples).
template <typename S>
Status ltv_simulate(const ModelOrders& orders, InterSample rule,
                    const Matrix<S>& W, S ts, const Matrix<S>& theta,
                    Vector<S>* x) {
  LtvSimulationConfig<S> config;
  config.orders = orders;
  config.u_intersample = rule;
  Status status = validate_orders(orders);
  if (!status.ok()) return status;
  LtvSimulator<S> simulator;
  status = simulator.configure(config);
  if (!status.ok()) return status;
  const Eigen::Index N = W.rows();
  RecordView<S> record;
  record.u = W.data();
  record.num_samples = N;
  record.num_inputs = W.cols();
  record.ts = ts;
  std::vector<S> instants(static_cast<std::size_t>(N));
  for (Eigen::Index k = 0; k < N; ++k) instants[k] = k * ts;
  const ParameterTrajectory<S> trajectory = piecewise_linear_trajectory<S>(
      instants.data(), theta.data(), theta.rows(), theta.cols());
  x->resize(N);
  SimulationOutputs<S> out;
  out.x = x->data();
  return simulator.simulate(trajectory, record, nullptr, nullptr, out);
}

// A numerator without its leading zeros (all zeros: [0]).
template <typename S>
Vector<S> trimmed(const Vector<S>& b) {
  Eigen::Index first = 0;
  while (first < b.size() && b(first) == 0) ++first;
  if (first == b.size()) return Vector<S>::Zero(1);
  return b.tail(b.size() - first);
}

template <typename S>
Status lti_simulate(const ResidtraceModel<S>& model, const Matrix<S>& u, S ts,
                    Vector<S>* x) {
  Matrix<S> W;
  Status status = channel_signals_at_rest(model.channels, u, &W);
  if (!status.ok()) return status;
  const Eigen::Index n = model.F.size() - 1;
  const S F0 = model.F(0);
  ModelOrders orders;
  orders.na = static_cast<int>(n);
  std::vector<Vector<S>> b;
  for (const StructureChannel<S>& c : model.channels) {
    b.push_back(trimmed<S>(Vector<S>(c.B / F0)));
    if (b.back().size() > n + 1) {
      return bad_input(
          "the model is improper (numerator degree above the "
          "denominator's)");
    }
    orders.nb.push_back(static_cast<int>(b.back().size()));
    orders.nk.push_back(c.nk);
  }
  Matrix<S> theta(1, orders.num_parameters());
  for (Eigen::Index i = 0; i < n; ++i) theta(0, i) = model.F(i + 1) / F0;
  for (std::size_t j = 0; j < b.size(); ++j) {
    theta.block(0, orders.numerator_offset(static_cast<int>(j)), 1,
                b[j].size()) = b[j].transpose();
  }
  return ltv_simulate<S>(orders, model.rule, W, ts, theta, x);
}

// One input channel with drifting parameters, open loop.
template <typename S>
Status drift_simulate(const ResidtraceModel<S>& model, const Matrix<S>& u, S ts,
                      const Matrix<S>& thm, Vector<S>* x) {
  const StructureChannel<S>& c = model.channels[0];
  const Eigen::Index n = model.F.size() - 1;
  const Eigen::Index N = u.rows();
  if (c.col < 0 || c.col >= u.cols()) {
    return bad_input("the channel reads an input the record does not have");
  }
  std::vector<Eigen::Index> free;
  for (Eigen::Index i = 0; i < n; ++i)
    if (!model.fixed[i]) free.push_back(i);
  const Eigen::Index nf = static_cast<Eigen::Index>(free.size());
  if (thm.rows() != N || thm.cols() != nf + c.nb) {
    return dimension_mismatch(
        "the parameter path needs one row per sample and the free f's and "
        "b's in its columns");
  }
  Matrix<S> T(N, n + c.nb);
  for (Eigen::Index k = 0; k < N; ++k) {
    T.row(k).head(n) = model.F.tail(n).transpose();
    T.row(k).tail(c.nb).setZero();
  }
  for (Eigen::Index i = 0; i < nf; ++i) T.col(free[i]) = thm.col(i);
  T.rightCols(c.nb) = thm.rightCols(c.nb);
  ModelOrders orders = siso_orders(static_cast<int>(n), c.nb, c.nk);
  return ltv_simulate<S>(orders, model.rule, Matrix<S>(u.col(c.col)), ts, T, x);
}

template <typename S>
Status effect_simulate(const ResidtraceModel<S>& model, const Matrix<S>& u,
                       S ts, const ClosedLoop<S>* loop, int substeps,
                       const Matrix<S>* thm, Vector<S>* x, Vector<S>* u1) {
  const Eigen::Index N = u.rows();
  const Eigen::Index n = model.F.size() - 1;
  const std::vector<StructureChannel<S>>& chans = model.channels;
  const Eigen::Index m = static_cast<Eigen::Index>(chans.size());
  const bool closed = loop != nullptr;
  EffectSimulationConfig<S> c;
  std::vector<StructureChannel<S>> exogenous;
  std::vector<Eigen::Index> ex_cols;
  for (Eigen::Index j = 0; j < m; ++j) {
    const StructureChannel<S>& ch = chans[j];
    EffectChannelKind kind = EffectChannelKind::kExogenous;
    S param = 0;
    switch (ch.kind) {
      case ChannelKind::kSignV:
        kind = EffectChannelKind::kSignVelocity;
        break;
      case ChannelKind::kSignOutput:
        kind = EffectChannelKind::kSignOutput;
        break;
      case ChannelKind::kOutputPower:
        kind = EffectChannelKind::kOutputPower;
        param = ch.param;
        break;
      default:
        break;
    }
    // in closed loop the channels of the controlled first input are
    // formed in the loop
    if (closed && kind == EffectChannelKind::kExogenous && ch.col == 0 &&
        ch.kind != ChannelKind::kConstant) {
      switch (ch.kind) {
        case ChannelKind::kInput:
          if (ch.param != 0) {
            return not_supported(
                "a delay of a fraction of a sample on the controlled input");
          }
          kind = EffectChannelKind::kControlledInput;
          break;
        case ChannelKind::kPower:
          kind = EffectChannelKind::kControlledPower;
          param = ch.param;
          break;
        case ChannelKind::kClip:
          kind = EffectChannelKind::kControlledClip;
          param = ch.param;
          break;
        default:
          return not_supported("a 'node' channel of the controlled input");
      }
    }
    if (kind == EffectChannelKind::kExogenous) {
      exogenous.push_back(ch);
      ex_cols.push_back(j);
    }
    c.kinds.push_back(kind);
    c.delays.push_back(ch.nk);
    c.params.push_back(param);
  }
  Matrix<S> W = Matrix<S>::Zero(N, m);
  if (!exogenous.empty()) {
    Matrix<S> We;
    Status status = channel_signals_at_rest(exogenous, u, &We);
    if (!status.ok()) return status;
    for (std::size_t i = 0; i < ex_cols.size(); ++i) {
      W.col(ex_cols[i]) = We.col(static_cast<Eigen::Index>(i));
    }
  }
  // the simulator's states are those of a strictly proper model: a
  // biproper channel would put the input into the output that the sign of
  // the velocity, the powers of the output or a controller read back
  for (const StructureChannel<S>& ch : chans) {
    if (ch.nb > n) {
      return not_supported(
          "a biproper model (direct feedthrough) with an effect fed back "
          "from its output, a closed loop or drifting parameters");
    }
  }
  const S F0 = model.F(0);
  c.f = model.F.tail(n) / F0;
  c.b = Matrix<S>::Zero(n, m);
  for (Eigen::Index j = 0; j < m; ++j) {
    const Vector<S>& B = chans[j].B;
    if (B.size() > n) return bad_input("a numerator longer than F");
    c.b.col(j).tail(B.size()) = B / F0;
  }
  // the output level the powers act on: x plus an output offset
  Vector<S> poly = Vector<S>::Zero(2);
  for (const OutputTerm<S>& t : model.out) {
    if (t.kind == OutputTermKind::kOffset) c.y_off += t.c(0);
    if (t.kind == OutputTermKind::kPolynomial) poly = t.c.head(2);
  }
  c.ts = ts;
  c.substeps = substeps;
  Vector<S> s;
  if (closed) {
    if (loop->r1.size() != N || loop->r2.size() != N) {
      return dimension_mismatch("r1 and r2 need one value per sample");
    }
    c.controller_num = loop->num;
    c.controller_den = loop->den;
    c.poly2 = poly(0);
    c.poly3 = poly(1);
    s = Vector<S>::Zero(N);
    for (const OutputTerm<S>& t : model.out) {
      if (t.kind != OutputTermKind::kSinusoid) continue;
      for (Eigen::Index k = 0; k < N; ++k) {
        const S tk = static_cast<S>(k) * ts;
        s(k) +=
            t.c(0) * std::sin(t.omega * tk) + t.c(1) * std::cos(t.omega * tk);
      }
    }
  }
  if (thm != nullptr) {
    std::vector<Eigen::Index> free;
    for (Eigen::Index i = 0; i < n; ++i)
      if (!model.fixed[i]) free.push_back(i);
    Eigen::Index cols = static_cast<Eigen::Index>(free.size());
    for (const StructureChannel<S>& ch : chans) cols += ch.nb;
    if (thm->rows() != N || thm->cols() != cols) {
      return dimension_mismatch(
          "the parameter path needs one row per sample and the free f's "
          "and b's in its columns");
    }
    c.f_t.resize(N, n);
    for (Eigen::Index k = 0; k < N; ++k) c.f_t.row(k) = model.F.tail(n);
    for (std::size_t i = 0; i < free.size(); ++i) {
      c.f_t.col(free[i]) = thm->col(static_cast<Eigen::Index>(i));
    }
    c.b_t = Matrix<S>::Zero(N, n * m);
    Eigen::Index off = static_cast<Eigen::Index>(free.size());
    for (Eigen::Index j = 0; j < m; ++j) {
      const int nb = chans[j].nb;
      c.b_t.middleCols(j * n + n - nb, nb) = thm->middleCols(off, nb);
      off += nb;
    }
  }
  x->resize(N);
  if (closed) u1->resize(N);
  return simulate_effect_model<S>(
      c, W.data(), N, closed ? loop->r1.data() : nullptr,
      closed ? loop->r2.data() : nullptr, closed ? s.data() : nullptr,
      x->data(), closed ? u1->data() : nullptr);
}

}  // namespace simulate_detail

// The channel signals of a physical realisation on u (N-by-nu): from
// rest, each delayed by its nk samples (zeros before).
template <typename S>
Status delayed_channel_signals(const std::vector<StructureChannel<S>>& chans,
                               const Matrix<S>& u, Matrix<S>* W) {
  const Eigen::Index N = u.rows();
  Status status = simulate_detail::channel_signals_at_rest(chans, u, W);
  if (!status.ok()) return status;
  for (Eigen::Index j = 0; j < W->cols(); ++j) {
    const Eigen::Index k = chans[j].nk;
    if (k <= 0) continue;
    const Vector<S> w = W->col(j);
    W->col(j).setZero();
    if (k < N) W->col(j).tail(N - k) = w.head(N - k);
  }
  return Status::Ok();
}

// The output y and inner state z (the position for an end stop) of the
// physical realisation of model (has_phys) on u, open loop from rest.
template <typename S>
Status simulate_physical_model(const ResidtraceModel<S>& model,
                               const Matrix<S>& u, S ts, Vector<S>* y,
                               Vector<S>* z) {
  if (y == nullptr || z == nullptr) return bad_input("no result");
  if (!model.has_phys) return bad_input("the model has no realisation");
  Matrix<S> W;
  Status status = delayed_channel_signals(model.channels, u, &W);
  if (!status.ok()) return status;
  Matrix<S> Y, Z;
  status = simulate_physical<S>({physical_realisation(model)}, W.data(),
                                u.rows(), W.cols(), ts, &Y, &Z);
  if (!status.ok()) return status;
  *y = Y.col(0);
  *z = Z.col(0);
  return Status::Ok();
}

// The output of the model on u (N-by-nu) from rest: see the head of this
// file. loop: the closed loop (nullptr: open); thm: the path of drifting
// parameters (nullptr: constant).
template <typename S>
Status simulate_model(const ResidtraceModel<S>& model, const Matrix<S>& u, S ts,
                      const ClosedLoop<S>* loop, int substeps,
                      const Matrix<S>* thm, ModelSimulation<S>* sim) {
  using namespace simulate_detail;
  if (sim == nullptr) return bad_input("no result");
  const Eigen::Index N = u.rows();
  const Eigen::Index n = model.F.size() - 1;
  if (n < 1 || model.F(0) == 0) {
    return bad_input("F must have order >= 1 with F(1) != 0");
  }
  if (static_cast<Eigen::Index>(model.fixed.size()) != n) {
    return dimension_mismatch("fixed needs one flag per coefficient of F");
  }
  if (!(ts > 0) || !std::isfinite(ts)) {
    return bad_input("the sampling interval must be finite and > 0");
  }
  if (substeps < 1) return bad_input("substeps must be >= 1");
  if (!model.F.allFinite()) return bad_input("F must be finite");
  for (const StructureChannel<S>& c : model.channels) {
    if (!c.B.allFinite()) return bad_input("the numerators must be finite");
    if (c.nk < 0 || c.nb < 0) return bad_input("nb and nk must be >= 0");
  }
  if (thm != nullptr && !thm->allFinite()) {
    return bad_input("the parameter path must be finite");
  }
  for (const OutputTerm<S>& t : model.out) {
    const Eigen::Index need = t.kind == OutputTermKind::kOffset ? 1 : 2;
    if (t.c.size() < need) {
      return bad_input("an output term without its coefficients");
    }
  }
  sim->uc = u;
  if (model.has_phys) {
    if (loop != nullptr || thm != nullptr) {
      return not_supported("a physical realisation in closed loop or drifting");
    }
    Vector<S> z;
    Status status = simulate_physical_model<S>(model, u, ts, &sim->y, &z);
    if (!status.ok()) return status;
    sim->x = sim->y;
    return Status::Ok();
  }
  bool needs_loop = loop != nullptr;
  for (const StructureChannel<S>& c : model.channels) {
    needs_loop = needs_loop || c.kind == ChannelKind::kSignV ||
                 c.kind == ChannelKind::kSignOutput ||
                 c.kind == ChannelKind::kOutputPower;
  }
  Matrix<S> uu = u;
  if (loop != nullptr) {
    if (uu.cols() < 1 || loop->r1.size() != N) {
      return dimension_mismatch("the closed loop needs r1 of N samples");
    }
    uu.col(0) = loop->r1;  // the controlled input is r1 + C (r2 - y)
  }
  Status status;
  Vector<S> u1;
  const bool one_input = model.channels.size() == 1 &&
                         model.channels[0].kind == ChannelKind::kInput &&
                         model.channels[0].param == 0;
  if (thm != nullptr && !needs_loop && one_input) {
    status = drift_simulate<S>(model, uu, ts, *thm, &sim->x);
  } else if (!needs_loop && thm == nullptr) {
    status = lti_simulate<S>(model, uu, ts, &sim->x);
  } else {
    status =
        effect_simulate<S>(model, uu, ts, loop, substeps, thm, &sim->x, &u1);
  }
  if (!status.ok()) return status;
  sim->uc = uu;
  if (loop != nullptr) sim->uc.col(0) = u1;
  sim->y = sim->x + output_terms<S>(model.out, sim->x, ts);
  return Status::Ok();
}

// A record the model was not fitted on.
template <typename S>
struct ValidationRecord {
  Vector<S> y;      // N
  Matrix<S> u;      // N-by-nu
  Matrix<S> u_pre;  // the inputs before it (a split record); 0 rows: none
  S ts = 1;
  bool closed = false;
  ClosedLoop<S> loop;
  std::vector<bool> missing;  // empty or N flags
  Matrix<S> thm;  // the parameter path over the whole record; empty: none
  // the simulated output with its initial state fitted (a cascade's
  // initial levels, fitted by the caller); empty: simulated here
  Vector<S> yh_given;
};

namespace simulate_detail {

// The least-squares fit X (X \ e) of e on the columns of X.
template <typename S>
Vector<S> projection(const Matrix<S>& X, const Vector<S>& e) {
  if (X.rows() == 0 || X.cols() == 0) return Vector<S>::Zero(X.rows());
  return X * X.colPivHouseholderQr().solve(e);
}

}  // namespace simulate_detail

// The validation error of the model on the record (see the head of this
// file), with `substeps` sub-steps per interval where the simulation takes
// them.
template <typename S>
Status validation_error(const ResidtraceModel<S>& model,
                        const ValidationRecord<S>& V, int substeps,
                        Vector<S>* e, Vector<S>* yh) {
  using simulate_detail::projection;
  if (e == nullptr || yh == nullptr) return bad_input("no result");
  const Eigen::Index N = V.y.size();
  if (V.u.rows() != N) {
    return dimension_mismatch("u needs one row per sample of y");
  }
  ResidtraceModel<S> m = model;
  std::vector<S> omegas;
  m.out.clear();
  for (const OutputTerm<S>& t : model.out) {
    if (t.kind == OutputTermKind::kSinusoid) {
      omegas.push_back(t.omega);
    } else {
      m.out.push_back(t);
    }
  }
  if (V.yh_given.size() > 0) {
    if (V.yh_given.size() != N) {
      return dimension_mismatch("the given simulation needs N samples");
    }
    *yh = V.yh_given;
    *e = V.y - *yh;
  } else {
    // with a prefix the simulation starts at the beginning of the whole
    // record, driven by its input
    const Eigen::Index npre = V.u_pre.rows();
    Matrix<S> uf(npre + N, V.u.cols());
    if (npre > 0) {
      if (V.u_pre.cols() != V.u.cols()) {
        return dimension_mismatch("the prefix needs the record's inputs");
      }
      uf.topRows(npre) = V.u_pre;
    }
    uf.bottomRows(N) = V.u;
    ModelSimulation<S> sim;
    Status status =
        simulate_model<S>(m, uf, V.ts, V.closed ? &V.loop : nullptr, substeps,
                          V.thm.size() > 0 ? &V.thm : nullptr, &sim);
    if (!status.ok()) return status;
    *yh = sim.y.tail(N);
    *e = V.y - *yh;
    if (m.x0 && e->allFinite()) {
      // the free response of the initial state, as MATLAB's compare does
      Matrix<S> X;
      status = free_responses<S>(Vector<S>(m.F.tail(m.F.size() - 1) / m.F(0)),
                                 V.ts, N, X);
      if (!status.ok()) return status;
      const Vector<S> f = projection<S>(X, *e);
      *yh += f;
      *e -= f;
    }
  }
  if (!omegas.empty() && e->allFinite()) {
    const Eigen::Index p = static_cast<Eigen::Index>(omegas.size());
    Matrix<S> X(N, 2 * p);
    for (Eigen::Index k = 0; k < N; ++k) {
      const S t = static_cast<S>(k) * V.ts;
      for (Eigen::Index i = 0; i < p; ++i) {
        X(k, i) = std::sin(t * omegas[i]);
        X(k, p + i) = std::cos(t * omegas[i]);
      }
    }
    const Eigen::Index h = N / 2;
    Vector<S> s(N);
    auto coefficients = [&](Eigen::Index start, Eigen::Index len) {
      if (len == 0) return Vector<S>(Vector<S>::Zero(2 * p));
      return Vector<S>(X.middleRows(start, len)
                           .colPivHouseholderQr()
                           .solve(e->segment(start, len)));
    };
    s.tail(N - h) = X.bottomRows(N - h) * coefficients(0, h);
    s.head(h) = X.topRows(h) * coefficients(h, N - h);
    *yh += s;
    *e -= s;
  }
  if (m.noise.size() > 0) {
    // the one-step-ahead prediction error A(q) e (a direct-form FIR filter,
    // the highest lag summed first)
    const Vector<S>& a = m.noise;
    const Eigen::Index q = a.size() - 1;
    Vector<S> p(N);
    for (Eigen::Index k = 0; k < N; ++k) {
      S acc = 0;
      for (Eigen::Index i = q; i >= 1; --i) {
        if (k - i >= 0) acc = a(i) * (*e)(k - i) + acc;
      }
      p(k) = a(0) * (*e)(k) + acc;
    }
    *yh += *e - p;
    *e = p;
  }
  if (static_cast<Eigen::Index>(V.missing.size()) == N) {
    for (Eigen::Index k = 0; k < N; ++k) {
      if (!V.missing[k]) continue;
      (*e)(k) = 0;  // a missing sample carries no error
      (*yh)(k) = V.y(k);
    }
  }
  return Status::Ok();
}

}  // namespace ctid::residtrace
