## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn {} {[@var{theta}, @var{iterations}] =} tocils_plain_octave (@var{y}, @var{u}, @var{Ts}, @var{nf}, @var{nb}, @var{L}, @var{lambda}, @var{iters})
## The TOCLS/TOCILS iteration of core/include/ctid/offline/cumulant_eiv.hpp
## in plain, vectorised Octave, the baseline of @file{tocils_octave_bench.m}:
## the means removed, the SVF (lambda/(p + lambda))^nf start, then
## @var{iters} solutions with the prefilter f_nf / F(p) of the previous
## one; each filters y and u by exact ZOH filters run by the built-in
## @code{filter} (@code{plain_zoh_derivatives}) and solves the
## third-order cross-cumulant equations for the lags 0 .. @var{L}-1 by
## least squares.  @var{nb} counts the numerator's coefficients.
## Difference from the core: y is filtered as held (ZOH) rather than by
## the core's rule for the output.
## @end deftypefn

function [theta, iterations] = tocils_plain_octave (y, u, Ts, nf, nb, L,
                                                    lambda, iters)
  y = y(:) - mean (y);
  u = u(:) - mean (u);
  N = numel (y);
  first = L;
  idx = (first:N)' - (0:L-1);            # u(t - tau), tau = 0 .. L-1
  W = u(idx) .^ 2;
  W -= mean (W, 1);
  D = poly (-lambda * ones (1, nf));
  theta = solve (D, D(end), y, u, Ts, nf, nb, W, first);
  iterations = 1;
  for it = 1:iters
    F = [1, theta(1:nf).'];
    theta = solve (F, F(end), y, u, Ts, nf, nb, W, first);
    iterations += 1;
  endfor
endfunction

function theta = solve (D, gain, y, u, Ts, nf, nb, W, first)
  Yd = gain * plain_zoh_derivatives (D, y, Ts);
  Ud = gain * plain_zoh_derivatives (D, u, Ts);
  Phi = [-Yd(:, nf:-1:1), Ud(:, nb:-1:1)];
  rows = first:numel (y);
  count = numel (rows);
  C = W' * Phi(rows, :) / count;
  c = W' * Yd(rows, nf + 1) / count;
  theta = C \ c;
endfunction
