// SPDX-License-Identifier: BSD-3-Clause
// Copyright (C) the ctid authors
// MEX gateway of the block-oriented refined-IV estimators (core/include/
// ctid/offline/hammerstein.hpp), called by octave/private/contsid_block.m:
//
//   [sep, cov, info] = hammerstein_mex (fname, y, w, t, opts)
//
// y N-by-1; w N-by-l, the basis functions f_i(u) of the input
// nonlinearity (u, u.^2, ..); t a scalar Ts or the N sampling instants.
// opts fields: model ('hsrivc' | 'hrivc' | 'hwsrivc'), nb, nf, nk, nc, nd
// (ARMA noise of hrivc), nw (terms of the output polynomial of hwsrivc),
// intersample (0 zoh, 1 foh), y_intersample, tol, maxiter, cutoffs,
// theta_init (the first pass's start [f; B_1; ..; B_l], empty: the
// engine's), arma_method ('pem' | 'ivarma', hrivc's noise model).
// sep = [f; b; alpha(2:l); beta(2:nw)], cov its covariance; info: f, b,
// alpha, beta, c, d, theta_miso, cov_miso, noise_variance, condition,
// iterations, converged, reason, simulated.
//
//   x = hammerstein_mex (fname, "poly_inverse", v, options)
//
// The inverse of the Wiener block's output polynomial, sample by sample:
// x solves beta(1) x + .. + beta(L) x^L = v (polynomial_inverse.hpp); x has
// the size of v. options field: beta.
#include <algorithm>

#include "ctid/base/polynomial_inverse.hpp"
#include "ctid/offline/hammerstein.hpp"
#include "gateway_common.hpp"
#include "options_reader.hpp"

