// SPDX-License-Identifier: BSD-3-Clause
// Copyright (C) the ctid authors
// MEX gateway of residtrace's computations (core/include/ctid/apps/
// residtrace/) and of the effect-model simulator (core/include/ctid/
// simulation/effect_simulator.hpp):
//
//   [x, u1] = effect_sim_mex (fname, W, options)
//
// W: N-by-m channel signals (the exogenous columns; the others are
// ignored). Fields of options: ts, f (1-by-n, f1..fn of the monic F), b
// (n-by-m, channel j's numerator right-aligned in column j), kind (1-by-m
// codes: 0 exogenous, 1 sign of the velocity, 2 sign of the output, 3 power
// of the output, 4 the controlled input u1, 5 a power of u1, 6 u1 clipped),
// nk (1-by-m delays in samples), param (1-by-m: the power or the clip
// level), y_off, substeps; in closed loop controller_num, controller_den,
// r1, r2 (N-by-1 each), s (N-by-1 sampled output terms, optional) and poly
// ([c2 c3]); for per-sample coefficients f_t (N-by-n) and b_t (N-by-nm).
//
// The other computations of residtrace (core/include/ctid/apps/residtrace/),
// by a method name in second place:
//
//   D = effect_sim_mex (fname, "filter", x, f, options)
//     p^i x / F(p), i = 0..n (N-by-(n+1)), F = p^n + f1 p^(n-1) + .. + fn;
//     options: ts, rule ('zoh' | 'foh');
//   X = effect_sim_mex (fname, "free", N, f, options)
//     the free responses of F(p) h = 0 (N-by-n); options: ts;
//   [thm, V, P] = effect_sim_mex (fname, "track", target, Phi, Z, f,
//                                 theta0, P0, Qn, options)
//     the tracking recursion (track.hpp); options: free (indices of the
//     tracked coefficients of f, 1-based), r (integrators), k0 (first
//     tracked sample, 1-based);
//   v = effect_sim_mex (fname, "dmtest", e0, e1, options)
//     the Diebold-Mariano and encompassing tests (statistics.hpp), v =
//     [score stat p bandwidth z p_corr]; options: none (a struct);
//   [r, Q, xc, S, reason, white_p, indep_p] = effect_sim_mex (fname,
//                                           "whiteness", e, u, options)
//     the Ljung-Box and Haugh statistics (statistics.hpp): autocorrelations
//     r (lags 0..m), Q, the prewhitened cross-correlations xc (lags -m..m,
//     one column per input), S; reason is empty, or says why e is not
//     tested (the others are then empty, the p-values NaN); white_p =
//     P(chi^2(m) > Q), indep_p = P(chi^2(nu (2m + 1)) > S) (judgement.hpp,
//     chi2_upper); options: maxlag, yscale;
//   a = effect_sim_mex (fname, "ar", x, options)
//     A(q) = [1 -c1 .. -cp] of the AR model of x whose order p <= pmax has
//     the smallest BIC (statistics.hpp); options: pmax;
//   [y, z] = effect_sim_mex (fname, "physsim", W, options)
//     the output and inner state (the position for "stop") of a physical
//     realisation (physical_fit.hpp) on the channel signals W (N-by-m,
//     delayed);
//   [fit, e] = effect_sim_mex (fname, "physfit", W, y, options)
//     its fit by the simulation error (physical_fit.hpp): fit holds the
//     fitted fields below and theta, cov, s2, bic, sse, iterations, ok; e
//     the errors on the whole record.
//   W = effect_sim_mex (fname, "channels", u, v, y, options)
//     the channel signals of a residtrace structure (structure_fit.hpp,
//     channel_signals), one column per channel; v (velocity) and y (the
//     output of the output powers) N rows each or [] when unused; options:
//     kind, col, param, nb, nk, node (see read_channels);
//   fit = effect_sim_mex (fname, "fit", u, y, options)
//     the structure fit (structure_fit.hpp, fit_structure); options: the
//     channels as for "channels" with B (a cell of start numerators), ts,
//     rule ('zoh' | 'foh'), F, fixed, levels, out_kind (0 offset, 1
//     polynomial, 2 sinusoid, 3 saturation), out_c (a cell), out_omega,
//     vhat, ysm, initial_state, missing, starts (a cell of F's, [] the
//     engine's automatic start), maxiter; fit: ok, failed_round, F, B, out_c,
//     out_cstd, out_fitted, theta, cov, s2, np, bic, e.
//   [y, x, uc] = effect_sim_mex (fname, "simulate", model, u, options)
//     the simulation of a residtrace model (the struct of
//     residtrace_model_io.hpp; simulate.hpp, simulate_model) from rest on
//     the inputs u (N-by-nu): output y, dynamic part x, inputs applied uc;
//     options: ts, substeps, loop ([] or num, den, r1, r2: the closed
//     loop), thm ([] or N rows: the path of drifting parameters);
//   [e, yh] = effect_sim_mex (fname, "valerror", model, V, options)
//     its error on the record V (simulate.hpp, validation_error): fields
//     y, u, Ts, loop, pre ([] or the part before it, with u), missing;
//     options: substeps, thm ([] or the path over the whole record), yh
//     ([] or the simulation with its initial state fitted by the caller);
//   model = effect_sim_mex (fname, "fitmodel", tmpl, D, options)
//     the fit of a residtrace model (model_fit.hpp, fit_model): tmpl with
//     the estimate; D: y, u, Ts, intersample, vhat, ysm, initial_state,
//     missing, loop; options: starts (a cell of F's), maxiter, keep_order,
//     substeps (residtrace_candidate_io.hpp, read_context).
//   v = effect_sim_mex (fname, "velocity", y, options)
//     the velocity of the measured output y (N-by-1) without phase lag
//     (responses.hpp, zero_lag_velocity); options: ts, lambda,
//     output_itself (0 or 1: y smoothed, not differentiated);
//   Fp = effect_sim_mex (fname, "prefilter", F, options)
//     the denominator of residtrace's prefilter and auxiliary model
//     (prefilter.hpp, prefilter_denominator; F a row of descending
//     powers); options: wlo, the band's lower edge;
//   [z0, h0] = effect_sim_mex (fname, "cascadelevels", phys, options)
//     the initial levels of a cascade realisation (physical_fit.hpp,
//     cascade_levels; phys: a model.phys struct, residtrace_model_io.hpp);
//     options: none (a struct);
//   p = effect_sim_mex (fname, "physical", model, options)
//     the physical reading of a residtrace model (physical_reading.hpp): a
//     struct array with fields name, value and std; options: ts.
//   The judgement of candidates: the methods "accept", "score", "judge"
//   and "noise_gate" (residtrace_judge_io.hpp).
//   The candidates: the methods "candidate", "select", "physcascade",
//   "physmodelfit" and "driftsegments" (residtrace_candidate_io.hpp).
//   The realisation's fields: kind ("stop" or "cascade"), ts, substeps,
//   yscale; "stop": F (1-by-(n+1)), fixed (1-by-n, 0 or 1), B (n-by-m,
//   channel j's numerator right-aligned in column j), nb (1-by-m numerator
//   lengths), offset (the output offset as a parameter; absent: none),
//   offset_fixed, lo, hi (the output's levels; absent: none); "cascade":
//   g ("sqrt" or "lin"), b (1-by-m gains), d, alpha, gamma, c, wbar
//   (1-by-m), hi (the inner level), yhi, spill, h0, z0 (each absent: none);
//   for the fit also initial_state (0 or 1) and maxiter.
// The signals and estimates may hold non-finite values (they propagate as
// in the recursion itself).
#include "ctid/apps/residtrace/candidate.hpp"
#include "ctid/apps/residtrace/judgement.hpp"
#include "ctid/apps/residtrace/model.hpp"
#include "ctid/apps/residtrace/model_fit.hpp"
#include "ctid/apps/residtrace/physical_fit.hpp"
#include "ctid/apps/residtrace/physical_reading.hpp"
#include "ctid/apps/residtrace/prefilter.hpp"
#include "ctid/apps/residtrace/responses.hpp"
#include "ctid/apps/residtrace/simulate.hpp"
#include "ctid/apps/residtrace/statistics.hpp"
#include "ctid/apps/residtrace/structure_fit.hpp"
#include "ctid/apps/residtrace/track.hpp"
#include "ctid/simulation/effect_simulator.hpp"
#include "gateway_common.hpp"
#include "residtrace_candidate_io.hpp"
#include "residtrace_judge_io.hpp"
#include "residtrace_model_io.hpp"

