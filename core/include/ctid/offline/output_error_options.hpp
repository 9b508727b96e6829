// SPDX-License-Identifier: BSD-3-Clause
// Copyright (C) the ctid authors
// The named options of the output-error estimators (output_error.hpp;
// the toolbox's tfcoe, tfest and oe), declared once in the form of
// base/options.hpp, over OeConfig: the orders and delays one entry per
// input as a host gives them, and the settings of the iteration. Their
// defaults are OeConfig's and OeSettings' member initialisers; the ranges
// are checked once, by validate() of output_error.hpp, when the estimator
// runs.
//
//   OeConfig<double> config;
//   OptionValue v;
//   v.integer = 50;
//   Status s = set_option(output_error_options<double>(), "maxiter", v,
//                         &config);
#pragma once

#include <string>
#include <vector>

#include "ctid/base/options.hpp"
#include "ctid/offline/output_error.hpp"
#include "ctid/offline/output_error_starts.hpp"

namespace ctid {

template <typename S>
struct OeConfig {
  OeTime time = OeTime::kContinuous;
  // One entry per input (a host that reads a scalar gives one entry).
  std::vector<int> nf, nb;
  std::vector<int> nk{0};
  std::vector<double> delay;  // continuous time, time units; empty: 0
  InterSample rule = InterSample::kZoh;
  bool estimate_delay = false;
  double delay_max = 0;
  OeSettings<S> settings;
  // Several starts (output_error_starts.hpp): used when starts are given
  // or the input is integrated.
  OeStartsSettings<S> starts;
  bool from_starts() const {
    return !starts.starts.empty() || starts.integrate;
  }
};

// The structure of a config for m inputs: one input fills OeStructure's
// own fields, several one OeChannel each. Orders or delays that do not
// have one entry per input are a dimension mismatch.
template <typename S>
Status oe_structure(const OeConfig<S>& config, std::size_t m, OeStructure* s) {
  if (config.nf.size() != m || config.nb.size() != m || config.nk.size() != m ||
      (!config.delay.empty() && config.delay.size() != m)) {
    return dimension_mismatch(
        "nf, nb, nk and delay need one entry per input (" + std::to_string(m) +
        ")");
  }
  *s = OeStructure();
  s->time = config.time;
  for (std::size_t j = 0; j < m; ++j) {
    OeChannel c;
    c.nf = config.nf[j];
    c.nb = config.nb[j];
    c.nk = config.nk[j];
    c.delay = config.delay.empty() ? 0.0 : config.delay[j];
    c.rule = config.rule;
    if (m == 1) {
      s->nf = c.nf;
      s->nb = c.nb;
      s->nk = c.nk;
      s->delay = c.delay;
      s->rule = c.rule;
    } else {
      s->inputs.push_back(c);
    }
  }
  s->estimate_delay = config.estimate_delay;
  s->delay_max = config.delay_max;
  return Status::Ok();
}

template <typename S>
const OptionTable<OeConfig<S>>& output_error_options() {
  using C = OeConfig<S>;
  using V = const OptionValue&;
  static const OptionTable<C> table = [] {
    OptionTable<C> t;
    t.push_back(integer_vector_option<C>(
        "nf", true, ">= 1 each (continuous time), >= 0 (discrete time)",
        "denominator order, one per input", member_access(&C::nf)));
    t.push_back(numerator_counts_option<C>(true, member_access(&C::nb)));
    t.push_back(input_delays_option<C>(member_access(&C::nk)));
    t.push_back(real_list_option<C>(
        "delay", "finite, >= 0 each",
        "continuous-time input delay in time units on top of nk, one per "
        "input",
        "0", member_access(&C::delay)));
    t.push_back({"intersample",
                 OptionType::kChoice,
                 false,
                 {"zoh", "foh"},
                 "'zoh' | 'foh'",
                 "how the input varies between samples (continuous time)",
                 [](const C& c) {
                   return std::string(options_detail::intersample_word(c.rule));
                 },
                 [](C* c, V v) {
                   c->rule = options_detail::intersample_of(v.word);
                   return Status::Ok();
                 }});
    t.push_back(flag_option<C>("estimate_delay",
                               "true | false; one input, nb <= nf",
                               "estimate the total delay as a parameter, "
                               "started from nk Ts + delay",
                               member_access(&C::estimate_delay)));
    t.push_back(real_option<C>(
        "delay_max", false, "finite, >= 0",
        "upper bound of the estimated delay (time units)",
        [](auto& c) -> auto& { return c.delay_max; }));
    t.push_back(vector_option<C>(
        "theta_init", "[f; b] (; delay), finite, a stable F",
        "initial parameters; absent: the SRIVC (continuous) or ARX "
        "(discrete) start",
        "(SRIVC or ARX start)", ErrorCode::kBadInput,
        [](auto& c) -> auto& { return c.settings.theta_init; }));
    t.push_back(integer_option<C>(
        "maxiter", false, ">= 0",
        "largest number of Levenberg-Marquardt iterations",
        [](auto& c) -> auto& { return c.settings.max_iterations; }));
    t.push_back(real_option<C>(
        "tol", false, "> 0",
        "stop once the relative step and loss decrease are below it",
        [](auto& c) -> auto& { return c.settings.tolerance; }));
    t.push_back(real_option<C>(
        "cutoff", false, ">= 0",
        "SVF cut-off of the SRIVC start (rad/s); 0: a grid",
        [](auto& c) -> auto& { return c.settings.srivc_cutoff; }));
    t.push_back({"starts",
                 OptionType::kMatrix,
                 false,
                 {},
                 "finite; one column [f; b] (; delay) per start",
                 "starts of the iteration, the lowest loss kept; none: "
                 "one run from theta_init",
                 [](const C& c) {
                   return c.starts.starts.empty()
                              ? std::string("(none)")
                              : std::to_string(c.starts.starts.size()) +
                                    " start(s)";
                 },
                 [](C* c, V v) {
                   const Matrix<double>& m = v.matrix;
                   if (!m.allFinite())
                     return bad_input("the starts must be finite");
                   c->starts.starts.clear();
                   for (Eigen::Index k = 0; k < m.cols(); ++k)
                     c->starts.starts.push_back(m.col(k).cast<S>());
                   return Status::Ok();
                 }});
    t.push_back(flag_option<C>(
        "default_start", "true | false",
        "with starts: also the run from theta_init (or the SRIVC / ARX "
        "start), first",
        [](auto& c) -> auto& { return c.starts.default_start; }));
    t.push_back(real_option<C>(
        "delay_min", false, "finite, in [0, delay_max]",
        "lower bound of the delay estimated from the starts (time "
        "units)",
        [](auto& c) -> auto& { return c.starts.delay_min; }));
    t.push_back(flag_option<C>(
        "integrate", "true | false; one ZOH input, nf >= 2, nb <= nf - 1",
        "a pole fixed at 0 (f_nf = 0): B/F' fitted on the integrated input",
        [](auto& c) -> auto& { return c.starts.integrate; }));
    return t;
  }();
  return table;
}

}  // namespace ctid
