## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn {} {@var{P} =} pstruct (@var{M})
## The plain struct behind a model object (its idmodel part), for the
## private helpers of the class, which must not index the object itself
## (that would call the overloaded subsref).
## @end deftypefn

function P = pstruct (M)
  P = struct (M);
  if (isfield (P, "idmodel"))
    P = struct (P.idmodel);
  endif
endfunction
