// SPDX-License-Identifier: BSD-3-Clause
// Copyright (C) the ctid authors
// Long run under poor excitation, shared by
// covariance_guard_test.cpp (10^6 samples in CI) and
// bench/long_run_bench.cpp (10^8 samples): the system
// (p^2 + 2.4 p + 4) x = 4 u of thesis sec. 2.3.5, Ts = 0.01 s, output noise
// of standard deviation 0.01. Open loop: a random binary input held 20
// samples for the first 10 % of the record, then u = 1 to the end (as the
// windup example of sec. 3.6.3). Closed loop (CLRIVSVF, CLRSRIVC): the
// proportional controller u = r1 + 0.5 (r2 - y), the binary signal on r2
// for the first 10 %, then r2 = 1 (only the measurement noise fed back
// excites the loop). Every recursive estimator of the core runs over it,
// and the symmetric part of P is checked for positive definiteness every
// `check_every` samples (by Eigen's Cholesky in double of the stored
// entries, independently of the guard's own LDL^T test; a Cholesky in the
// estimator's own precision is counted apart). LMR-RLSSVF propagates the Cholesky factor L of
// R = P^-1 (lmr.hpp): the same check runs on P = L^-T L^-1 formed from it.
// The IV estimators with a forgetting factor < 1 run with conditional
// updating (eq. 3.79, gamma = 300, the thesis' remedy for their windup):
// without it the IV estimates themselves diverge once the input is
// constant (to 1e17 and then NaN within 5e5 samples of RSRIVC-FF(0.999)
// here, whatever is done to P).
#pragma once

#include <cmath>
#include <functional>
#include <random>
#include <string>
#include <type_traits>
#include <vector>

#include "ctid/recursive/recursive_iv.hpp"
#include "ctid/recursive/rlssvf.hpp"

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
  // y(t_k) = x(t_k) + e.
  double output() { return x_(0) + 0.01 * normal_(rng_); }
  // The state moves on to t_(k+1) with u held.
  void advance(double u) { x_ = ad_ * x_ + bd_ * u; }

 private:
  std::mt19937 rng_;
  std::normal_distribution<double> normal_;
  Eigen::Matrix2d ad_;
  Eigen::Vector2d bd_;
  Eigen::Vector2d x_ = Eigen::Vector2d::Zero();
};

constexpr double kControllerGain = 0.5;

struct Result {
  long first_indefinite = -1;  // first checked sample with Ps not PD
  long first_nonfinite = -1;   // first checked sample with P or theta
                               // not finite
  long indefinite_checks = 0;  // checked samples with Ps not PD
  long precision_cholesky_failures = 0;  // checked samples with Ps PD but
                                         // a Cholesky in S failing
  double min_relative_eig = 1e300;  // min over eigenvalue checks of
                                    // lambda_min(Ps) / lambda_max(Ps)
  long guard_actions = 0;           // samples where the guard acted
  long first_guard = -1;            // first of them
  long guard_repairs = 0;           // samples with kGuardRepair
  long guard_ceilings = 0;          // samples with kGuardCeiling
  Eigen::VectorXd theta_end;
};

// Optional report of a run in progress (the 10^8-sample benchmark): when
// progress_interval > 0, progress(k, r) is called after every
// progress_interval samples with the result so far.
inline long progress_interval = 0;
inline std::function<void(long, const Result&)> progress;

// True when the symmetric part of the stored P is positive definite. The
// test is a Cholesky in double of the stored entries: float entries convert
// exactly and their half-sums are exact in double, so this decides the
// property of the matrix the estimator holds, reliably up to condition
// numbers near 1e15. A Cholesky in the estimator's own precision (below)
// can fail by its rounding alone once the condition number of the
// correlation form nears 1 / eps of that precision, although the stored
// matrix is positive definite: the single-precision 10^8-sample run of
// RLSSVF-FF(0.999) met one such sample, lambda_min(C) = 0.74 eps_float
// computed in double.
template <typename S, typename Derived>
bool symmetric_part_definite(const Eigen::MatrixBase<Derived>& P) {
  const Eigen::MatrixXd Pd = P.template cast<double>();
  const Eigen::MatrixXd sym = (Pd + Pd.transpose()) / 2;
  const Eigen::LLT<Eigen::MatrixXd> llt(sym);
  return llt.info() == Eigen::Success;
}

// The same Cholesky in the precision S (reported apart, see above).
template <typename S, typename Derived>
bool cholesky_in_precision(const Eigen::MatrixBase<Derived>& P) {
  const Matrix<S> sym = (P + P.transpose()) / 2;
  const Eigen::LLT<Matrix<S>> llt(sym);
  return llt.info() == Eigen::Success;
}

