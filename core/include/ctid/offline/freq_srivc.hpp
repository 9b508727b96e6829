// SPDX-License-Identifier: BSD-3-Clause
// Copyright (C) the ctid authors
// Continuous-time transfer functions (with a time delay) from frequency
// data: SRIVC in the frequency domain and output-error refinement.
//
//   Y_k = G(j w_k) U_k + V_k,  G(s) = B(s)/A(s) e^(-s td),
//   A(s) = s^n + a_1 s^(n-1) + .. + a_n,  B(s) = b_0 s^(m-1) + .. + b_(m-1)
//
// (U_k = 1 for a frequency response, idfrd). Several inputs: Y_k = sum_j
// G_j(j w_k) U_jk, each G_j = B_j/A_j e^(-s td_j) with its own denominator
// and fixed delay, theta = [a_1 .. a_m b_1 .. b_m]; each SRIVC iteration
// updates the inputs in turn, input j fitted to Y minus the other inputs'
// current model outputs (Gauss-Seidel, as refined_iv.hpp's groups), and
// the output-error Jacobian is per input. SRIVC (thesis eqs. 2.8-2.13
// with the prefilter 1/A applied in the frequency domain): with the
// current A_i, B_i the filtered data Y_f = Y / A_i(jw), U_f = e^(-jw td)
// U / A_i(jw) and the auxiliary-model output X_f = B_i/A_i U_f give the
// regressor phi = [-(jw)^(n-1) Y_f .. -Y_f, (jw)^(m-1) U_f .. U_f] and
// the instrument zeta (the same with X_f for Y_f); theta solves
// Re sum zeta^* phi^T theta = Re sum zeta^* (jw)^n Y_f (real and imaginary
// parts stacked). The start is least squares with the prefilter
// 1/(jw + lambda)^n. Frequencies are scaled by sigma (jw' = jw / sigma,
// the geometric centre of the band) for conditioning; coefficients map
// back exactly (a_i = sigma^i a'_i, b of power p: sigma^(n-p) b').
//
// The delay: fixed, or delay_search.hpp's search of the SRIVC loss over
// [td_min, td_max] (the time-domain estimators' search): a grid, then
// around each of the best local minima of the grid (up to eight) a scan
// of the two neighbouring grid steps with a sixteenth of a step, and
// golden section around each local minimum of that scan; the lowest
// refined loss is kept (the loss is separable in td, Chen, Zhuan, Garnier
// & Gilson, Automatica 2018). The loss of relay data has several minima
// within one grid step (the harmonics' phases wrap at different td); the
// fine scan puts the golden section in the basin of the lowest of them.
//
// At the SRIVC fixed point the instruments are the output-error
// Jacobian (zeta = d(G U)/d theta: X_f = B U / A^2 for the a's, U / A for
// the b's) and A Y_f - B U_f = Y - G U, so the IV equations are the
// normal equations J^T E = 0 of the output-error criterion: SRIVC's
// estimate is a stationary point of sum |Y - G U|^2, and with the delay at
// the minimum of the concentrated loss, of the joint criterion too.
// Output error (TFFCOE; oe and tfest on frequency data): the weighted
// nonlinear least squares sum_k |Y_k - G(j w_k) U_k|^2 over [a b (td)]
// (the frequency-domain form of the output-error criterion, thesis eq.
// 1.16 with H = 1, by Parseval), minimised from the SRIVC estimate by the
// Levenberg-Marquardt iteration of output_error.hpp (levenberg_marquardt)
// on the stacked real and imaginary parts. Covariance (both): s^2 (J^T J)^-1
// with J the Jacobian of the stacked model output and s^2 = sum |Y - G U|^2 /
// (2K - np), the asymptotic covariance of SRIVC (eq. 2.13) and of the
// output-error fit.
#pragma once

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <complex>
#include <limits>
#include <string>
#include <vector>

#include "ctid/base/stability.hpp"
#include "ctid/base/status.hpp"
#include "ctid/base/types.hpp"
#include "ctid/offline/delay_search.hpp"
#include "ctid/offline/output_error.hpp"

