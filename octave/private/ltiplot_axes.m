## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn {} {@var{ax} =} ltiplot_axes (@var{nrow}, @var{ncol})
## The @var{nrow}-by-@var{ncol} grid of axes of @code{bodeplot} and
## @code{stepplot} in the current figure, each held on for the curves of
## several models.
## @end deftypefn

function ax = ltiplot_axes (nrow, ncol)
  ax = zeros (nrow, ncol);
  for r = 1:nrow
    for c = 1:ncol
      ax(r,c) = subplot (nrow, ncol, (r - 1) * ncol + c);
      hold (ax(r,c), "on");
    endfor
  endfor
endfunction
