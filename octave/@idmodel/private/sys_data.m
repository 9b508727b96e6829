## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn {} {[@var{a}, @var{b}, @var{c}, @var{d}, @var{Ts}, @var{delay}, @var{P}] =} sys_data (@var{sys}, @var{fname})
## The delay-free state-space matrices (from the control package's
## realisation, @code{lti_of}), the sampling time and the ny-by-nu delays
## of a model of this toolbox or of the control package; @var{P} its model
## struct ([] for a control-package model).
## @end deftypefn

function [a, b, c, d, Ts, delay, P] = sys_data (sys, fname)
  if (isa (sys, "idmodel"))
    P = pstruct (sys);
    if (strcmp (P.kind, "idfrd"))
      error ("idfrd:notSupported",
             "%s: frequency response data have no time response", fname);
    endif
    [G, delay] = lti_of (P, "ss", fname);
  else
    P = [];
    G = sys;
    delay = zeros (size (sys));
  endif
  [a, b, c, d] = ssdata (G);
  Ts = max (get (G, "tsam"), 0);
endfunction
