## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn {} {@var{c} =} residtrace_chan (@var{type}, @var{col}, @var{param}, @var{nb}, @var{nk}, @var{name})
## One channel of a @code{residtrace} model (see @code{residtrace_channels}
## for the types): numerator B (nb coefficients, zero until estimated),
## delay nk in samples.
## @end deftypefn

function c = residtrace_chan (type, col, param, nb, nk, name)
  c = struct ("name", name, "type", type, "col", col, "param", param,
              "nb", nb, "nk", nk, "B", zeros (1, nb));
endfunction
