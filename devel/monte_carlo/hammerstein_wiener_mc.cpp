// SPDX-License-Identifier: BSD-3-Clause
// Copyright (C) the ctid authors
// Monte Carlo of HWSRIVC's reported standard deviations on the core
// directly (faster than devel/monte_carlo/hammerstein_mc.m on a loaded machine): the
// system of that script (CONTSID's Hammerstein-Wiener demo, f = u - 2u^2 +
// 0.8u^3, G = 1/(s + 2), g = x + 1.5x^2 + x^3, Ts = 5 ms, N = 5000, noise
// sd 0.03), other random numbers. Prints spread / mean reported sd and
// bias / spread per parameter [f b alpha2 alpha3 beta2 beta3].
// Build and run from the repository root:
//   g++ -O2 -std=c++17 -Icore/include -I/usr/include/eigen3 \
//     devel/monte_carlo/hammerstein_wiener_mc.cpp -o /tmp/hwmc && /tmp/hwmc 80
#include <cstdio>
#include <cstdlib>
#include <random>

#include "ctid/offline/hammerstein.hpp"
using namespace ctid;
int main(int argc, char** argv) {
  const int runs = argc > 1 ? std::atoi(argv[1]) : 80;
  const int N = 5000;
  const double Ts = 5e-3;
  std::mt19937 gen(1);
  std::uniform_real_distribution<double> U(-1, 1);
  Vector<double> u(N);
  {
    double v = 0;
    for (int k = 0; k < N; ++k) {
      if (k % 400 == 0) v = 0.5 * U(gen);
      u(k) = v;
    }
  }
  Matrix<double> W(N, 3);
  W << u, u.array().square().matrix(), u.array().cube().matrix();
  Vector<double> ubar = u - 2 * W.col(1) + 0.8 * W.col(2);
  Vector<double> f(1);
  f << 2;
  Vector<double> b(1);
  b << 1;
  RivData<double> data;
  data.num_samples = N;
  data.ts = Ts;
  Vector<double> y0(N);
  data.y = y0.data();
  data.w = u.data();
  Vector<double> xbar;
  block_detail::simulate_linear<double>(f, b, 0, InterSample::kZoh, ubar, data,
                                        xbar);
  Vector<double> x = xbar;
  for (int it = 0; it < 60; ++it)
    x.array() -= (x.array() + 1.5 * x.array().square() + x.array().cube() -
                  xbar.array()) /
                 (1 + 3 * x.array() + 3 * x.array().square());
  Vector<double> truth(6);
  truth << 2, 1, -2, 0.8, 1.5, 1;
  Matrix<double> th(6, runs), sd(6, runs);
  std::normal_distribution<double> G(0, 1);
  for (int r = 0; r < runs; ++r) {
    std::mt19937 g2(100 + r);
    Vector<double> y = x;
    for (int k = 0; k < N; ++k) y(k) += 0.03 * G(g2);
    data.y = y.data();
    data.w = W.data();
    BlockOrders o;
    o.nb = 1;
    o.nf = 1;
    o.nw = 3;
    BlockSettings<double> s;
    s.max_iterations = 100;
    BlockResult<double> res;

    Status st =
        block_srivc(BlockModel::kHammersteinWiener, o, s, data, 3, &res);
    Vector<double> sep(6);
    sep << res.f, res.b, res.alpha.tail(2), res.beta.tail(2);
    th.col(r) = sep;
    sd.col(r) = res.covariance.diagonal().cwiseSqrt();
    if (!st.ok()) printf("run %d: status %d\n", r, (int)st.code());
  }
  Vector<double> mean = th.rowwise().mean();
  printf("ratio spread/sd:");
  for (int i = 0; i < 6; ++i) {
    double v = (th.row(i).array() - mean(i)).square().sum() / (runs - 1);
    printf(" %.3f", std::sqrt(v) / sd.row(i).mean());
  }
  printf("\nbias/spread:");
  for (int i = 0; i < 6; ++i) {
    double v = (th.row(i).array() - mean(i)).square().sum() / (runs - 1);
    printf(" %.2f", (mean(i) - truth(i)) / std::sqrt(v));
  }
  printf("\n");
}
