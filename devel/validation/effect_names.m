## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn {} {@var{c} =} effect_names (@var{e})
## @code{R.effects} of @code{residtrace} as a row cell of names, whatever
## its form (a cellstr, one name, a struct array with field
## @code{effect}, or a cell of those); used by the residtrace studies.
## @end deftypefn

function c = effect_names (e)
  if (iscellstr (e))
    c = e(:).';
  elseif (ischar (e))
    c = {e};
  elseif (isstruct (e) && isfield (e, "effect"))
    c = {e.effect};
  elseif (iscell (e))
    c = cellfun (@(x) disp_name (x), e, "UniformOutput", false);
    c = c(:).';
  else
    c = {};
  endif
endfunction

function n = disp_name (x)
  if (ischar (x))
    n = x;
  elseif (isstruct (x) && isfield (x, "effect"))
    n = x.effect;
  else
    n = "?";
  endif
endfunction

