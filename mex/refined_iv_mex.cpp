// SPDX-License-Identifier: BSD-3-Clause
// Copyright (C) the ctid authors
// MEX gateway of the offline refined-IV engine (core/include/ctid/
// refined_iv.hpp), called by octave/private/contsid_refined_iv.m:
//
//   [theta, cov, info] = refined_iv_mex (fname, y, w, t, r, opts)
//
// y N-by-1; w N-by-m (the inputs and extra regressors, one channel each);
// t a scalar Ts or the N sampling instants; r the setpoint (N-by-1) or
// [r1 r] (N-by-2, r1 at the plant input: u = r1 + C (r - y)) of a closed
// loop with a continuous-time controller, or []. opts: the options of
// refined_iv_options() (core/include/ctid/offline/refined_iv_options.hpp:
// method, nf, and per column of w group (1-based), nb, nk, intersample (0
// zoh, 1 foh), delay; y_intersample, output_offset, initial_state, fixed,
// fixed_values, theta_init, cutoffs, tol, maxiter, max_starts, time_scale,
// integrator_pole, refit_integrators, controller_num, controller_den
// (descending powers of p; with discrete_controller, powers of q^-1 and r =
// [r1 r2])), read from that table with its defaults; `refined_iv_mex
// (fname, "options")` returns the table. info: converged,
// stable, iterations, reason, noise_variance, cutoff, time_scale, starts,
// condition, x0, offset, simulated, free_response, determined (false: the
// simulation loss converged while parameters moved in directions the data
// do not determine), clipped, clipped_iterations, integrator_suspected,
// loss_history, and lowest_theta, lowest_noise_variance,
// lowest_integrator_suspected, lowest_simulated (the lowest-loss stable
// iterate over all starts when it is not the returned model; lowest_theta
// and lowest_noise_variance empty if none), integrators and
// integrator_refit (see RivResult). integrator_start (a struct with theta,
// converged, stable, suspected, simulated, reason, lowest_theta,
// lowest_suspected, lowest_simulated: a fit's theta and info): the engine's
// integrator refit of that fit alone (refit_integrators of refined_iv.hpp),
// from the fit or its lowest-loss run as the engine chooses; theta and info
// are the refit's when it is kept (info.integrator_refit 1), else the fit's
// with info.integrator_refit -1 (refitted from the fit), -2 (from its
// lowest-loss run) or 0 (no refit applies) and cov zero.
//
//   [theta, cov, info] = refined_iv_mex (fname, "delay_search", y, w, t, r,
//                                        opts, search)
//
// the same problem with the continuous delay of its one channel searched
// (see delay_search_gateway).
//
//   range = refined_iv_mex (fname, "delay_range", y, u, t, given)
//
// the range of a delay search with the data's defaults
// (delay_search_defaults.hpp) for what given leaves out; given fields:
// tdmin, numtd, and tdmax, stepmax, td0 (the start delay), each absent or
// [] when not given. range fields: tdmax, stepmax, tdmax_limit (half the
// record when tdmax is the default, else 0), tdmax_auto.
//
//   [yf, uf] = refined_iv_mex (fname, "focus_filter", y, u, opts)
//
// y and u (N rows each) filtered column by column by the Focus band
// (focus_filter.hpp); opts fields: ts, band ([w1 w2] rad/s), order.
#include <algorithm>
#include <limits>

#include "ctid/filters/focus_filter.hpp"
#include "ctid/offline/delay_search_defaults.hpp"
#include "ctid/offline/refined_iv.hpp"
#include "ctid/offline/refined_iv_delay.hpp"
#include "ctid/offline/refined_iv_options.hpp"
#include "ctid/offline/tfsrivc_options.hpp"
#include "estimator_args.hpp"
#include "gateway_common.hpp"
#include "options_reader.hpp"
#include "rivc_info.hpp"

