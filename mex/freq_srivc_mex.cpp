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
// the options of freq_srivc_options.hpp, read from that table with its
// defaults (na, nb required; one entry per input, y = sum_j B_j/A_j U_j);
// `freq_srivc_mex (fname, "options")` returns the table. theta = [a; b]
// or [a; b; td] (estimate_delay; several inputs: [a_1; ..; a_m; b_1; ..;
// b_m]); cov its covariance; info: delay, noise_variance, loss,
// iterations, converged, stable, reason, and w, Y, U the data the fit used
// (core freq_fit_data: the frequencies where some input is nonzero, inside
// the Focus band `band`; the delay range's defaults from them and `period`).
//
//   [w, Y, U, period] = freq_srivc_mex (fname, "relay", y, u, opts)
//
// the limit cycle of a relay-feedback record (y, u N-by-1) as frequency
// data (core/include/ctid/offline/relay_frequency_data.hpp); opts fields
// Ts (regular sampling), intsamp (true: y_k is the mean of y over the
// sampling interval; default false).
#include <algorithm>
#include <complex>
#include <vector>

#include "ctid/offline/freq_srivc.hpp"
#include "ctid/offline/freq_srivc_options.hpp"
#include "ctid/offline/relay_frequency_data.hpp"
#include "estimator_args.hpp"
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

mxArray* complex_output(const std::vector<std::complex<double>>& v, long rows,
                        long cols) {
  mxArray* a = mxCreateDoubleMatrix(rows, cols, mxCOMPLEX);
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
  if (nrhs != 5) {
    g.fail("badInput",
           "the relay method takes 5 arguments, got " + std::to_string(nrhs));
  }
  if (nlhs > 4) g.fail("badInput", "at most 4 outputs");
  g.require_real_double(prhs[2], "y");
  const long n = static_cast<long>(mxGetNumberOfElements(prhs[2]));
  const double* y = g.matrix(prhs[2], "y", n, 1);
  const double* u = g.matrix(prhs[3], "u", n, 1);
  OptionsReader opt(g, prhs[4]);
  const double ts = opt.scalar("Ts");
  const bool intsamp = opt.flag("intsamp", false);
  opt.finish();
  ctid::RelayFrequencyData<double> d;
  g.check(ctid::relay_frequency_data(y, u, n, ts, intsamp, &d));
  plhs[0] = ctid::mex::make_output_matrix(static_cast<long>(d.w.size()), 1);
  std::copy(d.w.begin(), d.w.end(), mxGetPr(plhs[0]));
  const long k = static_cast<long>(d.w.size());
  if (nlhs >= 2) plhs[1] = complex_output(d.y, k, 1);
  if (nlhs >= 3) plhs[2] = complex_output(d.u, k, 1);
  if (nlhs >= 4) plhs[3] = mxCreateDoubleScalar(d.period);
}

void freq_gateway(const Gateway& g, int nlhs, mxArray* plhs[], int nrhs,
                  const mxArray* prhs[]) {
  if (ctid::mex::asks_for_options(nrhs, prhs)) {
    plhs[0] =
        ctid::mex::option_table_struct(ctid::freq_srivc_options<double>());
    return;
  }
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
  ctid::FreqConfig<double> config;
  ctid::mex::read_option_table(g, opt, ctid::freq_srivc_options<double>(),
                               &config);
  opt.finish();
  ctid::FreqSettings<double> s;
  ctid::FreqFitData<double> used;
  g.check(ctid::freq_fit_data(config, w, Y.data(),
                              U.empty() ? nullptr : U.data(), K,
                              static_cast<std::size_t>(inputs), &used, &s));
  long np = 0;
  for (const ctid::FreqChannel<double>& c : s.channels()) np += c.na + c.nb;

  const ctid::FreqData<double> data = used.view();
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
    const char* fields[] = {
        "delay",  "noise_variance", "loss", "iterations", "converged",
        "stable", "reason",         "w",    "Y",          "U"};
    mxArray* info = mxCreateStructMatrix(1, 1, 10, fields);
    mxSetField(info, 0, "delay", mxCreateDoubleScalar(result.delay));
    mxSetField(info, 0, "noise_variance",
               mxCreateDoubleScalar(result.noise_variance));
    mxSetField(info, 0, "loss", mxCreateDoubleScalar(result.loss));
    mxSetField(info, 0, "iterations", mxCreateDoubleScalar(result.iterations));
    mxSetField(info, 0, "converged", mxCreateLogicalScalar(result.converged));
    mxSetField(info, 0, "stable", mxCreateLogicalScalar(result.stable));
    mxSetField(info, 0, "reason", mxCreateString(result.reason.c_str()));
    const long k_used = static_cast<long>(used.w.size());
    mxArray* w_used = ctid::mex::make_output_matrix(k_used, 1);
    std::copy(used.w.begin(), used.w.end(), mxGetPr(w_used));
    mxSetField(info, 0, "w", w_used);
    mxSetField(info, 0, "Y", complex_output(used.y, k_used, 1));
    mxSetField(info, 0, "U",
               used.u.empty() ? mxCreateDoubleMatrix(0, 0, mxREAL)
                              : complex_output(used.u, k_used, inputs));
    plhs[2] = info;
  }
}

}  // namespace

void mexFunction(int nlhs, mxArray* plhs[], int nrhs, const mxArray* prhs[]) {
  ctid::mex::run_gateway(
      "srivc", {"srivc", "tffsrivc", "tffcoe", "oe", "tfest"}, nrhs, prhs,
      [&](const Gateway& g) { freq_gateway(g, nlhs, plhs, nrhs, prhs); });
}
