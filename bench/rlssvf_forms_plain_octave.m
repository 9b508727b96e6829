## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn {} {@var{thm} =} rlssvf_forms_plain_octave (@var{y}, @var{u}, @var{Ts}, @var{lambda_svf}, @var{na}, @var{form}, @var{param})
## RLSSVF in its square-root (PotterSVF) or regularised (LMR-RLSSVF) form
## written in plain Octave: the baseline a user would write without the
## toolbox, used by bench/adaptation_kernels_octave_bench.m.
##
## Model nn = [@var{na} 1 0]: x = b0 / (p^na + a1 p^(na-1) + .. + a_na) u with
## uniformly sampled data, u held between samples (ZOH); theta and the
## columns of @var{thm} (N-by-(na+1)) are [a1 .. a_na b0], as
## @code{rlssvf}. The regressors of the normalised SVF
## (lambda/(p + lambda))^na (eq. 3.1) are computed for the whole record at
## once with @code{filter} (u by exact ZOH, y by the trapezoidal rule, as
## the core), then one parameter update per sample from theta = 0,
## P = 1e4 I:
##
## @table @asis
## @item @var{form} = "potter", @var{param} = Qn (positive definite)
## PotterSVF, eq. (3.73): time update by a QR of [S^T; Qn^(T/2)], then
## f = S^T phi, beta = 1 + f^T f, alpha = beta + sqrt (beta),
## L = S f / beta, S = S - (S f) f^T / alpha.
## @item @var{form} = "lmr", @var{param} = [lambda, gamma]
## LMR-RLSSVF, eq. (3.82), in information form:
## R = lambda R + phi phi^T + (1 - lambda) gamma I,
## theta = theta + R \ phi (target - phi^T theta).
## @end table
##
## The same estimates as
## @code{rlssvf (data, [na 1 0], "lambda_svf", lambda_svf, "adm", "kf",
## "adg", Qn, "potter", true)} and @code{rlssvf (..., "adm", "lmr", "adg",
## lambda, "Gamma", gamma * eye (na + 1))} to rounding.
## @end deftypefn

function thm = rlssvf_forms_plain_octave (y, u, Ts, lambda_svf, na, form,
                                          param)
  y = y(:);
  u = u(:);
  N = numel (y);
  np = na + 1;
  ## Regressors phi = [-y_f^(na-1) .. -y_f, u_f], target y_f^(na).
  d_svf = poly (-lambda_svf * ones (1, na));
  g_svf = lambda_svf ^ na;
  yf = zeros (N, na + 1);                             # [y_f .. y_f^(na)]
  for i = 0:na
    [bq, aq] = tustin ([g_svf, zeros(1, i)], d_svf, Ts);
    yf(:, i + 1) = filter (bq, aq, y);
  endfor
  F = [zeros(na - 1, 1), eye(na - 1); -d_svf(end:-1:2)];
  E = expm ([F, [zeros(na - 1, 1); 1]; zeros(1, na + 1)] * Ts);
  Phi = E(1:na, 1:na);
  Gam = E(1:na, na + 1);
  den_q = poly (Phi);
  num_q = poly (Phi - Gam * [g_svf, zeros(1, na - 1)]) - den_q;
  uf = filter (num_q, den_q, u);
  phi_all = [-yf(:, na:-1:1), uf];
  target = yf(:, na + 1);

  theta = zeros (np, 1);
  thm = zeros (N, np);
  if (strcmp (form, "potter"))
    Qn = param;
    Qroot = chol (Qn).';                              # Qn = Qroot Qroot^T
    S = 100 * eye (np);                               # P = S S^T = 1e4 I
    for k = 1:N
      [~, R] = qr ([S.'; Qroot.'], 0);
      S = R.';
      ph = phi_all(k, :).';
      f = S.' * ph;
      beta = 1 + f.' * f;
      alpha = beta + sqrt (beta);
      Sf = S * f;
      theta = theta + Sf / beta * (target(k) - ph.' * theta);
      S = S - Sf * (f.' / alpha);
      thm(k, :) = theta.';
    endfor
  else
    lambda = param(1);
    gamma = param(2);
    R = 1e-4 * eye (np);
    reg = (1 - lambda) * gamma * eye (np);
    for k = 1:N
      ph = phi_all(k, :).';
      R = lambda * R + ph * ph.' + reg;
      theta = theta + (R \ ph) * (target(k) - ph.' * theta);
      thm(k, :) = theta.';
    endfor
  endif
endfunction

## Trapezoidal rule (Tustin) of b(p)/a(p), descending powers of p; [bq, aq]
## in powers of q^-1 (as in rsrivc_plain_octave.m).
function [bq, aq] = tustin (b, a, h)
  n = numel (a) - 1;
  b = [zeros(1, n + 1 - numel (b)), b];
  bq = zeros (1, n + 1);
  aq = zeros (1, n + 1);
  for j = 0:n
    t = (2 / h) ^ j * conv (poly (ones (1, j)), poly (-ones (1, n - j)));
    bq += b(n + 1 - j) * t;
    aq += a(n + 1 - j) * t;
  endfor
  bq /= aq(1);
  aq /= aq(1);
endfunction
