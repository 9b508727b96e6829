## -*- texinfo -*-
## @deftypefn {} {@var{k} =} legacy_order (@var{P})
## Indices into the idpoly parameter vector (order A, B, C, D, F) that
## give CONTSID's theta order: the denominator(s) A and F, then the
## numerators B.
## @end deftypefn

function k = legacy_order (M)
  p = M.par;
  na = numel (p.A) - 1;
  nb = sum (cellfun ("numel", p.B));
  nc = numel (p.C) - 1;
  nd = numel (p.D) - 1;
  nf = sum (cellfun ("numel", p.F) - 1);
  k = [1:na, na+nb+nc+nd+(1:nf), na+(1:nb)];
endfunction

