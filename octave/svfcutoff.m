## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn  {} {@var{lambda} =} svfcutoff (@var{data}, [@var{nb} @var{nf} @var{nk}])
## @deftypefnx {} {@var{lambda} =} svfcutoff (@dots{}, @var{name}, @var{value})
## @deftypefnx {} {[@var{lambda}, @var{info}] =} svfcutoff (@dots{})
## @deftypefnx {} {} svfcutoff (@dots{})
## Suggest the SVF cut-off lambda_svf of the recursive estimators from
## local LTI models fitted by SRIVC on segments of training data (thesis
## sec. 3.1.2, Suggested procedure 3.2); the spread of the local parameters
## also tells which parameters vary and how much (Suggested procedure 3.6,
## the choice of Qn).
##
## @strong{Inputs}
## @table @var
## @item data
## training data: an @code{iddata} object or numeric @var{y}, @var{u},
## @var{Ts} (or sampling instants), one input.
## @item nn
## [nb nf nk], the model structure of @code{srivc}: nb numerator and nf
## denominator parameters, nk the input delay in samples.
## @end table
##
## @strong{Options}
## @table @code
## @item segments
## number K of equal, consecutive, non-overlapping segments (default 10).
## @item seglength
## length (s) of the segments instead: K = floor (T / seglength) segments
## from the first sample on, the remainder of the record is not used.
## Give @code{segments} or @code{seglength}, not both.
## @item factor
## the margin of the rule below (default 1.1), a real scalar >= 1.
## @item srivc
## a cell of name-value options passed to @code{srivc} (e.g.
## @code{@{"lambda", 3@}}); default @code{@{@}}, SRIVC's own start.
## @end table
## Every segment must hold at least 20 (nb + nf) samples.
##
## @strong{Bandwidth} of a local model: @code{bandwidthc (M, "wmin", 2*pi/T_s)}
## with T_s the segment length, i.e. the -3 dB frequency of |G(j w)|
## relative to its low-frequency gain (its static gain, or for models with
## integrators that of the model without them), or for band-pass models
## (zeros at the origin) the upper -3 dB frequency relative to the peak
## gain; poles and zeros slower than 2 pi / T_s count as lying at the
## origin. See @code{help bandwidthc}.
##
## @strong{Rule.} @var{lambda} = factor * max (w_b), the largest bandwidth
## over the usable segments (a stable local model with a finite bandwidth),
## "somewhat larger than the system bandwidth" (sec. 3.1.2), "slightly
## larger than the maximum bandwidth" (sec. 2.3.5, where the thesis takes
## 3.2 rad/s for a maximum frozen bandwidth of 2.985 rad/s, and sec. 2.3.6,
## 16 rad/s for 15.77 rad/s). Local models average the system over a
## segment, so their largest bandwidth lies somewhat below the largest
## frozen bandwidth; more segments reduce this at the price of noisier
## models. A segment whose model is unstable or has no finite bandwidth is
## reported but not used; if none is usable the error
## @code{svfcutoff:notConverged} is raised.
##
## @strong{Outputs.} @var{lambda} (rad/s) and @var{info}, a struct with
## @table @code
## @item segments, samples
## K-by-2 start and end times (s from the first sample) and first and last
## sample indices of the segments.
## @item models
## K-by-1 cell of the local @code{idctm} models.
## @item theta, se
## K-by-np local parameters [f1 .. f_nf, b0 .. b_(nb-1)] (the order of
## @code{rlssvf}'s THM) and their standard errors from SRIVC's covariance.
## @item bandwidth, kind
## K-by-1 bandwidths (rad/s) and the kind of each model (see
## @code{bandwidthc}).
## @item stable, converged, used, RT2
## per segment: F(p) Hurwitz; SRIVC converged (a segment that did not is
## still used, its warning is not shown); usable for the rule; SRIVC's
## coefficient of determination.
## @item bwrange
## [min max] of the bandwidths of the usable segments.
## @item spread
## over the usable segments, for each parameter: @code{mean}, @code{std},
## @code{min}, @code{max}, @code{relstd} = std / |mean|, @code{se} (RMS of
## the segments' standard errors), @code{ratio} = std / se and
## @code{varying} = ratio > 3: a spread well beyond the local models'
## noise says the parameter varies; a ratio near 1 is consistent with a
## constant parameter, whose Qn element can be set (near) zero (Suggested
## procedure 3.6).
## @item factor, rule, lambda
## the rule as applied.
## @end table
## Without output arguments it plots the bandwidths of the segments with
## the suggested lambda, and the local parameters relative to their mean.
##
## @strong{Example}
## @example
## Ts = 0.05; u = prbs (12, 10); N = numel (u); t = (0:N-1)' * Ts;
## wn = 2 * (1 + 0.3 * cos (2 * pi * t / t(end)));
## y = simc ([1.2 * wn, wn .^ 2, wn .^ 2], [2 1 0], u, Ts) ...
##     + 0.05 * randn (N, 1);
## [lam, info] = svfcutoff (iddata (y, u, Ts), [1 2 0], "segments", 8);
## info.bwrange, lam
## @end example
## @seealso{bandwidthc, srivc, rlssvf, rlsconverge}
## @end deftypefn

