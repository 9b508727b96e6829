// SPDX-License-Identifier: BSD-3-Clause
// Copyright (C) the ctid authors
// MEX gateway of qnml (octave/qnml.m): maximum-likelihood estimation of the
// diagonal of Qn, thesis sec. 3.3 (core: qn_ml.hpp; minimiser: NLopt).
//
//   [q, V, sigma2, evaluations, converged, message] = qnml_mex ("qnml", y,
//       u, t, options)            with options.mode = "search"
//   [V, sigma2] = qnml_mex ("qnml", y, u, t, options)
//                                 with options.mode = "evaluate"
//
// options holds the fields of the estimator (estimator_args.hpp) named by
// its field estimator, 'rlssvf' or 'riv'; adm must be 'kf' (its adg is
// replaced by diag(q) at every evaluation) and precision, if given,
// 'double'. The search reads q0, lb, ub, free (np values each, in the
// core's parameter order), maxeval and xtol (the tolerance on log10 q);
// the evaluation reads Q, the np-by-M diagonals to evaluate.
#include <nlopt.h>

#include <vector>

#include "ctid/adaptation/nlopt_minimizer.hpp"
#include "ctid/adaptation/qn_ml.hpp"
#include "estimator_args.hpp"

namespace {

using ctid::mex::Gateway;
using ctid::mex::OptionsReader;

// V(q) for one diagonal q: runs the estimator with Qn = diag(q) and
// concentrates sigma_e^2 out of eq. (3.23).
template <typename Config, typename Run>
class LikelihoodCost {
 public:
  LikelihoodCost(const Config& config, const ctid::RecordView<double>& record,
                 Run run)
      : config_(config), record_(record), run_(run) {
    const std::size_t n = record.num_samples;
    thm_.assign(n * config.orders.num_parameters(), 0.0);
    error_.assign(n, 0.0);
    innovation_.assign(n, 0.0);
    out_.thm = thm_.data();
    out_.error = error_.data();
    out_.innovation = innovation_.data();
  }

  double operator()(const std::vector<double>& q, double* sigma2) {
    Eigen::VectorXd diagonal(q.size());
    for (std::size_t i = 0; i < q.size(); ++i) diagonal(i) = q[i];
    config_.adaptation =
        ctid::KalmanAdaptation<double>(Eigen::MatrixXd(diagonal.asDiagonal()));
    const ctid::Status status = run_(config_, record_, out_);
    if (!status.ok()) return std::numeric_limits<double>::infinity();
    const ctid::InnovationLikelihood l = ctid::concentrated_likelihood(
        error_.data(), innovation_.data(), record_.num_samples);
    if (sigma2 != nullptr) *sigma2 = l.sigma2;
    return l.cost;
  }

