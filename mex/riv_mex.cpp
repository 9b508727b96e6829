// MEX gateway of the recursive IV estimators rivsvf, rsrivc, clrivsvf and
// clrsrivc (octave/private/contsid_riv.m): converts the fixed argument list
// below, runs ctid::run_recursive_iv and returns THM, YH, PSET and the
// number of estimates refused by the stability test.
//
//   [thm, yh, pset, nrej, kappa] = riv_mex (fname, y, u, t, intersample, na,
//   nb, nk,
//       lambda_svf, svf_form, adm, adg, th0, P0, method, tsiv, dtupdate,
//       stability, mtheta_num, mtheta_den, prefilter_gain, A,
//       c_num, c_den, r1, r2)
//
// method 'rivsvf' | 'rsrivc'; stability 'keep' | 'reflect'; prefilter_gain
// 'unit' | 'monic'; mtheta_num/den, A: [] for the defaults; c_num = [] for
// open loop, else the controller C(q^-1) and the N-by-1 r1, r2.
#include "ctid/recursive_iv.hpp"
#include "gateway_common.hpp"

namespace {

using ctid::mex::Gateway;

void riv_gateway(const Gateway& g, int nlhs, mxArray* plhs[], int nrhs,
                 const mxArray* prhs[]) {
  if (nrhs != 26) {
    g.fail("badInput", "the gateway takes 26 arguments, got " +
                           std::to_string(nrhs) + " (call " + g.name() +
                           " instead)");
  }
  if (nlhs > 5) g.fail("badInput", "at most 5 outputs");
  ctid::RecursiveIvConfig<double> config;
  const ctid::RecordView<double> record =
      ctid::mex::read_recursive_arguments(g, prhs, &config);
  const long np = config.orders.num_parameters();
  const std::string method = g.text(prhs[14], "method");
  if (method == "rivsvf") {
    config.method = ctid::IvMethod::kRivsvf;
  } else if (method == "rsrivc") {
    config.method = ctid::IvMethod::kRsrivc;
  } else {
    g.fail("badOption", "method must be 'rivsvf' or 'rsrivc'");
  }
  config.t_s_iv = g.scalar(prhs[15], "tsiv");
  config.dtupdate = g.scalar(prhs[16], "dtupdate");
  const std::string stability = g.text(prhs[17], "stability");
  if (stability == "keep") {
    config.stability = ctid::StabilityPolicy::kKeepLast;
  } else if (stability == "reflect") {
    config.stability = ctid::StabilityPolicy::kReflect;
  } else {
    g.fail("badOption", "stability must be 'keep' or 'reflect'");
  }
  if (!mxIsEmpty(prhs[18])) {
    config.m_theta =
        ctid::mex::read_transfer_function(g, prhs[18], prhs[19], "M_theta");
  }
  const std::string gain = g.text(prhs[20], "prefilter gain");
  if (gain == "unit") {
    config.prefilter_gain = ctid::PrefilterGain::kUnitStaticGain;
  } else if (gain == "monic") {
    config.prefilter_gain = ctid::PrefilterGain::kMonic;
  } else {
    g.fail("badOption", "the prefilter gain must be 'unit' or 'monic'");
  }
  if (!mxIsEmpty(prhs[21])) {
    config.initial_denominator =
        g.eigen_matrix(prhs[21], "A", 1, config.orders.na).transpose();
  }
  ctid::ClosedLoopSignals<double> loop;
  if (!mxIsEmpty(prhs[22])) {
    config.closed_loop = true;
    config.controller = ctid::mex::read_transfer_function(g, prhs[22], prhs[23],
                                                          "the controller");
    const long n = record.num_samples;
    loop.r1 = g.matrix(prhs[24], "r1", n, 1);
    loop.r2 = g.matrix(prhs[25], "r2", n, 1);
  }
  g.check(ctid::validate(config));

  const std::size_t n = record.num_samples;
  ctid::RecursiveOutputs<double> out =
      ctid::mex::make_recursive_outputs(nlhs, plhs, n, np);
  ctid::mex::request_kappa(nlhs, plhs, 4, n, &out);
  long rejections = 0;
  g.check(ctid::run_recursive_iv(config, record, loop, out, &rejections));
  if (nlhs >= 4) {
    plhs[3] = mxCreateDoubleScalar(static_cast<double>(rejections));
  }
}

}  // namespace

void mexFunction(int nlhs, mxArray* plhs[], int nrhs, const mxArray* prhs[]) {
  ctid::mex::run_gateway(
      "rsrivc", {"rivsvf", "rsrivc", "clrivsvf", "clrsrivc"}, nrhs, prhs,
      [&](const Gateway& g) { riv_gateway(g, nlhs, plhs, nrhs, prhs); });
}
