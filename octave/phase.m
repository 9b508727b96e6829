## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn  {} {@var{phi} =} phase (@var{G})
## Phase, in radians, of the complex frequency response @var{G} (a vector,
## or a matrix with one response per column), unwrapped so that it stays
## continuous across +/- pi, as the System Identification Toolbox's
## @code{phase} that CONTSID's robot-arm case study calls
## (@code{phase (G)} of a measured frequency response).  It is
## @code{unwrap (angle (G))} along the first non-singleton dimension.
##
## @strong{Example}
## @example
## w = logspace (-1, 2, 200);
## G = 1 ./ (1i * w + 1) .^ 3;
## semilogx (w, phase (G) * 180 / pi)     # down to -270 degrees
## @end example
## @seealso{angle, unwrap, bode}
## @end deftypefn

function varargout = phase (varargin)
  varargout = contsid_guard ("phase", @phase_body, nargout, varargin);
endfunction

function [phi, varargout] = phase_body (varargin)
  contsid_nargchk ("phase", nargin, nargout, [1 1], 1);
  G = varargin{1};
  if (! (isnumeric (G) && ismatrix (G)) || any (! isfinite (G(:))))
    error ("phase:badInput",
           "phase: G must be a finite numeric vector or matrix");
  endif
  phi = angle (double (full (G)));
  if (isempty (phi))
    return;                              # unwrap fails on an empty matrix
  elseif (isrow (phi))
    phi = unwrap (phi, [], 2);
  else
    phi = unwrap (phi);
  endif
endfunction

%!test  # a third-order lag: the unwrapped phase is -3 atan (w)
%! w = logspace (-1, 2, 200);
%! G = 1 ./ (1i * w + 1) .^ 3;
%! assert (phase (G), -3 * atan (w), 1e-12);
%! assert (phase (G.'), -3 * atan (w.'), 1e-12);
%! assert (phase ([G.', 2 * G.']), -3 * atan ([w.', w.']), 1e-12);
%!assert (phase ([]), [])
%!assert (phase (zeros (0, 3)), zeros (0, 3))
%!error id=phase:badInput phase ()
%!error id=phase:badInput phase ("abc")
%!error id=phase:badInput phase ([1 NaN])
%!error id=phase:badInput phase (ones (2, 2, 2))
%!error id=phase:badInput [a, b] = phase (1)

%!demo
%! w = logspace (-1, 2, 200);
%! G = 1 ./ (1i * w + 1) .^ 3;
%! semilogx (w, phase (G) * 180 / pi);
%! xlabel ("w (rad/s)"); ylabel ("phase (deg)");