namespace ctid {

template <typename S>
struct FreqData {
  const S* w = nullptr;                // K frequencies (rad/s), >= 0
  const std::complex<S>* y = nullptr;  // K output values (or G)
  // K-by-num_inputs input values (column-major); null: 1 (one input)
  const std::complex<S>* u = nullptr;
  Eigen::Index num_frequencies = 0;
  int num_inputs = 1;
};

// One input of a multi-input model Y = sum_j B_j/A_j e^(-s td_j) U_j:
// its own denominator order na, numerator length nb and fixed delay.
template <typename S>
struct FreqChannel {
  int na = 1;
  int nb = 1;
  S delay = 0;
};

template <typename S>
struct FreqSettings {
  int na = 1;
  int nb = 1;
  S tolerance = S(1e-8);
  int max_iterations = 50;
  S delay = 0;  // fixed or initial delay
  bool estimate_delay = false;
  S td_min = 0, td_max = 0;   // search range (estimate_delay)
  int num_td = 50;            // grid points (estimate_delay)
  bool grid = true;           // search the grid (else refine from delay)
  bool output_error = false;  // Levenberg-Marquardt refinement (TFFCOE)
  Vector<S> theta_init;       // [a b] start (empty: LS with 1/(s+l)^n)
  // Several inputs: one entry per column of U (then na, nb and delay above
  // are not read; the delays are fixed); theta = [a_1 .. a_m b_1 .. b_m].
  std::vector<FreqChannel<S>> inputs;
  std::vector<FreqChannel<S>> channels() const {
    if (!inputs.empty()) return inputs;
    FreqChannel<S> c;
    c.na = na;
    c.nb = nb;
    c.delay = delay;
    return {c};
  }
};

template <typename S>
struct FreqResult {
  // A without its leading 1, B descending (several inputs: [a_1 .. a_m],
  // [b_1 .. b_m])
  Vector<S> a, b;
  S delay = 0;
  Matrix<S> covariance;  // of [a b] or [a b td] (estimate_delay)
  S noise_variance = 0;  // sum |Y - G U|^2 / (K - np/2): E|V_k|^2
  S loss = 0;            // sum |Y - G U|^2 / K
  int iterations = 0;
  bool converged = false;
  bool stable = false;
  std::string reason;
};

namespace freq_detail {

template <typename S>
using Complex = std::complex<S>;

template <typename S>
Complex<S> polyval(const Vector<S>& c, Complex<S> s) {
  Complex<S> v = 0;
  for (Eigen::Index i = 0; i < c.size(); ++i) v = v * s + c(i);
  return v;
}

// The problem in scaled frequency w' = w / sigma: Y and the inputs U_j,
// channel j with na[j], nb[j] coefficients at a_offset[j], b_offset[j] of
// theta' = [a_1' .. a_m' b_1' .. b_m'].
template <typename S>
struct Scaled {
  std::vector<Complex<S>> s, y;            // jw', Y
  std::vector<std::vector<Complex<S>>> u;  // U_j (without the delay)
  std::vector<S> w;                        // original w
  S sigma = 1;
  std::vector<int> na, nb, a_offset, b_offset;
  Eigen::Index K = 0;

