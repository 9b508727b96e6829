## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn {} {@var{G} =} tf (@var{M})
## The control package's transfer function of the input-output part of a
## model (@code{idpoly}, @code{idtf}, @code{idproc}, @code{idss}); loads
## the control package.  Control 3.4 has no delays: the delays of a
## discrete-time model become powers of z^-1; a continuous-time model with
## a delay raises @code{tf:notSupported} (use @code{tf (M.B, M.F)} and
## @code{totaldelay (M)}, or @code{c2d} first).
## @end deftypefn

function varargout = tf (varargin)
  varargout = contsid_guard ({"tf", "idmodel"}, @tf_body, nargout, varargin);
endfunction

function [G, varargout] = tf_body (M, varargin)
  contsid_nargchk ("tf", nargin, nargout, [1 1], 1);
  P = pstruct (M);
  [G, delay] = lti_of (P, "tf", "tf");
  if (any (delay(:) != 0))
    if (P.Ts == 0)
      error ("tf:notSupported",
             ["tf: the control package's tf has no time delay; this ", ...
              "model has delays %s s"], mat2str (delay, 4));
    endif
    [num, den] = tfdata (G);
    for k = 1:numel (num)
      den{k} = [den{k}, zeros(1, delay(k))];
    endfor
    G = feval ("tf", num, den, P.Ts);
  endif
endfunction

%!test
%! G = tf (idpoly (1, 2, 1, 1, [1 1.2 2], "Ts", 0));
%! assert (isa (G, "tf"));
%! [n, d] = tfdata (G, "v");
%! assert (d, [1 1.2 2], 1e-14);
%! assert (n(end), 2, 1e-14);
%! Gd = tf (idpoly (1, [0 0.5], 1, 1, [1 -0.9], 1, 0.1, "InputDelay", 2));
%! [n, d] = tfdata (Gd, "v");
%! assert (get (Gd, "tsam"), 0.1);
%! assert (polyval (n, 2) / polyval (d, 2), 0.5 * 2^-3 / (1 - 0.9/2), 1e-14);
%!error id=tf:notSupported tf (idtf (1, [1 1], "IODelay", 1))
%!error id=idfrd:notSupported tf (idfrd (1, 1))

%!demo
%! G = tf (idtf (2, [1 3 2]))
