// SPDX-License-Identifier: BSD-3-Clause
// Copyright (C) the ctid authors
// Argument conversion shared by every MEX gateway (Octave and MATLAB).
//
// Gateways validate every argument here before touching its memory (class,
// real, full, 2-D, sizes, finite values) and throw GatewayError; the entry
// point `run_gateway` catches it after all C++ objects are gone and only then
// calls mexErrMsgIdAndTxt, which does not unwind C++ frames in MATLAB.
#pragma once

#include <mex.h>

#include <Eigen/Dense>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <initializer_list>
#include <new>
#include <string>
#include <vector>

#include "ctid/base/status.hpp"

namespace ctid::mex {

struct GatewayError {
  std::string id;
  std::string message;
};

// The public function name every message starts with (the gateway's first
// argument, e.g. "rlssvf").
class Gateway {
 public:
  explicit Gateway(std::string fname) : fname_(std::move(fname)) {}
  const std::string& name() const { return fname_; }

  [[noreturn]] void fail(const char* reason, const std::string& message) const {
    throw GatewayError{fname_ + ":" + reason, fname_ + ": " + message};
  }
  // Maps a core Status to the error identifier, in one place.
  void check(const Status& status) const {
    if (!status.ok()) fail(error_reason(status.code()), status.message());
  }

  void require_real_double(const mxArray* a, const std::string& what) const {
    if (a == nullptr) fail("badInput", what + " is missing");
    if (!mxIsDouble(a) || mxIsComplex(a) || mxIsSparse(a)) {
      fail("badInput", what + " must be a real, full double array");
    }
    if (mxGetNumberOfDimensions(a) != 2) {
      fail("badInput", what + " must be a 2-D matrix");
    }
  }

  // A real double matrix; rows/cols < 0 accept any size.
  const double* matrix(const mxArray* a, const std::string& what,
                       long rows = -1, long cols = -1,
                       bool finite = true) const {
    require_real_double(a, what);
    const long m = static_cast<long>(mxGetM(a));
    const long n = static_cast<long>(mxGetN(a));
    if ((rows >= 0 && m != rows) || (cols >= 0 && n != cols)) {
      fail("dimensionMismatch",
           what + " must be " + size_text(rows) + "-by-" + size_text(cols) +
               ", got " + std::to_string(m) + "-by-" + std::to_string(n));
    }
    const double* p = mxGetPr(a);
    if (finite) {
      for (long i = 0; i < m * n; ++i) {
        if (!std::isfinite(p[i])) fail("badInput", what + " must be finite");
      }
    }
    return m * n > 0 ? p : nullptr;
  }

  double scalar(const mxArray* a, const std::string& what) const {
    return *matrix(a, what, 1, 1);
  }

  int integer(const mxArray* a, const std::string& what) const {
    const double v = scalar(a, what);
    if (v != std::floor(v) || std::abs(v) > 1e9) {
      fail("badInput", what + " must be an integer");
    }
    return static_cast<int>(v);
  }

  std::vector<int> integer_vector(const mxArray* a,
                                  const std::string& what) const {
    require_real_double(a, what);
    const std::size_t n = mxGetNumberOfElements(a);
    if (mxGetM(a) > 1 && mxGetN(a) > 1)
      fail("badInput", what + " must be a vector");
    std::vector<int> out(n);
    const double* p = mxGetPr(a);
    for (std::size_t i = 0; i < n; ++i) {
      if (!std::isfinite(p[i]) || p[i] != std::floor(p[i]) ||
          std::abs(p[i]) > 1e9) {
        fail("badInput", what + " must contain integers");
      }
      out[i] = static_cast<int>(p[i]);
    }
    return out;
  }

  std::string text(const mxArray* a, const std::string& what) const {
    if (a == nullptr || !mxIsChar(a) || mxGetM(a) > 1) {
      fail("badInput", what + " must be a character row vector");
    }
    char buffer[256];
    if (mxGetString(a, buffer, sizeof buffer) != 0) {
      fail("badInput", what + " is too long");
    }
    return buffer;
  }

