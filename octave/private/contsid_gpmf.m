## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn {} {[@var{M}, @var{sv}] =} contsid_gpmf (@var{fname}, @var{args})
## Shared back-end of the GPMF state-space estimators @code{sslsgpmf}
## (@var{fname} = @qcode{"sslsgpmf"}), @code{ssivgpmf}, @code{ssbcgpmf}
## and @code{sidgpmf}: reads @code{(data, nni, param[, n0])}, for
## @code{ssbcgpmf} @code{(data, nni, param, root[, n0])} or, for
## @code{sidgpmf}, @code{(data, i, j, lambda[, n, n0])} from the cell
## @var{args}, checks it
## (errors @code{@var{fname}:badInput}, @code{:dimensionMismatch},
## @code{:notSupported}), runs the core estimator through
## @code{gpmf_mex} and returns the continuous-time @code{idss} model
## (and, for @code{sidgpmf}, the singular values @var{sv}; for
## @code{ssbcgpmf}, the estimated output noise variances).
## @seealso{sslsgpmf, ssivgpmf, ssbcgpmf, sidgpmf}
## @end deftypefn

function [M, sv] = contsid_gpmf (fname, args)
  [y, u, t, rule] = read_data (fname, args{1});
  if (strcmp (fname, "sidgpmf"))
    opts = sid_options (fname, args(2:end), rows (y));
  else
    opts = canonical_options (fname, args(2:end), columns (y), rows (y));
  endif
  if (strcmp (fname, "ssbcgpmf") && ! isscalar (t))
    error ([fname ":notSupported"],
           "%s: bias compensation needs uniformly sampled data", fname);
  endif
  opts.intersample = lower (rule);
  try
    [A, B, C, D, sv] = gpmf_mex (fname, y, u, t, opts);
  catch err
    contsid_rethrow (err);
  end_try_catch
  M = idss (A, B, C, D);
  M.Ts = 0;
endfunction

function [y, u, t, rule] = read_data (fname, data)
  if (! isa (data, "iddata") || numel (data) != 1)
    error ([fname ":badInput"], "%s: 'data' must be one iddata object",
           fname);
  endif
  s = struct (data);
  if (! s.timedomain || numel (s.y) != 1)
    error ([fname ":badInput"],
           "%s: 'data' must be time-domain data with one experiment", fname);
  endif
  y = double (s.y{1});
  u = double (s.u{1});
  if (isempty (u) || isempty (y))
    error ([fname ":badInput"], "%s: 'data' needs outputs and inputs", fname);
  endif
  if (! isreal (y) || ! isreal (u) || ! all (isfinite ([y(:); u(:)])))
    error ([fname ":badInput"], "%s: 'data' must be real and finite", fname);
  endif
  info = samplinginfo (data);
  if (! info.Uniform)
    t = info.SamplingInstants(:);
  elseif (info.Ts > 0)
    t = info.Ts;
  else
    error ([fname ":badInput"], "%s: 'data' has no sampling interval", fname);
  endif
  rule = info.InterSample;
  if (iscell (rule))
    if (! all (strcmpi (rule, rule{1})))
      error ([fname ":notSupported"],
             "%s: all inputs must share one InterSample rule", fname);
    endif
    rule = rule{1};
  endif
  if (! any (strcmpi (rule, {"zoh", "foh"})))
    error ([fname ":notSupported"],
           "%s: InterSample must be 'zoh' or 'foh', not '%s'", fname, rule);
  endif
endfunction

function opts = canonical_options (fname, args, ny, N)
  [nni, param] = args{1:2};
  if (! isnumeric (nni) || ! isreal (nni) || isempty (nni)
      || any (nni(:) < 1) || any (nni(:) != fix (nni(:))))
    error ([fname ":badInput"],
           "%s: 'nni' must hold positive integer observability indices",
           fname);
  endif
  if (numel (nni) != ny)
    error ([fname ":dimensionMismatch"],
           "%s: 'nni' needs one index per output (%d), got %d", fname, ny,
           numel (nni));
  endif
  if (! isnumeric (param) || ! isreal (param) || isempty (param)
      || ! all (isfinite (param(:))) || any (param(:) <= 0))
    error ([fname ":badInput"],
           "%s: 'param' must hold positive filter parameters", fname);
  endif
  if (numel (param) != ny)
    error ([fname ":dimensionMismatch"],
           "%s: 'param' needs one filter parameter per output (%d), got %d",
           fname, ny, numel (param));
  endif
  method = struct ("sslsgpmf", "ls", "ssivgpmf", "iv",
                   "ssbcgpmf", "bc").(fname);
  if (strcmp (method, "bc"))
    root = args{3};
    if (! isnumeric (root) || ! isreal (root) || isempty (root)
        || ndims (root) != 2 || ! all (isfinite (root(:))) || any (root(:) >= 0))
      error ([fname ":badInput"],
             "%s: 'root' must hold finite negative filter roots", fname);
    endif
    if (rows (root) == 1)
      root = repmat (root, ny, 1);
    elseif (rows (root) != ny)
      error ([fname ":dimensionMismatch"],
             "%s: 'root' needs one row per output (%d) or one row, got %d",
             fname, ny, rows (root));
    endif
    n0 = first_sample (fname, args, 4, N);
  else
    n0 = first_sample (fname, args, 3, N);
  endif
  opts = struct ("method", method, "nni", double (nni(:)'),
                 "lambda", double (param(:)), "n0", n0);
  if (strcmp (method, "bc"))
    opts.root = double (root);
  endif
endfunction

function opts = sid_options (fname, args, N)
  [i, j, lambda] = args{1:3};
  if (! is_count (i) || i < 2)
    error ([fname ":badInput"], "%s: 'i' must be an integer >= 2", fname);
  endif
  if (! is_count (j) || j < i - 1 || j > 20)
    error ([fname ":badInput"],
           "%s: 'j' must be an integer in i-1 .. 20 (j >= i advised)", fname);
  endif
  if (! isnumeric (lambda) || ! isreal (lambda) || ! isscalar (lambda)
      || ! isfinite (lambda) || lambda <= 0)
    error ([fname ":badInput"],
           "%s: 'lambda' must be a positive scalar", fname);
  endif
  n = 0;
  if (numel (args) >= 4 && ! isempty (args{4}))
    n = args{4};
    if (! is_count (n) || n < 1)
      error ([fname ":badInput"], "%s: 'n' must be a positive integer",
             fname);
    endif
  endif
  opts = struct ("method", "sid", "i", double (i), "j", double (j),
                 "lambda", double (lambda), "n", double (n),
                 "n0", first_sample (fname, args, 5, N));
endfunction

function tf = is_count (x)
  tf = (isnumeric (x) && isreal (x) && isscalar (x) && isfinite (x)
        && x == fix (x));
endfunction

function n0 = first_sample (fname, args, k, N)
  n0 = 1;
  if (numel (args) >= k && ! isempty (args{k}))
    n0 = args{k};
    if (! is_count (n0) || n0 < 1 || n0 > N)
      error ([fname ":badInput"],
             "%s: 'n0' must be a sample index in 1..%d", fname, N);
    endif
    n0 = double (n0);
  endif
endfunction
