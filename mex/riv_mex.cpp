// SPDX-License-Identifier: BSD-3-Clause
// Copyright (C) the ctid authors
// MEX gateway of the recursive IV estimators rivsvf, rsrivc, clrivsvf and
// clrsrivc (octave/private/contsid_riv.m): reads the record and the options
// struct, runs ctid::run_recursive_iv and returns THM, YH, PSET and INFO.
//
//   [thm, yh, pset, info] = riv_mex (fname, y, u, t, options)
//
// y N-by-1, u N-by-nu, t the sampling interval or the N instants; the
// fields of options are those of the core's recursive_iv_options() table
// (estimator_args.hpp) plus precision 'double' | 'single' and the
// closed-loop signals r1, r2; `riv_mex (fname, "options")` returns the
// table. INFO has the number of estimates refused by the stability
// test, kappa_2(P), prediction errors and innovation scales per sample, and
// with conditional updating kappa_2 of the parallel RLSSVF-FF,
// whether each sample updated the estimates, and the number of resets.
#include <vector>

#include "estimator_args.hpp"

namespace {

using ctid::mex::Gateway;

// run_recursive_iv for S = double or float; the closed-loop signals and
// the conditional-updating outputs are converted for float.
struct RivRun {
  const ctid::ClosedLoopSignals<double>& loop;
  std::size_t n;
  double* monitor_kappa;
  double* updating;
  long* rejections;
  long* resets;

  template <typename S>
  ctid::Status operator()(const ctid::RecursiveIvConfig<S>& config,
                          const ctid::RecordView<S>& record,
                          const ctid::RecursiveOutputs<S>& out) const {
    std::vector<S> r1, r2, kappa, flags;
    ctid::ClosedLoopSignals<S> signals;
    if (loop.r1 != nullptr) {
      r1.assign(loop.r1, loop.r1 + n);
      r2.assign(loop.r2, loop.r2 + n);
      signals.r1 = r1.data();
      signals.r2 = r2.data();
    }
    ctid::AntiWindupOutputs<S> windup;
    if (monitor_kappa != nullptr) {
      kappa.assign(n, S(0));
      flags.assign(n, S(0));
      windup.monitor_kappa = kappa.data();
      windup.updating = flags.data();
    }
    const ctid::Status status = ctid::run_recursive_iv(
        config, record, signals, out, rejections, &windup);
    for (std::size_t k = 0; k < kappa.size(); ++k) {
      monitor_kappa[k] = kappa[k];
      updating[k] = flags[k];
    }
    *resets = windup.resets;
    return status;
  }
};

void riv_gateway(const Gateway& g, int nlhs, mxArray* plhs[], int nrhs,
                 const mxArray* prhs[]) {
  if (ctid::mex::asks_for_options(nrhs, prhs)) {
    plhs[0] =
        ctid::mex::option_table_struct(ctid::recursive_iv_options<double>());
    return;
  }
  if (nrhs != 5) {
    g.fail("badInput",
           "the gateway takes 5 arguments (fname, y, u, t, "
           "options), got " +
               std::to_string(nrhs) + " (call " + g.name() + " instead)");
  }
  if (nlhs > 4) g.fail("badInput", "at most 4 outputs (THM, YH, PSET, INFO)");
  const ctid::RecordView<double> record =
      ctid::mex::read_record(g, prhs[1], prhs[2], prhs[3]);
  ctid::mex::OptionsReader opt(g, prhs[4]);
  ctid::RecursiveIvConfig<double> config;
  ctid::ClosedLoopSignals<double> loop;
  ctid::mex::read_riv_config(g, opt, record, &config, &loop);
  const bool single = ctid::mex::read_single_precision(opt);
  opt.finish();

  const std::size_t n = record.num_samples;
  const std::size_t np = config.orders.num_parameters();
  ctid::RecursiveOutputs<double> out =
      ctid::mex::make_recursive_outputs(nlhs, plhs, n, np);
  ctid::mex::InfoStruct info;
  long rejections = 0;
  long resets = 0;
  RivRun run{loop, n, nullptr, nullptr, &rejections, &resets};
  if (nlhs >= 4) {
    out.kappa = info.add("kappa", n, 1);
    out.error = info.add("error", n, 1);
    out.innovation = info.add("innovation", n, 1);
    out.guard = info.add("covariance_guard", n, 1);
    if (config.antiwindup_gamma != 0) {
      run.monitor_kappa = info.add("kappa_ff", n, 1);
      run.updating = info.add("updating", n, 1);
    }
  }
  g.check(ctid::mex::run_in_precision(single, config, record, out, np, 0, run));
  if (nlhs >= 4) {
    info.add_scalar("stability_rejections", static_cast<double>(rejections));
    if (config.antiwindup_gamma != 0) {
      info.add_scalar("resets", static_cast<double>(resets));
    }
    plhs[3] = info.release();
  }
}

}  // namespace

void mexFunction(int nlhs, mxArray* plhs[], int nrhs, const mxArray* prhs[]) {
  ctid::mex::run_gateway(
      "rsrivc", {"rivsvf", "rsrivc", "clrivsvf", "clrsrivc"}, nrhs, prhs,
      [&](const Gateway& g) { riv_gateway(g, nlhs, plhs, nrhs, prhs); });
}
