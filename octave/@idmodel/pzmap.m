## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn  {} {} pzmap (@var{M1}, @var{style1}, @var{M2}, @dots{})
## @deftypefnx {} {[@var{p}, @var{z}] =} pzmap (@var{M})
## Poles (x) and zeros (o) of models in the complex plane.
## @end deftypefn

function varargout = pzmap (varargin)
  varargout = contsid_guard ({"pzmap", "idmodel"}, @pzmap_body, nargout,
                             varargin);
endfunction

function [pout, zout, varargout] = pzmap_body (varargin)
  contsid_nargchk ("pzmap", nargin, nargout, [1 Inf], 2);
  [sys, styles] = parse_sys_args ("pzmap", varargin);
  if (nargout > 0)
    pout = pole (sys{1});
    zout = zero (sys{1});
    return;
  endif
  colors = "brgmck";
  hold on;
  for s = 1:numel (sys)
    c = colors(mod (s - 1, numel (colors)) + 1);
    if (! isempty (styles{s}))
      c = styles{s}(isletter (styles{s}))(1);
    endif
    p = pole (sys{s});
    z = zero (sys{s});
    plot (real (p), imag (p), [c "x"], real (z), imag (z), [c "o"]);
  endfor
  hold off;
  grid on;
  xlabel ("real axis");
  ylabel ("imaginary axis");
  title ("pole-zero map");
endfunction

%!test
%! [p, z] = pzmap (idtf ([1 4], [1 3 2]));
%! assert (sort (p), [-2; -1], 1e-12);
%! assert (z, -4, 1e-12);
%!error id=pzmap:badInput pzmap (idtf (1, [1 1]), @sin)

%!demo
%! pzmap (idtf ([1 4], [1 3 2]), "b", idtf ([1 5], [1 3.2 2]), "r");
