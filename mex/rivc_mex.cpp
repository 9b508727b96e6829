// SPDX-License-Identifier: BSD-3-Clause
// Copyright (C) the ctid authors
// MEX gateway of the Box-Jenkins refined IV (core/include/ctid/
// refined_iv_bj.hpp), called by rivc.m, tfrivc.m, clrivc.m, cl2srivc.m:
//
//   [theta, cov, info] = rivc_mex (fname, y, u, Ts, r, opts)
//
// y N-by-1, u N-by-m (m > 1: MISO rivc, method 'rivc' in open loop), Ts
// the sampling interval (regular data), r the reference of a closed loop:
// the setpoint (N-by-1) or [r1 r] (N-by-2, r1 at the plant input: u = r1
// + C (r - y); cl2srivc: N-by-1), or []. opts: the options of
// rivc_options() (core/include/ctid/offline/refined_iv_options.hpp), read
// from that table with its defaults and checked by its validate(), every
// bad value a bad option; `rivc_mex (fname, "options")` returns the table:
//   method  'rivc' (default; with controller_num/_den: CLRIVC),
//           'cl2srivc' (two-stage SRIVC: u on r, then y on u_hat) or
//           'arma' (the ARMA estimator alone on y: nd, nc).
//   nb, nc, nd, nf, nk (nb, nf, nk: one entry per input), delay (continuous,
//   time units), intersample (0 zoh, 1 foh), tol, maxiter, theta_init ([f b]),
//   cutoffs, max_starts (the SRIVC start), arma_maxiter, arma_method ('pem' or
//   'ivarma': the noise model's estimator), controller_num,
//   controller_den (descending powers of p); cl2srivc: cl_nb, cl_nf, cl_nk,
//   cl_theta_init (stage 1's start; theta_init starts stage 2).
// info: converged, iterations, reason, C, D (q^-1), noise_variance (of e),
// noise_covariance ([d c]), simulation_variance, simulated, condition,
// start_theta; cl2srivc: cl_theta, cl_covariance, u_hat, stage2_covariance
// (stage 2's SRIVC covariance; cov is the two-stage estimator's),
// covariance_lags.
#include <algorithm>

#include "ctid/offline/refined_iv_bj.hpp"
#include "ctid/offline/refined_iv_options.hpp"
#include "estimator_args.hpp"
#include "gateway_common.hpp"
#include "options_reader.hpp"
#include "rivc_info.hpp"

