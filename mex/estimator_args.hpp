// The argument lists of the recursive gateways (rlssvf_mex, riv_mex) and
// what qnml_mex reuses of them: reading a whole estimator configuration,
// running it in double or single precision, and building the info struct.
//
// rlssvf argument list (after fname), 18 arguments:
//   y, u, t, intersample, na, nb, nk, lambda_svf, svf_form, adm, adg, th0,
//   P0, form, Gamma, scaling, ic, tsls
// riv argument list (after fname), 28 arguments:
//   y, u, t, intersample, na, nb, nk, lambda_svf, svf_form, adm, adg, th0,
//   P0, method, tsiv, dtupdate, stability, mtheta_num, mtheta_den,
//   prefilter_gain, A, c_num, c_den, r1, r2, scaling, aw_gamma, aw_lambda
// form 'standard' | 'potter' | 'lmr'; Gamma, scaling, th0, P0, A, mtheta,
// c_num: [] for none/defaults; ic 0/1; aw_gamma 0: no conditional updating.
#pragma once

#include <vector>

#include "ctid/recursive_iv.hpp"
#include "ctid/rlssvf.hpp"
#include "gateway_common.hpp"

namespace ctid::mex {

constexpr int kRlssvfArguments = 18;
constexpr int kRivArguments = 28;

inline UpdateForm read_update_form(const Gateway& g, const mxArray* a) {
  const std::string s = g.text(a, "the update form");
  if (s == "standard") return UpdateForm::kStandard;
  if (s == "potter") return UpdateForm::kPotter;
  if (s == "lmr") return UpdateForm::kLevenbergMarquardt;
  g.fail("badOption", "the update form must be 'standard', 'potter' or 'lmr'");
}

inline Vector<double> read_scaling(const Gateway& g, const mxArray* a, long n) {
  if (mxIsEmpty(a)) return Vector<double>();
  return g.eigen_matrix(a, "the scaling M_s", n, 1);
}

// prhs[0..17] as listed above.
inline RecordView<double> read_rlssvf_config(const Gateway& g,
                                             const mxArray* const prhs[],
                                             RlsSvfConfig<double>* config) {
  const RecordView<double> record = read_record(g, prhs[0], prhs[1], prhs[2]);
  config->svf.u_intersample = read_intersample(g, prhs[3]);
  config->orders = read_orders(g, prhs[4], prhs[5], prhs[6]);
  config->svf.lambda_svf = g.scalar(prhs[7], "lambda_svf");
  config->svf.normalised = read_normalised(g, prhs[8]);
  config->initial_conditions = g.scalar(prhs[16], "ic") != 0;
  const long n = num_estimated(*config);
  config->adaptation = read_adaptation(g, prhs[9], prhs[10], n);
  read_initial_estimate(g, prhs[11], prhs[12], n, &config->theta0, &config->P0);
  config->form = read_update_form(g, prhs[13]);
  if (!mxIsEmpty(prhs[14]))
    config->lmr_gamma = g.eigen_matrix(prhs[14], "Gamma", n, n);
  config->scaling = read_scaling(g, prhs[15], n);
  config->t_s_ls = g.scalar(prhs[17], "tsls");
  g.check(validate(*config));
  return record;
}

// prhs[0..27] as listed above.
inline RecordView<double> read_riv_config(const Gateway& g,
                                          const mxArray* const prhs[],
                                          RecursiveIvConfig<double>* config,
                                          ClosedLoopSignals<double>* loop) {
  const RecordView<double> record = read_record(g, prhs[0], prhs[1], prhs[2]);
  config->svf.u_intersample = read_intersample(g, prhs[3]);
  config->orders = read_orders(g, prhs[4], prhs[5], prhs[6]);
  config->svf.lambda_svf = g.scalar(prhs[7], "lambda_svf");
  config->svf.normalised = read_normalised(g, prhs[8]);
  const long np = config->orders.num_parameters();
  config->adaptation = read_adaptation(g, prhs[9], prhs[10], np);
  read_initial_estimate(g, prhs[11], prhs[12], np, &config->theta0,
                        &config->P0);
  const std::string method = g.text(prhs[13], "method");
  if (method == "rivsvf") {
    config->method = IvMethod::kRivsvf;
  } else if (method == "rsrivc") {
    config->method = IvMethod::kRsrivc;
  } else {
    g.fail("badOption", "method must be 'rivsvf' or 'rsrivc'");
  }
  config->t_s_iv = g.scalar(prhs[14], "tsiv");
  config->dtupdate = g.scalar(prhs[15], "dtupdate");
  const std::string stability = g.text(prhs[16], "stability");
  if (stability == "keep") {
    config->stability = StabilityPolicy::kKeepLast;
  } else if (stability == "reflect") {
    config->stability = StabilityPolicy::kReflect;
  } else {
    g.fail("badOption", "stability must be 'keep' or 'reflect'");
  }
  if (!mxIsEmpty(prhs[17])) {
    config->m_theta = read_transfer_function(g, prhs[17], prhs[18], "M_theta");
  }
  const std::string gain = g.text(prhs[19], "prefilter gain");
  if (gain == "unit") {
    config->prefilter_gain = PrefilterGain::kUnitStaticGain;
  } else if (gain == "monic") {
    config->prefilter_gain = PrefilterGain::kMonic;
  } else {
    g.fail("badOption", "the prefilter gain must be 'unit' or 'monic'");
  }
  if (!mxIsEmpty(prhs[20])) {
    config->initial_denominator =
        g.eigen_matrix(prhs[20], "A", 1, config->orders.na).transpose();
  }
  if (!mxIsEmpty(prhs[21])) {
    config->closed_loop = true;
    config->controller =
        read_transfer_function(g, prhs[21], prhs[22], "the controller");
    const long n = record.num_samples;
    loop->r1 = g.matrix(prhs[23], "r1", n, 1);
    loop->r2 = g.matrix(prhs[24], "r2", n, 1);
  }
  config->scaling = read_scaling(g, prhs[25], np);
  config->antiwindup_gamma = g.scalar(prhs[26], "the anti-windup gamma");
  config->antiwindup_lambda = g.scalar(prhs[27], "the anti-windup lambda");
  g.check(validate(*config));
  return record;
}

inline bool read_single_precision(const Gateway& g, const mxArray* a) {
  const std::string s = g.text(a, "precision");
  if (s == "double") return false;
  if (s == "single") return true;
  g.fail("badOption", "precision must be 'double' or 'single'");
}

// ---- single precision: the same core, instantiated for float -----------

template <typename T>
Vector<T> cast(const Vector<double>& v) {
  return v.cast<T>();
}
template <typename T>
Matrix<T> cast(const Matrix<double>& m) {
  return m.cast<T>();
}
template <typename T>
Adaptation<T> cast(const Adaptation<double>& a) {
  if (const auto* ff = std::get_if<ForgettingFactorAdaptation<double>>(&a)) {
    return ForgettingFactorAdaptation<T>(static_cast<T>(ff->lambda()));
  }
  return KalmanAdaptation<T>(
      std::get<KalmanAdaptation<double>>(a).qn().cast<T>());
}
template <typename T>
SvfSettings<T> cast(const SvfSettings<double>& s) {
  SvfSettings<T> out;
  out.lambda_svf = static_cast<T>(s.lambda_svf);
  out.normalised = s.normalised;
  out.u_intersample = s.u_intersample;
  out.y_intersample = s.y_intersample;
  out.rest_at_first_sample = s.rest_at_first_sample;
  return out;
}
template <typename T>
DiscreteTransferFunction<T> cast(const DiscreteTransferFunction<double>& f) {
  return {f.numerator.cast<T>(), f.denominator.cast<T>()};
}

template <typename T>
RlsSvfConfig<T> cast(const RlsSvfConfig<double>& c) {
  RlsSvfConfig<T> out;
  out.orders = c.orders;
  out.svf = cast<T>(c.svf);
  out.adaptation = cast<T>(c.adaptation);
  out.theta0 = cast<T>(c.theta0);
  out.P0 = cast<T>(c.P0);
  out.ts = static_cast<T>(c.ts);
  out.form = c.form;
  out.lmr_gamma = cast<T>(c.lmr_gamma);
  out.scaling = cast<T>(c.scaling);
  out.initial_conditions = c.initial_conditions;
  out.t_s_ls = static_cast<T>(c.t_s_ls);
  return out;
}

template <typename T>
RecursiveIvConfig<T> cast(const RecursiveIvConfig<double>& c) {
  RecursiveIvConfig<T> out;
  out.orders = c.orders;
  out.method = c.method;
  out.svf = cast<T>(c.svf);
  out.adaptation = cast<T>(c.adaptation);
  out.theta0 = cast<T>(c.theta0);
  out.P0 = cast<T>(c.P0);
  out.ts = static_cast<T>(c.ts);
  out.t_s_iv = static_cast<T>(c.t_s_iv);
  out.dtupdate = static_cast<T>(c.dtupdate);
  out.stability = c.stability;
  out.m_theta = cast<T>(c.m_theta);
  out.prefilter_gain = c.prefilter_gain;
  out.initial_denominator = cast<T>(c.initial_denominator);
  out.closed_loop = c.closed_loop;
  out.controller = cast<T>(c.controller);
  out.scaling = cast<T>(c.scaling);
  out.antiwindup_gamma = static_cast<T>(c.antiwindup_gamma);
  out.antiwindup_lambda = static_cast<T>(c.antiwindup_lambda);
  return out;
}

// A float copy of a record and of every optional output buffer; write()
// copies the results back into the double outputs.
struct SingleRecord {
  std::vector<float> y, u, instants;
  RecordView<float> view;
  explicit SingleRecord(const RecordView<double>& r) {
    const std::size_t n = r.num_samples;
    y.assign(r.y, r.y + n);
    u.assign(r.u, r.u + n * r.num_inputs);
    view.y = y.data();
    view.u = u.data();
    view.num_samples = r.num_samples;
    view.num_inputs = r.num_inputs;
    view.ts = static_cast<float>(r.ts);
    if (r.instants != nullptr) {
      instants.assign(r.instants, r.instants + n);
      view.instants = instants.data();
    }
  }
};

class SingleBuffers {
 public:
  explicit SingleBuffers(const RecursiveOutputs<double>& out, std::size_t n,
                         std::size_t np, std::size_t nextra)
      : target_(out) {
    out_.thm = take(out.thm, n * np, &thm_);
    out_.yh = take(out.yh, n, &yh_);
    out_.pset = take(out.pset, n * np * np, &pset_);
    out_.kappa = take(out.kappa, n, &kappa_);
    out_.extra = take(out.extra, n * nextra, &extra_);
    out_.error = take(out.error, n, &error_);
    out_.innovation = take(out.innovation, n, &innovation_);
    out_.guard = take(out.guard, n, &guard_);
  }
  const RecursiveOutputs<float>& outputs() const { return out_; }
  void write() const {
    copy(thm_, target_.thm);
    copy(yh_, target_.yh);
    copy(pset_, target_.pset);
    copy(kappa_, target_.kappa);
    copy(extra_, target_.extra);
    copy(error_, target_.error);
    copy(innovation_, target_.innovation);
    copy(guard_, target_.guard);
  }

