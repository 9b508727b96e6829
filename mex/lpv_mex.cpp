// SPDX-License-Identifier: BSD-3-Clause
// Copyright (C) the ctid authors
// MEX gateway of the LPV family (octave/simulLPVCT.m, lpvsrivc.m, lpvrivc.m):
//
//   y = lpv_mex (fname, "simulate", u, Ts, A, depA, dimsA, B, depB, dimsB)
//   [theta, A, B, c, d, J, iterations, converged, ysim] =
//       lpv_mex (fname, "estimate", y, u, Ts, depA, dimsA, depB, dimsB,
//                [nc nd], tol, maxiter, Ainit, Binit)
//
// depA, depB: the dependency arrays reshaped to n_dep-by-(n_coef*N) (the
// column-major storage of CONTSID's n_dep x n_coef x N arrays), dims their
// three sizes [n_dep n_coef N]. Ainit, Binit: [] or the initial model.
#include "ctid/offline/lpv_refined_iv.hpp"
#include "mex_helpers.hpp"

namespace {

using ctid::mex::Gateway;

ctid::LpvBasis<double> read_basis(const Gateway& g, const mxArray* values,
                                  const mxArray* dims, const char* what) {
  const std::vector<int> d =
      g.integer_vector(dims, std::string("the size of ") + what);
  if (d.size() != 3 || d[0] < 1 || d[1] < 1 || d[2] < 1) {
    g.fail("badInput", std::string(what) + " must be n_dep-by-n-by-N");
  }
  ctid::LpvBasis<double> basis;
  basis.num_functions = d[0];
  basis.num_coefficients = d[1];
  basis.num_samples = d[2];
  basis.values = g.matrix(values, what, d[0], static_cast<long>(d[1]) * d[2]);
  return basis;
}

Eigen::MatrixXd optional_matrix(const Gateway& g, const mxArray* a,
                                const char* what) {
  if (mxIsEmpty(a)) return Eigen::MatrixXd();
  return g.eigen_matrix(a, what);
}

void simulate(const Gateway& g, int nlhs, mxArray* plhs[], int nrhs,
              const mxArray* prhs[]) {
  if (nrhs != 10) g.fail("badInput", "simulate takes 10 arguments");
  if (nlhs > 1) g.fail("badInput", "one output");
  const long n = static_cast<long>(mxGetM(prhs[2]));
  const double* u = g.matrix(prhs[2], "u", n, 1);
  const double ts = g.scalar(prhs[3], "Ts");
  const Eigen::MatrixXd a = g.eigen_matrix(prhs[4], "A");
  const ctid::LpvBasis<double> dep_a = read_basis(g, prhs[5], prhs[6], "DepA");
  const Eigen::MatrixXd b = g.eigen_matrix(prhs[7], "B");
  const ctid::LpvBasis<double> dep_b = read_basis(g, prhs[8], prhs[9], "DepB");
  plhs[0] = ctid::mex::make_output_matrix(n, 1);
  g.check(ctid::simulate_lpv<double>(u, n, ts, a, dep_a, b, dep_b,
                                     mxGetPr(plhs[0])));
}

void estimate(const Gateway& g, int nlhs, mxArray* plhs[], int nrhs,
              const mxArray* prhs[]) {
  if (nrhs != 14) g.fail("badInput", "estimate takes 14 arguments");
  if (nlhs > 9) g.fail("badInput", "at most 9 outputs");
  ctid::LpvProblem<double> problem;
  const long n = static_cast<long>(mxGetM(prhs[2]));
  problem.num_samples = n;
  problem.y = g.matrix(prhs[2], "y", n, 1);
  problem.u = g.matrix(prhs[3], "u", n, 1);
  problem.ts = g.scalar(prhs[4], "Ts");
  problem.dep_a = read_basis(g, prhs[5], prhs[6], "DepA");
  problem.dep_b = read_basis(g, prhs[7], prhs[8], "DepB");
  const std::vector<int> noise = g.integer_vector(prhs[9], "[nc nd]");
  if (noise.size() != 2) g.fail("badInput", "[nc nd] must have 2 entries");
  problem.nc = noise[0];
  problem.nd = noise[1];
  ctid::LpvSettings<double> settings;
  settings.tolerance = g.scalar(prhs[10], "tol");
  settings.max_iterations =
      static_cast<int>(g.integer_vector(prhs[11], "maxiter").at(0));
  settings.a_init = optional_matrix(g, prhs[12], "Ainit");
  settings.b_init = optional_matrix(g, prhs[13], "Binit");
  if (settings.a_init.size() == 0 && settings.b_init.size() != 0) {
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
  ctid::mex::run_gateway(
      "simulLPVCT", {"simulLPVCT", "lpvsrivc", "lpvrivc"}, nrhs, prhs,
      [&](const Gateway& g) {
        if (nrhs < 2) g.fail("badInput", "expected a function name and mode");
        const std::string mode = g.text(prhs[1], "the mode");
        if (mode == "simulate") {
          simulate(g, nlhs, plhs, nrhs, prhs);
        } else if (mode == "estimate") {
          estimate(g, nlhs, plhs, nrhs, prhs);
        } else {
          g.fail("badInput", "unknown mode " + mode);
        }
      });
}
