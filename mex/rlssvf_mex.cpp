// MEX gateway of rlssvf (octave/rlssvf.m): converts the fixed argument list
// below, runs ctid::run_rlssvf and returns THM, YH and PSET.
//
//   [thm, yh, pset, kappa] = rlssvf_mex(fname, y, u, t, intersample, na, nb,
//   nk,
//                                lambda_svf, svf_form, adm, adg, th0, P0)
//
// t is Ts (scalar) or the N sampling instants; adm is 'ff' or 'kf'; adg the
// forgetting factor or the np-by-np Qn; th0 and P0 may be [] (defaults).
// YH, PSET and kappa_2(P) per sample are computed only when requested.
#include "ctid/rlssvf.hpp"
#include "gateway_common.hpp"

namespace {

using ctid::mex::Gateway;

void rlssvf_gateway(const Gateway& g, int nlhs, mxArray* plhs[], int nrhs,
                    const mxArray* prhs[]) {
  if (nrhs != 14) {
    g.fail("badInput", "the gateway takes 14 arguments, got " +
                           std::to_string(nrhs) + " (call rlssvf instead)");
  }
  if (nlhs > 4) g.fail("badInput", "at most 4 outputs (THM, YH, PSET, kappa)");
  ctid::RlsSvfConfig<double> config;
  const ctid::RecordView<double> record =
      ctid::mex::read_recursive_arguments(g, prhs, &config);
  const long np = config.orders.num_parameters();
  g.check(ctid::validate(config));
  g.check(ctid::validate_record(record, config.orders));

  const std::size_t n = record.num_samples;
  ctid::RecursiveOutputs<double> out =
      ctid::mex::make_recursive_outputs(nlhs, plhs, n, np);
  ctid::mex::request_kappa(nlhs, plhs, 3, n, &out);
  g.check(ctid::run_rlssvf(config, record, out));
}

}  // namespace

void mexFunction(int nlhs, mxArray* plhs[], int nrhs, const mxArray* prhs[]) {
  ctid::mex::run_gateway(
      "rlssvf", {"rlssvf"}, nrhs, prhs,
      [&](const Gateway& g) { rlssvf_gateway(g, nlhs, plhs, nrhs, prhs); });
}