namespace {

using ctid::mex::Gateway;
using ctid::mex::OptionsReader;
using ctid::mex::to_output;

void focus_filter_gateway(const Gateway& g, int nlhs, mxArray* plhs[], int nrhs,
                          const mxArray* prhs[]) {
  if (nrhs != 5) {
    g.fail("badInput",
           "the focus_filter method takes 5 arguments (fname, "
           "'focus_filter', y, u, opts), got " +
               std::to_string(nrhs));
  }
  if (nlhs > 2) g.fail("badInput", "the focus_filter method has 2 outputs");
  Eigen::MatrixXd y = g.eigen_matrix(prhs[2], "y");
  Eigen::MatrixXd u = g.eigen_matrix(prhs[3], "u", y.rows(), -1);
  OptionsReader opt(g, prhs[4]);
  const double ts = opt.scalar("ts");
  // (w2 may be Inf: read without the finiteness check, the core checks it)
  const mxArray* band_arg = opt.required("band");
  g.require_real_double(band_arg, "band");
  if (mxGetNumberOfElements(band_arg) != 2) {
    g.fail("badInput", "band must be [w1 w2]");
  }
  const double* band = mxGetPr(band_arg);
  const int order = opt.integer("order");
  opt.finish();
  ctid::DiscreteTransferFunction<double> filter;
  g.check(ctid::focus_band_filter<double>(order, band[0], band[1], ts, filter));
  ctid::apply_filter(filter, y);
  ctid::apply_filter(filter, u);
  plhs[0] = to_output(y);
  if (nlhs > 1) plhs[1] = to_output(u);
}

// The method 'delay_range' (see the header comment).
void delay_range_gateway(const Gateway& g, mxArray* plhs[], int nrhs,
                         const mxArray* prhs[]) {
  if (nrhs != 6) {
    g.fail("badInput",
           "the delay_range method takes 6 arguments (fname, 'delay_range', "
           "y, u, t, given), got " +
               std::to_string(nrhs));
  }
  const ctid::RecordView<double> record =
      ctid::mex::read_record(g, prhs[2], prhs[3], prhs[4]);
  OptionsReader opt(g, prhs[5]);
  const double none = std::numeric_limits<double>::quiet_NaN();
  ctid::DelayRangeRequest<double> given;
  given.td_min = opt.scalar("tdmin");
  given.num_td = opt.integer("numtd");
  given.td_max = opt.scalar("tdmax", none);
  given.step_max = opt.scalar("stepmax", none);
  given.td_start = opt.scalar("td0", none);
  opt.finish();
  ctid::DelayRange<double> r;
  g.check(ctid::delay_search_range(record, given, &r));
  const char* fields[] = {"tdmax", "stepmax", "tdmax_limit", "tdmax_auto"};
  mxArray* o = mxCreateStructMatrix(1, 1, 4, fields);
  mxSetField(o, 0, "tdmax", mxCreateDoubleScalar(r.td_max));
  mxSetField(o, 0, "stepmax", mxCreateDoubleScalar(r.step_max));
  mxSetField(o, 0, "tdmax_limit", mxCreateDoubleScalar(r.extend_limit));
  mxSetField(o, 0, "tdmax_auto", mxCreateLogicalScalar(r.td_max_from_data));
  plhs[0] = o;
}

// The method 'tf_options' (see the header comment).
void tf_options_gateway(const Gateway& g, mxArray* plhs[], int nrhs,
                        const mxArray* prhs[]) {
  const auto& table = ctid::tfsrivc_options<double>();
  if (nrhs != 3) {
    g.fail("badInput",
           "the tf_options method takes 3 arguments (fname, 'tf_options', "
           "given), got " +
               std::to_string(nrhs));
  }
  if (mxIsChar(prhs[2]) && g.text(prhs[2], "given") == "options") {
    plhs[0] = ctid::mex::option_table_struct(table);
    return;
  }
  OptionsReader opt(g, prhs[2]);
  ctid::TfsrivcConfig<double> c;
  ctid::mex::read_option_table(g, opt, table, &c, "badOption");
  opt.finish();
  g.check(ctid::validate(c));
  const auto automatic = [](double v) {
    return v == 0 ? mxCreateDoubleMatrix(0, 0, mxREAL)
                  : mxCreateDoubleScalar(v);
  };
  const char* fields[] = {"fixtd",         "tdmin",      "tdmax",
                          "numtd",         "lambda",     "maxiter",
                          "tolpar",        "tolfun",     "stepmax",
                          "stepreduction", "focusorder", "integration"};
  mxArray* o = mxCreateStructMatrix(1, 1, 12, fields);
  mxSetField(o, 0, "fixtd", mxCreateLogicalScalar(c.fix_td));
  mxSetField(o, 0, "tdmin", mxCreateDoubleScalar(c.td_min));
  mxSetField(o, 0, "tdmax",
             std::isnan(c.td_max) ? mxCreateDoubleMatrix(0, 0, mxREAL)
                                  : mxCreateDoubleScalar(c.td_max));
  mxSetField(o, 0, "numtd", mxCreateDoubleScalar(c.num_td));
  mxSetField(o, 0, "lambda", automatic(c.lambda));
  mxSetField(o, 0, "maxiter", mxCreateDoubleScalar(c.max_iterations));
  mxSetField(o, 0, "tolpar", mxCreateDoubleScalar(c.tol_par));
  mxSetField(o, 0, "tolfun", mxCreateDoubleScalar(c.tol_fun));
  mxSetField(o, 0, "stepmax", automatic(c.step_max));
  mxSetField(o, 0, "stepreduction", mxCreateDoubleScalar(c.step_factor()));
  mxSetField(o, 0, "focusorder", mxCreateDoubleScalar(c.focus_order));
  mxSetField(o, 0, "integration", mxCreateLogicalScalar(c.integration));
  plhs[0] = o;
}

mxArray* engine_info(const ctid::RivResult<double>& result);

// RIVC's info at the delay kept (the fields of rivc_mex's info for the
// method 'rivc', with stable and covariance).
mxArray* rivc_info(const ctid::RivcResult<double>& res) {
  mxArray* info = ctid::mex::make_rivc_info({"stable", "covariance"});
  ctid::mex::set_rivc_info(info, res);
  mxSetField(info, 0, "stable", mxCreateLogicalScalar(res.stable));
  mxSetField(info, 0, "covariance", to_output(res.covariance));
  return info;
}

// The method 'delay_search': the engine's problem with the delay of its
// one channel searched (core refined_iv_delay.hpp). search: the options of
// refined_iv_delay_options() (core/include/ctid/offline/
// refined_iv_options.hpp): td0 ([]: the grid), tdmin, tdmax, numtd, refine
// (Gauss-Newton on the delay), tdmax_limit (> tdmax: the grid extended up
// to it while its minimum is at its upper end), maxiter, tolpar (sampling
// intervals), tolfun, stepmax, stepreduction, noise ([] or [nd nc]: RIVC
// with that ARMA noise model). Outputs: theta, the engine's covariance and
// info at the delay kept (RIVC's with a noise model), info.delay_search:
// delay, delay_estimated, covariance (of [theta; td] or theta), loss,
// simulated, grid, grid_loss, tdmax, iterations, converged, reason.
void delay_search_gateway(const Gateway& g, int nlhs, mxArray* plhs[],
                          const mxArray* search_arg,
                          const ctid::RivProblem<double>& problem,
                          const ctid::RivSettings<double>& settings,
                          const ctid::RivData<double>& data) {
  OptionsReader opt(g, search_arg, "search.");
  ctid::RivDelaySettings<double> ds;
  ctid::mex::read_option_table(g, opt, ctid::refined_iv_delay_options<double>(),
                               &ds);
  opt.finish();
  ctid::RivDelayResult<double> r;
  g.check(ctid::refined_iv_delay(problem, settings, data, ds, &r));
  plhs[0] = to_output(ds.noise_model ? r.rivc.theta : r.engine.theta);
  if (nlhs >= 2) {
    plhs[1] =
        to_output(ds.noise_model ? r.rivc.covariance : r.engine.covariance);
  }
  if (nlhs < 3) return;
  mxArray* info = ds.noise_model ? rivc_info(r.rivc) : engine_info(r.engine);
  const char* fields[] = {"delay",     "delay_estimated", "covariance",
                          "loss",      "simulated",       "grid",
                          "grid_loss", "tdmax",           "iterations",
                          "converged", "reason"};
  mxArray* d = mxCreateStructMatrix(1, 1, 11, fields);
  mxSetField(d, 0, "delay", mxCreateDoubleScalar(r.delay));
  mxSetField(d, 0, "delay_estimated", mxCreateLogicalScalar(r.delay_estimated));
  mxSetField(d, 0, "covariance", to_output(r.covariance));
  mxSetField(d, 0, "loss", mxCreateDoubleScalar(r.loss));
  mxSetField(d, 0, "simulated", to_output(r.simulated));
  const Eigen::Map<const Eigen::RowVectorXd> grid(r.grid.data(), r.grid.size());
  const Eigen::Map<const Eigen::RowVectorXd> grid_loss(r.grid_loss.data(),
                                                       r.grid_loss.size());
  mxSetField(d, 0, "grid", to_output(Eigen::MatrixXd(grid)));
  mxSetField(d, 0, "grid_loss", to_output(Eigen::MatrixXd(grid_loss)));
  mxSetField(d, 0, "tdmax", mxCreateDoubleScalar(r.td_max));
  mxSetField(d, 0, "iterations", mxCreateDoubleScalar(r.iterations));
  mxSetField(d, 0, "converged", mxCreateLogicalScalar(r.converged));
  mxSetField(d, 0, "reason", mxCreateString(r.reason.c_str()));
  mxAddField(info, "delay_search");
  mxSetField(info, 0, "delay_search", d);
  plhs[2] = info;
}

void refined_iv_gateway(const Gateway& g, int nlhs, mxArray* plhs[], int nrhs,
                        const mxArray** prhs) {
  if (ctid::mex::asks_for_options(nrhs, prhs)) {
    plhs[0] =
        ctid::mex::option_table_struct(ctid::refined_iv_options<double>());
    return;
  }
  const mxArray* search = nullptr;
  if (nrhs >= 2 && mxIsChar(prhs[1])) {
    const std::string method = g.text(prhs[1], "the method");
    if (method == "focus_filter") {
      focus_filter_gateway(g, nlhs, plhs, nrhs, prhs);
      return;
    }
    if (method == "tf_options") {
      tf_options_gateway(g, plhs, nrhs, prhs);
      return;
    }
    if (method == "delay_range") {
      delay_range_gateway(g, plhs, nrhs, prhs);
      return;
    }
    if (method != "delay_search") {
      g.fail("badInput", "unknown method '" + method + "'");
    }
    if (nrhs != 8) {
      g.fail("badInput",
             "the delay_search method takes 8 arguments (fname, "
             "'delay_search', y, w, t, r, opts, search), got " +
                 std::to_string(nrhs));
    }
    search = prhs[7];
    ++prhs;
    nrhs = 6;
  }
  if (nrhs != 6) {
    g.fail("badInput",
           "the gateway takes 6 arguments, got " + std::to_string(nrhs));
  }
  if (nlhs > 3) g.fail("badInput", "at most 3 outputs");
  const ctid::RecordView<double> record =
      ctid::mex::read_record(g, prhs[1], prhs[2], prhs[3]);
  const long n = record.num_samples;
  const int m = static_cast<int>(record.num_inputs);
  ctid::RivData<double> data;
  data.y = record.y;
  data.w = record.u;
  data.num_samples = n;
  data.ts = record.ts;
  data.instants = record.instants;

  OptionsReader opt(g, prhs[5]);
  ctid::RivConfig<double> config;
  ctid::mex::read_option_table(g, opt, ctid::refined_iv_options<double>(),
                               &config);
  // The integrator refit of a given fit (see the header comment).
  const bool refit_only = opt.has("integrator_start");
  ctid::RivResult<double> fit;
  if (refit_only) {
    OptionsReader start = opt.nested("integrator_start");
    const auto vector = [&](const char* name) {
      const Eigen::MatrixXd v = start.matrix(name);
      return ctid::Vector<double>(v.reshaped());
    };
    fit.theta = vector("theta");
    fit.converged = start.flag("converged", false);
    fit.stable = start.flag("stable", false);
    fit.integrator_suspected = start.integer_vector("suspected");
    fit.simulated = vector("simulated");
    fit.reason = start.text("reason", "");
    fit.lowest_theta = vector("lowest_theta");
    fit.lowest_integrator_suspected =
        start.integer_vector("lowest_suspected", {});
    fit.lowest_simulated = vector("lowest_simulated");
    start.finish();
  }
  opt.finish();
  ctid::RivProblem<double> problem;
  g.check(ctid::riv_problem(config, m, &problem));
  const ctid::RivSettings<double>& settings = config.settings;
  const int np = problem.num_parameters();
  const ctid::Vector<double> cnum = problem.controller_num;
  const ctid::Vector<double> cden = problem.controller_den;
  const bool discrete = config.discrete_controller;
  ctid::DiscreteTransferFunction<double> controller;
  if (cnum.size() > 0 && discrete) {
    if (cden.size() == 0) {
      g.fail("badOption",
             "options 'controller_num' and 'controller_den' must be "
             "non-empty vectors");
    }
    controller.numerator = cnum;
    controller.denominator = cden;
    g.check(ctid::validate_controller(controller));
    const double* r = g.matrix(prhs[4], "[r1 r2]", n, 2);
    problem.controller_num.resize(0);
    problem.controller_den.resize(0);
    problem.discrete_controller = &controller;
    problem.r1 = r;
    problem.r2 = r + n;
  } else if (cnum.size() > 0) {
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

  if (search != nullptr) {
    delay_search_gateway(g, nlhs, plhs, search, problem, settings, data);
    return;
  }
  ctid::RivResult<double> result;
  ctid::Status status;
  if (refit_only) {
    result = fit;
    g.check(ctid::refit_integrators(problem, settings, data, &result));
    if (result.covariance.size() == 0) {
      result.covariance = Eigen::MatrixXd::Zero(np, np);
    }
  } else {
    status = ctid::refined_iv(problem, settings, data, &result);
    if (status.code() != ctid::ErrorCode::kNotConverged) g.check(status);
  }

  plhs[0] = to_output(result.theta);
  if (nlhs >= 2) {
    plhs[1] = ctid::mex::make_output_matrix(np, np);
    std::copy(result.covariance.data(), result.covariance.data() + np * np,
              mxGetPr(plhs[1]));
  }
  if (nlhs >= 3) plhs[2] = engine_info(result);
}

// The engine's info struct (see the header comment).
mxArray* engine_info(const ctid::RivResult<double>& result) {
  const char* fields[] = {"converged",
                          "stable",
                          "iterations",
                          "reason",
                          "noise_variance",
                          "cutoff",
                          "time_scale",
                          "starts",
                          "condition",
                          "x0",
                          "offset",
                          "simulated",
                          "free_response",
                          "determined",
                          "clipped",
                          "clipped_iterations",
                          "integrator_suspected",
                          "loss_history",
                          "lowest_theta",
                          "lowest_noise_variance",
                          "lowest_integrator_suspected",
                          "lowest_simulated",
                          "integrators",
                          "integrator_refit"};
  mxArray* info = mxCreateStructMatrix(1, 1, 24, fields);
  mxSetField(info, 0, "converged", mxCreateLogicalScalar(result.converged));
  mxSetField(info, 0, "stable", mxCreateLogicalScalar(result.stable));
  mxSetField(info, 0, "iterations", mxCreateDoubleScalar(result.iterations));
  mxSetField(info, 0, "reason", mxCreateString(result.reason.c_str()));
  mxSetField(info, 0, "noise_variance",
             mxCreateDoubleScalar(result.noise_variance));
  mxSetField(info, 0, "cutoff", mxCreateDoubleScalar(result.cutoff));
  mxSetField(info, 0, "time_scale", mxCreateDoubleScalar(result.time_scale));
  mxSetField(info, 0, "starts", mxCreateDoubleScalar(result.starts_tried));
  mxSetField(info, 0, "condition", mxCreateDoubleScalar(result.condition));
  mxSetField(info, 0, "x0", to_output(result.x0));
  mxSetField(info, 0, "offset", mxCreateDoubleScalar(result.offset));
  mxSetField(info, 0, "simulated", to_output(result.simulated));
  mxSetField(info, 0, "free_response", to_output(result.free_response));
  mxSetField(info, 0, "determined", mxCreateLogicalScalar(result.determined));
  mxSetField(info, 0, "clipped", mxCreateLogicalScalar(result.clipped));
  mxSetField(info, 0, "clipped_iterations",
             mxCreateDoubleScalar(result.clipped_iterations));
  const std::size_t groups = result.integrator_suspected.size();
  mxArray* suspected = mxCreateLogicalMatrix(1, groups);
  for (std::size_t g = 0; g < groups; ++g) {
    mxGetLogicals(suspected)[g] = result.integrator_suspected[g] != 0;
  }
  mxSetField(info, 0, "integrator_suspected", suspected);
  mxSetField(info, 0, "lowest_theta", to_output(result.lowest_theta));
  // Empty with lowest_theta when there is no such iterate (the core's
  // Inf there means "none", not a noise variance).
  mxSetField(info, 0, "lowest_noise_variance",
             result.lowest_theta.size() > 0
                 ? mxCreateDoubleScalar(result.lowest_noise_variance)
                 : mxCreateDoubleMatrix(0, 0, mxREAL));
  const std::size_t lowest_groups = result.lowest_integrator_suspected.size();
  mxArray* lowest_suspected = mxCreateLogicalMatrix(1, lowest_groups);
  for (std::size_t g = 0; g < lowest_groups; ++g) {
    mxGetLogicals(lowest_suspected)[g] =
        result.lowest_integrator_suspected[g] != 0;
  }
  mxSetField(info, 0, "lowest_integrator_suspected", lowest_suspected);
  mxSetField(info, 0, "lowest_simulated", to_output(result.lowest_simulated));
  mxArray* losses =
      ctid::mex::make_output_matrix(result.loss_history.size(), 1);
  std::copy(result.loss_history.begin(), result.loss_history.end(),
            mxGetPr(losses));
  mxSetField(info, 0, "loss_history", losses);
  mxArray* integrators = ctid::mex::make_output_matrix(
      1, static_cast<long>(result.integrators.size()));
  std::copy(result.integrators.begin(), result.integrators.end(),
            mxGetPr(integrators));
  mxSetField(info, 0, "integrators", integrators);
  mxSetField(info, 0, "integrator_refit",
             mxCreateDoubleScalar(result.integrator_refit));
  return info;
}

}  // namespace

void mexFunction(int nlhs, mxArray* plhs[], int nrhs, const mxArray* prhs[]) {
  ctid::mex::run_gateway(
      "srivc",
      {"lssvf", "ivsvf", "srivc", "clsrivc", "svfcutoff", "srivcstruc",
       "residtrace", "comparec", "simc", "tfsrivc", "tfsrivc_init", "procsrivc",
       "tfcoe", "tfrivc"},
      nrhs, prhs,
      [&](const Gateway& g) { refined_iv_gateway(g, nlhs, plhs, nrhs, prhs); });
}
