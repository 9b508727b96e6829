## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn {} {} display (@var{M})
## Shows a model @code{residtrace} returned as @code{present} does.
##
## @strong{Example}
## @example
## Ts = 0.05; u = prbs (9, 4); N = numel (u); G = idctm (2, [1 1.2 1]);
## y = simc (G, u + 0.3, Ts) + 0.03 * randn (N, 1);
## R = residtrace (iddata (y, u, Ts), G, "effects", @{"offset"@});
## M = R.final_model
## @end example
## @end deftypefn

function varargout = display (M, varargin)
  contsid_nargchk ("display", nargin, nargout, [1 1], 0);
  name = inputname (1);
  if (isempty (name))
    name = "ans";
  endif
  printf ("%s =\n\n%s\n", name, present (M));
endfunction

%!test
%! out = evalc ("M = idtraced ()");
%! assert (! isempty (strfind (out, "M =")));
%!error <Invalid call> display ()
