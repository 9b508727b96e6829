// SPDX-License-Identifier: BSD-3-Clause
// Copyright (C) the ctid authors

// The convergence of an RLSSVF start-up (rlsconverge, and `"tsiv",
// "auto"` of the recursive IV routines, which switch from RLSSVF to IV
// once the RLSSVF estimates have settled): RLSSVF runs over the record
// (rlssvf.hpp, thesis eqs. 1.32 and 1.57-1.59) with its frozen model's
// output (eq. 1.60) and the ratio trace P / trace P0 after each
// recursion, and convergence_detector.hpp examines the run.
//
//   RlsSvfConfig<double> config;        // orders, cut-off, adaptation...
//   ConvergenceSettings settings;       // block_length > 0, ...
//   ConvergenceRun<double> run;
//   Status s = rlssvf_convergence(config, record, settings, &run);
//   // run.report.converged, run.report.tsiv; run.thm, run.yh
#pragma once

#include <string>

#include "ctid/base/options.hpp"
#include "ctid/base/record.hpp"
#include "ctid/base/status.hpp"
#include "ctid/base/types.hpp"
#include "ctid/recursive/convergence_detector.hpp"
#include "ctid/recursive/rlssvf.hpp"

namespace ctid {

template <typename S>
struct ConvergenceRun {
  ConvergenceReport<S> report;
  Matrix<S> thm;  // N-by-np RLSSVF estimates
  Vector<S> yh;   // N simulated outputs of the frozen models
};

// The detector's settings on their own, before the run (the detector
// checks them again; here a bad option costs no RLSSVF run). A block must
// hold two samples of a uniformly sampled record (ts > 0).
inline Status validate(const ConvergenceSettings& s, double ts) {
  if (!(s.block_length > 0) || !std::isfinite(s.block_length)) {
    return bad_input("blocklength must be a finite real scalar > 0");
  }
  if (ts > 0 && s.block_length < 2 * ts * (1 - 1e-12)) {
    return bad_input("blocklength (" + std::to_string(s.block_length) +
                     " s) must hold at least two samples (Ts = " +
                     std::to_string(ts) + " s)");
  }
  if (s.num_blocks < 3) return bad_input("nblocks must be an integer >= 3");
  if (!(s.alpha > 0 && s.alpha < 0.5)) {
    return bad_input("alpha must lie in (0, 0.5)");
  }
  if (!(s.tol_theta > 0) || !std::isfinite(s.tol_theta)) {
    return bad_input("tol_theta must be a finite real scalar > 0");
  }
  if (!(s.ey_floor >= 0) || !std::isfinite(s.ey_floor)) {
    return bad_input("eyfloor must be a finite real >= 0");
  }
  if (!(s.p_tol > 0) || !std::isfinite(s.p_tol)) {
    return bad_input("ptol must be a finite real scalar > 0");
  }
  if (!s.use_output_error && !s.use_theta && !s.use_p) {
    return Status(ErrorCode::kBadOption,
                  "at least one criterion (output error, theta, P) is needed");
  }
  return Status::Ok();
}

// The detector's named options (base/options.hpp), the names of
// rlsconverge's options; the criteria as one flag each. Defaults are
// ConvergenceSettings' member initialisers; validate() above is the one
// range check.
inline const OptionTable<ConvergenceSettings>& convergence_options() {
  using C = ConvergenceSettings;
  auto real = [](const char* name, const char* range, const char* help,
                 double C::*member, bool required = false) {
    return real_option<C>(name, required, range, help, member_access(member));
  };
  auto flag = [](const char* name, const char* help, bool C::*member) {
    return flag_option<C>(name, "true or false", help, member_access(member));
  };
  static const OptionTable<C> table = {
      real("blocklength", "> 0, at least two samples", "block length T_b (s)",
           &C::block_length, true),
      integer_option<C>("nblocks", false, ">= 3",
                        "blocks n of the moving window",
                        member_access(&C::num_blocks)),
      real("alpha", "in (0, 0.5)",
           "significance level of the output-error steady-state test",
           &C::alpha),
      real("tol_theta", "> 0", "threshold of the estimates' relative change",
           &C::tol_theta),
      real("eyfloor", ">= 0", "relative output-error floor", &C::ey_floor),
      real("ptol", "> 0", "threshold of trace P / trace P0", &C::p_tol),
      flag("use_outputerror", "examine the output error", &C::use_output_error),
      flag("use_theta", "examine the estimates' change", &C::use_theta),
      flag("use_P", "examine trace P / trace P0", &C::use_p),
  };
  return table;
}

template <typename S>
Status rlssvf_convergence(const RlsSvfConfig<S>& config,
                          const RecordView<S>& record,
                          const ConvergenceSettings& settings,
                          ConvergenceRun<S>* run) {
  Status status = validate(settings, static_cast<double>(record.ts));
  if (!status.ok()) return status;
  status = validate_record(record, config.orders);
  if (!status.ok()) return status;
  const Eigen::Index n = record.num_samples;
  const Eigen::Index np = config.orders.num_parameters();
  run->thm.resize(n, np);
  run->yh.resize(n);
  Vector<S> pset;
  RecursiveOutputs<S> out;
  out.thm = run->thm.data();
  out.yh = run->yh.data();
  if (settings.use_p) {
    pset.resize(n * np * np);
    out.pset = pset.data();
  }
  status = run_rlssvf(config, record, out);
  if (!status.ok()) return status;
  // trace P / trace P0, P0 as RLSSVF starts it (1e4 I when not given)
  Vector<S> trace_ratio;
  if (settings.use_p) {
    const S trace0 =
        config.P0.size() != 0 ? config.P0.trace() : S(1e4) * static_cast<S>(np);
    trace_ratio.resize(n);
    for (Eigen::Index k = 0; k < n; ++k) {
      S trace = 0;
      for (Eigen::Index i = 0; i < np; ++i) {
        trace += pset[k * np * np + i * np + i];
      }
      trace_ratio[k] = trace / trace0;
    }
  }
  Vector<S> t(n);
  for (Eigen::Index k = 0; k < n; ++k) {
    t[k] = record.instants != nullptr ? record.instants[k] - record.instants[0]
                                      : static_cast<S>(k) * record.ts;
  }
  return detect_convergence(t.data(), record.y, run->yh.data(), run->thm,
                            settings.use_p ? trace_ratio.data() : nullptr,
                            settings, run->report);
}

}  // namespace ctid
