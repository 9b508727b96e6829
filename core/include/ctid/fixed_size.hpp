// Compile-time sizes for the small orders users run (issue 14).
//
// A second-order RSRIVC step is about a thousand floating-point operations;
// on dynamic-size Eigen objects the loops, size checks and the general
// matrix exponential and LU cost several times that. The recursive
// estimators are therefore templates on NA (na, the order of every filter)
// and NP (the number of parameters), Eigen::Dynamic by default. The batch
// functions run_rlssvf() and run_recursive_iv() choose the sizes ONCE, when
// the estimator is configured, through with_fixed_sizes(): one input and
// na <= kMaxFixedOrder get the fixed-size instantiation (the same code, on
// stack matrices the compiler unrolls), anything else the dynamic one, which
// stays the reference (tests/core/fixed_size_test.cpp compares the two).
// Online users can instantiate e.g. RlsSvf<double, 2, 3> themselves.
#pragma once

#include <type_traits>

#include "ctid/model.hpp"
#include "ctid/types.hpp"

namespace ctid {

// Orders 1..4 with the usual strictly proper nb <= na cover what users run;
// each (na, nb) pair is one instantiation (10 of them per scalar type and
// estimator, besides the dynamic one), a cost every gateway that runs the
// recursive path pays in compile time. Other orders (nb = na + 1 included)
// take the dynamic path.
constexpr int kMaxFixedOrder = 4;

template <int N>
using SizeConstant = std::integral_constant<int, N>;

namespace detail {

template <int NA, int NB, typename F>
auto dispatch_numerator(int nb, F& f) {
  if constexpr (NB > NA) {
    return f(SizeConstant<Eigen::Dynamic>{}, SizeConstant<Eigen::Dynamic>{});
  } else {
    if (nb == NB) return f(SizeConstant<NA>{}, SizeConstant<NA + NB>{});
    return dispatch_numerator<NA, NB + 1>(nb, f);
  }
}

template <int NA, typename F>
auto dispatch_order(int na, int nb, F& f) {
  if constexpr (NA > kMaxFixedOrder) {
    return f(SizeConstant<Eigen::Dynamic>{}, SizeConstant<Eigen::Dynamic>{});
  } else {
    if (na == NA) return dispatch_numerator<NA, 1>(nb, f);
    return dispatch_order<NA + 1>(na, nb, f);
  }
}

}  // namespace detail

// True when with_fixed_sizes() would pick a fixed-size instantiation.
inline bool has_fixed_sizes(const ModelOrders& orders) {
  return orders.num_inputs() == 1 && orders.na >= 1 &&
         orders.na <= kMaxFixedOrder && orders.nb[0] >= 1 &&
         orders.nb[0] <= orders.na;
}

// Calls f(SizeConstant<NA>, SizeConstant<NP>) with na and np = na + nb as
// compile-time constants for a one-input model with nb <= na <=
// kMaxFixedOrder when `enabled`, and f(SizeConstant<Dynamic>, SizeConstant<Dynamic>)
// otherwise; returns what f returns.
//
// Only in double: every fixed size is compiled again for each scalar type,
// and the gateways' single-precision option (meant for checking what a
// float implementation would give, not for speed) does not justify doubling
// their compile time, so run_rlssvf<float> and run_recursive_iv<float> take
// the dynamic path. The float kernels exist all the same (RlsSvf<float, 2,
// 3>, ...) and tests/core/fixed_size_test.cpp checks them.
template <typename S, typename F>
auto with_fixed_sizes(const ModelOrders& orders, bool enabled, F&& f) {
  if constexpr (std::is_same_v<S, double>) {
    if (enabled && has_fixed_sizes(orders)) {
      return detail::dispatch_order<1>(orders.na, orders.nb[0], f);
    }
  }
  return f(SizeConstant<Eigen::Dynamic>{}, SizeConstant<Eigen::Dynamic>{});
}

// Whether an estimator instantiated with NA, NP can run `orders` with
// `extra` further estimated parameters (initial conditions, which only the
// dynamic path has).
template <int NA, int NP>
bool sizes_match(const ModelOrders& orders, int extra) {
  if constexpr (NA == Eigen::Dynamic && NP == Eigen::Dynamic) {
    return true;
  } else {
    return extra == 0 && orders.num_inputs() == 1 && orders.na == NA &&
           orders.num_parameters() == NP;
  }
}

}  // namespace ctid
