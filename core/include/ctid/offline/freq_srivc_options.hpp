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

#include <algorithm>
#include <cmath>
#include <complex>
#include <limits>
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
  // The Focus band [w_lo w_hi] (rad/s): the fit uses the frequencies inside
  // it; empty: all.
  std::vector<double> band;
  // The upper end of the delay search; NaN: half the period of periodic
  // data, else pi over the median positive frequency used (freq_fit_data).
  S td_max = std::numeric_limits<S>::quiet_NaN();
  S period = std::numeric_limits<S>::infinity();  // periodic data: its period
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

// The data a fit uses.
template <typename S>
struct FreqFitData {
  std::vector<S> w;
  std::vector<std::complex<S>> y;
  std::vector<std::complex<S>> u;  // K-by-m column-major; empty: U = 1
  int num_inputs = 1;
  FreqData<S> view() const {
    FreqData<S> d;
    d.w = w.data();
    d.y = y.data();
    d.u = u.empty() ? nullptr : u.data();
    d.num_frequencies = static_cast<Eigen::Index>(w.size());
    d.num_inputs = num_inputs;
    return d;
  }
};

// The settings of a config for the K frequencies w, outputs y and (u not
// null) inputs u (K-by-m, column-major), and the data the fit uses: the
// frequencies where some input is nonzero (the others say nothing about
// G), finite there, and inside the Focus band. The delay range of an
// estimated delay: td_max by default half the period of periodic data
// (relay feedback: the delays within one half-cycle are told apart), else
// pi over the median positive frequency used (a phase of pi at the typical
// frequency); a start delay outside [td_min, td_max] widens the range to
// it.
template <typename S>
Status freq_fit_data(const FreqConfig<S>& config, const S* w,
                     const std::complex<S>* y, const std::complex<S>* u,
                     Eigen::Index K, std::size_t m, FreqFitData<S>* data,
                     FreqSettings<S>* s) {
  if (data == nullptr || s == nullptr) {
    return bad_input("the results must not be null");
  }
  Status st = freq_settings(config, m, s);
  if (!st.ok()) return st;
  const auto input_nonzero = [&](Eigen::Index k) {
    if (u == nullptr) return true;
    for (std::size_t j = 0; j < m; ++j)
      if (std::abs(u[j * K + k]) > 0) return true;
    return false;
  };
  const auto finite = [](const std::complex<S>& z) {
    return std::isfinite(z.real()) && std::isfinite(z.imag());
  };
  std::vector<Eigen::Index> kept;
  bool in_band = false;
  for (Eigen::Index k = 0; k < K; ++k) {
    if (!input_nonzero(k)) continue;
    bool ok = finite(y[k]);
    for (std::size_t j = 0; u != nullptr && j < m; ++j)
      ok = ok && finite(u[j * K + k]);
    if (!ok) return bad_input("the frequency data must be finite");
    if (!config.band.empty() &&
        !(w[k] >= config.band[0] && w[k] <= config.band[1]))
      continue;
    in_band = true;
    kept.push_back(k);
  }
  if (!config.band.empty() && !in_band) {
    return Status(ErrorCode::kBadOption,
                  "the Focus band [" + options_detail::number(config.band[0]) +
                      " " + options_detail::number(config.band[1]) +
                      "] holds no frequency of the data");
  }
  data->w.clear();
  data->y.clear();
  data->u.clear();
  data->num_inputs = static_cast<int>(m);
  for (Eigen::Index k : kept) {
    data->w.push_back(w[k]);
    data->y.push_back(y[k]);
  }
  for (std::size_t j = 0; u != nullptr && j < m; ++j)
    for (Eigen::Index k : kept) data->u.push_back(u[j * K + k]);
  if (!s->estimate_delay) return Status::Ok();
  S td_max = config.td_max;
  if (std::isnan(td_max)) {
    if (std::isfinite(config.period)) {
      td_max = config.period / 2;
    } else {
      std::vector<S> positive;
      for (S wk : data->w)
        if (wk > 0) positive.push_back(wk);
      std::sort(positive.begin(), positive.end());
      const std::size_t n = positive.size();
      td_max = n == 0
                   ? std::numeric_limits<S>::quiet_NaN()
                   : S(3.141592653589793238462643383279502884L) /
                         (n % 2 ? positive[n / 2]
                                : (positive[n / 2 - 1] + positive[n / 2]) / 2);
    }
  }
  const auto bad = [](const char* m) {
    return Status(ErrorCode::kBadOption, m);
  };
  if (!(s->td_min >= 0) || !std::isfinite(s->td_min)) {
    return bad("TdMin must be a finite scalar >= 0");
  }
  if (!(td_max >= 0) || !std::isfinite(td_max)) {
    return bad("TdMax must be a finite scalar >= 0");
  }
  if (td_max < s->td_min) return bad("TdMax must be >= TdMin");
  s->td_max = td_max;
  if (!config.delay.empty()) {
    s->td_min = std::min(s->td_min, s->delay);
    s->td_max = std::max(s->td_max, s->delay);
  }
  return Status::Ok();
}

