// SPDX-License-Identifier: BSD-3-Clause
// Copyright (C) the ctid authors
// Status values returned by the core instead of throwing or aborting.
//
// The core never raises on bad input or numerical trouble: every fallible
// call returns a Status, and the host layer (MEX gateway, C++ user) maps its
// code to an error identifier in one place (`error_reason`).
#pragma once

#include <string>
#include <utility>

namespace ctid {

enum class ErrorCode {
  kOk,
  kBadInput,
  kDimensionMismatch,
  kBadOption,
  kNotSupported,
  kNotConverged,
  kNumericalFailure,
};

// The reason part of an error identifier `<function>:<reason>`.
inline const char* error_reason(ErrorCode code) {
  switch (code) {
    case ErrorCode::kOk:
      return "ok";
    case ErrorCode::kBadInput:
      return "badInput";
    case ErrorCode::kDimensionMismatch:
      return "dimensionMismatch";
    case ErrorCode::kBadOption:
      return "badOption";
    case ErrorCode::kNotSupported:
      return "notSupported";
    case ErrorCode::kNotConverged:
      return "notConverged";
    case ErrorCode::kNumericalFailure:
      return "numericalFailure";
  }
  return "unknown";
}

class Status {
 public:
  Status() = default;
  Status(ErrorCode code, std::string message)
      : code_(code), message_(std::move(message)) {}

  static Status Ok() { return Status(); }

  bool ok() const { return code_ == ErrorCode::kOk; }
  ErrorCode code() const { return code_; }
  const std::string& message() const { return message_; }

 private:
  ErrorCode code_ = ErrorCode::kOk;
  std::string message_;
};

inline Status bad_input(std::string message) {
  return Status(ErrorCode::kBadInput, std::move(message));
}
inline Status dimension_mismatch(std::string message) {
  return Status(ErrorCode::kDimensionMismatch, std::move(message));
}
inline Status not_supported(std::string message) {
  return Status(ErrorCode::kNotSupported, std::move(message));
}
inline Status numerical_failure(std::string message) {
  return Status(ErrorCode::kNumericalFailure, std::move(message));
}

}  // namespace ctid
