// SPDX-License-Identifier: BSD-3-Clause
// Copyright (C) the ctid authors
// MEX gateway of the electronic throttle of thesis sec. 4.2 (octave/
// throttlesim.m and octave/throttleid.m):
//
//   [u, i, phi, phi_m, omega, r, info] = throttle_mex ("throttlesim", phi_d,
//       R, options)
//   [thm, pset, kappa, phi_hat, u_hat, info] = throttle_mex ("throttleid",
//       phi_d, u, i, phi_m, options)
//
// Signals are N-by-1; R holds R(t_k) (linear in between). Fields of
// options, both modes: Ts; plant, a struct of the 18 parameters of Table
// 4.3 by name (Ks1 Ks2 Ks3 M_close M_open phi_min phi_max phi_LH delta_phi
// phi_12 J Kb Mc R L Kv Kt Gr; SI, rad); the loop pid_num, pid_den (the PID
// of eq. 4.13 in q^-1), filter_num, filter_den (the set-point filter) and
// umax (may be Inf); substeps (default 1) and phi0 (absent or []: at
// phi_d(1)). throttlesim also reads noise (absent or []: none);
// throttleid reads method ('rlssvf' | 'clrsrivc' | 'rlsprefilter'),
// lambda_svf, adg (the 2-by-2 Qn), th0, P0, tsiv and phirule ('zoh' |
// 'foh'). info is [saturated outside_linear events phi_low phi_high]
// (throttlesim) or [rejections] (throttleid).
#include <limits>

#include "ctid/apps/throttle.hpp"
#include "gateway_common.hpp"