function varargout = svfcutoff (varargin)
  varargout = contsid_guard ("svfcutoff", @svfcutoff_body, nargout, varargin);
endfunction

function [lambda, info, varargout] = svfcutoff_body (varargin)
  contsid_nargchk ("svfcutoff", nargin, nargout, [0 Inf], 2);
  fname = "svfcutoff";
  defaults = struct ("segments", [], "seglength", [], "factor", 1.1,
                     "srivc", {{}});
  [d, orders, opts] = contsid_recursive_args (fname, "f", defaults,
                                              varargin{:});
  if (columns (d.u) != 1)
    error ("svfcutoff:badInput", "svfcutoff: one input only, got %d",
           columns (d.u));
  endif
  nn = [orders.nb, orders.na, orders.nk];
  np = orders.np;
  t = d.t - d.t(1);
  T = t(end);
  [K, Tseg, seg] = segments (opts, t, T);
  if (! isnumeric (opts.factor) || ! isreal (opts.factor)
      || ! isscalar (opts.factor) || ! isfinite (opts.factor)
      || opts.factor < 1)
    error ("svfcutoff:badInput",
           "svfcutoff: factor must be a finite real scalar >= 1");
  endif
  sopts = opts.srivc;
  if (! iscell (sopts))
    error ("svfcutoff:badInput",
           "svfcutoff: srivc must be a cell of name-value options");
  endif
  nseg = accumarray (seg(seg > 0), 1, [K 1]);
  if (any (nseg < 20 * np))
    error ("svfcutoff:badInput",
           ["svfcutoff: the training data are too short for %d segments: ", ...
            "%d samples in the shortest, at least 20 (nb + nf) = %d needed"],
           K, min (nseg), 20 * np);
  endif

  info = struct ();
  info.segments = [(0:K-1)' * Tseg, (1:K)' * Tseg];
  info.samples = zeros (K, 2);
  info.models = cell (K, 1);
  info.theta = zeros (K, np);
  info.se = zeros (K, np);
  info.bandwidth = NaN (K, 1);
  info.kind = cell (K, 1);
  info.stable = false (K, 1);
  info.converged = false (K, 1);
  info.RT2 = NaN (K, 1);
  wmin = 2 * pi / Tseg;
  warning ("off", "srivc:notConverged", "local");
  for k = 1:K
    i = find (seg == k);
    info.samples(k, :) = [i(1), i(end)];
    if (d.uniform)
      timing = d.Ts;
    else
      timing = t(i) - t(i(1));
    endif
    dk = iddata (d.y(i), d.u(i), timing, "InterSample", d.intersample);
    try
      [M, info.RT2(k)] = srivc (dk, nn, sopts{:});
    catch err
      rename_error (err);
    end_try_catch
    info.models{k} = M;
    info.theta(k, :) = M.theta(:).';
    info.se(k, :) = sqrt (max (diag (M.covariance), 0)).';
    info.converged(k) = M.converged;
    info.stable(k) = all (real (roots (M.F)) < 0);
    [info.bandwidth(k), info.kind{k}] = bandwidthc (M, "wmin", wmin);
  endfor
  info.used = info.stable & isfinite (info.bandwidth);
  if (! any (info.used))
    error ("svfcutoff:notConverged",
           ["svfcutoff: no segment gave a stable local model with a ", ...
            "finite bandwidth"]);
  endif
  bw = info.bandwidth(info.used);
  info.bwrange = [min(bw), max(bw)];
  th = info.theta(info.used, :);
  sp.mean = mean (th, 1);
  sp.std = std (th, 0, 1);
  sp.min = min (th, [], 1);
  sp.max = max (th, [], 1);
  sp.relstd = sp.std ./ abs (sp.mean);
  sp.se = sqrt (mean (info.se(info.used, :) .^ 2, 1));
  sp.ratio = sp.std ./ sp.se;
  sp.varying = sp.ratio > 3;
  info.spread = sp;
  info.factor = double (opts.factor);
  info.rule = "lambda_svf = factor * max bandwidth of the usable segments";
  info.lambda = info.factor * info.bwrange(2);
  if (nargout > 0)
    lambda = info.lambda;
    return;
  endif
  plot_info (info, orders);
endfunction

