// SPDX-License-Identifier: BSD-3-Clause
// Copyright (C) the ctid authors
// The named options of the offline refined-IV estimators, declared once in
// the form of base/options.hpp:
//
// - refined_iv_options(), over RivConfig: the engine of refined_iv.hpp
//   (the toolbox's lssvf, ivsvf, srivc, clsrivc, tfsrivc, procsrivc):
//   the structure one entry per group or channel as a host gives it, the
//   closed loop's controller and RivSettings;
// - rivc_options(), over RivcConfig: the Box-Jenkins refined IV of
//   refined_iv_bj.hpp (rivc, tfrivc, clrivc, cl2srivc);
// - refined_iv_delay_options(), over RivDelaySettings: the delay search of
//   refined_iv_delay.hpp (tfsrivc, tfrivc, procsrivc).
//
// Their defaults are the member initialisers of RivProblem, RivChannel,
// RivSettings, RivcProblem, RivcSettings and RivDelaySettings. The ranges
// are checked once: by riv_problem() below and the engine's validate()
// (refined_iv_validation.hpp) for the first table, by validate(RivcConfig)
// below for the second, by delay_search() (delay_search.hpp) for the
// third.
//
//   RivConfig<double> config;
//   OptionValue v;
//   v.integers = {2};
//   Status s = set_option(refined_iv_options<double>(), "nf", v, &config);
#pragma once

#include <cmath>
#include <string>
#include <vector>

#include "ctid/base/options.hpp"
#include "ctid/offline/refined_iv_bj.hpp"
#include "ctid/offline/refined_iv_delay.hpp"
#include "ctid/offline/refined_iv_problem.hpp"

