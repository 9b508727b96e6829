// SPDX-License-Identifier: BSD-3-Clause
// Copyright (C) the ctid authors
// The limit cycle of a relay-feedback record as frequency data for the
// frequency-domain estimators (freq_srivc.hpp; the toolbox's tffsrivc and
// tffcoe on time-domain data). The record between the first and the last
// upward crossing of the input's mid level (max u + min u) / 2 holds a
// whole number c of periods; its DFT at the multiples of c are the
// harmonics of the cycle, w_r = 2 pi r / (n Ts). Kept: those below a
// quarter of the sampling frequency where U has at least 1 % of its
// largest harmonic, and the mean (r = 0) when it is not negligible. The
// input is held between samples (ZOH): its continuous-time spectrum is
// the DFT times the hold's response h(w) = (1 - e^(-j w Ts)) / (j w Ts)
// (h(0) = 1); with `intersample_mean` (y_k the mean of y over the
// interval, CONTSID's IntSamp) the output's is Y_d / h likewise.
#pragma once

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <complex>
#include <unsupported/Eigen/FFT>
#include <vector>

#include "ctid/base/status.hpp"

namespace ctid {

template <typename S>
struct RelayFrequencyData {
  std::vector<S> w;                   // rad/s
  std::vector<std::complex<S>> y, u;  // output and input spectra
  S period = 0;                       // of the limit cycle (time units)
};

template <typename S>
Status relay_frequency_data(const S* y, const S* u, Eigen::Index n, S ts,
                            bool intersample_mean, RelayFrequencyData<S>* out) {
  using C = std::complex<S>;
  if (out == nullptr) return bad_input("no result given");
  if (y == nullptr || u == nullptr || n < 2) return bad_input("no data given");
  if (!(ts > 0) || !std::isfinite(ts)) return bad_input("Ts must be > 0");
  S hi = u[0], lo = u[0], largest = 0;
  for (Eigen::Index k = 0; k < n; ++k) {
    if (!std::isfinite(u[k]) || !std::isfinite(y[k]))
      return bad_input("the frequency data must be finite");
    hi = std::max(hi, u[k]);
    lo = std::min(lo, u[k]);
    largest = std::max(largest, std::abs(u[k]));
  }
  const S level = (hi + lo) / 2;
  std::vector<Eigen::Index> up;  // first samples above the level
  for (Eigen::Index k = 1; k < n; ++k) {
    if (u[k - 1] <= level && u[k] > level) up.push_back(k);
  }
  if (up.size() < 3) {
    return bad_input(
        "the input shows fewer than two periods of a limit cycle (relay "
        "feedback data expected)");
  }
  const Eigen::Index first = up.front();
  const Eigen::Index m = up.back() - first;  // samples of c whole periods
  const Eigen::Index c = static_cast<Eigen::Index>(up.size()) - 1;
  out->period = static_cast<S>(m) / static_cast<S>(c) * ts;
  std::vector<S> yc(y + first, y + first + m), uc(u + first, u + first + m);
  Eigen::FFT<S> fft;
  fft.SetFlag(Eigen::FFT<S>::Unscaled);
  std::vector<C> Yd, Ud;
  fft.fwd(Yd, yc);
  fft.fwd(Ud, uc);
  std::vector<Eigen::Index> r;
  if (std::abs(Ud[0]) > S(1e-9) * static_cast<S>(m) * largest) r.push_back(0);
  for (Eigen::Index k = c; k <= m / 4; k += c) r.push_back(k);
  S peak = 0;
  for (Eigen::Index k : r) peak = std::max(peak, std::abs(Ud[k]));
  out->w.clear();
  out->y.clear();
  out->u.clear();
  for (Eigen::Index k : r) {
    if (!(std::abs(Ud[k]) >= S(0.01) * peak)) continue;
    const S w = S(2) * S(M_PI) * static_cast<S>(k) / (static_cast<S>(m) * ts);
    C h(1);
    if (w > 0) {
      const C jwt(0, w * ts);
      h = (S(1) - std::exp(-jwt)) / jwt;
    }
    out->w.push_back(w);
    out->u.push_back(Ud[k] * h);
    out->y.push_back(intersample_mean ? Yd[k] / h : Yd[k]);
  }
  return Status::Ok();
}

}  // namespace ctid
