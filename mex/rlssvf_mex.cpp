// SPDX-License-Identifier: BSD-3-Clause
// Copyright (C) the ctid authors
// MEX gateway of rlssvf (octave/rlssvf.m): reads the record and the options
// struct, runs ctid::run_rlssvf and returns THM, YH, PSET and INFO.
//
//   [thm, yh, pset, info] = rlssvf_mex (fname, y, u, t, options)
//
// y N-by-1, u N-by-nu, t the sampling interval or the N instants; the
// fields of options are those of the core's rlssvf_options() table
// (estimator_args.hpp) plus precision 'double' | 'single' (the core
// instantiated for float on a float copy of the data);
// `rlssvf_mex ("rlssvf", "options")` returns the table. YH, PSET
// and INFO (kappa_2(P), the initial-condition coefficients, prediction errors
// and innovation scales per sample) are computed only when requested.
//
//   [info, thm, yh] = rlssvf_mex (fname, "converge", y, u, t, options,
//                                 detector)
//
// An RLSSVF start-up and its convergence (rlssvf_convergence.hpp): y, u,
// t and options as for rlssvf; detector the fields of the core's
// convergence_options() table (blocklength, nblocks, alpha, tol_theta,
// eyfloor, ptol, use_outputerror, use_theta, use_P);
// `rlssvf_mex (fname, "converge", "options")` returns that table. info:
// nblocks (B), Rcrit, ey_ms, y_ms, R, dtheta, theta_index, P_index,
// steady_ey, steady_theta, small_P (B-by-1 each), converged, tsiv, k
// (the first sample at or after tsiv, 1-based; NaN when not converged) and
// settings (the detector's settings used, defaults included); thm, yh the
// RLSSVF run.
#include "ctid/recursive/rlssvf_convergence.hpp"
#include "estimator_args.hpp"

