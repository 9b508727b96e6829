// SPDX-License-Identifier: BSD-3-Clause
// Copyright (C) the ctid authors
// Benchmark arguments shared by rlssvf_bench.cpp and rsrivc_bench.cpp:
// orders 1-4, each with the fixed-size kernels and the dynamic reference
// next to each other.
#pragma once

#include <benchmark/benchmark.h>

inline void orders_and_kernels(benchmark::internal::Benchmark* b) {
  b->ArgNames({"na", "dynamic"});
  for (int na = 1; na <= 4; ++na) {
    b->Args({na, 0});
    b->Args({na, 1});
  }
  b->Unit(benchmark::kMillisecond);
}
