// SPDX-License-Identifier: BSD-3-Clause
// Copyright (C) the ctid authors
// Continuous-time model structure of the thesis, eqs. (1.2)-(1.3), (1.28)
// and (2.22), in the CONTSID ordering:
//
//   A(p) x = sum_j B_j(p) u_j(t - nk_j Ts)
//   A(p)   = p^na + a1 p^(na-1) + ... + a_na
//   B_j(p) = b_j,0 p^(nb_j-1) + ... + b_j,(nb_j-1)
//
// theta = [a1 .. a_na, b_1,0 .. b_1,(nb_1-1), b_2,0 .. ] (one block per
// input). `nb_j` counts numerator parameters, so nb_j = 1 is a single gain;
// the model is proper when nb_j <= na + 1.
#pragma once

#include <string>
#include <vector>

#include "ctid/base/status.hpp"
#include "ctid/base/types.hpp"

namespace ctid {

struct ModelOrders {
  int na = 0;
  std::vector<int> nb;  // numerator parameters, one entry per input
  std::vector<int> nk;  // input delay in samples, one entry per input

  int num_inputs() const { return static_cast<int>(nb.size()); }
  int num_parameters() const {
    int n = na;
    for (int v : nb) n += v;
    return n;
  }
  // Index in theta of b_j,0.
  int numerator_offset(int input) const {
    int offset = na;
    for (int j = 0; j < input; ++j) offset += nb[j];
    return offset;
  }
  int max_delay() const {
    int d = 0;
    for (int v : nk) d = v > d ? v : d;
    return d;
  }
};

inline ModelOrders siso_orders(int na, int nb, int nk) {
  ModelOrders orders;
  orders.na = na;
  orders.nb = {nb};
  orders.nk = {nk};
  return orders;
}

// Orders accepted by every estimator: na >= 1, 0 <= nb_j <= na + 1 with at
// least one numerator parameter in all, nk_j >= 0.
inline Status validate_orders(const ModelOrders& orders) {
  if (orders.na < 1) {
    return bad_input("na must be an integer >= 1, got " +
                     std::to_string(orders.na));
  }
  if (orders.nb.empty()) {
    return bad_input("nb must have one entry per input");
  }
  if (orders.nk.size() != orders.nb.size()) {
    return dimension_mismatch("nk must have one entry per input (" +
                              std::to_string(orders.nb.size()) + "), got " +
                              std::to_string(orders.nk.size()));
  }
  int total_nb = 0;
  for (std::size_t j = 0; j < orders.nb.size(); ++j) {
    if (orders.nb[j] < 0) {
      return bad_input("nb must be >= 0, got " + std::to_string(orders.nb[j]));
    }
    if (orders.nb[j] > orders.na + 1) {
      return bad_input("nb = " + std::to_string(orders.nb[j]) +
                       " gives an improper model: nb must be <= na + 1 = " +
                       std::to_string(orders.na + 1));
    }
    if (orders.nk[j] < 0) {
      return bad_input("nk must be >= 0, got " + std::to_string(orders.nk[j]));
    }
    total_nb += orders.nb[j];
  }
  if (total_nb == 0) {
    return bad_input("the model needs at least one numerator parameter");
  }
  return Status::Ok();
}

// Monic denominator coefficients [a1 .. a_na] of theta.
template <typename S>
Vector<S> denominator_of(const ModelOrders& orders, const Vector<S>& theta) {
  return theta.head(orders.na);
}

// Numerator coefficients [b_j,0 .. b_j,(nb_j-1)] (descending powers of p).
template <typename S>
Vector<S> numerator_of(const ModelOrders& orders, const Vector<S>& theta,
                       int input) {
  return theta.segment(orders.numerator_offset(input), orders.nb[input]);
}

// State-space form of the frozen model of input j, controllable canonical:
//   w' = F w + G u_j,  x = H w + J u_j,  w = [w, w', .., w^(na-1)],
// with F the companion matrix of A(p) and x = B_j(p) w (the highest
// derivative, present when nb_j = na + 1, gives the feedthrough J).
template <typename S>
struct StateSpace {
  Matrix<S> F, G, H, J;
};

template <typename S>
StateSpace<S> to_state_space(const ModelOrders& orders, const Vector<S>& theta,
                             int input) {
  const int na = orders.na;
  StateSpace<S> ss;
  ss.F = Matrix<S>::Zero(na, na);
  for (int i = 0; i + 1 < na; ++i) ss.F(i, i + 1) = 1;
  for (int c = 0; c < na; ++c) ss.F(na - 1, c) = -theta(na - 1 - c);
  ss.G = Matrix<S>::Zero(na, 1);
  ss.G(na - 1, 0) = 1;
  ss.H = Matrix<S>::Zero(1, na);
  ss.J = Matrix<S>::Zero(1, 1);
  const int nb = orders.nb[input];
  const int offset = orders.numerator_offset(input);
  for (int l = 0; l < nb; ++l) {
    const int derivative = nb - 1 - l;
    const S b = theta(offset + l);
    if (derivative < na) {
      ss.H(0, derivative) += b;
    } else {  // w^(na) = u - sum a_i w^(na-i)
      ss.J(0, 0) += b;
      ss.H += b * ss.F.row(na - 1);
    }
  }
  return ss;
}

}  // namespace ctid
