// SPDX-License-Identifier: BSD-3-Clause
// Copyright (C) the ctid authors
// The named options of the recursive estimators, declared once, beside
// their config structs (RlsSvfConfig, RecursiveIvConfig), in the form of
// base/options.hpp. Hosts read options through these tables (the MEX
// gateways rlssvf_mex and riv_mex do; a C++ program may too, with
// set_option()), and validate(config) is the one range check on every
// path.
//
//   RecursiveIvConfig<double> config;
//   OptionValue v;
//   v.real = 3;
//   Status s = set_option(recursive_iv_options<double>(), "lambda_svf", v,
//                         &config);
#pragma once

#include <cstdio>
#include <functional>
#include <limits>
#include <string>
#include <utility>
#include <vector>

#include "ctid/base/options.hpp"
#include "ctid/recursive/recursive_iv.hpp"
#include "ctid/recursive/rlssvf.hpp"

namespace ctid {

namespace options_detail {

// The parameters a config estimates (the size of Qn, th0, P0, M_s).
template <typename S>
Eigen::Index estimated_count(const RlsSvfConfig<S>& c) {
  return num_estimated(c);
}
template <typename S>
Eigen::Index estimated_count(const RecursiveIvConfig<S>& c) {
  return c.orders.num_parameters();
}

// The options every recursive estimator shares, for Config = RlsSvfConfig
// or RecursiveIvConfig (same member names), in two parts: the model
// structure and its filter, then the adaptation and the start. Table
// order is the order a host applies them in: the orders (and an
// estimator's own structural options) before anything sized by them, adm
// before adg.
template <typename S, typename Config>
void add_structure_options(OptionTable<Config>* table) {
  using V = const OptionValue&;
  table->push_back({"intersample",
                    OptionType::kChoice,
                    false,
                    {"zoh", "foh", "trapezoid"},
                    "'zoh' | 'foh' | 'trapezoid'",
                    "how the input varies between samples: the input filters' "
                    "discretisation",
                    [](const Config& c) {
                      return std::string(intersample_word(c.svf.u_intersample));
                    },
                    [](Config* c, V v) {
                      c->svf.u_intersample = intersample_of(v.word);
                      return Status::Ok();
                    }});
  table->push_back(integer_option<Config>(
      "na", true, ">= 1", "denominator order",
      [](auto& c) -> auto& { return c.orders.na; }));
  table->push_back(integer_vector_option<Config>(
      "nb", true, ">= 0 each, at most na + 1",
      "numerator parameters, one per input",
      [](auto& c) -> auto& { return c.orders.nb; }));
  table->push_back({"nk",
                    OptionType::kIntegerVector,
                    true,
                    {},
                    ">= 0 each",
                    "input delay in samples, one per input",
                    [](const Config& c) { return integers(c.orders.nk); },
                    [](Config* c, V v) {
                      c->orders.nk = v.integers;
                      return validate_orders(c->orders);
                    }});
  table->push_back(real_option<Config>(
      "lambda_svf", true, "> 0, finite",
      "cut-off (rad/s) of the state-variable filter",
      [](auto& c) -> auto& { return c.svf.lambda_svf; }));
  table->push_back(
      {"svf",
       OptionType::kChoice,
       false,
       {"normalised", "normalized", "ordinary"},
       "'normalised' | 'ordinary'",
       "the SVF (lambda/(p + lambda))^na (eq. 3.1) or 1/(p + lambda)^na",
       [](const Config& c) {
         return std::string(c.svf.normalised ? "normalised" : "ordinary");
       },
       [](Config* c, V v) {
         c->svf.normalised = v.word != "ordinary";
         return Status::Ok();
       }});
  table->push_back(
      {"kernels",
       OptionType::kChoice,
       false,
       {"fixed", "dynamic"},
       "'fixed' | 'dynamic'",
       "fixed-size filter kernels for orders 1-4, or the dynamic-size "
       "reference",
       [](const Config& c) {
         return std::string(
             c.svf.kernels == FilterKernels::kFixedSize ? "fixed" : "dynamic");
       },
       [](Config* c, V v) {
         c->svf.kernels = v.word == "dynamic" ? FilterKernels::kDynamic
                                              : FilterKernels::kFixedSize;
         return Status::Ok();
       }});
}

template <typename S, typename Config>
void add_estimate_options(OptionTable<Config>* table) {
  using V = const OptionValue&;
  table->push_back(
      {"adm",
       OptionType::kChoice,
       false,
       {"ff", "kf"},
       "'ff' | 'kf'",
       "adaptation: forgetting factor (eq. 1.57) or Kalman filter (eq. 1.59; "
       "Qn = 0 unless adg is given)",
       [](const Config& c) {
         return std::string(
             std::holds_alternative<ForgettingFactorAdaptation<S>>(c.adaptation)
                 ? "ff"
                 : "kf");
       },
       [](Config* c, V v) {
         if (v.word == "kf") {
           // Qn = 0 until adg says otherwise: no drift of the parameters.
           const Eigen::Index n = estimated_count(*c);
           c->adaptation = KalmanAdaptation<S>(Matrix<S>::Zero(n, n));
         } else {
           c->adaptation = ForgettingFactorAdaptation<S>();
         }
         return Status::Ok();
       }});
  table->push_back(
      {"adg",
       OptionType::kMatrix,
       false,
       {},
       "ff: a scalar in (0, 1]; kf: np-by-np, symmetric, positive "
       "semi-definite",
       "the forgetting factor (adm 'ff') or Qn (adm 'kf')",
       [](const Config& c) {
         if (const auto* ff =
                 std::get_if<ForgettingFactorAdaptation<S>>(&c.adaptation)) {
           return number(ff->lambda());
         }
         return matrix_text(std::get<KalmanAdaptation<S>>(c.adaptation).qn(),
                            "[]");
       },
       [](Config* c, V v) -> Status {
         if (std::holds_alternative<ForgettingFactorAdaptation<S>>(
                 c->adaptation)) {
           if (v.matrix.size() != 1) {
             return bad_input(
                 "adg with adm 'ff' must be a scalar (the forgetting "
                 "factor)");
           }
           c->adaptation =
               ForgettingFactorAdaptation<S>(static_cast<S>(v.matrix(0, 0)));
         } else {
           // Checked here, not by validate(): KalmanAdaptation keeps the
           // symmetric part of what it is given.
           const Matrix<double>& q = v.matrix;
           if (q.rows() != q.cols()) {
             return bad_input("adg (Qn) must be square");
           }
           if ((q - q.transpose()).cwiseAbs().maxCoeff() >
               1000 * std::numeric_limits<double>::epsilon() *
                   q.cwiseAbs().maxCoeff()) {
             return bad_input("adg (Qn) must be symmetric");
           }
           c->adaptation = KalmanAdaptation<S>(q.cast<S>());
         }
         return Status::Ok();
       }});
  table->push_back(vector_option<Config>(
      "th0", "np-by-1, finite", "initial estimate (default zeros)", "0",
      ErrorCode::kDimensionMismatch,
      [](auto& c) -> auto& { return c.theta0; }));
  table->push_back({"P0",
                    OptionType::kMatrix,
                    false,
                    {},
                    "np-by-np, symmetric, positive definite",
                    "initial covariance (default 1e4 I)",
                    [](const Config& c) { return matrix_text(c.P0, "1e4 I"); },
                    [](Config* c, V v) {
                      c->P0 = v.matrix.cast<S>();
                      return Status::Ok();
                    }});
  table->push_back(vector_option<Config>(
      "scaling", "np-by-1, > 0",
      "diagonal of the scaling matrix M_s (eq. 3.74); [] for none", "none",
      ErrorCode::kDimensionMismatch,
      [](auto& c) -> auto& { return c.scaling; }));
  table->push_back(flag_option<Config>(
      "covariance_guard", "true | false",
      "keep P symmetric positive definite (covariance_guard.hpp)",
      member_access(&Config::covariance_guard)));
  table->push_back(real_option<Config>(
      "gap_interval", false, ">= 0, finite",
      "a sampling interval above this (s) is a gap of missing samples (0: "
      "none)",
      member_access(&Config::gap_interval)));
  table->push_back(
      real_option<Config>("gap_settle", false, ">= 0, finite",
                          "no update for this long (s) after a gap",
                          member_access(&Config::gap_settle)));
}

}  // namespace options_detail

// The options of RLSSVF (rlssvf.hpp).
template <typename S>
const OptionTable<RlsSvfConfig<S>>& rlssvf_options() {
  using Config = RlsSvfConfig<S>;
  using V = const OptionValue&;
  static const OptionTable<Config> table = [] {
    OptionTable<Config> t;
    options_detail::add_structure_options<S>(&t);
    t.push_back(
        {"form",
         OptionType::kChoice,
         false,
         {"standard", "potter", "lmr"},
         "'standard' | 'potter' | 'lmr'",
         "the update: P (eqs. 1.57/1.59), Potter's square root (eq. 3.73) "
         "or LMR (eq. 3.82)",
         [](const Config& c) {
           return std::string(c.form == UpdateForm::kPotter ? "potter"
                              : c.form == UpdateForm::kLevenbergMarquardt
                                  ? "lmr"
                                  : "standard");
         },
         [](Config* c, V v) {
           c->form = v.word == "potter" ? UpdateForm::kPotter
                     : v.word == "lmr"  ? UpdateForm::kLevenbergMarquardt
                                        : UpdateForm::kStandard;
           return Status::Ok();
         }});
    t.push_back(flag_option<Config>(
        "ic", "true | false", "estimate the initial conditions c_1 .. c_na too",
        member_access(&Config::initial_conditions)));
    options_detail::add_estimate_options<S>(&t);
    t.push_back({"Gamma",
                 OptionType::kMatrix,
                 false,
                 {},
                 "np-by-np, symmetric, positive semi-definite",
                 "the regularisation Gamma of LMR (eq. 3.82)",
                 [](const Config& c) {
                   return options_detail::matrix_text(c.lmr_gamma, "[]");
                 },
                 [](Config* c, V v) {
                   c->lmr_gamma = v.matrix.cast<S>();
                   return Status::Ok();
                 }});
    t.push_back(real_option<Config>(
        "tsls", false, ">= 0, finite",
        "first update at the first sample with t - t_1 >= tsls (s)",
        member_access(&Config::t_s_ls)));
    return t;
  }();
  return table;
}

// The options of the recursive IV estimators RIVSVF and RSRIVC, open and
// closed loop (recursive_iv.hpp).
template <typename S>
const OptionTable<RecursiveIvConfig<S>>& recursive_iv_options() {
  using Config = RecursiveIvConfig<S>;
  using V = const OptionValue&;
  static const OptionTable<Config> table = [] {
    OptionTable<Config> t;
    options_detail::add_structure_options<S>(&t);
    options_detail::add_estimate_options<S>(&t);
    t.push_back({"method",
                 OptionType::kChoice,
                 false,
                 {"rivsvf", "rsrivc"},
                 "'rivsvf' | 'rsrivc'",
                 "the SVF as prefilter (sec. 2.2.3) or the adaptive prefilter "
                 "(sec. 2.3.3)",
                 [](const Config& c) {
                   return std::string(c.method == IvMethod::kRivsvf ? "rivsvf"
                                                                    : "rsrivc");
                 },
                 [](Config* c, V v) {
                   c->method = v.word == "rivsvf" ? IvMethod::kRivsvf
                                                  : IvMethod::kRsrivc;
                   return Status::Ok();
                 }});
    t.push_back(real_option<Config>(
        "tsiv", false, ">= 0, finite",
        "RLSSVF until tsiv (s), the IV update after it (the "
        "front-ends default to a tenth of the record, as CONTSID)",
        member_access(&Config::t_s_iv)));
    t.push_back(real_option<Config>(
        "dtupdate", false, ">= 0, finite",
        "refresh period (s) of the auxiliary model and the prefilter (0: "
        "every sample)",
        member_access(&Config::dtupdate)));
    t.push_back(
        {"stability",
         OptionType::kChoice,
         false,
         {"keep", "reflect"},
         "'keep' | 'reflect'",
         "an unstable estimate keeps the last stable one or is reflected "
         "(eq. 3.10)",
         [](const Config& c) {
           return std::string(
               c.stability == StabilityPolicy::kReflect ? "reflect" : "keep");
         },
         [](Config* c, V v) {
           c->stability = v.word == "reflect" ? StabilityPolicy::kReflect
                                              : StabilityPolicy::kKeepLast;
           return Status::Ok();
         }});
    t.push_back(vector_option<Config>(
        "mtheta_num", "a vector, with mtheta_den; unit static gain",
        "numerator of the smoothing filter M_theta(q^-1) (default q^-1)",
        "q^-1", ErrorCode::kBadInput,
        [](auto& c) -> auto& { return c.m_theta.numerator; }));
    t.push_back(vector_option<Config>(
        "mtheta_den", "a vector, with mtheta_num",
        "denominator of M_theta(q^-1)", "1", ErrorCode::kBadInput,
        [](auto& c) -> auto& { return c.m_theta.denominator; }));
    t.push_back(
        {"prefilter",
         OptionType::kChoice,
         false,
         {"unit", "monic"},
         "'unit' | 'monic'",
         "gain of the adaptive prefilter: f_na/A(p) or 1/A(p) (eq. 2.19)",
         [](const Config& c) {
           return std::string(
               c.prefilter_gain == PrefilterGain::kMonic ? "monic" : "unit");
         },
         [](Config* c, V v) {
           c->prefilter_gain = v.word == "monic"
                                   ? PrefilterGain::kMonic
                                   : PrefilterGain::kUnitStaticGain;
           return Status::Ok();
         }});
    t.push_back(vector_option<Config>(
        "A", "1-by-na, a stable [a1 .. a_na]",
        "denominator that starts the prefilter and the auxiliary model "
        "(default (p + lambda_svf)^na)",
        "(p + lambda_svf)^na", ErrorCode::kBadInput,
        [](auto& c) -> auto& { return c.initial_denominator; }));
    t.push_back({"controller_num",
                 OptionType::kMatrix,
                 false,
                 {},
                 "a vector, with controller_den",
                 "numerator of the controller C(q^-1), u = r1 + C (r2 - y)",
                 [](const Config& c) {
                   return options_detail::matrix_text(
                       Matrix<S>(c.controller.numerator), "open loop");
                 },
                 [](Config* c, V v) {
                   c->closed_loop = true;
                   return options_detail::set_vector<S>(
                       v, "controller_num", ErrorCode::kBadInput,
                       &c->controller.numerator);
                 }});
    t.push_back({"controller_den",
                 OptionType::kMatrix,
                 false,
                 {},
                 "a vector, with controller_num",
                 "denominator of the controller C(q^-1)",
                 [](const Config& c) {
                   return options_detail::matrix_text(
                       Matrix<S>(c.controller.denominator), "open loop");
                 },
                 [](Config* c, V v) {
                   c->closed_loop = true;
                   return options_detail::set_vector<S>(
                       v, "controller_den", ErrorCode::kBadInput,
                       &c->controller.denominator);
                 }});
    t.push_back(real_option<Config>(
        "antiwindup", false, "0 (none) or > 1",
        "conditional updating: the threshold gamma on kappa_2(P) (eq. 3.79)",
        member_access(&Config::antiwindup_gamma)));
    t.push_back(real_option<Config>(
        "antiwindup_lambda", false, "(0, 1]",
        "forgetting factor of the parallel RLSSVF-FF of conditional "
        "updating (Table 3.2)",
        member_access(&Config::antiwindup_lambda)));
    return t;
  }();
  return table;
}

}  // namespace ctid
