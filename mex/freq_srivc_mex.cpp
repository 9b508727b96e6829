// SPDX-License-Identifier: BSD-3-Clause
// Copyright (C) the ctid authors
// MEX gateway of the frequency-domain estimators (core/include/ctid/
// freq_srivc.hpp), called by octave/private/contsid_freq.m (srivc,
// tffsrivc, tffcoe; oe and tfest on frequency data):
//
//   [theta, cov, info] = freq_srivc_mex (fname, w, Y, U, opts)
//
// w K-by-1 frequencies (rad/s, >= 0); Y K-by-1 complex output (or the
// frequency response); U K-by-m complex inputs, or [] (U = 1). opts fields:
// na, nb (required; one entry per input, y = sum_j B_j/A_j U_j), tol, maxiter,
// delay, estimate_delay, td_min, td_max, num_td, grid, output_error, theta_init
// ([a b]). theta = [a; b] or [a; b; td] (several inputs: [a_1; ..; a_m; b_1;
// ..; b_m]) (estimate_delay); cov its covariance; info: delay, noise_variance,
// loss, iterations, converged, stable, reason.
//
//   [w, Y, U, period] = freq_srivc_mex (fname, "relay", y, u, Ts, intsamp)
//
// the limit cycle of a relay-feedback record (y, u N-by-1, regular
// sampling Ts) as frequency data (core/include/ctid/offline/
// relay_frequency_data.hpp); intsamp true: y_k is the mean of y over the
// sampling interval.
#include <algorithm>
#include <complex>
#include <vector>

#include "ctid/offline/freq_srivc.hpp"
#include "ctid/offline/relay_frequency_data.hpp"
#include "gateway_common.hpp"
#include "options_reader.hpp"

