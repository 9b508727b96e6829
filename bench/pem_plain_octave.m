## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn {} {[@var{theta}, @var{iters}] =} pem_plain_octave (@var{y}, @var{u}, @var{Ts}, @var{nf}, @var{nb}, @var{theta0}, @var{kind}, @var{maxiter})
## The baseline of bench/pem_octave_bench.m: the iteration of
## core/include/ctid/offline/output_error.hpp written in plain Octave as a user
## would without the toolbox: Levenberg-Marquardt (scaled damping, steps
## refused while F is unstable or the loss does not fall) on the
## simulation error, exact Jacobian.  @var{kind} "ct": B(p)/F(p) with a
## ZOH input, simulated by the ZOH-discretised state-space model sample by
## sample (expm of the companion form), sensitivities by the same rule
## through 1/F^2; "dt": B(q)/F(q) q^-1 with Octave's @code{filter}.
## "ctf": as "ct" with each filter p^i / F discretised by the control
## package's c2d (ZOH) and run by Octave's compiled @code{filter} (the
## fastest plain-Octave form).
## theta = [f; b] as in the core (continuous time, unscaled).
## @end deftypefn

function [theta, iters] = pem_plain_octave (y, u, Ts, nf, nb, theta, kind, maxiter)
  N = numel (y);
  mu = 1e-3;
  [yh, J] = model (theta, u, Ts, nf, nb, kind, true);
  e = y - yh;
  cost = e' * e;
  iters = 0;
  for it = 1:maxiter
    s = sqrt (sum (J .^ 2))';
    s(s == 0) = 1;
    Jn = J ./ s';
    [Q, R] = qr (Jn, 0);
    qte = Q' * e;
    accepted = false;
    for a = 1:40
      dn = [R; sqrt(mu) * eye(nf + nb)] \ [qte; zeros(nf + nb, 1)];
      step = dn ./ s;
      trial = theta + step;
      if (stable (trial(1:nf), kind))
        yt = model (trial, u, Ts, nf, nb, kind, false);
        c = sum ((y - yt) .^ 2);
        if (c < cost)
          accepted = true;
          break;
        endif
      endif
      mu *= 10;
    endfor
    if (! accepted)
      break;
    endif
    rel = norm (step .* s) / norm (theta .* s);
    dec = (cost - c) / cost;
    theta = trial;
    cost = c;
    mu = max (mu / 10, 1e-12);
    iters = it;
    [yh, J] = model (theta, u, Ts, nf, nb, kind, true);
    e = y - yh;
    if (rel <= 1e-8 && dec <= 1e-8)
      break;
    endif
  endfor
endfunction

function ok = stable (f, kind)
  r = roots ([1; f(:)]);
  if (kind(1) == "c")
    ok = all (real (r) < 0);
  else
    ok = all (abs (r) < 1);
  endif
endfunction

function [yh, J] = model (theta, u, Ts, nf, nb, kind, want)
  f = theta(1:nf);
  b = theta(nf+1:end);
  J = [];
  if (strcmp (kind, "dt"))
    F = [1; f]';
    v = filter (1, F, u);
    yh = filter ([0; b]', 1, v);
    if (want)
      J = zeros (numel (u), nf + nb);
      for k = 1:nb
        J(:, nf + k) = [zeros(k, 1); v(1:end-k)];
      endfor
      w = filter (1, F, yh);
      for i = 1:nf
        J(:, i) = -[zeros(i, 1); w(1:end-i)];
      endfor
    endif
    return;
  endif
  if (strcmp (kind, "ctf"))
    derivs = @derivs_filter;
  else
    derivs = @derivs_loop;
  endif
  X = derivs ([1; f], u, Ts);            # p^i u / F, i = 0..nf
  yh = X(:, nb:-1:1) * b;
  if (want)
    J = zeros (numel (u), nf + nb);
    J(:, nf+1:end) = X(:, nb:-1:1);
    X2 = derivs (conv ([1; f], [1; f]), u, Ts);
    for i = 1:nf
      J(:, i) = -X2(:, nf - i + nb:-1:nf - i + 1) * b;
    endfor
  endif
endfunction

## p^i u / D(p), i = 0..n, u held between samples (ZOH), at rest at t0.
function X = derivs_filter (D, u, Ts)
  n = numel (D) - 1;
  X = zeros (numel (u), n + 1);
  for i = 0:n
    [b, a] = tfdata (c2d (tf ([1, zeros(1, i)], D(:)'), Ts, "zoh"), "vector");
    b = [zeros(1, numel (a) - numel (b)), b];
    X(:, i + 1) = filter (b, a, u);
  endfor
endfunction

function X = derivs_loop (D, u, Ts)
  n = numel (D) - 1;
  A = [zeros(n - 1, 1), eye(n - 1); -flipud(D(2:end))'];
  E = expm ([A, [zeros(n - 1, 1); 1]; zeros(1, n + 1)] * Ts);
  Phi = E(1:n, 1:n);
  G = E(1:n, n + 1);
  N = numel (u);
  X = zeros (N, n + 1);
  z = zeros (n, 1);
  for k = 1:N
    if (k > 1)
      z = Phi * z + G * u(k - 1);
    endif
    X(k, 1:n) = z';
    X(k, n + 1) = u(k) - D(2:end)' * flipud (z);
  endfor
endfunction
