## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn {} {[@var{away}, @var{level}] =} contsid_start_level (@var{y})
## Where the output @var{y} (a column) starts: @var{level} is the median
## of its first five samples, and @var{away} is true when that level lies
## more than 5 % of the output's range from zero, a record that does not
## start at rest (raw units, an operating point). srivc's 'auto'
## OutputOffset rule and residtrace's levels rule.
## @end deftypefn

function [away, level] = contsid_start_level (y)
  m = min (5, numel (y));
  level = median (y(1:m));
  away = abs (level) > 0.05 * (max (y) - min (y));
endfunction
