## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn {} {@var{D} =} residtrace_filter (@var{F}, @var{x}, @var{Ts}, @var{rule})
## Filtered time-derivatives of a sampled signal: column i+1 of @var{D}
## (N-by-(n+1)) is p^i / F(p) x for i = 0 .. n, F = [F0 f1 .. fn] with
## n >= 1, the filter at rest at the first sample. The signal is held
## between samples by @var{rule}: @qcode{"zoh"} (constant) or
## @qcode{"foh"} (linear); for either the result is exact (the core's
## batch filters, core/include/ctid/apps/residtrace/responses.hpp, through
## @code{effect_sim_mex}).
## @end deftypefn

function D = residtrace_filter (F, x, Ts, rule)
  F = F(:).' / F(1);
  D = effect_sim_mex ("residtrace", "filter", x(:), F(2:end),
                      struct ("ts", Ts, "rule", rule));
endfunction
