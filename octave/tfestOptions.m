## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn  {} {@var{opt} =} tfestOptions ()
## @deftypefnx {} {@var{opt} =} tfestOptions (@var{name}, @var{value}, @dots{})
## Option set of @code{tfest} (System Identification Toolbox form): a struct
## with @code{Focus} (@qcode{"simulation"} (default), @qcode{"prediction"}
## or a band [w1 w2] in rad/s), @code{InitialCondition}
## (@qcode{"zero"}; the estimators start from rest), @code{Display}
## (@qcode{"off"}), @code{SearchMethod} (@qcode{"lm"}), and
## @code{SearchOptions} (@code{MaxIterations} 100, @code{Tolerance} 1e-8).
## Unknown names are errors (@code{tfestOptions:badOption}).
##
## @strong{Example}
## @example
## opt = tfestOptions ("Focus", [0 10]);
## opt.SearchOptions.MaxIterations = 50;
## @end example
## @seealso{tfest, oeOptions}
## @end deftypefn

function varargout = tfestOptions (varargin)
  varargout = contsid_guard ("tfestOptions", @tfestOptions_body, nargout,
                             varargin);
endfunction

function [opt, varargout] = tfestOptions_body (varargin)
  contsid_nargchk ("tfestOptions", nargin, nargout, [0 Inf], 1);
  opt = contsid_pem_options ("tfestOptions", varargin);
endfunction

%!test
%! o = tfestOptions ();
%! assert (o.Focus, "simulation");
%! assert (o.SearchOptions.MaxIterations, 100);
%! o = tfestOptions ("Focus", [0 25], "Display", "on");
%! assert (o.Focus, [0 25]);

%!error id=tfestOptions:badOption tfestOptions ("Bogus", 1)
%!error id=tfestOptions:badOption tfestOptions ("Focus")
%!error id=tfestOptions:badOption tfestOptions (1, 2)
%!error id=tfestOptions:badOption tfestOptions ("Focus", [3 1])
%!error id=tfestOptions:badOption tfestOptions ("InitialCondition", "estimate")
%!error id=tfestOptions:badOption tfestOptions ("SearchMethod", "gna")

%!demo
%! opt = tfestOptions ("Focus", [0 10])
