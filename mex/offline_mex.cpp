// SPDX-License-Identifier: BSD-3-Clause
// Copyright (C) the ctid authors
// MEX gateway of the offline estimators lssvf, ivsvf, srivc and clsrivc
// (octave/private/contsid_offline.m):
//
//   [theta, cov, sigma2, iterations, converged] = offline_mex (fname, y, u,
//       t, options)
//
// y N-by-1, u N-by-nu, t the sampling interval or the N instants. Fields of
// options: intersample, na, nb, nk, lambda_svf, svf (gateway_common.hpp),
// method 'lssvf' | 'ivsvf' | 'srivc' | 'clsrivc'; for srivc and clsrivc
// tol, maxiter and theta_init (absent or []: the IVSVF/CLIVSVF start, else
// np values); for clsrivc controller_num, controller_den, r1 and r2.
// theta is in the core's order [a1 .. a_na, b ..]. An SRIVC that does not
// converge returns its last iterate with converged = false (the front-end
// warns).
//
//   m = offline_mex (fname, y, u, t, options)   with options.method =
//                                               "scaling"
// returns instead the diagonal of the scaling matrix M_s of eq. (3.54) for
// the SVF regression of this record (svfscaling, rlssvf/rsrivc 'scaling').
//
// method 'tocls' | 'tocils' (errors-in-variables, cumulant_eiv.hpp): the
// options lags (M), and for tocils maxiter and tol; cov and sigma2 are then
// empty (no covariance is computed).
#include "ctid/offline/cumulant_eiv.hpp"
#include "ctid/offline/refined_iv.hpp"
#include "ctid/recursive/scaling.hpp"
#include "gateway_common.hpp"

