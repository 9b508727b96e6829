// SPDX-License-Identifier: BSD-3-Clause
// Copyright (C) the ctid authors
// MEX gateway of the prediction-error estimators (core/include/ctid/
// output_error.hpp), called by octave/private/contsid_pem.m:
//
//   [theta, cov, info] = pem_mex (fname, y, u, t, opts)
//
// y N-by-1; u N-by-nu; t a scalar Ts or the N sampling instants
// (continuous-time output error only). opts fields: model ('oe_ct' |
// 'oe_dt' | 'arx'); output error: nf, nb, nk, delay (one entry per input:
// y = sum_j B_j/F_j u_j; delay in time units, continuous time, default 0),
// estimate_delay (true: the total delay is the last parameter, started from nk
// Ts + delay, kept in [0, delay_max]), cutoff (SVF cut-off of the SRIVC start,
// rad/s; 0 a grid), intersample (0 zoh, 1 foh), theta_init
// ([f; b], or absent for the SRIVC / ARX start), maxiter, tol; arx: na,
// nb, nk (nb, nk one entry per input). info: converged, iterations,
// reason, loss, noise_variance, gradient_norm, damping, start,
// theta_start, simulated (output error) or rows (arx).
#include <algorithm>

#include "ctid/offline/output_error.hpp"
#include "gateway_common.hpp"
#include "options_reader.hpp"

