## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn  {} {@var{opt} =} oeOptions ()
## @deftypefnx {} {@var{opt} =} oeOptions (@var{name}, @var{value}, @dots{})
## Option set of @code{oe} (System Identification Toolbox form): a struct
## with @code{Focus} (@qcode{"simulation"} (default), @qcode{"prediction"}
## or a band [w1 w2] in rad/s), @code{InitialCondition}
## (@qcode{"zero"}; the estimators start from rest), @code{Display}
## (@qcode{"off"}), @code{SearchMethod} (@qcode{"lm"}), and
## @code{SearchOptions} (@code{MaxIterations} 100, @code{Tolerance} 1e-8).
## Unknown names are errors (@code{oeOptions:badOption}).
##
## @strong{Example}
## @example
## opt = oeOptions ("Focus", [0 10]);
## opt.SearchOptions.MaxIterations = 50;
## @end example
## @seealso{oe, tfestOptions}
## @end deftypefn

function varargout = oeOptions (varargin)
  varargout = contsid_guard ("oeOptions", @oeOptions_body, nargout, varargin);
endfunction

function [opt, varargout] = oeOptions_body (varargin)
  contsid_nargchk ("oeOptions", nargin, nargout, [0 Inf], 1);
  opt = contsid_pem_options ("oeOptions", varargin);
endfunction

%!test
%! o = oeOptions ();
%! assert (o.Focus, "simulation");
%! assert (o.SearchOptions.MaxIterations, 100);
%! o = oeOptions ("Focus", [0 25], "Display", "on");
%! assert (o.Focus, [0 25]);

%!error id=oeOptions:badOption oeOptions ("Bogus", 1)
%!error id=oeOptions:badOption oeOptions ("Focus")
%!error id=oeOptions:badOption oeOptions (1, 2)
%!error id=oeOptions:badOption oeOptions ("Focus", [3 1])
%!error id=oeOptions:badOption oeOptions ("InitialCondition", "estimate")
%!error id=oeOptions:badOption oeOptions ("SearchMethod", "gna")

%!demo
%! opt = oeOptions ("Focus", [0 10])