namespace {

using ctid::mex::Gateway;

mxArray* logical_column(const std::vector<bool>& v) {
  mxArray* a = mxCreateLogicalMatrix(v.size(), 1);
  mxLogical* p = mxGetLogicals(a);
  for (std::size_t i = 0; i < v.size(); ++i) p[i] = v[i];
  return a;
}

void converge_gateway(const Gateway& g, int nlhs, mxArray* plhs[], int nrhs,
                      const mxArray* prhs[]) {
  if (nrhs == 3 && mxIsChar(prhs[2])) {
    if (g.text(prhs[2], "the third argument") != "options") {
      g.fail("badInput", "the converge method's table is asked by 'options'");
    }
    plhs[0] = ctid::mex::option_table_struct(ctid::convergence_options());
    return;
  }
  if (nrhs != 7) {
    g.fail("badInput",
           "the converge method takes 7 arguments (fname, 'converge', y, u, "
           "t, options, detector), got " +
               std::to_string(nrhs));
  }
  if (nlhs > 3) g.fail("badInput", "the converge method has 3 outputs");
  const ctid::RecordView<double> record =
      ctid::mex::read_record(g, prhs[2], prhs[3], prhs[4]);
  ctid::RlsSvfConfig<double> config;
  {
    ctid::mex::OptionsReader opt(g, prhs[5]);
    ctid::mex::read_rlssvf_config(g, opt, &config);
    // the start-up is examined in double precision: single precision
    // would not change the estimates the detector reads
    ctid::mex::read_single_precision(opt);
    opt.finish();
  }
  ctid::ConvergenceSettings settings;
  {
    ctid::mex::OptionsReader opt(g, prhs[6]);
    ctid::mex::read_option_table(g, opt, ctid::convergence_options(),
                                 &settings);
    opt.finish();
  }
  ctid::ConvergenceRun<double> run;
  g.check(ctid::rlssvf_convergence(config, record, settings, &run));
  const ctid::ConvergenceReport<double>& report = run.report;
  const char* fields[] = {
      "nblocks", "Rcrit",       "ey_ms",   "y_ms",      "R",
      "dtheta",  "theta_index", "P_index", "steady_ey", "steady_theta",
      "small_P", "converged",   "tsiv",    "k",         "settings"};
  mxArray* info = mxCreateStructMatrix(1, 1, 15, fields);
  using ctid::mex::to_output;
  mxSetField(info, 0, "nblocks",
             mxCreateDoubleScalar(static_cast<double>(report.num_blocks)));
  mxSetField(info, 0, "Rcrit", mxCreateDoubleScalar(report.r_crit));
  mxSetField(info, 0, "ey_ms", to_output(report.ey_ms));
  mxSetField(info, 0, "y_ms", to_output(report.y_ms));
  mxSetField(info, 0, "R", to_output(report.r));
  mxSetField(info, 0, "dtheta", to_output(report.dtheta));
  mxSetField(info, 0, "theta_index", to_output(report.theta_index));
  mxSetField(info, 0, "P_index", to_output(report.p_index));
  mxSetField(info, 0, "steady_ey", logical_column(report.steady_ey));
  mxSetField(info, 0, "steady_theta", logical_column(report.steady_theta));
  mxSetField(info, 0, "small_P", logical_column(report.small_p));
  mxSetField(info, 0, "converged", mxCreateLogicalScalar(report.converged));
  mxSetField(info, 0, "tsiv", mxCreateDoubleScalar(report.tsiv));
  mxSetField(info, 0, "k",
             mxCreateDoubleScalar(report.sample >= 0
                                      ? static_cast<double>(report.sample + 1)
                                      : mxGetNaN()));
  // the settings used, the table's defaults included
  const char* used[] = {"blocklength", "nblocks", "alpha",
                        "tol_theta",   "eyfloor", "ptol"};
  mxArray* given = mxCreateStructMatrix(1, 1, 6, used);
  mxSetField(given, 0, "blocklength",
             mxCreateDoubleScalar(settings.block_length));
  mxSetField(given, 0, "nblocks", mxCreateDoubleScalar(settings.num_blocks));
  mxSetField(given, 0, "alpha", mxCreateDoubleScalar(settings.alpha));
  mxSetField(given, 0, "tol_theta", mxCreateDoubleScalar(settings.tol_theta));
  mxSetField(given, 0, "eyfloor", mxCreateDoubleScalar(settings.ey_floor));
  mxSetField(given, 0, "ptol", mxCreateDoubleScalar(settings.p_tol));
  mxSetField(info, 0, "settings", given);
  plhs[0] = info;
  if (nlhs > 1) plhs[1] = to_output(run.thm);
  if (nlhs > 2) plhs[2] = to_output(run.yh);
}

void rlssvf_gateway(const Gateway& g, int nlhs, mxArray* plhs[], int nrhs,
                    const mxArray* prhs[]) {
  if (ctid::mex::asks_for_options(nrhs, prhs)) {
    plhs[0] = ctid::mex::option_table_struct(ctid::rlssvf_options<double>());
    return;
  }
  if (nrhs >= 2 && mxIsChar(prhs[1])) {
    const std::string method = g.text(prhs[1], "the method");
    if (method != "converge") {
      g.fail("badInput", "unknown method '" + method + "'");
    }
    converge_gateway(g, nlhs, plhs, nrhs, prhs);
    return;
  }
  if (nrhs != 5) {
    g.fail("badInput",
           "the gateway takes 5 arguments (fname, y, u, t, "
           "options), got " +
               std::to_string(nrhs) + " (call rlssvf instead)");
  }
  if (nlhs > 4) g.fail("badInput", "at most 4 outputs (THM, YH, PSET, INFO)");
  const ctid::RecordView<double> record =
      ctid::mex::read_record(g, prhs[1], prhs[2], prhs[3]);
  ctid::mex::OptionsReader opt(g, prhs[4]);
  ctid::RlsSvfConfig<double> config;
  ctid::mex::read_rlssvf_config(g, opt, &config);
  const bool single = ctid::mex::read_single_precision(opt);
  opt.finish();
  g.check(ctid::validate_record(record, config.orders));

  const std::size_t n = record.num_samples;
  const std::size_t np = config.orders.num_parameters();
  const std::size_t nextra = ctid::num_estimated(config) - np;
  ctid::RecursiveOutputs<double> out =
      ctid::mex::make_recursive_outputs(nlhs, plhs, n, np);
  ctid::mex::InfoStruct info;
  if (nlhs >= 4) {
    out.kappa = info.add("kappa", n, 1);
    out.error = info.add("error", n, 1);
    out.innovation = info.add("innovation", n, 1);
    out.guard = info.add("covariance_guard", n, 1);
    if (nextra > 0) out.extra = info.add("ic", n, nextra);
  }
  g.check(ctid::mex::run_in_precision(
      single, config, record, out, np, nextra,
      [](const auto& c, const auto& r, const auto& o) {
        return ctid::run_rlssvf(c, r, o);
      }));
  if (nlhs >= 4) plhs[3] = info.release();
}

}  // namespace

void mexFunction(int nlhs, mxArray* plhs[], int nrhs, const mxArray* prhs[]) {
  ctid::mex::run_gateway(
      "rlssvf", {"rlssvf"}, nrhs, prhs,
      [&](const Gateway& g) { rlssvf_gateway(g, nlhs, plhs, nrhs, prhs); });
}
