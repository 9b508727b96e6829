## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn  {} {} nyquist (@var{M1}, @var{style1}, @dots{}, @var{w})
## @deftypefnx {} {[@var{re}, @var{im}, @var{w}] =} nyquist (@var{M}, @var{w})
## Nyquist diagram of models (delays included); @var{re}, @var{im}:
## ny-by-nu-by-N.
## @end deftypefn

function varargout = nyquist (varargin)
  varargout = contsid_guard ({"nyquist", "idmodel"}, @nyquist_body, nargout,
                             varargin);
endfunction

function [re, im, wout, varargout] = nyquist_body (varargin)
  contsid_nargchk ("nyquist", nargin, nargout, [1 Inf], 3);
  [sys, styles, w] = parse_sys_args ("nyquist", varargin);
  if (nargout > 0)
    [H, wout] = freq_data (sys{1}, w, "nyquist");
    re = real (H);
    im = imag (H);
    return;
  endif
  hold on;
  for s = 1:numel (sys)
    H = freq_data (sys{s}, w, "nyquist");
    st = styles{s};
    if (isempty (st))
      st = "-";
    endif
    h = H(:);
    plot (real (h), imag (h), st, real (h), -imag (h), ":");
  endfor
  plot (-1, 0, "r+");
  hold off;
  grid on;
  xlabel ("real axis");
  ylabel ("imaginary axis");
endfunction

%!test
%! w = [0.1; 1; 10];
%! [re, im] = nyquist (idtf (2, [1 3 2]), w);
%! H = 2 ./ ((1i*w).^2 + 3*1i*w + 2);
%! assert (squeeze (re + 1i * im), H, 1e-13);
%!error id=nyquist:badInput nyquist (idtf (1, [1 1]), @sin)

%!demo
%! nyquist (idtf (2, [1 3 2], "IODelay", 0.3));