namespace {

using ctid::mex::Gateway;
using ctid::mex::OptionsReader;
using ctid::mex::to_output;

void set_info(mxArray* info, const char* name, mxArray* value) {
  mxSetField(info, 0, name, value);
}

void rivc_gateway(const Gateway& g, int nlhs, mxArray* plhs[], int nrhs,
                  const mxArray* prhs[]) {
  if (ctid::mex::asks_for_options(nrhs, prhs)) {
    plhs[0] = ctid::mex::option_table_struct(ctid::rivc_options<double>());
    return;
  }
  if (nrhs != 6) {
    g.fail("badInput",
           "the gateway takes 6 arguments, got " + std::to_string(nrhs));
  }
  if (nlhs > 3) g.fail("badInput", "at most 3 outputs");
  const ctid::RecordView<double> record =
      ctid::mex::read_record(g, prhs[1], prhs[2], prhs[3]);
  const long n = record.num_samples;
  const int num_inputs = static_cast<int>(record.num_inputs);
  if (num_inputs < 1) g.fail("badInput", "u needs at least one column");
  if (record.instants != nullptr) {
    g.fail("badInput", "regularly sampled data only (a scalar Ts)");
  }
  OptionsReader opt(g, prhs[5]);
  ctid::RivcConfig<double> config;
  ctid::mex::read_option_table(g, opt, ctid::rivc_options<double>(), &config,
                               "badOption");
  opt.finish();
  g.check(ctid::validate(config));
  const ctid::RivcMethod method = config.method;
  // nb, nf, nk: one entry per input (MISO rivc); scalars for one input.
  const std::vector<int>& nb_each = config.nb;
  const std::vector<int>& nf_each = config.nf;
  const std::vector<int>& nk_each = config.nk;
  if (static_cast<int>(nb_each.size()) != num_inputs ||
      static_cast<int>(nf_each.size()) != num_inputs ||
      static_cast<int>(nk_each.size()) != num_inputs) {
    g.fail("dimensionMismatch", "nb, nf and nk need one entry per input (" +
                                    std::to_string(num_inputs) + ")");
  }
  ctid::RivcProblem<double> problem = config.problem;
  problem.nb = nb_each[0];
  problem.nf = nf_each[0];
  problem.nk = nk_each[0];
  ctid::RivcSettings<double> settings = config.settings;
  settings.start.tolerance = settings.tolerance;
  settings.start.max_iterations = method == ctid::RivcMethod::kCl2srivc
                                      ? settings.max_iterations
                                      : std::max(settings.max_iterations, 30);
  if (num_inputs > 1 && (method != ctid::RivcMethod::kRivc ||
                         problem.closed_loop() || problem.delay != 0)) {
    g.fail("notSupported",
           "several inputs: open-loop rivc without a fractional delay only");
  }

  mxArray* info =
      ctid::mex::make_rivc_info({"cl_theta", "cl_covariance", "u_hat",
                                 "stage2_covariance", "covariance_lags"});
  ctid::Vector<double> theta;
  ctid::Matrix<double> cov;

  if (method == ctid::RivcMethod::kArma) {
    ctid::ArmaResult<double> arma;
    g.check(ctid::arma_estimate<double>(record.y, n, problem.nd, problem.nc,
                                        settings.arma, &arma));
    theta.resize(problem.nd + problem.nc);
    theta << arma.d.tail(problem.nd), arma.c.tail(problem.nc);
    cov = arma.covariance;
    set_info(info, "converged", mxCreateLogicalScalar(arma.converged));
    set_info(info, "iterations", mxCreateDoubleScalar(arma.iterations));
    set_info(info, "C", to_output(arma.c.transpose()));
    set_info(info, "D", to_output(arma.d.transpose()));
    set_info(info, "noise_variance",
             mxCreateDoubleScalar(arma.innovation_variance));
  } else if (method == ctid::RivcMethod::kCl2srivc) {
    if (mxIsEmpty(prhs[4])) g.fail("badInput", "cl2srivc needs r");
    const double* r = g.matrix(prhs[4], "the reference r", n, 1);
    ctid::RivProblem<double> plant, loop;
    plant.nf = {problem.nf};
    ctid::RivChannel c;
    c.nb = problem.nb;
    c.nk = problem.nk;
    c.rule = problem.u_rule;
    plant.channels.push_back(c);
    loop.nf = {config.cl_nf};
    ctid::RivChannel cl;
    cl.nb = config.cl_nb;
    cl.nk = config.cl_nk;
    loop.channels.push_back(cl);
    ctid::Cl2srivcResult<double> res;
    ctid::RivSettings<double> stage_settings = settings.start;
    stage_settings.theta_init = settings.theta_init;
    const ctid::Status status =
        ctid::cl2srivc<double>(plant, loop, stage_settings, record.y, record.u,
                               r, n, record.ts, &res, config.cl_theta_init);
    if (status.code() != ctid::ErrorCode::kNotConverged) g.check(status);
    theta = res.plant.theta;
    cov = res.covariance.size() > 0 ? res.covariance : res.plant.covariance;
    set_info(info, "stage2_covariance", to_output(res.plant.covariance));
    set_info(info, "covariance_lags",
             mxCreateDoubleScalar(res.covariance_lags));
    set_info(info, "converged",
             mxCreateLogicalScalar(res.plant.converged &&
                                   res.sensitivity.converged));
    set_info(info, "iterations", mxCreateDoubleScalar(res.plant.iterations));
    set_info(info, "reason",
             mxCreateString(status.ok() ? res.plant.reason.c_str()
                                        : status.message().c_str()));
    set_info(info, "noise_variance",
             mxCreateDoubleScalar(res.plant.noise_variance));
    set_info(info, "simulation_variance",
             mxCreateDoubleScalar(res.plant.noise_variance));
    set_info(info, "simulated", to_output(res.plant.simulated));
    set_info(info, "condition", mxCreateDoubleScalar(res.plant.condition));
    set_info(info, "cl_theta", to_output(res.sensitivity.theta));
    set_info(info, "cl_covariance", to_output(res.sensitivity.covariance));
    set_info(info, "u_hat", to_output(res.sensitivity.simulated));
  } else {
    if (problem.closed_loop()) {
      if (problem.controller_den.size() == 0) {
        g.fail("badOption", "controller_num needs controller_den");
      }
      // r (N-by-1, the setpoint) or [r1 r] (N-by-2, r1 at the plant input)
      if (mxGetN(prhs[4]) == 2) {
        const double* r = g.matrix(prhs[4], "[r1 r]", n, 2);
        problem.r1 = r;
        problem.reference = r + n;
      } else {
        problem.reference = g.matrix(prhs[4], "the reference r", n, 1);
      }
    } else if (!mxIsEmpty(prhs[4])) {
      g.fail("badInput", "a reference r needs a controller");
    }
    ctid::RivcResult<double> res;
    ctid::Status status;
    if (num_inputs > 1) {
      ctid::RivcMisoProblem<double> miso;
      for (int i = 0; i < num_inputs; ++i) {
        miso.inputs.push_back({nb_each[i], nf_each[i], nk_each[i]});
      }
      miso.nc = problem.nc;
      miso.nd = problem.nd;
      miso.u_rule = problem.u_rule;
      const ctid::RivcMisoData<double> data{record.y, record.u, n, record.ts};
      status = ctid::rivc_miso<double>(miso, settings, data, &res);
    } else {
      const ctid::RivcData<double> data{record.y, record.u, n, record.ts};
      status = ctid::rivc<double>(problem, settings, data, &res);
    }
    if (status.code() != ctid::ErrorCode::kNotConverged) g.check(status);
    theta = res.theta;
    cov = res.covariance;
    ctid::mex::set_rivc_info(info, res);
  }
  plhs[0] = to_output(theta);
  if (nlhs >= 2) plhs[1] = to_output(cov);
  if (nlhs >= 3) {
    plhs[2] = info;
  } else {
    mxDestroyArray(info);
  }
}

}  // namespace

void mexFunction(int nlhs, mxArray* plhs[], int nrhs, const mxArray* prhs[]) {
  ctid::mex::run_gateway(
      "rivc", {"rivc", "tfrivc", "clrivc", "cl2srivc"}, nrhs, prhs,
      [&](const Gateway& g) { rivc_gateway(g, nlhs, plhs, nrhs, prhs); });
}
