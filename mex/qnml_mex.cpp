// MEX gateway of qnml (octave/qnml.m): maximum-likelihood estimation of the
// diagonal of Qn, thesis sec. 3.3 (core: qn_ml.hpp; minimiser: NLopt).
//
//   [q, V, sigma2, evaluations, converged, message] = qnml_mex ("qnml",
//       estimator, "search", q0, lb, ub, free, maxeval, xtol, [], <args>)
//   [V, sigma2] = qnml_mex ("qnml", estimator, "evaluate", [], [], [], [],
//       [], [], Q, <args>)
//
// estimator 'rlssvf' (then <args> are the 18 rlssvf arguments of
// estimator_args.hpp) or 'riv' (the 28 riv arguments); adm must be 'kf' (its
// adg is replaced by diag(q) at every evaluation). q0, lb, ub, free: np
// values in the core's parameter order; Q: np-by-M diagonals to evaluate.
#include <nlopt.h>

#include <vector>

#include "ctid/nlopt_minimizer.hpp"
#include "ctid/qn_ml.hpp"
#include "estimator_args.hpp"

namespace {

using ctid::mex::Gateway;

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

std::vector<double> read_values(const Gateway& g, const mxArray* a,
                                const std::string& what, long np) {
  const double* p = g.matrix(a, what, np, 1, false);
  return std::vector<double>(p, p + np);
}

template <typename Cost>
void search_or_evaluate(const Gateway& g, int nlhs, mxArray* plhs[],
                        const mxArray* prhs[], long np, Cost& cost) {
  const std::string mode = g.text(prhs[2], "mode");
  if (mode == "evaluate") {
    const Eigen::Map<const Eigen::MatrixXd> Q =
        g.eigen_matrix(prhs[9], "the diagonals to evaluate", np, -1);
    if ((Q.array() < 0).any()) {
      g.fail("badInput", "the diagonals to evaluate must be >= 0");
    }
    const long m = static_cast<long>(Q.cols());
    plhs[0] = ctid::mex::make_output_matrix(1, m);
    mxArray* s2 = ctid::mex::make_output_matrix(1, m);
    for (long j = 0; j < m; ++j) {
      std::vector<double> q(Q.col(j).data(), Q.col(j).data() + np);
      mxGetPr(plhs[0])[j] = cost(q, mxGetPr(s2) + j);
    }
    if (nlhs >= 2) plhs[1] = s2;
    return;
  }
  if (mode != "search")
    g.fail("badOption", "mode must be 'search' or 'evaluate'");
  ctid::QnSearchSettings settings;
  settings.q0 = read_values(g, prhs[3], "q0", np);
  settings.lower = read_values(g, prhs[4], "the lower bounds", np);
  settings.upper = read_values(g, prhs[5], "the upper bounds", np);
  const std::vector<double> free = read_values(g, prhs[6], "free", np);
  settings.free.assign(np, false);
  for (long i = 0; i < np; ++i) settings.free[i] = free[i] != 0;
  settings.max_evaluations = g.integer(prhs[7], "maxeval");
  settings.xtol_log10 = g.scalar(prhs[8], "the tolerance");
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
  if (nrhs < 10) g.fail("badInput", "too few arguments (call qnml instead)");
  if (nlhs > 6) g.fail("badInput", "at most 6 outputs");
  const std::string estimator = g.text(prhs[1], "estimator");
  const mxArray* const* args = prhs + 10;
  const int nargs = nrhs - 10;
  if (estimator == "rlssvf") {
    if (nargs != ctid::mex::kRlssvfArguments) {
      g.fail("badInput", "wrong number of rlssvf arguments");
    }
    ctid::RlsSvfConfig<double> config;
    const ctid::RecordView<double> record =
        ctid::mex::read_rlssvf_config(g, args, &config);
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
    search_or_evaluate(g, nlhs, plhs, prhs, ctid::num_estimated(config), cost);
  } else if (estimator == "riv") {
    if (nargs != ctid::mex::kRivArguments) {
      g.fail("badInput", "wrong number of riv arguments");
    }
    ctid::RecursiveIvConfig<double> config;
    ctid::ClosedLoopSignals<double> loop;
    const ctid::RecordView<double> record =
        ctid::mex::read_riv_config(g, args, &config, &loop);
    require_kalman(g, config.adaptation);
    auto run = [loop](const ctid::RecursiveIvConfig<double>& c,
                      const ctid::RecordView<double>& r,
                      const ctid::RecursiveOutputs<double>& o) {
      return ctid::run_recursive_iv(c, r, loop, o);
    };
    LikelihoodCost<ctid::RecursiveIvConfig<double>, decltype(run)> cost(
        config, record, run);
    search_or_evaluate(g, nlhs, plhs, prhs, config.orders.num_parameters(),
                       cost);
  } else {
    g.fail("badOption", "the estimator must be 'rlssvf' or 'riv'");
  }
}

}  // namespace

void mexFunction(int nlhs, mxArray* plhs[], int nrhs, const mxArray* prhs[]) {
  ctid::mex::run_gateway("qnml", {"qnml"}, nrhs, prhs, [&](const Gateway& g) {
    qnml_gateway(g, nlhs, plhs, nrhs, prhs);
  });
}