namespace {

using ctid::mex::Gateway;
using ctid::mex::OptionsReader;

std::vector<std::complex<double>> complex_column(const Gateway& g,
                                                 const mxArray* a,
                                                 const char* name, long n) {
  // (a vector, or the K-by-m matrix U read as its n = K m values)
  if (!mxIsDouble(a) || mxIsSparse(a) ||
      mxGetNumberOfElements(a) != static_cast<size_t>(n) ||
      (mxGetM(a) != 1 && mxGetN(a) != 1 && std::string(name) != "U")) {
    g.fail("badInput", std::string(name) + " must be a double vector of " +
                           std::to_string(n) + " values");
  }
  std::vector<std::complex<double>> v(n);
  const double* re = mxGetPr(a);
  const double* im = mxIsComplex(a) ? mxGetPi(a) : nullptr;
  for (long k = 0; k < n; ++k) {
    v[k] = std::complex<double>(re[k], im != nullptr ? im[k] : 0.0);
  }
  return v;
}

mxArray* complex_output(const std::vector<std::complex<double>>& v) {
  mxArray* a = mxCreateDoubleMatrix(v.size(), 1, mxCOMPLEX);
  double* re = mxGetPr(a);
  double* im = mxGetPi(a);
  for (std::size_t k = 0; k < v.size(); ++k) {
    re[k] = v[k].real();
    im[k] = v[k].imag();
  }
  return a;
}

void relay_gateway(const Gateway& g, int nlhs, mxArray* plhs[], int nrhs,
                   const mxArray* prhs[]) {
  if (nrhs != 6) {
    g.fail("badInput",
           "the relay method takes 6 arguments, got " + std::to_string(nrhs));
  }
  if (nlhs > 4) g.fail("badInput", "at most 4 outputs");
  g.require_real_double(prhs[2], "y");
  const long n = static_cast<long>(mxGetNumberOfElements(prhs[2]));
  const double* y = g.matrix(prhs[2], "y", n, 1);
  const double* u = g.matrix(prhs[3], "u", n, 1);
  const double ts = g.scalar(prhs[4], "Ts");
  const bool intsamp = g.scalar(prhs[5], "intsamp") != 0;
  ctid::RelayFrequencyData<double> d;
  g.check(ctid::relay_frequency_data(y, u, n, ts, intsamp, &d));
  plhs[0] = ctid::mex::make_output_matrix(static_cast<long>(d.w.size()), 1);
  std::copy(d.w.begin(), d.w.end(), mxGetPr(plhs[0]));
  if (nlhs >= 2) plhs[1] = complex_output(d.y);
  if (nlhs >= 3) plhs[2] = complex_output(d.u);
  if (nlhs >= 4) plhs[3] = mxCreateDoubleScalar(d.period);
}

void freq_gateway(const Gateway& g, int nlhs, mxArray* plhs[], int nrhs,
                  const mxArray* prhs[]) {
  if (nrhs >= 2 && mxIsChar(prhs[1])) {
    char word[8] = {0};
    if (mxGetString(prhs[1], word, sizeof word) != 0 ||
        std::string(word) != "relay") {
      g.fail("badInput", "the only method is 'relay'");
    }
    relay_gateway(g, nlhs, plhs, nrhs, prhs);
    return;
  }
  if (nrhs != 5) {
    g.fail("badInput",
           "the gateway takes 5 arguments, got " + std::to_string(nrhs));
  }
  if (nlhs > 3) g.fail("badInput", "at most 3 outputs");
  g.require_real_double(prhs[1], "w");
  const long K = static_cast<long>(mxGetNumberOfElements(prhs[1]));
  if (K < 1) g.fail("badInput", "w must not be empty");
  const double* w = g.matrix(prhs[1], "w", K, 1);
  const std::vector<std::complex<double>> Y =
      complex_column(g, prhs[2], "Y", K);
  // U: K-by-m, one column per input (several inputs: y = sum_j G_j U_j)
  std::vector<std::complex<double>> U;
  long inputs = 1;
  if (!mxIsEmpty(prhs[3])) {
    if (mxGetNumberOfDimensions(prhs[3]) != 2 ||
        mxGetM(prhs[3]) != static_cast<size_t>(K)) {
      g.fail("badInput",
             "U must have one row per frequency (" + std::to_string(K) + ")");
    }
    inputs = static_cast<long>(mxGetN(prhs[3]));
    U = complex_column(g, prhs[3], "U", K * inputs);
  }

  OptionsReader opt(g, prhs[4]);
  ctid::FreqSettings<double> s;
  // na, nb, delay: one entry per input (a scalar: one input)
  const std::vector<int> na = opt.integer_vector("na");
  const std::vector<int> nb = opt.integer_vector("nb");
  const Eigen::MatrixXd delay = opt.matrix("delay");
  if (na.size() != static_cast<size_t>(inputs) ||
      nb.size() != static_cast<size_t>(inputs) ||
      (delay.size() != 0 && delay.size() != inputs)) {
    g.fail("dimensionMismatch", "na, nb and delay need one entry per input (" +
                                    std::to_string(inputs) + ")");
  }
  s.na = na[0];
  s.nb = nb[0];
  s.delay = delay.size() != 0 ? delay(0) : 0.0;
  long np = 0;
  for (long j = 0; j < inputs; ++j) {
    ctid::FreqChannel<double> c;
    c.na = na[j];
    c.nb = nb[j];
    c.delay = delay.size() != 0 ? delay(j) : 0.0;
    if (inputs > 1) s.inputs.push_back(c);
    if (c.na < 0 || c.nb < 0 || c.na > 1000 || c.nb > 1000) {
      g.fail("badInput", "na and nb must lie in [0, 1000]");
    }
    np += c.na + c.nb;
  }
  s.tolerance = opt.scalar("tol", 1e-8);
  s.max_iterations = opt.integer("maxiter", 50);
  s.estimate_delay = opt.flag("estimate_delay", false);
  s.td_min = opt.scalar("td_min", 0);
  s.td_max = opt.scalar("td_max", 0);
  s.num_td = opt.integer("num_td", 50);
  s.grid = opt.flag("grid", true);
  s.output_error = opt.flag("output_error", false);
  const Eigen::MatrixXd init = opt.matrix("theta_init");
  if (init.size() > 0) {
    s.theta_init = Eigen::Map<const Eigen::VectorXd>(init.data(), init.size());
  }
  opt.finish();

  ctid::FreqData<double> data;
  data.w = w;
  data.y = Y.data();
  data.u = U.empty() ? nullptr : U.data();
  data.num_frequencies = K;
  data.num_inputs = static_cast<int>(inputs);
  ctid::FreqResult<double> result;
  const ctid::Status status = ctid::freq_srivc(s, data, &result);
  if (status.code() != ctid::ErrorCode::kNotConverged) g.check(status);

  if (s.estimate_delay) ++np;
  plhs[0] = ctid::mex::make_output_matrix(np, 1);
  double* th = mxGetPr(plhs[0]);
  const long na_total = static_cast<long>(result.a.size());
  std::copy(result.a.data(), result.a.data() + na_total, th);
  std::copy(result.b.data(), result.b.data() + result.b.size(), th + na_total);
  if (s.estimate_delay) th[np - 1] = result.delay;
  if (nlhs >= 2) {
    plhs[1] = ctid::mex::make_output_matrix(np, np);
    std::copy(result.covariance.data(), result.covariance.data() + np * np,
              mxGetPr(plhs[1]));
  }
  if (nlhs >= 3) {
    const char* fields[] = {"delay",      "noise_variance", "loss",
                            "iterations", "converged",      "stable",
                            "reason"};
    mxArray* info = mxCreateStructMatrix(1, 1, 7, fields);
    mxSetField(info, 0, "delay", mxCreateDoubleScalar(result.delay));
    mxSetField(info, 0, "noise_variance",
               mxCreateDoubleScalar(result.noise_variance));
    mxSetField(info, 0, "loss", mxCreateDoubleScalar(result.loss));
    mxSetField(info, 0, "iterations", mxCreateDoubleScalar(result.iterations));
    mxSetField(info, 0, "converged", mxCreateLogicalScalar(result.converged));
    mxSetField(info, 0, "stable", mxCreateLogicalScalar(result.stable));
    mxSetField(info, 0, "reason", mxCreateString(result.reason.c_str()));
    plhs[2] = info;
  }
}

}  // namespace

void mexFunction(int nlhs, mxArray* plhs[], int nrhs, const mxArray* prhs[]) {
  ctid::mex::run_gateway(
      "srivc", {"srivc", "tffsrivc", "tffcoe", "oe", "tfest"}, nrhs, prhs,
      [&](const Gateway& g) { freq_gateway(g, nlhs, plhs, nrhs, prhs); });
}
