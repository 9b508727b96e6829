// SPDX-License-Identifier: BSD-3-Clause
// Copyright (C) the ctid authors
// MEX gateway of residtrace's physical realisations (core/include/ctid/
// simulation/physical_realisations.hpp), used by
// octave/private/residtrace_physsim.m:
//
//   x      = physsim_mex (fname, W, options)    options.kind = "stop"
//   [y, z] = physsim_mex (fname, W, options)    options.kind = "cascade"
//
// fname: the public function ("residtrace"). W: N-by-m channel signals,
// already delayed. options.kind: "stop" or "cascade" (the default). Other
// fields for "stop": ts, f (1-by-n, f1..fn of the monic F), b (n-by-m,
// channel j's numerator right-aligned in column j), substeps, lo and hi (the
// levels of x1; absent or []: none). For "cascade": ts, g ("sqrt" or
// "lin"), b (m-by-K, one column per parameter set), d, alpha, gamma, c
// (1-by-K each), hi (1-by-K upper levels of the inner state; absent or []:
// none), ho (1-by-K upper levels of the outer state h; absent or []:
// none), spill (1-by-K shares in [0, 1] of the inner overflow that fall
// into h; absent or []: 0), substeps, z0 and h0 (1-by-K initial states
// of z and h; both absent or []: at rest for the first sample's inflow).
// y, z: N-by-K.
#include "ctid/simulation/physical_realisations.hpp"
#include "options_reader.hpp"

namespace {

using ctid::mex::Gateway;

Eigen::VectorXd row(const Eigen::MatrixXd& a) { return a.row(0).transpose(); }

void physsim_gateway(const Gateway& g, int nlhs, mxArray* plhs[], int nrhs,
                     const mxArray* prhs[]) {
  if (nrhs != 3) {
    g.fail("badInput",
           "the gateway takes 3 arguments (fname, W, options), "
           "got " +
               std::to_string(nrhs));
  }
  g.require_real_double(prhs[1], "W");
  const long n = static_cast<long>(mxGetM(prhs[1]));
  const long m = static_cast<long>(mxGetN(prhs[1]));
  const double* W = g.matrix(prhs[1], "W", n, m);
  ctid::mex::OptionsReader opt(g, prhs[2]);
  const bool stop =
      opt.choice<bool>("kind", {{"stop", true}, {"cascade", false}}, false);
  if (stop) {
    if (nlhs > 1) g.fail("badInput", "at most 1 output for 'stop'");
    ctid::EndStopConfig<double> c;
    c.ts = opt.scalar("ts");
    c.f = row(opt.required_matrix("f", 1, -1));
    c.b = opt.required_matrix("b", c.f.size(), m);
    c.substeps = opt.integer("substeps", 1);
    const Eigen::MatrixXd lo = opt.matrix("lo", 1, 1);
    const Eigen::MatrixXd hi = opt.matrix("hi", 1, 1);
    if (lo.size() == 1) c.lo = lo(0, 0);
    if (hi.size() == 1) c.hi = hi(0, 0);
    opt.finish();
    plhs[0] = ctid::mex::make_output_matrix(n, 1);
    g.check(ctid::simulate_end_stop<double>(c, W, n, mxGetPr(plhs[0])));
    return;
  }
  if (nlhs > 2) g.fail("badInput", "at most 2 outputs (y, z) for 'cascade'");
  ctid::CascadeConfig<double> c;
  c.ts = opt.scalar("ts");
  c.sqrt_nodes = opt.choice<bool>("g", {{"sqrt", true}, {"lin", false}}, true);
  c.b = opt.required_matrix("b", m, -1);
  const long K = static_cast<long>(c.b.cols());
  c.d = row(opt.required_matrix("d", 1, K));
  c.alpha = row(opt.required_matrix("alpha", 1, K));
  c.gamma = row(opt.required_matrix("gamma", 1, K));
  c.c = row(opt.required_matrix("c", 1, K));
  const Eigen::MatrixXd hi = opt.matrix("hi", 1, K);
  c.hi = hi.size() > 0 ? row(hi)
                       : Eigen::VectorXd::Constant(
                             K, std::numeric_limits<double>::infinity());
  const Eigen::MatrixXd ho = opt.matrix("ho", 1, K);
  if (ho.size() > 0) c.ho = row(ho);
  const Eigen::MatrixXd spill = opt.matrix("spill", 1, K);
  if (spill.size() > 0) {
    if ((spill.array() < 0).any() || (spill.array() > 1).any()) {
      g.fail("badInput", "spill must lie in [0, 1]");
    }
    c.spill = row(spill);
  }
  c.substeps = opt.integer("substeps", 1);
  const Eigen::MatrixXd z0 = opt.matrix("z0", 1, K);
  const Eigen::MatrixXd h0 = opt.matrix("h0", 1, K);
  if (z0.size() != h0.size()) {
    g.fail("badInput", "z0 and h0 are given together");
  }
  if (z0.size() > 0) {
    c.z0 = row(z0);
    c.h0 = row(h0);
  }
  opt.finish();
  plhs[0] = ctid::mex::make_output_matrix(n, K);
  double* z = nullptr;
  if (nlhs >= 2) {
    plhs[1] = ctid::mex::make_output_matrix(n, K);
    z = mxGetPr(plhs[1]);
  }
  g.check(ctid::simulate_cascade<double>(c, W, n, mxGetPr(plhs[0]), z));
}

}  // namespace

void mexFunction(int nlhs, mxArray* plhs[], int nrhs, const mxArray* prhs[]) {
  ctid::mex::run_gateway(
      "residtrace", {"residtrace"}, nrhs, prhs,
      [&](const Gateway& g) { physsim_gateway(g, nlhs, plhs, nrhs, prhs); });
}
