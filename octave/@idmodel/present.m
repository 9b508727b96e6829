## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn {} {} present (@var{M})
## @deftypefnx {} {@var{txt} =} present (@var{M})
## Displays a model with the standard deviation of each estimated
## parameter, "value (+/- sd)", sd the square root of the corresponding
## diagonal entry of the covariance (@code{getcov}), followed by the
## estimation status, fit to the estimation data (%), loss function and
## mean square error, as the System Identification Toolbox prints it,
## and the levels the model carries (@code{Report.DataUsed.InputOffset},
## @code{OutputOffset}; see @code{help idpoly}) when it has any.
## With an output, returns the text instead.
## @end deftypefn

function [txt, varargout] = present (M, varargin)
  contsid_nargchk ("present", nargin, nargout, [1 1], 1);
  s = sprintf ("%s =\n%s\n", inputname (1), model_text (pstruct (M), true));
  if (nargout > 0)
    txt = s;
  else
    printf ("%s\n", s);
  endif
endfunction

%!test  # the printed standard deviations are sqrt (diag (covariance))
%! M = idctm (struct ("B", 5, "F", [1 2 3], "covariance", diag ([4 9 16]),
%!                    "method", "srivc"));
%! t = present (M);
%! assert (! isempty (strfind (t, "B(s) = 5 (+/- 4)")));
%! assert (! isempty (strfind (t, "F(s) = s^2 + 2 (+/- 2) s + 3 (+/- 3)")));
%! assert (! isempty (strfind (t, "SRIVC")));
%!test
%! t = present (idtf (2, [1 3 2]));
%! assert (isempty (strfind (t, "+/-")));
%!test  # the levels the model carries are shown; none, no line
%! M = idtf (2, [1 1.2 1]);
%! assert (isempty (strfind (present (M), "Levels")));
%! M.Report.DataUsed.InputOffset = 5;
%! M.Report.DataUsed.OutputOffset = 20;
%! t = present (M);
%! assert (! isempty (strfind (t, "InputOffset = 5, OutputOffset = 20")));
%!error id=present:badInput present (idtf (1, [1 1]), 2)

%!demo
%! M = setcov (idtf (2, [1 3]), diag ([0.04 0.01]));
%! present (M)
