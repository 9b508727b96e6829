## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn {} {@var{nu} =} plain_gpmf_coupling (@var{nni}, @var{i}, @var{j})
## How many derivatives of output @var{j} enter output equation @var{i} of
## the observable canonical form with indices @var{nni} (as the core's
## coupling_degree), for the plain-Octave GPMF benchmarks.
## @end deftypefn

function nu = plain_gpmf_coupling (nni, i, j)
  if (j == i)
    nu = nni(i);
  elseif (j < i)
    nu = min (nni(i) + 1, nni(j));
  else
    nu = min (nni(i), nni(j));
  endif
endfunction
