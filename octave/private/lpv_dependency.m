## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn {} {[@var{flat}, @var{dims}] =} lpv_dependency (@var{fname}, @var{dep}, @var{name})
## Check a dependency array of the LPV functions (CONTSID's DepA or DepB:
## @var{n_dep}-by-@var{n}-by-@var{N}, basis function j of coefficient i at
## sample k in @code{@var{dep}(j, i, k)}) and return it reshaped to
## @var{n_dep}-by-(@var{n}*@var{N}) with its sizes @var{dims} =
## [@var{n_dep} @var{n} @var{N}], as the gateway @code{lpv_mex} takes it.
## Errors @code{@var{fname}:badInput} for a non-numeric, complex,
## non-finite, empty or more than 3-D array.
## @end deftypefn

function [flat, dims] = lpv_dependency (fname, dep, name)
  if (! (isnumeric (dep) || islogical (dep)) || ! isreal (dep)
      || isempty (dep) || ndims (dep) > 3)
    error ([fname ":badInput"],
           "%s: %s must be a real n_dep-by-n-by-N array (basis function, coefficient, sample)",
           fname, name);
  endif
  dep = double (dep);
  if (! all (isfinite (dep(:))))
    error ([fname ":badInput"], "%s: %s must be finite", fname, name);
  endif
  dims = [size(dep, 1), size(dep, 2), size(dep, 3)];
  flat = reshape (dep, dims(1), dims(2) * dims(3));
endfunction
