## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn {} {@var{s} =} ch2_ifelse_str (@var{b}, @var{a}, @var{c})
## Helper of the Chapter 2 demos: @var{a} if @var{b} is true, else @var{c}.
## @end deftypefn

function s = ch2_ifelse_str (b, a, c)
  if (b)
    s = a;
  else
    s = c;
  endif
endfunction
