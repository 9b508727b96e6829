## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn {} {[@var{theta}, @var{cov}, @var{info}] =} contsid_refined_iv (@var{fname}, @var{y}, @var{W}, @var{t}, @var{opts})
## The Octave entry point of the offline refined-IV engine
## (core/include/ctid/offline/refined_iv.hpp): LSSVF (thesis eq. 1.32), IVSVF
## (eqs. 2.4-2.7), SRIVC (eqs. 2.8-2.13) and CLSRIVC with a
## continuous-time controller (eqs. 2.47-2.50) for the model
## @example
## y(t) = sum_g x_g(t) + y0(t) + c + e(t)
## F_g(p) x_g(t) = sum_(j in g) B_j(p) w_j(t - nk_j Ts)
## @end example
## @var{fname} names the caller in every error identifier. @var{y}
## N-by-1; @var{W} N-by-m, one channel per column (inputs and extra
## regressors such as effect terms); @var{t} the sampling interval Ts or the
## N sampling instants. @var{opts} (a struct): the options of the core's
## table (core/include/ctid/offline/refined_iv_options.hpp, returned by
## @code{refined_iv_mex (fname, "options")}, which checks them and gives
## an absent one its default) and the ones converted here:
## @table @code
## @item nf
## order of each denominator F_g (required); one entry: common denominator.
## @item group, nb, nk
## per channel: its denominator (1-based, default all 1), numerator
## parameters (required), delay in samples (default 0).
## @item delay
## per channel, a continuous delay (time units, >= 0, default 0) on top of
## nk: any fraction of a sample, also on irregular data; the delayed
## ZOH/FOH input is filtered exactly.
## @item intersample
## per channel "zoh" or "foh" (a string for all, or a cellstr); default
## "zoh". @code{y_intersample}: the output's rule, default "foh".
## @item integrators
## per group, the number of poles at p = 0 (trailing f's fixed at 0).
## @item fixed, fixed_values
## a logical mask over theta and the values of the fixed entries.
## @item method
## "srivc" (default), "ivsvf" or "lssvf".
## @item theta_init, cutoffs, tol, maxiter, max_starts, time_scale, integrator_pole
## the start (theta in the layout below; empty: the automatic start
## from IVSVF at the cut-offs, 12 log-spaced between 5/T and 0.5 pi/Ts),
## the stop rule, how many starts SRIVC runs from, the time scale and
## the prefilter pole that replaces integrators.
## @item initial_state, output_offset, input_offset
## estimate the initial state (free responses, reported as the initial
## derivatives of each group's free response), an output offset c, and
## per channel an input offset d_j (a constant channel in its group).
## @item controller, reference
## closed loop u = r1 + C(p) (r - y): @code{controller} a struct with
## @code{num} and @code{den} (descending powers of p), @code{reference}
## r (N-by-1, the setpoint) or [r1 r] (N-by-2). One input, W = the
## measured u. With
## @code{controller.discrete} true, C(q^-1) = num/den in powers of q^-1
## in the loop u = r1 + C (r2 - y) (ZOH data) and @code{reference} =
## [r1 r2] (N-by-2).
## @item refit_integrators, integrator_start
## the engine's integrator refit (core refined_iv.hpp): after the fit
## (true), or alone of a given fit (a struct with its @code{theta} and
## the fields @code{converged}, @code{stable}, @code{simulated},
## @code{reason}, @code{lowest_theta}, @code{lowest_simulated} of its
## @var{info}, @code{suspected} and @code{lowest_suspected} its
## @code{integrator_suspected} and @code{lowest_integrator_suspected});
## @var{info}.integrators and @var{info}.integrator_refit report it.
## @item delay_search
## the delay of the one channel searched (refined_iv_mex's method
## 'delay_search', core refined_iv_delay.hpp): a struct of the search's
## options; @var{info}.delay_search holds its result and @var{info} the
## engine's (RIVC's with a noise model) at the delay kept.
## @end table
##
## @var{theta} = [f of each group (f1 .. f_nf), b of each channel
## (descending powers of p), c if estimated]; @var{cov} its covariance
## (zero for fixed entries; for SRIVC sigma^2 (sum zeta_f zeta_f')^-1 per
## group, eq. 2.13). @var{info}: @code{converged}, @code{stable},
## @code{iterations}, @code{reason}, @code{noise_variance} (simulation
## error variance), @code{cutoff}, @code{time_scale}, @code{starts},
## @code{condition}, @code{x0}, @code{offset}, @code{input_offset},
## @code{simulated} (the model's output incl. y0 and c),
## @code{free_response}, @code{F} (cell, [1 f..] per group), @code{B}
## (cell, per channel), @code{determined}, @code{clipped},
## @code{clipped_iterations}, @code{integrator_suspected},
## @code{loss_history}, and @code{lowest_theta} (layout of @var{theta}),
## @code{lowest_noise_variance}, @code{lowest_integrator_suspected},
## @code{lowest_simulated}: the lowest-loss stable iterate over all starts
## when it did not converge and is not the model returned (empty
## @code{lowest_theta} otherwise). SRIVC that does not converge returns its last
## iterate with @code{info.converged} false (no warning here: the caller
## reports it).
## @end deftypefn

