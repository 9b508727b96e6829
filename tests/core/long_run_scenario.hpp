// Long run under poor excitation, shared by covariance_guard_test.cpp (10^6
// samples in CI) and bench/long_run_bench.cpp (10^8 samples): the system
// (p^2 + 2.4 p + 4) x = 4 u of thesis sec. 2.3.5, a random binary input
// held 20 samples for the first 10 % of the record, then u = 1 to the end
// (as the windup example of sec. 3.6.3), output noise of standard
// deviation 0.01, Ts = 0.01 s. Every recursive estimator of the core is
// run over it, and the symmetric part of P is checked for positive
// definiteness every `check_every` samples.
#pragma once

#include <cmath>
#include <functional>
#include <random>
#include <string>
#include <vector>

#include "ctid/recursive_iv.hpp"
#include "ctid/rlssvf.hpp"

namespace ctid {
namespace long_run {

// Exact ZOH discretisation of the system (matrix exponential by scaling
// and squaring of a Taylor series), stepped sample by sample so that 10^8
// samples need no record in memory.
class Plant {
 public:
  explicit Plant(double ts, unsigned seed) : rng_(seed) {
    Eigen::Matrix2d A;
    A << 0, 1, -4, -2.4;
    Eigen::Matrix3d M = Eigen::Matrix3d::Zero();  // [A b; 0 0] * ts
    M.topLeftCorner<2, 2>() = A * ts;
    M(1, 2) = 4 * ts;
    Eigen::Matrix3d E = Eigen::Matrix3d::Identity(), term = E;
    const Eigen::Matrix3d Ms = M / 1024;
    for (int i = 1; i < 20; ++i) {
      term = term * Ms / i;
      E += term;
    }
    for (int i = 0; i < 10; ++i) E = E * E;
    ad_ = E.topLeftCorner<2, 2>();
    bd_ = E.topRightCorner<2, 1>();
  }
  // Output y(t_k) = x(t_k) + e, then the state moves on with u held.
  double step(double u) {
    const double y = x_(0) + 0.01 * normal_(rng_);
    x_ = ad_ * x_ + bd_ * u;
    return y;
  }

