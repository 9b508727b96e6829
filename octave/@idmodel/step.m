## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn  {} {} step (@var{M})
## @deftypefnx {} {} step (@var{M1}, @var{style1}, @var{M2}, @var{style2}, @dots{}, @var{t})
## @deftypefnx {} {[@var{y}, @var{t}] =} step (@var{M}, @var{t})
## Step response of models (this toolbox's, control-package ones may be
## mixed in), with their delays; plotted without outputs, one line style
## per model.  @var{t}: a vector of times or the final time.  @var{y}:
## N-by-ny-by-nu.  In continuous time the response is exact at each
## instant (matrix exponential of the control package's realisation); in
## discrete time a unit step at sample 0.
## @end deftypefn

function varargout = step (varargin)
  varargout = contsid_guard ({"step", "idmodel"}, @step_body, nargout,
                             varargin);
endfunction

function varargout = step_body (varargin)
  contsid_nargchk ("step", nargin, nargout, [1 Inf], 2);
  [varargout{1:nargout}] = time_response ("step", "step", varargin);
endfunction

%!test  # against the control package's step of the same tf
%! pkg load control
%! t = (0:0.05:5)';
%! M = idpoly (1, [1 4], 1, 1, [1 2.4 4], "Ts", 0);
%! y = step (M, t);
%! yc = step (tf ([1 4], [1 2.4 4]), t);
%! assert (y, yc(:), 1e-10);
%! ## a delay of 0.5 s shifts the response by 10 samples
%! yd = step (idtf ([1 4], [1 2.4 4], "IODelay", 0.5), t);
%! assert (yd, [zeros(10, 1); yc(1:end-10)], 1e-10);
%! ## discrete time
%! Md = idpoly (1, [0 0.5], 1, 1, [1 -0.9], 1, 0.1);
%! yd = step (Md, (0:20)' * 0.1);
%! assert (yd, [0; 5 * (1 - 0.9 .^ (1:20)')], 1e-12);
%!test  # a fractional delay, times in any order, against e^(At) directly
%! M = idtf ([1 3], [1 1.2 1 0.3], "InputDelay", 0.37);
%! t = [3; 0; 0.1; 2.5; 2.5; 7; 0.37; 0.2];
%! a = [-1.2 -1 -0.3; 1 0 0; 0 1 0];  b = [1; 0; 0];  c = [0 1 3];
%! yr = zeros (size (t));
%! for k = find (t >= 0.37)'
%!   E = expm ([a, b; zeros(1, 4)] * (t(k) - 0.37));
%!   yr(k) = c * E(1:3, 4);
%! endfor
%! assert (step (M, t), yr, 1e-12);
%! assert (step (idtf (2.5, 1), [0; 1]), [2.5; 2.5]);
%!test
%! [y, t] = step (idss ([-1 0; 0 -2], eye (2), eye (2), zeros (2)));
%! assert (size (y), [numel(t), 2, 2]);
%! assert (y(end, 2, 2), 0.5, 1e-5);
%!error id=step:badInput step (idtf (1, [1 1]), {1})
%!error id=step:badInput step (idtf (1, [1 1]), -1)
%!error id=idfrd:notSupported step (idfrd (1, 1))

%!demo
%! M0 = idpoly (1, 4, 1, 1, [1 2.4 4], "Ts", 0);
%! M1 = idtf (4.2, [1 2.2 4], "IODelay", 0.2);
%! step (M0, "b-", M1, "r--", 8);
