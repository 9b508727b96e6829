// SPDX-License-Identifier: BSD-3-Clause
// Copyright (C) the ctid authors
// The gateways' options convention: every gateway takes its data arrays
// positionally and then ONE struct of named options (libigl's parse_rhs
// reads its arguments by name in the same way). OptionsReader reads that
// struct field by field, checking class, size and range of each field
// before touching its memory; finish() rejects any field nobody asked for,
// so a misspelt or stale option is an identified error, never ignored.
//
// A new option is then one line in the front-end (the field), one line
// where the gateway reads it, and one field in the core's config struct.
//
//   OptionsReader opt(g, prhs[3]);               // [] or a 1x1 struct
//   config.lambda_svf = opt.scalar("lambda_svf");            // required
//   config.tolerance = opt.scalar("tol", 1e-6);              // optional
//   config.adm = opt.choice<Adm>("adm", {{"ff", kFf}, {"kf", kKf}}, kFf);
//   opt.finish();
#pragma once

#include <algorithm>
#include <string>
#include <utility>
#include <vector>

#include "mex_helpers.hpp"

namespace ctid::mex {

class OptionsReader {
 public:
  // options: a 1x1 struct, or an empty array for "no options". A nested
  // struct (e.g. the field "plant") is read by a second reader whose prefix
  // ("plant.") names its fields in the messages.
  OptionsReader(const Gateway& g, const mxArray* options,
                std::string prefix = "")
      : g_(g), options_(options), prefix_(std::move(prefix)) {
    const std::string whole =
        prefix_.empty()
            ? std::string("the options")
            : "option '" + prefix_.substr(0, prefix_.size() - 1) + "'";
    if (options_ == nullptr) g_.fail("badInput", whole + " is missing");
    if (mxIsStruct(options_)) {
      if (mxGetNumberOfElements(options_) != 1) {
        g_.fail("badInput", whole + " must be a 1x1 struct");
      }
    } else if (mxIsEmpty(options_)) {
      options_ = nullptr;
    } else {
      g_.fail("badInput", whole + " must be a struct");
    }
  }

  bool has(const std::string& name) const { return raw(name) != nullptr; }

  // The field's array (marked as read), or nullptr when absent.
  const mxArray* field(const std::string& name) {
    used_.push_back(name);
    return raw(name);
  }

  // A required field: absent (or []) is an error naming it.
  const mxArray* required(const std::string& name) {
    const mxArray* a = field(name);
    if (absent(a)) g_.fail("badOption", what(name) + " is missing");
    return a;
  }

  double scalar(const std::string& name) {
    return g_.scalar(required(name), what(name));
  }
  // Optional fields: absent or [] give the fallback.
  double scalar(const std::string& name, double fallback) {
    const mxArray* a = field(name);
    return absent(a) ? fallback : g_.scalar(a, what(name));
  }
  // A scalar that must lie in [lo, hi].
  double scalar_in(const std::string& name, double fallback, double lo,
                   double hi) {
    const double v = scalar(name, fallback);
    if (!(v >= lo && v <= hi)) {
      g_.fail("badOption", what(name) + " must lie in [" + std::to_string(lo) +
                               ", " + std::to_string(hi) + "]");
    }
    return v;
  }

  int integer(const std::string& name) {
    return g_.integer(required(name), what(name));
  }
  int integer(const std::string& name, int fallback) {
    const mxArray* a = field(name);
    return absent(a) ? fallback : g_.integer(a, what(name));
  }

  bool flag(const std::string& name, bool fallback) {
    const mxArray* a = field(name);
    if (absent(a)) return fallback;
    if (mxIsLogical(a) && mxGetNumberOfElements(a) == 1) {
      return mxIsLogicalScalarTrue(a);
    }
    return g_.scalar(a, what(name)) != 0;
  }

  std::vector<int> integer_vector(const std::string& name) {
    return g_.integer_vector(required(name), what(name));
  }
  std::vector<int> integer_vector(const std::string& name,
                                  std::vector<int> fallback) {
    const mxArray* a = field(name);
    return a == nullptr ? std::move(fallback)
                        : g_.integer_vector(a, what(name));
  }

  std::string text(const std::string& name) {
    return g_.text(required(name), what(name));
  }
  std::string text(const std::string& name, std::string fallback) {
    const mxArray* a = field(name);
    return absent(a) ? std::move(fallback) : g_.text(a, what(name));
  }

  // A finite real double matrix (rows/cols < 0: any). Absent or [] gives an
  // empty matrix, which callers read as "use the default".
  Eigen::MatrixXd matrix(const std::string& name, long rows = -1,
                         long cols = -1) {
    const mxArray* a = field(name);
    if (absent(a)) return Eigen::MatrixXd();
    return g_.eigen_matrix(a, what(name), rows, cols);
  }
  // A required finite real double matrix.
  Eigen::MatrixXd required_matrix(const std::string& name, long rows = -1,
                                  long cols = -1) {
    return g_.eigen_matrix(required(name), what(name), rows, cols);
  }

  // A signal of n finite values, one per sample, read in place: nullptr when
  // absent or [].
  const double* signal(const std::string& name, long n) {
    const mxArray* a = field(name);
    if (absent(a)) return nullptr;
    return g_.matrix(a, what(name), n, 1);
  }

  // A nested struct field, read by its own reader (whose finish() the
  // caller calls).
  OptionsReader nested(const std::string& name) {
    return OptionsReader(g_, required(name), prefix_ + name + ".");
  }

  // One of a fixed list of strings, mapped to a value.
  template <typename T>
  T choice(const std::string& name,
           std::initializer_list<std::pair<const char*, T>> choices,
           T fallback) {
    const mxArray* a = field(name);
    if (absent(a)) return fallback;
    const std::string s = g_.text(a, what(name));
    std::string allowed;
    for (const auto& c : choices) {
      if (s == c.first) return c.second;
      allowed += (allowed.empty() ? "'" : ", '") + std::string(c.first) + "'";
    }
    g_.fail("badOption",
            what(name) + " must be one of " + allowed + ", got '" + s + "'");
  }

  // Every field must have been read: an unknown one is an error.
  void finish() const {
    if (options_ == nullptr) return;
    const int n = mxGetNumberOfFields(options_);
    for (int i = 0; i < n; ++i) {
      const std::string name = mxGetFieldNameByNumber(options_, i);
      if (std::find(used_.begin(), used_.end(), name) == used_.end()) {
        g_.fail("badOption", "unknown option '" + prefix_ + name + "'");
      }
    }
  }

 private:
  static bool absent(const mxArray* a) {
    return a == nullptr || (mxIsEmpty(a) && mxIsDouble(a));
  }
  const mxArray* raw(const std::string& name) const {
    return options_ == nullptr ? nullptr
                               : mxGetField(options_, 0, name.c_str());
  }
  std::string what(const std::string& name) const {
    return "option '" + prefix_ + name + "'";
  }

  const Gateway& g_;
  const mxArray* options_;
  std::string prefix_;
  std::vector<std::string> used_;
};

}  // namespace ctid::mex
