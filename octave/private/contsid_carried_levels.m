## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn {} {[@var{c}, @var{d}] =} contsid_carried_levels (@var{M}, @var{nu})
## The output offset @var{c} and the input offsets @var{d} (1-by-@var{nu})
## that @var{M} carries in @code{Report.DataUsed} (@code{srivc}'s
## estimated levels, MATLAB's convention: y - c = M (u - d)); zeros for a
## model without them or without a Report. Read by residtrace and
## srivcstruc to simulate a model as it was estimated.
## @end deftypefn

function [c, d] = contsid_carried_levels (M, nu)
  c = 0;
  d = zeros (1, nu);
  try
    lev = get (M, "Report").DataUsed;
  catch
    return;                            # a model class without a Report
  end_try_catch
  if (isfield (lev, "OutputOffset") && isscalar (lev.OutputOffset)
      && isfinite (lev.OutputOffset))
    c = double (lev.OutputOffset);
  endif
  if (isfield (lev, "InputOffset") && numel (lev.InputOffset) == nu
      && all (isfinite (lev.InputOffset(:))))
    d = double (lev.InputOffset(:).');
  endif
endfunction
