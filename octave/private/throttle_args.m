## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn {} {[@var{gw}, @var{p}, @var{loop}] =} @
##   throttle_args (@var{fname}, @var{params}, @var{loop})
## Shared argument check of throttlesim and throttleid: the plant
## parameters @var{params} and the loop @var{loop} as structs whose fields
## override those of @code{throttleparams} ([] for the defaults).
##
## Returns @var{gw}, the fields of the gateway's options struct they give
## (mex/throttle_mex.cpp): @code{plant} (the 18 parameters by name),
## @code{pid_num}, @code{pid_den} (the PID of eq. 4.13 written as a
## transfer function in q^-1), @code{filter_num}, @code{filter_den} and
## @code{umax}; the full struct @var{p} and the full @var{loop} struct.
## Errors carry the identifiers @var{fname}:badOption (unknown field, not a
## struct) and @var{fname}:badInput (a value that is not a real finite
## scalar, a filter that is not a pair of real vectors).
## @end deftypefn

function [gw, p, loop] = throttle_args (fname, params, loop_in)
  [p, loop] = throttleparams ();
  p = override (fname, p, params, "params");

  loop = override (fname, loop, loop_in, "loop");
  if (! (loop.Ts > 0))
    error ([fname ":badInput"], "%s: loop.Ts must be > 0", fname);
  endif
  if (! (loop.umax > 0))
    error ([fname ":badInput"], "%s: loop.umax must be > 0 (Inf: no limit)",
           fname);
  endif
  kp = loop.kp; ki = loop.ki; kd = loop.kd;
  pid_num = [kp + ki + kd, -kp - 2 * kd, kd];
  pid_den = [1 -1];
  f = loop.setpoint_filter;
  gw = struct ("plant", p, "pid_num", pid_num, "pid_den", pid_den,
               "filter_num", f.num, "filter_den", f.den, "umax", loop.umax);
endfunction

function s = override (fname, s, given, what)
  if (isempty (given))
    return;
  endif
  if (! (isstruct (given) && isscalar (given)))
    error ([fname ":badOption"], "%s: %s must be a scalar struct", fname,
           what);
  endif
  known = fieldnames (s);
  fields = fieldnames (given);
  for k = 1:numel (fields)
    f = fields{k};
    if (! any (strcmp (f, known)))
      error ([fname ":badOption"], "%s: unknown field '%s' in %s (known: %s)",
             fname, f, what, strjoin (known.', ", "));
    endif
    v = given.(f);
    if (strcmp (f, "setpoint_filter"))
      if (! (isstruct (v) && isscalar (v) && all (isfield (v, {"num", "den"})))
          || ! is_real_vector (v.num) || ! is_real_vector (v.den)
          || v.den(1) == 0)
        error ([fname ":badInput"],
               ["%s: loop.setpoint_filter must be a struct with real ", ...
                "finite vectors num and den (den(1) != 0)"], fname);
      endif
      v = struct ("num", double (v.num(:).'), "den", double (v.den(:).'));
    elseif (! (isnumeric (v) && isreal (v) && isscalar (v) && ! isnan (v)
               && (isfinite (v) || strcmp (f, "umax"))))
      error ([fname ":badInput"], "%s: %s.%s must be a real finite scalar",
             fname, what, f);
    else
      v = double (v);
    endif
    s.(f) = v;
  endfor
endfunction

function tf = is_real_vector (v)
  tf = (isnumeric (v) && isreal (v) && isvector (v) && ! isempty (v)
        && all (isfinite (v)));
endfunction
