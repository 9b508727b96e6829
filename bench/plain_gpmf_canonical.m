## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn {} {[@var{A}, @var{B}] =} plain_gpmf_canonical (@var{thetas}, @var{nni}, @var{m})
## The observable canonical realisation of the GPMF output equations, in
## plain Octave, for the speed benchmarks of the GPMF estimators (as the
## core's canonical_model): @var{thetas}@{i@} holds output i's
## [alpha_(i1,0..nu_i1-1) .. alpha_(ip,..) beta_(i1,0..n_i-1) ..
## beta_(im,..)] for observability indices @var{nni} and @var{m} inputs.
## @end deftypefn

function [A, B] = plain_gpmf_canonical (thetas, nni, m)
  p = numel (nni);
  n = sum (nni);
  starts = cumsum ([0, nni(1:end-1)]);
  A = zeros (n);
  T = zeros (n);
  beta = zeros (n, m);
  for i = 1:p
    theta = thetas{i};
    s = starts(i);
    A(s+1:s+nni(i)-1, s+2:s+nni(i)) = eye (nni(i) - 1);
    for d = 0:nni(i)-1
      T(s+d+1, s+nni(i)-d) = 1;
    endfor
    off = 0;
    for j = 1:p
      for k = 0:plain_gpmf_coupling (nni, i, j)-1
        off += 1;
        A(s+nni(i), starts(j)+k+1) = -theta(off);
        for d = 0:k-1
          T(s+d+1, starts(j)+k-d) += theta(off);
        endfor
      endfor
    endfor
    beta(s+1:s+nni(i), :) = reshape (theta(off+1:end), nni(i), m);
  endfor
  B = T \ beta;
endfunction
