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

// An intersample rule held in one member (as real_option), read as a
// host's code 0 (zoh) or 1 (foh).
template <typename Config, typename Member>
OptionDecl<Config> intersample_code_option(const char* name, const char* help,
                                           Member member) {
  return member_option<Config>(
      name, OptionType::kInteger, false, "0 (zoh) | 1 (foh)", help, member,
      [](InterSample rule) {
        return std::to_string(rule == InterSample::kFoh ? 1 : 0);
      },
      [](InterSample& rule, const OptionValue& v) {
        return intersample_code(v.integer, &rule);
      });
}

// The start of an iteration (kMatrix, taken in column-major order whatever
// its shape) held in one member; absent: the SRIVC start.
template <typename Config, typename Member>
OptionDecl<Config> srivc_start_option(const char* name, const char* range,
                                      const char* help, Member member) {
  return member_option<Config>(
      name, OptionType::kMatrix, false, range, help, member,
      [](const auto&) { return std::string("(SRIVC start)"); },
      [](auto& target, const OptionValue& v) {
        using Scalar = typename std::decay_t<decltype(target)>::Scalar;
        target =
            Eigen::Map<const Vector<double>>(v.matrix.data(), v.matrix.size())
                .cast<Scalar>();
        return Status::Ok();
      });
}

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
  // One entry per column of w, shown by RivChannel's default `shown`.
  const auto per_column = [](const char* name, bool required, const char* range,
                             const char* help, std::string shown,
                             std::vector<int> C::*member) {
    OptionDecl<C> decl = integer_vector_option<C>(name, required, range, help,
                                                  member_access(member));
    decl.show = [shown](const C&) { return shown; };
    return decl;
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
    t.push_back(integer_vector_option<C>(
        "nf", true, ">= 1 each", "order of each denominator F_g",
        [](auto& c) -> auto& { return c.problem.nf; }));
    t.push_back(per_column("group", true, "1..numel(nf) each",
                           "the denominator each column of w enters (1-based)",
                           each(RivChannel().group + 1), &C::group));
    t.push_back(integer_vector_option<C>(
        "nb", true, ">= 0 each, at most nf + 1 of its group",
        "numerator coefficients of each column of w", member_access(&C::nb)));
    t.push_back(per_column("nk", true, ">= 0 each (0 on irregular data)",
                           "input delay in samples of each column of w",
                           each(RivChannel().nk), &C::nk));
    t.push_back(per_column("intersample", false, "0 (zoh) | 1 (foh) each",
                           "how each column of w varies between samples",
                           each(RivChannel().rule == InterSample::kFoh ? 1 : 0),
                           &C::intersample));
    t.push_back(real_list_option<C>(
        "delay", "finite, >= 0 each; open loop",
        "continuous delay (time units) of each column of w on top of nk",
        options_detail::number(RivChannel().delay) + " each",
        member_access(&C::delay)));
    t.push_back(options_detail::intersample_code_option<C>(
        "y_intersample",
        "how the output is interpolated by the refined steps' filters",
        [](auto& c) -> auto& { return c.problem.y_rule; }));
    t.push_back(flag_option<C>(
        "output_offset", "true | false",
        "estimate a constant output offset c (the last parameter)",
        [](auto& c) -> auto& { return c.problem.output_offset; }));
    t.push_back(flag_option<C>(
        "initial_state", "true | false",
        "estimate the free response of an unknown initial state",
        [](auto& c) -> auto& { return c.problem.initial_state; }));
    t.push_back(
        real_list_option<C>("fixed", "empty or one entry per parameter",
                            "mask of the coefficients held at fixed_values",
                            "(none)", member_access(&C::fixed)));
    t.push_back(real_list_option<C>(
        "fixed_values", "finite, one entry per parameter",
        "the values of the fixed coefficients (original time)", "(none)",
        member_access(&C::fixed_values)));
    t.push_back(vector_option<C>(
        "theta_init", "finite, one entry per parameter",
        "the start of the iterations (original time)", "(automatic start)",
        ErrorCode::kBadInput,
        [](auto& c) -> auto& { return c.settings.theta_init; }));
    t.push_back(real_list_option<C>(
        "cutoffs", "finite, > 0 each",
        "SVF cut-off(s) (rad/s) of LSSVF/IVSVF or of the start grid",
        "(12 log-spaced)",
        [](auto& c) -> auto& { return c.settings.cutoffs; }));
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
    t.push_back(flag_option<C>(
        "refit_integrators", "true | false; SRIVC in open loop",
        "refit a fit whose slowest pole crept to p = 0 with that pole declared",
        [](auto& c) -> auto& { return c.settings.refit_integrators; }));
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
    t.push_back(
        flag_option<C>("discrete_controller", "true | false; ZOH data",
                       "the controller is C(q^-1) in u = r1 + C (r2 - y)",
                       member_access(&C::discrete_controller)));
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
  static const OptionTable<C> table = [] {
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
    t.push_back(numerator_counts_option<C>(false, member_access(&C::nb)));
    t.push_back(integer_option<C>(
        "nc", false, ">= 0", "order of the noise numerator C(q^-1)",
        [](auto& c) -> auto& { return c.problem.nc; }));
    t.push_back(integer_option<C>(
        "nd", false, ">= 0", "order of the noise denominator D(q^-1)",
        [](auto& c) -> auto& { return c.problem.nd; }));
    t.push_back(integer_vector_option<C>("nf", false, ">= 1 each",
                                         "denominator order, one per input",
                                         member_access(&C::nf)));
    t.push_back(input_delays_option<C>(member_access(&C::nk)));
    t.push_back(real_option<C>(
        "delay", false, "finite, >= 0; one input, open loop",
        "continuous delay (time units) on top of nk",
        [](auto& c) -> auto& { return c.problem.delay; }));
    t.push_back(options_detail::intersample_code_option<C>(
        "intersample", "how the input varies between samples",
        [](auto& c) -> auto& { return c.problem.u_rule; }));
    t.push_back(real_option<C>(
        "tol", false, "finite, > 0",
        "stop once the relative change of theta is below it",
        [](auto& c) -> auto& { return c.settings.tolerance; }));
    t.push_back(integer_option<C>(
        "maxiter", false, "1..1e5", "largest number of RIVC iterations",
        [](auto& c) -> auto& { return c.settings.max_iterations; }));
    t.push_back(options_detail::srivc_start_option<C>(
        "theta_init", "[f b], a stable F",
        "the start of the iterations; absent: the SRIVC start",
        [](auto& c) -> auto& { return c.settings.theta_init; }));
    t.push_back(real_list_option<C>(
        "cutoffs", "finite, > 0 each",
        "SVF cut-off(s) (rad/s) of the SRIVC start's IVSVF", "(12 log-spaced)",
        [](auto& c) -> auto& { return c.settings.start.cutoffs; }));
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
    t.push_back(integer_option<C>(
        "cl_nb", false, ">= 1, at most cl_nf + 1",
        "cl2srivc's first stage (u on r): numerator coefficients",
        member_access(&C::cl_nb)));
    t.push_back(integer_option<C>("cl_nf", false, ">= 1",
                                  "cl2srivc's first stage: denominator order",
                                  member_access(&C::cl_nf)));
    t.push_back(integer_option<C>("cl_nk", false, ">= 0",
                                  "cl2srivc's first stage: delay in samples",
                                  member_access(&C::cl_nk)));
    t.push_back(options_detail::srivc_start_option<C>(
        "cl_theta_init", "[f b] of the first stage, a stable F",
        "cl2srivc's first stage's start; absent: its SRIVC start",
        member_access(&C::cl_theta_init)));
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
  // A member of the search's settings.
  const auto search = [](auto DelaySearchSettings<S>::*field) {
    return [field](auto& c) -> auto& { return c.search.*field; };
  };
  const auto real = [search](const char* name, bool required, const char* range,
                             const char* help,
                             S DelaySearchSettings<S>::*field) {
    return real_option<C>(name, required, range, help, search(field));
  };
  const auto count = [search](const char* name, const char* range,
                              const char* help,
                              int DelaySearchSettings<S>::*field) {
    return integer_option<C>(name, false, range, help, search(field));
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
