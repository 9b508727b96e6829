// SPDX-License-Identifier: BSD-3-Clause
// Copyright (C) the ctid authors
// The named options of the transfer-function estimators with a delay in
// CONTSID's form (the toolbox's tfsrivc, tfsrivc_init, tfrivc), declared
// once in the form of base/options.hpp over TfsrivcConfig. Their defaults
// are TfsrivcConfig's member initialisers: CONTSID 7.3's documented
// defaults of tfsrivc (NumTd 50, MaxIter 100, StepReduction 2, FocusOrder
// 5, FixTd and Integration off), except the tolerances, tighter here
// (CONTSID: 1e-4 both), and StepMax, one grid spacing here (a Gauss-Newton
// step on td never jumps over the grid's minimum). TdMax and StepMax left
// out are the data's (delay_search_defaults.hpp). They differ from the
// refined-IV engine's (refined_iv_options.hpp) and are mapped onto it and
// onto the delay search (refined_iv_delay_options()) by the host. The
// ranges are checked once, by validate(TfsrivcConfig) below.
//
//   TfsrivcConfig<double> config;
//   OptionValue v;
//   v.real = 1.5;
//   Status s = set_option(tfsrivc_options<double>(), "tdmax", v, &config);
//   if (s.ok()) s = validate(config);
#pragma once

#include <cmath>
#include <limits>
#include <string>

#include "ctid/base/options.hpp"
#include "ctid/base/status.hpp"

namespace ctid {

template <typename S>
struct TfsrivcConfig {
  bool fix_td = false;  // keep the start delay
  S td_min = 0;         // the delay range of the search (time units)
  // NaN: from the data (delay_search_defaults.hpp, delay_search_range)
  S td_max = std::numeric_limits<S>::quiet_NaN();
  int num_td = 50;  // the delays of the grid
  S lambda = 0;     // the SVF cut-off of the start; 0: the engine's grid
  int max_iterations = 100;  // SRIVC iterations and Gauss-Newton steps
  S tol_par = S(1e-5);       // relative change of theta; delay step (samples)
  S tol_fun = S(1e-8);       // relative loss decrease
  S step_max = 0;            // largest delay step; 0: one grid spacing
  S step_reduction = 2;      // > 1 divides a failed step, in (0, 1) scales
  int focus_order = 5;       // order of the Focus low-pass
  bool integration = false;  // an integrator enforced (a pole at s = 0)

  // The factor a step that does not decrease the loss is multiplied by
  // (CONTSID's r > 1 divides it).
  S step_factor() const {
    return step_reduction > 1 ? 1 / step_reduction : step_reduction;
  }
};

// The ranges of the table's options.
template <typename S>
Status validate(const TfsrivcConfig<S>& c) {
  const auto bad = [](const char* m) {
    return Status(ErrorCode::kBadOption, m);
  };
  if (!(c.td_min >= 0) || !std::isfinite(c.td_min) ||
      !(std::isnan(c.td_max) || c.td_max >= c.td_min)) {
    return bad("need 0 <= TdMin <= TdMax (finite)");
  }
  if (c.num_td < 1) return bad("NumTd must be an integer >= 1");
  if (c.max_iterations < 1) return bad("MaxIter must be an integer >= 1");
  if (!(c.tol_par > 0) || !(c.tol_fun >= 0)) {
    return bad("TolPar > 0 and TolFun >= 0 needed");
  }
  if (!(c.step_reduction > 0) || c.step_reduction == 1) {
    return bad(
        "StepReduction must be a factor > 1 (the delay step is divided by "
        "it) or in (0, 1) (multiplied)");
  }
  if (c.focus_order < 1 || c.focus_order > 10) {
    return bad("FocusOrder must be an integer in 1..10");
  }
  return Status::Ok();
}

template <typename S>
const OptionTable<TfsrivcConfig<S>>& tfsrivc_options() {
  using C = TfsrivcConfig<S>;
  using options_detail::number;
  const auto flag = [](const char* name, const char* help, bool C::*member) {
    return flag_option<C>(name, "true | false ('on' | 'off')", help,
                          member_access(member));
  };
  const auto real = [](const char* name, bool required, const char* range,
                       const char* help, S C::*member) {
    return real_option<C>(name, required, range, help, member_access(member));
  };
  // A real > 0 whose default 0 stands for an automatic value.
  const auto automatic = [](const char* name, const char* shown,
                            const char* help, S C::*member) {
    return member_option<C>(
        name, OptionType::kReal, false, "> 0", help, member_access(member),
        [shown](S x) { return x == 0 ? std::string(shown) : number(x); },
        [name](S& target, const OptionValue& v) {
          if (!(v.real > 0)) {
            return Status(ErrorCode::kBadOption,
                          std::string(name) + " must be a scalar > 0");
          }
          target = static_cast<S>(v.real);
          return Status::Ok();
        });
  };
  const auto count = [](const char* name, const char* range, const char* help,
                        int C::*member) {
    return integer_option<C>(name, false, range, help, member_access(member));
  };
  static const OptionTable<C> table = [&] {
    OptionTable<C> t;
    t.push_back(flag("fixtd", "keep the start delay (IODelay)", &C::fix_td));
    t.push_back(real("tdmin", false, "finite, >= 0",
                     "the lower end of the delay search (time units)",
                     &C::td_min));
    t.push_back(
        derived_real_option<C>("tdmax", "finite, >= tdmin",
                               "the upper end of the delay search (time units)",
                               "(from the input-output cross-correlation)",
                               member_access(&C::td_max)));
    t.push_back(
        count("numtd", ">= 1", "the delays of the search's grid", &C::num_td));
    t.push_back(automatic("lambda", "(the engine's grid of cut-offs)",
                          "the SVF cut-off (rad/s) of the start", &C::lambda));
    t.push_back(count("maxiter", ">= 1",
                      "largest number of SRIVC iterations and of "
                      "Gauss-Newton steps on the delay",
                      &C::max_iterations));
    t.push_back(real("tolpar", false, "> 0",
                     "stop once the relative change of theta and the delay "
                     "step (sampling intervals) are below it",
                     &C::tol_par));
    t.push_back(real("tolfun", false, ">= 0",
                     "stop once the relative loss decrease is below it",
                     &C::tol_fun));
    t.push_back(automatic("stepmax",
                          "(one grid spacing, at least one sampling interval)",
                          "largest Gauss-Newton step on the delay (time "
                          "units)",
                          &C::step_max));
    t.push_back(real("stepreduction", false, "> 1 (divides) or in (0, 1)",
                     "the factor of a delay step that does not decrease the "
                     "loss",
                     &C::step_reduction));
    t.push_back(count("focusorder", "1..10",
                      "order of the Focus filter's Butterworth low-pass",
                      &C::focus_order));
    t.push_back(flag("integration", "an integrator enforced (a pole at s = 0)",
                     &C::integration));
    return t;
  }();
  return table;
}

}  // namespace ctid
