## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn {} {} test_frozen_model_kernels ()
## YH of @code{[thm, yh] = rlssvf (...)} and of
## @code{[thm, yh] = rsrivc (...)} (the frozen model's output,
## eq. 1.60) on the fixed-size path (the series of CompanionZohAdvance,
## companion_kernels.hpp) against the gateway's dynamic-size reference
## (option kernels = "dynamic": a matrix exponential per sample) and against
## a plain-Octave simulation of the frozen models from THM (expm of the
## augmented matrix per sample), na = 1..4: one input on a record with a
## gap (irregular intervals), two inputs (one delayed) uniformly sampled;
## RSRIVC (riv_mex, the same FrozenModel behind the IV estimators) on the
## one-input record with the gap.
## Errors on the first failure:
## @example
## octave --no-gui -q --eval \
##   "addpath octave tests/octave; test_frozen_model_kernels"
## @end example
## The private folder (the gateway) is put on the path for the duration of
## the test.
## @end deftypefn

function test_frozen_model_kernels ()
  root = fileparts (fileparts (fileparts (mfilename ("fullpath"))));
  private_dir = fullfile (root, "octave", "private");
  addpath (private_dir);
  cleanup = onCleanup (@() rmpath (private_dir));
  rand ("state", 14);
  randn ("state", 14);
  Ts = 0.1;
  A = {2, [2.4 4], [3 7 5], [3.2 8.4 10.4 8]};
  N = 1500;
  for na = 1:4
    for nu = 1:2
      u = 2 * mod (cumsum (rand (N, nu) < 0.1), 2) - 1;
      t = Ts * (1:N).';
      nb = [na, 1](1:nu);
      nk = [0, 2](1:nu);
      if (nu == 1)
        t(800:end) += 0.35;  # a gap: one interval of 0.45 s
        time_arg = t;
      else
        time_arg = Ts;  # (a delay needs uniform sampling)
      endif
      ## the true system: A(p) y = a_na u_1 (+ 0.5 a_na u_2 delayed)
      theta = [A{na}, zeros(1, na - 1), A{na}, 0.5 * A{na}];
      theta = theta(1:na + sum (nb));
      y = frozen_model_output (repmat (theta, N, 1), u, t, na, nb, nk);
      y += 0.02 * randn (N, 1);
      p = contsid_rlssvf_args ("rlssvf", y, u, time_arg, [na nb nk],
                               "lambda_svf", 3, "adm", "kf",
                               "adg", 1e-4 * eye (na + sum (nb)));
      opts = p.opts;
      opts.kernels = "fixed";
      [thm, yh] = rlssvf_mex ("rlssvf", p.data{:}, opts);
      opts.kernels = "dynamic";
      [thm_d, yh_d] = rlssvf_mex ("rlssvf", p.data{:}, opts);
      what = sprintf ("na = %d, nu = %d", na, nu);
      ## THM on the two paths (the SVF kernels, not this test's subject):
      ## after the settling window, as tests/core/companion_kernels_test.cpp
      ## (there P0 = 1e4 I amplifies the rounding of the regressors)
      assert (thm(201:end, :), thm_d(201:end, :),
              1e-12 * max (abs (thm_d(:))));
      ## YH against plain Octave, each path on its own THM, every sample
      yo = frozen_model_output (thm, u, t, na, nb, nk);
      e_plain = max (abs (yh - yo)) / max (abs (yo));
      assert (e_plain <= 1e-12, "%s: yh vs plain Octave %.1e", what, e_plain);
      yo_d = frozen_model_output (thm_d, u, t, na, nb, nk);
      e_plain_d = max (abs (yh_d - yo_d)) / max (abs (yo_d));
      ## YH fixed vs dynamic once the THM agree (the frozen model forgets
      ## the settling window's differences as fast as its slowest pole)
      e_dyn = max (abs (yh(401:end) - yh_d(401:end))) / max (abs (yh_d));
      assert (e_dyn <= 1e-12, "%s: yh fixed vs dynamic %.1e", what, e_dyn);
      printf (["%s: |yh - plain Octave| %.1e (dynamic path: %.1e), ", ...
               "|yh - dynamic| %.1e\n"], what, e_plain, e_plain_d, e_dyn);
      if (nu == 1)
        check_rsrivc (y, u, t, na, [theta(1:na), theta(end)]);
      endif
    endfor
  endfor
endfunction

## RSRIVC through riv_mex: YH on each path against plain Octave on that
## path's THM, and the paths against each other after tsiv's settling.
function check_rsrivc (y, u, t, na, theta)
  p = contsid_riv_args ("rsrivc", "rsrivc", y, u, t, [1 na 0],
                        "lambda_svf", 3, "adm", "kf",
                        "adg", 1e-4 * eye (na + 1), "tsiv", 20);
  opts = p.opts;
  opts.kernels = "fixed";
  [thm, yh] = riv_mex ("rsrivc", p.data{:}, opts);
  opts.kernels = "dynamic";
  [thm_d, yh_d] = riv_mex ("rsrivc", p.data{:}, opts);
  what = sprintf ("rsrivc na = %d", na);
  ## the estimates track the true system (the record is informative)
  assert (thm(end, :), theta, 0.05 * max (abs (theta)));
  yo = frozen_model_output (thm, u, t, na, 1, 0);
  e_plain = max (abs (yh - yo)) / max (abs (yo));
  assert (e_plain <= 1e-12, "%s: yh vs plain Octave %.1e", what, e_plain);
  yo_d = frozen_model_output (thm_d, u, t, na, 1, 0);
  e_plain_d = max (abs (yh_d - yo_d)) / max (abs (yo_d));
  assert (e_plain_d <= 1e-12, "%s: dynamic yh vs plain Octave %.1e", what,
          e_plain_d);
  late = t >= t(1) + 40;  # 20 s after tsiv
  e_dyn = max (abs (yh(late) - yh_d(late))) / max (abs (yh_d));
  assert (e_dyn <= 1e-12, "%s: yh fixed vs dynamic %.1e", what, e_dyn);
  printf (["%s: |yh - plain Octave| %.1e (dynamic path: %.1e), ", ...
           "|yh - dynamic| %.1e\n"], what, e_plain, e_plain_d, e_dyn);
endfunction

## x(t_k) of the frozen model theta(t_k) advanced over (t_(k-1), t_k] from
## the state of the previous sample, input held (ZOH); at rest at t_1.
function yo = frozen_model_output (thm, u, t, na, nb, nk)
  [N, nu] = size (u);
  Z = zeros (na, nu);
  prev = zeros (1, nu);
  yo = zeros (N, 1);
  ud = u;
  for j = 1:nu
    ud(:, j) = [zeros(nk(j), 1); u(1:end-nk(j), j)];
  endfor
  for k = 1:N
    d = thm(k, 1:na);
    F = [zeros(na - 1, 1), eye(na - 1); -fliplr(d)];
    if (k > 1)
      E = expm ([F, [zeros(na - 1, 1); 1]; zeros(1, na + 1)] * (t(k) - t(k-1)));
      Z = E(1:na, 1:na) * Z + E(1:na, end) * prev;
    endif
    prev = ud(k, :);
    offset = na;
    for j = 1:nu
      w = [Z(:, j); prev(j) - fliplr(d) * Z(:, j)];
      b = thm(k, offset + (1:nb(j)));
      yo(k) += b * w(nb(j):-1:1);
      offset += nb(j);
    endfor
  endfor
endfunction
