## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn {} {@var{est} =} residtrace_estimate (@var{y}, @var{ch}, @var{Ts}, @var{spec}, @var{opts})
## The one place where @code{residtrace} estimates a model: SRIVC (thesis
## eqs. 2.8-2.13) of
## @example
## F(p) y(t) = sum_j B_j(p) w_j(t - nk_j Ts) + e(t)
## @end example
## by the toolbox's offline refined-IV engine
## (@code{contsid_refined_iv}, core/include/ctid/offline/refined_iv.hpp), the
## channels w_j (inputs and effect terms) as its extra regressors, some
## coefficients of F fixed (integrators, a missing damping term).
##
## @var{ch}: struct array of channels with fields @code{w} (N-by-1),
## @code{nb}, @code{nk}, @code{rule} (@qcode{"zoh"} or @qcode{"foh"}).
## @var{spec}: @code{n} (order of F), @code{fixed} (1-by-n logical over
## f1..fn), @code{fval} (their values), optionally @code{missing} (the
## N-by-1 mask of missing samples, bridged: their y is replaced by the
## model's output and the fit repeated, twice; @code{x} equals y at the
## missing ones) and optionally
## @code{initial_state} (true: its free response estimated with the
## model) and @code{output_offset} (true: a constant added to the output
## estimated with the model, returned as @code{offset}; @code{x} then
## includes it). @var{opts}: @code{F0} (a start
## for F, with @code{B0} the channels' numerators (a cell, zeros where
## unknown); [] for the engine's automatic start), @code{maxiter},
## @code{tol}, optionally @code{c0} (a start for the output offset).
##
## @var{est}: @code{F}, @code{B} (cell, one row per channel),
## @code{theta} (the free parameters: free f's, then each channel's b's),
## @code{cov} (their SRIVC covariance), @code{s2}, @code{x} (the model
## output; with r integrators, the polynomial of degree r - 1 of their
## initial conditions fitted to y), @code{iterations}, @code{converged},
## @code{stable}, @code{ok}, @code{np}.
## @end deftypefn

function est = residtrace_estimate (y, ch, Ts, spec, opts)
  n = spec.n;
  fixed_f = logical (spec.fixed(:).');
  N = numel (y);
  m = numel (ch);
  W = zeros (N, m);
  for j = 1:m
    W(:, j) = ch(j).w(:);
  endfor
  nb = [ch.nb];
  r = 0;
  while (r < n && fixed_f(n-r) && spec.fval(n-r) == 0)
    r++;
  endwhile
  np_all = n + sum (nb);
  fixed = [fixed_f(:); false(sum (nb), 1)];
  values = [spec.fval(:); zeros(sum (nb), 1)];
  values(! fixed) = 0;
  e = struct ("nf", n, "nb", nb, "nk", [ch.nk], "intersample", {{ch.rule}},
              "integrators", r, "method", "srivc", "tol", opts.tol,
              "maxiter", opts.maxiter);
  if (isfield (spec, "initial_state") && spec.initial_state)
    e.initial_state = true;   # a record that does not start at rest
  endif
  joint_offset = isfield (spec, "output_offset") && spec.output_offset;
  if (joint_offset)
    e.output_offset = true;   # the record's output level, jointly
  endif
  nc = double (joint_offset);         # theta ends with c when estimated
  if (any (fixed))
    e.fixed = [fixed; false(nc, 1)];
    e.fixed_values = [values; zeros(nc, 1)];
  endif
  if (! isempty (opts.F0) && ! strictly_stable (opts.F0, r))
    opts.F0 = [];       # the engine starts from stable denominators only
  endif
  if (! isempty (opts.F0))
    F0 = opts.F0(:).' / opts.F0(1);
    th = [F0(2:end), cell2mat(cellfun (@(b) b(:).', opts.B0(:).',
                                       "UniformOutput", false))];
    th(fixed) = values(fixed);
    if (joint_offset)
      if (isfield (opts, "c0") && isfinite (opts.c0) && opts.c0 != 0)
        th(end+1) = opts.c0;
      else
        th(end+1) = mean (y(1:min (5, N)));  # at rest at its first samples
      endif
    endif
    e.theta_init = th(:);
    e.max_starts = 1;
  endif
  est = struct ("ok", false, "converged", false, "stable", false,
                "iterations", 0);
  present = true (N, 1);
  if (isfield (spec, "missing") && any (spec.missing))
    present = ! spec.missing(:);
  endif
  [theta, P, info] = contsid_refined_iv ("residtrace", y, W, Ts, e);
  for k = 1:2 * any (! present)
    ## missing samples (y bridged by residtrace_bridge): replaced by the
    ## model's own output and the fit repeated from where it ended, so
    ## that they carry no error (the expectation step of an output-error
    ## model); the inputs there are known or bridged
    if (numel (theta) != np_all + nc || any (! isfinite (theta)))
      break;
    endif
    y(! present) = info.simulated(! present);
    e.theta_init = theta(:);
    e.max_starts = 1;
    [theta, P, info] = contsid_refined_iv ("residtrace", y, W, Ts, e);
  endfor
  if (numel (theta) != np_all + nc || any (! isfinite (theta)))
    return;
  endif
  est.converged = info.converged;
  est.stable = info.stable;
  est.iterations = info.iterations;
  est.offset = 0;
  est.offset_std = 0;
  if (joint_offset)
    est.offset = theta(end);
    est.offset_std = sqrt (max (P(end, end), 0));
  endif
  est.F = info.F{1};
  est.F(1 + find (fixed_f)) = spec.fval(fixed_f);   # exactly, not to 1e-8
  est.B = info.B;
  free = [! fixed_f(:); true(sum (nb), 1)];
  est.theta = theta(free);
  est.cov = P(free, free);
  x = info.simulated(:);
  if (r > 0)
    T = ((0:N-1)' * Ts) .^ (0:r-1);
    x(present) += T(present, :) * (T(present, :) \ (y(present) - x(present)));
  endif
  x(! present) = y(! present);          # a missing sample: no error
  np = numel (est.theta);
  est.s2 = sum ((y - x) .^ 2) / max (nnz (present) - np - r, 1);
  est.x = x;
  est.np = np;
  est.ok = all (isfinite (x));
endfunction

## F's roots apart from its r integrators in the open left half-plane.
function ok = strictly_stable (F, r)
  F = F(:).';
  z = roots (F(1:end-r));
  ok = all (real (z) < 0);
endfunction
