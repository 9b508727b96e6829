## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn  {} {@var{val} =} get (@var{data}, @var{name})
## @deftypefnx {} {[@var{v1}, @var{v2}, @dots{}] =} get (@var{data}, @
##   @var{n1}, @var{n2}, @dots{})
## @deftypefnx {} {@var{props} =} get (@var{data})
## @deftypefnx {} {} get (@var{data})
## Properties of an @code{iddata} set.
##
## @code{get (data, "InterSample")} equals @code{data.InterSample}; see
## @code{help iddata} for the property names.  With one argument,
## @code{get} returns a struct of all properties, or prints them when no
## output is requested.
## @seealso{iddata, set, subsref}
## @end deftypefn

function varargout = get (varargin)
  varargout = contsid_guard ({"get", "iddata"}, @get_body, nargout, varargin);
endfunction

function varargout = get_body (dat, varargin)
  contsid_nargchk ("get", nargin, nargout, [1 Inf], max (1, nargin - 1));
  if (nargin == 1)
    names = property_name ();
    vals = cellfun (@(name) property_value (dat, name, false), names,
                    "uniformoutput", false);
    if (nargout == 0)
      width = max (cellfun ("numel", names));
      for k = 1:numel (names)
        printf ("  %*s: %s\n", width, names{k}, summary (vals{k}));
      endfor
    else
      varargout{1} = cell2struct (vals, names, 1);
    endif
    return;
  endif
  varargout = cell (1, max (1, numel (varargin)));
  for k = 1:numel (varargin)
    name = property_name (varargin{k}, "iddata: get");
    control_style = called_from_control (name);
    varargout{k} = property_value (dat, name, control_style);
  endfor
endfunction

function str = summary (val)
  if (ischar (val) && rows (val) <= 1)
    str = ["\"", val, "\""];
  elseif ((isnumeric (val) || islogical (val)) && isscalar (val))
    str = num2str (val);
  elseif (iscellstr (val) && numel (val) <= 4)
    quoted = cellfun (@(s) ["\"", s, "\""], val(:).', "uniformoutput", false);
    str = ["{", strjoin(quoted, ", "), "}"];
  else
    str = sprintf ("[%s %s]", strjoin (arrayfun (@num2str, size (val),
                                                 "uniformoutput", false),
                                       "x"), class (val));
  endif
endfunction

%!shared data
%! data = iddata ((1:5).', (6:10).', 2, "InterSample", "foh", "Name", "run");

%!test
%! assert (get (data, "InterSample"), "foh");
%! [y, ts, n] = get (data, "y", "Ts", "name");
%! assert (y, (1:5).');
%! assert (ts, 2);
%! assert (n, "run");
%! props = get (data);
%! assert (props.InterSample, "foh");
%! assert (props.SamplingInstants, (0:4).' * 2);
%! assert (props.UserData, []);

%!error id=iddata:badOption get (data, "Bogus")
%!error id=iddata:badOption get (data, 3)

%!demo
%! data = iddata (randn (20, 1), randn (20, 2), 0.1, "InterSample", "foh");
%! get (data)
