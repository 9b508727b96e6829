// MEX gateway of the electronic throttle of thesis sec. 4.2 (octave/
// throttlesim.m and octave/throttleid.m):
//
//   [u, i, phi, phi_m, omega, r, info] = throttle_mex ("throttlesim", phi_d,
//       Ts, R, noise, params, pid_num, pid_den, f_num, f_den, umax,
//       substeps, phi0)
//   [thm, pset, kappa, phi_hat, u_hat, info] = throttle_mex ("throttleid",
//       method, phi_d, u, i, phi_m, Ts, params, pid_num, pid_den, f_num,
//       f_den, umax, substeps, phi0, lambda_svf, Qn, th0, P0, tsiv, phirule)
//
// Signals are N-by-1; R holds R(t_k) (linear in between); noise and phi0
// may be []; params is the 18-vector [Ks1 Ks2 Ks3 M_close M_open phi_min
// phi_max phi_LH delta_phi phi_12 J Kb Mc R L Kv Kt Gr] (SI, rad); umax may
// be Inf. method is "rlssvf", "clrsrivc" or "rlsprefilter"; phirule "zoh"
// or "foh". info is [saturated outside_linear events phi_low phi_high]
// (throttlesim) or [rejections] (throttleid).
#include <limits>

#include "ctid/throttle.hpp"
#include "gateway_common.hpp"

namespace {

using ctid::mex::Gateway;

// A real N-by-1 column of finite values.
const double* column(const Gateway& g, const mxArray* a, const char* what,
                     long n) {
  return g.matrix(a, what, n, 1);
}

ctid::ThrottleParameters<double> read_parameters(const Gateway& g,
                                                 const mxArray* a) {
  g.require_real_double(a, "params");
  if (mxGetNumberOfElements(a) != 18 || (mxGetM(a) != 1 && mxGetN(a) != 1)) {
    g.fail("dimensionMismatch", "params must be a vector of 18 values");
  }
  const double* v = g.matrix(a, "params");
  ctid::ThrottleParameters<double> p;
  double* fields[18] = {
      &p.Ks1,     &p.Ks2,    &p.Ks3,       &p.M_close, &p.M_open, &p.phi_min,
      &p.phi_max, &p.phi_LH, &p.delta_phi, &p.phi_12,  &p.J,      &p.Kb,
      &p.Mc,      &p.R,      &p.L,         &p.Kv,      &p.Kt,     &p.Gr};
  for (int k = 0; k < 18; ++k) *fields[k] = v[k];
  g.check(ctid::validate(p));
  return p;
}

ctid::ThrottleController<double> read_loop(const Gateway& g,
                                           const mxArray* prhs[], int first) {
  ctid::ThrottleController<double> c;
  c.pid = ctid::mex::read_transfer_function(g, prhs[first], prhs[first + 1],
                                            "the PID");
  c.setpoint_filter = ctid::mex::read_transfer_function(
      g, prhs[first + 2], prhs[first + 3], "the set-point filter");
  const mxArray* umax = prhs[first + 4];
  g.require_real_double(umax, "umax");
  if (mxGetNumberOfElements(umax) != 1) {
    g.fail("dimensionMismatch", "umax must be a scalar");
  }
  c.u_max = *g.matrix(umax, "umax", 1, 1, false);
  if (!(c.u_max > 0)) g.fail("badInput", "umax must be > 0 (Inf: no limit)");
  g.check(ctid::validate(c));
  return c;
}

double read_phi0(const Gateway& g, const mxArray* a) {
  g.require_real_double(a, "phi0");
  if (mxIsEmpty(a)) return std::numeric_limits<double>::quiet_NaN();
  return g.scalar(a, "phi0");
}

void throttlesim_gateway(const Gateway& g, int nlhs, mxArray* plhs[], int nrhs,
                         const mxArray* prhs[]) {
  if (nrhs != 13) {
    g.fail("badInput", "the gateway takes 13 arguments, got " +
                           std::to_string(nrhs) + " (call throttlesim)");
  }
  if (nlhs > 7) g.fail("badInput", "at most 7 outputs");
  g.require_real_double(prhs[1], "phi_d");
  const long n = static_cast<long>(mxGetM(prhs[1]));
  if (n < 1) g.fail("badInput", "phi_d must not be empty");
  ctid::ThrottleSimulationInputs<double> in;
  in.phi_d = column(g, prhs[1], "phi_d", n);
  in.num_samples = n;
  ctid::ThrottleSimulationConfig<double> config;
  config.ts = g.scalar(prhs[2], "Ts");
  in.resistance = column(g, prhs[3], "R", n);
  g.require_real_double(prhs[4], "noise");
  if (!mxIsEmpty(prhs[4])) in.noise = column(g, prhs[4], "noise", n);
  config.plant = read_parameters(g, prhs[5]);
  config.controller = read_loop(g, prhs, 6);
  config.substeps = g.integer(prhs[11], "substeps");
  config.phi0 = read_phi0(g, prhs[12]);
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
  if (nrhs != 21) {
    g.fail("badInput", "the gateway takes 21 arguments, got " +
                           std::to_string(nrhs) + " (call throttleid)");
  }
  if (nlhs > 6) g.fail("badInput", "at most 6 outputs");
  ctid::ThrottleIdConfig<double> config;
  const std::string method = g.text(prhs[1], "the method");
  if (method == "rlssvf") {
    config.method = ctid::ThrottleIdMethod::kRlsSvf;
  } else if (method == "clrsrivc") {
    config.method = ctid::ThrottleIdMethod::kClrsrivc;
  } else if (method == "rlsprefilter") {
    config.method = ctid::ThrottleIdMethod::kRlsPrefilter;
  } else {
    g.fail("badOption",
           "the method must be 'clrsrivc', 'rlssvf' or 'rlsprefilter', got '" +
               method + "'");
  }
  g.require_real_double(prhs[2], "phi_d");
  const long n = static_cast<long>(mxGetM(prhs[2]));
  if (n < 2) g.fail("badInput", "the record needs at least 2 samples");
  ctid::ThrottleRecord<double> record;
  record.phi_d = column(g, prhs[2], "phi_d", n);
  record.u = column(g, prhs[3], "u", n);
  record.i = column(g, prhs[4], "i", n);
  record.phi_m = column(g, prhs[5], "phi_m", n);
  record.num_samples = n;
  record.ts = g.scalar(prhs[6], "Ts");
  config.ts = record.ts;
  config.plant = read_parameters(g, prhs[7]);
  config.controller = read_loop(g, prhs, 8);
  config.substeps = g.integer(prhs[13], "substeps");
  config.phi0 = read_phi0(g, prhs[14]);
  config.lambda_svf = g.scalar(prhs[15], "lambda_svf");
  config.adaptation = ctid::KalmanAdaptation<double>(
      g.eigen_matrix(prhs[16], "adg (Qn)", 2, 2));
  ctid::mex::read_initial_estimate(g, prhs[17], prhs[18], 2, &config.theta0,
                                   &config.P0);
  config.t_s_iv = g.scalar(prhs[19], "tsiv");
  config.phi_intersample = ctid::mex::read_intersample(g, prhs[20]);
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
  const std::string name = ctid::mex::public_name(
      nrhs, prhs, "throttlesim", {"throttlesim", "throttleid"});
  ctid::mex::run_gateway(name.c_str(), {"throttlesim", "throttleid"}, nrhs,
                         prhs, [&](const Gateway& g) {
                           if (g.name() == "throttleid") {
                             throttleid_gateway(g, nlhs, plhs, nrhs, prhs);
                           } else {
                             throttlesim_gateway(g, nlhs, plhs, nrhs, prhs);
                           }
                         });
}
