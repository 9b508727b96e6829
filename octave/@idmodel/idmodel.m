## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn {} {@var{M} =} idmodel (@var{kind}, @var{par}, @var{ny}, @var{nu})
## The common parent of the System Identification Toolbox model classes
## @code{idpoly}, @code{idtf}, @code{idproc}, @code{idss} and
## @code{idfrd} (as the control package's @code{tf} and @code{ss} share
## @code{lti}).  Users do not call it: the constructors of those classes
## do.  It holds the properties common to all of them (@code{Ts},
## @code{InputDelay}, @code{NoiseVariance}, @code{Report}, names and
## units, the parameter covariance) and the class-specific data in
## @var{par}; the methods (@code{get}, @code{set}, @code{bode},
## @code{step}, @code{sim}, @code{present}, @dots{}) are defined here
## once for all five classes.
##
## @var{kind} is the class name, @var{par} a struct with the class'
## own properties, @var{ny} and @var{nu} the numbers of outputs and inputs.
## @seealso{idpoly, idtf, idproc, idss, idfrd}
## @end deftypefn

function varargout = idmodel (varargin)
  varargout = contsid_guard ({"idmodel", "idmodel"}, @idmodel_body, nargout,
                             varargin);
endfunction

function [M, varargout] = idmodel_body (kind, par, ny, nu, varargin)
  contsid_nargchk ("idmodel", nargin, nargout, [0 4], 1);
  if (nargin != 4 || ! ischar (kind) || ! isstruct (par))
    error ("idmodel:badInput", "idmodel: expected kind, par, ny and nu");
  endif
  model_props (kind);                  # checks kind
  if (! (is_count (ny) && is_count (nu)))
    error ("idmodel:badInput",
           "idmodel: ny and nu must be whole numbers of outputs and inputs");
  endif
  ny = double (ny);
  nu = double (nu);
  s = struct ();
  s.kind = kind;
  s.par = par;
  s.ny = ny;
  s.nu = nu;
  s.Ts = 0;
  s.TimeUnit = "seconds";
  s.InputDelay = zeros (nu, 1);
  s.InputName = repmat ({""}, nu, 1);
  s.InputUnit = repmat ({""}, nu, 1);
  s.OutputName = repmat ({""}, ny, 1);
  s.OutputUnit = repmat ({""}, ny, 1);
  s.Name = "";
  s.Notes = {};
  s.UserData = [];
  s.NoiseVariance = eye (ny);
  status = ["Created by direct construction or transformation. ", ...
            "Not estimated."];
  s.Report = struct ("Status", status,
                     "Method", "",
                     "Fit", struct ("FitPercent", [], "LossFcn", [],
                                    "MSE", [], "FPE", [], "AIC", [],
                                    "BIC", []),
                     "Parameters", struct ("ParVector", [],
                                           "FreeParCovariance", []),
                     "Termination", struct ("Iterations", [],
                                            "Converged", []),
                     "DataUsed", struct ("Length", [], "Ts", [],
                                         "InterSample", "",
                                         "InputOffset", [],
                                         "OutputOffset", []));
  s.cov = [];
  ## CONTSID idctm data that have no SITB property: theta and covariance
  ## of a model with more parameters than its polynomials (residtrace),
  ## delays in samples without the data's sampling interval.
  s.legacy = struct ("theta", [], "covariance", [], "nk", []);
  M = class (s, "idmodel");
endfunction

function tf = is_count (n)
  tf = isnumeric (n) && isreal (n) && isscalar (n) && n >= 0 && n == fix (n);
endfunction

%!test
%! M = idmodel ("idtf", struct ("Numerator", {{1}}, "Denominator", {{[1 1]}},
%!              "IODelay", 0, "Variable", "s"), 1, 1);
%! assert (class (M), "idmodel");
%!error id=idmodel:badInput idmodel ("idtf")
%!error id=idmodel:badInput idmodel ("nothing", struct (), 1, 1)
%!error id=idmodel:badInput idmodel ("idtf", struct (), -1, 1)
%!error id=idmodel:badInput idmodel ("idtf", struct (), 1, NaN)
%!error id=idmodel:badInput idmodel ("idtf", struct (), 1, "a")
%!error id=idmodel:badInput idmodel ("idtf", struct (), [1 2], 1)

%!demo
%! ## idmodel is the parent class; users build its children:
%! M = idpoly (1, 2, 1, 1, [1 1.2 2], "Ts", 0)
