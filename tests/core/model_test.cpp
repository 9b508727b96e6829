// Tests of core/include/ctid/model.hpp.
#include "ctid/model.hpp"

#include <gtest/gtest.h>

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

}  // namespace
}  // namespace ctid
