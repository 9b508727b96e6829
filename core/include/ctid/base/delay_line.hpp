// SPDX-License-Identifier: BSD-3-Clause
// Copyright (C) the ctid authors
// Fixed-length delay of a sampled signal by nk samples (zero before the
// record starts), without allocation per sample.
#pragma once

#include <algorithm>
#include <vector>

namespace ctid {

template <typename S>
class DelayLine {
 public:
  explicit DelayLine(int delay = 0) { configure(delay); }
  void configure(int delay) {
    buffer_.assign(static_cast<std::size_t>(delay), S(0));
    head_ = 0;
  }
  void reset() {
    std::fill(buffer_.begin(), buffer_.end(), S(0));
    head_ = 0;
  }
  // s(t_(k-nk)) for the next push, when nk > 0.
  S oldest() const { return buffer_[head_]; }
  // Pushes s(t_k) and returns s(t_(k-nk)).
  S push(S s) {
    if (buffer_.empty()) return s;
    const S out = buffer_[head_];
    buffer_[head_] = s;
    head_ = (head_ + 1) % buffer_.size();
    return out;
  }

 private:
  std::vector<S> buffer_;
  std::size_t head_ = 0;
};

}  // namespace ctid
