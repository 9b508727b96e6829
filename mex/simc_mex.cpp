// SPDX-License-Identifier: BSD-3-Clause
// Copyright (C) the ctid authors
// MEX gateway of the LTV simulator (octave/simc.m):
//
//   [x, y, u] = simc_mex (fname, u, t, theta, options)
//
// u: N-by-nu input (r1 in closed loop); t: Ts or N instants; theta: 1-by-np
// (time-invariant) or N-by-np (values at the samples, linear in between).
// Fields of options: intersample, na, nb, nk (gateway_common.hpp),
// substeps (default 1), x0 (absent or [], or the na*nu initial state),
// noise (absent or [], or N-by-1 e(t_k) added to y); in closed loop
// controller_num, controller_den (C(q^-1) of u = r1 + C (r2 - y)) and r2
// (N-by-1).
#include "ctid/simulation/ltv_simulator.hpp"
#include "gateway_common.hpp"

namespace {

using ctid::mex::Gateway;

void simc_gateway(const Gateway& g, int nlhs, mxArray* plhs[], int nrhs,
                  const mxArray* prhs[]) {
  if (nrhs != 5) {
    g.fail("badInput",
           "the gateway takes 5 arguments (fname, u, t, theta, "
           "options), got " +
               std::to_string(nrhs) + " (call simc instead)");
  }
  if (nlhs > 3) g.fail("badInput", "at most 3 outputs (x, y, u)");
  g.require_real_double(prhs[1], "u");
  const long n = static_cast<long>(mxGetM(prhs[1]));
  if (n < 1) g.fail("badInput", "u must not be empty");
  ctid::RecordView<double> record;
  record.u = g.matrix(prhs[1], "u", n, -1);
  record.num_samples = n;
  record.num_inputs = static_cast<Eigen::Index>(mxGetN(prhs[1]));
  g.require_real_double(prhs[2], "Ts");
  if (mxGetNumberOfElements(prhs[2]) == 1) {
    record.ts = g.scalar(prhs[2], "Ts");
    if (!(record.ts > 0)) g.fail("badInput", "Ts must be > 0");
  } else {
    record.instants = g.matrix(prhs[2], "the sampling instants", n, 1);
    for (long k = 1; k < n; ++k) {
      if (!(record.instants[k] > record.instants[k - 1])) {
        g.fail("badInput", "the sampling instants must be strictly increasing");
      }
    }
  }
  ctid::mex::OptionsReader opt(g, prhs[4]);
  ctid::LtvSimulationConfig<double> config;
  config.u_intersample = ctid::mex::read_intersample(opt, config.u_intersample);
  config.orders = ctid::mex::read_orders(g, opt);
  if (record.num_inputs != config.orders.num_inputs()) {
    g.fail("dimensionMismatch", "u has " + std::to_string(record.num_inputs) +
                                    " column(s) but the model has " +
                                    std::to_string(config.orders.num_inputs()) +
                                    " input(s)");
  }
  if (record.instants != nullptr && config.orders.max_delay() > 0) {
    g.fail("badInput", "nk must be 0 for irregularly sampled data");
  }
  const long np = config.orders.num_parameters();
  g.require_real_double(prhs[3], "theta");
  const long theta_rows = static_cast<long>(mxGetM(prhs[3]));
  if (theta_rows != 1 && theta_rows != n) {
    g.fail("dimensionMismatch", "theta must have 1 row or one row per sample");
  }
  const double* theta = g.matrix(prhs[3], "theta", theta_rows, np);
  config.substeps = opt.integer("substeps", config.substeps);
  const long ns = static_cast<long>(config.orders.na) * record.num_inputs;
  const Eigen::MatrixXd x0 = opt.matrix("x0", ns, 1);
  if (x0.size() != 0) config.initial_state = x0;
  const double* noise = opt.signal("noise", n);
  config.closed_loop = ctid::mex::read_transfer_function(g, opt, "controller",
                                                         &config.controller);
  const double* r2 = opt.signal("r2", n);
  if (config.closed_loop != (r2 != nullptr)) {
    g.fail("badOption",
           "the closed loop needs the options 'controller_num', "
           "'controller_den' and 'r2' together");
  }
  opt.finish();
  ctid::LtvSimulator<double> simulator;
  g.check(simulator.configure(config));

  std::vector<double> instants;
  const double* t_samples = record.instants;
  if (t_samples == nullptr) {
    instants.resize(n);
    for (long k = 0; k < n; ++k) instants[k] = k * record.ts;
    t_samples = instants.data();
  }
  const ctid::ParameterTrajectory<double> trajectory =
      ctid::piecewise_linear_trajectory<double>(t_samples, theta, theta_rows,
                                                np);
  plhs[0] = ctid::mex::make_output_matrix(n, 1);
  ctid::SimulationOutputs<double> out;
  out.x = mxGetPr(plhs[0]);
  if (nlhs >= 2) {
    plhs[1] = ctid::mex::make_output_matrix(n, 1);
    out.y = mxGetPr(plhs[1]);
  }
  if (nlhs >= 3) {
    plhs[2] = ctid::mex::make_output_matrix(n, record.num_inputs);
    out.u_applied = mxGetPr(plhs[2]);
  }
  g.check(simulator.simulate(trajectory, record, r2, noise, out));
}

}  // namespace

void mexFunction(int nlhs, mxArray* plhs[], int nrhs, const mxArray* prhs[]) {
  ctid::mex::run_gateway("simc", {"simc"}, nrhs, prhs, [&](const Gateway& g) {
    simc_gateway(g, nlhs, plhs, nrhs, prhs);
  });
}
