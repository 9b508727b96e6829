## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn {} {[@var{thm}, @var{V}, @var{P}] =} residtrace_track (@var{model}, @var{D}, @var{ctx}, @var{Qn}, @var{th0}, @var{P0}, @var{k0})
## Tracks the dynamic parameters of a @code{residtrace} model (its free
## f's, then each channel's numerator) along the record @var{D} by the
## Kalman-filter IV update of the thesis, eq. (2.29):
## @example
## K = P zeta / (1 + phi' P zeta),  theta += K (p^n y_f - phi' theta),
## P = P - K phi' P + Qn
## @end example
## with the prefilter and the auxiliary model frozen at @var{model} (as
## RSRIVC with no refresh; fine for slow drift): the SRIVC regression at
## the model (thesis eqs. 2.8-2.13), regressors phi the filtered
## derivatives of y (free f's) and of each channel, instruments zeta those
## of the auxiliary-model output in place of y's (prefilter 1/Fp(p), Fp =
## F made stable with separated roots, integrators moved to -wlo). @var{Qn} is normalised
## by the noise variance, @var{P0} likewise. An update that makes F
## unstable (apart from the model's integrators) is not accepted, as
## the stability test of the thesis' sec. 3.2 with "keep" (P still is).
## The regression is built here; the recursion is the core's
## (core/include/ctid/apps/residtrace/track.hpp, through
## @code{effect_sim_mex}).
##
## @var{thm}(k, :) is the estimate after sample k - 1 (one sample behind,
## so that sample k is never explained by itself; before sample @var{k0},
## default 1, the estimate stays at @var{th0}); @var{V} the negative
## log-likelihood of the innovations (prediction-error decomposition, the
## noise variance concentrated out; thesis sec. 3.3), @var{P} the final
## P.
## @end deftypefn

function [thm, V, P] = residtrace_track (model, D, ctx, Qn, th0, P0, k0)
  if (nargin < 7)
    k0 = 1;
  endif
  [lhs, Phi, Z] = regression (model, D, ctx);
  F = model.F;
  n = numel (F) - 1;
  r = 0;
  while (r < n && model.fixed(n-r) && F(n-r+1) == 0)
    r++;
  endwhile
  o = struct ("free", find (! model.fixed), "r", r, "k0", k0);
  [thm, V, P] = effect_sim_mex ("residtrace", "track", lhs, Phi, Z,
                                F(2:end), th0(:), P0, Qn, o);
endfunction

function [lhs, Phi, Z] = regression (model, D, ctx)
  o = 0;
  if (! isempty (model.out))
    [ys, xs] = residtrace_simulate (model, D.u, D.Ts, D.loop,
                                    ctx.opts.substeps);
    o = ys - xs;
  endif
  ch = residtrace_chdata (model, D);
  spec = struct ("n", numel (model.F) - 1, "fixed", model.fixed,
                 "fval", model.F(2:end));
  n = spec.n;
  free = find (! spec.fixed(:).');
  W = cell (1, numel (ch));
  for j = 1:numel (ch)
    W{j} = delay (ch(j).w(:), ch(j).nk);
  endfor
  r = 0;
  while (r < n && spec.fixed(n-r) && spec.fval(n-r) == 0)
    r++;
  endwhile
  [lhs, Phi, Z] = regression_at (model.F, {model.channels.B}, D.y - o, W,
                                 ch, D.Ts, spec, ctx.wlo, r, free, true);
endfunction

## The filtered regression at (F, B): lhs = p^n y_f + sum_fixed f_i
## p^(n-i) y_f, regressors [-p^(n-i) y_f (free i), p^k w_jf], instruments
## with x in place of y (least squares when use_iv is false or B unknown).
function [lhs, Phi, Z, x] = regression_at (F, B, y, W, ch, Ts, spec, wlo,
                                           r, free, use_iv)
  n = spec.n;
  Fp = residtrace_prefilter (F, wlo);
  Y = residtrace_filter (Fp, y, Ts, "foh");
  Phi_u = [];
  for j = 1:numel (ch)
    D = residtrace_filter (Fp, W{j}, Ts, ch(j).rule);
    Phi_u = [Phi_u, D(:, ch(j).nb:-1:1)];      # p^(nb-1) .. p^0
  endfor
  lhs = Y(:, n+1);
  for i = find (spec.fixed)
    lhs += spec.fval(i) * Y(:, n+1-i);
  endfor
  Phi = [-Y(:, n+1-free), Phi_u];
  x = [];
  if (use_iv && ! isempty (B{1}))
    [Xi, x] = instruments (F, W, ch, B, Fp, Ts, wlo, r, n, free);
    Z = [Xi, Phi_u];
  else
    Z = Phi;
  endif
endfunction

## Instruments -p^(n-i) x_f for the free f_i, with x = sum B_j/F w_j the
## auxiliary model. With r integrators (F = p^r F1) the model's r-th
## derivative x_r = sum B_j/F1 w_j is stable, and p^m x / Fp = p^(m-r) x_r
## / Fp for the columns m >= r that carry free coefficients. Also returns
## x itself: x_r integrated r times (trapezoidal rule).
function [Z, x] = instruments (F, W, ch, B, Fp, Ts, wlo, r, n, free)
  F1 = F(1:end-r);
  xr = 0;
  if (numel (F1) > 1)
    F1p = residtrace_prefilter (F1, wlo);
    for j = 1:numel (ch)
      D = residtrace_filter (F1p, W{j}, Ts, ch(j).rule);
      xr += D(:, ch(j).nb:-1:1) * B{j}(:);
    endfor
  else
    for j = 1:numel (ch)
      xr += W{j} * B{j}(end);            # F1 = 1: x_r = B w (nb = 1)
    endfor
  endif
  X = residtrace_filter (Fp, xr, Ts, "foh");
  Z = -X(:, n+1-free-r);
  x = xr;
  for k = 1:r
    x = Ts * cumsum ([0; (x(1:end-1) + x(2:end)) / 2]);
  endfor
  x = x(:);
endfunction

function w = delay (w, nk)
  if (nk > 0)
    w = [zeros(nk, 1); w(1:end-nk)];
  endif
endfunction

