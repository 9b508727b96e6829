// Reading the arguments that several gateways share: the record (y, u,
// sampling), the model orders and the SVF settings.
#pragma once

#include "ctid/adaptation.hpp"
#include "ctid/controller.hpp"
#include "ctid/model.hpp"
#include "ctid/record.hpp"
#include "ctid/svf_regressor.hpp"
#include "mex_helpers.hpp"

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

inline InterSample read_intersample(const Gateway& g, const mxArray* a) {
  const std::string s = g.text(a, "InterSample");
  if (s == "zoh") return InterSample::kZoh;
  if (s == "foh") return InterSample::kFoh;
  g.fail("badOption", "InterSample must be 'zoh' or 'foh', got '" + s + "'");
}

inline ModelOrders read_orders(const Gateway& g, const mxArray* na,
                               const mxArray* nb, const mxArray* nk) {
  ModelOrders orders;
  orders.na = g.integer(na, "na");
  orders.nb = g.integer_vector(nb, "nb");
  orders.nk = g.integer_vector(nk, "nk");
  g.check(validate_orders(orders));
  return orders;
}

inline bool read_normalised(const Gateway& g, const mxArray* a) {
  const std::string s = g.text(a, "the SVF form");
  if (s == "normalised" || s == "normalized") return true;
  if (s == "ordinary") return false;
  g.fail("badOption", "the SVF form must be 'normalised' or 'ordinary'");
}

// adm ('ff' or 'kf') and adg (forgetting factor or np-by-np Qn).
inline Adaptation<double> read_adaptation(const Gateway& g, const mxArray* adm,
                                          const mxArray* adg, long np) {
  const std::string kind = g.text(adm, "adm");
  if (kind == "ff") {
    return ForgettingFactorAdaptation<double>(g.scalar(adg, "adg"));
  }
  if (kind == "kf") {
    return KalmanAdaptation<double>(g.eigen_matrix(adg, "adg (Qn)", np, np));
  }
  g.fail("badOption", "adm must be 'ff' or 'kf', got '" + kind + "'");
}

// th0 (np-by-1) and P0 (np-by-np), each possibly [] (defaults).
inline void read_initial_estimate(const Gateway& g, const mxArray* th0,
                                  const mxArray* P0, long np,
                                  Vector<double>* theta0, Matrix<double>* p0) {
  if (!mxIsEmpty(th0)) *theta0 = g.eigen_matrix(th0, "th0", np, 1);
  if (!mxIsEmpty(P0)) *p0 = g.eigen_matrix(P0, "P0", np, np);
}

// A discrete transfer function from numerator and denominator rows.
inline DiscreteTransferFunction<double> read_transfer_function(
    const Gateway& g, const mxArray* num, const mxArray* den,
    const std::string& what) {
  DiscreteTransferFunction<double> tf;
  g.require_real_double(num, what + " numerator");
  g.require_real_double(den, what + " denominator");
  tf.numerator = g.eigen_matrix(num, what + " numerator").reshaped();
  tf.denominator = g.eigen_matrix(den, what + " denominator").reshaped();
  return tf;
}

}  // namespace ctid::mex