namespace ctid {

// ---- the refined-IV engine ----------------------------------------------

template <typename S>
struct RivConfig {
  // nf, y_rule, output_offset, initial_state and the controller; its
  // channels and fixed coefficients are made by riv_problem() from the
  // fields below.
  RivProblem<S> problem;
  // One entry per column of the signals w (a host gives group, nb and nk);
  // empty: RivChannel's default for every channel. group is 1-based;
  // intersample codes 0 (zoh) and 1 (foh).
  std::vector<int> group, nb, nk, intersample;
  std::vector<double> delay;
  // Empty (none) or one entry per coefficient of theta each.
  std::vector<double> fixed, fixed_values;
  // The controller (problem.controller_num/_den) is C(q^-1) in the thesis'
  // loop u = r1 + C (r2 - y), which the host wires with its signals.
  bool discrete_controller = false;
  RivSettings<S> settings;
};

namespace options_detail {

// An intersample code of a host (0 zoh, 1 foh) as a rule.
inline Status intersample_code(int code, InterSample* rule) {
  if (code != 0 && code != 1) {
    return Status(ErrorCode::kBadOption,
                  "intersample codes must be 0 (zoh) or 1 (foh)");
  }
  *rule = code == 1 ? InterSample::kFoh : InterSample::kZoh;
  return Status::Ok();
}

inline std::string each(int v) { return std::to_string(v) + " each"; }

}  // namespace options_detail

// The engine's problem for m columns of w: the config's problem with one
// channel per column and its fixed coefficients. Per-channel entries that
// are not one per column are a dimension mismatch; maxiter below 1 a bad
// input (the engine itself takes 0: its start alone).
template <typename S>
Status riv_problem(const RivConfig<S>& config, int m, RivProblem<S>* problem) {
  const auto fits = [m](std::size_t size, bool may_be_empty) {
    return static_cast<int>(size) == m || (may_be_empty && size == 0);
  };
  if (!fits(config.nb.size(), false) || !fits(config.group.size(), true) ||
      !fits(config.nk.size(), true) || !fits(config.intersample.size(), true)) {
    return dimension_mismatch(
        "group, nb, nk and intersample need one entry per column of w (" +
        std::to_string(m) + ")");
  }
  if (!fits(config.delay.size(), true)) {
    return dimension_mismatch("delay needs one entry per column of w (" +
                              std::to_string(m) + ")");
  }
  if (config.settings.max_iterations < 1) {
    return bad_input("maxiter must be an integer >= 1");
  }
  *problem = config.problem;
  problem->channels.clear();
  for (int j = 0; j < m; ++j) {
    RivChannel c;
    if (!config.group.empty()) c.group = config.group[j] - 1;
    c.nb = config.nb[j];
    if (!config.nk.empty()) c.nk = config.nk[j];
    if (!config.intersample.empty()) {
      const Status s =
          options_detail::intersample_code(config.intersample[j], &c.rule);
      if (!s.ok()) return s;
    }
    if (!config.delay.empty()) c.delay = config.delay[j];
    problem->channels.push_back(c);
  }
  problem->fixed.clear();
  problem->fixed_values = Vector<S>();
  if (!config.fixed.empty()) {
    const std::size_t np = problem->num_parameters();
    if (config.fixed.size() != np || config.fixed_values.size() != np) {
      return dimension_mismatch("fixed and fixed_values need " +
                                std::to_string(np) + " entries each");
    }
    for (double f : config.fixed) problem->fixed.push_back(f != 0);
    problem->fixed_values =
        Eigen::Map<const Vector<double>>(config.fixed_values.data(), np)
            .cast<S>();
  }
  return Status::Ok();
}

template <typename S>
const OptionTable<RivConfig<S>>& refined_iv_options() {
  using C = RivConfig<S>;
  using V = const OptionValue&;
  using options_detail::each;
  using options_detail::integers;
  using options_detail::number;
  const auto flag = [](bool b) { return std::string(b ? "true" : "false"); };
  const auto values = [](const Matrix<double>& m) {
    return std::vector<double>(m.data(), m.data() + m.size());
  };
  static const OptionTable<C> table = [&] {
    OptionTable<C> t;
    t.push_back({"method",
                 OptionType::kChoice,
                 false,
                 {"srivc", "ivsvf", "lssvf"},
                 "'srivc' | 'ivsvf' | 'lssvf'",
                 "the estimator: SRIVC, or one IVSVF or LSSVF step",
                 [](const C& c) {
                   const RivMethod m = c.settings.method;
                   return std::string(m == RivMethod::kSrivc   ? "srivc"
                                      : m == RivMethod::kIvsvf ? "ivsvf"
                                                               : "lssvf");
                 },
                 [](C* c, V v) {
                   c->settings.method = v.word == "ivsvf"   ? RivMethod::kIvsvf
                                        : v.word == "lssvf" ? RivMethod::kLssvf
                                                            : RivMethod::kSrivc;
                   return Status::Ok();
                 }});
    t.push_back({"nf",
                 OptionType::kIntegerVector,
                 true,
                 {},
                 ">= 1 each",
                 "order of each denominator F_g",
                 [](const C& c) { return integers(c.problem.nf); },
                 [](C* c, V v) {
                   c->problem.nf = v.integers;
                   return Status::Ok();
                 }});
    t.push_back({"group",
                 OptionType::kIntegerVector,
                 true,
                 {},
                 "1..numel(nf) each",
                 "the denominator each column of w enters (1-based)",
                 [](const C&) { return each(RivChannel().group + 1); },
                 [](C* c, V v) {
                   c->group = v.integers;
                   return Status::Ok();
                 }});
    t.push_back({"nb",
                 OptionType::kIntegerVector,
                 true,
                 {},
                 ">= 0 each, at most nf + 1 of its group",
                 "numerator coefficients of each column of w",
                 [](const C& c) { return integers(c.nb); },
                 [](C* c, V v) {
                   c->nb = v.integers;
                   return Status::Ok();
                 }});
    t.push_back({"nk",
                 OptionType::kIntegerVector,
                 true,
                 {},
                 ">= 0 each (0 on irregular data)",
                 "input delay in samples of each column of w",
                 [](const C&) { return each(RivChannel().nk); },
                 [](C* c, V v) {
                   c->nk = v.integers;
                   return Status::Ok();
                 }});
    t.push_back({"intersample",
                 OptionType::kIntegerVector,
                 false,
                 {},
                 "0 (zoh) | 1 (foh) each",
                 "how each column of w varies between samples",
                 [](const C&) {
                   return each(RivChannel().rule == InterSample::kFoh ? 1 : 0);
                 },
                 [](C* c, V v) {
                   c->intersample = v.integers;
                   return Status::Ok();
                 }});
    t.push_back({"delay",
                 OptionType::kMatrix,
                 false,
                 {},
                 "finite, >= 0 each; open loop",
                 "continuous delay (time units) of each column of w on top "
                 "of nk",
                 [](const C&) { return number(RivChannel().delay) + " each"; },
                 [values](C* c, V v) {
                   c->delay = values(v.matrix);
                   return Status::Ok();
                 }});
    t.push_back({"y_intersample",
                 OptionType::kInteger,
                 false,
                 {},
                 "0 (zoh) | 1 (foh)",
                 "how the output is interpolated by the refined steps' "
                 "filters",
                 [](const C& c) {
                   return std::to_string(
                       c.problem.y_rule == InterSample::kFoh ? 1 : 0);
                 },
                 [](C* c, V v) {
                   return options_detail::intersample_code(v.integer,
                                                           &c->problem.y_rule);
                 }});
    t.push_back({"output_offset",
                 OptionType::kFlag,
                 false,
                 {},
                 "true | false",
                 "estimate a constant output offset c (the last parameter)",
                 [flag](const C& c) { return flag(c.problem.output_offset); },
                 [](C* c, V v) {
                   c->problem.output_offset = v.flag;
                   return Status::Ok();
                 }});
    t.push_back({"initial_state",
                 OptionType::kFlag,
                 false,
                 {},
                 "true | false",
                 "estimate the free response of an unknown initial state",
                 [flag](const C& c) { return flag(c.problem.initial_state); },
                 [](C* c, V v) {
                   c->problem.initial_state = v.flag;
                   return Status::Ok();
                 }});
    t.push_back({"fixed",
                 OptionType::kMatrix,
                 false,
                 {},
                 "empty or one entry per parameter",
                 "mask of the coefficients held at fixed_values",
                 [](const C&) { return std::string("(none)"); },
                 [values](C* c, V v) {
                   c->fixed = values(v.matrix);
                   return Status::Ok();
                 }});
    t.push_back({"fixed_values",
                 OptionType::kMatrix,
                 false,
                 {},
                 "finite, one entry per parameter",
                 "the values of the fixed coefficients (original time)",
                 [](const C&) { return std::string("(none)"); },
                 [values](C* c, V v) {
                   c->fixed_values = values(v.matrix);
                   return Status::Ok();
                 }});
    t.push_back(vector_option<C>(
        "theta_init", "finite, one entry per parameter",
        "the start of the iterations (original time)", "(automatic start)",
        ErrorCode::kBadInput,
        [](auto& c) -> auto& { return c.settings.theta_init; }));
    t.push_back({"cutoffs",
                 OptionType::kMatrix,
                 false,
                 {},
                 "finite, > 0 each",
                 "SVF cut-off(s) (rad/s) of LSSVF/IVSVF or of the start grid",
                 [](const C&) { return std::string("(12 log-spaced)"); },
                 [](C* c, V v) {
                   const Matrix<double>& m = v.matrix;
                   c->settings.cutoffs.assign(m.data(), m.data() + m.size());
                   return Status::Ok();
                 }});
    t.push_back(real_option<C>(
        "tol", false, "> 0",
        "stop once the relative change of theta is below it",
        [](auto& c) -> auto& { return c.settings.tolerance; }));
    t.push_back(integer_option<C>(
        "maxiter", false, ">= 1", "largest number of refined-IV iterations",
        [](auto& c) -> auto& { return c.settings.max_iterations; }));
    // (read as a real: a fraction is a bad option, as a count below 1 is)
    t.push_back(
        {"max_starts",
         OptionType::kReal,
         false,
         {},
         "an integer >= 1",
         "SRIVC runs from at most this many of the ranked starts",
         [](const C& c) { return std::to_string(c.settings.max_starts); },
         [](C* c, V v) {
           if (v.real != std::floor(v.real) || !(std::abs(v.real) < 1e9)) {
             return Status(ErrorCode::kBadOption,
                           "max_starts must be an integer >= 1");
           }
           c->settings.max_starts = static_cast<int>(v.real);
           return Status::Ok();
         }});
    t.push_back(real_option<C>(
        "time_scale", false, "finite, >= 0",
        "the time scale sigma of the iterations (t' = sigma t); "
        "0: automatic",
        [](auto& c) -> auto& { return c.settings.time_scale; }));
    t.push_back(real_option<C>(
        "integrator_pole", false, "finite, >= 0",
        "the prefilter pole that replaces p = 0 (rad/s); 0: 10/T",
        [](auto& c) -> auto& { return c.settings.integrator_pole; }));
    t.push_back(
        {"refit_integrators",
         OptionType::kFlag,
         false,
         {},
         "true | false; SRIVC in open loop",
         "refit a fit whose slowest pole crept to p = 0 with that "
         "pole declared",
         [flag](const C& c) { return flag(c.settings.refit_integrators); },
         [](C* c, V v) {
           c->settings.refit_integrators = v.flag;
           return Status::Ok();
         }});
    t.push_back(vector_option<C>(
        "controller_num", "a vector; with controller_den",
        "closed loop: the controller's numerator (powers of p, or of q^-1 "
        "with discrete_controller)",
        "(open loop)", ErrorCode::kBadOption,
        [](auto& c) -> auto& { return c.problem.controller_num; }));
    t.push_back(vector_option<C>(
        "controller_den", "a vector, proper controller",
        "closed loop: the controller's denominator", "(open loop)",
        ErrorCode::kBadOption,
        [](auto& c) -> auto& { return c.problem.controller_den; }));
    t.push_back({"discrete_controller",
                 OptionType::kFlag,
                 false,
                 {},
                 "true | false; ZOH data",
                 "the controller is C(q^-1) in u = r1 + C (r2 - y)",
                 [flag](const C& c) { return flag(c.discrete_controller); },
                 [](C* c, V v) {
                   c->discrete_controller = v.flag;
                   return Status::Ok();
                 }});
    return t;
  }();
  return table;
}

// ---- the Box-Jenkins refined IV -----------------------------------------

enum class RivcMethod { kRivc, kCl2srivc, kArma };

template <typename S>
struct RivcConfig {
  RivcMethod method = RivcMethod::kRivc;
  // nb, nf, nk one entry per input (the problem's own: one input);
  // problem.controller_num/_den: clrivc's controller.
  std::vector<int> nb{RivcProblem<S>().nb}, nf{RivcProblem<S>().nf},
      nk{RivcProblem<S>().nk};
  RivcProblem<S> problem;
  RivcSettings<S> settings;
  // cl2srivc's first stage, u on r: its structure and start.
  int cl_nb = RivcProblem<S>().nb;
  int cl_nf = RivcProblem<S>().nf;
  int cl_nk = RivcProblem<S>().nk;
  Vector<S> cl_theta_init;
};

// The ranges of the rivc options (every error a bad option): maxiter in
// 1..1e5, arma_maxiter in 0..1e5, max_starts in 1..100, tol finite and >
// 0, the cut-offs finite and > 0.
template <typename S>
Status validate(const RivcConfig<S>& config) {
  const RivcSettings<S>& s = config.settings;
  const auto bad = [](const std::string& what) {
    return Status(ErrorCode::kBadOption, what);
  };
  if (!(s.tolerance > 0) || !std::isfinite(s.tolerance)) {
    return bad("tol must be finite and > 0");
  }
  if (s.max_iterations < 1 || s.max_iterations > 100000 ||
      s.arma.max_iterations < 0 || s.arma.max_iterations > 100000 ||
      s.start.max_starts < 1 || s.start.max_starts > 100) {
    return bad(
        "maxiter must be in 1..1e5, arma_maxiter in 0..1e5 and max_starts "
        "in 1..100");
  }
  for (S c : s.start.cutoffs) {
    if (!(c > 0) || !std::isfinite(c)) {
      return bad("the cut-offs (lambda) must be finite and > 0");
    }
  }
  return Status::Ok();
}

template <typename S>
const OptionTable<RivcConfig<S>>& rivc_options() {
  using C = RivcConfig<S>;
  using V = const OptionValue&;
  using options_detail::integers;
  using options_detail::number;
  const auto order = [](const char* name, const char* range, const char* help,
                        std::vector<int> C::*field) {
    return OptionDecl<C>{name,
                         OptionType::kIntegerVector,
                         false,
                         {},
                         range,
                         help,
                         [field](const C& c) { return integers(c.*field); },
                         [field](C* c, V v) {
                           c->*field = v.integers;
                           return Status::Ok();
                         }};
  };
  const auto count = [](const char* name, const char* range, const char* help,
                        int C::*field) {
    return OptionDecl<C>{
        name,
        OptionType::kInteger,
        false,
        {},
        range,
        help,
        [field](const C& c) { return std::to_string(c.*field); },
        [field](C* c, V v) {
          c->*field = v.integer;
          return Status::Ok();
        }};
  };
  static const OptionTable<C> table = [&] {
    OptionTable<C> t;
    t.push_back({"method",
                 OptionType::kChoice,
                 false,
                 {"rivc", "cl2srivc", "arma"},
                 "'rivc' | 'cl2srivc' | 'arma'",
                 "RIVC (CLRIVC with a controller), the two-stage cl2srivc, "
                 "or the ARMA estimator alone on y",
                 [](const C& c) {
                   return std::string(c.method == RivcMethod::kRivc ? "rivc"
                                      : c.method == RivcMethod::kCl2srivc
                                          ? "cl2srivc"
                                          : "arma");
                 },
                 [](C* c, V v) {
                   c->method = v.word == "cl2srivc" ? RivcMethod::kCl2srivc
                               : v.word == "arma"   ? RivcMethod::kArma
                                                    : RivcMethod::kRivc;
                   return Status::Ok();
                 }});
    t.push_back(order("nb", ">= 1 each, at most nf + 1",
                      "numerator coefficients, one per input", &C::nb));
    t.push_back(integer_option<C>(
        "nc", false, ">= 0", "order of the noise numerator C(q^-1)",
        [](auto& c) -> auto& { return c.problem.nc; }));
    t.push_back(integer_option<C>(
        "nd", false, ">= 0", "order of the noise denominator D(q^-1)",
        [](auto& c) -> auto& { return c.problem.nd; }));
    t.push_back(
        order("nf", ">= 1 each", "denominator order, one per input", &C::nf));
    t.push_back(order("nk", ">= 0 each",
                      "input delay in samples, one per input", &C::nk));
    t.push_back(real_option<C>(
        "delay", false, "finite, >= 0; one input, open loop",
        "continuous delay (time units) on top of nk",
        [](auto& c) -> auto& { return c.problem.delay; }));
    t.push_back({"intersample",
                 OptionType::kInteger,
                 false,
                 {},
                 "0 (zoh) | 1 (foh)",
                 "how the input varies between samples",
                 [](const C& c) {
                   return std::to_string(
                       c.problem.u_rule == InterSample::kFoh ? 1 : 0);
                 },
                 [](C* c, V v) {
                   return options_detail::intersample_code(v.integer,
                                                           &c->problem.u_rule);
                 }});
    t.push_back(real_option<C>(
        "tol", false, "finite, > 0",
        "stop once the relative change of theta is below it",
        [](auto& c) -> auto& { return c.settings.tolerance; }));
    t.push_back(integer_option<C>(
        "maxiter", false, "1..1e5", "largest number of RIVC iterations",
        [](auto& c) -> auto& { return c.settings.max_iterations; }));
    t.push_back({"theta_init",
                 OptionType::kMatrix,
                 false,
                 {},
                 "[f b], a stable F",
                 "the start of the iterations; absent: the SRIVC start",
                 [](const C&) { return std::string("(SRIVC start)"); },
                 [](C* c, V v) {
                   c->settings.theta_init =
                       Eigen::Map<const Vector<double>>(v.matrix.data(),
                                                        v.matrix.size())
                           .cast<S>();
                   return Status::Ok();
                 }});
    t.push_back({"cutoffs",
                 OptionType::kMatrix,
                 false,
                 {},
                 "finite, > 0 each",
                 "SVF cut-off(s) (rad/s) of the SRIVC start's IVSVF",
                 [](const C&) { return std::string("(12 log-spaced)"); },
                 [](C* c, V v) {
                   const Matrix<double>& m = v.matrix;
                   c->settings.start.cutoffs.assign(m.data(),
                                                    m.data() + m.size());
                   return Status::Ok();
                 }});
    t.push_back(integer_option<C>(
        "max_starts", false, "1..100",
        "the SRIVC start runs from at most this many ranked starts",
        [](auto& c) -> auto& { return c.settings.start.max_starts; }));
    t.push_back(integer_option<C>(
        "arma_maxiter", false, "0..1e5",
        "largest number of iterations of the noise model's estimator",
        [](auto& c) -> auto& { return c.settings.arma.max_iterations; }));
    t.push_back({"arma_method",
                 OptionType::kChoice,
                 false,
                 {"pem", "ivarma"},
                 "'pem' | 'ivarma'",
                 "the noise model's estimator",
                 [](const C& c) {
                   return std::string(c.settings.arma.method == ArmaMethod::kPem
                                          ? "pem"
                                          : "ivarma");
                 },
                 [](C* c, V v) {
                   c->settings.arma.method = v.word == "ivarma"
                                                 ? ArmaMethod::kIvarma
                                                 : ArmaMethod::kPem;
                   return Status::Ok();
                 }});
    t.push_back(vector_option<C>(
        "controller_num", "a vector; with controller_den",
        "closed loop (clrivc): the controller's numerator, descending "
        "powers of p",
        "(open loop)", ErrorCode::kBadOption,
        [](auto& c) -> auto& { return c.problem.controller_num; }));
    t.push_back(vector_option<C>(
        "controller_den", "a vector, proper controller",
        "closed loop (clrivc): the controller's denominator", "(open loop)",
        ErrorCode::kBadOption,
        [](auto& c) -> auto& { return c.problem.controller_den; }));
    t.push_back(count("cl_nb", ">= 1, at most cl_nf + 1",
                      "cl2srivc's first stage (u on r): numerator "
                      "coefficients",
                      &C::cl_nb));
    t.push_back(count("cl_nf", ">= 1",
                      "cl2srivc's first stage: denominator order", &C::cl_nf));
    t.push_back(count("cl_nk", ">= 0",
                      "cl2srivc's first stage: delay in samples", &C::cl_nk));
    t.push_back({"cl_theta_init",
                 OptionType::kMatrix,
                 false,
                 {},
                 "[f b] of the first stage, a stable F",
                 "cl2srivc's first stage's start; absent: its SRIVC start",
                 [](const C&) { return std::string("(SRIVC start)"); },
                 [](C* c, V v) {
                   c->cl_theta_init = Eigen::Map<const Vector<double>>(
                                          v.matrix.data(), v.matrix.size())
                                          .cast<S>();
                   return Status::Ok();
                 }});
    return t;
  }();
  return table;
}

// ---- the delay search --------------------------------------------------

template <typename S>
const OptionTable<RivDelaySettings<S>>& refined_iv_delay_options() {
  using C = RivDelaySettings<S>;
  using V = const OptionValue&;
  using options_detail::number;
  const auto real = [](const char* name, bool required, const char* range,
                       const char* help, S DelaySearchSettings<S>::*field) {
    return OptionDecl<C>{
        name,
        OptionType::kReal,
        required,
        {},
        range,
        help,
        [field](const C& c) { return number(c.search.*field); },
        [field](C* c, V v) {
          c->search.*field = static_cast<S>(v.real);
          return Status::Ok();
        }};
  };
  const auto count = [](const char* name, const char* range, const char* help,
                        int DelaySearchSettings<S>::*field) {
    return OptionDecl<C>{
        name,
        OptionType::kInteger,
        false,
        {},
        range,
        help,
        [field](const C& c) { return std::to_string(c.search.*field); },
        [field](C* c, V v) {
          c->search.*field = v.integer;
          return Status::Ok();
        }};
  };
  static const OptionTable<C> table = [&] {
    OptionTable<C> t;
    t.push_back({"td0",
                 OptionType::kMatrix,
                 false,
                 {},
                 "empty or one delay (time units)",
                 "the start delay; absent: the grid",
                 [](const C& c) {
                   return c.search.grid ? std::string("(the grid)")
                                        : number(c.search.td_start);
                 },
                 [](C* c, V v) {
                   if (v.matrix.size() > 1) {
                     return Status(ErrorCode::kBadOption,
                                   "td0 must be empty or one delay");
                   }
                   c->search.grid = v.matrix.size() == 0;
                   if (!c->search.grid) c->search.td_start = v.matrix(0);
                   return Status::Ok();
                 }});
    t.push_back(real("tdmin", true, "finite, >= 0",
                     "the lower end of the delay range (time units)",
                     &DelaySearchSettings<S>::td_min));
    t.push_back(real("tdmax", true, "finite, >= tdmin",
                     "the upper end of the delay range (time units)",
                     &DelaySearchSettings<S>::td_max));
    t.push_back(count("numtd", "1..1e5", "the delays of the grid",
                      &DelaySearchSettings<S>::num_td));
    t.push_back({"refine",
                 OptionType::kFlag,
                 false,
                 {},
                 "true | false",
                 "Gauss-Newton steps on the delay from the best grid point "
                 "(or td0)",
                 [](const C& c) {
                   return std::string(c.search.refinement ==
                                              DelayRefinement::kGaussNewton
                                          ? "true"
                                          : "false");
                 },
                 [](C* c, V v) {
                   c->search.refinement = v.flag ? DelayRefinement::kGaussNewton
                                                 : DelayRefinement::kNone;
                   return Status::Ok();
                 }});
    t.push_back(real("tdmax_limit", false, "0, or > tdmax",
                     "the grid is extended up to it while its minimum lies at "
                     "its upper end; 0: not extended",
                     &DelaySearchSettings<S>::extend_limit));
    t.push_back(count("maxiter", ">= 0", "largest number of Gauss-Newton steps",
                      &DelaySearchSettings<S>::max_iterations));
    t.push_back(real("tolpar", false, ">= 0",
                     "stop once a step is below it (sampling intervals)",
                     &DelaySearchSettings<S>::step_tolerance));
    t.push_back(real("tolfun", false, ">= 0",
                     "stop once the relative loss decrease is below it",
                     &DelaySearchSettings<S>::loss_tolerance));
    t.push_back(real("stepmax", false, "> 0",
                     "largest Gauss-Newton step (time units)",
                     &DelaySearchSettings<S>::max_step));
    t.push_back(real("stepreduction", false, "in (0, 1)",
                     "the step's factor while the loss does not decrease",
                     &DelaySearchSettings<S>::step_reduction));
    t.push_back({"noise",
                 OptionType::kMatrix,
                 false,
                 {},
                 "empty or [nd nc]",
                 "RIVC with that ARMA noise model instead of SRIVC",
                 [](const C& c) {
                   return c.noise_model ? "[" + std::to_string(c.nd) + " " +
                                              std::to_string(c.nc) + "]"
                                        : std::string("(none)");
                 },
                 [](C* c, V v) {
                   const Matrix<double>& m = v.matrix;
                   if (m.size() != 0 && m.size() != 2) {
                     return Status(ErrorCode::kBadOption,
                                   "search.noise must be [] or [nd nc]");
                   }
                   c->noise_model = m.size() == 2;
                   if (c->noise_model) {
                     c->nd = static_cast<int>(m(0));
                     c->nc = static_cast<int>(m(1));
                   }
                   return Status::Ok();
                 }});
    return t;
  }();
  return table;
}

}  // namespace ctid