  int inputs() const { return static_cast<int>(na.size()); }
  int num_ab() const { return b_offset.back() + nb.back(); }
  void set_orders(const std::vector<FreqChannel<S>>& channels) {
    int at = 0;
    for (const FreqChannel<S>& c : channels) {
      na.push_back(c.na);
      nb.push_back(c.nb);
      a_offset.push_back(at);
      at += c.na;
    }
    for (const FreqChannel<S>& c : channels) {
      b_offset.push_back(at);
      at += c.nb;
    }
  }
  Vector<S> a(const Vector<S>& theta, int j) const {
    return theta.segment(a_offset[j], na[j]);
  }
  Vector<S> b(const Vector<S>& theta, int j) const {
    return theta.segment(b_offset[j], nb[j]);
  }
  Vector<S> monic(const Vector<S>& a) const {
    Vector<S> A(a.size() + 1);
    A << 1, a;
    return A;
  }
  Complex<S> delayed_u(int j, Eigen::Index k, S td) const {
    return u[j][k] * std::exp(Complex<S>(0, -w[k] * td));
  }
  // Y minus the model output of every input but j (the target of input
  // j's refined-IV step, Gauss-Seidel over the inputs as in refined_iv.hpp);
  // with one input, Y. Only the inputs before `upto` count (the start,
  // where the later ones have no model yet).
  std::vector<Complex<S>> target(const Vector<S>& theta,
                                 const std::vector<S>& td, int j,
                                 int upto) const {
    std::vector<Complex<S>> t = y;
    for (int i = 0; i < upto; ++i) {
      if (i == j) continue;
      const Vector<S> A = monic(a(theta, i)), B = b(theta, i);
      for (Eigen::Index k = 0; k < K; ++k)
        t[k] -= polyval(B, s[k]) / polyval(A, s[k]) * delayed_u(i, k, td[i]);
    }
    return t;
  }
};

// One SRIVC step of input j (or LS with instruments = regressors when aux
// is false) from the prefilter 1/Af, fitted to the target y; returns its
// theta_j' = [a_j' b_j'].
template <typename S>
Status iv_step(const Scaled<S>& p, int j, const std::vector<Complex<S>>& y,
               const Vector<S>& Af, const Vector<S>& Bx, bool aux, S td,
               Vector<S>& theta) {
  const int n = p.na[j], m = p.nb[j], np = n + m;
  Matrix<S> Phi(2 * p.K, np), Z(2 * p.K, np);
  Vector<S> T(2 * p.K);
  for (Eigen::Index k = 0; k < p.K; ++k) {
    const Complex<S> s = p.s[k];
    const Complex<S> A = polyval(Af, s);
    const Complex<S> U = p.delayed_u(j, k, td);
    const Complex<S> Yf = y[k] / A, Uf = U / A;
    const Complex<S> Xf = aux ? polyval(Bx, s) / polyval(Af, s) * Uf : Yf;
    std::vector<Complex<S>> phi(np), zeta(np);
    Complex<S> power = 1;
    // powers s^0 .. s^(n-1) for a_n .. a_1; s^0 .. s^(m-1) for b.
    for (int i = 0; i < std::max(n, m); ++i) {
      if (i < n) {
        phi[n - 1 - i] = -power * Yf;
        zeta[n - 1 - i] = -power * Xf;
      }
      if (i < m) {
        phi[n + m - 1 - i] = power * Uf;
        zeta[n + m - 1 - i] = power * Uf;
      }
      power *= s;
    }
    Complex<S> sn = 1;
    for (int i = 0; i < n; ++i) sn *= s;
    const Complex<S> t = sn * Yf;
    for (int c = 0; c < np; ++c) {
      Phi(k, c) = phi[c].real();
      Phi(p.K + k, c) = phi[c].imag();
      Z(k, c) = zeta[c].real();
      Z(p.K + k, c) = zeta[c].imag();
    }
    T(k) = t.real();
    T(p.K + k) = t.imag();
  }
  Vector<S> d = Phi.colwise().norm().transpose();
  const std::string of =
      p.inputs() > 1 ? " (input " + std::to_string(j + 1) + ")" : std::string();
  for (int c = 0; c < np; ++c) {
    if (!(d(c) > 0)) {
      return numerical_failure(
          "the frequency data do not excite the model (a regressor is "
          "zero)" +
          of);
    }
  }
  const Matrix<S> M = Z.transpose() * Phi * d.cwiseInverse().asDiagonal();
  Eigen::ColPivHouseholderQR<Matrix<S>> qr(M);
  if (qr.rank() < np) {
    return numerical_failure(
        "the instrument matrix is rank deficient: too few frequencies or "
        "too little excitation for this model order" +
        of);
  }
  theta =
      d.cwiseInverse().asDiagonal() * qr.solve(Vector<S>(Z.transpose() * T));
  if (!theta.allFinite()) return numerical_failure("the IV step diverged");
  return Status::Ok();
}

// Output error E_k = Y_k - sum_j G_j U_jk (td_j in time units) and its
// stacked Jacobian in [a' b' td'], td' = sigma td (the delay of input 1:
// the one that can be estimated, with one input).
template <typename S>
S residual(const Scaled<S>& p, const Vector<S>& theta, const std::vector<S>& td,
           bool jac, Vector<S>& r, Matrix<S>* J) {
  const int q = p.num_ab();
  r.resize(2 * p.K);
  if (jac) J->setZero(2 * p.K, q + 1);
  S cost = 0;
  std::vector<Vector<S>> A(p.inputs()), B(p.inputs());
  for (int j = 0; j < p.inputs(); ++j) {
    A[j] = p.monic(p.a(theta, j));
    B[j] = p.b(theta, j);
  }
  std::vector<Complex<S>> GU(p.inputs()), Av(p.inputs()), U(p.inputs());
  for (Eigen::Index k = 0; k < p.K; ++k) {
    const Complex<S> s = p.s[k];
    Complex<S> total = 0;
    for (int j = 0; j < p.inputs(); ++j) {
      Av[j] = polyval(A[j], s);
      U[j] = p.delayed_u(j, k, td[j]);
      GU[j] = polyval(B[j], s) / Av[j] * U[j];
      total += GU[j];
    }
    const Complex<S> e = p.y[k] - total;
    r(k) = e.real();
    r(p.K + k) = e.imag();
    cost += std::norm(e);
    if (!jac) continue;
    for (int j = 0; j < p.inputs(); ++j) {
      const int n = p.na[j], m = p.nb[j];
      const int ao = p.a_offset[j], bo = p.b_offset[j];
      Complex<S> power = 1;
      for (int i = 0; i < std::max(n, m); ++i) {
        if (i < n) {
          const Complex<S> g = -GU[j] * power / Av[j];  // d(GU)/d a_(n-i)
          (*J)(k, ao + n - 1 - i) = g.real();
          (*J)(p.K + k, ao + n - 1 - i) = g.imag();
        }
        if (i < m) {
          const Complex<S> g = power / Av[j] * U[j];
          (*J)(k, bo + m - 1 - i) = g.real();
          (*J)(p.K + k, bo + m - 1 - i) = g.imag();
        }
        power *= s;
      }
    }
    // td' = sigma td: d/dtd' of e^(-j w' td') G_1 U_1.
    const Complex<S> g = -s * GU[0];
    (*J)(k, q) = g.real();
    (*J)(p.K + k, q) = g.imag();
  }
  return cost;
}

// Reflects the unstable roots of input j's A; true if any was.
template <typename S>
bool stabilise_input(const Scaled<S>& p, int j, Vector<S>& theta) {
  const int n = p.na[j];
  HurwitzTest<S> hurwitz(n);
  auto a = theta.segment(p.a_offset[j], n);
  if (hurwitz.is_stable(a)) return false;
  a = reflect_unstable_roots<S>(Vector<S>(a));
  return true;
}

// The same for every input; true if any was unstable.
template <typename S>
bool stabilise(const Scaled<S>& p, Vector<S>& theta) {
  bool changed = false;
  for (int j = 0; j < p.inputs(); ++j)
    changed = stabilise_input(p, j, theta) || changed;
  return changed;
}

// SRIVC at the fixed delays td. theta' in/out (empty: LS start). With
// several inputs each step updates the inputs in turn, input j fitted to
// Y minus the other inputs' current model outputs.
template <typename S>
Status srivc_fixed(const Scaled<S>& p, const FreqSettings<S>& settings,
                   const std::vector<S>& td, Vector<S>& theta, int& iterations,
                   bool& converged, S& cost) {
  const int q = p.num_ab();
  Status status;
  if (theta.size() != q) {
    // LS start with the prefilter 1/(s' + 1)^n, input by input (the
    // inputs not yet started count as zero).
    theta = Vector<S>::Zero(q);
    for (int j = 0; j < p.inputs(); ++j) {
      Vector<S> Af = Vector<S>::Ones(1);
      for (int i = 0; i < p.na[j]; ++i) {
        Vector<S> next = Vector<S>::Zero(Af.size() + 1);
        next.head(Af.size()) += Af;
        next.tail(Af.size()) += Af;
        Af = next;
      }
      std::vector<Complex<S>> y = p.y;
      if (p.inputs() > 1) y = p.target(theta, td, j, j);
      Vector<S> tj;
      status = iv_step(p, j, y, Af, Vector<S>(), false, td[j], tj);
      if (!status.ok()) return status;
      theta.segment(p.a_offset[j], p.na[j]) = tj.head(p.na[j]);
      theta.segment(p.b_offset[j], p.nb[j]) = tj.tail(p.nb[j]);
      stabilise_input(p, j, theta);
    }
  }
  converged = false;
  iterations = 0;
  for (int it = 1; it <= settings.max_iterations; ++it) {
    Vector<S> next = theta;
    for (int j = 0; j < p.inputs(); ++j) {
      std::vector<Complex<S>> y = p.y;
      if (p.inputs() > 1) y = p.target(next, td, j, p.inputs());
      Vector<S> tj;
      status = iv_step(p, j, y, p.monic(p.a(next, j)), p.b(next, j), true,
                       td[j], tj);
      if (!status.ok()) return status;
      next.segment(p.a_offset[j], p.na[j]) = tj.head(p.na[j]);
      next.segment(p.b_offset[j], p.nb[j]) = tj.tail(p.nb[j]);
      stabilise_input(p, j, next);
    }
    const S change = (next - theta).norm() / std::max(next.norm(), S(1e-300));
    theta = next;
    iterations = it;
    if (change < settings.tolerance) {
      converged = true;
      break;
    }
  }
  Vector<S> r;
  cost = residual<S>(p, theta, td, false, r, nullptr);
  return Status::Ok();
}

// The output-error model of the frequency data for levenberg_marquardt
// (output_error.hpp): y_hat = [Re sum G_j U_j; Im ..] over [a' b' (td')].
template <typename S>
class FreqOeModel {
 public:
  FreqOeModel(const Scaled<S>& p, bool estimate_delay, std::vector<S> td)
      : p_(p), estimate_delay_(estimate_delay), td_(std::move(td)) {}
  bool stable(const Vector<S>& x) {
    if (!x.allFinite()) return false;
    for (int j = 0; j < p_.inputs(); ++j) {
      HurwitzTest<S> hurwitz(p_.na[j]);
      if (!hurwitz.is_stable(x.segment(p_.a_offset[j], p_.na[j]))) return false;
    }
    return true;
  }
  void evaluate(const Vector<S>& x, Vector<S>& yhat, Matrix<S>* J) {
    const int nm = p_.num_ab();
    const Vector<S> theta = x.head(nm);
    std::vector<S> td = td_;
    if (estimate_delay_) td[0] = x(nm) / p_.sigma;
    Vector<S> r;
    residual<S>(p_, theta, td, J != nullptr, r, J ? &J_ : nullptr);
    yhat.resize(2 * p_.K);
    for (Eigen::Index k = 0; k < p_.K; ++k) {
      yhat(k) = p_.y[k].real() - r(k);
      yhat(p_.K + k) = p_.y[k].imag() - r(p_.K + k);
    }
    if (J != nullptr) *J = J_.leftCols(x.size());
  }

