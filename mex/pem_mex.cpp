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
// rad/s; 0 a grid), intersample ('zoh' or 'foh'), theta_init
// ([f; b], or absent for the SRIVC / ARX start), maxiter, tol: the options
// of output_error_options.hpp, read from that table with its defaults;
// starts (one column per start), default_start, delay_min, integrate: the
// minimisation from several starts of output_error_starts.hpp, the lowest
// loss kept. `pem_mex (fname, "options")` returns the table. arx: na, nb,
// nk (nb, nk one entry per input). info: converged, iterations, reason,
// loss, noise_variance, gradient_norm, damping, start, theta_start,
// simulated, delay_estimated, delay (the model's delay, one input),
// free_parameters (output error) or rows, prediction_error (arx).
//
//   start = pem_mex (fname, "reduce", f, b, spec)
//
// the start [f; b; td] of output_error_starts.hpp's reduced_start from the
// over-parametrised model b/(p^n + f_1 p^(n-1) + ..) e^(-td p) (f without
// its leading 1), [] when the reduced model is unstable; spec fields nf,
// nb, band ([w_lo w_hi], rad/s), td, search_delay, delay_max.
#include <algorithm>

#include "ctid/offline/output_error.hpp"
#include "ctid/offline/output_error_options.hpp"
#include "ctid/offline/output_error_starts.hpp"
#include "estimator_args.hpp"
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
    const char* fields[] = {"loss", "noise_variance", "rows",
                            "prediction_error"};
    mxArray* info = mxCreateStructMatrix(1, 1, 4, fields);
    mxSetField(info, 0, "loss", mxCreateDoubleScalar(r.loss));
    mxSetField(info, 0, "noise_variance",
               mxCreateDoubleScalar(r.noise_variance));
    mxSetField(info, 0, "rows",
               mxCreateDoubleScalar(static_cast<double>(r.rows)));
    mxSetField(info, 0, "prediction_error", to_output(r.prediction_error));
    plhs[2] = info;
  }
}

void reduce_gateway(const Gateway& g, int nlhs, mxArray* plhs[], int nrhs,
                    const mxArray* prhs[]) {
  if (nrhs != 5) {
    g.fail("badInput",
           "the reduce method takes 5 arguments, got " + std::to_string(nrhs));
  }
  if (nlhs > 1) g.fail("badInput", "at most 1 output");
  const Eigen::MatrixXd f = g.eigen_matrix(prhs[2], "f", -1, -1);
  const Eigen::MatrixXd b = g.eigen_matrix(prhs[3], "b", -1, -1);
  OptionsReader opt(g, prhs[4]);
  const int nf = opt.integer("nf");
  const int nb = opt.integer("nb");
  const Eigen::MatrixXd band = opt.matrix("band");
  if (band.size() != 2)
    g.fail("badOption", "option 'band' must be [w_lo w_hi]");
  const double td = opt.scalar("td", 0.0);
  const bool search = opt.flag("search_delay", false);
  const double delay_max = opt.scalar("delay_max", 0.0);
  opt.finish();
  const Eigen::VectorXd fv =
      Eigen::Map<const Eigen::VectorXd>(f.data(), f.size());
  const Eigen::VectorXd bv =
      Eigen::Map<const Eigen::VectorXd>(b.data(), b.size());
  Eigen::VectorXd start;
  g.check(ctid::reduced_start<double>(fv, bv, td, nf, nb, band(0), band(1),
                                      search, delay_max, &start));
  plhs[0] = to_output(start);
}

void pem_gateway(const Gateway& g, int nlhs, mxArray* plhs[], int nrhs,
                 const mxArray* prhs[]) {
  if (nrhs >= 2 && mxIsChar(prhs[1]) &&
      !ctid::mex::asks_for_options(nrhs, prhs)) {
    char word[8] = {0};
    if (mxGetString(prhs[1], word, sizeof word) != 0 ||
        std::string(word) != "reduce") {
      g.fail("badInput", "the only methods are 'options' and 'reduce'");
    }
    reduce_gateway(g, nlhs, plhs, nrhs, prhs);
    return;
  }
  if (ctid::mex::asks_for_options(nrhs, prhs)) {
    plhs[0] =
        ctid::mex::option_table_struct(ctid::output_error_options<double>());
    return;
  }
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
  ctid::OeConfig<double> config;
  config.time =
      model == "oe_ct" ? ctid::OeTime::kContinuous : ctid::OeTime::kDiscrete;
  ctid::mex::read_option_table(g, opt, ctid::output_error_options<double>(),
                               &config);
  opt.finish();
  const std::size_t m = record.num_inputs;
  ctid::OeStructure s;
  g.check(ctid::oe_structure(config, m, &s));
  const ctid::OeSettings<double>& settings = config.settings;
  ctid::OeData<double> data;
  data.y = record.y;
  data.u = record.u;
  data.num_inputs = static_cast<int>(m);
  data.num_samples = record.num_samples;
  data.ts = record.ts;
  data.instants = record.instants;
  ctid::OeStartsResult<double> outcome;
  ctid::Status status;
  if (config.from_starts()) {
    status = ctid::output_error_from_starts(s, settings, config.starts, data,
                                            &outcome);
  } else {
    status = ctid::output_error(s, settings, data, &outcome.best);
    const ctid::OeResult<double>& b = outcome.best;
    outcome.delay_estimated = s.estimate_delay;
    outcome.delay = s.estimate_delay && b.theta.size() > 0
                        ? b.theta(b.theta.size() - 1)
                        : s.delay;
    outcome.free_parameters = static_cast<int>(b.theta.size());
  }
  if (status.code() != ctid::ErrorCode::kNotConverged) g.check(status);
  const ctid::OeResult<double>& r = outcome.best;
  plhs[0] = to_output(r.theta);
  if (nlhs >= 2) plhs[1] = to_output(r.covariance);
  if (nlhs >= 3) {
    const char* fields[] = {
        "converged",      "iterations",    "reason",          "loss",
        "noise_variance", "gradient_norm", "damping",         "start",
        "theta_start",    "simulated",     "delay_estimated", "delay",
        "free_parameters"};
    mxArray* info = mxCreateStructMatrix(1, 1, 13, fields);
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
    mxSetField(info, 0, "delay_estimated",
               mxCreateLogicalScalar(outcome.delay_estimated));
    mxSetField(info, 0, "delay", mxCreateDoubleScalar(outcome.delay));
    mxSetField(info, 0, "free_parameters",
               mxCreateDoubleScalar(outcome.free_parameters));
    plhs[2] = info;
  }
}

}  // namespace

void mexFunction(int nlhs, mxArray* plhs[], int nrhs, const mxArray* prhs[]) {
  ctid::mex::run_gateway(
      "tfcoe", {"tfcoe", "oe", "tfest", "arx", "delayest"}, nrhs, prhs,
      [&](const Gateway& g) { pem_gateway(g, nlhs, plhs, nrhs, prhs); });
}
