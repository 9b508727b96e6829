// SPDX-License-Identifier: BSD-3-Clause
// Copyright (C) the ctid authors

// The size of an adaptation step (adaptation.hpp, potter.hpp, lmr.hpp,
// covariance_guard.hpp), written once for every size.
//
// Each step is a template on N, the parameter count when it is known at
// compile time (1..kMaxFixedParameters) or Eigen::Dynamic, and runs plain
// loops over n = step_size<N>(np). For a fixed N the bounds are constants:
// the compiler unrolls the loops and keeps the step's arrays in registers.
// The arrays are Working copies: for a fixed N a local array, loaded from
// the object's storage once and written back once (through the members'
// storage, every store would make the compiler reload the rest, since all
// of it is S*, and Eigen's packet copies of these small objects reload,
// 16 bytes at a time, values just stored 8 bytes at a time, which stalls
// store forwarding); for Eigen::Dynamic the storage itself. Either way
// the arithmetic is the same source, in the same order.
//
// select_size() picks the step once, where the estimator is configured, as
// a pointer to the member function of that size. A switch on the size at
// every sample, which lets the compiler inline the step into its caller,
// measured up to 12 % slower (bench_rlssvf, bench_rsrivc, each against
// the same reference build run alternately).
#pragma once

#include <Eigen/Core>
#include <type_traits>

namespace ctid {

// Largest parameter count with a compile-time-size step: na = 4, nb = 4.
constexpr int kMaxFixedParameters = 8;

template <int N>
using StepSize = std::integral_constant<int, N>;

// n of a step: N itself when it is known at compile time.
template <int N>
constexpr int step_size(Eigen::Index np) {
  return N == Eigen::Dynamic ? int(np) : N;
}

// Number of scalars of an a-by-b array, Eigen::Dynamic if either is.
constexpr int array_size(int a, int b) {
  return a == Eigen::Dynamic || b == Eigen::Dynamic ? Eigen::Dynamic : a * b;
}

// Count scalars a step works on: a local array holding a copy of `home`
// (copied in when `load`, copied back by write_back()) when Count is a
// compile-time size, `home` itself when it is Eigen::Dynamic. A buffer the
// step only writes and reads back (scratch) is a Working that is neither
// loaded nor written back.
template <typename S, int Count>
class Working {
 public:
  Working(S* home, bool load) : home_(home) {
    if (!load) return;
#pragma GCC unroll 128
    for (int i = 0; i < Count; ++i) local_[i] = home_[i];
  }
  S& operator[](int i) { return local_[i]; }
  const S& operator[](int i) const { return local_[i]; }
  void write_back() const {
#pragma GCC unroll 128
    for (int i = 0; i < Count; ++i) home_[i] = local_[i];
  }

 private:
  S* home_;
  S local_[Count];
};

template <typename S>
class Working<S, Eigen::Dynamic> {
 public:
  Working(S* home, bool /*load*/) : home_(home) {}
  S& operator[](Eigen::Index i) { return home_[i]; }
  const S& operator[](Eigen::Index i) const { return home_[i]; }
  void write_back() const {}

 private:
  S* home_;
};

// f(StepSize<np>()) when fixed and 1 <= np <= kMaxFixedParameters, else
// f(StepSize<Eigen::Dynamic>()): the one place where a runtime parameter
// count becomes a compile-time one. f returns the step to use (a pointer to
// member function), the same type for every size.
template <typename F>
auto select_size(Eigen::Index np, bool fixed, F&& f) {
  if (fixed) {
    switch (np) {
      case 1:
        return f(StepSize<1>());
      case 2:
        return f(StepSize<2>());
      case 3:
        return f(StepSize<3>());
      case 4:
        return f(StepSize<4>());
      case 5:
        return f(StepSize<5>());
      case 6:
        return f(StepSize<6>());
      case 7:
        return f(StepSize<7>());
      case 8:
        return f(StepSize<8>());
      default:
        break;
    }
  }
  return f(StepSize<Eigen::Dynamic>());
}

// The parameter count of the step select_size() picks, 0 for the dynamic
// one.
inline int fixed_step_size(Eigen::Index np, bool fixed) {
  return fixed && np >= 1 && np <= kMaxFixedParameters ? int(np) : 0;
}

// x's storage when it is contiguous, else a copy in buffer (preallocated:
// no allocation when its size does not change).
template <typename S, typename Derived>
const S* contiguous(const Eigen::MatrixBase<Derived>& x,
                    Eigen::Matrix<S, Eigen::Dynamic, 1>& buffer) {
  if constexpr ((int(Derived::Flags) & Eigen::DirectAccessBit) &&
                int(Derived::InnerStrideAtCompileTime) == 1) {
    return x.derived().data();
  } else {
    buffer = x;
    return buffer.data();
  }
}

}  // namespace ctid
