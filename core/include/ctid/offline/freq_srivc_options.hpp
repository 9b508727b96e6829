// SPDX-License-Identifier: BSD-3-Clause
// Copyright (C) the ctid authors
// The named options of the frequency-domain estimators (freq_srivc.hpp;
// the toolbox's srivc on frequency data, tffsrivc, tffcoe, and oe / tfest
// on frequency data), declared once in the form of base/options.hpp, over
// FreqConfig: the orders and delays one entry per input as a host gives
// them, and the settings of the fit. Their defaults are FreqSettings'
// member initialisers; the ranges are checked by freq_srivc() when the
// estimator runs.
//
//   FreqConfig<double> config;
//   OptionValue v;
//   v.integer = 20;
//   Status s = set_option(freq_srivc_options<double>(), "num_td", v,
//                         &config);
#pragma once

#include <string>
#include <vector>

#include "ctid/base/options.hpp"
#include "ctid/offline/freq_srivc.hpp"

namespace ctid {

template <typename S>
struct FreqConfig {
  // One entry per input (a host that reads a scalar gives one entry).
  std::vector<int> na, nb;
  std::vector<double> delay;  // time units; empty: 0
  FreqSettings<S> settings;
};

// The settings of a config for m inputs: one input fills FreqSettings' own
// orders and delay, several one FreqChannel each. Orders or delays that do
// not have one entry per input are a dimension mismatch.
template <typename S>
Status freq_settings(const FreqConfig<S>& config, std::size_t m,
                     FreqSettings<S>* s) {
  if (config.na.size() != m || config.nb.size() != m ||
      (!config.delay.empty() && config.delay.size() != m)) {
    return dimension_mismatch("na, nb and delay need one entry per input (" +
                              std::to_string(m) + ")");
  }
  *s = config.settings;
  s->inputs.clear();
  for (std::size_t j = 0; j < m; ++j) {
    FreqChannel<S> c;
    c.na = config.na[j];
    c.nb = config.nb[j];
    c.delay = config.delay.empty() ? S(0) : static_cast<S>(config.delay[j]);
    // (before any sum of the orders)
    if (c.na < 0 || c.nb < 0 || c.na > 1000 || c.nb > 1000)
      return bad_input("na and nb must lie in [0, 1000]");
    if (j == 0) {
      s->na = c.na;
      s->nb = c.nb;
      s->delay = c.delay;
    }
    if (m > 1) s->inputs.push_back(c);
  }
  return Status::Ok();
}

template <typename S>
const OptionTable<FreqConfig<S>>& freq_srivc_options() {
  using C = FreqConfig<S>;
  using V = const OptionValue&;
  using options_detail::integers;
  using options_detail::number;
  auto flag_text = [](bool b) { return std::string(b ? "true" : "false"); };
  static const OptionTable<C> table = [&] {
    OptionTable<C> t;
    t.push_back({"na",
                 OptionType::kIntegerVector,
                 true,
                 {},
                 ">= 1 each",
                 "denominator order, one per input",
                 [](const C& c) { return integers(c.na); },
                 [](C* c, V v) {
                   c->na = v.integers;
                   return Status::Ok();
                 }});
    t.push_back({"nb",
                 OptionType::kIntegerVector,
                 true,
                 {},
                 ">= 1 each, at most na + 1",
                 "numerator coefficients, one per input",
                 [](const C& c) { return integers(c.nb); },
                 [](C* c, V v) {
                   c->nb = v.integers;
                   return Status::Ok();
                 }});
    t.push_back({"delay",
                 OptionType::kMatrix,
                 false,
                 {},
                 "finite, >= 0 each",
                 "input delay (time units), one per input: fixed, or the "
                 "start of the estimated one",
                 [](const C& c) {
                   return c.delay.empty()
                              ? std::string("0")
                              : std::to_string(c.delay.size()) + " value(s)";
                 },
                 [](C* c, V v) {
                   const Matrix<double>& m = v.matrix;
                   c->delay.assign(m.data(), m.data() + m.size());
                   return Status::Ok();
                 }});
    t.push_back(real_option<C>(
        "tol", false, "> 0",
        "stop once the relative change of the estimate is below it",
        [](auto& c) -> auto& { return c.settings.tolerance; }));
    t.push_back(integer_option<C>(
        "maxiter", false, ">= 1",
        "largest number of SRIVC (or Levenberg-Marquardt) iterations",
        [](auto& c) -> auto& { return c.settings.max_iterations; }));
    t.push_back({"estimate_delay",
                 OptionType::kFlag,
                 false,
                 {},
                 "true | false; one input",
                 "estimate the delay in [td_min, td_max]",
                 [flag_text](const C& c) {
                   return flag_text(c.settings.estimate_delay);
                 },
                 [](C* c, V v) {
                   c->settings.estimate_delay = v.flag;
                   return Status::Ok();
                 }});
    t.push_back(real_option<C>(
        "td_min", false, "finite, >= 0",
        "lower end of the delay search (time units)",
        [](auto& c) -> auto& { return c.settings.td_min; }));
    t.push_back(real_option<C>(
        "td_max", false, "finite, >= td_min",
        "upper end of the delay search (time units)",
        [](auto& c) -> auto& { return c.settings.td_max; }));
    t.push_back(integer_option<C>(
        "num_td", false, "2 .. 1e5", "delays of the search's grid",
        [](auto& c) -> auto& { return c.settings.num_td; }));
    t.push_back({"grid",
                 OptionType::kFlag,
                 false,
                 {},
                 "true | false",
                 "search the grid (false: refine from the delay given)",
                 [flag_text](const C& c) { return flag_text(c.settings.grid); },
                 [](C* c, V v) {
                   c->settings.grid = v.flag;
                   return Status::Ok();
                 }});
    t.push_back(
        {"output_error",
         OptionType::kFlag,
         false,
         {},
         "true | false",
         "refine SRIVC's estimate by output error (TFFCOE)",
         [flag_text](const C& c) { return flag_text(c.settings.output_error); },
         [](C* c, V v) {
           c->settings.output_error = v.flag;
           return Status::Ok();
         }});
    t.push_back(
        {"theta_init",
         OptionType::kMatrix,
         false,
         {},
         "[a b], finite, a stable A",
         "initial parameters; absent: least squares with the prefilter "
         "1/(s + lambda)^n",
         [](const C& c) {
           return options_detail::matrix_text(Matrix<S>(c.settings.theta_init),
                                              "(least-squares start)");
         },
         [](C* c, V v) {
           const Matrix<double>& m = v.matrix;
           c->settings.theta_init =
               Eigen::Map<const Vector<double>>(m.data(), m.size()).cast<S>();
           return Status::Ok();
         }});
    return t;
  }();
  return table;
}

}  // namespace ctid
