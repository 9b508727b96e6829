## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn {} {[@var{t}, @var{x}, @var{y}, @var{u}] =} pde_heat_data @
##   (@var{fname}, @var{Data1}, @var{Data2}, @var{need_output})
## Reads the CONTSID heat-equation data structures: @var{Data2}.t (time
## grid) and @var{Data2}.x (space grid) as rows, @var{Data1}.Input (and
## @var{Data1}.Output when @var{need_output}) as numel(t)-by-numel(x)
## fields (one row per instant, one column per node).  Errors
## @code{@var{fname}:badInput} and @code{@var{fname}:dimensionMismatch}.
## @end deftypefn

function [t, x, y, u] = pde_heat_data (fname, Data1, Data2, need_output)
  if (! isstruct (Data2) || ! isscalar (Data2) || ! isfield (Data2, "t")
      || ! isfield (Data2, "x"))
    error ([fname ":badInput"],
           "%s: Data2 must be a struct with fields t (time) and x (space)",
           fname);
  endif
  t = grid_row (fname, Data2.t, "Data2.t");
  x = grid_row (fname, Data2.x, "Data2.x");
  if (! isstruct (Data1) || ! isscalar (Data1) || ! isfield (Data1, "Input"))
    error ([fname ":badInput"],
           "%s: Data1 must be a struct with the field Input", fname);
  endif
  u = field (fname, Data1.Input, "Data1.Input", t, x);
  y = [];
  if (need_output)
    if (! isfield (Data1, "Output"))
      error ([fname ":badInput"], "%s: Data1 has no field Output", fname);
    endif
    y = field (fname, Data1.Output, "Data1.Output", t, x);
  endif
endfunction

function v = grid_row (fname, v, what)
  if (! (isnumeric (v) && isreal (v) && isvector (v) && numel (v) >= 2
         && all (isfinite (v))))
    error ([fname ":badInput"],
           "%s: %s must be a finite real vector of at least 2 points",
           fname, what);
  endif
  v = full (double (v(:).'));
  if (any (diff (v) <= 0))
    error ([fname ":badInput"], "%s: %s must be strictly increasing",
           fname, what);
  endif
endfunction

function f = field (fname, f, what, t, x)
  if (! (isnumeric (f) && isreal (f) && ismatrix (f)))
    error ([fname ":badInput"], "%s: %s must be a real matrix", fname, what);
  endif
  if (! isequal (size (f), [numel(t), numel(x)]))
    error ([fname ":dimensionMismatch"],
           "%s: %s must be numel(Data2.t)-by-numel(Data2.x) = %d-by-%d, got %d-by-%d",
           fname, what, numel (t), numel (x), rows (f), columns (f));
  endif
  if (! all (isfinite (f(:))))
    error ([fname ":badInput"], "%s: %s must be finite", fname, what);
  endif
  f = full (double (f));
endfunction
