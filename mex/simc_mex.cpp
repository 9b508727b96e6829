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
//
//   y = simc_mex (fname, "state_space", u, t, options)
//
// Output (N-by-ny) of the state-space model x' = a x + b u, y = c x + d u
// from rest (state_space_simulator.hpp). Fields of options: a, b, c, d;
// nk (absent or [], or ny-by-nu delays in samples, fractional allowed with
// a sampling interval); intersample ('zoh' default, or 'foh').
#include "ctid/simulation/ltv_simulator.hpp"
#include "ctid/simulation/state_space_simulator.hpp"
#include "gateway_common.hpp"

namespace {

using ctid::mex::Gateway;

// The sampling interval or the N sampling instants, into the record.
void read_time(const Gateway& g, const mxArray* t, long n,
               ctid::RecordView<double>* record) {
  g.require_real_double(t, "Ts");
  if (mxGetNumberOfElements(t) == 1) {
    record->ts = g.scalar(t, "Ts");
    if (!(record->ts > 0)) g.fail("badInput", "Ts must be > 0");
    return;
  }
  record->instants = g.matrix(t, "the sampling instants", n, 1);
  for (long k = 1; k < n; ++k) {
    if (!(record->instants[k] > record->instants[k - 1])) {
      g.fail("badInput", "the sampling instants must be strictly increasing");
    }
  }
}

void state_space_gateway(const Gateway& g, int nlhs, mxArray* plhs[], int nrhs,
                         const mxArray* prhs[]) {
  if (nrhs != 5) {
    g.fail("badInput",
           "the state-space method takes 5 arguments (fname, "
           "'state_space', u, t, options), got " +
               std::to_string(nrhs));
  }
  if (nlhs > 1) g.fail("badInput", "the state-space method has 1 output");
  g.require_real_double(prhs[2], "u");
  const long n = static_cast<long>(mxGetM(prhs[2]));
  if (n < 1) g.fail("badInput", "u must not be empty");
  ctid::RecordView<double> record;
  record.u = g.matrix(prhs[2], "u", n, -1);
  record.num_samples = n;
  record.num_inputs = static_cast<Eigen::Index>(mxGetN(prhs[2]));
  read_time(g, prhs[3], n, &record);
  ctid::mex::OptionsReader opt(g, prhs[4]);
  ctid::StateSpaceModel<double> model;
  model.a = opt.required_matrix("a");
  model.b = opt.required_matrix("b");
  model.c = opt.required_matrix("c");
  model.d = opt.required_matrix("d");
  model.delays = opt.matrix("nk");
  const ctid::InterSample rule =
      ctid::mex::read_intersample(opt, ctid::InterSample::kZoh);
  opt.finish();
  Eigen::MatrixXd y;
  g.check(ctid::simulate_state_space(model, rule, record, y));
  plhs[0] = ctid::mex::to_output(y);
}

void simc_gateway(const Gateway& g, int nlhs, mxArray* plhs[], int nrhs,
                  const mxArray* prhs[]) {
  if (nrhs >= 2 && mxIsChar(prhs[1])) {
    const std::string method = g.text(prhs[1], "the method");
    if (method != "state_space") {
      g.fail("badInput", "unknown method '" + method + "'");
    }
    state_space_gateway(g, nlhs, plhs, nrhs, prhs);
    return;
  }
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
  read_time(g, prhs[2], n, &record);
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