function [theta, cov, info] = contsid_refined_iv (fname, y, W, t, opts)
  if (nargin < 5)
    opts = struct ();
  endif
  if (! isstruct (opts) || ! isscalar (opts))
    error ([fname ":badInput"], "%s: the engine options must be a struct",
           fname);
  endif
  ## The fields converted here; every other one is an option of the
  ## gateway, which checks it and gives an absent one its default
  ## (core/include/ctid/offline/refined_iv_options.hpp).
  own = {"integrators", "input_offset", "controller", "reference", ...
         "delay_search", "fixed", "fixed_values", "theta_init", ...
         "integrator_start"};
  g = rmfield (opts, intersect (fieldnames (opts), own));
  if (! isfield (opts, "nf") || ! isfield (opts, "nb"))
    error ([fname ":badOption"], "%s: the engine needs nf and nb", fname);
  endif
  m = columns (W);
  g.nf = double (opts.nf(:).');
  g.nb = double (opts.nb(:).');
  g.group = get_or (opts, "group", ones (1, m));
  g.nk = get_or (opts, "nk", zeros (1, m));
  g.delay = double (get_or (opts, "delay", zeros (1, m)));
  if (numel (g.nb) != m || numel (g.group) != m || numel (g.nk) != m
      || numel (g.delay) != m)
    error ([fname ":dimensionMismatch"],
           "%s: nb, nk, delay and group need one entry per channel (%d)",
           fname, m);
  endif
  g.intersample = rule_codes (fname, get_or (opts, "intersample", "zoh"), m);
  if (isfield (opts, "y_intersample"))
    g.y_intersample = rule_codes (fname, opts.y_intersample, 1);
  endif
  c = (isfield (g, "output_offset") && ! isempty (g.output_offset)
       && g.output_offset);

  ## Input offsets: one constant channel (nb = 1) in the input's group.
  in_off = logical (get_or (opts, "input_offset", false(1, m)));
  if (isscalar (in_off))
    in_off = repmat (in_off, 1, m);
  endif
  if (numel (in_off) != m)
    error ([fname ":dimensionMismatch"],
           "%s: input_offset needs one entry per channel", fname);
  endif
  extra = find (in_off);
  n = rows (W);
  Wx = [W, ones(n, numel (extra))];
  g.group = [g.group(:).', g.group(extra)];
  g.nb = [g.nb, ones(1, numel (extra))];
  g.nk = [g.nk(:).', zeros(1, numel (extra))];
  g.delay = [g.delay(:).', zeros(1, numel (extra))];
  g.intersample = [g.intersample, zeros(1, numel (extra))];

  ## The full layout (with the constant channels) and its fixed mask.
  nfx = sum (g.nf);
  np_user = nfx + sum (g.nb(1:m)) + c;
  np = nfx + sum (g.nb) + c;
  keep = 1:nfx + sum (g.nb(1:m));
  if (c)
    keep(end+1) = np;
  endif
  fixed = false (np, 1);
  values = zeros (np, 1);
  if (isfield (opts, "fixed") && ! isempty (opts.fixed))
    if (numel (opts.fixed) != np_user || ! isfield (opts, "fixed_values")
        || numel (opts.fixed_values) != np_user)
      error ([fname ":dimensionMismatch"],
             "%s: fixed and fixed_values need %d entries", fname, np_user);
    endif
    fixed(keep) = logical (opts.fixed(:));
    values(keep) = double (opts.fixed_values(:));
  endif
  integ = get_or (opts, "integrators", zeros (1, numel (g.nf)));
  if (numel (integ) != numel (g.nf) || any (integ < 0)
      || any (integ > g.nf))
    error ([fname ":badOption"],
           "%s: integrators needs one count (0..nf) per denominator", fname);
  endif
  off = 0;
  for k = 1:numel (g.nf)
    idx = off + (g.nf(k) - integ(k) + 1:g.nf(k));
    fixed(idx) = true;
    values(idx) = 0;
    off += g.nf(k);
  endfor
  if (any (fixed))
    g.fixed = double (fixed);
    g.fixed_values = values;
  endif
  if (isfield (opts, "theta_init") && ! isempty (opts.theta_init))
    if (c && numel (opts.theta_init) == np_user - 1)
      opts.theta_init(end+1) = 0;      # c is re-estimated at every step
    endif
    if (numel (opts.theta_init) != np_user)
      error ([fname ":dimensionMismatch"],
             "%s: theta_init needs %d entries", fname, np_user);
    endif
    th = zeros (np, 1);
    th(keep) = opts.theta_init(:);
    g.theta_init = th;
  endif
  if (isfield (opts, "integrator_start"))
    ## the fit's parameters, in the full layout
    g.integrator_start = opts.integrator_start;
    for f = {"theta", "lowest_theta"}
      if (! isempty (g.integrator_start.(f{1})))
        th = zeros (np, 1);
        th(keep) = g.integrator_start.(f{1})(:);
        g.integrator_start.(f{1}) = th;
      endif
    endfor
  endif
  r = [];
  if (isfield (opts, "controller") && ! isempty (opts.controller))
    g.controller_num = double (opts.controller.num(:));
    g.controller_den = double (opts.controller.den(:));
    g.discrete_controller = isfield (opts.controller, "discrete") ...
                            && opts.controller.discrete;
    r = double (opts.reference);
  endif
  if (isfield (opts, "delay_search"))
    [th, P, info] = refined_iv_mex (fname, "delay_search", double (y(:)),
                                    double (Wx), double (t), r, g,
                                    opts.delay_search);
  else
    [th, P, info] = refined_iv_mex (fname, double (y(:)), double (Wx),
                                    double (t), r, g);
  endif
  ## Input offsets d_j = (constant channel coefficient) / b_j(end).
  info.input_offset = zeros (1, m);
  boff = nfx + cumsum ([0, g.nb]);
  for k = 1:numel (extra)
    j = extra(k);
    info.input_offset(j) = th(boff(m + k) + 1) / th(boff(j) + g.nb(j));
  endfor
  theta = th(keep);
  cov = P(keep, keep);
  if (isfield (info, "lowest_theta") && ! isempty (info.lowest_theta))
    info.lowest_theta = info.lowest_theta(keep);
  endif
  info.F = cell (1, numel (g.nf));
  off = 0;
  for k = 1:numel (g.nf)
    info.F{k} = [1, theta(off + (1:g.nf(k))).'];
    off += g.nf(k);
  endfor
  info.B = cell (1, m);
  for j = 1:m
    info.B{j} = theta(off + (1:g.nb(j))).';
    off += g.nb(j);
  endfor
endfunction

function v = get_or (s, name, default)
  if (isfield (s, name) && ! isempty (s.(name)))
    v = s.(name);
  else
    v = default;
  endif
endfunction

function codes = rule_codes (fname, rule, m)
  if (ischar (rule))
    rule = repmat ({rule}, 1, m);
  endif
  if (! iscellstr (rule) || numel (rule) != m)
    error ([fname ":badOption"],
           "%s: intersample must be 'zoh'/'foh' or a cell of %d of them",
           fname, m);
  endif
  codes = zeros (1, m);
  for j = 1:m
    switch (lower (rule{j}))
      case "zoh"
        codes(j) = 0;
      case "foh"
        codes(j) = 1;
      otherwise
        error ([fname ":badOption"],
               "%s: intersample must be 'zoh' or 'foh', got '%s'", fname,
               rule{j});
    endswitch
  endfor
endfunction