// Runs the estimator n samples; `step(e, u, y, r2)` makes one update.
// P is checked every check_every samples, its eigenvalues every
// 1000 check_every.
// `definite(e)` decides whether the estimator's covariance is positive
// definite (default: Cholesky of the symmetric part of P).
template <typename S, typename Estimator, typename Step>
Result run(Estimator& e, Step step, bool closed_loop, long n,
           long check_every) {
  auto definite = [](const Estimator& est) {
    if constexpr (std::is_same_v<Estimator, RlsSvf<S>>) {
      if (est.failed()) return false;
    }
    return symmetric_part_definite<S>(est.P());
  };
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
    const double y = plant.output();
    const double u = closed_loop ? kControllerGain * (level - y) : level;
    plant.advance(u);
    step(e, S(u), S(y), S(level));
    const int action = e.covariance_guard();
    if (action != 0) {
      if (r.first_guard < 0) r.first_guard = k;
      ++r.guard_actions;
      r.guard_repairs += (action & kGuardRepair) != 0;
      r.guard_ceilings += (action & kGuardCeiling) != 0;
    }
    if (k % check_every == 0 || k == n - 1) {
      const auto& P = e.P();
      if (!P.allFinite() || !e.theta().allFinite()) {
        if (r.first_nonfinite < 0) r.first_nonfinite = k;
        continue;
      }
      if (!definite(e)) {
        if (r.first_indefinite < 0) r.first_indefinite = k;
        ++r.indefinite_checks;
        continue;
      }
      if (!cholesky_in_precision<S>(P)) ++r.precision_cholesky_failures;
      if (k % (1000 * check_every) == 0 || k == n - 1) {
        const Eigen::MatrixXd Pd = P.template cast<double>();
        const Eigen::MatrixXd sym = (Pd + Pd.transpose()) / 2;
        const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(
            sym, Eigen::EigenvaluesOnly);
        const double ratio = double(eig.eigenvalues()(0)) /
                             double(eig.eigenvalues()(sym.rows() - 1));
        if (ratio < r.min_relative_eig) r.min_relative_eig = ratio;
      }
    }
    if (progress_interval > 0 && (k + 1) % progress_interval == 0 &&
        progress) {
      progress(k + 1, r);
    }
  }
  r.theta_end = e.theta().template cast<double>();
  return r;
}

// The estimators: name and a function that configures one and runs it.
struct Case {
  std::string name;
  std::function<Result(long n, long check_every, bool guard)> run;
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
RecursiveIvConfig<S> riv_config(IvMethod method, bool closed_loop, long n) {
  RecursiveIvConfig<S> c;
  c.orders = siso_orders(2, 1, 0);
  c.method = method;
  c.svf.lambda_svf = 3;
  c.ts = S(0.01);
  c.t_s_iv = S(0.05 * n * 0.01);  // half-way through the excited part
  if (closed_loop) {
    c.closed_loop = true;
    c.controller.numerator = Vector<S>::Constant(1, S(kControllerGain));
    c.controller.denominator = Vector<S>::Ones(1);
  }
  return c;
}

template <typename S>
Result run_rlssvf_case(RlsSvfConfig<S> c, long n, long every, bool guard) {
  c.covariance_guard = guard;
  RlsSvf<S> e;
  if (!e.configure(c).ok()) {
    Result r;
    r.first_nonfinite = 0;
    return r;
  }
  return run<S>(
      e, [](RlsSvf<S>& est, S u, S y, S) { est.update(&u, y, S(0.01)); },
      false, n, every);
}

template <typename S>
Result run_riv_case(RecursiveIvConfig<S> c, long n, long every, bool guard) {
  c.covariance_guard = guard;
  RecursiveIv<S> e;
  if (!e.configure(c).ok()) {
    Result r;
    r.first_nonfinite = 0;
    return r;
  }
  const bool loop = c.closed_loop;
  return run<S>(
      e,
      [loop](RecursiveIv<S>& est, S u, S y, S r2) {
        if (loop) {
          est.update(&u, y, S(0.01), S(0), r2);
        } else {
          est.update(&u, y, S(0.01));
        }
      },
      loop, n, every);
}

// Every recursive estimator with the adaptations it takes: RLSSVF FF(1),
// FF(0.999), KF; PotterSVF KF and FF(1); LMR-RLSSVF FF(0.998); RIVSVF,
// RSRIVC, CLRIVSVF, CLRSRIVC each FF(1), KF, and FF(0.999) with
// conditional updating (AW).
template <typename S>
std::vector<Case> cases(long n) {
  std::vector<Case> out;
  const Matrix<S> qn = S(1e-8) * Matrix<S>::Identity(3, 3);
  auto add_ls = [&](std::string name, RlsSvfConfig<S> c) {
    out.push_back({name, [c](long m, long every, bool guard) {
                     return run_rlssvf_case<S>(c, m, every, guard);
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
  for (const bool loop : {false, true}) {
    for (const IvMethod method : {IvMethod::kRivsvf, IvMethod::kRsrivc}) {
      const std::string name = std::string(loop ? "CL" : "") +
                               (method == IvMethod::kRivsvf ? "RIVSVF"
                                                            : "RSRIVC");
      RecursiveIvConfig<S> iv = riv_config<S>(method, loop, n);
      auto add_iv = [&](std::string label, RecursiveIvConfig<S> c) {
        out.push_back({label, [c](long m, long every, bool guard) {
                         return run_riv_case<S>(c, m, every, guard);
                       }});
      };
      add_iv(name + "-FF(1)", iv);
      iv.adaptation = KalmanAdaptation<S>(qn);
      add_iv(name + "-KF", iv);
      iv.adaptation = ForgettingFactorAdaptation<S>(S(0.999));
      iv.antiwindup_gamma = S(300);
      add_iv(name + "-FF(0.999)+AW", iv);
    }
  }
  return out;
}

}  // namespace long_run
}  // namespace ctid