 private:
  const Scaled<S>& p_;
  bool estimate_delay_;
  std::vector<S> td_;
  Matrix<S> J_;
};

// The SRIVC fit at one delay, for delay_search.hpp.
template <typename S>
struct FreqFit {
  S td = 0;
  S loss = std::numeric_limits<S>::infinity();  // sum |Y - G U|^2
  Vector<S> theta;
  int iterations = 0;
  bool converged = false;
};

template <typename S, typename F>
class FreqDelayModel {
 public:
  using Fit = FreqFit<S>;
  explicit FreqDelayModel(F fit) : fit_(fit) {}
  Status fit(S td, const Vector<S>&, Fit* out) {
    out->td = td;
    return fit_(td, out);
  }
  // (the frequency-domain search refines by golden section, without it)
  Status step_terms(const Fit&, Vector<S>*, Vector<S>*, Matrix<S>*) {
    return not_supported("no Gauss-Newton refinement in the frequency domain");
  }

 private:
  F fit_;
};

}  // namespace freq_detail

template <typename S>
Status freq_srivc(const FreqSettings<S>& settings, const FreqData<S>& data,
                  FreqResult<S>* result) {
  using namespace freq_detail;
  if (result == nullptr) return bad_input("result must not be null");
  const std::vector<FreqChannel<S>> channels = settings.channels();
  const int inputs = static_cast<int>(channels.size());
  for (const FreqChannel<S>& c : channels) {
    if (c.na < 1 || c.nb < 1 || c.nb > c.na + 1 || c.na > 1000) {
      return bad_input("orders must be np >= 1 and 0 <= nz <= np");
    }
    if (!(c.delay >= 0) || !std::isfinite(c.delay)) {
      return Status(ErrorCode::kBadOption, "the delay must be finite and >= 0");
    }
  }
  if (settings.max_iterations < 1 || !(settings.tolerance > 0) ||
      settings.num_td < 2 || settings.num_td > 100000) {
    return Status(ErrorCode::kBadOption,
                  "MaxIter must be >= 1, Tol > 0 and 2 <= NumTd <= 1e5");
  }
  if (data.num_inputs != inputs) {
    return Status(ErrorCode::kDimensionMismatch,
                  "the structure has " + std::to_string(inputs) +
                      " input(s), the data " + std::to_string(data.num_inputs));
  }
  if (inputs > 1 && (settings.estimate_delay || data.u == nullptr)) {
    return bad_input("several inputs need their input data U and fixed delays");
  }
  const Eigen::Index K = data.num_frequencies;
  if (data.w == nullptr || data.y == nullptr || K < 1) {
    return bad_input("the frequency data are empty");
  }
  Scaled<S> p;
  p.set_orders(channels);
  p.K = K;
  const int nab = p.num_ab();
  const int np = nab + (settings.estimate_delay ? 1 : 0);
  if (2 * K < np + 1) {
    return bad_input("too few frequencies for the model: " + std::to_string(K) +
                     " complex values, " + std::to_string(np) + " parameters");
  }
  S lo = std::numeric_limits<S>::infinity(), hi = 0;
  for (Eigen::Index k = 0; k < K; ++k) {
    const S w = data.w[k];
    if (!(w >= 0) || !std::isfinite(w)) {
      return bad_input("frequencies must be finite and >= 0");
    }
    if (!std::isfinite(data.y[k].real()) || !std::isfinite(data.y[k].imag())) {
      return bad_input("the frequency data must be finite");
    }
    for (int j = 0; j < inputs && data.u != nullptr; ++j) {
      const std::complex<S> v = data.u[j * K + k];
      if (!std::isfinite(v.real()) || !std::isfinite(v.imag()))
        return bad_input("the frequency data must be finite");
    }
    if (w > 0) lo = std::min(lo, w);
    hi = std::max(hi, w);
  }
  if (!(hi > 0)) return bad_input("at least one frequency must be > 0");
  p.sigma = std::sqrt(lo * hi);
  p.u.resize(inputs);
  for (Eigen::Index k = 0; k < K; ++k) {
    p.w.push_back(data.w[k]);
    p.s.push_back(Complex<S>(0, data.w[k] / p.sigma));
    p.y.push_back(data.y[k]);
    for (int j = 0; j < inputs; ++j) {
      p.u[j].push_back(data.u != nullptr ? data.u[j * K + k] : Complex<S>(1));
    }
  }
  if (settings.estimate_delay &&
      !(settings.td_min >= 0 && settings.td_max >= settings.td_min &&
        std::isfinite(settings.td_max))) {
    return Status(ErrorCode::kBadOption,
                  "the delay range must satisfy 0 <= TdMin <= TdMax < Inf");
  }
  // The scale factors of [a b]: a_i = sigma^i a_i', b of power k:
  // sigma^(n-k) b'.
  Vector<S> D(nab);
  for (int j = 0; j < inputs; ++j) {
    const int n = p.na[j], m = p.nb[j];
    for (int i = 0; i < n; ++i)
      D(p.a_offset[j] + i) = std::pow(p.sigma, S(i + 1));
    for (int k = 0; k < m; ++k)
      D(p.b_offset[j] + k) = std::pow(p.sigma, S(n - (m - 1 - k)));
  }
  // Start in scaled units.
  Vector<S> start;
  if (settings.theta_init.size() == nab) {
    start = settings.theta_init.cwiseQuotient(D);
    if (stabilise(p, start)) {
      return bad_input("the initial model must be stable");
    }
  }
  std::vector<S> delays;
  for (const FreqChannel<S>& c : channels) delays.push_back(c.delay);
  auto srivc_at = [&](S td, Vector<S>& theta, int& its, bool& conv,
                      S& cost) -> Status {
    theta = start;
    std::vector<S> t = delays;
    t[0] = td;  // (one input when the delay is estimated)
    return srivc_fixed(p, settings, t, theta, its, conv, cost);
  };

  Vector<S> theta;
  int iterations = 0;
  bool converged = false;
  S cost = 0;
  S td = delays[0];
  Status status;
  if (settings.estimate_delay) {
    // The search of delay_search.hpp: grid, then a fine scan and golden
    // section around each of the best local minima of the grid.
    DelaySearchSettings<S> search;
    search.grid = settings.grid;
    search.td_start = std::min(std::max(td, settings.td_min), settings.td_max);
    search.td_min = settings.td_min;
    search.td_max = settings.td_max;
    search.num_td = settings.num_td;
    search.refinement = DelayRefinement::kScanGolden;
    search.resolution = 1 / p.sigma;
    search.min_scan_step = S(1e-3) / p.sigma;
    auto fit = [&](S t, FreqFit<S>* f) {
      return srivc_at(t, f->theta, f->iterations, f->converged, f->loss);
    };
    FreqDelayModel<S, decltype(fit)> model(fit);
    DelaySearchOutcome<S, FreqFit<S>> out;
    status = delay_search(model, search, &out);
    if (!status.ok()) return status;
    td = out.best.td;
  }
  status = srivc_at(td, theta, iterations, converged, cost);
  if (!status.ok()) return status;
  std::string reason =
      converged ? "SRIVC converged" : "SRIVC: maximum number of iterations";

  if (settings.output_error) {
    // Output error on [a' b' (td')], td' = sigma td: the Levenberg-Marquardt
    // minimiser of the time-domain output error (output_error.hpp) on the
    // stacked real and imaginary parts of Y - G U.
    const int q = settings.estimate_delay ? nab + 1 : nab;
    Vector<S> x(q);
    x.head(nab) = theta;
    if (settings.estimate_delay) x(nab) = td * p.sigma;
    delays[0] = td;
    FreqOeModel<S> model(p, settings.estimate_delay, delays);
    Vector<S> target(2 * K);
    for (Eigen::Index k = 0; k < K; ++k) {
      target(k) = p.y[k].real();
      target(K + k) = p.y[k].imag();
    }
    OeSettings<S> lm_settings;
    lm_settings.max_iterations = settings.max_iterations;
    lm_settings.tolerance = settings.tolerance;
    LmBound<S> bound;
    if (settings.estimate_delay) {
      bound.index = nab;
      bound.lower = settings.td_min * p.sigma;
      bound.upper = settings.td_max * p.sigma;
    }
    LmOutcome<S> lm;
    status = levenberg_marquardt<S>(model, target, lm_settings, bound, &x, &lm);
    if (!status.ok()) return status;
    theta = x.head(nab);
    if (settings.estimate_delay) td = x(nab) / p.sigma;
    iterations = lm.iterations;
    converged = lm.converged;
    reason = "output error (Levenberg-Marquardt): " + lm.reason;
    cost = lm.cost;
  }

  // Covariance in scaled units, mapped back.
  Vector<S> r;
  Matrix<S> J;
  delays[0] = td;
  cost = residual(p, theta, delays, true, r, &J);
  const int q = settings.estimate_delay ? nab + 1 : nab;
  const Matrix<S> Jq = J.leftCols(q);
  const S dof = std::max(S(1), S(2 * K - q));
  const S s2 = r.squaredNorm() / dof;
  Vector<S> Dq(q);
  Dq.head(nab) = D;
  if (settings.estimate_delay) Dq(nab) = 1 / p.sigma;
  Eigen::ColPivHouseholderQR<Matrix<S>> qr(Jq.transpose() * Jq);
  Matrix<S> cov =
      Matrix<S>::Constant(q, q, std::numeric_limits<S>::quiet_NaN());
  if (qr.rank() == q) cov = s2 * qr.inverse();
  result->covariance = Dq.asDiagonal() * cov * Dq.asDiagonal();
  int na_total = 0;
  for (int j = 0; j < inputs; ++j) na_total += p.na[j];
  const Vector<S> ab = D.cwiseProduct(theta);
  result->a = ab.head(na_total);
  result->b = ab.tail(nab - na_total);
  result->delay = td;
  result->noise_variance = 2 * s2;
  result->loss = cost / static_cast<S>(K);
  result->iterations = iterations;
  result->converged = converged;
  result->stable = !stabilise(p, theta);
  result->reason = reason;
  if (!converged) return Status(ErrorCode::kNotConverged, reason);
  return Status::Ok();
}

}  // namespace ctid
