## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn  {} {} present (@var{sys})
## @deftypefnx {} {@var{txt} =} present (@var{sys})
## @code{present} for the control package's models (@code{tf}, @code{zpk},
## @code{ss}): CONTSID demos print the true system they built with
## control, e.g. @code{sys0 = tf (Bs, As); present (sys0)} in the
## Hammerstein-Wiener demo.  The model is converted to an @code{idtf}
## (tf, zpk) or @code{idss} (ss) of the same sampling time and shown as
## the identified-model @code{present} shows it (no standard deviations:
## the model carries no covariance).  Identified models (@code{idpoly},
## @code{idtf}, @code{idss}, @code{idproc}, @code{idctm}) take their own
## @code{present} method.  With an output, returns the text instead.
## @seealso{idtf, idss}
## @end deftypefn

function [txt, varargout] = present (varargin)
  contsid_nargchk ("present", nargin, nargout, [1 1], 1);
  sys = varargin{1};
  if (! isa (sys, "lti"))
    error ("present:badInput",
           "present: expected a model (idpoly, idtf, idss, tf, ss), got %s",
           class (sys));
  endif
  if (isa (sys, "ss"))
    [a, b, c, d] = ssdata (sys);
    model = idss (a, b, c, d, sys.tsam);
  else
    [num, den] = tfdata (tf (sys));
    if (numel (num) != 1)
      error ("present:notSupported",
             "present: a tf/zpk with several inputs or outputs (use ss)");
    endif
    num = num{1};
    first = find (num != 0, 1);           # control pads num with zeros
    if (isempty (first))
      num = 0;
    else
      num = num(first:end);
    endif
    model = idtf (num, den{1}, sys.tsam);
  endif
  name = inputname (1, false);
  s = present (model);
  s = regexprep (s, '^model =', [name " ="], "once");
  if (nargout > 0)
    txt = s;
  else
    printf ("%s", s);
  endif
endfunction

%!test  # the control tf is shown as the same idtf
%! pkg load control
%! sys0 = tf (1, [1 2]);
%! t = present (sys0);
%! ref = present (idtf (1, [1 2]));
%! assert (strrep (t, "sys0 =", ""), regexprep (ref, '^\S* =', "", "once"));
%! assert (strncmp (t, "sys0 =", 6));
%! t = present (ss (-2, 1, 1, 0));
%! assert (! isempty (strfind (t, "-2")));
%! t = present (tf ([1 0.5], [1 -0.9], 0.1));
%! assert (! isempty (t));

%!error id=present:badInput present (1)
%!error id=present:badInput present ("tf")
%!error id=present:badInput present ()
%!error id=present:notSupported present (tf ({1, 2}, {[1 1], [1 2]}))
%!error id=present:badInput [a, b] = present (tf (1, [1 1]))

%!demo
%! pkg load control
%! sys0 = tf (1, [1 2]);
%! present (sys0)
