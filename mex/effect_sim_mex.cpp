// SPDX-License-Identifier: BSD-3-Clause
// Copyright (C) the ctid authors
// MEX gateway of the effect-model simulator (core/include/ctid/
// effect_simulator.hpp), used by octave/private/residtrace_simulate.m:
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
#include "ctid/simulation/effect_simulator.hpp"
#include "gateway_common.hpp"

namespace {

using ctid::mex::Gateway;

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

}  // namespace

void mexFunction(int nlhs, mxArray* plhs[], int nrhs, const mxArray* prhs[]) {
  ctid::mex::run_gateway(
      "residtrace", {"residtrace"}, nrhs, prhs,
      [&](const Gateway& g) { effect_sim_gateway(g, nlhs, plhs, nrhs, prhs); });
}
