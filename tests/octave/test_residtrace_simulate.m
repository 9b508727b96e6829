## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn {} {} test_residtrace_simulate ()
## The core's effect-model simulator (core/include/ctid/simulation/effect_simulator.hpp,
## gateway effect_sim_mex, used by residtrace's private
## residtrace_simulate) against independent computations:
## @itemize
## @item exogenous channels only (two channels with their own delays and
## numerators): the control package's exact ZOH discretisation (c2d) and
## lsim, to 1e-9 relative;
## @item a discrete controller closing the loop u1 = r1 + C(q^-1)(r2 - y):
## the same c2d model stepped by hand with the controller's difference
## equation, to 1e-9 relative;
## @item per-sample coefficients held constant give the constant-model
## result exactly; a step change of the coefficients at sample k0 equals
## the constant-model simulation restarted from its state;
## @item a channel fed by the output itself, (y + y_off)^1 with numerator
## b: the linear model with F(p) - b and a constant input b y_off, which
## the sub-stepped loop approaches as the sub-steps shrink (error of order
## h: at least 5 times smaller from 10 to 100 sub-steps, below 1 % at 100);
## @item the gateway's other methods: the filtered derivatives p^i/F(p) x
## (ZOH and FOH) and the free responses against c2d and lsim, to 1e-9
## relative; bad arguments give identified errors.
## @end itemize
## @end deftypefn