namespace {

using ctid::mex::Gateway;
using ctid::mex::OptionsReader;
using ctid::mex::to_output;

void arx_gateway(const Gateway& g, OptionsReader& opt,
                 const ctid::RecordView<double>& record, int nlhs,
                 mxArray* plhs[]) {
  const int na = opt.integer("na");
  const std::vector<int> nb = opt.integer_vector("nb");
  const std::vector<int> nk = opt.integer_vector("nk");
  opt.finish();
  if (record.instants != nullptr) {
    g.fail("badInput", "ARX needs regularly sampled data");
  }
  ctid::ArxResult<double> r;
  g.check(ctid::arx_least_squares<double>(
      record.y, record.u, record.num_samples,
      static_cast<int>(record.num_inputs), na, nb, nk, &r));
  plhs[0] = to_output(r.theta);
  if (nlhs >= 2) plhs[1] = to_output(r.covariance);
  if (nlhs >= 3) {
    const char* fields[] = {"loss", "noise_variance", "rows"};
    mxArray* info = mxCreateStructMatrix(1, 1, 3, fields);
    mxSetField(info, 0, "loss", mxCreateDoubleScalar(r.loss));
    mxSetField(info, 0, "noise_variance",
               mxCreateDoubleScalar(r.noise_variance));
    mxSetField(info, 0, "rows",
               mxCreateDoubleScalar(static_cast<double>(r.rows)));
    plhs[2] = info;
  }
}

void pem_gateway(const Gateway& g, int nlhs, mxArray* plhs[], int nrhs,
                 const mxArray* prhs[]) {
  if (nrhs != 5) {
    g.fail("badInput",
           "the gateway takes 5 arguments, got " + std::to_string(nrhs));
  }
  if (nlhs > 3) g.fail("badInput", "at most 3 outputs");
  const ctid::RecordView<double> record =
      ctid::mex::read_record(g, prhs[1], prhs[2], prhs[3]);
  OptionsReader opt(g, prhs[4]);
  const std::string model = opt.text("model");
  if (model == "arx") {
    arx_gateway(g, opt, record, nlhs, plhs);
    return;
  }
  if (model != "oe_ct" && model != "oe_dt") {
    g.fail("badOption", "model must be 'oe_ct', 'oe_dt' or 'arx'");
  }
  ctid::OeStructure s;
  s.time =
      model == "oe_ct" ? ctid::OeTime::kContinuous : ctid::OeTime::kDiscrete;
  // One entry per input (a scalar: one input).
  const std::vector<int> nf = opt.integer_vector("nf");
  const std::vector<int> nb = opt.integer_vector("nb");
  const std::vector<int> nk = opt.integer_vector("nk", {0});
  const Eigen::MatrixXd delay = opt.matrix("delay");
  const std::size_t m = record.num_inputs;
  if (nf.size() != m || nb.size() != m || nk.size() != m ||
      (delay.size() != 0 && static_cast<std::size_t>(delay.size()) != m)) {
    g.fail("dimensionMismatch",
           "nf, nb, nk and delay need one entry per input (" +
               std::to_string(m) + ")");
  }
  const int rule = opt.integer("intersample", 0);
  if (rule != 0 && rule != 1) {
    g.fail("badOption", "intersample must be 0 (zoh) or 1 (foh)");
  }
  for (std::size_t j = 0; j < m; ++j) {
    ctid::OeChannel c;
    c.nf = nf[j];
    c.nb = nb[j];
    c.nk = nk[j];
    c.delay = delay.size() != 0 ? delay(j) : 0.0;
    c.rule = rule == 0 ? ctid::InterSample::kZoh : ctid::InterSample::kFoh;
    if (m == 1) {
      s.nf = c.nf;
      s.nb = c.nb;
      s.nk = c.nk;
      s.delay = c.delay;
      s.rule = c.rule;
    } else {
      s.inputs.push_back(c);
    }
  }
  s.estimate_delay = opt.flag("estimate_delay", false);
  s.delay_max = opt.scalar("delay_max", 0);
  ctid::OeSettings<double> settings;
  const Eigen::MatrixXd theta_init = opt.matrix("theta_init");
  if (theta_init.size() > 0) {
    settings.theta_init =
        Eigen::Map<const Eigen::VectorXd>(theta_init.data(), theta_init.size());
  }
  settings.max_iterations = opt.integer("maxiter", 100);
  settings.tolerance = opt.scalar("tol", 1e-8);
  settings.srivc_cutoff = opt.scalar("cutoff", 0);
  opt.finish();
  ctid::OeData<double> data;
  data.y = record.y;
  data.u = record.u;
  data.num_inputs = static_cast<int>(m);
  data.num_samples = record.num_samples;
  data.ts = record.ts;
  data.instants = record.instants;
  ctid::OeResult<double> r;
  const ctid::Status status = ctid::output_error(s, settings, data, &r);
  if (status.code() != ctid::ErrorCode::kNotConverged) g.check(status);
  plhs[0] = to_output(r.theta);
  if (nlhs >= 2) plhs[1] = to_output(r.covariance);
  if (nlhs >= 3) {
    const char* fields[] = {"converged", "iterations",     "reason",
                            "loss",      "noise_variance", "gradient_norm",
                            "damping",   "start",          "theta_start",
                            "simulated"};
    mxArray* info = mxCreateStructMatrix(1, 1, 10, fields);
    mxSetField(info, 0, "converged", mxCreateLogicalScalar(r.converged));
    mxSetField(info, 0, "iterations", mxCreateDoubleScalar(r.iterations));
    mxSetField(info, 0, "reason", mxCreateString(r.reason.c_str()));
    mxSetField(info, 0, "loss", mxCreateDoubleScalar(r.loss));
    mxSetField(info, 0, "noise_variance",
               mxCreateDoubleScalar(r.noise_variance));
    mxSetField(info, 0, "gradient_norm", mxCreateDoubleScalar(r.gradient_norm));
    mxSetField(info, 0, "damping", mxCreateDoubleScalar(r.damping));
    mxSetField(info, 0, "start", mxCreateString(r.start.c_str()));
    mxSetField(info, 0, "theta_start", to_output(r.theta_start));
    mxSetField(info, 0, "simulated", to_output(r.simulated));
    plhs[2] = info;
  }
}

}  // namespace

void mexFunction(int nlhs, mxArray* plhs[], int nrhs, const mxArray* prhs[]) {
  ctid::mex::run_gateway(
      "tfcoe", {"tfcoe", "oe", "tfest", "arx", "delayest"}, nrhs, prhs,
      [&](const Gateway& g) { pem_gateway(g, nlhs, plhs, nrhs, prhs); });
}
