## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn {} {[@var{names}, @var{readonly}] =} model_props (@var{kind})
## The property names of a model of class @var{kind} (canonical spelling),
## the common ones first, and those of them that cannot be set.
## @end deftypefn

function [names, readonly] = model_props (kind)
  common = {"Ts", "TimeUnit", "InputDelay", "InputName", "InputUnit", ...
            "OutputName", "OutputUnit", "Name", "Notes", "UserData", ...
            "NoiseVariance", "Report"};
  readonly = {};
  switch (kind)
    case "idpoly"
      own = {"A", "B", "C", "D", "F", "IODelay", "Variable"};
      ## CONTSID's idctm fields, aliases of the above (see set_prop).
      legacy = {"theta", "covariance", "nk", "noise_variance", "method", ...
                "iterations", "converged", "InterSample"};
      own = [own, legacy];
      readonly = [readonly, {"Variable"}];
    case "idtf"
      own = {"Numerator", "Denominator", "IODelay", "Variable"};
      readonly = [readonly, {"Variable"}];
    case "idproc"
      own = {"Type", "Kp", "Tp1", "Tp2", "Tp3", "Tw", "Zeta", "Td", "Tz", ...
             "Integration", "Structure"};
      readonly = [readonly, {"Type", "Integration"}];
    case "idss"
      own = {"A", "B", "C", "D", "K", "x0", "StateName", "StateUnit"};
    case "idfrd"
      own = {"ResponseData", "Frequency", "FrequencyUnit"};
    otherwise
      error ("idmodel:badInput", "idmodel: unknown model class '%s'", kind);
  endswitch
  names = [common, own];
endfunction
