// SPDX-License-Identifier: BSD-3-Clause
// Copyright (C) the ctid authors
// The options structs of the recursive gateways (rlssvf_mex, riv_mex) and
// what qnml_mex reuses of them: reading a whole estimator configuration by
// field name, running it in double or single precision, and building the
// info struct. The data y, u, t are positional; every other setting is a
// field of the one options struct, declared once in the core
// (ctid/recursive/recursive_options.hpp: rlssvf_options,
// recursive_iv_options) and read from that table, plus what is not a
// setting of the estimator: precision 'double' | 'single' and, for the
// closed loop, the signals r1 and r2. Absent optional fields keep the
// core's defaults (its config structs); `<gateway> (fname, "options")`
// returns the table.
#pragma once

#include <vector>

#include "ctid/recursive/recursive_iv.hpp"
#include "ctid/recursive/recursive_options.hpp"
#include "ctid/recursive/rlssvf.hpp"
#include "gateway_common.hpp"

namespace ctid::mex {

template <typename Config>
void read_option_values(const Gateway& g, OptionsReader& opt,
                        const OptionTable<Config>& table, Config* config) {
  for (const auto& decl : table) {
    const mxArray* a = opt.field(decl.name);
    if (a == nullptr || (mxIsEmpty(a) && mxIsDouble(a))) {
      if (decl.required) {
        g.fail("badOption",
               std::string("option '") + decl.name + "' is missing");
      }
      continue;
    }
    const std::string what = std::string("option '") + decl.name + "'";
    const bool one_number =
        (mxIsNumeric(a) || mxIsLogical(a)) && mxGetNumberOfElements(a) == 1;
    OptionValue value;
    switch (decl.type) {
      case OptionType::kReal:
        if (!one_number) g.fail("badInput", what + " must be a real scalar");
        value.real = g.scalar(a, what);
        break;
      case OptionType::kInteger:
        value.integer = g.integer(a, what);
        break;
      case OptionType::kIntegerVector:
        value.integers = g.integer_vector(a, what);
        break;
      case OptionType::kFlag:
        if (!one_number) g.fail("badOption", what + " must be true or false");
        if (mxIsLogical(a)) {
          value.flag = mxIsLogicalScalarTrue(a);
        } else {
          const double v = g.scalar(a, what);
          if (v != 0 && v != 1)
            g.fail("badOption", what + " must be true or false");
          value.flag = v != 0;
        }
        break;
      case OptionType::kChoice:
        if (!mxIsChar(a)) {
          g.fail("badOption", what + " must be one of " + option_choices(decl));
        }
        value.word = g.text(a, what);
        break;
      case OptionType::kMatrix:
        value.matrix = g.eigen_matrix(a, what, -1, -1);
        break;
    }
    g.check(set_option(decl, value, config));
  }
}

// Every option of a table (ctid/recursive/recursive_options.hpp) that the
// struct holds, converted by its declared type and set in table order;
// a required one that is absent is an error. The ranges are checked once,
// by the core's validate(config), which the caller runs after the last
// option is set. A value of the wrong class or size is an error of reason
// bad_value.
template <typename Config>
void read_option_table(const Gateway& g, OptionsReader& opt,
                       const OptionTable<Config>& table, Config* config,
                       const std::string& bad_value = "badInput") {
  try {
    read_option_values(g, opt, table, config);
  } catch (const GatewayError& e) {
    if (e.id != g.name() + ":badInput") throw;
    throw GatewayError{g.name() + ":" + bad_value, e.message};
  }
}

// The table as a struct array (name, type, default, range, help): what a
// gateway returns for `<gateway> (fname, "options")`, and what the help
// texts are checked against.
template <typename Config>
mxArray* option_table_struct(const OptionTable<Config>& table) {
  const char* fields[] = {"name", "type", "default", "range", "help"};
  mxArray* s = mxCreateStructMatrix(table.size(), 1, 5, fields);
  for (std::size_t k = 0; k < table.size(); ++k) {
    const auto& decl = table[k];
    mxSetField(s, k, "name", mxCreateString(decl.name));
    mxSetField(s, k, "type", mxCreateString(option_type_name(decl.type)));
    mxSetField(s, k, "default",
               mxCreateString(decl.required ? "(required)"
                                            : option_default(decl).c_str()));
    mxSetField(s, k, "range", mxCreateString(decl.range));
    mxSetField(s, k, "help", mxCreateString(decl.help));
  }
  return s;
}

// True for the call `<gateway> (fname, "options")`.
inline bool asks_for_options(int nrhs, const mxArray* prhs[]) {
  if (nrhs != 2 || !mxIsChar(prhs[1])) return false;
  char word[8] = {0};
  return mxGetString(prhs[1], word, sizeof word) == 0 &&
         std::string(word) == "options";
}

// The rlssvf configuration; the caller calls opt.finish().
inline void read_rlssvf_config(const Gateway& g, OptionsReader& opt,
                               RlsSvfConfig<double>* config) {
  read_option_table(g, opt, rlssvf_options<double>(), config);
  g.check(validate(*config));
}

// The riv configuration and the closed-loop signals (read in place, N =
// record.num_samples); the caller calls opt.finish().
inline void read_riv_config(const Gateway& g, OptionsReader& opt,
                            const RecordView<double>& record,
                            RecursiveIvConfig<double>* config,
                            ClosedLoopSignals<double>* loop) {
  read_option_table(g, opt, recursive_iv_options<double>(), config);
  const long n = record.num_samples;
  loop->r1 = opt.signal("r1", n);
  loop->r2 = opt.signal("r2", n);
  const bool controller = config->controller.numerator.size() != 0 &&
                          config->controller.denominator.size() != 0;
  if (config->closed_loop != controller ||
      config->closed_loop != (loop->r1 != nullptr && loop->r2 != nullptr)) {
    g.fail("badOption",
           "the closed loop needs the options 'controller_num', "
           "'controller_den', 'r1' and 'r2' together");
  }
  g.check(validate(*config));
}

// 'double' (default) or 'single': the core instantiated for float on a
// float copy of the data.
inline bool read_single_precision(OptionsReader& opt) {
  return opt.choice<bool>("precision", {{"double", false}, {"single", true}},
                          false);
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
  out.kernels = s.kernels;
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
  out.covariance_guard = c.covariance_guard;
  out.gap_interval = static_cast<T>(c.gap_interval);
  out.gap_settle = static_cast<T>(c.gap_settle);
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
  out.covariance_guard = c.covariance_guard;
  out.gap_interval = static_cast<T>(c.gap_interval);
  out.gap_settle = static_cast<T>(c.gap_settle);
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
