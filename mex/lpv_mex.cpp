// SPDX-License-Identifier: BSD-3-Clause
// Copyright (C) the ctid authors
// MEX gateway of the LPV family (octave/simulLPVCT.m, lpvsrivc.m, lpvrivc.m):
//
//   y = lpv_mex ("simulLPVCT", u, depA, depB, options)
//   [theta, A, B, c, d, J, iterations, converged, ysim] =
//       lpv_mex (fname, y, u, depA, depB, options)      (lpvsrivc, lpvrivc)
//
// depA, depB: the dependency arrays reshaped to n_dep-by-(n_coef*N) (the
// column-major storage of CONTSID's n_dep x n_coef x N arrays).
// Options of both: Ts, dims_a, dims_b (the three sizes [n_dep n_coef N] of
// each dependency array), all required. Simulation: A, B (required).
// Estimation: nc, nd (default 0), tol (1e-4), maxiter (50), Ainit, Binit
// (absent or [], or the initial model).
#include <string>
#include <vector>

#include "ctid/offline/lpv_refined_iv.hpp"
#include "mex_helpers.hpp"
#include "options_reader.hpp"

namespace {

using ctid::mex::Gateway;
using ctid::mex::OptionsReader;

ctid::LpvBasis<double> read_basis(const Gateway& g, OptionsReader& opt,
                                  const mxArray* values, const char* dims,
                                  const char* what) {
  const std::vector<int> d = opt.integer_vector(dims);
  if (d.size() != 3 || d[0] < 1 || d[1] < 1 || d[2] < 1) {
    g.fail("badOption", std::string("option '") + dims +
                            "' must be [n_dep n N], positive integers");
  }
  ctid::LpvBasis<double> basis;
  basis.num_functions = d[0];
  basis.num_coefficients = d[1];
  basis.num_samples = d[2];
  basis.values = g.matrix(values, what, d[0], static_cast<long>(d[1]) * d[2]);
  return basis;
}

void simulate(const Gateway& g, int nlhs, mxArray* plhs[], int nrhs,
              const mxArray* prhs[]) {
  if (nrhs != 5) {
    g.fail("badInput",
           "the gateway takes 5 arguments (fname, u, depA, depB, options)");
  }
  if (nlhs > 1) g.fail("badInput", "one output");
  g.require_real_double(prhs[1], "u");
  const long n = static_cast<long>(mxGetM(prhs[1]));
  if (n < 1) g.fail("badInput", "u must not be empty");
  const double* u = g.matrix(prhs[1], "u", n, 1);
  OptionsReader opt(g, prhs[4]);
  const double ts = opt.scalar("Ts");
  const Eigen::MatrixXd a = opt.required_matrix("A");
  const Eigen::MatrixXd b = opt.required_matrix("B");
  const ctid::LpvBasis<double> dep_a =
      read_basis(g, opt, prhs[2], "dims_a", "DepA");
  const ctid::LpvBasis<double> dep_b =
      read_basis(g, opt, prhs[3], "dims_b", "DepB");
  opt.finish();
  plhs[0] = ctid::mex::make_output_matrix(n, 1);
  g.check(ctid::simulate_lpv<double>(u, n, ts, a, dep_a, b, dep_b,
                                     mxGetPr(plhs[0])));
}

void estimate(const Gateway& g, int nlhs, mxArray* plhs[], int nrhs,
              const mxArray* prhs[]) {
  if (nrhs != 6) {
    g.fail("badInput",
           "the gateway takes 6 arguments (fname, y, u, depA, depB, "
           "options)");
  }
  if (nlhs > 9) g.fail("badInput", "at most 9 outputs");
  ctid::LpvProblem<double> problem;
  g.require_real_double(prhs[1], "y");
  const long n = static_cast<long>(mxGetM(prhs[1]));
  if (n < 1) g.fail("badInput", "y must not be empty");
  problem.num_samples = n;
  problem.y = g.matrix(prhs[1], "y", n, 1);
  problem.u = g.matrix(prhs[2], "u", n, 1);
  OptionsReader opt(g, prhs[5]);
  problem.ts = opt.scalar("Ts");
  problem.dep_a = read_basis(g, opt, prhs[3], "dims_a", "DepA");
  problem.dep_b = read_basis(g, opt, prhs[4], "dims_b", "DepB");
  problem.nc = opt.integer("nc", 0);
  problem.nd = opt.integer("nd", 0);
  ctid::LpvSettings<double> settings;
  settings.tolerance = opt.scalar("tol", settings.tolerance);
  settings.max_iterations = opt.integer("maxiter", settings.max_iterations);
  if (!(settings.tolerance > 0) || settings.max_iterations < 1 ||
      settings.max_iterations > 10000) {
    g.fail("badOption", "tol must be > 0 and maxiter in 1..10000");
  }
  settings.a_init = opt.matrix("Ainit");
  settings.b_init = opt.matrix("Binit");
  opt.finish();
  if ((settings.a_init.size() == 0) != (settings.b_init.size() == 0)) {
    g.fail("badInput", "Ainit and Binit go together");
  }
  ctid::LpvResult<double> result;
  g.check(ctid::lpv_refined_iv<double>(problem, settings, &result));
  auto put = [&](int i, const Eigen::MatrixXd& m) {
    if (nlhs > i || i == 0) {
      plhs[i] = ctid::mex::make_output_matrix(m.rows(), m.cols());
      Eigen::Map<Eigen::MatrixXd>(mxGetPr(plhs[i]), m.rows(), m.cols()) = m;
    }
  };
  put(0, result.theta);
  put(1, result.a);
  put(2, result.b);
  put(3, result.c.transpose());
  put(4, result.d.transpose());
  put(5, Eigen::MatrixXd::Constant(1, 1, result.cost));
  put(6, Eigen::MatrixXd::Constant(1, 1, result.iterations));
  put(7, Eigen::MatrixXd::Constant(1, 1, result.converged ? 1.0 : 0.0));
  put(8, result.ysim);
}

}  // namespace

void mexFunction(int nlhs, mxArray* plhs[], int nrhs, const mxArray* prhs[]) {
  ctid::mex::run_gateway("simulLPVCT", {"simulLPVCT", "lpvsrivc", "lpvrivc"},
                         nrhs, prhs, [&](const Gateway& g) {
                           if (g.name() == "simulLPVCT") {
                             simulate(g, nlhs, plhs, nrhs, prhs);
                           } else {
                             estimate(g, nlhs, plhs, nrhs, prhs);
                           }
                         });
}