 private:
  std::mt19937 rng_;
  std::normal_distribution<double> normal_;
  Eigen::Matrix2d ad_;
  Eigen::Vector2d bd_;
  Eigen::Vector2d x_ = Eigen::Vector2d::Zero();
};

struct Result {
  long first_indefinite = -1;  // first checked sample with Ps not PD
  long first_nonfinite = -1;   // first checked sample with P or theta
                               // not finite
  double min_relative_eig = 1e300;  // min over checks of lambda_min(Ps) /
                                    // lambda_max(Ps)
  long guard_actions = 0;           // samples where the guard acted
  Eigen::VectorXd theta_end;
};

// True when the symmetric part of P is positive definite (Cholesky).
template <typename S>
bool symmetric_part_definite(const Matrix<S>& P) {
  const Matrix<S> sym = (P + P.transpose()) / 2;
  const Eigen::LLT<Matrix<S>> llt(sym);
  return llt.info() == Eigen::Success;
}

// Runs `update(u, y)` n times; `P()` and `theta()` give the state,
// `guard()` what the protection did.
template <typename S, typename Estimator>
Result run(Estimator& e, long n, long check_every) {
  Result r;
  Plant plant(0.01, 7);
  std::mt19937 rng(11);
  double level = 1;
  for (long k = 0; k < n; ++k) {
    if (k < n / 10) {
      if (k % 20 == 0) level = (rng() & 1) ? 1.0 : -1.0;
    } else {
      level = 1;
    }
    const double y = plant.step(level);
    const S u = S(level);
    e.update(&u, S(y), S(0.01));
    if (e.covariance_guard() != 0) ++r.guard_actions;
    if (k % check_every == 0 || k == n - 1) {
      const Matrix<S>& P = e.P();
      if (!P.allFinite() || !e.theta().allFinite()) {
        if (r.first_nonfinite < 0) r.first_nonfinite = k;
        continue;
      }
      if (!symmetric_part_definite<S>(P)) {
        if (r.first_indefinite < 0) r.first_indefinite = k;
        continue;
      }
      const Matrix<S> sym = (P + P.transpose()) / 2;
      const Eigen::SelfAdjointEigenSolver<Matrix<S>> eig(sym);
      const double ratio = double(eig.eigenvalues()(0)) /
                           double(eig.eigenvalues()(sym.rows() - 1));
      if (ratio < r.min_relative_eig) r.min_relative_eig = ratio;
    }
  }
  r.theta_end = e.theta().template cast<double>();
  return r;
}

// The estimators: name and a function that configures one and runs it.
template <typename S>
struct Case {
  std::string name;
  std::function<Result(long n, long check_every)> run;
};

template <typename S>
RlsSvfConfig<S> rlssvf_config() {
  RlsSvfConfig<S> c;
  c.orders = siso_orders(2, 1, 0);
  c.svf.lambda_svf = 3;
  c.ts = S(0.01);
  return c;
}

template <typename S>
RecursiveIvConfig<S> riv_config(IvMethod method, long n) {
  RecursiveIvConfig<S> c;
  c.orders = siso_orders(2, 1, 0);
  c.method = method;
  c.svf.lambda_svf = 3;
  c.ts = S(0.01);
  c.t_s_iv = S(0.05 * n * 0.01);  // half-way through the excited part
  return c;
}

template <typename S, typename Config, typename Estimator>
Result configure_and_run(const Config& c, long n, long check_every) {
  Estimator e;
  const Status status = e.configure(c);
  if (!status.ok()) {
    Result r;
    r.first_nonfinite = 0;
    return r;
  }
  return run<S>(e, n, check_every);
}

template <typename S>
std::vector<Case<S>> cases(long n) {
  std::vector<Case<S>> out;
  const Matrix<S> qn = S(1e-8) * Matrix<S>::Identity(3, 3);
  auto add_ls = [&](std::string name, RlsSvfConfig<S> c) {
    out.push_back({name, [c](long m, long every) {
                     return configure_and_run<S, RlsSvfConfig<S>, RlsSvf<S>>(
                         c, m, every);
                   }});
  };
  auto add_iv = [&](std::string name, RecursiveIvConfig<S> c) {
    out.push_back({name, [c](long m, long every) {
                     return configure_and_run<S, RecursiveIvConfig<S>,
                                              RecursiveIv<S>>(c, m, every);
                   }});
  };
  RlsSvfConfig<S> ls = rlssvf_config<S>();
  add_ls("RLSSVF-FF(1)", ls);
  ls.adaptation = ForgettingFactorAdaptation<S>(S(0.999));
  add_ls("RLSSVF-FF(0.999)", ls);
  ls.adaptation = KalmanAdaptation<S>(qn);
  add_ls("RLSSVF-KF", ls);
  ls.form = UpdateForm::kPotter;
  add_ls("Potter-KF", ls);
  ls.adaptation = ForgettingFactorAdaptation<S>(S(1));
  add_ls("Potter-FF(1)", ls);
  ls.form = UpdateForm::kLevenbergMarquardt;
  ls.adaptation = ForgettingFactorAdaptation<S>(S(0.998));
  ls.lmr_gamma = S(1e-3) * Matrix<S>::Identity(3, 3);
  add_ls("LMR-FF(0.998)", ls);
  for (const IvMethod method : {IvMethod::kRivsvf, IvMethod::kRsrivc}) {
    const std::string name =
        method == IvMethod::kRivsvf ? "RIVSVF" : "RSRIVC";
    RecursiveIvConfig<S> iv = riv_config<S>(method, n);
    add_iv(name + "-FF(1)", iv);
    iv.adaptation = KalmanAdaptation<S>(qn);
    add_iv(name + "-KF", iv);
  }
  return out;
}

}  // namespace long_run
}  // namespace ctid
