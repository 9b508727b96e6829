## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn {} {[@var{theta}, @var{P}, @var{C}, @var{D}] =} rivc_plain_octave (@var{y}, @var{u}, @var{Ts}, @var{nn}, @var{theta}, @var{iters}, @var{r}, @var{cnum}, @var{cden})
## The RIVC / CLRIVC iteration of core/include/ctid/offline/refined_iv_bj.hpp
## written in plain Octave, the baseline of @file{rivc_octave_bench.m}:
## @var{iters} iterations from @var{theta} = [f b] (original time; no time
## scaling), nn = [nb nc nd nf]. Each iteration: the exact ZOH filters
## p^i s / F(p) (the sampled state recursion z(k+1) = Phi z(k) + g s(k),
## each state run as a discrete transfer function by the built-in
## @code{filter}: vectorised, about 11 times faster than the loop over
## the samples of the control package's lsim), the auxiliary model
## x_hat = B/F u through 1/F^2, the ARMA model of y - x_hat
## (Hannan-Rissanen, or the previous iteration's model, then Gauss-Newton
## with @code{filter}), the D/C
## prefilter (@code{filter}) and the IV solve. With @var{cnum}, @var{cden}
## (a continuous controller) and @var{r}: the closed-loop instruments of
## CLRIVC. Differences from the core: no time scaling, the noise estimate
## is filtered as held (ZOH) rather than linear between samples, no step
## halving (the iterate is kept if stable).
## @end deftypefn

function [theta, P, C, D] = rivc_plain_octave (y, u, Ts, nn, theta, iters,
                                               r, cnum, cden)
  nb = nn(1); nc = nn(2); nd = nn(3); nf = nn(4);
  y = y(:); u = u(:); theta = theta(:);
  N = numel (y);
  closed = nargin >= 9 && ! isempty (cnum);
  start = [];
  for it = 1:iters
    F = [1, theta(1:nf).'];
    b = theta(nf+1:end);
    Uf = plain_zoh_derivatives (F, u, Ts);
    U2 = plain_zoh_derivatives (conv (F, F), u, Ts);
    xh = Uf(:, nb:-1:1) * b;
    Xf = zeros (N, nf + 1);
    for i = 0:nf
      Xf(:, i+1) = U2(:, (nb-1:-1:0) + i + 1) * b;
    endfor
    xi = y - xh;
    Yf = Xf + plain_zoh_derivatives (F, xi, Ts);
    Zx = Xf;
    Zu = Uf;
    if (closed)
      bnc = conv (b.', cnum);
      acl = conv (F, cden);
      acl(end-numel (bnc)+1:end) += bnc;
      lead = acl(1);
      acl /= lead;
      R = plain_zoh_derivatives (conv (acl, F), r(:), Ts) / lead;
      fnc = conv (F, cnum);
      Zx = apply_num (bnc, nf + 1, R);
      Zu = apply_num (fnc, nb, R);
    endif
    Phi = [-Yf(:, nf:-1:1), Uf(:, nb:-1:1)];
    Z = [-Zx(:, nf:-1:1), Zu(:, nb:-1:1)];
    target = Yf(:, nf+1);
    [C, D, s2] = arma_plain (xi, nd, nc, start);
    start = [D(2:end), C(2:end)].';
    Phi = filter (D, C, Phi);
    Z = filter (D, C, Z);
    target = filter (D, C, target);
    next = (Z' * Phi) \ (Z' * target);
    if (all (real (roots ([1; next(1:nf)])) < 0))
      theta = next;
    endif
  endfor
  P = s2 * inv (Z' * Z);
endfunction

function out = apply_num (num, count, R)
  deg = numel (num) - 1;
  out = zeros (rows (R), count);
  for i = 0:count-1
    for k = 0:deg
      col = deg - k + i;
      if (col < columns (R))
        out(:, i+1) += num(k+1) * R(:, col+1);
      endif
    endfor
  endfor
endfunction

## Hannan-Rissanen and Gauss-Newton prediction-error steps, D xi = C e.
function [C, D, s2] = arma_plain (x, nd, nc, start)
  N = numel (x);
  np = nd + nc;
  if (np == 0)
    C = 1; D = 1; s2 = mean (x .^ 2);
    return;
  endif
  e = zeros (N, 1);
  if (nc > 0 && numel (start) == np)
    eta = start(:);
  elseif (nc > 0)
    L = min (max (20, 3 * np + 10), floor (N / 10));
    A = zeros (N - L, L);
    for i = 1:L
      A(:, i) = -x(L+1-i:N-i);
    endfor
    a = A \ x(L+1:N);
    e = filter ([1; a], 1, x);
  endif
  if (! (nc > 0 && numel (start) == np))
    s = max (nd, nc);
    A = zeros (N - s, np);
    for i = 1:nd
      A(:, i) = -x(s+1-i:N-i);
    endfor
    for i = 1:nc
      A(:, nd+i) = e(s+1-i:N-i);
    endfor
    eta = A \ x(s+1:N);
  endif
  loss = @(p) mean (filter ([1; p(1:nd)], [1; p(nd+1:end)], x) .^ 2);
  v = loss (eta);
  for it = 1:50
    if (nc == 0)
      break;
    endif
    Cp = [1; eta(nd+1:end)];
    Dp = [1; eta(1:nd)];
    err = filter (Dp, Cp, x);
    xc = filter (1, Cp, x);
    ec = filter (1, Cp, err);
    J = zeros (N, np);
    for i = 1:nd
      J(i+1:N, i) = xc(1:N-i);
    endfor
    for i = 1:nc
      J(i+1:N, nd+i) = -ec(1:N-i);
    endfor
    step = J \ err;
    alpha = 1;
    improved = false;
    for h = 1:20
      trial = eta - alpha * step;
      vt = loss (trial);
      if (vt < v && all (abs (roots ([1; trial(nd+1:end)])) < 1))
        improved = true;
        break;
      endif
      alpha /= 2;
    endfor
    if (! improved)
      break;
    endif
    dec = (v - vt) / v;
    eta = trial;
    v = vt;
    if (dec < 1e-8)
      break;
    endif
  endfor
  C = [1; eta(nd+1:end)].';
  D = [1; eta(1:nd)].';
  s2 = v;
endfunction
