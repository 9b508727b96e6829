// SPDX-License-Identifier: BSD-3-Clause
// Copyright (C) the ctid authors
// MEX gateway of the GPMF state-space estimators sslsgpmf, ssivgpmf,
// ssbcgpmf and sidgpmf (core: ctid/offline/gpmf_state_space.hpp):
//
//   [A, B, C, D, sv] = gpmf_mex (fname, y, u, t, options)
//
// y N-by-p, u N-by-m, t the sampling interval or the N instants. Fields of
// options: method 'ls' | 'iv' | 'bc' | 'sid'; n0 (first sample used,
// default 1); intersample 'zoh' | 'foh' (of u, default 'zoh'); for 'ls',
// 'iv' and 'bc' nni (p observability indices) and lambda (p Poisson filter
// parameters); for 'bc' root (p-by-r, the artificial filter roots of each
// output equation; sv returns the p estimated noise variances); for
// 'sid' i, j, lambda (scalar) and n (0: chosen from the singular values,
// returned in sv; empty for 'ls' and 'iv').
#include <vector>

#include "ctid/offline/gpmf_state_space.hpp"
#include "gateway_common.hpp"

namespace {

using ctid::mex::Gateway;

void gpmf_gateway(const Gateway& g, int nlhs, mxArray* plhs[], int nrhs,
                  const mxArray* prhs[]) {
  if (nrhs != 5) {
    g.fail("badInput",
           "the gateway takes 5 arguments (fname, y, u, t, options), got " +
               std::to_string(nrhs) + " (call " + g.name() + " instead)");
  }
  if (nlhs > 5) g.fail("badInput", "at most 5 outputs");
  ctid::MultiRecordView<double> record;
  g.require_real_double(prhs[1], "y");
  g.require_real_double(prhs[2], "u");
  const long n = static_cast<long>(mxGetM(prhs[1]));
  if (n < 1 || mxGetN(prhs[1]) < 1) g.fail("badInput", "y must not be empty");
  record.y = g.matrix(prhs[1], "y", n, -1);
  record.u = g.matrix(prhs[2], "u", n, -1);
  record.num_samples = n;
  record.num_outputs = static_cast<Eigen::Index>(mxGetN(prhs[1]));
  record.num_inputs = static_cast<Eigen::Index>(mxGetN(prhs[2]));
  g.require_real_double(prhs[3], "Ts");
  if (mxGetNumberOfElements(prhs[3]) == 1) {
    record.ts = g.scalar(prhs[3], "Ts");
  } else {
    record.instants = g.matrix(prhs[3], "the sampling instants", n, 1);
  }
  ctid::mex::OptionsReader opt(g, prhs[4]);
  enum class Method { kLs, kIv, kBc, kSid };
  const Method method = opt.choice<Method>("method",
                                           {{"ls", Method::kLs},
                                            {"iv", Method::kIv},
                                            {"bc", Method::kBc},
                                            {"sid", Method::kSid}},
                                           Method::kLs);
  if (!opt.has("method")) g.fail("badOption", "option 'method' is missing");
  record.u_intersample =
      ctid::mex::read_intersample(opt, ctid::InterSample::kZoh);
  if (method == Method::kSid) {
    ctid::SubspaceGpmfSettings sid;
    sid.block_rows = opt.integer("i");
    sid.filter_order = opt.integer("j");
    sid.lambda = opt.scalar("lambda");
    sid.order = opt.integer("n", 0);
    sid.first_sample = opt.integer("n0", 1) - 1;
    opt.finish();
    ctid::SubspaceGpmfEstimate<double> estimate;
    g.check(ctid::sid_gpmf(record, sid, &estimate));
    plhs[0] = ctid::mex::to_output(estimate.model.A);
    if (nlhs >= 2) plhs[1] = ctid::mex::to_output(estimate.model.B);
    if (nlhs >= 3) plhs[2] = ctid::mex::to_output(estimate.model.C);
    if (nlhs >= 4) plhs[3] = ctid::mex::to_output(estimate.model.D);
    if (nlhs >= 5) plhs[4] = ctid::mex::to_output(estimate.singular_values);
    return;
  }
  const bool iv = method == Method::kIv;
  ctid::GpmfSettings<double> settings;
  settings.observability_indices = opt.integer_vector("nni");
  const Eigen::MatrixXd lambda = opt.required_matrix("lambda");
  settings.lambda.assign(lambda.data(), lambda.data() + lambda.size());
  settings.first_sample = opt.integer("n0", 1) - 1;
  std::vector<std::vector<double>> roots;
  if (method == Method::kBc) {
    const Eigen::MatrixXd root = opt.required_matrix("root");
    for (Eigen::Index i = 0; i < root.rows(); ++i) {
      roots.emplace_back();
      for (Eigen::Index k = 0; k < root.cols(); ++k) {
        roots.back().push_back(root(i, k));
      }
    }
  }
  opt.finish();
  ctid::StateSpaceEstimate<double> estimate;
  Eigen::VectorXd variance(0);
  if (method == Method::kBc) {
    g.check(ctid::ss_bc_gpmf(record, settings, roots, &estimate, &variance));
  } else {
    g.check(iv ? ctid::ss_iv_gpmf(record, settings, &estimate)
               : ctid::ss_ls_gpmf(record, settings, &estimate));
  }
  plhs[0] = ctid::mex::to_output(estimate.A);
  if (nlhs >= 2) plhs[1] = ctid::mex::to_output(estimate.B);
  if (nlhs >= 3) plhs[2] = ctid::mex::to_output(estimate.C);
  if (nlhs >= 4) plhs[3] = ctid::mex::to_output(estimate.D);
  if (nlhs >= 5) plhs[4] = ctid::mex::to_output(variance);
}

}  // namespace

void mexFunction(int nlhs, mxArray* plhs[], int nrhs, const mxArray* prhs[]) {
  ctid::mex::run_gateway(
      "sslsgpmf", {"sslsgpmf", "ssivgpmf", "ssbcgpmf", "sidgpmf"}, nrhs, prhs,
      [&](const Gateway& g) { gpmf_gateway(g, nlhs, plhs, nrhs, prhs); });
}
