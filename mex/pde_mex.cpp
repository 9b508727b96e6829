// SPDX-License-Identifier: BSD-3-Clause
// Copyright (C) the ctid authors
// MEX gateway of the heat-equation routines (core/include/ctid/offline/
// pde_heat.hpp). The first argument names the public function and chooses
// the routine:
//
//   y  = pde_mex ("sim_heat", theta, t, x, u, ic)
//   yf = pde_mex ("local_filter3", num, den, x)
//   th = pde_mex ("pdelssvf4heatdiffusion", t, x, y, u, options)
//   [th, ni, conv] = pde_mex ("pdesrivc4heatdiffusion", t, x, y, u, options)
//   [th, ni, conv, ct, dt, cs, ds] = pde_mex ("pderivc4heatdiffusion", t, x,
//                                             y, u, options)
//
// theta = [a b]; t, x vectors; y, u numel(t)-by-numel(x). options: for
// LSSVF, rule ("bili" or "euler") and lambda = [lambda_t lambda_x]; for
// SRIVC and RIVC, ic (numel(x) values), tol, maxiter, and for RIVC nn =
// [ndt nct nds ncs]. th is 2-by-1; the noise polynomials are rows.
#include "ctid/offline/pde_heat.hpp"
#include "gateway_common.hpp"
#include "options_reader.hpp"

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
  nargs(6);
  const Eigen::VectorXd t = vec(g, prhs[1], "Data2.t");
  const Eigen::VectorXd x = vec(g, prhs[2], "Data2.x");
  const Eigen::MatrixXd y = g.eigen_matrix(prhs[3], "Data1.Output");
  const Eigen::MatrixXd u = g.eigen_matrix(prhs[4], "Data1.Input");
  ctid::mex::OptionsReader opt(g, prhs[5]);
  if (f == "pdelssvf4heatdiffusion") {
    const ctid::HeatRule rule = opt.choice<ctid::HeatRule>(
        "rule", {{"bili", ctid::HeatRule::kBilinear},
                 {"euler", ctid::HeatRule::kEuler}},
        ctid::HeatRule::kBilinear);
    const Eigen::MatrixXd lambda = opt.required_matrix("lambda", 1, 2);
    opt.finish();
    Eigen::Vector2d theta;
    g.check(ctid::heat_lssvf(t, x, y, u, rule, lambda(0, 0), lambda(0, 1),
                             &theta));
    plhs[0] = ctid::mex::to_output(theta);
    return;
  }
  const bool refined = f == "pderivc4heatdiffusion";
  const Eigen::MatrixXd icm = opt.required_matrix("ic", 1, x.size());
  const Eigen::VectorXd ic = icm.row(0).transpose();
  ctid::HeatIvOptions iv;
  iv.tol = opt.scalar("tol", iv.tol);
  iv.maxiter = opt.integer("maxiter", iv.maxiter);
  if (refined) {
    const std::vector<int> nn = opt.integer_vector("nn");
    if (nn.size() != 4) g.fail("badInput", "nn must be [ndet ncet ndes nces]");
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
  ctid::mex::run_gateway(
      "sim_heat",
      {"sim_heat", "local_filter3", "pdelssvf4heatdiffusion",
       "pdesrivc4heatdiffusion", "pderivc4heatdiffusion"},
      nrhs, prhs,
      [&](const Gateway& g) { pde_gateway(g, nlhs, plhs, nrhs, prhs); });
}
