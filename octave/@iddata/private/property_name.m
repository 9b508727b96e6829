## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn  {} {@var{name} =} property_name (@var{key}, @var{who})
## @deftypefnx {} {@var{names} =} property_name ()
## Canonical name of the @code{iddata} property @var{key}, or the list of
## all canonical names.
##
## Matching ignores case.  Besides the MATLAB names the control package's
## names are accepted (@qcode{"y"}, @qcode{"outname"}, @qcode{"tsam"},
## @qcode{"w"}, ...).  An exact match wins; otherwise a prefix must point
## to a single property.  @var{who} starts the error messages.
## @end deftypefn

function name = property_name (key, who)
  persistent table = {
    "OutputData",       {"y", "outdata", "outputdata"};
    "OutputName",       {"outname", "outputname"};
    "OutputUnit",       {"outunit", "outputunit"};
    "InputData",        {"u", "indata", "inputdata"};
    "InputName",        {"inname", "inputname"};
    "InputUnit",        {"inunit", "inputunit"};
    "Ts",               {"ts"};
    "tsam",             {"tsam"};
    "SamplingInstants", {"samplinginstants"};
    "InterSample",      {"intersample"};
    "TimeUnit",         {"timeunit"};
    "ExperimentName",   {"expname", "experimentname"};
    "Name",             {"name"};
    "Notes",            {"notes"};
    "UserData",         {"userdata"};
    "Domain",           {"domain"};
    "TimeDomain",       {"timedomain"};
    "Frequency",        {"w", "frequency"};
    "N",                {"n"}};

  if (nargin == 0)
    name = table(:,1);
    return;
  endif
  if (! (ischar (key) && rows (key) <= 1))
    error ("iddata:badOption", "%s: property name must be a string", who);
  endif
  lkey = lower (key);
  owner = cellfun (@(aliases) any (strcmp (lkey, aliases)), table(:,2));
  if (! any (owner) && ! isempty (lkey))
    owner = cellfun (@(aliases) any (strncmp (lkey, aliases, numel (lkey))),
                     table(:,2));
  endif
  switch (nnz (owner))
    case 1
      name = table{owner, 1};
    case 0
      error ("iddata:badOption", "%s: unknown property '%s'", who, key);
    otherwise
      error ("iddata:badOption",
             "%s: property name '%s' is ambiguous (%s)", who, key,
             strjoin (table(owner, 1).', ", "));
  endswitch
endfunction
