// SPDX-License-Identifier: BSD-3-Clause
// Copyright (C) the ctid authors
// ctid_stream: online RLSSVF-KF (thesis eqs. 1.53-1.55 with the Kalman-filter
// update of eq. 1.59) on samples arriving one by one on stdin, printing the
// estimates after each one. An example of the installed C++ core used from
// another project (find_package(ctid), target ctid::core).
//
//   ctid_stream [--na 2] [--nb 1] [--nk 0] [--lambda 3] [--qn 1e-6]
//               [--every 1]
//
// Input: one sample per line, "t y u" (whitespace-separated; lines starting
// with '#' and blank lines are skipped); t strictly increasing, possibly
// irregular. Output: one line per --every-th sample, "t a1 .. a_na b ..".
// The first sample is held until the second gives the first interval.
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <iostream>
#include <sstream>
#include <string>

#include "ctid/ctid.hpp"  // the whole core; "ctid/recursive/rlssvf.hpp" alone would do

namespace {

struct Options {
  int na = 2;
  int nb = 1;
  int nk = 0;
  double lambda_svf = 3;
  double qn = 1e-6;
  long every = 1;
};

[[noreturn]] void usage(const char* message) {
  std::fprintf(stderr,
               "ctid_stream: %s\nusage: ctid_stream [--na N] [--nb N] "
               "[--nk N] [--lambda L] [--qn Q] [--every K] < samples\n",
               message);
  std::exit(2);
}

Options parse(int argc, char** argv) {
  Options o;
  for (int i = 1; i < argc; ++i) {
    if (i + 1 >= argc) usage("every option needs a value");
    const std::string name = argv[i];
    char* end = nullptr;
    const double v = std::strtod(argv[++i], &end);
    if (end == argv[i] || *end != '\0') usage("option values are numbers");
    if (name == "--na") {
      o.na = static_cast<int>(v);
    } else if (name == "--nb") {
      o.nb = static_cast<int>(v);
    } else if (name == "--nk") {
      o.nk = static_cast<int>(v);
    } else if (name == "--lambda") {
      o.lambda_svf = v;
    } else if (name == "--qn") {
      o.qn = v;
    } else if (name == "--every") {
      o.every = static_cast<long>(v);
    } else {
      usage(("unknown option " + name).c_str());
    }
  }
  if (o.every < 1) usage("--every must be >= 1");
  return o;
}

// One "t y u" line; false for comments and blank lines.
bool read_sample(const std::string& line, long number, double* t, double* y,
                 double* u) {
  const std::size_t first = line.find_first_not_of(" \t\r");
  if (first == std::string::npos || line[first] == '#') return false;
  std::istringstream in(line);
  std::string rest;
  if (!(in >> *t >> *y >> *u) || (in >> rest)) {
    std::fprintf(stderr, "ctid_stream: line %ld is not \"t y u\"\n", number);
    std::exit(1);
  }
  return true;
}

}  // namespace

int main(int argc, char** argv) {
  const Options o = parse(argc, argv);
  ctid::RlsSvfConfig<double> config;
  config.orders = ctid::siso_orders(o.na, o.nb, o.nk);
  config.svf.lambda_svf = o.lambda_svf;
  const Eigen::Index np = config.orders.num_parameters();
  config.adaptation =
      ctid::KalmanAdaptation<double>(o.qn * Eigen::MatrixXd::Identity(np, np));
  ctid::RlsSvf<double> estimator;
  const ctid::Status status = estimator.configure(config);
  if (!status.ok()) {
    std::fprintf(stderr, "ctid_stream: %s\n", status.message().c_str());
    return 2;
  }

  std::string line;
  long number = 0;
  long count = 0;
  bool held = false;  // the first sample, waiting for its interval
  double t_prev = 0, y_held = 0, u_held = 0;
  auto process = [&](double t, double y, double u, double h) {
    const Eigen::VectorXd& theta = estimator.update(&u, y, h);
    if (count++ % o.every != 0) return;
    std::printf("%.9g", t);
    for (Eigen::Index i = 0; i < theta.size(); ++i) {
      std::printf(" %.9g", theta(i));
    }
    std::printf("\n");
  };
  while (std::getline(std::cin, line)) {
    ++number;
    double t, y, u;
    if (!read_sample(line, number, &t, &y, &u)) continue;
    if (number > 1 && (held || count > 0) && !(t > t_prev)) {
      std::fprintf(stderr, "ctid_stream: line %ld: t must increase\n", number);
      return 1;
    }
    if (count == 0 && !held) {
      held = true;
      y_held = y;
      u_held = u;
    } else {
      const double h = t - t_prev;
      if (held) {
        process(t_prev, y_held, u_held, h);
        held = false;
      }
      process(t, y, u, h);
    }
    t_prev = t;
    if (estimator.failed()) {
      std::fprintf(stderr, "ctid_stream: the estimator failed at t = %g\n", t);
      return 1;
    }
  }
  if (held) process(t_prev, y_held, u_held, 1.0);  // a single sample
  return 0;
}
