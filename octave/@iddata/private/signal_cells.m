## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn {} {@var{c} =} signal_cells (@var{x}, @var{key}, @var{who}, @
##   @var{isout})
## Column cell with one signal matrix (samples in rows) per experiment.
##
## @var{x} is a matrix or a cell of matrices (the control package's
## multi-experiment form).  For the inputs an empty @var{x} gives
## @code{@{@}}, the control package's way of storing "no inputs"; for the
## outputs (@var{isout} true) @code{[]} and @code{@{@}} give one empty
## experiment.  Each matrix must be a numeric or logical 2-D array;
## @var{key} names the argument in error messages.
## @end deftypefn

function c = signal_cells (x, key, who, is_output)
  if (isempty (x) && (iscell (x) || ! is_output))
    if (is_output)
      c = {[]};
    else
      c = {};
    endif
    return;
  endif
  if (iscell (x))
    c = x(:);
  else
    c = {x};
  endif
  ok = cellfun (@(s) (isnumeric (s) || islogical (s)) && ndims (s) == 2, c);
  if (! all (ok))
    error ("iddata:badInput",
           ["%s: '%s' must be a numeric matrix with one row per sample ", ...
            "(or a cell of them, one per experiment)"], who, key);
  endif
endfunction