## Segment number of every sample (0: not used), their number and length.
function [K, Tseg, seg] = segments (opts, t, T)
  if (! isempty (opts.segments) && ! isempty (opts.seglength))
    error ("svfcutoff:badOption",
           "svfcutoff: give segments or seglength, not both");
  endif
  if (! isempty (opts.seglength))
    L = opts.seglength;
    if (! isnumeric (L) || ! isreal (L) || ! isscalar (L) || ! isfinite (L)
        || L <= 0 || L > T * (1 + 1e-12))
      error ("svfcutoff:badInput",
             ["svfcutoff: seglength must be a real scalar in (0, %g] ", ...
              "(the record's length, s)"], T);
    endif
    Tseg = double (L);
    K = max (1, floor (T / Tseg * (1 + 1e-12)));
    seg = floor (t / Tseg * (1 + 1e-12)) + 1;
    seg(seg > K) = 0;
    ## The end point of the last segment belongs to it.
    seg(abs (t - K * Tseg) <= 1e-9 * Tseg) = K;
  else
    K = opts.segments;
    if (isempty (K))
      K = 10;
    endif
    if (! isnumeric (K) || ! isreal (K) || ! isscalar (K) || K != fix (K)
        || K < 1 || K > numel (t))
      error ("svfcutoff:badInput",
             "svfcutoff: segments must be an integer from 1 to %d (samples)",
             numel (t));
    endif
    K = double (K);
    Tseg = T / K;
    seg = min (floor (t / Tseg) + 1, K);
  endif
endfunction

## srivc's errors carry its name; re-raise them as this function's.
function rename_error (err)
  id = regexprep (err.identifier, '^srivc:', 'svfcutoff:');
  msg = regexprep (err.message, '^srivc:', 'svfcutoff: srivc:');
  error (struct ("message", msg, "identifier", id, "stack", err.stack));
endfunction

function plot_info (info, orders)
  tc = mean (info.segments, 2);
  subplot (2, 1, 1);
  K = rows (info.segments);
  hold on;
  for k = 1:K
    c = "b";
    if (! info.used(k))
      c = "r";
    endif
    plot (info.segments(k, :), info.bandwidth(k) * [1 1], c, "linewidth", 2);
  endfor
  plot (info.segments([1 end]), info.lambda * [1 1], "k--");
  hold off;
  ylabel ("\\omega_b (rad/s)");
  title (sprintf (["local bandwidths [%.3g, %.3g] rad/s; suggested ", ...
                   "\\lambda_{svf} = %.3g rad/s (dashed)"],
                  info.bwrange, info.lambda));
  grid on;
  subplot (2, 1, 2);
  names = [arrayfun(@(i) sprintf ("a_%d", i), 1:orders.na,
                    "uniformoutput", false), ...
           arrayfun(@(i) sprintf ("b_%d", i), 0:orders.nb-1,
                    "uniformoutput", false)];
  rel = info.theta ./ info.spread.mean;
  plot (tc, rel, "o-");
  legend (names{:}, "location", "eastoutside");
  xlabel ("time (s)");
  ylabel ("\\theta_i / mean");
  title ("local SRIVC parameters relative to their mean");
  grid on;
endfunction

%!shared Ts, u, N, t
%! Ts = 0.05; u = prbs (11, 6); N = numel (u); t = (0:N-1)' * Ts;

%!test  # noise-free LTI: the local models are the truth
%! x = simc (idctm (4, [1 2.4 4]), u, Ts);
%! [lam, info] = svfcutoff (iddata (x, u, Ts), [1 2 0], "segments", 4);
%! wb = 2 * sqrt (0.28 + sqrt (0.28 ^ 2 + 1));     # wn = 2, zeta = 0.6
%! ## The first segment starts at rest: exact. The others start from the
%! ## state left by the previous one, which SRIVC takes as zero: their
%! ## estimates carry that initial-condition error (0.5 % here).
%! assert (info.theta(1, :), [2.4 4 4], 1e-8);
%! assert (info.bandwidth(1), wb, 1e-8);
%! assert (info.theta, repmat ([2.4 4 4], 4, 1), 0.01 * 4);
%! assert (info.bandwidth, wb * ones (4, 1), 0.01 * wb);
%! assert (info.bwrange, [min(info.bandwidth), max(info.bandwidth)]);
%! assert (lam, 1.1 * max (info.bandwidth), 1e-12);
%! assert (info.spread.std, std (info.theta), 1e-12);
%! assert (info.samples([1 end]), [1 N]);
%! assert (all (info.used & info.stable));

