## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn {} {@var{M} =} contsid_gpmf (@var{fname}, @var{args})
## Shared back-end of the GPMF state-space estimators @code{sslsgpmf}
## (@var{fname} = @qcode{"sslsgpmf"}) and @code{ssivgpmf}: reads
## @code{(data, nni, param[, n0])} from the cell @var{args}, checks it
## (errors @code{@var{fname}:badInput}, @code{:dimensionMismatch},
## @code{:notSupported}), runs the core estimator through
## @code{gpmf_mex} and returns the continuous-time @code{idss} model.
## @seealso{sslsgpmf, ssivgpmf}
## @end deftypefn

function M = contsid_gpmf (fname, args)
  contsid_nargchk (fname, numel (args), 1, [3 4], 1);
  [data, nni, param] = args{1:3};
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
  ny = columns (y);
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
  n0 = 1;
  if (numel (args) >= 4 && ! isempty (args{4}))
    n0 = args{4};
    if (! isnumeric (n0) || ! isscalar (n0) || n0 < 1 || n0 != fix (n0)
        || n0 > rows (y))
      error ([fname ":badInput"],
             "%s: 'n0' must be a sample index in 1..%d", fname, rows (y));
    endif
  endif
  method = struct ("sslsgpmf", "ls", "ssivgpmf", "iv").(fname);
  opts = struct ("method", method, "nni", double (nni(:)'),
                 "lambda", double (param(:)), "n0", double (n0),
                 "intersample", lower (rule));
  try
    [A, B, C, D] = gpmf_mex (fname, y, u, t, opts);
  catch err
    contsid_rethrow (err);
  end_try_catch
  M = idss (A, B, C, D);
  M.Ts = 0;
endfunction
