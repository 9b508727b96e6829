## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn {} {@var{nn} =} parsimonious_structure (@var{V})
## The structure rule of the residtrace studies (@code{residtrace_lab_rigs},
## @code{residtrace_cascaded_tanks}), a user's choice from the table
## @var{V} of @code{srivcstruc (..., "NN", "list")} (rows [RT2, YIC, nb,
## nf, nk, ...]): of the structures whose validation residual variance
## (1 - R_T^2) is within 10 % of the smallest, the one with the fewest
## parameters, then the best R_T^2. The plain best R_T^2 can be a
## structure with a spurious pole (the simulated conveyor of
## @code{lab_rigs}: a time constant of 3e-10 s).
## @end deftypefn

function nn = parsimonious_structure (V)
  r = 1 - V(:,1);
  ok = isfinite (r) & r <= 1.1 * min (r);
  npar = sum (V(:,3:4), 2);
  npar(! ok) = Inf;
  cand = find (npar == min (npar));
  [~, j] = min (r(cand));
  nn = V(cand(j), 3:end-2);
endfunction
