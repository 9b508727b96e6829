## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn {} {@var{H} =} freqresp (@var{M}, @var{w})
## Frequency response of a model at the frequencies @var{w} (rad/s):
## ny-by-nu-by-numel(@var{w}), delays included (e^(-j w tau), or
## e^(-j w Ts d) in discrete time).  The delay-free part comes from the
## control package's @code{freqresp}.  An @code{idfrd} returns its data
## at its own frequencies (other @var{w}: @code{idfrd:badInput}).
## @end deftypefn

function varargout = freqresp (varargin)
  varargout = contsid_guard ({"freqresp", "idmodel"}, @freqresp_body, nargout,
                             varargin);
endfunction

function [H, varargout] = freqresp_body (M, w, varargin)
  contsid_nargchk ("freqresp", nargin, nargout, [1 2], 1);
  P = pstruct (M);
  if (nargin < 2 || ! isnumeric (w) || ! isreal (w) || ! isvector (w)
      || any (! isfinite (w)))
    error ([P.kind ":badInput"], "%s: freqresp needs real frequencies w",
           P.kind);
  endif
  w = double (w(:));
  if (strcmp (P.kind, "idfrd"))
    if (! isequal (w, P.par.Frequency))
      error ("idfrd:badInput",
             "idfrd: freqresp only at the data's own frequencies");
    endif
    H = P.par.ResponseData;
    return;
  endif
  [G, delay] = lti_of (P, "tf", P.kind);
  H = freqresp (G, w);
  H = reshape (H, P.ny, P.nu, numel (w));
  if (any (delay(:) != 0))
    scale = 1;
    if (P.Ts > 0)
      scale = P.Ts;
    endif
    for k = 1:numel (w)
      H(:, :, k) .*= exp (-1i * w(k) * scale * delay);
    endfor
  endif
endfunction

%!test  # against the polynomials evaluated directly
%! w = [0.1; 1; 10];
%! H = freqresp (idtf (2, [1 3 2], "IODelay", 0.5), w);
%! s = 1i * w;
%! assert (squeeze (H), 2 ./ (s.^2 + 3*s + 2) .* exp (-0.5 * s), 1e-13);
%! Hd = freqresp (idpoly (1, [0 0.5], 1, 1, [1 -0.9], 1, 0.1), w);
%! z = exp (1i * w * 0.1);
%! assert (squeeze (Hd), 0.5 ./ z ./ (1 - 0.9 ./ z), 1e-13);
%!error id=idtf:badInput freqresp (idtf (1, [1 1]))
%!error id=idfrd:badInput freqresp (idfrd ([1 2], [1 2]), [1 3])

%!demo
%! H = squeeze (freqresp (idtf (2, [1 3 2]), logspace (-1, 1, 5)))
