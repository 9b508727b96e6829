// SPDX-License-Identifier: BSD-3-Clause
// Copyright (C) the ctid authors
// Tests of core/include/ctid/base/model.hpp.
#include "ctid/base/model.hpp"

#include <gtest/gtest.h>

#include <complex>

namespace ctid {
namespace {

TEST(ModelOrders, ParameterLayout) {
  ModelOrders orders;
  orders.na = 2;
  orders.nb = {1, 3};
  orders.nk = {0, 2};
  EXPECT_EQ(orders.num_parameters(), 6);
  EXPECT_EQ(orders.numerator_offset(0), 2);
  EXPECT_EQ(orders.numerator_offset(1), 3);
  EXPECT_EQ(orders.max_delay(), 2);
  Eigen::VectorXd theta(6);
  theta << 1, 2, 3, 4, 5, 6;
  EXPECT_EQ(denominator_of(orders, theta), Eigen::Vector2d(1, 2));
  EXPECT_EQ(numerator_of(orders, theta, 1), Eigen::Vector3d(4, 5, 6));
}

TEST(ModelOrders, Validation) {
  EXPECT_TRUE(validate_orders(siso_orders(2, 1, 0)).ok());
  EXPECT_TRUE(validate_orders(siso_orders(2, 3, 0)).ok()) << "biproper";
  EXPECT_EQ(validate_orders(siso_orders(2, 4, 0)).code(), ErrorCode::kBadInput)
      << "improper";
  EXPECT_EQ(validate_orders(siso_orders(0, 1, 0)).code(), ErrorCode::kBadInput);
  EXPECT_EQ(validate_orders(siso_orders(2, -1, 0)).code(),
            ErrorCode::kBadInput);
  EXPECT_EQ(validate_orders(siso_orders(2, 0, 0)).code(), ErrorCode::kBadInput)
      << "no numerator at all";
  EXPECT_EQ(validate_orders(siso_orders(2, 1, -1)).code(),
            ErrorCode::kBadInput);
  ModelOrders mismatch = siso_orders(2, 1, 0);
  mismatch.nk = {0, 1};
  EXPECT_EQ(validate_orders(mismatch).code(), ErrorCode::kDimensionMismatch);
}

// The state-space form has the transfer function B(s)/A(s): compare
// H (sI - F)^-1 G + J with the polynomials evaluated at s = j w.
TEST(ModelOrders, StateSpaceFormMatchesTransferFunction) {
  for (int nb : {1, 2, 3}) {
    const ModelOrders orders = siso_orders(2, nb, 0);
    Eigen::VectorXd all_coefficients(5);
    all_coefficients << 1.3, 4.0, 2.0, -0.7, 0.9;
    const Eigen::VectorXd theta = all_coefficients.head(2 + nb);
    const StateSpace<double> ss = to_state_space(orders, theta, 0);
    for (double w : {0.0, 0.3, 1.0, 7.0}) {
      const std::complex<double> s(0, w);
      const std::complex<double> a = s * s + theta(0) * s + theta(1);
      std::complex<double> b = 0;
      for (int l = 0; l < nb; ++l) b = b * s + theta(2 + l);
      const Eigen::MatrixXcd resolvent = (s * Eigen::MatrixXcd::Identity(2, 2) -
                                          ss.F.cast<std::complex<double>>())
                                             .inverse();
      const std::complex<double> g =
          (ss.H.cast<std::complex<double>>() * resolvent *
           ss.G.cast<std::complex<double>>())(0, 0) +
          ss.J(0, 0);
      EXPECT_LT(std::abs(g - b / a), 1e-12 * std::abs(b / a) + 1e-14)
          << "nb " << nb << " w " << w;
    }
  }
}

}  // namespace
}  // namespace ctid
