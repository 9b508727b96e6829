## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn {} {[@var{num}, @var{den}] =} contsid_controller (@var{fname}, @var{C}, @var{Ts})
## The discrete controller C(q^-1) = num(q^-1) / den(q^-1) of a closed loop
## u = r1 + C (r2 - y), from any of the forms the toolbox accepts:
## @itemize
## @item a struct with fields @code{num} and @code{den} (coefficients of
## q^0, q^-1, ..);
## @item a struct with @code{kp}, @code{ki}, @code{kd}: the backward-Euler
## PID kp + ki Ts/(1 - q^-1) + (kd/Ts)(1 - q^-1), the reading of thesis
## eq. (2.55) that keeps its example 2.4.6 stable (needs a constant
## @var{Ts});
## @item a discrete-time @code{tf} of the control package.
## @end itemize
## Errors carry the identifier @var{fname}:badInput.
## @end deftypefn

function [num, den] = contsid_controller (fname, C, Ts)
  id = [fname ":badInput"];
  if (isa (C, "tf"))
    if (isct (C))
      error (id, "%s: the controller must be discrete-time", fname);
    endif
    [num, den] = tfdata (C, "vector");
    len = max (numel (num), numel (den));
    num = [zeros(1, len - numel (num)), num];   # powers of z -> of q^-1
    den = [den, zeros(1, len - numel (den))];
    return;
  endif
  if (isstruct (C) && isscalar (C) && all (isfield (C, {"kp", "ki", "kd"})))
    g = {C.kp, C.ki, C.kd};
    if (! all (cellfun (@is_finite_scalar, g)))
      error (id, "%s: the PID gains kp, ki, kd must be real scalars", fname);
    endif
    if (! is_finite_scalar (Ts) || Ts <= 0)
      error (id, "%s: a PID controller needs a constant sampling interval",
             fname);
    endif
    [kp, ki, kd] = g{:};
    C = struct ("num", [kp + ki * Ts + kd / Ts, -kp - 2 * kd / Ts, kd / Ts],
                "den", [1 -1]);
  endif
  if (! isstruct (C) || ! isscalar (C) || ! all (isfield (C, {"num", "den"})))
    error (id, ["%s: the controller must be a struct with num and den ", ...
                "(powers of q^-1), one with kp, ki and kd, or a discrete tf"],
           fname);
  endif
  num = C.num;
  den = C.den;
  if (! isnumeric (num) || ! isnumeric (den) || ! isreal (num)
      || ! isreal (den) || isempty (num) || isempty (den) || ! isvector (num)
      || ! isvector (den) || any (! isfinite ([num(:); den(:)])) || den(1) == 0)
    error (id, ["%s: the controller's num and den must be finite real ", ...
                "vectors with den(1) != 0"], fname);
  endif
  num = double (num(:).');
  den = double (den(:).');
endfunction

function tf = is_finite_scalar (v)
  tf = isnumeric (v) && isreal (v) && isscalar (v) && isfinite (v);
endfunction
