// SPDX-License-Identifier: BSD-3-Clause
// Copyright (C) the ctid authors
// The problem, settings and result types of the offline refined
// instrumental-variable engine (refined_iv.hpp): the generalised
// output-error structure
//
//   y(t) = sum_g x_g(t) + y0(t) + c + e(t),
//   F_g(p) x_g(t) = sum_(j in g) B_j(p) w_j(t - nk_j Ts),
//
// with theta = [f of group 0, f of group 1, .., b of channel 0, b of
// channel 1, .., c] (see refined_iv.hpp for the whole description).
#pragma once

#include <string>
#include <vector>

#include "ctid/offline/offline_iv.hpp"

namespace ctid {

enum class RivMethod { kLssvf, kIvsvf, kSrivc };

// One column of the signal matrix w: the denominator group it enters, its
// numerator length, delay in samples and intersample rule.
struct RivChannel {
  int group = 0;
  int nb = 1;
  int nk = 0;
  InterSample rule = InterSample::kZoh;
  // A continuous delay (time units, >= 0) on top of nk samples: not a
  // multiple of Ts, or on irregularly sampled data (filtered exactly by
  // filter_delayed_derivatives).
  double delay = 0;
};

template <typename S>
struct RivProblem {
  std::vector<int> nf;               // denominator order of each group, >= 1
  std::vector<RivChannel> channels;  // one per column of the signals
  // Fixed coefficients: empty (none) or one entry per theta element; the
  // fixed ones take their value from fixed_values (original time).
  std::vector<bool> fixed;
  Vector<S> fixed_values;
  InterSample y_rule = InterSample::kFoh;  // y: exact first-order hold
  bool output_offset = false;              // estimate c
  bool initial_state = false;              // estimate y0 (free responses)
  // Closed loop u = r1 + C(p) (r - y), C = nc / dc a continuous-time
  // controller (one group, one channel: the plant input; the thesis' form
  // of eq. 2.49b with r2 = r). Empty nc: open loop. r1 (the external
  // signal at the plant input, CONTSID's closedloop demos' r) is optional
  // here (nullptr: 0).
  Vector<S> controller_num, controller_den;  // descending powers of p
  const S* reference = nullptr;              // r (setpoint), N samples
  // Closed loop u = r1 + C(q^-1) (r2 - y) with a discrete controller (the
  // thesis' form, eqs. 2.44-2.50; ZOH input), simulated by LtvSimulator.
  const DiscreteTransferFunction<S>* discrete_controller = nullptr;
  const S* r1 = nullptr;
  const S* r2 = nullptr;

  int num_groups() const { return static_cast<int>(nf.size()); }
  int num_parameters() const {
    int n = output_offset ? 1 : 0;
    for (int v : nf) n += v;
    for (const RivChannel& c : channels) n += c.nb;
    return n;
  }
  bool continuous_loop() const { return controller_num.size() > 0; }
  bool closed_loop() const {
    return continuous_loop() || discrete_controller != nullptr;
  }
};

template <typename S>
struct RivSettings {
  RivMethod method = RivMethod::kSrivc;
  S tolerance = S(1e-6);  // on ||theta_i - theta_(i-1)|| / ||theta_i||, t'
  int max_iterations = 30;
  Vector<S> theta_init;  // original time; empty: the automatic start
  // SVF cut-offs (rad/s): the one of LSSVF/IVSVF, or the start grid;
  // empty: 12 log-spaced between 5/T and 0.5 pi/Ts.
  std::vector<S> cutoffs;
  int max_starts = 3;     // SRIVC runs from at most this many starts
  S time_scale = 0;       // sigma; 0 = automatic
  S integrator_pole = 0;  // prefilter pole replacing p = 0; 0: 10/T
  // The output offset c as a column of the refined-IV regression instead
  // of refitted between steps only; refined_iv() sets it for its second
  // attempt (see there).
  bool offset_in_regression = false;
  // SRIVC in open loop: a fit whose slowest pole crept to p = 0 is
  // refitted with that pole declared there (refined_iv.hpp,
  // refit_integrators), and the refit kept when it is better.
  bool refit_integrators = false;
};

template <typename S>
struct RivResult {
  Vector<S> theta;       // original time, fixed entries included
  Matrix<S> covariance;  // np x np, zero rows/columns for fixed entries
  S noise_variance = 0;  // ||y - y_hat||^2 / (N - free parameters)
  int iterations = 0;
  bool converged = false;
  bool stable = false;  // every F_g (without integrators) Hurwitz
  // False when SRIVC converged on its simulation loss while parameters
  // still moved by more than their standard errors: directions the data
  // do not determine (an over-parameterised structure).
  bool determined = true;
  // The returned iterate was pulled back into the stable region (its
  // unconstrained refined-IV solution was unstable), and how many of the
  // iterations had to be.
  bool clipped = false;
  int clipped_iterations = 0;
  // Per group: the slowest pole was real and moved monotonically toward
  // p = 0 over the last iterations, with a falling loss, and SRIVC did not
  // converge: the data ask for an integrator the structure does not
  // declare (the caller may refit with it declared).
  std::vector<int> integrator_suspected;
  std::vector<S> loss_history;  // simulation loss after each iteration
  // The lowest-loss stable iterate over all starts when it is not the
  // returned model (it did not converge, and has a lower loss than the
  // returned converged run): theta (original time, empty if none), its
  // simulation-error variance, integrator flags and simulated output, so
  // that the caller can refit from it (e.g. with the integrator it creeps
  // toward declared).
  Vector<S> lowest_theta;
  S lowest_noise_variance = std::numeric_limits<S>::infinity();
  std::vector<int> lowest_integrator_suspected;
  Vector<S> lowest_simulated;
  // With refit_integrators: per group, the poles at p = 0 that the refit
  // declared (zeros if none), and 1 (the refit was kept), 0 (no refit
  // tried), -1 (a refit from the returned fit was not better) or -2 (a
  // refit from the lowest-loss run was not better).
  std::vector<int> integrators;
  int integrator_refit = 0;
  std::string reason;  // why it stopped, in words
  S cutoff = 0;        // cut-off of the SVF start used (0: theta_init)
  S time_scale = 1;    // sigma of the final iterations
  int starts_tried = 0;
  S condition = 0;          // condition number of Z^T Phi (equilibrated)
  Vector<S> x0;             // per group: y0_g^(i)(t_0), i = 0..nf_g-1
  S offset = 0;             // c
  Vector<S> simulated;      // y_hat = sum x_g + y0 + c at the samples
  Vector<S> free_response;  // y0 at the samples
};

// The engine's signals: y (N), w (N x channels, column-major), the time
// base (ts or instants, as RecordView).
template <typename S>
struct RivData {
  const S* y = nullptr;
  const S* w = nullptr;
  Eigen::Index num_samples = 0;
  S ts = 0;
  const S* instants = nullptr;
};

}  // namespace ctid
