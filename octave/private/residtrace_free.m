## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn {} {@var{X} =} residtrace_free (@var{F}, @var{N}, @var{Ts})
## Free responses of the model 1/F(p) at the N samples: column l is the
## solution of F(p) h = 0 with h^(k)(0) = 1 for k = l - 1 and 0 otherwise,
## a basis of the model's initial-condition responses (the core's
## responses.hpp through @code{effect_sim_mex}). From the first row with
## a non-finite entry on (an unstable F) the rows are zero.
## @end deftypefn

function X = residtrace_free (F, N, Ts)
  F = F(:).' / F(1);
  X = effect_sim_mex ("residtrace", "free", N, F(2:end), struct ("ts", Ts));
endfunction
