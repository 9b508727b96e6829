## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn {} {@var{thm} =} rsrivc_plain_octave (@var{y}, @var{u}, @var{Ts}, @var{lambda_svf}, @var{Qn}, @var{tsiv})
## RSRIVC with the IV Kalman filter written in plain Octave: the baseline a
## user would write without the toolbox, used by bench/rsrivc_octave_bench.m
## to measure what the compiled @code{rsrivc} front-end buys.
##
## Model nn = [1 na 0]: x = b0 / (p^na + f1 p^(na-1) + .. + f_na) u,
## y = x + noise, with uniformly sampled data, u held constant between
## samples (ZOH); na = rows (@var{Qn}) - 1 (the benchmark runs na = 1..4;
## na = 2, nn = [1 2 0], is the case described below). @var{Qn} is the
## (na+1)-by-(na+1) normalised covariance of the random walk of the
## parameters and @var{thm} (N-by-(na+1)) is ordered [b0 f1 .. f_na], as
## @code{rsrivc}. The same algorithm as the core
## (core/include/ctid/recursive_iv.hpp) and so as
##
##   rsrivc (iddata (y, u, Ts, "InterSample", "zoh"), [1 na 0],
##           "lambda_svf", lambda_svf, "adm", "kf", "adg", Qn, "tsiv", tsiv)
##
## with the defaults th0 = 0, P0 = 1e4 I, dtupdate = Ts, M_theta = q^-1,
## stability "keep" and the unit-static-gain prefilter:
##
## @enumerate
## @item While t - t_1 < tsiv: RLSSVF-KF (thesis eqs. 1.24-1.27, 1.59) with
## the normalised SVF (lambda/(p + lambda))^2 (eq. 3.1); u filtered by exact
## ZOH (Appendix A.1, expm of the augmented matrix), y by the trapezoidal
## rule (Appendix A.2). The SVF does not change, so these regressors are
## computed for the whole record at once with @code{filter}.
## @item From t - t_1 >= tsiv: the IV Kalman filter (eq. 2.29) with the
## regressor phi = [u_f, -y_f', -y_f] and the instrument zeta = [u_f,
## -x_f', -x_f] (eqs. 2.17-2.20), where x_hat = b0/A(p) u is the auxiliary
## model and the subscript f the adaptive prefilter f2/A(p) (unit static
## gain), A(p) = p^2 + f1 p + f2: y and x_hat by the trapezoidal rule, u by
## ZOH.
## @item The auxiliary model and the prefilter run from the first sample.
## At every sample (dtupdate = Ts) they are refreshed with the estimate of
## the previous sample (M_theta = q^-1, sec. 3.2.3) if its A(p) is stable
## (eq. 3.10); otherwise the last stable estimate is kept. They start from
## A(p) = (p + lambda_svf)^2 and a zero numerator. Both change at every
## sample, so their discretisation (a matrix exponential for ZOH, a 2-by-2
## solve for the trapezoidal rule) is redone at every sample; their states
## [w, w'] (A(p) w = input) carry over the change of coefficients.
## @end enumerate
## @end deftypefn

