## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn {} {@var{G} =} ss (@var{M})
## The control package's state-space model of the input-output part of a
## model (delays as for @code{tf}: error @code{ss:notSupported} for a
## continuous-time delay).
## @end deftypefn

function varargout = ss (varargin)
  varargout = contsid_guard ({"ss", "idmodel"}, @ss_body, nargout, varargin);
endfunction

function [G, varargout] = ss_body (M, varargin)
  contsid_nargchk ("ss", nargin, nargout, [1 1], 1);
  P = pstruct (M);
  [G, delay] = lti_of (P, "ss", "ss");
  if (any (delay(:) != 0))
    if (P.Ts == 0)
      error ("ss:notSupported",
             "ss: the control package's ss has no time delay (%s s)",
             mat2str (delay, 4));
    endif
    G = feval ("ss", tf (M));
  endif
endfunction

%!test
%! G = ss (idss ([-1 0; 1 -2], [1; 0], [0 1], 0));
%! assert (isa (G, "ss"));
%! [a, b, c, d] = ssdata (G);
%! assert (a, [-1 0; 1 -2]);
%! H = ss (idtf (2, [1 3 2]));
%! assert (sort (eig (ssdata (H))), [-2; -1], 1e-12);
%!error id=ss:notSupported ss (idtf (1, [1 1], "IODelay", 1))

%!demo
%! G = ss (idtf (2, [1 3 2]))
