## -*- texinfo -*-
## @deftypefn  {} {@var{est} =} residtrace_srivc (@var{y}, @var{ch}, @var{Ts}, @var{spec}, @var{opts})
## @deftypefnx {} {[@var{lhs}, @var{Phi}, @var{Z}] =} residtrace_srivc (@var{y}, @var{ch}, @var{Ts}, @var{spec}, @var{opts}, @var{B})
## SRIVC for the multi-input model of @code{residtrace}
## @example
## F(p) y(t) = sum_j B_j(p) w_j(t - nk_j Ts) + e(t)
## @end example
## with some coefficients of F fixed (integrators, a missing damping).
##
## @var{ch}: struct array of channels with fields @code{w} (N-by-1 signal
## at the samples), @code{nb}, @code{nk}, @code{rule} (@qcode{"zoh"} or
## @qcode{"foh"}). @var{spec}: @code{n} (order of F), @code{fixed}
## (1-by-n logical, which of f1..fn are fixed) and @code{fval} (their
## values). @var{opts}: @code{F0} (a start for F, or [] for an SVF start at
## @code{lambda}), @code{lambda}, @code{wlo} (where the prefilter puts
## the model's integrators), @code{maxiter}, @code{tol}, @code{iv}
## (false: instruments = regressors, i.e. least squares).
##
## Algorithm (thesis eqs. 2.8-2.13): with the current F, the prefilter
## 1/Fp(p) (Fp = F made stable and with separated roots by
## @code{residtrace_prefilter}) gives the filtered derivatives of y (held
## linearly between samples, Suggested procedure 3.3), of each channel
## (its own hold) and of the auxiliary-model output x = sum B_j/F w_j;
## the IV estimate solves sum zeta phi' theta = sum zeta p^n y_f with
## zeta the filtered derivatives of x in place of those of y. A model with
## r integrators (F = p^r F1) runs its auxiliary model without them (its
## r-th derivative, sum B_j/F1 w_j, is stable) since only the derivatives
## of order >= r of x enter the instruments. The start without F0 is the
## LSSVF estimate with the filter (p + lambda)^n (its roots spread by
## +-15 % so that they are distinct).
##
## @var{est}: @code{F}, @code{B} (cell, one row per channel), @code{theta}
## (the free parameters: free f's, then each channel's b's), @code{cov}
## (sigma^2 (sum zeta zeta')^-1), @code{s2}, @code{x} (auxiliary-model
## output; with integrators, x_r integrated r times with its initial
## conditions fitted to y), @code{iterations}, @code{converged}, @code{ok}
## (false when the regression was singular).
##
## With a sixth argument (the numerators, a cell) and @code{opts.F0} it
## only returns the regression at that model: the left side p^n y_f (fixed
## coefficients moved to it), the regressors and the instruments.
## @end deftypefn

function [est, Phi_o, Z_o] = residtrace_srivc (y, ch, Ts, spec, opts, B0)
  n = spec.n;
  free = find (! spec.fixed(:).');
  N = numel (y);
  W = cell (1, numel (ch));
  for j = 1:numel (ch)
    W{j} = delay (ch(j).w(:), ch(j).nk);
  endfor
  ## r integrators: f_(n-r+1) .. f_n fixed at 0
  r = 0;
  while (r < n && spec.fixed(n-r) && spec.fval(n-r) == 0)
    r++;
  endwhile
  if (nargin > 5)
    F = opts.F0(:).';
    [est, Phi_o, Z_o] = regression (F, B0, y, W, ch, Ts, spec, opts.wlo, r,
                                    free, true);
    return;
  endif
  if (isempty (opts.F0))
    lam = opts.lambda;
    if (n == 1)
      rs = -lam;
    else
      rs = -lam * (1 + 0.3 * ((0:n-1) / (n - 1) - 0.5));
    endif
    F = real (poly (rs));
    iv = false;
  else
    F = opts.F0(:).';
    iv = opts.iv;
  endif
  F(1 + find (spec.fixed)) = spec.fval(spec.fixed);
  B = cell (1, numel (ch));
  est = struct ("ok", false, "converged", false, "iterations", 0);
  theta_old = [];
  for it = 1:opts.maxiter
    use_iv = iv && ! isempty (B{1});
    [lhs, Phi, Z] = regression (F, B, y, W, ch, Ts, spec, opts.wlo, r,
                                free, use_iv);
    ZP = Z' * Phi;
    if (rcond (ZP) < 1e-14 || any (! isfinite (ZP(:))))
      return;
    endif
    theta = ZP \ (Z' * lhs);
    F(1 + free) = theta(1:numel (free));
    off = numel (free);
    for j = 1:numel (ch)
      B{j} = theta(off+1:off+ch(j).nb).';
      off += ch(j).nb;
    endfor
    est.iterations = it;
    if (! isempty (theta_old)
        && norm (theta - theta_old) <= opts.tol * norm (theta))
      est.converged = true;
      break;
    endif
    theta_old = theta;
    iv = opts.iv;
  endfor
  ## Covariance and auxiliary-model output at the final estimate.
  [~, ~, Z, x] = regression (F, B, y, W, ch, Ts, spec, opts.wlo, r, free,
                             true);
  np = numel (theta);
  if (r > 0)
    T = ((0:N-1)' * Ts) .^ (0:r-1);
    x += T * (T \ (y - x));
  endif
  e = y - x;
  s2 = sum (e .^ 2) / max (N - np - r, 1);
  est.ok = all (isfinite (theta)) && all (isfinite (x));
  est.F = F;
  est.B = B;
  est.theta = theta;
  est.cov = s2 * inv (Z' * Z);
  est.s2 = s2;
  est.x = x;
  est.np = np;
endfunction

## The filtered regression at (F, B): lhs = p^n y_f + sum_fixed f_i
## p^(n-i) y_f, regressors [-p^(n-i) y_f (free i), p^k w_jf], instruments
## with x in place of y (least squares when use_iv is false or B unknown).
function [lhs, Phi, Z, x] = regression (F, B, y, W, ch, Ts, spec, wlo, r,
                                        free, use_iv)
  n = spec.n;
  Fp = residtrace_prefilter (F, wlo);
  Y = residtrace_modal (Fp, y, Ts, "foh");
  Phi_u = [];
  for j = 1:numel (ch)
    D = residtrace_modal (Fp, W{j}, Ts, ch(j).rule);
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
      D = residtrace_modal (F1p, W{j}, Ts, ch(j).rule);
      xr += D(:, ch(j).nb:-1:1) * B{j}(:);
    endfor
  else
    for j = 1:numel (ch)
      xr += W{j} * B{j}(end);            # F1 = 1: x_r = B w (nb = 1)
    endfor
  endif
  X = residtrace_modal (Fp, xr, Ts, "foh");
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