function thm = rsrivc_plain_octave (y, u, Ts, lambda_svf, Qn, tsiv)
  y = y(:);
  u = u(:);
  N = numel (y);
  nb = 1;                     # numerator parameters [b0]
  na = rows (Qn) - 1;         # denominator parameters [f1 .. f_na]
  np = nb + na;
  if (numel (u) != N || na < 1 || ! isequal (size (Qn), [np np]))
    error ("rsrivc_plain_octave: y, u must have N samples and Qn be square, at least 2-by-2");
  endif

  ## 1. RLSSVF regressors over the whole record: phi_ls = [u_f,
  ## -y_f^(na-1) .. -y_f], target y_f^(na) with the fixed SVF
  ## lambda^na / (p + lambda)^na.
  d_svf = poly (-lambda_svf * ones (1, na));          # [1 2*lambda lambda^2]
  g_svf = lambda_svf ^ na;
  yf_svf = zeros (N, na + 1);                         # [y_f .. y_f^(na)]
  for i = 0:na
    [bq, aq] = tustin ([g_svf, zeros(1, i)], d_svf, Ts);  # g p^i / D(p)
    yf_svf(:, i + 1) = filter (bq, aq, y);
  endfor
  [Phi, Gam] = zoh (companion (d_svf(2:end)), Ts);
  den_q = poly (Phi);
  c_svf = [g_svf, zeros(1, na - 1)];
  num_q = poly (Phi - Gam * c_svf) - den_q;           # g e1' (qI - Phi)^-1 Gam
  uf_svf = filter (num_q, den_q, u);                  # u_f
  phi_ls = [uf_svf, -yf_svf(:, na:-1:1)];
  target_ls = yf_svf(:, na + 1);

  ## 2.-3. The recursion.
  theta = zeros (np, 1);      # [b0; f1; ..; f_na]
  P = 1e4 * eye (np);
  theta_prev = zeros (np, 1); # M_theta = q^-1: the estimate one sample back
  a_fb = d_svf(2:end);        # A(p) of the auxiliary model and prefilter
  b_fb = zeros (nb, 1);       # and the auxiliary model's numerator
  ## States [w; w'; ..] of 1/A(p). The auxiliary model b0/A(p) and the prefilter
  ## f2/A(p) on u have the same denominator, rule (ZOH) and input, so one
  ## state serves both.
  w_u = zeros (na, 1);
  w_y = zeros (na, 1);
  w_x = zeros (na, 1);
  u_prev = 0;                 # as if the signals were 0 before the record
  y_prev = 0;
  x_prev = 0;
  G = [zeros(na - 1, 1); 1];
  thm = zeros (N, np);
  for k = 1:N
    ## Discretise the current A(p) over one sampling interval.
    F = companion (a_fb);
    [Phi_z, Gam_z] = zoh (F, Ts);
    M = eye (na) - (Ts / 2) * F;
    Phi_t = M \ (eye (na) + (Ts / 2) * F);
    Gam_t = M \ (G * (Ts / 2));

    ## Auxiliary model and prefilter on u (ZOH).
    w_u = Phi_z * w_u + Gam_z * u_prev;
    xhat = b_fb(1) * w_u(1);
    ## Prefilter on y and x_hat (trapezoidal rule).
    w_y = Phi_t * w_y + Gam_t * (y_prev + y(k));
    w_x = Phi_t * w_x + Gam_t * (x_prev + xhat);
    u_prev = u(k);
    y_prev = y(k);
    x_prev = xhat;

    g = a_fb(na);             # unit static gain f_na / A(p)
    u_f = g * w_u(1);
    y_fna = g * (y(k) - a_fb * w_y(na:-1:1));         # y_f^(na)
    phi = [u_f; -g * w_y(na:-1:1)];
    zeta = [u_f; -g * w_x(na:-1:1)];

    P = P + Qn;
    if ((k - 1) * Ts < tsiv * (1 - 1e-12))
      ## RLSSVF-KF
      ph = phi_ls(k, :).';
      Pphi = P * ph;
      den = 1 + ph.' * Pphi;
      theta = theta + Pphi / den * (target_ls(k) - ph.' * theta);
      P = P - (Pphi * Pphi.') / den;
    else
      ## IV Kalman filter, eq. (2.29)
      Pzeta = P * zeta;
      L = Pzeta / (1 + phi.' * Pzeta);
      theta = theta + L * (y_fna - phi.' * theta);
      P = P - L * (phi.' * P);
    endif
    thm(k, :) = theta.';

    ## Refresh the auxiliary model and the prefilter with the estimate of
    ## the previous sample if its A(p) is stable (keep the last stable one).
    th_m = theta_prev;
    theta_prev = theta;
    a_m = th_m(nb+1:end).';
    if (all (isfinite (th_m)) && all (real (roots ([1, a_m])) < 0))
      a_fb = a_m;
      b_fb = th_m(1:nb);
    endif
  endfor
endfunction

## Companion matrix of p^n + a1 p^(n-1) + .. + an, state [w; w'; ..].
function F = companion (a)
  n = numel (a);
  F = [zeros(n - 1, 1), eye(n - 1); -a(n:-1:1)];
endfunction

## Exact ZOH discretisation of w^(n) = F w + s, F = companion (a), in the
## state [w; w'; ..]: [Phi Gam; 0 1] = expm ([F G; 0 0] h) (Appendix A.1).
function [Phi, Gam] = zoh (F, h)
  n = rows (F);
  E = expm ([F, [zeros(n - 1, 1); 1]; zeros(1, n + 1)] * h);
  Phi = E(1:n, 1:n);
  Gam = E(1:n, n + 1);
endfunction

## Trapezoidal rule (Tustin, p = 2/h (1 - q^-1)/(1 + q^-1)) of b(p)/a(p),
## polynomials in descending powers of p; [bq, aq] in powers of q^-1.
function [bq, aq] = tustin (b, a, h)
  n = numel (a) - 1;
  b = [zeros(1, n + 1 - numel (b)), b];
  bq = zeros (1, n + 1);
  aq = zeros (1, n + 1);
  for j = 0:n                 # the term in p^j
    t = (2 / h) ^ j * conv (poly (ones (1, j)), poly (-ones (1, n - j)));
    bq += b(n + 1 - j) * t;
    aq += a(n + 1 - j) * t;
  endfor
  bq /= aq(1);
  aq /= aq(1);
endfunction
