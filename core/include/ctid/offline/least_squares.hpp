// SPDX-License-Identifier: BSD-3-Clause
// Copyright (C) the ctid authors
// Batch least squares on the filtered SVF regression: LSSVF, eq. (1.32),
// solved with a column-pivoting Householder QR of the regressor matrix
// instead of the normal equations.
#pragma once

#include "ctid/base/record.hpp"
#include "ctid/filters/svf_regressor.hpp"

namespace ctid {

// Stacks phi_f^T(t_k) into the rows of Phi and y_f^(na)(t_k) into target.
template <typename S>
Status build_svf_regression(const ModelOrders& orders,
                            const SvfSettings<S>& svf,
                            const RecordView<S>& record, Matrix<S>& Phi,
                            Vector<S>& target) {
  Status status = validate_orders(orders);
  if (!status.ok()) return status;
  status = validate_svf_settings(svf);
  if (!status.ok()) return status;
  status = validate_record(record, orders);
  if (!status.ok()) return status;
  SvfRegressor<S> regressor;
  regressor.configure(orders, svf);
  const Eigen::Index n = record.num_samples;
  Phi.resize(n, orders.num_parameters());
  target.resize(n);
  Vector<S> u_k(record.num_inputs);
  for (Eigen::Index k = 0; k < n; ++k) {
    for (Eigen::Index j = 0; j < record.num_inputs; ++j) {
      u_k(j) = record.u_at(k, j);
    }
    regressor.step(u_k.data(), record.y[k], record.interval(k));
    Phi.row(k) = regressor.phi().transpose();
    target(k) = regressor.target();
  }
  return Status::Ok();
}

// theta = argmin ||target - Phi theta||, by QR. Fails on a rank-deficient
// Phi (no persistent excitation) instead of returning an arbitrary answer.
template <typename S>
Status solve_least_squares(const Matrix<S>& Phi, const Vector<S>& target,
                           Vector<S>& theta) {
  if (Phi.rows() != target.size()) {
    return dimension_mismatch("regressor and target lengths differ");
  }
  const Eigen::ColPivHouseholderQR<Matrix<S>> qr(Phi);
  if (qr.rank() < Phi.cols()) {
    return numerical_failure(
        "the regressor matrix is rank deficient (rank " +
        std::to_string(qr.rank()) + " < " + std::to_string(Phi.cols()) +
        "): the input is not persistently exciting for this model order");
  }
  theta = qr.solve(target);
  return Status::Ok();
}

}  // namespace ctid
