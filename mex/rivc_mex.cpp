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
// + C (r - y); cl2srivc: N-by-1), or []. opts fields:
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
#include "gateway_common.hpp"
#include "options_reader.hpp"

namespace {

using ctid::mex::Gateway;
using ctid::mex::intersample_rule;
using ctid::mex::OptionsReader;
using ctid::mex::to_output;

enum class Method { kRivc, kCl2srivc, kArma };

void set_info(mxArray* info, const char* name, mxArray* value) {
  mxSetField(info, 0, name, value);
}

void rivc_gateway(const Gateway& g, int nlhs, mxArray* plhs[], int nrhs,
                  const mxArray* prhs[]) {
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
  const Method method = opt.choice<Method>("method",
                                           {{"rivc", Method::kRivc},
                                            {"cl2srivc", Method::kCl2srivc},
                                            {"arma", Method::kArma}},
                                           Method::kRivc);
  ctid::RivcProblem<double> problem;
  ctid::RivcSettings<double> settings;
  // nb, nf, nk: one entry per input (MISO rivc); scalars for one input.
  const std::vector<int> nb_each = opt.integer_vector("nb", {1});
  problem.nc = opt.integer("nc", 0);
  problem.nd = opt.integer("nd", 0);
  const std::vector<int> nf_each = opt.integer_vector("nf", {1});
  const std::vector<int> nk_each = opt.integer_vector("nk", {0});
  if (static_cast<int>(nb_each.size()) != num_inputs ||
      static_cast<int>(nf_each.size()) != num_inputs ||
      static_cast<int>(nk_each.size()) != num_inputs) {
    g.fail("dimensionMismatch", "nb, nf and nk need one entry per input (" +
                                    std::to_string(num_inputs) + ")");
  }
  problem.nb = nb_each[0];
  problem.nf = nf_each[0];
  problem.nk = nk_each[0];
  problem.delay = opt.scalar("delay", 0);
  problem.u_rule = intersample_rule(g, opt.integer("intersample", 0));
  settings.tolerance = opt.scalar("tol", 1e-6);
  settings.max_iterations = opt.integer("maxiter", 30);
  const Eigen::MatrixXd theta_init = opt.matrix("theta_init");
  if (theta_init.size() > 0) settings.theta_init = theta_init.reshaped();
  const Eigen::MatrixXd cutoffs = opt.matrix("cutoffs");
  settings.start.cutoffs.assign(cutoffs.data(),
                                cutoffs.data() + cutoffs.size());
  settings.start.max_starts = opt.integer("max_starts", 3);
  settings.start.tolerance = settings.tolerance;
  settings.start.max_iterations = std::max(settings.max_iterations, 30);
  settings.arma.max_iterations = opt.integer("arma_maxiter", 50);
  settings.arma.method = opt.choice<ctid::ArmaMethod>(
      "arma_method",
      {{"pem", ctid::ArmaMethod::kPem}, {"ivarma", ctid::ArmaMethod::kIvarma}},
      ctid::ArmaMethod::kPem);
  const Eigen::MatrixXd cnum = opt.matrix("controller_num");
  const Eigen::MatrixXd cden = opt.matrix("controller_den");
  const int cl_nb = opt.integer("cl_nb", 1);
  const int cl_nf = opt.integer("cl_nf", 1);
  const int cl_nk = opt.integer("cl_nk", 0);
  const Eigen::MatrixXd cl_theta_init = opt.matrix("cl_theta_init");
  opt.finish();
  if (method == Method::kCl2srivc) {
    settings.start.max_iterations = settings.max_iterations;
  }
  if (num_inputs > 1 &&
      (method != Method::kRivc || cnum.size() > 0 || problem.delay != 0)) {
    g.fail("notSupported",
           "several inputs: open-loop rivc without a fractional delay only");
  }
  if (settings.max_iterations < 1 || settings.max_iterations > 100000 ||
      settings.arma.max_iterations < 0 ||
      settings.arma.max_iterations > 100000 || settings.start.max_starts < 1 ||
      settings.start.max_starts > 100) {
    g.fail("badOption",
           "maxiter must be in 1..1e5, arma_maxiter in 0..1e5 and max_starts "
           "in 1..100");
  }

  const char* fields[] = {"converged",
                          "iterations",
                          "reason",
                          "C",
                          "D",
                          "noise_variance",
                          "noise_covariance",
                          "simulation_variance",
                          "simulated",
                          "condition",
                          "start_theta",
                          "cl_theta",
                          "cl_covariance",
                          "u_hat",
                          "stage2_covariance",
                          "covariance_lags"};
  mxArray* info = mxCreateStructMatrix(1, 1, 16, fields);
  ctid::Vector<double> theta;
  ctid::Matrix<double> cov;

  if (method == Method::kArma) {
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
  } else if (method == Method::kCl2srivc) {
    if (mxIsEmpty(prhs[4])) g.fail("badInput", "cl2srivc needs r");
    const double* r = g.matrix(prhs[4], "the reference r", n, 1);
    ctid::RivProblem<double> plant, loop;
    plant.nf = {problem.nf};
    ctid::RivChannel c;
    c.nb = problem.nb;
    c.nk = problem.nk;
    c.rule = problem.u_rule;
    plant.channels.push_back(c);
    loop.nf = {cl_nf};
    ctid::RivChannel cl;
    cl.nb = cl_nb;
    cl.nk = cl_nk;
    loop.channels.push_back(cl);
    ctid::Cl2srivcResult<double> res;
    ctid::RivSettings<double> stage_settings = settings.start;
    stage_settings.theta_init = settings.theta_init;
    ctid::Vector<double> loop_start;
    if (cl_theta_init.size() > 0) loop_start = cl_theta_init.reshaped();
    const ctid::Status status =
        ctid::cl2srivc<double>(plant, loop, stage_settings, record.y, record.u,
                               r, n, record.ts, &res, loop_start);
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
    if (cnum.size() > 0) {
      if (cden.size() == 0) {
        g.fail("badOption", "controller_num needs controller_den");
      }
      problem.controller_num = cnum.reshaped();
      problem.controller_den = cden.reshaped();
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
    set_info(info, "converged", mxCreateLogicalScalar(res.converged));
    set_info(info, "iterations", mxCreateDoubleScalar(res.iterations));
    set_info(info, "reason", mxCreateString(res.reason.c_str()));
    set_info(info, "C", to_output(res.noise.c.transpose()));
    set_info(info, "D", to_output(res.noise.d.transpose()));
    set_info(info, "noise_variance",
             mxCreateDoubleScalar(res.noise.innovation_variance));
    set_info(info, "noise_covariance", to_output(res.noise.covariance));
    set_info(info, "simulation_variance",
             mxCreateDoubleScalar(res.simulation_variance));
    set_info(info, "simulated", to_output(res.simulated));
    set_info(info, "condition", mxCreateDoubleScalar(res.condition));
    set_info(info, "start_theta", to_output(res.start_theta));
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
