## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn {} {@var{rej0} =} ch2_iv_phase_rejections (@var{estfun}, @var{data}, @var{M})
## Helper of the Chapter 2 demos: the stability rejections of methods
## 2..@var{M} on @var{data} with the IV stage never started, i.e. of the
## RLSSVF phase alone. @var{estfun} (m, data) must run method m with
## tsiv at the last sample and return the info struct as its second
## output. @var{rej0}(1) is 0.
## @end deftypefn

function rej0 = ch2_iv_phase_rejections (estfun, data, M)
  rej0 = zeros (1, M);
  for m = 2:M
    [~, info] = estfun (m, data);
    rej0(m) = info.stability_rejections;
  endfor
endfunction
