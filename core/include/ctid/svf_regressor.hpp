// The filtered linear regression of the SVF methods, eqs. (1.24)-(1.27):
//
//   y_f^(na)(t_k) = phi_f^T(t_k) theta + v_f(t_k)
//   phi_f = [-y_f^(na-1) .. -y_f, u_1f^(nb_1-1) .. u_1f, u_2f^(nb_2-1) ..]
//
// built sample by sample from the filter channels of each signal. The input
// is filtered with the data's InterSample rule; the output, never piecewise
// constant, with the trapezoidal rule by default (Suggested procedure 3.3;
// see shared/implementation-notes.md, note 1).
#pragma once

#include <vector>

#include "ctid/delay_line.hpp"
#include "ctid/model.hpp"
#include "ctid/svf.hpp"

namespace ctid {

template <typename S>
struct SvfSettings {
  S lambda_svf = 1;
  bool normalised = true;  // (lambda/(p+lambda))^na, eq. (3.1)
  InterSample u_intersample = InterSample::kZoh;
  InterSample y_intersample = InterSample::kFoh;
};

template <typename S>
Status validate_svf_settings(const SvfSettings<S>& svf) {
  if (!(svf.lambda_svf > 0) || !std::isfinite(svf.lambda_svf)) {
    return bad_input("lambda_svf must be finite and > 0");
  }
  return Status::Ok();
}

template <typename S>
class SvfRegressor {
 public:
  SvfRegressor() = default;

  void configure(const ModelOrders& orders, const SvfSettings<S>& svf) {
    orders_ = orders;
    const int na = orders.na;
    const Vector<S> d = svf_denominator<S>(na, svf.lambda_svf);
    gain_ = svf_gain<S>(na, svf.lambda_svf, svf.normalised);
    y_disc_.configure(na, svf.y_intersample);
    y_disc_.set_denominator(d);
    u_disc_.configure(na, svf.u_intersample);
    u_disc_.set_denominator(d);
    y_channel_.configure(na);
    u_channels_.resize(orders.num_inputs());
    delays_.resize(orders.num_inputs());
    for (int j = 0; j < orders.num_inputs(); ++j) {
      u_channels_[j].configure(na);
      delays_[j].configure(orders.nk[j]);
    }
    phi_ = Vector<S>::Zero(orders.num_parameters());
    target_ = 0;
  }

  void reset() {
    y_channel_.reset();
    for (auto& c : u_channels_) c.reset();
    for (auto& d : delays_) d.reset();
  }

  // Feeds u(t_k) (num_inputs values) and y(t_k); h = t_k - t_(k-1).
  void step(const S* u, S y, S h) {
    const int na = orders_.na;
    y_disc_.ensure(h);
    u_disc_.ensure(h);
    y_channel_.step(y_disc_, gain_, y);
    const Vector<S>& yf = y_channel_.outputs();
    for (int i = 0; i < na; ++i) phi_(i) = -yf(na - 1 - i);
    target_ = yf(na);
    int offset = na;
    for (int j = 0; j < orders_.num_inputs(); ++j) {
      u_channels_[j].step(u_disc_, gain_, delays_[j].push(u[j]));
      const Vector<S>& uf = u_channels_[j].outputs();
      const int nb = orders_.nb[j];
      for (int l = 0; l < nb; ++l) phi_(offset + l) = uf(nb - 1 - l);
      offset += nb;
    }
  }

  const Vector<S>& phi() const { return phi_; }
  S target() const { return target_; }
  const ModelOrders& orders() const { return orders_; }

 private:
  ModelOrders orders_;
  FilterDiscretization<S> y_disc_;
  FilterDiscretization<S> u_disc_;
  FilterChannel<S> y_channel_;
  std::vector<FilterChannel<S>> u_channels_;
  S gain_ = 1;
  std::vector<DelayLine<S>> delays_;
  Vector<S> phi_;
  S target_ = 0;
};

}  // namespace ctid