template <typename S>
const OptionTable<FreqConfig<S>>& freq_srivc_options() {
  using C = FreqConfig<S>;
  using V = const OptionValue&;
  using options_detail::number;
  static const OptionTable<C> table = [] {
    OptionTable<C> t;
    t.push_back(integer_vector_option<C>("na", true, ">= 1 each",
                                         "denominator order, one per input",
                                         member_access(&C::na)));
    t.push_back(integer_vector_option<C>(
        "nb", true, ">= 1 each, at most na + 1",
        "numerator coefficients, one per input", member_access(&C::nb)));
    t.push_back(real_list_option<C>(
        "delay", "finite, >= 0 each",
        "input delay (time units), one per input: fixed, or the start of the "
        "estimated one",
        "0", member_access(&C::delay)));
    t.push_back(real_option<C>(
        "tol", false, "> 0",
        "stop once the relative change of the estimate is below it",
        [](auto& c) -> auto& { return c.settings.tolerance; }));
    t.push_back(integer_option<C>(
        "maxiter", false, ">= 1",
        "largest number of SRIVC (or Levenberg-Marquardt) iterations",
        [](auto& c) -> auto& { return c.settings.max_iterations; }));
    t.push_back(flag_option<C>(
        "estimate_delay", "true | false; one input",
        "estimate the delay in [td_min, td_max]",
        [](auto& c) -> auto& { return c.settings.estimate_delay; }));
    t.push_back(real_option<C>(
        "td_min", false, "finite, >= 0",
        "lower end of the delay search (time units)",
        [](auto& c) -> auto& { return c.settings.td_min; }));
    t.push_back(derived_real_option<C>(
        "td_max", "finite, >= td_min",
        "upper end of the delay search (time units)",
        "(half the period of periodic data, else pi / the median frequency)",
        member_access(&C::td_max)));
    t.push_back(real_option<C>(
        "period", false, "> 0, Inf: not periodic",
        "the period of periodic data (relay feedback; time units)",
        member_access(&C::period)));
    t.push_back({"band",
                 OptionType::kMatrix,
                 false,
                 {},
                 "[w_lo w_hi], 0 <= w_lo <= w_hi (rad/s)",
                 "the Focus band: the frequencies the fit uses",
                 [](const C& c) {
                   return c.band.empty() ? std::string("(all frequencies)")
                                         : "[" + number(c.band[0]) + " " +
                                               number(c.band[1]) + "]";
                 },
                 [](C* c, V v) {
                   const Matrix<double>& m = v.matrix;
                   if (m.size() != 0 && m.size() != 2) {
                     return Status(ErrorCode::kBadOption,
                                   "band must be [] or [w_lo w_hi]");
                   }
                   c->band.assign(m.data(), m.data() + m.size());
                   return Status::Ok();
                 }});
    t.push_back(integer_option<C>(
        "num_td", false, "2 .. 1e5", "delays of the search's grid",
        [](auto& c) -> auto& { return c.settings.num_td; }));
    t.push_back(flag_option<C>(
        "grid", "true | false",
        "search the grid (false: refine from the delay given)",
        [](auto& c) -> auto& { return c.settings.grid; }));
    t.push_back(flag_option<C>(
        "output_error", "true | false",
        "refine SRIVC's estimate by output error (TFFCOE)",
        [](auto& c) -> auto& { return c.settings.output_error; }));
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
