// SPDX-License-Identifier: BSD-3-Clause
// Copyright (C) the ctid authors
// Counts heap allocations so that a test can check that a per-sample path
// allocates nothing. Replaces the global operator new/delete: include it in
// exactly one translation unit of a test program.
#pragma once

#include <atomic>
#include <cstdlib>
#include <new>

// (GCC warns that free() meets operator new: both are the replaced pair.)
#pragma GCC diagnostic ignored "-Wmismatched-new-delete"

inline std::atomic<long> g_allocations{0};

void* operator new(std::size_t size) {
  ++g_allocations;
  if (void* p = std::malloc(size ? size : 1)) return p;
  throw std::bad_alloc();
}
void operator delete(void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }
