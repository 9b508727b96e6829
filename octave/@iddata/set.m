## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn  {} {@var{data} =} set (@var{data}, @var{name}, @var{val}, @
##   @dots{})
## @deftypefnx {} {} set (@var{data}, @var{name}, @var{val}, @dots{})
## @deftypefnx {} {} set (@var{data})
## Set properties of an @code{iddata} set.
##
## All name-value pairs are applied before the consistency checks, so the
## length of the data can change in one call:
## @code{data = set (data, "y", y2, "u", u2)}.  Without an output argument
## the variable passed as @var{data} is updated in the caller (as in the
## control package).  @code{set (data)} lists the properties that can be
## set.  See @code{help iddata} for the property names.
## @seealso{iddata, get, subsasgn}
## @end deftypefn

function [retdat, varargout] = set (dat, varargin)
  contsid_nargchk ("set", nargin, nargout, [1 Inf], 1);
  if (nargin == 1)
    names = setdiff (property_name (), {"Domain", "TimeDomain", "N"}, "stable");
    printf ("  %s\n", names{:});
    if (nargout > 0)
      retdat = dat;
    endif
    return;
  endif
  if (mod (numel (varargin), 2) != 0)
    error ("iddata:badOption",
           "iddata: set: properties must come in name-value pairs");
  endif
  for k = 1:2:numel (varargin)
    name = property_name (varargin{k}, "iddata: set");
    dat = assign_property (dat, name, varargin{k+1}, varargin{k},
                           "iddata: set");
  endfor
  check_dataset (dat, "iddata: set");
  if (nargout > 0)
    retdat = dat;
  else
    var = inputname (1, false);
    if (! isvarname (var))
      error ("iddata:badInput",
             ["iddata: set: the first argument is not a variable; ", ...
              "use 'data = set (data, ...)'"]);
    endif
    assignin ("caller", var, dat);
  endif
endfunction

%!shared data
%! data = iddata ((1:5).', (6:10).', 1);

%!test
%! d = set (data, "y", (1:7).', "u", (1:7).', "InterSample", "foh");
%! assert (size (d), [7, 1, 1, 1]);
%! assert (d.InterSample, "foh");
%! set (d, "InterSample", "zoh", "OutputName", "level");
%! assert (d.InterSample, "zoh");
%! assert (d.OutputName, {"level"});
%! listing = evalc ("same = set (d);");
%! assert (struct (same), struct (d));
%! assert (! isempty (strfind (listing, "InterSample")));

%!error id=iddata:badOption set (data, "Ts")
%!error id=iddata:badOption set (data, "Bogus", 1)
%!error id=iddata:badInput set (data, "Ts", -2)
%!error id=iddata:badInput set (iddata ((1:5).', (6:10).', 1), "Ts", 2)
%!error id=iddata:dimensionMismatch set (data, "y", (1:7).')
%!error id=iddata:dimensionMismatch
%! set (iddata ((1:3).', (1:3).', [0 1 3]), "y", (1:4).', "u", (1:4).');

%!demo
%! data = iddata (randn (50, 1), randn (50, 1), 0.1);
%! data = set (data, "InterSample", "foh", "InputName", "voltage");
%! get (data, "InterSample", "InputName")
