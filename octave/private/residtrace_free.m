## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn {} {@var{X} =} residtrace_free (@var{F}, @var{N}, @var{Ts})
## Free responses of the model 1/F(p) in observable canonical form (x1 =
## y, A = [-f, [I; 0]]): column k is the output at the N samples started
## from the k-th unit state with no input, y(t) = C expm (A t) e_k, by the
## exact one-step map expm (A Ts): row t is e_1' Phi^(t-1), filled by
## doubling (rows m+1..2m are rows 1..m times Phi^m, Phi^(2m) by squaring),
## a few matrix products instead of a loop over the samples. From the
## first row with a non-finite entry on (an unstable F) the rows are zero.
## @end deftypefn

function X = residtrace_free (F, N, Ts)
  F = F(:).' / F(1);
  n = numel (F) - 1;
  A = [-F(2:end)(:), eye(n, n-1)];
  Phi = expm (A * Ts);
  X = zeros (N, n);
  if (N < 1)
    return;
  endif
  X(1, 1) = 1;
  m = 1;                                 # rows done; P = Phi^m
  P = Phi;
  while (m < N)
    k = min (m, N - m);
    X(m+1:m+k, :) = X(1:k, :) * P;
    m += k;
    P = P * P;
  endwhile
  bad = find (any (! isfinite (X), 2), 1);
  if (! isempty (bad))
    X(bad:end, :) = 0;
  endif
endfunction
