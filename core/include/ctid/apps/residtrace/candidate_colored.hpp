// SPDX-License-Identifier: BSD-3-Clause
// Copyright (C) the ctid authors

// The coloured-noise candidate of residtrace (candidate.hpp): an AR noise
// model A(q) e = eps of the current model's estimation residual e (its
// mean removed), of the order p <= min(20, N / 20) with the smallest BIC,
// fitted by least squares (statistics.hpp, ar_whitener). A noise model
// does not change the simulated output: its validation output is the
// one-step-ahead prediction of y (the model output plus the residual
// predicted from the past validation residuals), so its kind is
// "prediction", and it ranks after every significant deterministic
// effect. Evidence: the AR order and its dominant pole (the root of A of
// the largest modulus), the lag-1 autocorrelation of the residual.
#pragma once

#include <complex>
#include <limits>
#include <string>
#include <vector>

#include "ctid/apps/residtrace/candidate.hpp"
#include "ctid/apps/residtrace/model_fit.hpp"
#include "ctid/apps/residtrace/statistics.hpp"
#include "ctid/base/status.hpp"

namespace ctid::residtrace {

// The coloured-noise candidate (head of this file).
template <typename S>
Status colored_candidate(const ResidtraceModel<S>& cur,
                         const CandidateContext<S>& ctx, Candidate<S>* c) {
  using candidate_detail::num;
  if (c == nullptr) return bad_input("no result");
  *c = Candidate<S>();
  c->effect = "colored_noise";
  c->kind = "prediction";
  const Eigen::Index N = cur.estimate.e.size();
  if (N != ctx.D.y.size()) {
    return bad_input(
        "the model's estimation residual needs one value a sample of the "
        "record");
  }
  const Vector<S> e = cur.estimate.e.array() - cur.estimate.e.mean();
  const int pmax = static_cast<int>(std::min<Eigen::Index>(20, N / 20));
  if (pmax < 1) {
    c->reason = "too few samples for a noise model";
    return Status::Ok();
  }
  const Vector<S> a = ar_whitener<S>(e, pmax);
  const int p = static_cast<int>(a.size()) - 1;
  if (p == 0) {
    c->reason = "an AR model does not improve on white noise (BIC)";
    return Status::Ok();
  }
  c->applicable = true;
  c->has_model = true;
  c->model = cur;
  c->model.noise = a;
  c->variant = "AR(" + std::to_string(p) + ")";
  c->nadd = p;
  const S r1 = e.tail(N - 1).dot(e.head(N - 1)) / e.squaredNorm();
  // the dominant pole: a root of the largest modulus, of a complex pair
  // the one with the positive imaginary part (the one LAPACK lists first)
  const std::vector<std::complex<S>> z = roots_descending<S>(a);
  std::size_t i = 0;
  for (std::size_t k = 1; k < z.size(); ++k) {
    if (std::abs(z[k]) > std::abs(z[i])) i = k;
  }
  std::complex<S> pole = z.empty() ? std::complex<S>(0) : z[i];
  if (pole.imag() < 0) pole = std::conj(pole);
  c->evidence.add("term", "AR order");
  c->evidence.add("value", static_cast<S>(p));
  c->evidence.add("std", std::numeric_limits<S>::quiet_NaN());
  c->evidence.add("rho1", r1);
  EvidenceField<S> f;
  f.name = "pole";
  f.value = Vector<S>::Constant(1, pole.real());
  if (pole.imag() != 0) f.imag = Vector<S>::Constant(1, pole.imag());
  c->evidence.fields.push_back(f);
  // the pole as Octave's num2str (z, 3) writes it
  const std::string pole_text =
      pole.imag() != 0
          ? num("%.3g", pole.real()) + num("%-+.3g", pole.imag()) + "i"
          : num("%.3g", pole.real());
  c->evidence.text = "AR(" + std::to_string(p) +
                     ") noise model, dominant pole " + pole_text +
                     ", lag-1 autocorrelation " + num("%.2f", r1);
  c->evidence.add("text", c->evidence.text);
  return Status::Ok();
}

}  // namespace ctid::residtrace