function test_residtrace_simulate ()
  root = ctid_test_root ();
  pkg load control
  tmp = tempname ();
  mkdir (tmp);
  cleanup = onCleanup (@() remove_dir (tmp));
  copyfile (fullfile (root, "octave", "private", "effect_sim_mex.mex"), tmp);
  addpath (tmp);
  randn ("state", 7);
  N = 400; Ts = 0.05;
  u = randn (N, 2);
  F = [1 1.2 4];
  B1 = [0.5 4]; B2 = [-1];
  nk = [2 5];

  ## 1. exogenous channels vs c2d + lsim
  o = struct ("ts", Ts, "f", F(2:end), "b", [B1(:), [0; B2]],
              "kind", [0 0], "nk", nk, "param", [0 0], "substeps", 3);
  x = effect_sim_mex ("residtrace", u, o);
  ref = zeros (N, 1);
  Bs = {B1, B2};
  for j = 1:2
    G = c2d (tf (Bs{j}, F), Ts, "zoh");
    w = [zeros(nk(j), 1); u(1:end-nk(j), j)];
    ref += lsim (G, w, (0:N-1)' * Ts);
  endfor
  check ("exogenous channels vs c2d/lsim", x, ref, 1e-9);

  ## 2. closed loop with a discrete PI controller
  cn = [0.8 -0.6]; cd = [1 -1];
  r1 = 0.2 * randn (N, 1); r2 = sign (sin ((1:N)' / 30));
  o2 = struct ("ts", Ts, "f", F(2:end), "b", B1(:), "kind", 4, "nk", 1,
               "param", 0, "substeps", 1, "controller_num", cn,
               "controller_den", cd, "r1", r1, "r2", r2, "y_off", 0.3,
               "poly", [0 0]);
  [x2, u2] = effect_sim_mex ("residtrace", zeros (N, 1), o2);
  sys = ss (c2d (tf (B1, F), Ts, "zoh"));
  [A, Bd, C, D] = ssdata (sys);
  xs = zeros (rows (A), 1);
  e = zeros (2, 1); uc = 0; ua = zeros (N, 1); xr = zeros (N, 1);
  for k = 1:N
    xr(k) = C * xs;                           # D = 0 (strictly proper)
    e = [r2(k) - (xr(k) + 0.3); e(1)];
    uc = (cn * e - cd(2) * uc) / cd(1);
    ua(k) = r1(k) + uc;
    w = 0;
    if (k > 1)
      w = ua(k-1);                            # nk = 1
    endif
    xs = A * xs + Bd * w;
  endfor
  check ("closed loop vs c2d and the controller by hand", x2, xr, 1e-9);
  check ("closed loop applied input", u2, ua, 1e-9);

  ## 3. per-sample coefficients
  o3 = o;
  o3.f_t = repmat (F(2:end), N, 1);
  o3.b_t = repmat ([B1, 0, B2], N, 1);
  check ("constant per-sample coefficients", effect_sim_mex ("residtrace",
         u, o3), x, 1e-12);
  k0 = 200;
  F2 = [1 0.8 6];
  o3.f_t(k0+1:end, :) = repmat (F2(2:end), N - k0, 1);
  x3 = effect_sim_mex ("residtrace", u, o3);
  ## reference: both channels' state at k0 (observable form, the
  ## controllable state is not needed: compare with a step-by-step
  ## exact model whose A changes at k0)
  xr = zeros (N, 1);
  z = zeros (2, 1);
  for k = 1:N
    Fk = ifelse (k <= k0, F, F2);
    Ao = [-Fk(2:end)(:), [1; 0]];
    Bo = [B1(:), [0; B2]];
    E = expm ([Ao, Bo; zeros(2, 4)] * Ts);
    xr(k) = z(1);
    w = zeros (2, 1);
    for j = 1:2
      if (k - nk(j) >= 1)
        w(j) = u(k - nk(j), j);
      endif
    endfor
    z = E(1:2, 1:2) * z + E(1:2, 3:4) * w;
  endfor
  check ("coefficients changing at a sample", x3, xr, 1e-9);

  ## 4. the output fed back: (y + y_off)^1 through b
  b = 1.5; yoff = 0.4;
  o4 = struct ("ts", Ts, "f", F(2:end), "b", [B1(:), [0; b]],
               "kind", [0 3], "nk", [0 0], "param", [0 1], "y_off", yoff);
  Fl = F - [0 0 b];
  ref = lsim (c2d (tf (B1, Fl), Ts, "zoh"), u(:, 1), (0:N-1)' * Ts) ...
        + lsim (c2d (tf (b * yoff, Fl), Ts, "zoh"), ones (N, 1),
                (0:N-1)' * Ts);
  err = zeros (1, 2);
  subs = [10 100];
  for i = 1:2
    o4.substeps = subs(i);
    xi = effect_sim_mex ("residtrace", [u(:, 1), zeros(N, 1)], o4);
    err(i) = norm (xi - ref) / norm (ref);
  endfor
  printf ("output feedback: relative error %.3g (10 sub-steps), %.3g (100)\n",
          err);
  assert (err(2) < 0.01 && err(2) < err(1) / 5, ...
          "output feedback: errors %g, %g", err(1), err(2));

  ## 5. bad options give identified errors
  bad = o; bad.kind = [0 9];
  fails (@() effect_sim_mex ("residtrace", u, bad), "residtrace:badOption");
  bad = o; bad.kind = [4 0];
  fails (@() effect_sim_mex ("residtrace", u, bad), "residtrace:badInput");
  bad = o; bad.b = [1; 2];
  fails (@() effect_sim_mex ("residtrace", u, bad),
         "residtrace:dimensionMismatch");

  ## 6. the gateway's filtered derivatives and free responses
  ## (core/include/ctid/apps/residtrace/responses.hpp) against c2d/lsim:
  ## p^i / F(p) x for i < n, the signal held (ZOH) or linear (FOH, from 0
  ## at the first sample, where the filter is at rest); the free response
  ## from the unit initial condition h^(l)(0) = 1 by lsim from that state
  F3 = [1 3.5 6 4];
  t = (0:N-1)' * Ts;
  xs = u(:, 1);
  xs(1) = 0;
  for rule = {"zoh", "foh"}
    D = effect_sim_mex ("residtrace", "filter", xs, F3(2:end),
                        struct ("ts", Ts, "rule", rule{1}));
    for i = 0:2
      ref = lsim (c2d (tf ([1, zeros(1, i)], F3), Ts, rule{1}), xs, t);
      check (sprintf ("filter %s, p^%d / F", rule{1}, i), D(:, i+1), ref,
             1e-9);
    endfor
  endfor
  X = effect_sim_mex ("residtrace", "free", N, F(2:end), struct ("ts", Ts));
  A = [0 1; -F(3) -F(2)];
  for l = 1:2
    e = zeros (2, 1);
    e(l) = 1;
    ref = lsim (c2d (ss (A, [0; 1], [1 0], 0), Ts), zeros (N, 1), t, e);
    check (sprintf ("free response %d", l), X(:, l), ref, 1e-9);
  endfor
  fails (@() effect_sim_mex ("residtrace", "nomethod", u, o),
         "residtrace:badInput");
  fails (@() effect_sim_mex ("residtrace", "track", ones (5, 1), ones (5, 2),
                             ones (4, 2), [1 2], [0; 0], eye (2), eye (2),
                             struct ("free", 1, "r", 0, "k0", 1)),
         "residtrace:dimensionMismatch");
  fails (@() effect_sim_mex ("residtrace", "dmtest", ones (5, 1),
                             ones (4, 1), struct ()),
         "residtrace:dimensionMismatch");
  fails (@() effect_sim_mex ("residtrace", "ar", ones (5, 1),
                             struct ("pmax", -1)),
         "residtrace:badOption");
  printf ("test_residtrace_simulate: all checks passed\n");
endfunction

function check (what, a, b, tol)
  r = norm (a(:) - b(:)) / max (norm (b(:)), realmin);
  printf ("%-50s relative error %.3g (tolerance %g)\n", what, r, tol);
  assert (r < tol, "%s: relative error %g > %g", what, r, tol);
endfunction

function fails (f, id)
  try
    f ();
  catch err
    assert (strcmp (err.identifier, id), "expected %s, got %s (%s)", id,
            err.identifier, err.message);
    return;
  end_try_catch
  error ("expected the error %s", id);
endfunction

function v = ifelse (c, a, b)
  if (c)
    v = a;
  else
    v = b;
  endif
endfunction

function remove_dir (d)
  confirm_recursive_rmdir (false);
  rmdir (d, "s");
endfunction