  Eigen::Map<const Eigen::MatrixXd> eigen_matrix(const mxArray* a,
                                                 const std::string& what,
                                                 long rows = -1,
                                                 long cols = -1) const {
    const double* p = matrix(a, what, rows, cols);
    return Eigen::Map<const Eigen::MatrixXd>(
        p, static_cast<Eigen::Index>(mxGetM(a)),
        static_cast<Eigen::Index>(mxGetN(a)));
  }

 private:
  static std::string size_text(long n) {
    return n < 0 ? std::string("any") : std::to_string(n);
  }
  std::string fname_;
};

inline mxArray* make_output_matrix(std::size_t rows, std::size_t cols) {
  return mxCreateDoubleMatrix(rows, cols, mxREAL);
}

inline mxArray* make_output_array3(std::size_t d1, std::size_t d2,
                                   std::size_t d3) {
  const mwSize dims[3] = {static_cast<mwSize>(d1), static_cast<mwSize>(d2),
                          static_cast<mwSize>(d3)};
  return mxCreateNumericArray(3, dims, mxDOUBLE_CLASS, mxREAL);
}

// The public name from the gateway's first argument when it is one of the
// names this gateway serves, else the gateway's own public name.
inline std::string public_name(int nrhs, const mxArray* prhs[],
                               const char* fallback,
                               std::initializer_list<const char*> allowed) {
  if (nrhs < 1 || !mxIsChar(prhs[0]) || mxGetM(prhs[0]) != 1 ||
      mxGetN(prhs[0]) > 60) {
    return fallback;
  }
  char buffer[64];
  if (mxGetString(prhs[0], buffer, sizeof buffer) != 0) return fallback;
  for (const char* name : allowed) {
    if (std::strcmp(buffer, name) == 0) return name;
  }
  return fallback;
}

// Runs body(gateway) and turns every failure into an identified error whose
// identifier starts with the public name of the call (the fallback only
// when the first argument names no function this gateway serves).
template <typename Body>
void run_gateway(const char* fallback_name,
                 std::initializer_list<const char*> allowed_names, int nrhs,
                 const mxArray* prhs[], Body&& body) {
  static char id[128];
  static char message[2048];
  bool failed = false;
  {
    const char* name = fallback_name;
    try {
      const std::string public_fname =
          public_name(nrhs, prhs, fallback_name, allowed_names);
      for (const char* allowed : allowed_names) {
        if (public_fname == allowed) name = allowed;
      }
      Gateway gateway(public_fname);
      body(gateway);
    } catch (const GatewayError& e) {
      std::snprintf(id, sizeof id, "%s", e.id.c_str());
      std::snprintf(message, sizeof message, "%s", e.message.c_str());
      failed = true;
    } catch (const std::bad_alloc&) {
      std::snprintf(id, sizeof id, "%s:numericalFailure", name);
      std::snprintf(message, sizeof message, "%s: out of memory", name);
      failed = true;
    } catch (const std::exception& e) {
      std::snprintf(id, sizeof id, "%s:numericalFailure", name);
      std::snprintf(message, sizeof message, "%s: internal error: %s", name,
                    e.what());
      failed = true;
    }
  }
  if (failed) mexErrMsgIdAndTxt(id, "%s", message);
}

// The name the running MEX file was called by: its file name without
// directory or extension (a file compiled once and installed under several
// names dispatches on it, see scripts/make_unity_gateways).
inline std::string called_name() {
  std::string name = mexFunctionName();
  const std::string::size_type slash = name.find_last_of("/\\");
  if (slash != std::string::npos) name.erase(0, slash + 1);
  const std::string::size_type dot = name.find('.');
  if (dot != std::string::npos) name.erase(dot);
  return name;
}

}  // namespace ctid::mex