namespace {

using ctid::mex::Gateway;
using ctid::mex::OptionsReader;

// A real N-by-1 column of finite values.
const double* column(const Gateway& g, const mxArray* a, const char* what,
                     long n) {
  return g.matrix(a, what, n, 1);
}

// The 18 plant parameters, each read by name from the struct "plant".
ctid::ThrottleParameters<double> read_parameters(const Gateway& g,
                                                 OptionsReader& opt) {
  OptionsReader plant = opt.nested("plant");
  ctid::ThrottleParameters<double> p;
  const std::pair<const char*, double*> fields[18] = {
      {"Ks1", &p.Ks1},
      {"Ks2", &p.Ks2},
      {"Ks3", &p.Ks3},
      {"M_close", &p.M_close},
      {"M_open", &p.M_open},
      {"phi_min", &p.phi_min},
      {"phi_max", &p.phi_max},
      {"phi_LH", &p.phi_LH},
      {"delta_phi", &p.delta_phi},
      {"phi_12", &p.phi_12},
      {"J", &p.J},
      {"Kb", &p.Kb},
      {"Mc", &p.Mc},
      {"R", &p.R},
      {"L", &p.L},
      {"Kv", &p.Kv},
      {"Kt", &p.Kt},
      {"Gr", &p.Gr}};
  for (const auto& f : fields) *f.second = plant.scalar(f.first);
  plant.finish();
  g.check(ctid::validate(p));
  return p;
}

ctid::DiscreteTransferFunction<double> read_filter(const Gateway& g,
                                                   OptionsReader& opt,
                                                   const std::string& prefix,
                                                   const std::string& what) {
  ctid::DiscreteTransferFunction<double> tf;
  if (!ctid::mex::read_transfer_function(g, opt, prefix, &tf)) {
    g.fail("badOption", what + " (options '" + prefix + "_num' and '" + prefix +
                            "_den') is missing");
  }
  return tf;
}

ctid::ThrottleController<double> read_loop(const Gateway& g,
                                           OptionsReader& opt) {
  ctid::ThrottleController<double> c;
  c.pid = read_filter(g, opt, "pid", "the PID");
  c.setpoint_filter = read_filter(g, opt, "filter", "the set-point filter");
  c.u_max = *g.matrix(opt.required("umax"), "option 'umax'", 1, 1, false);
  if (!(c.u_max > 0)) {
    g.fail("badInput", "option 'umax' must be > 0 (Inf: no limit)");
  }
  g.check(ctid::validate(c));
  return c;
}

double read_phi0(OptionsReader& opt) {
  return opt.scalar("phi0", std::numeric_limits<double>::quiet_NaN());
}

void throttlesim_gateway(const Gateway& g, int nlhs, mxArray* plhs[], int nrhs,
                         const mxArray* prhs[]) {
  if (nrhs != 4) {
    g.fail("badInput",
           "the gateway takes 4 arguments (fname, phi_d, R, "
           "options), got " +
               std::to_string(nrhs) + " (call throttlesim)");
  }
  if (nlhs > 7) g.fail("badInput", "at most 7 outputs");
  g.require_real_double(prhs[1], "phi_d");
  const long n = static_cast<long>(mxGetM(prhs[1]));
  if (n < 1) g.fail("badInput", "phi_d must not be empty");
  ctid::ThrottleSimulationInputs<double> in;
  in.phi_d = column(g, prhs[1], "phi_d", n);
  in.num_samples = n;
  in.resistance = column(g, prhs[2], "R", n);
  OptionsReader opt(g, prhs[3]);
  ctid::ThrottleSimulationConfig<double> config;
  config.ts = opt.scalar("Ts");
  in.noise = opt.signal("noise", n);
  config.plant = read_parameters(g, opt);
  config.controller = read_loop(g, opt);
  config.substeps = opt.integer("substeps", config.substeps);
  config.phi0 = read_phi0(opt);
  opt.finish();
  g.check(ctid::validate(config));

  ctid::ThrottleSimulationOutputs<double> out;
  double** targets[6] = {&out.u,     &out.i,     &out.phi,
                         &out.phi_m, &out.omega, &out.reference};
  for (int k = 0; k < 6 && k < std::max(nlhs, 1); ++k) {
    plhs[k] = ctid::mex::make_output_matrix(n, 1);
    *targets[k] = mxGetPr(plhs[k]);
  }
  ctid::ThrottleSimulationInfo<double> info;
  g.check(ctid::simulate_throttle(config, in, out, &info));
  if (nlhs >= 7) {
    plhs[6] = ctid::mex::make_output_matrix(1, 5);
    double* v = mxGetPr(plhs[6]);
    v[0] = static_cast<double>(info.saturated);
    v[1] = static_cast<double>(info.outside_linear);
    v[2] = static_cast<double>(info.events);
    v[3] = info.phi_low;
    v[4] = info.phi_high;
  }
}

void throttleid_gateway(const Gateway& g, int nlhs, mxArray* plhs[], int nrhs,
                        const mxArray* prhs[]) {
  if (nrhs != 6) {
    g.fail("badInput",
           "the gateway takes 6 arguments (fname, phi_d, u, i, "
           "phi_m, options), got " +
               std::to_string(nrhs) + " (call throttleid)");
  }
  if (nlhs > 6) g.fail("badInput", "at most 6 outputs");
  g.require_real_double(prhs[1], "phi_d");
  const long n = static_cast<long>(mxGetM(prhs[1]));
  if (n < 2) g.fail("badInput", "the record needs at least 2 samples");
  ctid::ThrottleRecord<double> record;
  record.phi_d = column(g, prhs[1], "phi_d", n);
  record.u = column(g, prhs[2], "u", n);
  record.i = column(g, prhs[3], "i", n);
  record.phi_m = column(g, prhs[4], "phi_m", n);
  record.num_samples = n;
  OptionsReader opt(g, prhs[5]);
  ctid::ThrottleIdConfig<double> config;
  if (!opt.has("method")) g.fail("badOption", "option 'method' is missing");
  config.method = opt.choice<ctid::ThrottleIdMethod>(
      "method",
      {{"rlssvf", ctid::ThrottleIdMethod::kRlsSvf},
       {"clrsrivc", ctid::ThrottleIdMethod::kClrsrivc},
       {"rlsprefilter", ctid::ThrottleIdMethod::kRlsPrefilter}},
      config.method);
  record.ts = opt.scalar("Ts");
  config.ts = record.ts;
  config.plant = read_parameters(g, opt);
  config.controller = read_loop(g, opt);
  config.substeps = opt.integer("substeps", config.substeps);
  config.phi0 = read_phi0(opt);
  config.lambda_svf = opt.scalar("lambda_svf");
  config.adaptation =
      ctid::KalmanAdaptation<double>(opt.required_matrix("adg", 2, 2));
  ctid::mex::read_initial_estimate(opt, 2, &config.theta0, &config.P0);
  config.t_s_iv = opt.scalar("tsiv", config.t_s_iv);
  config.phi_intersample = opt.choice<ctid::InterSample>(
      "phirule",
      {{"zoh", ctid::InterSample::kZoh}, {"foh", ctid::InterSample::kFoh}},
      config.phi_intersample);
  opt.finish();
  g.check(ctid::validate(config));

  ctid::ThrottleIdOutputs<double> out;
  plhs[0] = ctid::mex::make_output_matrix(n, 2);
  out.thm = mxGetPr(plhs[0]);
  if (nlhs >= 2) {
    plhs[1] = ctid::mex::make_output_array3(2, 2, n);
    out.pset = mxGetPr(plhs[1]);
  }
  double** optional[3] = {&out.kappa, &out.phi_hat, &out.u_hat};
  for (int k = 0; k < 3; ++k) {
    if (nlhs >= k + 3) {
      plhs[k + 2] = ctid::mex::make_output_matrix(n, 1);
      *optional[k] = mxGetPr(plhs[k + 2]);
    }
  }
  ctid::ThrottleIdInfo<double> info;
  g.check(ctid::run_throttle_id(config, record, out, &info));
  if (nlhs >= 6) {
    plhs[5] = ctid::mex::make_output_matrix(1, 1);
    *mxGetPr(plhs[5]) = static_cast<double>(info.rejections);
  }
}

}  // namespace

void mexFunction(int nlhs, mxArray* plhs[], int nrhs, const mxArray* prhs[]) {
  ctid::mex::run_gateway("throttlesim", {"throttlesim", "throttleid"}, nrhs,
                         prhs, [&](const Gateway& g) {
                           if (g.name() == "throttleid") {
                             throttleid_gateway(g, nlhs, plhs, nrhs, prhs);
                           } else {
                             throttlesim_gateway(g, nlhs, plhs, nrhs, prhs);
                           }
                         });
}