namespace {

using ctid::mex::Gateway;
using ctid::mex::intersample_rule;
using ctid::mex::OptionsReader;
using ctid::mex::to_output;

void poly_inverse_gateway(const Gateway& g, int nlhs, mxArray* plhs[], int nrhs,
                          const mxArray* prhs[]) {
  if (nrhs != 4) {
    g.fail("badInput",
           "the poly_inverse method takes 4 arguments (fname, "
           "'poly_inverse', v, options), got " +
               std::to_string(nrhs));
  }
  if (nlhs > 1) g.fail("badInput", "the poly_inverse method has 1 output");
  g.require_real_double(prhs[2], "the values");
  const long rows = static_cast<long>(mxGetM(prhs[2]));
  const long cols = static_cast<long>(mxGetN(prhs[2]));
  const double* v = g.matrix(prhs[2], "the values", rows, cols);
  OptionsReader opt(g, prhs[3]);
  const Eigen::MatrixXd beta = opt.required_matrix("beta");
  opt.finish();
  if (beta.rows() > 1 && beta.cols() > 1) {
    g.fail("badInput", "the polynomial beta must be a vector");
  }
  plhs[0] = ctid::mex::make_output_matrix(rows, cols);
  g.check(ctid::invert_polynomial<double>(Eigen::VectorXd(beta.reshaped()), v,
                                          rows * cols, mxGetPr(plhs[0])));
}

void hammerstein_gateway(const Gateway& g, int nlhs, mxArray* plhs[], int nrhs,
                         const mxArray* prhs[]) {
  if (nrhs >= 2 && mxIsChar(prhs[1])) {
    const std::string method = g.text(prhs[1], "the method");
    if (method != "poly_inverse") {
      g.fail("badInput", "unknown method '" + method + "'");
    }
    poly_inverse_gateway(g, nlhs, plhs, nrhs, prhs);
    return;
  }
  if (nrhs != 5) {
    g.fail("badInput",
           "the gateway takes 5 arguments, got " + std::to_string(nrhs));
  }
  if (nlhs > 3) g.fail("badInput", "at most 3 outputs");
  const ctid::RecordView<double> record =
      ctid::mex::read_record(g, prhs[1], prhs[2], prhs[3]);
  for (long k = 0; k < record.num_samples * (1 + record.num_inputs); ++k) {
    const double v =
        k < record.num_samples ? record.y[k] : record.u[k - record.num_samples];
    if (!std::isfinite(v)) g.fail("badInput", "y and w must be finite");
  }
  if (record.num_inputs < 1) g.fail("badInput", "w needs a basis column");
  ctid::RivData<double> data;
  data.y = record.y;
  data.w = record.u;
  data.num_samples = record.num_samples;
  data.ts = record.ts;
  data.instants = record.instants;

  OptionsReader opt(g, prhs[4]);
  const ctid::BlockModel model = opt.choice<ctid::BlockModel>(
      "model",
      {{"hsrivc", ctid::BlockModel::kHammerstein},
       {"hrivc", ctid::BlockModel::kHammersteinArma},
       {"hwsrivc", ctid::BlockModel::kHammersteinWiener}},
      ctid::BlockModel::kHammerstein);
  ctid::BlockOrders orders;
  orders.nb = opt.integer("nb");
  orders.nf = opt.integer("nf");
  orders.nk = opt.integer("nk", 0);
  orders.nc = opt.integer("nc", 0);
  orders.nd = opt.integer("nd", 0);
  orders.nw = opt.integer("nw", 1);
  ctid::BlockSettings<double> settings;
  settings.u_rule = intersample_rule(g, opt.integer("intersample", 0));
  settings.y_rule = intersample_rule(g, opt.integer("y_intersample", 1));
  settings.tolerance = opt.scalar("tol", 1e-6);
  settings.max_iterations = opt.integer("maxiter", 30);
  const Eigen::MatrixXd cutoffs = opt.matrix("cutoffs");
  settings.cutoffs.assign(cutoffs.data(), cutoffs.data() + cutoffs.size());
  const Eigen::MatrixXd theta_init = opt.matrix("theta_init");
  if (theta_init.size() > 0) settings.theta_init = theta_init.reshaped();
  settings.arma_method = opt.choice<ctid::ArmaMethod>(
      "arma_method",
      {{"pem", ctid::ArmaMethod::kPem}, {"ivarma", ctid::ArmaMethod::kIvarma}},
      ctid::ArmaMethod::kPem);
  opt.finish();

  ctid::BlockResult<double> result;
  const ctid::Status status =
      ctid::block_srivc(model, orders, settings, data,
                        static_cast<int>(record.num_inputs), &result);
  if (status.code() != ctid::ErrorCode::kNotConverged) g.check(status);

  const int l = static_cast<int>(result.alpha.size());
  const int m = static_cast<int>(result.beta.size());
  ctid::Vector<double> sep(result.f.size() + result.b.size() + l - 1 + m - 1);
  sep << result.f, result.b, result.alpha.tail(l - 1), result.beta.tail(m - 1);
  plhs[0] = to_output(sep);
  if (nlhs >= 2) plhs[1] = to_output(result.covariance);
  if (nlhs >= 3) {
    const char* fields[] = {
        "f",          "b",          "alpha",    "beta",           "c",
        "d",          "theta_miso", "cov_miso", "noise_variance", "condition",
        "iterations", "converged",  "reason",   "simulated"};
    mxArray* info = mxCreateStructMatrix(1, 1, 14, fields);
    mxSetField(info, 0, "f", to_output(result.f));
    mxSetField(info, 0, "b", to_output(result.b));
    mxSetField(info, 0, "alpha", to_output(result.alpha));
    mxSetField(info, 0, "beta", to_output(result.beta));
    mxSetField(info, 0, "c", to_output(result.c));
    mxSetField(info, 0, "d", to_output(result.d));
    mxSetField(info, 0, "theta_miso", to_output(result.theta_miso));
    mxSetField(info, 0, "cov_miso", to_output(result.covariance_miso));
    mxSetField(info, 0, "noise_variance",
               mxCreateDoubleScalar(result.noise_variance));
    mxSetField(info, 0, "condition", mxCreateDoubleScalar(result.condition));
    mxSetField(info, 0, "iterations", mxCreateDoubleScalar(result.iterations));
    mxSetField(info, 0, "converged", mxCreateLogicalScalar(result.converged));
    mxSetField(info, 0, "reason", mxCreateString(result.reason.c_str()));
    mxSetField(info, 0, "simulated", to_output(result.simulated));
    plhs[2] = info;
  }
}

}  // namespace

void mexFunction(int nlhs, mxArray* plhs[], int nrhs, const mxArray* prhs[]) {
  ctid::mex::run_gateway("hsrivc",
                         {"hsrivc", "hrivc", "hwsrivc", "Wie", "simc_hw"}, nrhs,
                         prhs, [&](const Gateway& g) {
                           hammerstein_gateway(g, nlhs, plhs, nrhs, prhs);
                         });
}