namespace {

using ctid::mex::Gateway;

// A real double matrix of any values (non-finite ones too).
Eigen::Map<const Eigen::MatrixXd> any_matrix(const Gateway& g, const mxArray* a,
                                             const char* what, long rows = -1,
                                             long cols = -1) {
  const double* p = g.matrix(a, what, rows, cols, false);
  return Eigen::Map<const Eigen::MatrixXd>(
      p, static_cast<Eigen::Index>(mxGetM(a)),
      static_cast<Eigen::Index>(mxGetN(a)));
}

Eigen::VectorXd row(const Eigen::MatrixXd& a) { return a.row(0).transpose(); }

// f as a column: a row or column vector.
Eigen::VectorXd read_f(const Gateway& g, const mxArray* a) {
  g.require_real_double(a, "f");
  if (mxGetM(a) > 1 && mxGetN(a) > 1) g.fail("badInput", "f must be a vector");
  const auto f = any_matrix(g, a, "f");
  return Eigen::Map<const Eigen::VectorXd>(f.data(), f.size());
}

void filter_method(const Gateway& g, int nlhs, mxArray* plhs[], int nrhs,
                   const mxArray* prhs[]) {
  if (nrhs != 5) {
    g.fail("badInput", "filter takes (fname, 'filter', x, f, options)");
  }
  if (nlhs > 1) g.fail("badInput", "filter has one output");
  g.require_real_double(prhs[2], "x");
  // a column: N-by-1, or empty (no samples, whatever its shape)
  if (mxGetN(prhs[2]) != 1 && !mxIsEmpty(prhs[2])) {
    g.fail("badInput", "x must be a column vector");
  }
  const long n = static_cast<long>(mxGetNumberOfElements(prhs[2]));
  const Eigen::VectorXd x =
      n > 0 ? Eigen::VectorXd(
                  Eigen::Map<const Eigen::VectorXd>(mxGetPr(prhs[2]), n))
            : Eigen::VectorXd();
  const Eigen::VectorXd f = read_f(g, prhs[3]);
  ctid::mex::OptionsReader opt(g, prhs[4]);
  const double ts = opt.scalar("ts");
  const ctid::InterSample rule = opt.choice<ctid::InterSample>(
      "rule",
      {{"zoh", ctid::InterSample::kZoh}, {"foh", ctid::InterSample::kFoh}},
      ctid::InterSample::kZoh);
  if (!opt.has("rule")) g.fail("badOption", "option 'rule' is missing");
  opt.finish();
  Eigen::MatrixXd out;
  g.check(ctid::residtrace::filtered_derivatives<double>(f, ts, rule, x.data(),
                                                         n, out));
  plhs[0] = ctid::mex::make_output_matrix(out.rows(), out.cols());
  Eigen::Map<Eigen::MatrixXd>(mxGetPr(plhs[0]), out.rows(), out.cols()) = out;
}

void free_method(const Gateway& g, int nlhs, mxArray* plhs[], int nrhs,
                 const mxArray* prhs[]) {
  if (nrhs != 5) {
    g.fail("badInput", "free takes (fname, 'free', N, f, options)");
  }
  if (nlhs > 1) g.fail("badInput", "free has one output");
  const int n = g.integer(prhs[2], "N");
  const Eigen::VectorXd f = read_f(g, prhs[3]);
  ctid::mex::OptionsReader opt(g, prhs[4]);
  const double ts = opt.scalar("ts");
  opt.finish();
  Eigen::MatrixXd out;
  g.check(ctid::residtrace::free_responses<double>(f, ts, n, out));
  plhs[0] = ctid::mex::make_output_matrix(out.rows(), out.cols());
  Eigen::Map<Eigen::MatrixXd>(mxGetPr(plhs[0]), out.rows(), out.cols()) = out;
}

void track_method(const Gateway& g, int nlhs, mxArray* plhs[], int nrhs,
                  const mxArray* prhs[]) {
  if (nrhs != 10) {
    g.fail("badInput",
           "track takes (fname, 'track', target, Phi, Z, f, theta0, P0, Qn, "
           "options)");
  }
  if (nlhs > 3) g.fail("badInput", "track has at most 3 outputs");
  const auto target = any_matrix(g, prhs[2], "target", -1, 1);
  const auto Phi = any_matrix(g, prhs[3], "Phi");
  const auto Z = any_matrix(g, prhs[4], "Z");
  ctid::residtrace::TrackConfig<double> c;
  c.f = read_f(g, prhs[5]);
  const auto theta0 = any_matrix(g, prhs[6], "theta0");
  c.theta0 = Eigen::Map<const Eigen::VectorXd>(theta0.data(), theta0.size());
  c.P0 = any_matrix(g, prhs[7], "P0");
  c.Qn = any_matrix(g, prhs[8], "Qn");
  ctid::mex::OptionsReader opt(g, prhs[9]);
  for (const int i : opt.integer_vector("free")) c.free.push_back(i - 1);
  c.integrators = opt.integer("r");
  c.first = opt.integer("k0") - 1;
  opt.finish();
  ctid::residtrace::TrackResult<double> result;
  g.check(ctid::residtrace::track<double>(c, target, Phi, Z, &result));
  plhs[0] =
      ctid::mex::make_output_matrix(result.theta.rows(), result.theta.cols());
  Eigen::Map<Eigen::MatrixXd>(mxGetPr(plhs[0]), result.theta.rows(),
                              result.theta.cols()) = result.theta;
  if (nlhs >= 2) plhs[1] = mxCreateDoubleScalar(result.V);
  if (nlhs >= 3) {
    plhs[2] = ctid::mex::make_output_matrix(result.P.rows(), result.P.cols());
    Eigen::Map<Eigen::MatrixXd>(mxGetPr(plhs[2]), result.P.rows(),
                                result.P.cols()) = result.P;
  }
}

void effect_sim_gateway(const Gateway& g, int nlhs, mxArray* plhs[], int nrhs,
                        const mxArray* prhs[]) {
  if (nrhs != 3) {
    g.fail("badInput",
           "the gateway takes 3 arguments (fname, W, options), "
           "got " +
               std::to_string(nrhs));
  }
  if (nlhs > 2) g.fail("badInput", "at most 2 outputs (x, u1)");
  g.require_real_double(prhs[1], "W");
  const long n = static_cast<long>(mxGetM(prhs[1]));
  const long m = static_cast<long>(mxGetN(prhs[1]));
  if (n < 1) g.fail("badInput", "W must not be empty");
  const double* W = g.matrix(prhs[1], "W", n, m);
  ctid::mex::OptionsReader opt(g, prhs[2]);
  ctid::EffectSimulationConfig<double> c;
  c.ts = opt.scalar("ts");
  if (!(c.ts > 0)) g.fail("badOption", "option 'ts' must be > 0");
  const Eigen::MatrixXd f = opt.required_matrix("f", 1, -1);
  const long order = static_cast<long>(f.cols());
  if (order < 1) g.fail("badOption", "option 'f' must not be empty");
  c.f = f.row(0).transpose();
  c.b = opt.required_matrix("b", order, m);
  const std::vector<int> kind = opt.integer_vector("kind");
  const std::vector<int> nk = opt.integer_vector("nk");
  const Eigen::MatrixXd param = opt.required_matrix("param", 1, m);
  if (static_cast<long>(kind.size()) != m ||
      static_cast<long>(nk.size()) != m) {
    g.fail("dimensionMismatch",
           "options 'kind' and 'nk' need one entry per column of W");
  }
  for (long j = 0; j < m; ++j) {
    if (kind[j] < 0 || kind[j] > 6) {
      g.fail("badOption", "option 'kind' must hold codes 0..6");
    }
    c.kinds.push_back(static_cast<ctid::EffectChannelKind>(kind[j]));
    c.delays.push_back(nk[j]);
    c.params.push_back(param(0, j));
  }
  c.y_off = opt.scalar("y_off", 0.0);
  c.substeps = opt.integer("substeps", 1);
  const Eigen::MatrixXd cnum = opt.matrix("controller_num", 1, -1);
  const Eigen::MatrixXd cden = opt.matrix("controller_den", 1, -1);
  if ((cnum.size() == 0) != (cden.size() == 0)) {
    g.fail("badOption",
           "options 'controller_num' and 'controller_den' go "
           "together");
  }
  if (cden.size() > 0) {
    c.controller_num = cnum.row(0).transpose();
    c.controller_den = cden.row(0).transpose();
  }
  const double* r1 = opt.signal("r1", n);
  const double* r2 = opt.signal("r2", n);
  const double* s = opt.signal("s", n);
  const Eigen::MatrixXd poly = opt.matrix("poly", 1, 2);
  if (poly.size() == 2) {
    c.poly2 = poly(0, 0);
    c.poly3 = poly(0, 1);
  }
  c.f_t = opt.matrix("f_t", n, order);
  c.b_t = opt.matrix("b_t", n, order * m);
  if ((c.f_t.size() == 0) != (c.b_t.size() == 0)) {
    g.fail("badOption", "options 'f_t' and 'b_t' go together");
  }
  opt.finish();
  plhs[0] = ctid::mex::make_output_matrix(n, 1);
  double* u1 = nullptr;
  if (nlhs >= 2) {
    plhs[1] = ctid::mex::make_output_matrix(n, 1);
    u1 = mxGetPr(plhs[1]);
  }
  g.check(ctid::simulate_effect_model<double>(c, W, n, r1, r2, s,
                                              mxGetPr(plhs[0]), u1));
}

// A column of any values.
Eigen::VectorXd any_column(const Gateway& g, const mxArray* a,
                           const char* what) {
  const auto m = any_matrix(g, a, what, -1, 1);
  return m.col(0);
}

void dmtest_method(const Gateway& g, int nlhs, mxArray* plhs[], int nrhs,
                   const mxArray* prhs[]) {
  if (nrhs != 5) {
    g.fail("badInput", "dmtest takes (fname, 'dmtest', e0, e1, options)");
  }
  if (nlhs > 1) g.fail("badInput", "dmtest has one output");
  const Eigen::VectorXd e0 = any_column(g, prhs[2], "e0");
  const Eigen::VectorXd e1 = any_column(g, prhs[3], "e1");
  ctid::mex::OptionsReader opt(g, prhs[4]);
  opt.finish();
  ctid::residtrace::DmTest<double> t;
  g.check(ctid::residtrace::dm_test<double>(e0, e1, &t));
  plhs[0] = ctid::mex::make_output_matrix(1, 6);
  double* v = mxGetPr(plhs[0]);
  v[0] = t.score;
  v[1] = t.stat;
  v[2] = t.p;
  v[3] = static_cast<double>(t.bandwidth);
  v[4] = t.z;
  v[5] = t.p_corr;
}

void whiteness_method(const Gateway& g, int nlhs, mxArray* plhs[], int nrhs,
                      const mxArray* prhs[]) {
  if (nrhs != 5) {
    g.fail("badInput", "whiteness takes (fname, 'whiteness', e, u, options)");
  }
  if (nlhs > 7) g.fail("badInput", "whiteness has at most 7 outputs");
  const Eigen::VectorXd e = any_column(g, prhs[2], "e");
  const long n = static_cast<long>(e.size());
  g.require_real_double(prhs[3], "u");
  Eigen::MatrixXd u(n, 0);
  if (mxGetNumberOfElements(prhs[3]) > 0) u = any_matrix(g, prhs[3], "u", n);
  ctid::mex::OptionsReader opt(g, prhs[4]);
  const int maxlag = opt.integer("maxlag");
  const double yscale = opt.scalar("yscale", 0.0);
  opt.finish();
  ctid::residtrace::WhitenessStatistics<double> w;
  g.check(
      ctid::residtrace::whiteness_statistics<double>(e, u, maxlag, yscale, &w));
  auto put = [](const Eigen::MatrixXd& m) {
    mxArray* a = ctid::mex::make_output_matrix(m.rows(), m.cols());
    Eigen::Map<Eigen::MatrixXd>(mxGetPr(a), m.rows(), m.cols()) = m;
    return a;
  };
  plhs[0] = put(w.autocorr);
  if (nlhs >= 2)
    plhs[1] = put(Eigen::MatrixXd::Constant(w.testable, w.testable, w.Q));
  if (nlhs >= 3) plhs[2] = put(w.xcorr);
  if (nlhs >= 4) {
    plhs[3] = put(Eigen::MatrixXd::Constant(w.testable, w.testable, w.S_indep));
  }
  if (nlhs >= 5) plhs[4] = mxCreateString(w.reason.c_str());
  // the tail probabilities: Q against chi^2(m), S against chi^2(nu (2m + 1))
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double nu = static_cast<double>(u.cols());
  if (nlhs >= 6) {
    plhs[5] = mxCreateDoubleScalar(
        w.testable ? ctid::residtrace::chi2_upper<double>(w.Q, maxlag) : nan);
  }
  if (nlhs >= 7) {
    plhs[6] =
        mxCreateDoubleScalar(w.testable ? ctid::residtrace::chi2_upper<double>(
                                              w.S_indep, nu * (2 * maxlag + 1))
                                        : nan);
  }
}

void ar_method(const Gateway& g, int nlhs, mxArray* plhs[], int nrhs,
               const mxArray* prhs[]) {
  if (nrhs != 4) g.fail("badInput", "ar takes (fname, 'ar', x, options)");
  if (nlhs > 1) g.fail("badInput", "ar has one output");
  const Eigen::VectorXd x = any_column(g, prhs[2], "x");
  ctid::mex::OptionsReader opt(g, prhs[3]);
  const int pmax = opt.integer("pmax");
  opt.finish();
  if (pmax < 0) g.fail("badOption", "option 'pmax' must be >= 0");
  if (x.size() < 1) g.fail("badInput", "x must not be empty");
  const Eigen::VectorXd a = ctid::residtrace::ar_whitener<double>(x, pmax);
  plhs[0] = ctid::mex::make_output_matrix(1, a.size());
  Eigen::Map<Eigen::VectorXd>(mxGetPr(plhs[0]), a.size()) = a;
}

// The realisation's fields (see the head of this file).
ctid::residtrace::PhysicalModel<double> read_physical(
    const Gateway& g, ctid::mex::OptionsReader& opt, long m) {
  using ctid::residtrace::PhysicalKind;
  ctid::residtrace::PhysicalModel<double> p;
  p.kind = opt.choice<PhysicalKind>(
      "kind",
      {{"stop", PhysicalKind::kStop}, {"cascade", PhysicalKind::kCascade}},
      PhysicalKind::kStop);
  if (!opt.has("kind")) g.fail("badOption", "option 'kind' is missing");
  p.substeps = opt.integer("substeps", 1);
  if (p.substeps < 1) g.fail("badOption", "option 'substeps' must be >= 1");
  p.yscale = opt.scalar("yscale", 1.0);
  auto optional = [&](const char* name, bool* has, double* v) {
    const Eigen::MatrixXd a = opt.matrix(name, 1, 1);
    if (has != nullptr) *has = a.size() == 1;
    if (a.size() == 1) *v = a(0, 0);
  };
  if (p.kind == PhysicalKind::kStop) {
    p.F = row(opt.required_matrix("F", 1, -1));
    const long n = static_cast<long>(p.F.size()) - 1;
    if (n < 2 || p.F(0) == 0) {
      g.fail("badOption", "option 'F' must be of order >= 2 with F(1) != 0");
    }
    const Eigen::MatrixXd fixed = opt.required_matrix("fixed", 1, n);
    for (long i = 0; i < n; ++i) p.fixed.push_back(fixed(0, i) != 0);
    const Eigen::MatrixXd B = opt.required_matrix("B", n, m);
    const std::vector<int> nb = opt.integer_vector("nb");
    if (static_cast<long>(nb.size()) != m) {
      g.fail("dimensionMismatch", "option 'nb' needs one entry per channel");
    }
    for (long j = 0; j < m; ++j) {
      if (nb[j] < 0 || nb[j] > n)
        g.fail("badOption", "option 'nb' out of range");
      p.B.push_back(B.col(j).tail(nb[j]));
    }
    optional("offset", &p.has_offset, &p.offset);
    p.offset_fixed = opt.scalar("offset_fixed", 0.0);
    optional("lo", nullptr, &p.lo);
    optional("hi", nullptr, &p.hi);
    return p;
  }
  p.sqrt_nodes = opt.choice<bool>("g", {{"sqrt", true}, {"lin", false}}, true);
  p.b = row(opt.required_matrix("b", 1, m));
  p.d = opt.scalar("d");
  p.alpha = opt.scalar("alpha");
  p.gamma = opt.scalar("gamma");
  p.c = opt.scalar("c");
  const Eigen::MatrixXd wbar = opt.matrix("wbar", 1, m);
  p.wbar = wbar.size() > 0 ? row(wbar) : Eigen::VectorXd::Zero(m);
  optional("hi", nullptr, &p.hi);
  optional("yhi", &p.has_yhi, &p.yhi);
  optional("spill", &p.has_spill, &p.spill);
  optional("h0", &p.has_h0, &p.h0);
  optional("z0", &p.has_z0, &p.z0);
  if (p.has_spill && !(p.spill >= 0 && p.spill <= 1)) {
    g.fail("badOption", "option 'spill' must lie in [0, 1]");
  }
  return p;
}

mxArray* put_matrix(const Eigen::MatrixXd& a) {
  mxArray* out = ctid::mex::make_output_matrix(a.rows(), a.cols());
  Eigen::Map<Eigen::MatrixXd>(mxGetPr(out), a.rows(), a.cols()) = a;
  return out;
}

void physsim_method(const Gateway& g, int nlhs, mxArray* plhs[], int nrhs,
                    const mxArray* prhs[]) {
  if (nrhs != 4)
    g.fail("badInput", "physsim takes (fname, 'physsim', W, options)");
  if (nlhs > 2) g.fail("badInput", "physsim has at most 2 outputs");
  g.require_real_double(prhs[2], "W");
  const long n = static_cast<long>(mxGetM(prhs[2]));
  const long m = static_cast<long>(mxGetN(prhs[2]));
  const double* W = g.matrix(prhs[2], "W", n, m);
  ctid::mex::OptionsReader opt(g, prhs[3]);
  const double ts = opt.scalar("ts");
  if (!(ts > 0)) g.fail("badOption", "option 'ts' must be > 0");
  const auto p = read_physical(g, opt, m);
  opt.finish();
  Eigen::MatrixXd y, z;
  g.check(
      ctid::residtrace::simulate_physical<double>({p}, W, n, m, ts, &y, &z));
  plhs[0] = put_matrix(y);
  if (nlhs >= 2) plhs[1] = put_matrix(z);
}

void physfit_method(const Gateway& g, int nlhs, mxArray* plhs[], int nrhs,
                    const mxArray* prhs[]) {
  if (nrhs != 5) {
    g.fail("badInput", "physfit takes (fname, 'physfit', W, y, options)");
  }
  if (nlhs > 2) g.fail("badInput", "physfit has at most 2 outputs");
  const Eigen::VectorXd y = any_column(g, prhs[3], "y");
  const long n = static_cast<long>(y.size());
  g.require_real_double(prhs[2], "W");
  const long m = static_cast<long>(mxGetN(prhs[2]));
  const double* W = g.matrix(prhs[2], "W", n, m);
  ctid::mex::OptionsReader opt(g, prhs[4]);
  const double ts = opt.scalar("ts");
  if (!(ts > 0)) g.fail("badOption", "option 'ts' must be > 0");
  const auto p = read_physical(g, opt, m);
  const bool x0 = opt.flag("initial_state", false);
  const int maxiter = opt.integer("maxiter");
  opt.finish();
  ctid::residtrace::PhysicalFit<double> fit;
  g.check(ctid::residtrace::fit_physical<double>(p, W, m, y, ts, x0, maxiter,
                                                 &fit));
  const auto& q = fit.model;
  const bool stop = q.kind == ctid::residtrace::PhysicalKind::kStop;
  std::vector<std::pair<const char*, mxArray*>> f;
  auto scalar = [](double v) { return mxCreateDoubleScalar(v); };
  auto maybe = [&](bool has, double v) {
    return has ? scalar(v) : ctid::mex::make_output_matrix(0, 0);
  };
  f.push_back({"ok", scalar(fit.ok ? 1 : 0)});
  f.push_back({"theta", put_matrix(fit.theta)});
  f.push_back({"cov", put_matrix(fit.cov)});
  f.push_back({"s2", scalar(fit.s2)});
  f.push_back({"bic", scalar(fit.bic)});
  f.push_back({"sse", scalar(fit.sse)});
  f.push_back({"iterations", scalar(fit.iterations)});
  f.push_back({"F", put_matrix(q.F.transpose())});
  if (stop) {
    const long nn = static_cast<long>(q.F.size()) - 1;
    Eigen::MatrixXd B = Eigen::MatrixXd::Zero(nn, m);
    for (long j = 0; j < m; ++j) B.col(j).tail(q.B[j].size()) = q.B[j];
    f.push_back({"B", put_matrix(B)});
    f.push_back({"offset", maybe(q.has_offset, q.offset)});
    f.push_back({"lo", scalar(q.lo)});
    f.push_back({"hi", scalar(q.hi)});
  } else {
    f.push_back({"b", put_matrix(q.b.transpose())});
    f.push_back({"d", scalar(q.d)});
    f.push_back({"alpha", scalar(q.alpha)});
    f.push_back({"gamma", scalar(q.gamma)});
    f.push_back({"c", scalar(q.c)});
    f.push_back({"hi", scalar(q.hi)});
    f.push_back({"yhi", maybe(q.has_yhi, q.yhi)});
    f.push_back({"spill", maybe(q.has_spill, q.spill)});
    f.push_back({"h0", maybe(q.has_h0, q.h0)});
    f.push_back({"z0", maybe(q.has_z0, q.z0)});
  }
  std::vector<const char*> names;
  for (const auto& kv : f) names.push_back(kv.first);
  plhs[0] =
      mxCreateStructMatrix(1, 1, static_cast<int>(names.size()), names.data());
  for (std::size_t i = 0; i < f.size(); ++i) {
    mxSetFieldByNumber(plhs[0], 0, static_cast<int>(i), f[i].second);
  }
  if (nlhs >= 2) plhs[1] = put_matrix(fit.e);
}

// The channels of a structure (structure_fit.hpp) from the options kind
// (1-by-m codes: 0 input, 1 constant, 2 sign of the velocity, 3 sign of
// the output, 4 power, 5 clip, 6 power of the output, 7 node), col
// (1-based, 0: none), param, nb, nk, B (a cell of m numerators; absent:
// zeros) and node (a cell: [] or a struct with fa, ts, rule, lo, hi).
std::vector<ctid::residtrace::StructureChannel<double>> read_channels(
    const Gateway& g, ctid::mex::OptionsReader& opt, long nu) {
  using ctid::residtrace::ChannelKind;
  const std::vector<int> kind = opt.integer_vector("kind");
  const std::size_t m = kind.size();
  const std::vector<int> col =
      opt.integer_vector("col", std::vector<int>(m, 0));
  Eigen::MatrixXd param = opt.matrix("param");
  if (param.size() == 0) param = Eigen::MatrixXd::Zero(1, m);
  const std::vector<int> nb = opt.integer_vector("nb", std::vector<int>(m, 1));
  const std::vector<int> nk = opt.integer_vector("nk", std::vector<int>(m, 0));
  const mxArray* B = opt.field("B");
  const mxArray* node = opt.field("node");
  if (col.size() != m || static_cast<std::size_t>(param.size()) != m ||
      nb.size() != m || nk.size() != m) {
    g.fail("dimensionMismatch",
           "col, param, nb and nk need one entry per channel");
  }
  auto cell = [&](const mxArray* c, const char* what) {
    if (c != nullptr && !mxIsEmpty(c) &&
        (!mxIsCell(c) || mxGetNumberOfElements(c) != m)) {
      g.fail("dimensionMismatch",
             std::string(what) + " must be a cell with one entry per channel");
    }
    return c != nullptr && !mxIsEmpty(c);
  };
  const bool has_b = cell(B, "B");
  const bool has_node = cell(node, "node");
  std::vector<ctid::residtrace::StructureChannel<double>> out(m);
  for (std::size_t j = 0; j < m; ++j) {
    auto& c = out[j];
    if (kind[j] < 0 || kind[j] > 7) g.fail("badOption", "unknown channel kind");
    c.kind = static_cast<ChannelKind>(kind[j]);
    c.col = col[j] - 1;
    if (col[j] > nu) g.fail("badInput", "a channel reads a missing input");
    c.param = param(j);
    c.nb = nb[j];
    c.nk = nk[j];
    c.B = Eigen::VectorXd::Zero(std::max(nb[j], 0));
    if (has_b) {
      const mxArray* b = mxGetCell(B, j);
      const auto v = g.eigen_matrix(b, "B");
      if (v.size() != nb[j]) {
        g.fail("dimensionMismatch", "each B needs nb coefficients");
      }
      c.B = Eigen::Map<const Eigen::VectorXd>(v.data(), v.size());
    }
    if (c.kind == ChannelKind::kNode) {
      if (!has_node || mxIsEmpty(mxGetCell(node, j))) {
        g.fail("badOption", "a node channel needs its node struct");
      }
      ctid::mex::OptionsReader p(g, mxGetCell(node, j), "node.");
      c.node_f = p.required_matrix("fa").reshaped();
      c.node_ts = p.scalar("ts");
      c.node_rule = p.choice<ctid::InterSample>(
          "rule",
          {{"zoh", ctid::InterSample::kZoh}, {"foh", ctid::InterSample::kFoh}},
          ctid::InterSample::kZoh);
      c.node_lo = *g.matrix(p.required("lo"), "node.lo", 1, 1, false);
      c.node_hi = *g.matrix(p.required("hi"), "node.hi", 1, 1, false);
      p.finish();
    }
  }
  return out;
}

// An optional N-row signal of any values ([]: none).
Eigen::MatrixXd optional_signal(const Gateway& g, const mxArray* a,
                                const char* what, long n) {
  if (a == nullptr || mxIsEmpty(a)) return Eigen::MatrixXd();
  return any_matrix(g, a, what, n, -1);
}

void channels_method(const Gateway& g, int nlhs, mxArray* plhs[], int nrhs,
                     const mxArray* prhs[]) {
  if (nrhs != 6) {
    g.fail("badInput", "channels takes (fname, 'channels', u, v, y, options)");
  }
  if (nlhs > 1) g.fail("badInput", "channels has one output");
  const Eigen::MatrixXd u = any_matrix(g, prhs[2], "u");
  const long n = static_cast<long>(u.rows());
  const Eigen::MatrixXd v = optional_signal(g, prhs[3], "v", n);
  const Eigen::MatrixXd y = optional_signal(g, prhs[4], "y", n);
  ctid::mex::OptionsReader opt(g, prhs[5]);
  const auto channels = read_channels(g, opt, u.cols());
  opt.finish();
  Eigen::MatrixXd W;
  g.check(ctid::residtrace::channel_signals<double>(
      channels, u, v, y.size() ? Eigen::VectorXd(y.col(0)) : Eigen::VectorXd(),
      &W));
  plhs[0] = put_matrix(W);
}

mxArray* put_cell(const std::vector<Eigen::VectorXd>& v) {
  mxArray* c = mxCreateCellMatrix(1, v.size());
  for (std::size_t i = 0; i < v.size(); ++i) {
    mxSetCell(c, i, put_matrix(v[i].transpose()));
  }
  return c;
}

void fit_method(const Gateway& g, int nlhs, mxArray* plhs[], int nrhs,
                const mxArray* prhs[]) {
  using ctid::residtrace::OutputTermKind;
  if (nrhs != 5) {
    g.fail("badInput", "fit takes (fname, 'fit', u, y, options)");
  }
  if (nlhs > 1) g.fail("badInput", "fit has one output");
  ctid::residtrace::StructureRecord<double> rec;
  rec.y = any_column(g, prhs[3], "y");
  const long n = static_cast<long>(rec.y.size());
  rec.u = any_matrix(g, prhs[2], "u", n, -1);
  ctid::mex::OptionsReader opt(g, prhs[4]);
  rec.ts = opt.scalar("ts");
  if (!(rec.ts > 0)) g.fail("badOption", "option 'ts' must be > 0");
  rec.rule = opt.choice<ctid::InterSample>(
      "rule",
      {{"zoh", ctid::InterSample::kZoh}, {"foh", ctid::InterSample::kFoh}},
      ctid::InterSample::kZoh);
  rec.vhat = optional_signal(g, opt.field("vhat"), "vhat", n);
  const Eigen::MatrixXd ysm = optional_signal(g, opt.field("ysm"), "ysm", n);
  if (ysm.size()) rec.ysm = ysm.col(0);
  rec.initial_state = opt.flag("initial_state", false);
  const Eigen::MatrixXd miss = opt.matrix("missing");
  if (miss.size() == n) {
    for (long k = 0; k < n; ++k) rec.missing.push_back(miss(k) != 0);
  }
  ctid::residtrace::StructureModel<double> model;
  model.F = opt.required_matrix("F", 1, -1).row(0).transpose();
  const long order = static_cast<long>(model.F.size()) - 1;
  const Eigen::MatrixXd fixed = opt.matrix("fixed");
  if (fixed.size() != order) {
    g.fail("dimensionMismatch", "fixed needs one flag per coefficient of F");
  }
  for (long i = 0; i < order; ++i) model.fixed.push_back(fixed(i) != 0);
  model.levels = opt.flag("levels", false);
  model.channels = read_channels(g, opt, rec.u.cols());
  const std::vector<int> out_kind =
      opt.integer_vector("out_kind", std::vector<int>());
  const std::size_t K = out_kind.size();
  const mxArray* out_c = opt.field("out_c");
  const Eigen::MatrixXd omega = opt.matrix("out_omega");
  if (K > 0 && (out_c == nullptr || !mxIsCell(out_c) ||
                mxGetNumberOfElements(out_c) != K ||
                static_cast<std::size_t>(omega.size()) != K)) {
    g.fail("dimensionMismatch", "out_c and out_omega need one entry per term");
  }
  for (std::size_t k = 0; k < K; ++k) {
    ctid::residtrace::OutputTerm<double> t;
    if (out_kind[k] < 0 || out_kind[k] > 3) {
      g.fail("badOption", "unknown output term kind");
    }
    t.kind = static_cast<OutputTermKind>(out_kind[k]);
    const mxArray* c = mxGetCell(out_c, k);
    if (c != nullptr && !mxIsEmpty(c)) {
      const auto v = any_matrix(g, c, "out_c");
      t.c = Eigen::Map<const Eigen::VectorXd>(v.data(), v.size());
    }
    t.omega = omega(k);
    model.out.push_back(t);
  }
  std::vector<Eigen::VectorXd> starts;
  const mxArray* s = opt.field("starts");
  if (s != nullptr && !mxIsEmpty(s)) {
    if (!mxIsCell(s)) g.fail("badOption", "starts must be a cell");
    for (std::size_t i = 0; i < mxGetNumberOfElements(s); ++i) {
      const mxArray* F0 = mxGetCell(s, i);
      if (F0 == nullptr || mxIsEmpty(F0)) {
        starts.push_back(Eigen::VectorXd());
      } else {
        const auto v = g.eigen_matrix(F0, "a start");
        starts.push_back(Eigen::Map<const Eigen::VectorXd>(v.data(), v.size()));
      }
    }
  }
  const int maxiter = opt.integer("maxiter");
  opt.finish();
  ctid::residtrace::StructureFit<double> fit;
  g.check(ctid::residtrace::fit_structure<double>(model, rec, starts, maxiter,
                                                  &fit));
  std::vector<Eigen::VectorXd> c, cstd;
  Eigen::MatrixXd fitted = Eigen::MatrixXd::Zero(1, K);
  for (std::size_t k = 0; k < fit.out.size(); ++k) {
    c.push_back(fit.out[k].c);
    cstd.push_back(fit.out[k].cstd);
    fitted(k) = fit.out[k].fitted;
  }
  const char* names[] = {"ok",       "failed_round", "F",     "B",   "out_c",
                         "out_cstd", "out_fitted",   "theta", "cov", "s2",
                         "np",       "bic",          "e"};
  plhs[0] = mxCreateStructMatrix(1, 1, 13, names);
  mxSetField(plhs[0], 0, "ok", mxCreateLogicalScalar(fit.ok));
  mxSetField(plhs[0], 0, "failed_round",
             mxCreateDoubleScalar(fit.failed_round));
  mxSetField(plhs[0], 0, "F", put_matrix(fit.F.transpose()));
  mxSetField(plhs[0], 0, "B", put_cell(fit.B));
  mxSetField(plhs[0], 0, "out_c", put_cell(c));
  mxSetField(plhs[0], 0, "out_cstd", put_cell(cstd));
  mxSetField(plhs[0], 0, "out_fitted", put_matrix(fitted));
  mxSetField(plhs[0], 0, "theta", put_matrix(fit.theta));
  mxSetField(plhs[0], 0, "cov", put_matrix(fit.cov));
  mxSetField(plhs[0], 0, "s2", mxCreateDoubleScalar(fit.s2));
  mxSetField(plhs[0], 0, "np", mxCreateDoubleScalar(fit.np));
  mxSetField(plhs[0], 0, "bic", mxCreateDoubleScalar(fit.bic));
  mxSetField(plhs[0], 0, "e", put_matrix(fit.e));
}

// A field of a record struct (absent: nullptr).
const mxArray* record_field(const mxArray* s, const char* name) {
  return mxGetField(s, 0, name);
}

Eigen::MatrixXd record_matrix(const Gateway& g, const mxArray* s,
                              const char* name, long rows) {
  const mxArray* a = record_field(s, name);
  if (a == nullptr)
    g.fail("badInput", std::string("the record has no ") + name);
  return any_matrix(g, a, name, rows, -1);
}

void require_record(const Gateway& g, const mxArray* s, const char* what) {
  if (!mxIsStruct(s) || mxGetNumberOfElements(s) != 1) {
    g.fail("badInput", std::string(what) + " must be a 1x1 struct");
  }
}

void simulate_method(const Gateway& g, int nlhs, mxArray* plhs[], int nrhs,
                     const mxArray* prhs[]) {
  if (nrhs != 5) {
    g.fail("badInput", "simulate takes (fname, 'simulate', model, u, options)");
  }
  if (nlhs > 3) g.fail("badInput", "simulate has at most 3 outputs");
  const auto model = ctid::mex::read_model(g, prhs[2]);
  const Eigen::MatrixXd u = any_matrix(g, prhs[3], "u");
  const long n = static_cast<long>(u.rows());
  ctid::mex::OptionsReader opt(g, prhs[4]);
  const double ts = opt.scalar("ts");
  const int substeps = opt.integer("substeps", 1);
  if (substeps < 1 || substeps > 10000) {
    g.fail("badOption", "option 'substeps' must lie in [1, 1e4]");
  }
  ctid::residtrace::ClosedLoop<double> loop;
  const bool closed =
      ctid::mex::read_closed_loop(g, opt.field("loop"), n, &loop);
  const Eigen::MatrixXd thm = optional_signal(g, opt.field("thm"), "thm", n);
  opt.finish();
  ctid::residtrace::ModelSimulation<double> sim;
  g.check(ctid::residtrace::simulate_model<double>(
      model, u, ts, closed ? &loop : nullptr, substeps,
      thm.size() ? &thm : nullptr, &sim));
  plhs[0] = put_matrix(sim.y);
  if (nlhs >= 2) plhs[1] = put_matrix(sim.x);
  if (nlhs >= 3) plhs[2] = put_matrix(sim.uc);
}

void valerror_method(const Gateway& g, int nlhs, mxArray* plhs[], int nrhs,
                     const mxArray* prhs[]) {
  if (nrhs != 5) {
    g.fail("badInput", "valerror takes (fname, 'valerror', model, V, options)");
  }
  if (nlhs > 2) g.fail("badInput", "valerror has at most 2 outputs");
  const auto model = ctid::mex::read_model(g, prhs[2]);
  const mxArray* s = prhs[3];
  require_record(g, s, "V");
  ctid::residtrace::ValidationRecord<double> V;
  V.y = record_matrix(g, s, "y", -1).reshaped();
  const long n = static_cast<long>(V.y.size());
  V.u = record_matrix(g, s, "u", n);
  V.ts = g.scalar(record_field(s, "Ts"), "V.Ts");
  V.closed =
      ctid::mex::read_closed_loop(g, record_field(s, "loop"), n, &V.loop);
  const mxArray* pre = record_field(s, "pre");
  if (pre != nullptr && !mxIsEmpty(pre)) {
    require_record(g, pre, "V.pre");
    V.u_pre = record_matrix(g, pre, "u", -1);
  }
  const mxArray* miss = record_field(s, "missing");
  if (miss != nullptr &&
      mxGetNumberOfElements(miss) == static_cast<std::size_t>(n)) {
    const Eigen::VectorXd mv =
        ctid::mex::model_io_detail::values(g, miss, "V.missing");
    for (long k = 0; k < n; ++k) V.missing.push_back(mv(k) != 0);
  }
  ctid::mex::OptionsReader opt(g, prhs[4]);
  const int substeps = opt.integer("substeps", 1);
  if (substeps < 1 || substeps > 10000) {
    g.fail("badOption", "option 'substeps' must lie in [1, 1e4]");
  }
  V.thm = optional_signal(g, opt.field("thm"), "thm",
                          n + static_cast<long>(V.u_pre.rows()));
  const Eigen::MatrixXd yh = optional_signal(g, opt.field("yh"), "yh", n);
  if (yh.size()) V.yh_given = yh.col(0);
  opt.finish();
  Eigen::VectorXd e, yhat;
  g.check(ctid::residtrace::validation_error<double>(model, V, substeps, &e,
                                                     &yhat));
  plhs[0] = put_matrix(e);
  if (nlhs >= 2) plhs[1] = put_matrix(yhat);
}

void fitmodel_method(const Gateway& g, int nlhs, mxArray* plhs[], int nrhs,
                     const mxArray* prhs[]) {
  if (nrhs != 5) {
    g.fail("badInput", "fitmodel takes (fname, 'fitmodel', tmpl, D, options)");
  }
  if (nlhs > 1) g.fail("badInput", "fitmodel has one output");
  const auto tmpl = ctid::mex::read_model(g, prhs[2]);
  ctid::mex::OptionsReader opt(g, prhs[4]);
  const auto ctx =
      ctid::mex::residtrace_candidate::read_context(g, prhs[3], opt);
  const std::vector<Eigen::VectorXd> starts =
      ctid::mex::residtrace_candidate::read_starts(g, opt.field("starts"));
  opt.finish();
  ctid::residtrace::ResidtraceModel<double> fit;
  g.check(
      ctid::residtrace::fit_model<double>(tmpl, ctx.D, starts, ctx.fit, &fit));
  plhs[0] = ctid::mex::write_model(prhs[2], fit);
}

// The velocity of a measured output without phase lag (responses.hpp).
void velocity_method(const Gateway& g, int nlhs, mxArray* plhs[], int nrhs,
                     const mxArray* prhs[]) {
  if (nrhs != 4) {
    g.fail("badInput", "velocity takes (fname, 'velocity', y, options)");
  }
  if (nlhs > 1) g.fail("badInput", "velocity has one output");
  g.require_real_double(prhs[2], "y");
  if (mxGetN(prhs[2]) != 1 && !mxIsEmpty(prhs[2])) {
    g.fail("badInput", "y must be a column vector");
  }
  const long n = static_cast<long>(mxGetNumberOfElements(prhs[2]));
  const Eigen::VectorXd y =
      n > 0 ? Eigen::VectorXd(
                  Eigen::Map<const Eigen::VectorXd>(mxGetPr(prhs[2]), n))
            : Eigen::VectorXd();
  ctid::mex::OptionsReader opt(g, prhs[3]);
  const double ts = opt.scalar("ts");
  const double lambda = opt.scalar("lambda");
  const bool output_itself = opt.flag("output_itself", false);
  opt.finish();
  Eigen::VectorXd v;
  g.check(ctid::residtrace::zero_lag_velocity<double>(y.data(), n, ts, lambda,
                                                      output_itself, &v));
  plhs[0] = put_matrix(v);
}

// The prefilter's denominator of residtrace's SRIVC iterations
// (prefilter.hpp).
void prefilter_method(const Gateway& g, int nlhs, mxArray* plhs[], int nrhs,
                      const mxArray* prhs[]) {
  if (nrhs != 4) {
    g.fail("badInput", "prefilter takes (fname, 'prefilter', F, options)");
  }
  if (nlhs > 1) g.fail("badInput", "prefilter has one output");
  g.require_real_double(prhs[2], "F");
  const long n = static_cast<long>(mxGetNumberOfElements(prhs[2]));
  if (n < 1 || (mxGetM(prhs[2]) != 1 && mxGetN(prhs[2]) != 1)) {
    g.fail("badInput", "F must be a nonempty vector");
  }
  const Eigen::VectorXd F =
      Eigen::Map<const Eigen::VectorXd>(mxGetPr(prhs[2]), n);
  ctid::mex::OptionsReader opt(g, prhs[3]);
  const double wlo = opt.scalar("wlo");
  opt.finish();
  Eigen::VectorXd Fp;
  g.check(ctid::residtrace::prefilter_denominator<double>(F, wlo, &Fp));
  plhs[0] = put_matrix(Eigen::MatrixXd(Fp.transpose()));
}

// The initial levels of a cascade realisation (physical_fit.hpp).
void cascadelevels_method(const Gateway& g, int nlhs, mxArray* plhs[], int nrhs,
                          const mxArray* prhs[]) {
  if (nrhs != 4) {
    g.fail("badInput",
           "cascadelevels takes (fname, 'cascadelevels', phys, options)");
  }
  if (nlhs > 2) g.fail("badInput", "cascadelevels has at most 2 outputs");
  if (!mxIsStruct(prhs[2]) || mxGetNumberOfElements(prhs[2]) != 1) {
    g.fail("badInput", "the realisation must be a 1x1 struct");
  }
  const auto phys = ctid::mex::model_io_detail::read_phys(g, prhs[2]);
  if (phys.kind != ctid::residtrace::PhysicalKind::kCascade) {
    g.fail("badInput", "the realisation must be a cascade");
  }
  ctid::mex::OptionsReader opt(g, prhs[3]);
  opt.finish();
  double z0, h0;
  ctid::residtrace::cascade_levels<double>(phys, &z0, &h0);
  plhs[0] = mxCreateDoubleScalar(z0);
  if (nlhs >= 2) plhs[1] = mxCreateDoubleScalar(h0);
}

// The physical reading of a model (physical_reading.hpp): a struct array
// with fields name, value (real unless a complex zero or pole) and std.
void physical_method(const Gateway& g, int nlhs, mxArray* plhs[], int nrhs,
                     const mxArray* prhs[]) {
  if (nrhs != 4) {
    g.fail("badInput", "physical takes (fname, 'physical', model, options)");
  }
  if (nlhs > 1) g.fail("badInput", "physical has one output");
  const auto model = ctid::mex::read_model(g, prhs[2]);
  const auto labels = ctid::mex::read_reading_labels(g, prhs[2]);
  ctid::mex::OptionsReader opt(g, prhs[3]);
  const double ts = opt.scalar("ts");
  if (!(ts > 0)) g.fail("badOption", "option 'ts' must be > 0");
  opt.finish();
  const auto p = ctid::residtrace::physical_reading<double>(model, ts, labels);
  const char* names[] = {"name", "value", "std"};
  plhs[0] = mxCreateStructMatrix(p.empty() ? 0 : 1, p.size(), 3, names);
  for (std::size_t k = 0; k < p.size(); ++k) {
    const auto& v = p[k].value;
    bool complex = false;
    for (const auto& z : v) complex = complex || z.imag() != 0;
    mxArray* a =
        mxCreateDoubleMatrix(1, v.size(), complex ? mxCOMPLEX : mxREAL);
    for (std::size_t i = 0; i < v.size(); ++i) {
      mxGetPr(a)[i] = v[i].real();
      if (complex) mxGetPi(a)[i] = v[i].imag();
    }
    mxSetField(plhs[0], k, "name", mxCreateString(p[k].name.c_str()));
    mxSetField(plhs[0], k, "value", a);
    mxSetField(plhs[0], k, "std", mxCreateDoubleScalar(p[k].std));
  }
}

}  // namespace

