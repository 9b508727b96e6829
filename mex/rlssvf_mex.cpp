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
#include "estimator_args.hpp"

namespace {

using ctid::mex::Gateway;

void rlssvf_gateway(const Gateway& g, int nlhs, mxArray* plhs[], int nrhs,
                    const mxArray* prhs[]) {
  if (ctid::mex::asks_for_options(nrhs, prhs)) {
    plhs[0] = ctid::mex::option_table_struct(ctid::rlssvf_options<double>());
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
