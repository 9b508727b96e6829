// SPDX-License-Identifier: BSD-3-Clause
// Copyright (C) the ctid authors
// MEX gateway of the recursive DT ARX estimator and its ZOH conversion to
// continuous time (octave/rarx.m, octave/rarxc.m): converts the record and
// one options struct, runs ctid::run_recursive_arx.
//
//   [thm, yhat, thmc, failed, P] = rarx_mex (fname, y, u, opts)
//
// opts fields: na, nb, nk (required), Ts (required), adm 'ff' | 'kf',
// adg (forgetting factor or (na+nb)-square Qn), th0, P0 ([] = defaults),
// lambda (bilinear SVF prefilter cut-off, 0 = none), continuous (convert
// to CT at every step).
#include "ctid/recursive/recursive_arx.hpp"
#include "mex_helpers.hpp"
#include "options_reader.hpp"

namespace {

using ctid::mex::Gateway;

void rarx_gateway(const Gateway& g, int nlhs, mxArray* plhs[], int nrhs,
                  const mxArray* prhs[]) {
  if (nrhs != 4) {
    g.fail("badInput", "the gateway takes (fname, y, u, opts), got " +
                           std::to_string(nrhs) + " arguments");
  }
  if (nlhs > 5) g.fail("badInput", "at most 5 outputs");
  const double* y = g.matrix(prhs[1], "y", -1, 1);
  const long n = static_cast<long>(mxGetM(prhs[1]));
  if (n < 1) g.fail("badInput", "y must not be empty");
  const double* u = g.matrix(prhs[2], "u", n, 1);

  ctid::mex::OptionsReader opt(g, prhs[3]);
  ctid::RecursiveArxConfig<double> config;
  config.na = opt.integer("na");
  config.nb = opt.integer("nb");
  config.nk = opt.integer("nk");
  config.ts = opt.scalar("Ts");
  config.to_continuous = opt.flag("continuous", false);
  config.lambda_prefilter = opt.scalar("lambda", 0.0);
  if (config.na < 1 || config.nb < 1 || config.na > 50 || config.nb > 50) {
    g.fail("badInput", "na and nb must be integers in 1..50");
  }
  const long np = config.na + config.nb;
  const bool kalman =
      opt.choice<bool>("adm", {{"ff", false}, {"kf", true}}, false);
  if (kalman) {
    config.adaptation =
        ctid::KalmanAdaptation<double>(opt.matrix("adg", np, np));
  } else {
    config.adaptation =
        ctid::ForgettingFactorAdaptation<double>(opt.scalar("adg", 1.0));
  }
  config.theta0 = opt.matrix("th0", np, 1);
  config.P0 = opt.matrix("P0", np, np);
  opt.finish();
  g.check(ctid::validate(config));

  plhs[0] = ctid::mex::make_output_matrix(n, np);
  ctid::RecursiveArxOutputs<double> out;
  out.theta = mxGetPr(plhs[0]);
  if (nlhs >= 2) {
    plhs[1] = ctid::mex::make_output_matrix(n, 1);
    out.prediction = mxGetPr(plhs[1]);
  }
  if (nlhs >= 3) {
    plhs[2] = ctid::mex::make_output_matrix(
        n, config.to_continuous ? 2 * config.na : 0);
    if (config.to_continuous) out.theta_ct = mxGetPr(plhs[2]);
  }
  if (nlhs >= 4) {
    plhs[3] = ctid::mex::make_output_matrix(n, config.to_continuous ? 1 : 0);
    if (config.to_continuous) out.conversion_failed = mxGetPr(plhs[3]);
  }
  if (nlhs >= 5) {
    plhs[4] = ctid::mex::make_output_matrix(np, np);
    out.final_P = mxGetPr(plhs[4]);
  }
  long failures = 0;
  g.check(ctid::run_recursive_arx<double>(config, y, u, n, out, &failures));
}

}  // namespace

void mexFunction(int nlhs, mxArray* plhs[], int nrhs, const mxArray* prhs[]) {
  ctid::mex::run_gateway(
      "rarx", {"rarx", "rarxc"}, nrhs, prhs,
      [&](const Gateway& g) { rarx_gateway(g, nlhs, plhs, nrhs, prhs); });
}
