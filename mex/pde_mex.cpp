// SPDX-License-Identifier: BSD-3-Clause
// Copyright (C) the ctid authors
// MEX gateway of the heat-equation routines (core/include/ctid/offline/
// pde_heat.hpp). The first argument names the public function and chooses
// the routine:
//
//   y  = pde_mex ("sim_heat", theta, t, x, u, ic)
//   yf = pde_mex ("local_filter3", num, den, x)
//   th = pde_mex ("pdelssvf4heatdiffusion", t, x, y, u, rule, lambda)
//   [th, ni, conv] = pde_mex ("pdesrivc4heatdiffusion", t, x, y, u, ic,
//                             tol, maxiter)
//   [th, ni, conv, ct, dt, cs, ds] = pde_mex ("pderivc4heatdiffusion", t, x,
//                             y, u, ic, tol, maxiter, orders)
//
// theta = [a b]; t, x vectors; y, u numel(t)-by-numel(x); ic numel(x)
// values; rule 0 bilinear, 1 Euler; lambda = [lambda_t lambda_x]; orders =
// [ndt nct nds ncs]. th is 2-by-1; the noise polynomials are rows.
#include "ctid/offline/pde_heat.hpp"
#include "gateway_common.hpp"

namespace {

using ctid::mex::Gateway;

Eigen::VectorXd vec(const Gateway& g, const mxArray* a, const char* what) {
  g.require_real_double(a, what);
  if (mxGetM(a) > 1 && mxGetN(a) > 1) g.fail("badInput", std::string(what) + " must be a vector");
  const Eigen::Map<const Eigen::MatrixXd> m = g.eigen_matrix(a, what);
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
  const auto nargs = [&](int n) {
    if (nrhs != n) {
      g.fail("badInput", "the gateway takes " + std::to_string(n) +
                             " arguments, got " + std::to_string(nrhs));
    }
  };
  if (f == "sim_heat") {
    nargs(6);
    const Eigen::VectorXd theta = vec(g, prhs[1], "theta");
    if (theta.size() != 2) g.fail("badInput", "theta must be [a b]");
    const Eigen::VectorXd t = vec(g, prhs[2], "t"), x = vec(g, prhs[3], "x");
    const Eigen::MatrixXd u = g.eigen_matrix(prhs[4], "the input field");
    const Eigen::VectorXd ic = vec(g, prhs[5], "the initial condition");
    Eigen::MatrixXd y;
    g.check(ctid::simulate_heat(theta[0], theta[1], t, x, u, ic, &y));
    plhs[0] = ctid::mex::to_output(y);
    return;
  }
  if (f == "local_filter3") {
    nargs(4);
    const Eigen::MatrixXd num = g.eigen_matrix(prhs[1], "the numerator");
    const Eigen::MatrixXd den = g.eigen_matrix(prhs[2], "the denominator");
    const Eigen::MatrixXd x = g.eigen_matrix(prhs[3], "the data");
    Eigen::MatrixXd y;
    g.check(ctid::filter_2d(num, den, x, &y));
    plhs[0] = ctid::mex::to_output(y);
    return;
  }
  const Eigen::VectorXd t = vec(g, prhs[1], "Data2.t");
  const Eigen::VectorXd x = vec(g, prhs[2], "Data2.x");
  const Eigen::MatrixXd y = g.eigen_matrix(prhs[3], "Data1.Output");
  const Eigen::MatrixXd u = g.eigen_matrix(prhs[4], "Data1.Input");
  if (f == "pdelssvf4heatdiffusion") {
    nargs(7);
    const int rule = g.integer(prhs[5], "rule");
    const Eigen::VectorXd lambda = vec(g, prhs[6], "Filter.BF");
    if (lambda.size() != 2) g.fail("badOption", "Filter.BF must be [lambda_t lambda_x]");
    Eigen::Vector2d theta;
    g.check(ctid::heat_lssvf(t, x, y, u,
                             rule == 1 ? ctid::HeatRule::kEuler
                                       : ctid::HeatRule::kBilinear,
                             lambda[0], lambda[1], &theta));
    plhs[0] = ctid::mex::to_output(theta);
    return;
  }
  const bool refined = f == "pderivc4heatdiffusion";
  nargs(refined ? 9 : 8);
  const Eigen::VectorXd ic = vec(g, prhs[5], "the initial condition");
  ctid::HeatIvOptions opt;
  opt.tol = g.scalar(prhs[6], "tol");
  opt.maxiter = g.integer(prhs[7], "maxiter");
  if (refined) {
    const std::vector<int> nn = g.integer_vector(prhs[8], "nn");
    if (nn.size() != 4) g.fail("badInput", "nn must be [ndet ncet ndes nces]");
    for (int i = 0; i < 4; ++i) opt.orders[i] = nn[i];
  }
  ctid::HeatIvResult res;
  g.check(refined ? ctid::heat_rivc(t, x, y, u, ic, opt, &res)
                  : ctid::heat_srivc(t, x, y, u, ic, opt, &res));
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
  ctid::mex::run_gateway(
      "sim_heat",
      {"sim_heat", "local_filter3", "pdelssvf4heatdiffusion",
       "pdesrivc4heatdiffusion", "pderivc4heatdiffusion"},
      nrhs, prhs,
      [&](const Gateway& g) { pde_gateway(g, nlhs, plhs, nrhs, prhs); });
}
