// SPDX-License-Identifier: BSD-3-Clause
// Copyright (C) the ctid authors
// Reading what several gateways share: the record (y, u and the sampling,
// positional data arrays) and, from the options struct (options_reader.hpp),
// the model orders, the SVF settings, the adaptation and the initial
// estimate.
#pragma once

#include "ctid/adaptation/adaptation.hpp"
#include "ctid/base/model.hpp"
#include "ctid/base/record.hpp"
#include "ctid/filters/svf_regressor.hpp"
#include "ctid/simulation/controller.hpp"
#include "options_reader.hpp"

namespace ctid::mex {

// y (N-by-1), u (N-by-nu), and t: a scalar Ts or N sampling instants.
inline RecordView<double> read_record(const Gateway& g, const mxArray* y,
                                      const mxArray* u, const mxArray* t) {
  RecordView<double> record;
  g.require_real_double(y, "y");
  if (mxGetN(y) != 1) g.fail("badInput", "y must be a column vector");
  const long n = static_cast<long>(mxGetM(y));
  if (n < 1) g.fail("badInput", "y must not be empty");
  record.y = g.matrix(y, "y", n, 1);
  g.require_real_double(u, "u");
  if (static_cast<long>(mxGetM(u)) != n) {
    g.fail("dimensionMismatch", "u must have as many rows as y (" +
                                    std::to_string(n) + "), got " +
                                    std::to_string(mxGetM(u)));
  }
  record.u = g.matrix(u, "u", n, -1);
  record.num_samples = n;
  record.num_inputs = static_cast<Eigen::Index>(mxGetN(u));
  g.require_real_double(t, "Ts");
  if (mxGetNumberOfElements(t) == 1) {
    record.ts = g.scalar(t, "Ts");
  } else {
    record.instants = g.matrix(t, "the sampling instants", n, 1);
  }
  return record;
}

// The options every estimator and simulator shares, by field name:
//   intersample  'zoh' | 'foh' | 'trapezoid' (of u; default of the core:
//                'zoh'; 'foh' the exact first-order hold, 'trapezoid' the
//                thesis' Tustin filter of a linear intersample behaviour)
//   na, nb, nk   the orders (nb, nk one entry per input)
//   lambda_svf   the SVF cut-off (rad/s)
//   svf          'normalised' (default) | 'normalized' | 'ordinary'
//   adm, adg     'ff' and the forgetting factor, or 'kf' and the np-by-np Qn
//   th0, P0      np-by-1 and np-by-np, absent or [] for the core's defaults
inline InterSample read_intersample(OptionsReader& opt, InterSample fallback) {
  return opt.choice<InterSample>("intersample",
                                 {{"zoh", InterSample::kZoh},
                                  {"foh", InterSample::kFoh},
                                  {"trapezoid", InterSample::kTrapezoid}},
                                 fallback);
}

inline ModelOrders read_orders(const Gateway& g, OptionsReader& opt) {
  ModelOrders orders;
  orders.na = opt.integer("na");
  orders.nb = opt.integer_vector("nb");
  orders.nk = opt.integer_vector("nk");
  g.check(validate_orders(orders));
  return orders;
}

inline void read_svf(OptionsReader& opt, SvfSettings<double>* svf) {
  svf->u_intersample = read_intersample(opt, svf->u_intersample);
  svf->lambda_svf = opt.scalar("lambda_svf");
  svf->normalised = opt.choice<bool>(
      "svf", {{"normalised", true}, {"normalized", true}, {"ordinary", false}},
      svf->normalised);
}

inline Adaptation<double> read_adaptation(OptionsReader& opt, long np) {
  enum class Kind { kFf, kKf };
  const Kind kind = opt.choice<Kind>(
      "adm", {{"ff", Kind::kFf}, {"kf", Kind::kKf}}, Kind::kFf);
  if (kind == Kind::kFf) {
    return ForgettingFactorAdaptation<double>(opt.scalar("adg"));
  }
  return KalmanAdaptation<double>(opt.required_matrix("adg", np, np));
}

inline void read_initial_estimate(OptionsReader& opt, long np,
                                  Vector<double>* theta0, Matrix<double>* p0) {
  const Eigen::MatrixXd th0 = opt.matrix("th0", np, 1);
  if (th0.size() != 0) *theta0 = th0;
  const Eigen::MatrixXd P0 = opt.matrix("P0", np, np);
  if (P0.size() != 0) *p0 = P0;
}

// A discrete transfer function from the fields <prefix>_num and
// <prefix>_den (vectors of coefficients in q^-1); both absent or []:
// returns false.
inline bool read_transfer_function(const Gateway& g, OptionsReader& opt,
                                   const std::string& prefix,
                                   DiscreteTransferFunction<double>* tf) {
  const Eigen::MatrixXd num = opt.matrix(prefix + "_num");
  const Eigen::MatrixXd den = opt.matrix(prefix + "_den");
  if (num.size() == 0 && den.size() == 0) return false;
  if (num.size() == 0 || den.size() == 0) {
    g.fail("badOption", "options '" + prefix + "_num' and '" + prefix +
                            "_den' must both be non-empty");
  }
  if (num.rows() > 1 && num.cols() > 1) {
    g.fail("badInput", "option '" + prefix + "_num' must be a vector");
  }
  if (den.rows() > 1 && den.cols() > 1) {
    g.fail("badInput", "option '" + prefix + "_den' must be a vector");
  }
  tf->numerator = num.reshaped();
  tf->denominator = den.reshaped();
  return true;
}

// A new output array holding a copy of the double matrix m (a vector is
// one column; pass v.transpose() for a row).
template <typename Derived>
mxArray* to_output(const Eigen::DenseBase<Derived>& m) {
  mxArray* a = make_output_matrix(m.rows(), m.cols());
  Eigen::Map<Eigen::MatrixXd>(mxGetPr(a), m.rows(), m.cols()) = m;
  return a;
}

// The intersample rule of an option code: 0 zoh, 1 foh.
inline InterSample intersample_rule(const Gateway& g, int code) {
  if (code == 0) return InterSample::kZoh;
  if (code == 1) return InterSample::kFoh;
  g.fail("badOption", "intersample codes must be 0 (zoh) or 1 (foh)");
}

}  // namespace ctid::mex
