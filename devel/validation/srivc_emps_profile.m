## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn {} {} srivc_emps_profile (@var{rec})
## Is the mean-removed EMPS force -> position [2 3 0] fit of @code{srivc}
## (R_T^2 0.93) a local minimum of the simulation loss? Checked outside
## the engine: (1) Gauss-Newton steps from the returned model with
## finite-difference sensitivities of @code{simc} (parameters and the
## output offset c), printing the score statistic N e'P e / e'e and
## R_T^2 after each full or halved step; (2) the loss profiled along the
## slowest real pole p0, F = (p^2 + a1 p + a0)(p - p0), with a1 a0 by
## Gauss-Newton (at most 25 steps) and b, c by least squares. Not a test
## (a few minutes); run from the repository root:
## @example
## devel/run-study srivc_emps_profile
## @end example
## @var{rec}: @qcode{"DATA_EMPS.mat"} (default) or
## @qcode{"DATA_EMPS_PULSES.mat"}.
## @end deftypefn

function srivc_emps_profile (rec)
  if (nargin < 1)
    rec = "DATA_EMPS.mat";
  endif
  [data, why] = ctid_data_dir ("emps");
  if (isempty (data))
    error ("srivc_emps_profile:noData", "srivc_emps_profile: %s", why);
  endif
  s = load (fullfile (data, rec));
  Ts = s.t(2) - s.t(1);
  u = s.gtau * s.vir(:);
  y = s.qm(:);
  y -= mean (y);
  u -= mean (u);
  N = numel (y);
  vy = sumsq (y - mean (y));
  state = warning ("off", "all");
  cleanup = onCleanup (@() warning (state));
  [M, RT2, ~, ~, ~, info] = srivc (iddata (y, u, Ts, "InterSample", "zoh"),
                             [2 3 0]);
  printf ("%s [2 3 0]: RT2 %.5f converged %d: %s\n", rec, RT2,
          info.converged, info.reason);
  th = [M.F(2:end), M.B(end-1:end)];
  sim = @(t) simc (struct ("B", t(4:5), "F", [1 t(1:3)]), u, Ts,
                   "InterSample", "zoh");
  x = sim (th);
  for pass = 1:4
    e = y - x - mean (y - x);
    Psi = ones (N, 6);
    for i = 1:5
      h = 1e-6 * max (abs (th(i)), 1e-3);
      t2 = th;
      t2(i) += h;
      Psi(:, i) = (sim (t2) - x) / h;
    endfor
    sc = sqrt (sumsq (Psi));
    coef = (Psi ./ sc) \ e;
    fit = (Psi ./ sc) * coef;
    printf ("  RT2 %.5f score %.3g\n", 1 - sumsq (e) / vy,
            N * sumsq (fit) / sumsq (e));
    delta = coef(1:5)' ./ sc(1:5);
    beta = 1;
    for j = 1:10
      t2 = th + beta * delta;
      if (all (real (roots ([1 t2(1:3)])) < 0))
        x2 = sim (t2);
        if (sumsq (y - x2 - mean (y - x2)) < sumsq (e))
          break;
        endif
      endif
      beta /= 2;
    endfor
    if (j == 10)
      printf ("  no Gauss-Newton decrease\n");
      break;
    endif
    th = t2;
    x = x2;
  endfor
  r = roots ([1 M.F(2:end)]);
  [~, k] = min (abs (r));
  p0 = real (r(k));
  a = real (poly (r([1:k-1, k+1:end])))(2:3);
  for p0 = [p0 -0.5 -0.3 -0.15 -0.08 -0.04 -0.02 -0.01 -0.003]
    for it = 1:25
      res = resid (a, p0, u, y, Ts);
      J = zeros (N, 2);
      for i = 1:2
        h = 1e-6 * max (abs (a(i)), 1e-3);
        a2 = a;
        a2(i) += h;
        J(:, i) = (resid (a2, p0, u, y, Ts) - res) / h;
      endfor
      d = -(J \ res)';
      beta = 1;
      ok = false;
      for j = 1:12
        a2 = a + beta * d;
        if (all (a2 > 0))
          if (sumsq (resid (a2, p0, u, y, Ts)) < sumsq (res))
            ok = true;
            break;
          endif
        endif
        beta /= 2;
      endfor
      if (! ok)
        break;
      endif
      a = a2;
    endfor
    res = resid (a, p0, u, y, Ts);
    printf ("  p0 %8.4f a1 %.4f a0 %.4f RT2 %.5f (%d steps)\n", p0, a(1),
            a(2), 1 - sumsq (res) / vy, it);
  endfor
endfunction

function r = resid (a, p0, u, y, Ts)
  F = conv ([1 a], [1 -p0]);
  X = [simc(struct ("B", [1 0], "F", F), u, Ts, "InterSample", "zoh"), ...
       simc(struct ("B", 1, "F", F), u, Ts, "InterSample", "zoh"), ...
       ones(numel (y), 1)];
  r = y - X * (X \ y);
endfunction
