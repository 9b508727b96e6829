## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn  {} {} impulse (@var{M})
## @deftypefnx {} {} impulse (@var{M1}, @var{style1}, @var{M2}, @var{style2}, @dots{}, @var{t})
## @deftypefnx {} {[@var{y}, @var{t}] =} impulse (@var{M}, @var{t})
## Impulse response of models (this toolbox's, control-package ones may be
## mixed in), with their delays; plotted without outputs, one line style
## per model.  @var{t}: a vector of times or the final time.  @var{y}:
## N-by-ny-by-nu.  In continuous time the response is exact at each
## instant (matrix exponential of the control package's realisation); in
## discrete time a unit pulse at sample 0.
## @end deftypefn

function varargout = impulse (varargin)
  varargout = contsid_guard ({"impulse", "idmodel"}, @impulse_body, nargout,
                             varargin);
endfunction

function varargout = impulse_body (varargin)
  contsid_nargchk ("impulse", nargin, nargout, [1 Inf], 2);
  [varargout{1:nargout}] = time_response ("impulse", "impulse", varargin);
endfunction

%!test  # against the control package's impulse of the same tf
%! pkg load control
%! t = (0:0.05:5)';
%! y = impulse (idtf ([1 4], [1 2.4 4]), t);
%! yc = impulse (tf ([1 4], [1 2.4 4]), t);
%! assert (y, yc(:), 1e-10);
%! ## first order, exact: 2 e^(-3 t)
%! assert (impulse (idproc ("P1", "Kp", 2/3, "Tp1", 1/3), t), 2 * exp (-3 * t),
%!         1e-12);
%!error id=impulse:badInput impulse (idtf (2, [1 3 2]), realmax)
%!error id=impulse:numericalFailure impulse (idtf (1, [1 -1]), 1000)
%!error id=impulse:badInput impulse (idtf (1, [1 -0.5], 0.1), 1e9)
%!error id=impulse:badInput impulse (idtf (1, [1 1]), "sd", -1)

%!demo
%! impulse (idproc ("P2DU", "Kp", 1, "Tw", 0.5, "Zeta", 0.3, "Td", 0.2));