 private:
  static float* take(double* target, std::size_t size,
                     std::vector<float>* buffer) {
    if (target == nullptr) return nullptr;
    buffer->assign(size, 0.0f);
    return buffer->data();
  }
  static void copy(const std::vector<float>& from, double* to) {
    if (to == nullptr) return;
    for (std::size_t i = 0; i < from.size(); ++i) to[i] = from[i];
  }
  RecursiveOutputs<double> target_;
  RecursiveOutputs<float> out_;
  std::vector<float> thm_, yh_, pset_, kappa_, extra_, error_, innovation_,
      guard_;
};

// ---- outputs -----------------------------------------------------------

// THM (N-by-np) always, YH (N-by-1) and PSET (np-by-np-by-N) only when
// requested: the outputs of every recursive routine.
inline RecursiveOutputs<double> make_recursive_outputs(int nlhs,
                                                       mxArray* plhs[],
                                                       std::size_t n,
                                                       std::size_t np) {
  RecursiveOutputs<double> out;
  plhs[0] = make_output_matrix(n, np);
  out.thm = mxGetPr(plhs[0]);
  if (nlhs >= 2) {
    plhs[1] = make_output_matrix(n, 1);
    out.yh = mxGetPr(plhs[1]);
  }
  if (nlhs >= 3) {
    plhs[2] = make_output_array3(np, np, n);
    out.pset = mxGetPr(plhs[2]);
  }
  return out;
}

// The 4th output, a struct of per-sample diagnostics: its fields are
// allocated here and filled by the run through `out` (and the caller for
// the rest). Returns the struct.
class InfoStruct {
 public:
  InfoStruct() : info_(mxCreateStructMatrix(1, 1, 0, nullptr)) {}
  double* add(const char* name, std::size_t rows, std::size_t cols) {
    mxArray* field = make_output_matrix(rows, cols);
    mxSetFieldByNumber(info_, 0, mxAddField(info_, name), field);
    return mxGetPr(field);
  }
  void add_scalar(const char* name, double value) {
    mxSetFieldByNumber(info_, 0, mxAddField(info_, name),
                       mxCreateDoubleScalar(value));
  }
  mxArray* release() { return info_; }

 private:
  mxArray* info_;
};

// Runs `run(config, record, out)` in double, or in single precision on
// float copies of the record and the configuration.
template <typename Config, typename Run>
Status run_in_precision(bool single, const Config& config,
                        const RecordView<double>& record,
                        const RecursiveOutputs<double>& out, std::size_t np,
                        std::size_t nextra, Run&& run) {
  if (!single) return run(config, record, out);
  const SingleRecord single_record(record);
  const SingleBuffers buffers(out, record.num_samples, np, nextra);
  const Status status =
      run(cast<float>(config), single_record.view, buffers.outputs());
  buffers.write();
  return status;
}

}  // namespace ctid::mex
