## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn {} {} display (@var{M})
## Shows a model as the System Identification Toolbox does: its equation,
## polynomials (or transfer function, process parameters, matrices),
## delays, sample time, number of parameters and estimation status with
## the fit to the estimation data.  @code{present} adds the standard
## deviations.
## @end deftypefn

function varargout = display (M, varargin)
  contsid_nargchk ("display", nargin, nargout, [1 1], 0);
  printf ("%s =\n%s\n\n", inputname (1), model_text (pstruct (M), false));
endfunction

%!test
%! M0 = idpoly (1, 2, 1, 1, [1 1.2 2], "Ts", 0);
%! out = evalc ("display (M0)");
%! assert (! isempty (strfind (out, "Continuous-time OE model")));
%! assert (! isempty (strfind (out, "F(s) = s^2 + 1.2 s + 2")));
%! out = evalc ("M1 = idpoly (1, [0 0.5], 1, 1, [1 -0.9], 1, 0.1)");
%! assert (! isempty (strfind (out, "F(z) = 1 - 0.9 z^-1")));
%! out = evalc ("P = idproc ('P2DU', 'Kp', 1, 'Tw', 2, 'Zeta', 0.5, 'Td', 1)");
%! assert (! isempty (strfind (out, "Zeta = 0.5")));
%! out = evalc ("G = idtf (2, [1 3 2], 'IODelay', 0.5)");
%! assert (! isempty (strfind (out, "exp(-0.5*s)")));
%! out = evalc ("L = idctm (1, [1 1], 'nk', 3)");
%! assert (! isempty (strfind (out, "samples of the data): 3")));
%! out = evalc ("S = idss (-1, 1, 1, 0)");
%! assert (! isempty (strfind (out, "dx/dt")));
%!error <Invalid call> display ()

%!demo
%! M0 = idpoly (1, {2, [1 1]}, 1, 1, {[1 1.2 2], [1 3]}, 0, 0, ...
%!              "InputDelay", [0.1 0.2])