 private:
  Config config_;
  ctid::RecordView<double> record_;
  Run run_;
  std::vector<double> thm_, error_, innovation_;
  ctid::RecursiveOutputs<double> out_;
};

std::vector<double> read_values(const Gateway& g, OptionsReader& opt,
                                const std::string& name, long np) {
  const double* p =
      g.matrix(opt.required(name), "option '" + name + "'", np, 1, false);
  return std::vector<double>(p, p + np);
}

// Reads the mode's fields, checks that no other field is left, and runs.
template <typename Cost>
void search_or_evaluate(const Gateway& g, int nlhs, mxArray* plhs[],
                        OptionsReader& opt, bool evaluate, long np,
                        Cost& cost) {
  if (evaluate) {
    const Eigen::MatrixXd Q = opt.required_matrix("Q", np, -1);
    opt.finish();
    if ((Q.array() < 0).any()) {
      g.fail("badInput", "the diagonals to evaluate must be >= 0");
    }
    if (nlhs > 2) g.fail("badInput", "the evaluation has at most 2 outputs");
    const long m = static_cast<long>(Q.cols());
    plhs[0] = ctid::mex::make_output_matrix(1, m);
    mxArray* s2 = ctid::mex::make_output_matrix(1, m);
    for (long j = 0; j < m; ++j) {
      std::vector<double> q(Q.col(j).data(), Q.col(j).data() + np);
      mxGetPr(plhs[0])[j] = cost(q, mxGetPr(s2) + j);
    }
    if (nlhs >= 2) {
      plhs[1] = s2;
    } else {
      mxDestroyArray(s2);
    }
    return;
  }
  ctid::QnSearchSettings settings;
  settings.q0 = read_values(g, opt, "q0", np);
  settings.lower = read_values(g, opt, "lb", np);
  settings.upper = read_values(g, opt, "ub", np);
  const std::vector<double> free = read_values(g, opt, "free", np);
  settings.free.assign(np, false);
  for (long i = 0; i < np; ++i) settings.free[i] = free[i] != 0;
  settings.max_evaluations = opt.integer("maxeval");
  settings.xtol_log10 = opt.scalar("xtol");
  opt.finish();
  ctid::QnSearchResult result;
  g.check(ctid::estimate_qn_diagonal(
      [&](const std::vector<double>& q, double* sigma2) {
        return cost(q, sigma2);
      },
      settings, ctid::nlopt_minimize, result));
  plhs[0] = ctid::mex::make_output_matrix(np, 1);
  std::copy(result.q.begin(), result.q.end(), mxGetPr(plhs[0]));
  if (nlhs >= 2) plhs[1] = mxCreateDoubleScalar(result.cost);
  if (nlhs >= 3) plhs[2] = mxCreateDoubleScalar(result.sigma2);
  if (nlhs >= 4) plhs[3] = mxCreateDoubleScalar(result.evaluations);
  if (nlhs >= 5) plhs[4] = mxCreateLogicalScalar(result.converged);
  if (nlhs >= 6) plhs[5] = mxCreateString(result.message.c_str());
}

template <typename Adaptation>
void require_kalman(const Gateway& g, const Adaptation& adaptation) {
  if (!std::holds_alternative<ctid::KalmanAdaptation<double>>(adaptation)) {
    g.fail("badOption", "the Qn search needs the Kalman filter (adm 'kf')");
  }
}

void qnml_gateway(const Gateway& g, int nlhs, mxArray* plhs[], int nrhs,
                  const mxArray* prhs[]) {
  if (nrhs != 5) {
    g.fail("badInput",
           "the gateway takes 5 arguments (fname, y, u, t, "
           "options), got " +
               std::to_string(nrhs) + " (call qnml instead)");
  }
  if (nlhs > 6) g.fail("badInput", "at most 6 outputs");
  const ctid::RecordView<double> record =
      ctid::mex::read_record(g, prhs[1], prhs[2], prhs[3]);
  OptionsReader opt(g, prhs[4]);
  enum class Estimator { kRlssvf, kRiv };
  const Estimator estimator = opt.choice<Estimator>(
      "estimator", {{"rlssvf", Estimator::kRlssvf}, {"riv", Estimator::kRiv}},
      Estimator::kRlssvf);
  if (!opt.has("estimator"))
    g.fail("badOption", "option 'estimator' is missing");
  const bool evaluate =
      opt.choice<bool>("mode", {{"search", false}, {"evaluate", true}}, false);
  if (!opt.has("mode")) g.fail("badOption", "option 'mode' is missing");
  if (ctid::mex::read_single_precision(opt)) {
    g.fail("notSupported", "the Qn search runs in double precision only");
  }
  if (estimator == Estimator::kRlssvf) {
    ctid::RlsSvfConfig<double> config;
    ctid::mex::read_rlssvf_config(g, opt, &config);
    require_kalman(g, config.adaptation);
    if (config.form == ctid::UpdateForm::kLevenbergMarquardt) {
      g.fail("badOption", "the Qn search needs a Kalman filter, not LMR");
    }
    g.check(ctid::validate_record(record, config.orders));
    auto run = [](const ctid::RlsSvfConfig<double>& c,
                  const ctid::RecordView<double>& r,
                  const ctid::RecursiveOutputs<double>& o) {
      return ctid::run_rlssvf(c, r, o);
    };
    LikelihoodCost<ctid::RlsSvfConfig<double>, decltype(run)> cost(config,
                                                                   record, run);
    search_or_evaluate(g, nlhs, plhs, opt, evaluate,
                       ctid::num_estimated(config), cost);
  } else {
    ctid::RecursiveIvConfig<double> config;
    ctid::ClosedLoopSignals<double> loop;
    ctid::mex::read_riv_config(g, opt, record, &config, &loop);
    require_kalman(g, config.adaptation);
    auto run = [loop](const ctid::RecursiveIvConfig<double>& c,
                      const ctid::RecordView<double>& r,
                      const ctid::RecursiveOutputs<double>& o) {
      return ctid::run_recursive_iv(c, r, loop, o);
    };
    LikelihoodCost<ctid::RecursiveIvConfig<double>, decltype(run)> cost(
        config, record, run);
    search_or_evaluate(g, nlhs, plhs, opt, evaluate,
                       config.orders.num_parameters(), cost);
  }
}

}  // namespace

void mexFunction(int nlhs, mxArray* plhs[], int nrhs, const mxArray* prhs[]) {
  ctid::mex::run_gateway("qnml", {"qnml"}, nrhs, prhs, [&](const Gateway& g) {
    qnml_gateway(g, nlhs, plhs, nrhs, prhs);
  });
}
