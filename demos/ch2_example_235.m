## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn {} {[@var{Ts}, @var{t}, @var{theta}, @var{u}] =} ch2_example_235 ()
## The LTV system of thesis eqs. (1.61)-(1.63) (sec. 1.3.4, example 2.3.5,
## and with a constant input from 6000 s example 3.6.4):
##
##   (p^2 + a1(t) p + a2(t)) x = b0(t) u,  a1 = 2 zeta wn,  a2 = b0 = wn^2,
##   zeta = 0.6,  wn(t) = 2 (1 + 0.3 cos (2 pi t / 4500)),
##
## Ts = 0.1 s over 9000 s; @var{theta} = [a1 a2 b0] per sample and the
## input @var{u} = prbs (15, 10) (15-bit maximum-length PRBS, levels +-1,
## each chip held 10 samples: implementation notes, item 6).
## @end deftypefn

function [Ts, t, theta, u] = ch2_example_235 ()
  Ts = 0.1;
  t = (0:Ts:9000)';
  wn = 2 * (1 + 0.3 * cos (2 * pi * t / 4500));
  theta = [2 * 0.6 * wn, wn .^ 2, wn .^ 2];
  u = prbs (15, 10);
  u = u(1:numel (t));
endfunction
