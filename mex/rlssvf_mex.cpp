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
//   info = rlssvf_mex (fname, "converge", t, y, yh, thm, trP, options)
//
// The convergence detector of an RLSSVF start-up (convergence_detector.hpp):
// t the N instants from 0, y and yh N-by-1, thm N-by-np, trP N-by-1 (trace
// P / trace P0) or []; options fields blocklength, nblocks, alpha,
// tol_theta, eyfloor, ptol, use_outputerror, use_theta, use_P. info: nblocks
// (B), Rcrit, ey_ms, y_ms, R, dtheta, theta_index, P_index, steady_ey,
// steady_theta, small_P (B-by-1 each), converged, tsiv and k (the first
// sample at or after tsiv, 1-based; NaN when not converged).
#include "ctid/recursive/convergence_detector.hpp"
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
  if (nrhs != 8) {
    g.fail("badInput",
           "the converge method takes 8 arguments (fname, 'converge', t, "
           "y, yh, thm, trP, options), got " +
               std::to_string(nrhs));
  }
  if (nlhs > 1) g.fail("badInput", "the converge method has 1 output");
  g.require_real_double(prhs[5], "thm");
  const long n = static_cast<long>(mxGetM(prhs[5]));
  // (a diverging start may leave non-finite estimates: the detector
  // reads them as an infinite change)
  const double* thm = g.matrix(prhs[5], "thm", n, -1, false);
  const Eigen::MatrixXd theta = Eigen::Map<const Eigen::MatrixXd>(
      thm, n, static_cast<Eigen::Index>(mxGetN(prhs[5])));
  const double* t = g.matrix(prhs[2], "t", n, 1);
  const double* y = g.matrix(prhs[3], "y", n, 1);
  const double* yh = g.matrix(prhs[4], "yh", n, 1, false);
  const double* trace_ratio = nullptr;
  if (mxGetNumberOfElements(prhs[6]) != 0) {
    trace_ratio = g.matrix(prhs[6], "trP", n, 1, false);
  }
  ctid::mex::OptionsReader opt(g, prhs[7]);
  ctid::ConvergenceSettings settings;
  settings.block_length = opt.scalar("blocklength");
  settings.num_blocks = opt.integer("nblocks", settings.num_blocks);
  settings.alpha = opt.scalar("alpha", settings.alpha);
  settings.tol_theta = opt.scalar("tol_theta", settings.tol_theta);
  settings.ey_floor = opt.scalar("eyfloor", settings.ey_floor);
  settings.p_tol = opt.scalar("ptol", settings.p_tol);
  settings.use_output_error = opt.flag("use_outputerror", true);
  settings.use_theta = opt.flag("use_theta", true);
  settings.use_p = opt.flag("use_P", true);
  opt.finish();
  ctid::ConvergenceReport<double> report;
  g.check(
      ctid::detect_convergence(t, y, yh, theta, trace_ratio, settings, report));
  const char* fields[] = {
      "nblocks", "Rcrit",       "ey_ms",   "y_ms",      "R",
      "dtheta",  "theta_index", "P_index", "steady_ey", "steady_theta",
      "small_P", "converged",   "tsiv",    "k"};
  mxArray* info = mxCreateStructMatrix(1, 1, 14, fields);
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
  plhs[0] = info;
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
