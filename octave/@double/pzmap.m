## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn  {} {} pzmap (@var{num}, @var{den})
## @deftypefnx {} {} pzmap (@var{a}, @var{b}, @var{c}, @var{d})
## @deftypefnx {} {[@var{p}, @var{z}] =} pzmap (@dots{})
## Poles and zeros in the pre-LTI forms of MATLAB's Control System Toolbox
## (@code{pzmap (A, B, C, D)} in CONTSID scripts).
##
## A method of the class @code{double}: Octave calls it only when no
## argument is an object, i.e. for the calls the control package's
## @code{pzmap} rejects; calls with a model go to the control package
## unchanged.  @code{(num, den)} is @code{tf (num, den)}, @code{(a, b, c,
## d)} is @code{ss (a, b, c, d)}; the result is the control package's
## @code{pzmap} of that model (a plot without outputs).
## The other built-in classes (@code{single}, the integer types,
## @code{logical}, @code{char}, @code{cell}, @code{struct},
## @code{function_handle}) link to this file: Octave sends a call whose
## arguments are all built-in to the method of the highest of their
## classes, so every such call comes here (numbers of any numeric class
## are read as double, anything else is an identified error) instead of
## reaching the control package's function, which fails on it without an
## identifier.
## @seealso{step, bode}
## @end deftypefn

function varargout = pzmap (varargin)
  varargout = contsid_guard ({"pzmap", "double"}, @pzmap_body, nargout,
                             varargin);
endfunction

function [p, z, varargout] = pzmap_body (varargin)
  contsid_nargchk ("pzmap", nargin, nargout, [2 4], 2);
  if (! any (nargin == [2, 4]))
    error ("pzmap:badInput",
           ["pzmap: with numeric arguments use pzmap (num, den) or ", ...
            "pzmap (a, b, c, d)"]);
  endif
  sys = pre_lti_args ("pzmap", varargin);
  if (nargout == 0)
    [p, z] = pzmap (sys);
    if (isempty (p) && isempty (z))
      ## (the control package's plot would fail without an identifier)
      error ("pzmap:badInput",
             "pzmap: the model (a static gain) has no poles or zeros to plot");
    endif
    pzmap (sys);
  else
    [p, z] = pzmap (sys);
  endif
endfunction

%!test
%! pkg load control
%! a = [0 1; -2 -3]; b = [0; 1]; c = [1 1]; d = 0;
%! [p, z] = pzmap (a, b, c, d);
%! assert (sort (p), sort (eig (a)), 1e-12);
%! assert (z, -1, 1e-12);
%! [p, z] = pzmap ([1 2], [1 4 3]);
%! assert (sort (p), [-3; -1], 1e-12);
%! assert (z, -2, 1e-12);
%! [p2, z2] = pzmap (tf ([1 2], [1 4 3]));
%! assert ([sort(p2); z2], [sort(p); z]);

%!error id=pzmap:badInput pzmap (1, 2, 3)
%!error id=pzmap:badInput pzmap (4, [1 2.4 4], {1})
%!test
%! [p, z] = pzmap (true, single ([1 3 2]));
%! assert (sort (p), [-2; -1], 1e-6);
%!error id=pzmap:badInput pzmap (1, [0 0])
%!error id=pzmap:dimensionMismatch pzmap (eye (2), [1; 1], [1 0 0], 0)
%!error id=pzmap:badInput [a, b, c] = pzmap (1, [1 1])
%!error id=pzmap:badInput pzmap (-1, 1)
%!error id=pzmap:badInput pzmap (2, NaN)

%!demo
%! pzmap ([0 1; -2 -3], [0; 1], [1 1], 0)
