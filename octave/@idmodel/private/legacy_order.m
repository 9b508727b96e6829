## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn {} {@var{T} =} legacy_order (@var{P})
## The map from CONTSID's theta to the idpoly parameter vector (order A,
## B, C, D, F): pvec = T theta.  theta holds the denominators (A, then F)
## before the numerators B; a denominator common to all inputs (every F
## equal, as CONTSID's SRIVC with one denominator returns it) appears once
## in theta and once per input in pvec.
## @end deftypefn

function T = legacy_order (P)
  s = P.par;
  na = numel (s.A) - 1;
  nbj = cellfun ("numel", s.B);
  nb = sum (nbj);
  nc = numel (s.C) - 1;
  nd = numel (s.D) - 1;
  nfj = cellfun ("numel", s.F) - 1;
  np = na + nb + nc + nd + sum (nfj);
  common = (P.nu > 1 && nfj(1) > 0 && nc == 0 && nd == 0
            && all (cellfun (@(f) isequal (f, s.F{1}), s.F)));
  if (common)
    nth = na + nfj(1) + nb;
    T = zeros (np, nth);
    T(1:na, 1:na) = eye (na);
    T(na + (1:nb), na + nfj(1) + (1:nb)) = eye (nb);
    for j = 1:P.nu
      rows_ = na + nb + (j - 1) * nfj(1) + (1:nfj(1));
      T(rows_, na + (1:nfj(1))) = eye (nfj(1));
    endfor
  else
    ## A noise model C/D (rivc's hybrid model) is not part of CONTSID's
    ## theta: its rows of T are zero.
    k = [1:na, na+nb+nc+nd+(1:sum (nfj)), na+(1:nb)];
    T = zeros (np, numel (k));
    T(sub2ind ([np numel(k)], k, 1:numel (k))) = 1;
  endif
endfunction
