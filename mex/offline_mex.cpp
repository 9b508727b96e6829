// MEX gateway of the offline estimators lssvf, ivsvf, srivc and clsrivc
// (octave/private/contsid_offline.m):
//
//   [theta, cov, sigma2, iterations, converged] = offline_mex (fname, y, u,
//       t, intersample, na, nb, nk, lambda_svf, svf_form, method, tol,
//       maxiter, theta_init, c_num, c_den, r1, r2)
//
// theta is in the core's order [a1 .. a_na, b ..]; method 'lssvf' |
// 'ivsvf' | 'srivc' | 'clsrivc'; theta_init [] (IVSVF/CLIVSVF start) or
// np values; c_num = [] except for clsrivc. An SRIVC that does not converge
// returns its last iterate with converged = false (the front-end warns).
//
//   m = offline_mex (fname, y, u, t, intersample, na, nb, nk, lambda_svf,
//       svf_form, "scaling", ...)
// returns instead the diagonal of the scaling matrix M_s of eq. (3.54) for
// the SVF regression of this record (svfscaling, rlssvf/rsrivc 'scaling').
#include "ctid/refined_iv.hpp"
#include "ctid/scaling.hpp"
#include "gateway_common.hpp"

namespace {

using ctid::mex::Gateway;

void offline_gateway(const Gateway& g, int nlhs, mxArray* plhs[], int nrhs,
                     const mxArray* prhs[]) {
  if (nrhs != 18) {
    g.fail("badInput", "the gateway takes 18 arguments, got " +
                           std::to_string(nrhs) + " (call " + g.name() +
                           " instead)");
  }
  if (nlhs > 5) g.fail("badInput", "at most 5 outputs");
  const ctid::RecordView<double> record =
      ctid::mex::read_record(g, prhs[1], prhs[2], prhs[3]);
  ctid::SvfSettings<double> svf;
  svf.u_intersample = ctid::mex::read_intersample(g, prhs[4]);
  const ctid::ModelOrders orders =
      ctid::mex::read_orders(g, prhs[5], prhs[6], prhs[7]);
  svf.lambda_svf = g.scalar(prhs[8], "lambda_svf");
  svf.normalised = ctid::mex::read_normalised(g, prhs[9]);
  const std::string method = g.text(prhs[10], "method");
  if (method == "scaling") {
    ctid::Vector<double> m;
    g.check(ctid::svf_scaling(orders, svf, record, m));
    plhs[0] = ctid::mex::make_output_matrix(m.size(), 1);
    std::copy(m.data(), m.data() + m.size(), mxGetPr(plhs[0]));
    return;
  }
  ctid::SrivcSettings<double> settings;
  settings.tolerance = g.scalar(prhs[11], "Tol");
  settings.max_iterations = g.integer(prhs[12], "MaxIter");
  const long np = orders.num_parameters();
  if (!mxIsEmpty(prhs[13])) {
    settings.theta_init =
        g.eigen_matrix(prhs[13], "the initial estimate", np, 1);
  }
  ctid::OfflineEstimate<double> estimate;
  ctid::Status status;
  if (method == "lssvf") {
    status = ctid::lssvf(orders, svf, record, &estimate);
  } else if (method == "ivsvf") {
    status = ctid::ivsvf(orders, svf, record, &estimate);
  } else if (method == "srivc") {
    status = ctid::srivc(orders, svf, settings, record, &estimate);
  } else if (method == "clsrivc") {
    const ctid::DiscreteTransferFunction<double> controller =
        ctid::mex::read_transfer_function(g, prhs[14], prhs[15],
                                          "the controller");
    const long n = record.num_samples;
    const double* r1 = g.matrix(prhs[16], "r1", n, 1);
    const double* r2 = g.matrix(prhs[17], "r2", n, 1);
    status = ctid::clsrivc(orders, svf, settings, record, r1, r2, controller,
                           &estimate);
  } else {
    g.fail("badOption", "method must be lssvf, ivsvf, srivc or clsrivc");
  }
  if (status.code() != ctid::ErrorCode::kNotConverged) g.check(status);
  if (estimate.theta.size() != np) {
    g.fail("numericalFailure", "no estimate was produced");
  }
  plhs[0] = ctid::mex::make_output_matrix(np, 1);
  std::copy(estimate.theta.data(), estimate.theta.data() + np,
            mxGetPr(plhs[0]));
  if (nlhs >= 2) {
    plhs[1] = ctid::mex::make_output_matrix(np, np);
    if (estimate.covariance.rows() == np && estimate.covariance.cols() == np) {
      std::copy(estimate.covariance.data(),
                estimate.covariance.data() + np * np, mxGetPr(plhs[1]));
    }
  }
  if (nlhs >= 3) plhs[2] = mxCreateDoubleScalar(estimate.noise_variance);
  if (nlhs >= 4) plhs[3] = mxCreateDoubleScalar(estimate.iterations);
  if (nlhs >= 5) plhs[4] = mxCreateLogicalScalar(estimate.converged);
}

}  // namespace

void mexFunction(int nlhs, mxArray* plhs[], int nrhs, const mxArray* prhs[]) {
  ctid::mex::run_gateway("srivc",
                         {"lssvf", "ivsvf", "srivc", "clsrivc", "svfscaling",
                          "rlssvf", "rivsvf", "rsrivc", "clrivsvf", "clrsrivc"},
                         nrhs, prhs, [&](const Gateway& g) {
                           offline_gateway(g, nlhs, plhs, nrhs, prhs);
                         });
}
