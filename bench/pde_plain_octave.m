## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn {} {[@var{theta}, @var{theta0}] =} pde_plain_octave (@var{t}, @var{x}, @var{y}, @var{u}, @var{ic}, @var{K})
## The heat-equation SRIVC iteration of
## core/include/ctid/offline/pde_heat.hpp written in plain, vectorised
## Octave: the LSSVF start (@code{filter} along time and along space on the
## differenced fields, cut-offs 20/span), then @var{K} iterations (sparse
## tridiagonal Crank-Nicolson solves, one loop over the instants with the
## four arrays to prefilter as four right-hand sides), no convergence
## test.  @var{t}, @var{x} rows; @var{y}, @var{u} numel(t)-by-numel(x);
## @var{theta0} is the LSSVF start.  The baseline of
## @file{pde_octave_bench.m}.
## @end deftypefn

function [theta, theta0] = pde_plain_octave (t, x, y, u, ic, K)
  h = t(2) - t(1);  dx = x(2) - x(1);
  n = numel (x) - 2;
  e = ones (n, 1) / dx^2;
  L = spdiags ([e, -2 * e, e], -1:1, n, n);
  Y = y(:, 2:end-1);  U = u(:, 2:end-1);         # interior, time-by-space
  A = diff (Y) / h;                              # Dt y
  B = (Y(2:end, :) + Y(1:end-1, :)) / 2 * L;     # M L y (L symmetric)
  C = (U(2:end, :) + U(1:end-1, :)) / 2;         # M u
  ## LSSVF start: lambda_t/(s+lambda_t) (bilinear, divided by M) in time,
  ## (lambda_x/(p+lambda_x))^2 (bilinear) in space.
  lt = 20 / (t(end) - t(1)) * h;  lx = 20 / (x(end) - x(1)) * dx;
  bt = 2 * lt;  at = [2 + lt, -(2 - lt)];
  bs = conv ([lx lx], [lx lx]);  as = conv ([2 + lx, -(2 - lx)], [2 + lx, -(2 - lx)]);
  f = @(M) filter (bs, as, filter (bt, at, M), [], 2);
  Af = f (A);  Bf = f (B);  Cf = f (C);
  theta = [Bf(:), Cf(:)] \ Af(:);
  theta0 = theta;
  I = speye (n);
  for it = 1:K
    a = theta(1);
    T = I / h - a / 2 * L;  S = I / h + a / 2 * L;
    ## auxiliary model from ic
    Xh = zeros (numel (t), n);  Xh(1, :) = ic(2:end-1);
    src = theta(2) * C;
    for k = 2:numel (t)
      Xh(k, :) = (T \ (S * Xh(k-1, :)' + src(k-1, :)'))';
    endfor
    Bh = (Xh(2:end, :) + Xh(1:end-1, :)) / 2 * L;
    ## prefilter P = (Dt - a M L)^-1, zero start, on A, B, C, Bh at once
    W = cat (3, A, B, C, Bh);
    Z = zeros (size (W));
    z = zeros (n, 4);
    for k = 1:rows (A)
      z = T \ (S * z + reshape (W(k, :, :), n, 4));
      Z(k, :, :) = reshape (z, 1, n, 4);
    endfor
    Zf = reshape (Z, [], 4);
    theta = [Zf(:, 4), Zf(:, 3)]' * [Zf(:, 2), Zf(:, 3)] \ ...
            ([Zf(:, 4), Zf(:, 3)]' * Zf(:, 1));
  endfor
endfunction
