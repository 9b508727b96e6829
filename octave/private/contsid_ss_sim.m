## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn {} {@var{y} =} contsid_ss_sim (@var{a}, @var{b}, @var{c}, @var{d}, @var{u}, @var{t}, @var{intersample}, @var{nk})
## Output of the continuous-time state-space model x' = a x + b u,
## y = c x + d u, from rest, at the sampling instants of the input
## @var{u} (N-by-nu), exact for a piecewise constant (@qcode{"zoh"}) or
## piecewise linear (@qcode{"foh"}) input: each interval h is integrated
## with the matrix exponential of [a b 0; 0 0 I; 0 0 0] h (Van Loan),
## whose blocks give x(t+h) from x(t), the input and its slope.
## @var{t}: the sampling interval or the N instants.  @var{nk}: ny-by-nu
## input delays in samples; with a sampling interval they may be
## fractional, m + phi: the delayed input then changes (ZOH) or bends
## (FOH) at phi Ts after each sample, and each interval is integrated in
## the two pieces, still exactly.
## @end deftypefn

function y = contsid_ss_sim (a, b, c, d, u, t, intersample, nk)
  [N, nu] = size (u);
  ny = rows (c);
  if (isempty (nk))
    nk = zeros (ny, nu);
  endif
  foh = strcmp (intersample, "foh");
  if (all (nk(:) == fix (nk(:))))
    y = zeros (N, ny);
    if (all (all (nk == nk(1, :))))
      groups = {1:ny};
    else
      groups = num2cell (1:ny);
    endif
    for g = 1:numel (groups)
      r = groups{g};
      ud = u;
      for j = 1:nu
        k = nk(r(1), j);
        ud(:, j) = [zeros(k, 1); u(1:N-k, j)];
      endfor
      y(:, r) = simulate (a, b, c(r, :), d(r, :), ud, t, foh);
    endfor
    return;
  endif
  if (! isscalar (t))
    error ("contsid_ss_sim:notSupported",
           "fractional delays need uniformly sampled data");
  endif
  ## fractional delays: input by input and output by output (linearity)
  y = zeros (N, ny);
  for i = 1:ny
    for j = 1:nu
      y(:, i) += fractional (a, b(:, j), c(i, :), d(i, j), u(:, j), t,
                             foh, nk(i, j));
    endfor
  endfor
endfunction

function y = simulate (a, b, c, d, u, t, foh)
  [N, nu] = size (u);
  n = rows (a);
  if (isscalar (t))
    h = repmat (t, N - 1, 1);
  else
    h = diff (t(:));
  endif
  x = zeros (n, 1);
  X = zeros (n, N);
  last_h = NaN;
  for k = 1:N-1
    if (h(k) != last_h)
      [E11, E12, E13] = blocks (a, b, h(k));
      last_h = h(k);
    endif
    s = zeros (nu, 1);
    if (foh)
      s = (u(k+1, :) - u(k, :)).' / h(k);
    endif
    x = E11 * x + E12 * u(k, :).' + E13 * s;
    X(:, k+1) = x;
  endfor
  y = (c * X).' + u * d.';
endfunction

## x(t + h) = E11 x(t) + E12 v(t) + E13 v'  for an input v linear on h.
function [E11, E12, E13] = blocks (a, b, h)
  n = rows (a);
  nu = columns (b);
  E = expm ([a, b, zeros(n, nu); zeros(nu, n + nu), eye(nu);
             zeros(nu, n + 2 * nu)] * h);
  E11 = E(1:n, 1:n);
  E12 = E(1:n, n+1:n+nu);
  E13 = E(1:n, n+nu+1:end);
endfunction

## One input, one output, delay m + phi samples (0 < phi < 1): on
## [t_k, t_k + phi Ts) the delayed input is the continuation of the piece
## that starts at u_(k-m-1), on [t_k + phi Ts, t_(k+1)) the piece from
## u_(k-m).
function y = fractional (a, b, c, d, u, Ts, foh, delay)
  N = numel (u);
  n = rows (a);
  m = floor (delay);
  phi = delay - m;
  [F11, F12, F13] = blocks (a, b, phi * Ts);
  [G11, G12, G13] = blocks (a, b, (1 - phi) * Ts);
  U = @(k) (k >= 1 && k <= N) * u(max (min (k, N), 1));
  x = zeros (n, 1);
  y = zeros (N, 1);
  for k = 1:N
    ## the delayed input at t_k, on the piece that started at u_(k-m-1)
    p = k - m - 1;                     # index of that piece's sample
    s1 = 0;
    if (foh)
      s1 = (U (p + 1) - U (p)) / Ts;
    endif
    v0 = U (p) + s1 * (1 - phi) * Ts;
    y(k) = c * x + d * v0;
    if (k == N)
      break;
    endif
    x = F11 * x + F12 * v0 + F13 * s1;
    s2 = 0;
    if (foh)
      s2 = (U (p + 2) - U (p + 1)) / Ts;
    endif
    x = G11 * x + G12 * U (p + 1) + G13 * s2;
  endfor
endfunction
