## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn  {} {@var{opt} =} bodeoptions ()
## @deftypefnx {} {@var{opt} =} bodeoptions ("cstprefs")
## Options for @code{bodeplot}, with MATLAB's names and defaults
## (@code{opt = bodeoptions; opt.FreqUnits = "Hz"; bodeplot (sys, opt)}).
##
## @var{opt} is a plain struct with the fields of MATLAB's
## @code{BodePlotOptions}.  @code{bodeplot} draws with
## @code{Title.String}, @code{XLabel.String}, @code{YLabel.String}
## (@code{@{magnitude, phase@}}), @code{Grid}, @code{XLim},
## @code{FreqUnits} (@qcode{"rad/s"}, @qcode{"rad/sec"}, @qcode{"Hz"}),
## @code{FreqScale} (@qcode{"log"}, @qcode{"linear"}), @code{MagUnits}
## (@qcode{"dB"}, @qcode{"abs"}), @code{MagScale}, @code{MagVisible},
## @code{PhaseUnits} (@qcode{"deg"}, @qcode{"rad"}), @code{PhaseVisible},
## @code{PhaseWrapping}.  The other fields are accepted; when one of them
## differs from its default, @code{bodeplot} warns
## (@code{bodeplot:notSupported}) that it is not drawn.  A field that
## MATLAB does not have is an error in @code{bodeplot}.
## @seealso{bodeplot, stepplot}
## @end deftypefn

function varargout = bodeoptions (varargin)
  varargout = contsid_guard ("bodeoptions", @bodeoptions_body, nargout,
                             varargin);
endfunction

function [opt, varargout] = bodeoptions_body (varargin)
  contsid_nargchk ("bodeoptions", nargin, nargout, [0 Inf], 1);
  if (nargin > 1 || (nargin == 1 && ! strcmpi (varargin{1}, "cstprefs")))
    error ("bodeoptions:badInput",
           "bodeoptions: takes no argument, or \"cstprefs\"");
  endif
  label = @(str) struct ("String", str, "FontSize", 8, "FontWeight",
                         "normal", "FontAngle", "normal",
                         "Color", [0 0 0], "Interpreter", "tex");
  opt = struct ("Title", label ("Bode Diagram"),
                "XLabel", label ("Frequency"),
                "YLabel", label ({{"Magnitude", "Phase"}}),
                "TickLabel", struct ("FontSize", 8, "FontWeight", "normal",
                                     "FontAngle", "normal",
                                     "Color", [0 0 0]),
                "Grid", "off", "GridColor", [0.15 0.15 0.15],
                "XLim", {{[1 10]}}, "XLimMode", {{"auto"}},
                "YLim", {{[1 10]}}, "YLimMode", {{"auto"}},
                "IOGrouping", "none",
                "InputLabels", label (""), "OutputLabels", label (""),
                "InputVisible", {{"on"}}, "OutputVisible", {{"on"}},
                "ConfidenceRegionNumberSD", 1,
                "FreqUnits", "rad/s", "FreqScale", "log",
                "MagUnits", "dB", "MagScale", "linear", "MagVisible", "on",
                "MagLowerLimMode", "auto", "MagLowerLim", 0,
                "PhaseUnits", "deg", "PhaseVisible", "on",
                "PhaseWrapping", "off", "PhaseMatching", "off",
                "PhaseMatchingFreq", 0, "PhaseMatchingValue", 0);
endfunction

%!test
%! opt = bodeoptions ();
%! assert (opt.FreqUnits, "rad/s");
%! assert (opt.Title.String, "Bode Diagram");
%! assert (opt.YLabel.String, {"Magnitude", "Phase"});
%! assert (opt.XLim, {[1 10]});
%! assert (isequal (bodeoptions ("cstprefs"), opt));

%!error id=bodeoptions:badInput bodeoptions ("other")
%!error id=bodeoptions:badInput bodeoptions (1, 2)

%!demo
%! opt = bodeoptions;
%! opt.FreqUnits = "Hz";
%! opt.PhaseVisible = "off";
%! bodeplot (tf (1, [1 0.4 1]), opt)
