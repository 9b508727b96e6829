// SPDX-License-Identifier: BSD-3-Clause
// Copyright (C) the ctid authors
// The info fields of a RIVC result (core/include/ctid/offline/
// refined_iv_bj.hpp), written once for the two gateways that return it:
// rivc_mex (method 'rivc') and refined_iv_mex (its delay search with a
// noise model).
#pragma once

#include "ctid/offline/refined_iv_bj.hpp"
#include "gateway_common.hpp"

namespace ctid::mex {

// The fields RIVC's info holds, in the order rivc_mex's info lists them.
inline const std::vector<const char*>& rivc_info_fields() {
  static const std::vector<const char*> fields = {
      "converged", "iterations",     "reason",           "C",
      "D",         "noise_variance", "noise_covariance", "simulation_variance",
      "simulated", "condition",      "start_theta"};
  return fields;
}

// Sets those fields of the 1x1 struct info (which has them) from res.
inline void set_rivc_info(mxArray* info, const RivcResult<double>& res) {
  mxSetField(info, 0, "converged", mxCreateLogicalScalar(res.converged));
  mxSetField(info, 0, "iterations", mxCreateDoubleScalar(res.iterations));
  mxSetField(info, 0, "reason", mxCreateString(res.reason.c_str()));
  mxSetField(info, 0, "C", to_output(res.noise.c.transpose()));
  mxSetField(info, 0, "D", to_output(res.noise.d.transpose()));
  mxSetField(info, 0, "noise_variance",
             mxCreateDoubleScalar(res.noise.innovation_variance));
  mxSetField(info, 0, "noise_covariance", to_output(res.noise.covariance));
  mxSetField(info, 0, "simulation_variance",
             mxCreateDoubleScalar(res.simulation_variance));
  mxSetField(info, 0, "simulated", to_output(res.simulated));
  mxSetField(info, 0, "condition", mxCreateDoubleScalar(res.condition));
  mxSetField(info, 0, "start_theta", to_output(res.start_theta));
}

// A 1x1 struct with RIVC's fields followed by `extra`.
inline mxArray* make_rivc_info(const std::vector<const char*>& extra) {
  std::vector<const char*> fields = rivc_info_fields();
  fields.insert(fields.end(), extra.begin(), extra.end());
  return mxCreateStructMatrix(1, 1, static_cast<int>(fields.size()),
                              fields.data());
}

}  // namespace ctid::mex
