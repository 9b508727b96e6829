## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn  {} {} step (@var{num}, @var{den})
## @deftypefnx {} {} step (@var{num}, @var{den}, @var{t})
## @deftypefnx {} {} step (@var{a}, @var{b}, @var{c}, @var{d})
## @deftypefnx {} {} step (@var{a}, @var{b}, @var{c}, @var{d}, @var{iu})
## @deftypefnx {} {} step (@var{a}, @var{b}, @var{c}, @var{d}, @var{iu}, @
##   @var{t})
## @deftypefnx {} {[@var{y}, @var{x}, @var{t}] =} step (@dots{})
## Step response in the pre-LTI forms of MATLAB's Control System Toolbox,
## as CONTSID scripts call it: @code{step (Nc, Dc)},
## @code{y1 = step (B1, F1, ti)}, @code{step (a, b, c, d)}.
##
## This is a method of the class @code{double}: Octave calls it only when
## no argument is an object, i.e. for exactly the calls that the control
## package's @code{step} rejects (it needs an LTI model).  Calls with a
## model (@code{step (sys, t)}, @code{step (M0, M)}) go to the control
## package (or the model's class) unchanged.
## The other built-in classes (@code{single}, the integer types,
## @code{logical}, @code{char}, @code{cell}, @code{struct},
## @code{function_handle}) link to this file: Octave sends a call whose
## arguments are all built-in to the method of the highest of their
## classes, so every such call comes here (numbers of any numeric class
## are read as double, anything else is an identified error) instead of
## reaching the control package's function, which fails on it without an
## identifier.
##
## @code{(num, den)} is the continuous-time transfer function
## @code{tf (num, den)}; @code{(a, b, c, d)} the continuous-time state-space
## model @code{ss (a, b, c, d)}, restricted to input @var{iu} when given.
## @var{t} is a time vector or the final time, as for the control package's
## @code{step}.  Without output arguments the response is plotted.
##
## The outputs follow the pre-LTI order @code{[y, x, t]}: @var{y} is
## @code{numel (t)}-by-@var{ny} (with several inputs and no @var{iu},
## @code{numel (t)}-by-@var{ny}-by-@var{nu}), @var{x} the state trajectory
## (for a transfer function, of its state-space realization).
## @seealso{bode, ord2, stepplot}
## @end deftypefn

function varargout = step (varargin)
  varargout = contsid_guard ({"step", "double"}, @step_body, nargout, varargin);
endfunction

function [y, x, t, varargout] = step_body (varargin)
  contsid_nargchk ("step", nargin, nargout, [2 6], 3);
  [sys, iu, tt] = pre_lti_args ("step", varargin);
  if (! isempty (iu))
    sys = sys(:, iu);
  endif
  targs = {};
  if (! isempty (tt))
    targs = {tt};
  endif
  if (nargout == 0)
    step (sys, targs{:});
    return;
  endif
  [y, t, x] = step (sys, targs{:});
  if (! isempty (iu) || size (y, 3) == 1)
    y = y(:, :, 1);
  endif
  if (ndims (x) == 3 && size (x, 3) == 1)
    x = x(:, :, 1);
  endif
endfunction

## the same numbers as the control package on the same model
%!test
%! pkg load control
%! t = (0:0.05:4).';
%! y = step ([2 2], [1 3 2], t);
%! assert (y, step (tf ([2 2], [1 3 2]), t), 1e-12);
%! ## against the closed form of 2(s+1)/((s+1)(s+2)) = 2/(s+2)
%! assert (y, 1 - exp (-2 * t), 1e-8);
%! a = [0 1; -2 -3]; b = [0 1; 1 0]; c = [1 0; 1 1]; d = zeros (2);
%! [y, x, tt] = step (a, b, c, d, 2, t);
%! assert (size (y), [numel(t), 2]);
%! ys = step (ss (a, b, c, d), t);
%! assert (y, ys(:, :, 2), 1e-12);
%! assert (tt, t);
%! assert (size (x), [numel(t), 2]);
%! y3 = step (a, b, c, d, [], t);
%! assert (size (y3), [numel(t), 2, 2]);
%! [y, ~, tt] = step (1, [1 1]);
%! assert (y, 1 - exp (-tt), 1e-8);

## forwarding: calls with a model are the control package's own
%!test
%! pkg load control
%! sys = tf (1, [1 2 1]);
%! [y1, t1] = step (sys);
%! control = fileparts (fileparts (which ("tf")));
%! assert (which ("step"), fullfile (control, "step.m"));
%! [y2, t2] = step (sys, 3);
%! assert (t2(end), 3, 1e-12);
%! assert (numel (y1), numel (t1));
%! h = figure ("visible", "off");
%! unwind_protect
%!   step (1, [1 1]);
%!   assert (! isempty (findobj (h, "type", "line")));
%! unwind_protect_cleanup
%!   close (h);
%! end_unwind_protect

%!test  # a sparse final time is a final time (fuzz seed 12, call 7128)
%! y1 = step (1, [1 2 1], sparse (3));
%! y2 = step (1, [1 2 1], 3);
%! assert (y1, y2);
%! assert (! issparse (y1));

%!error id=step:badInput step (1, 2, 3, 4, 5, 6, 7)
## all built-in arguments, a higher class than double among them
%!error id=step:badInput step (4, [1 2.4 4], {1})
%!error id=step:badInput step (4, struct ())
%!error id=step:badInput step (@sin, [1 1])
%!test
%! assert (step (int8 (4), single ([1 3 2]), 3), step (4, [1 3 2], 3), 0);
%!error id=step:badInput step ([1 2; 3 4], [1 2; 3 4])
%!error id=step:badInput step (1, [0 0])
%!error id=step:badInput step (1, [1 1], [1 NaN])
%!error id=step:badInput step (1, [1i 1])
%!error id=step:badInput step (-1, 1, Inf, 0)
%!error id=step:badInput step ([1 2], [2 1 1], 0)
%!error id=step:badInput step ([1 2], 1e9)
%!error id=step:notSupported step (1, 0.98, 10)
%!error id=step:dimensionMismatch step (eye (2), [1; 1], [1 0 0], 0)
%!error id=step:badInput step (-1, 1, 1, 0, 2)
%!error id=step:badInput [a, b, c, d] = step (1, [1 1])

%!demo
%! ## a CONTSID script's pre-LTI call: the step response of N(s)/D(s)
%! Nc = [0.5 1]; Dc = [1 1.2 1];
%! step (Nc, Dc)