namespace {

using ctid::mex::Gateway;

enum class Method {
  kScaling,
  kLssvf,
  kIvsvf,
  kSrivc,
  kClsrivc,
  kTocls,
  kTocils
};

void offline_gateway(const Gateway& g, int nlhs, mxArray* plhs[], int nrhs,
                     const mxArray* prhs[]) {
  if (nrhs != 5) {
    g.fail("badInput",
           "the gateway takes 5 arguments (fname, y, u, t, "
           "options), got " +
               std::to_string(nrhs) + " (call " + g.name() + " instead)");
  }
  if (nlhs > 5) g.fail("badInput", "at most 5 outputs");
  const ctid::RecordView<double> record =
      ctid::mex::read_record(g, prhs[1], prhs[2], prhs[3]);
  ctid::mex::OptionsReader opt(g, prhs[4]);
  ctid::SvfSettings<double> svf;
  ctid::mex::read_svf(opt, &svf);
  const ctid::ModelOrders orders = ctid::mex::read_orders(g, opt);
  const Method method = opt.choice<Method>("method",
                                           {{"scaling", Method::kScaling},
                                            {"lssvf", Method::kLssvf},
                                            {"ivsvf", Method::kIvsvf},
                                            {"srivc", Method::kSrivc},
                                            {"clsrivc", Method::kClsrivc},
                                            {"tocls", Method::kTocls},
                                            {"tocils", Method::kTocils}},
                                           Method::kSrivc);
  if (!opt.has("method")) g.fail("badOption", "option 'method' is missing");
  if (method == Method::kScaling) {
    opt.finish();
    if (nlhs > 1) g.fail("badInput", "the scaling has 1 output");
    ctid::Vector<double> m;
    g.check(ctid::svf_scaling(orders, svf, record, m));
    plhs[0] = ctid::mex::make_output_matrix(m.size(), 1);
    std::copy(m.data(), m.data() + m.size(), mxGetPr(plhs[0]));
    return;
  }
  const long np = orders.num_parameters();
  if (method == Method::kTocls || method == Method::kTocils) {
    ctid::CumulantEivSettings<double> eiv;
    eiv.lags = opt.integer("lags", eiv.lags);
    if (method == Method::kTocils) {
      eiv.max_iterations = opt.integer("maxiter", eiv.max_iterations);
      eiv.tolerance = opt.scalar("tol", eiv.tolerance);
    }
    opt.finish();
    ctid::CumulantEivEstimate<double> estimate;
    g.check(method == Method::kTocls
                ? ctid::tocls(orders, svf, record, eiv, &estimate)
                : ctid::tocils(orders, svf, record, eiv, &estimate));
    plhs[0] = ctid::mex::make_output_matrix(np, 1);
    std::copy(estimate.theta.data(), estimate.theta.data() + np,
              mxGetPr(plhs[0]));
    if (nlhs >= 2) plhs[1] = ctid::mex::make_output_matrix(0, 0);
    if (nlhs >= 3) plhs[2] = ctid::mex::make_output_matrix(0, 0);
    if (nlhs >= 4) plhs[3] = mxCreateDoubleScalar(estimate.iterations);
    if (nlhs >= 5) plhs[4] = mxCreateLogicalScalar(estimate.converged);
    return;
  }
  ctid::SrivcSettings<double> settings;
  const bool iterative = method == Method::kSrivc || method == Method::kClsrivc;
  if (iterative) {
    settings.tolerance = opt.scalar("tol", settings.tolerance);
    settings.max_iterations = opt.integer("maxiter", settings.max_iterations);
    const Eigen::MatrixXd theta_init = opt.matrix("theta_init", np, 1);
    if (theta_init.size() != 0) settings.theta_init = theta_init;
  }
  ctid::DiscreteTransferFunction<double> controller;
  const double* r1 = nullptr;
  const double* r2 = nullptr;
  if (method == Method::kClsrivc) {
    if (!ctid::mex::read_transfer_function(g, opt, "controller", &controller)) {
      g.fail("badOption",
             "clsrivc needs the options 'controller_num' and "
             "'controller_den'");
    }
    const long n = record.num_samples;
    r1 = opt.signal("r1", n);
    r2 = opt.signal("r2", n);
    if (r1 == nullptr || r2 == nullptr) {
      g.fail("badOption", "clsrivc needs the options 'r1' and 'r2'");
    }
  }
  opt.finish();
  ctid::OfflineEstimate<double> estimate;
  ctid::Status status;
  switch (method) {
    case Method::kLssvf:
      status = ctid::lssvf(orders, svf, record, &estimate);
      break;
    case Method::kIvsvf:
      status = ctid::ivsvf(orders, svf, record, &estimate);
      break;
    case Method::kSrivc:
      status = ctid::srivc(orders, svf, settings, record, &estimate);
      break;
    case Method::kScaling:  // returned above
    case Method::kTocls:
    case Method::kTocils:
      break;
    case Method::kClsrivc:
      status = ctid::clsrivc(orders, svf, settings, record, r1, r2, controller,
                             &estimate);
      break;
  }
  if (status.code() != ctid::ErrorCode::kNotConverged) g.check(status);
  if (estimate.theta.size() != np) {
    g.fail("numericalFailure", "no estimate was produced");
  }
  plhs[0] = ctid::mex::make_output_matrix(np, 1);
  std::copy(estimate.theta.data(), estimate.theta.data() + np,
            mxGetPr(plhs[0]));
  if (nlhs >= 2) {
    plhs[1] = ctid::mex::make_output_matrix(np, np);
    if (estimate.covariance.rows() == np && estimate.covariance.cols() == np) {
      std::copy(estimate.covariance.data(),
                estimate.covariance.data() + np * np, mxGetPr(plhs[1]));
    }
  }
  if (nlhs >= 3) plhs[2] = mxCreateDoubleScalar(estimate.noise_variance);
  if (nlhs >= 4) plhs[3] = mxCreateDoubleScalar(estimate.iterations);
  if (nlhs >= 5) plhs[4] = mxCreateLogicalScalar(estimate.converged);
}

}  // namespace

void mexFunction(int nlhs, mxArray* plhs[], int nrhs, const mxArray* prhs[]) {
  ctid::mex::run_gateway(
      "srivc",
      {"lssvf", "ivsvf", "srivc", "clsrivc", "svfscaling", "tocls", "tocils",
       "rlssvf", "rivsvf", "rsrivc", "clrivsvf", "clrsrivc"},
      nrhs, prhs,
      [&](const Gateway& g) { offline_gateway(g, nlhs, plhs, nrhs, prhs); });
}
