// SPDX-License-Identifier: BSD-3-Clause
// Copyright (C) the ctid authors
// MEX gateway of the heat-equation routines (core/include/ctid/offline/
// pde_heat.hpp). The first argument names the public function and chooses
// the routine; the data arrays come positionally, the rest in one options
// struct:
//
//   y  = pde_mex ("sim_heat", u, options)          theta, t, x, ic
//   yf = pde_mex ("local_filter3", x, options)     num, den
//   th = pde_mex ("pdelssvf4heatdiffusion", y, u, options)
//                                                  t, x, lambda[, rule]
//   [th, ni, conv] = pde_mex ("pdesrivc4heatdiffusion", y, u, options)
//                                                  t, x, ic[, tol, maxiter]
//   [th, ni, conv, ct, dt, cs, ds] = pde_mex ("pderivc4heatdiffusion", y, u,
//                                             options)   the same and nn
//
// theta = [a b]; t, x vectors (time and space grids); y, u
// numel(t)-by-numel(x); ic numel(x) values; lambda = [lambda_t lambda_x];
// rule "bili" (default) or "euler"; nn = [ndt nct nds ncs]. th is 2-by-1;
// the noise polynomials are rows.
#include "ctid/offline/pde_heat.hpp"
#include "gateway_common.hpp"
#include "options_reader.hpp"

namespace {

using ctid::mex::Gateway;
using ctid::mex::OptionsReader;

// A required vector option (a row or a column).
Eigen::VectorXd vector_option(const Gateway& g, OptionsReader& opt,
                              const char* name) {
  const Eigen::MatrixXd m = opt.required_matrix(name);
  if (m.rows() > 1 && m.cols() > 1) {
    g.fail("badOption", std::string("option '") + name + "' must be a vector");
  }
  return Eigen::Map<const Eigen::VectorXd>(m.data(), m.size());
}

mxArray* row_out(const Eigen::VectorXd& v) {
  mxArray* out = ctid::mex::make_output_matrix(1, v.size());
  std::copy(v.data(), v.data() + v.size(), mxGetPr(out));
  return out;
}

void pde_gateway(const Gateway& g, int nlhs, mxArray* plhs[], int nrhs,
                 const mxArray* prhs[]) {
  const std::string& f = g.name();
  const auto counts = [&](int nin, int nout) {
    if (nrhs != nin) {
      g.fail("badInput", "the gateway takes " + std::to_string(nin) +
                             " arguments, got " + std::to_string(nrhs));
    }
    if (nlhs > nout) {
      g.fail("badInput", "at most " + std::to_string(nout) + " outputs");
    }
  };
  if (f == "sim_heat") {
    counts(3, 1);
    const Eigen::MatrixXd u = g.eigen_matrix(prhs[1], "the input field");
    OptionsReader opt(g, prhs[2]);
    const Eigen::MatrixXd theta = opt.required_matrix("theta", 1, 2);
    const Eigen::VectorXd t = vector_option(g, opt, "t");
    const Eigen::VectorXd x = vector_option(g, opt, "x");
    const Eigen::VectorXd ic = vector_option(g, opt, "ic");
    opt.finish();
    Eigen::MatrixXd y;
    g.check(ctid::simulate_heat(theta(0, 0), theta(0, 1), t, x, u, ic, &y));
    plhs[0] = ctid::mex::to_output(y);
    return;
  }
  if (f == "local_filter3") {
    counts(3, 1);
    const Eigen::MatrixXd x = g.eigen_matrix(prhs[1], "the data");
    OptionsReader opt(g, prhs[2]);
    const Eigen::MatrixXd num = opt.required_matrix("num");
    const Eigen::MatrixXd den = opt.required_matrix("den");
    opt.finish();
    Eigen::MatrixXd y;
    g.check(ctid::filter_2d(num, den, x, &y));
    plhs[0] = ctid::mex::to_output(y);
    return;
  }
  const bool lssvf = f == "pdelssvf4heatdiffusion";
  const bool refined = f == "pderivc4heatdiffusion";
  counts(4, lssvf ? 1 : (refined ? 7 : 3));
  const Eigen::MatrixXd y = g.eigen_matrix(prhs[1], "Data1.Output");
  const Eigen::MatrixXd u = g.eigen_matrix(prhs[2], "Data1.Input");
  OptionsReader opt(g, prhs[3]);
  const Eigen::VectorXd t = vector_option(g, opt, "t");
  const Eigen::VectorXd x = vector_option(g, opt, "x");
  if (lssvf) {
    const ctid::HeatRule rule =
        opt.choice<ctid::HeatRule>("rule",
                                   {{"bili", ctid::HeatRule::kBilinear},
                                    {"euler", ctid::HeatRule::kEuler}},
                                   ctid::HeatRule::kBilinear);
    const Eigen::MatrixXd lambda = opt.required_matrix("lambda", 1, 2);
    opt.finish();
    Eigen::Vector2d theta;
    g.check(
        ctid::heat_lssvf(t, x, y, u, rule, lambda(0, 0), lambda(0, 1), &theta));
    plhs[0] = ctid::mex::to_output(theta);
    return;
  }
  const Eigen::VectorXd ic = vector_option(g, opt, "ic");
  ctid::HeatIvOptions iv;
  iv.tol = opt.scalar("tol", iv.tol);
  iv.maxiter = opt.integer("maxiter", iv.maxiter);
  if (refined) {
    const std::vector<int> nn = opt.integer_vector("nn");
    if (nn.size() != 4) g.fail("badOption", "nn must be [ndet ncet ndes nces]");
    for (int i = 0; i < 4; ++i) iv.orders[i] = nn[i];
  }
  opt.finish();
  ctid::HeatIvResult res;
  g.check(refined ? ctid::heat_rivc(t, x, y, u, ic, iv, &res)
                  : ctid::heat_srivc(t, x, y, u, ic, iv, &res));
  plhs[0] = ctid::mex::to_output(res.theta);
  if (nlhs > 1) plhs[1] = mxCreateDoubleScalar(res.iterations);
  if (nlhs > 2) plhs[2] = mxCreateDoubleScalar(res.converged ? 1.0 : 0.0);
  if (nlhs > 3) plhs[3] = row_out(res.ct);
  if (nlhs > 4) plhs[4] = row_out(res.dt);
  if (nlhs > 5) plhs[5] = row_out(res.cs);
  if (nlhs > 6) plhs[6] = row_out(res.ds);
}

}  // namespace

void mexFunction(int nlhs, mxArray* plhs[], int nrhs, const mxArray* prhs[]) {
  ctid::mex::run_gateway("sim_heat",
                         {"sim_heat", "local_filter3", "pdelssvf4heatdiffusion",
                          "pdesrivc4heatdiffusion", "pderivc4heatdiffusion"},
                         nrhs, prhs, [&](const Gateway& g) {
                           pde_gateway(g, nlhs, plhs, nrhs, prhs);
                         });
}