%!test  # first-order plant whose pole jumps at the segment boundaries
%! a = [1 2 4 3];                                 # one value per segment
%! k = min (floor (t / (t(end) / 4)) + 1, 4);
%! theta = [a(k)', 2 * a(k)'];                    # static gain 2
%! x = simc (theta, [1 1 0], u, Ts);
%! [lam, info] = svfcutoff (iddata (x, u, Ts), [1 1 0], "segments", 4, ...
%!                          "factor", 1.25);
%! ## Each segment starts from the state the previous piece left, which
%! ## SRIVC does not model: a transient of a few 1/a s in 51 s.
%! assert (info.bandwidth, a', 0.02 * a');
%! assert (lam, 1.25 * max (info.bandwidth), 1e-12);
%! assert (info.bwrange, [min(info.bandwidth), max(info.bandwidth)]);

%!test  # noisy data: a varying and a constant parameter are told apart
%! randn ("state", 1);
%! wn = 2 * (1 + 0.3 * cos (2 * pi * t / t(end)));
%! x = simc ([1.2 * wn, wn .^ 2, 4 * ones(N, 1)], [2 1 0], u, Ts);
%! y = x + 0.02 * randn (N, 1);
%! [~, info] = svfcutoff (iddata (y, u, Ts), [1 2 0], "seglength", 40);
%! assert (rows (info.segments), floor (t(end) / 40));
%! assert (info.segments(end, 2), 40 * rows (info.segments), 1e-9);
%! assert (info.spread.varying, [true true false]);

%!test  # srivc options are passed on; seglength of the whole record
%! x = simc (idctm (4, [1 2.4 4]), u, Ts);
%! [lam, info] = svfcutoff (iddata (x, u, Ts), [1 2 0], "seglength", ...
%!                          t(end), "srivc", {"lambda", 3, "Tol", 1e-10});
%! assert (rows (info.segments), 1);
%! assert (info.theta, [2.4 4 4], 1e-8);

%!error id=svfcutoff:badInput svfcutoff (iddata (zeros (N, 1), [u u], Ts), [1 1 2 0 0])
%!error id=svfcutoff:badOption svfcutoff (iddata (u, u, Ts), [1 2 0], "segments", 2, "seglength", 10)
%!error id=svfcutoff:badInput svfcutoff (iddata (u, u, Ts), [1 2 0], "segments", 0)
%!error id=svfcutoff:badInput
%! svfcutoff (iddata (u, u, Ts), [1 2 0], "segments", 1e308);
%!error id=svfcutoff:badInput svfcutoff (iddata (u, u, Ts), [1 2 0], "segments", 2.5)
%!error id=svfcutoff:badInput svfcutoff (iddata (u, u, Ts), [1 2 0], "segments", "a")
%!error id=svfcutoff:badInput svfcutoff (iddata (u, u, Ts), [1 2 0], "seglength", -1)
%!error id=svfcutoff:badInput svfcutoff (iddata (u, u, Ts), [1 2 0], "seglength", 1e6)
%!error id=svfcutoff:badInput svfcutoff (iddata (u, u, Ts), [1 2 0], "factor", 0.9)
%!error id=svfcutoff:badInput svfcutoff (iddata (u, u, Ts), [1 2 0], "factor", [1 2])
%!error id=svfcutoff:badInput svfcutoff (iddata (u, u, Ts), [1 2 0], "srivc", "lambda")
%!error id=svfcutoff:badOption svfcutoff (iddata (u, u, Ts), [1 2 0], "srivc", {"bogus", 1})
%!error id=svfcutoff:badInput svfcutoff (iddata (u, u, Ts), [1 2 0], "srivc", {"lambda", -1})
%!error <too short> svfcutoff (iddata (u, u, Ts), [1 2 0], "segments", 500)
%!error id=svfcutoff:badInput svfcutoff (iddata (u, u, Ts), [1 2 0], "segments", 500)
%!error id=svfcutoff:badInput svfcutoff (iddata (u, u, Ts), [4 2 0])
%!error id=svfcutoff:badOption svfcutoff (iddata (u, u, Ts), [1 2 0], "bogus", 1)
%!error id=svfcutoff:badOption svfcutoff (iddata (u, u, Ts), [1 2 0], 3)
%!error id=svfcutoff:badInput svfcutoff (iddata (u, u, Ts))

%!demo
%! ## Local SRIVC models of a drifting resonance (cf. thesis sec. 2.3.5).
%! Ts = 0.05; u = prbs (12, 10); N = numel (u); t = (0:N-1)' * Ts;
%! wn = 2 * (1 + 0.3 * cos (2 * pi * t / t(end)));
%! y = simc ([1.2 * wn, wn .^ 2, wn .^ 2], [2 1 0], u, Ts) ...
%!     + 0.05 * randn (N, 1);
%! svfcutoff (iddata (y, u, Ts, "InterSample", "zoh"), [1 2 0], ...
%!            "segments", 8);