void mexFunction(int nlhs, mxArray* plhs[], int nrhs, const mxArray* prhs[]) {
  ctid::mex::run_gateway(
      "residtrace", {"residtrace"}, nrhs, prhs, [&](const Gateway& g) {
        if (nrhs >= 2 && mxIsChar(prhs[1])) {
          const std::string method = g.text(prhs[1], "the method");
          if (method == "filter") {
            filter_method(g, nlhs, plhs, nrhs, prhs);
          } else if (method == "free") {
            free_method(g, nlhs, plhs, nrhs, prhs);
          } else if (method == "track") {
            track_method(g, nlhs, plhs, nrhs, prhs);
          } else if (method == "dmtest") {
            dmtest_method(g, nlhs, plhs, nrhs, prhs);
          } else if (method == "whiteness") {
            whiteness_method(g, nlhs, plhs, nrhs, prhs);
          } else if (method == "ar") {
            ar_method(g, nlhs, plhs, nrhs, prhs);
          } else if (method == "physsim") {
            physsim_method(g, nlhs, plhs, nrhs, prhs);
          } else if (method == "physfit") {
            physfit_method(g, nlhs, plhs, nrhs, prhs);
          } else if (method == "channels") {
            channels_method(g, nlhs, plhs, nrhs, prhs);
          } else if (method == "fit") {
            fit_method(g, nlhs, plhs, nrhs, prhs);
          } else if (method == "simulate") {
            simulate_method(g, nlhs, plhs, nrhs, prhs);
          } else if (method == "valerror") {
            valerror_method(g, nlhs, plhs, nrhs, prhs);
          } else if (method == "fitmodel") {
            fitmodel_method(g, nlhs, plhs, nrhs, prhs);
          } else if (method == "velocity") {
            velocity_method(g, nlhs, plhs, nrhs, prhs);
          } else if (method == "prefilter") {
            prefilter_method(g, nlhs, plhs, nrhs, prhs);
          } else if (method == "cascadelevels") {
            cascadelevels_method(g, nlhs, plhs, nrhs, prhs);
          } else if (method == "physical") {
            physical_method(g, nlhs, plhs, nrhs, prhs);
          } else if (!ctid::mex::residtrace_judge::dispatch(method, g, nlhs,
                                                            plhs, nrhs, prhs) &&
                     !ctid::mex::residtrace_candidate::dispatch(
                         method, g, nlhs, plhs, nrhs, prhs)) {
            g.fail("badInput", "unknown method '" + method + "'");
          }
          return;
        }
        effect_sim_gateway(g, nlhs, plhs, nrhs, prhs);
      });
}
